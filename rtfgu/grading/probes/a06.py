"""Probes of a06's tests: the intersection functions in WGSL (02562 week 2), run on the GPU adapter through wgpu.

Each test assembles a small compute shader: the generated constants, ``ray.wgsl`` and
``hitinfo.wgsl``, the student's intersection function, and a kernel that calls it once per
case and writes back what it returned and what it put in the HitInfo. It runs in a newly
started interpreter (a GPU driver does not survive fork), in float32.
"""
from __future__ import annotations

import importlib
import math
from pathlib import Path

from .a03 import TRIANGLE
from .support import StudentError

FAR = 1.0e30   # rtfgu.layout.FAR: WGSL has no infinity
PLANE, TRIANGLE_KIND, SPHERE = 0, 1, 2

KERNEL = """
@group(0) @binding(0) var<storage, read> cases: array<vec4f>;
@group(0) @binding(1) var<storage, read_write> results: array<vec4f>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3u)
{
    let i = id.x;
    if (i * 6u >= arrayLength(&cases)) {
        return;
    }
    let c = i * 6u;
    let r = Ray(cases[c].xyz, cases[c + 1u].xyz, cases[c].w, cases[c + 1u].w);
    var hit = empty_hit();
    var hit_found = false;
    %(call)s
    results[i * 3u] = vec4f(select(0.0, 1.0, hit_found), select(0.0, 1.0, hit.has_hit), hit.dist, 0.0);
    results[i * 3u + 1u] = vec4f(hit.position, 0.0);
    results[i * 3u + 2u] = vec4f(hit.normal, 0.0);
}
"""

CALLS = {
    "intersect_plane": "hit_found = intersect_plane(r, &hit, cases[c + 2u].xyz, cases[c + 3u].xyz);",
    "intersect_triangle": ("hit_found = intersect_triangle(r, &hit, cases[c + 2u].xyz, cases[c + 3u].xyz, "
                           "cases[c + 4u].xyz, cases[c + 5u].xyz);"),
    "intersect_sphere": "hit_found = intersect_sphere(r, &hit, cases[c + 2u].xyz, cases[c + 3u].x);",
}


def _run_on_gpu(rt, function: str, rows):
    """rows: one list of 24 floats per case; returns (returned, has_hit, dist, position, normal) per case."""
    import numpy as np

    harness = importlib.import_module("rtfgu.wgsl.harness")
    folder = Path(rt.__file__).parent / "wgsl"
    names = ["ray.wgsl", "hitinfo.wgsl", function + ".wgsl"]
    overrides = {name: (folder / name).read_text() for name in names}
    overrides["a06_kernel.wgsl"] = KERNEL % {"call": CALLS[function]}
    program = harness.batch_program(names + ["a06_kernel.wgsl"], overrides=overrides)
    try:
        out = harness.run_batch(program, [np.asarray(rows, dtype=np.float32)], len(rows), vec4s=3).astype(float)
    except harness.WGSLCompileError as error:
        text = str(error)
        if "TODO_a06_" in text:
            raise StudentError("%s is not written yet: its stub names TODO_a06_%s, so the shader does not compile"
                               % (function, function)) from None
        raise StudentError("your %s.wgsl does not compile: %s" % (function, text.strip()[:1500])) from None
    return [(bool(o[0, 0] > 0.5), bool(o[0, 1] > 0.5), float(o[0, 2]), o[1, :3].tolist(), o[2, :3].tolist())
            for o in out]


def _cases(rt, function, specs):
    """specs: (label, inputs, row); one GPU run for all, then one case per row."""
    rows = [row for _, _, row in specs]
    answers = _run_on_gpu(rt, function, rows)
    cases = []
    for (label, inputs, _), (returned, has_hit, dist, position, normal) in zip(specs, answers):
        out = {"returned": returned, "hit.has_hit": has_hit}
        if returned:
            out.update({"hit.dist": dist, "hit.position": position, "hit.normal": normal})
        cases.append({"label": label, "in": inputs, "out": out})
    return {"cases": cases}


def _ray_row(o, d, tmin, tmax):
    return list(o) + [tmin] + list(d) + [FAR if tmax == math.inf else tmax]


def _label(shape, o, d, tmin, tmax):
    return "%s and the ray from (%g, %g, %g) along (%g, %g, %g) with tmin %g, tmax %s" % (
        (shape,) + tuple(o) + tuple(d) + (tmin, "1e30" if tmax == math.inf else "%g" % tmax))


def observe_plane(rt):
    specs = []
    for a, n in [((0, -1, 0), (0, 1, 0)), ((0, 0, -4), (0, 0.5, 2))]:
        shape = "intersect_plane with the plane through (%g, %g, %g), normal (%g, %g, %g)" % (tuple(a) + tuple(n))
        for o, d, tmin, tmax in [((0, 0, 0), (0, -0.6, -0.8), 1e-5, math.inf), ((0, 0, 0), (0, 0.6, 0.8), 1e-5, math.inf),
                                 ((0, 0, 0), (0, -0.6, -0.8), 1e-5, 0.5), ((3, 2, 1), (-1, -1, -1), 1e-5, 100.0),
                                 ((0, 0, 0), (1, 0, 0), 1e-5, math.inf)]:
            specs.append((_label(shape, o, d, tmin, tmax), {"o": list(o), "d": list(d), "tmin": tmin, "tmax": tmax},
                          _ray_row(o, d, tmin, tmax) + list(a) + [PLANE] + list(n) + [0] + [0] * 8))
    return _cases(rt, "intersect_plane", specs)


SPHERES = [
    ((0, 0, -3), 1.0, (0, 0, 0), (0, 0, -1), 1e-5, math.inf),
    ((0, 0, -3), 1.0, (0.5, 0.5, 0), (0, 0, -1), 1e-5, math.inf),
    ((1, 2, -5), 2.0, (0, 0, 0), (0.2, 0.4, -1.0), 1e-5, math.inf),
    ((0, 0, -3), 1.0, (0, 0, 0), (0, 1, 0), 1e-5, math.inf),
    ((0, 0, -3), 1.0, (1.5, 0, 0), (0, 0, -1), 1e-5, math.inf),
    ((0, 0, 3), 1.0, (0, 0, 0), (0, 0, -1), 1e-5, math.inf),
    ((0, 0, -3), 1.0, (0, 0, -2.5), (0, 0, -1), 1e-5, math.inf),
    ((0, 0, -3), 1.0, (0, 0, 0), (0, 0, -1), 1e-5, 1.5),
    ((0, 0, -3), 1.0, (0, 0, 0), (0, 0, -1), 2.5, math.inf),
    ((0, 0, -3), 1.0, (0, 0, 0), (0, 0, -2), 1e-5, math.inf),
]


def observe_sphere(rt):
    specs = []
    for c, radius, o, d, tmin, tmax in SPHERES:
        shape = "intersect_sphere with the sphere at (%g, %g, %g), radius %g" % (tuple(c) + (radius,))
        specs.append((_label(shape, o, d, tmin, tmax),
                      {"o": list(o), "d": list(d), "tmin": tmin, "tmax": tmax, "center": list(c), "radius": radius},
                      _ray_row(o, d, tmin, tmax) + list(c) + [SPHERE] + [radius, 0, 0, 0] + [0] * 8))
    return _cases(rt, "intersect_sphere", specs)


def observe_triangle(rt):
    specs = []
    v0, v1, v2 = TRIANGLE
    e0 = [v1[i] - v0[i] for i in range(3)]
    e1 = [v2[i] - v0[i] for i in range(3)]
    n = [e0[1] * e1[2] - e0[2] * e1[1], e0[2] * e1[0] - e0[0] * e1[2], e0[0] * e1[1] - e0[1] * e1[0]]
    shape = "intersect_triangle with the triangle %s" % (TRIANGLE,)
    for o, d, tmin, tmax in [((0, 0, 0), (0, -0.1, -1), 1e-5, math.inf), ((0, 0, 0), (0.9, 0.9, -1), 1e-5, math.inf),
                             ((0, 0, 0), (0, -0.5, -1), 1e-5, math.inf), ((0, 0, 0), (0, 0, 1), 1e-5, math.inf),
                             ((0, 0, 0), (0, 0, -1), 1e-5, 2.0), ((0, 0, -5), (0, 0.2, 1), 1e-5, math.inf),
                             ((0.9, 0.9, 0), (0, 0, -1), 1e-5, math.inf)]:
        specs.append((_label(shape, o, d, tmin, tmax), {"o": list(o), "d": list(d), "tmin": tmin, "tmax": tmax},
                      _ray_row(o, d, tmin, tmax) + list(v0) + [TRIANGLE_KIND] + e0 + [0] + e1 + [0] + n + [0]))
    return _cases(rt, "intersect_triangle", specs)


def render_wgsl(rt, scene, width, height):
    runner = importlib.import_module("rtfgu.wgsl.runner")
    # The slide formula: the image shows the student's intersect_sphere.wgsl, not robust_sphere.wgsl.
    return runner.render_wgpu(scene, width, height, formula="slide")
