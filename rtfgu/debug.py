"""Trace one pixel (or one ray) through the paths, bounce by bounce, and say where they
first differ.

``trace_pixel(scene, x, y, width, height, backend, precision)`` returns what one path
computed for pixel (x, y) (column, row, row 0 at the top as in the image file): a
``Bounce`` per ray of the pixel's path (02562 "Intersecting with the scene and tracing a
path"): the ray, the shape hit (its place in Scene.shapes, a Mesh there counted as its
faces, and its kind), the hit distance
t, the normal there, the shader and the radiance that shader added. The pixel's path is that
of its centre ray (through the lens centre for a ThinLens): the image of a scene without a
sampler, one of the samples a sampled pixel averages. ``trace_rays`` does the
same for given rays (origin, direction, tmin, tmax), many in one call.

``first_difference(a, b, tolerance)`` compares two such lists bounce by bounce, field by
field in FIELDS order (the ray, then what it hit, then how it was shaded) and names the
first field that differs. The shape, its kind and the shader must be the same; numbers are
close when |a - b| <= tolerance * max(1, |a|, |b|): relative above 1, absolute below, where
directions, normals and colours live. TOLERANCES holds each precision's: a float64 path
must agree with the lecture layer bit for bit (the numba kernels do the lecture's
operations in its order), a float32 path within FLOAT32_TOLERANCE.

``python -m rtfgu debug-pixel NAME X Y`` prints the paths side by side (``report``).
"""
from __future__ import annotations

import copy
import importlib.util
import math
from dataclasses import dataclass
from typing import NamedTuple

from .cameras import PinholeCamera
from .float3 import Float3
from .materials.material import SHADER_NAMES
from .ray import Ray
from .registry import SHAPES, shape_kind_of
from .shapes.compound import Compound
from .options import DEFAULT_FORMULAS, FORMULAS
from .tracers.whitted import Whitted

BACKENDS = ("reference", "numba", "wgpu")
# Every path, as (label, backend, precision), in the order a report shows them.
PATHS = (("reference", "reference", "float64"), ("numba-float64", "numba", "float64"),
         ("numba-float32", "numba", "float32"), ("wgpu-float32", "wgpu", "float32"))

# A float32 path against float64: float32 keeps 24 bits (a relative 6e-8 a rounding); a
# bounce's few dozen roundings, and the drift of t and the direction over a path of
# refractions, stay below this, while a different hit, a missed shadow or a wrong formula
# is far above it.
FLOAT32_TOLERANCE = 1e-4
TOLERANCES = {"float64": 0.0, "float32": FLOAT32_TOLERANCE}
FIELDS = ("origin", "direction", "shape", "kind", "t", "normal", "shader", "color")
EXACT_FIELDS = ("shape", "kind", "shader")


@dataclass(frozen=True)
class Bounce:
    """One ray of a path and what became of it. On a miss ``shape``, ``kind``, ``t`` and
    ``normal`` are None, ``shader`` is "background" and ``color`` the background; the
    normal is None too for base_color, whose shader reads none."""

    origin: tuple
    direction: tuple
    shape: int | None        # place in Scene.shapes
    kind: str | None         # the shape kind's name (rtfgu.registry)
    t: float | None
    normal: tuple | None
    shader: str
    color: tuple             # the radiance this bounce added


class PathNotInRelease(ValueError):
    """A path this copy of rtfgu leaves out: a student release has neither the numba
    kernels nor the WGSL pieces of the assignments it does not reveal
    (rtfgu.grading.release); the debugger then traces the paths it has."""


class Difference(NamedTuple):
    bounce: int
    field: str
    first: object
    second: object


def _f3(v) -> tuple:
    return (float(v.x), float(v.y), float(v.z)) if isinstance(v, Float3) else tuple(float(c) for c in v)


def _shader_name(shader) -> str:
    return SHADER_NAMES.get(int(shader), "shader %d" % int(shader))


def _hit(origin, direction, shape, kind, t, normal, shader, color) -> Bounce:
    name = _shader_name(shader)
    return Bounce(_f3(origin), _f3(direction), int(shape), kind, float(t),
                  None if name == "base_color" else _f3(normal), name, _f3(color))


def _miss(origin, direction, color, shader="background") -> Bounce:
    return Bounce(_f3(origin), _f3(direction), None, None, None, None, shader, _f3(color))


def _numbered(scene) -> list:
    """The shapes as the flat paths number them: a Compound's leaves in its place."""
    out = []
    for shape in scene.shapes:
        out += shape.leaves() if isinstance(shape, Compound) else [shape]
    return out


class _Logged:
    """A shape of Scene.shapes that notes its place there whenever it reports a hit."""

    def __init__(self, shape, index, log):
        self._shape, self._index, self._log = shape, index, log

    def intersect_p(self, ray) -> bool:
        found = self._shape.intersect_p(ray)
        if found:
            index = self._index
            if isinstance(self._shape, Compound):   # numbered as its leaves: the place of the leaf hit
                index += self._shape.leaves().index(self._shape.hit_object)
            self._log.append(index)
        return found

    def __getattr__(self, name):
        return getattr(self._shape, name)


class _Collect(Whitted):
    """A tracer that traces nothing: it notes the rays a material's ``shade`` sends on and
    returns black for each, so that ``shade`` returns what the hit itself adds."""

    def __init__(self, samples_area_lights: bool, rays: list):
        super().__init__()
        self.samples_area_lights, self.rays = samples_area_lights, rays

    def trace_ray(self, ray, depth: int = 0) -> Float3:
        self.rays.append(ray)
        return Float3(0.0)


class _Recording(Whitted):
    """Whitted (the 02562 path loop), noting a Bounce per ray it traces, depth first: the
    shape hit (the last to report a hit, on a view of the scene whose shapes note their place
    in Scene.shapes), and the radiance its material's ``shade`` adds there, the rays it sends
    on seen as black; then those rays in the order the material sent them."""

    def __init__(self, scene, out: list):
        super().__init__()
        scene = scene.with_faces()      # a Mesh's faces, each in its place
        self.scene, self.out, self.log = scene, out, []
        self.numbered = _numbered(scene)
        self.world = copy.copy(scene)
        self.world.shapes, i = [], 0
        for shape in scene.shapes:
            self.world.shapes.append(_Logged(shape, i, self.log))
            i += len(shape.leaves()) if isinstance(shape, Compound) else 1
        self.world.tracer = self

    def trace_ray(self, ray, depth: int = 0) -> Float3:
        if depth >= self.max_depth:
            return Float3(0.0)
        origin, direction = ray.origin, ray.direction
        self.log.clear()
        sr = self.hit(ray, depth)
        if sr is None:
            self.out.append(_miss(origin, direction, self.scene.background_radiance(direction)))
            return Float3(0.0)
        index = self.log[-1]
        sent = []
        self.world.tracer = _Collect(self.samples_area_lights, sent)
        color = sr.material.shade(sr)
        self.world.tracer = self
        kind = shape_kind_of(self.numbered[index])[1]
        self.out.append(_hit(origin, direction, index, kind.name if kind else None, sr.dist, sr.normal,
                             sr.material.shader, color))
        for next_ray in sent:
            self.trace_ray(next_ray, depth + 1)
        return Float3(0.0)


def _reference(scene, r: Ray) -> list:
    """The lecture layer's Whitted tracer on ``r``, recording each bounce (_Recording)."""
    if scene.show_ray_direction:
        return [_miss(r.origin, r.direction, r.direction * 0.5 + Float3(0.5), "ray direction")]
    out = []
    _Recording(scene, out).trace_ray(r, 0)
    return out


def _from_numba(records, miss: str) -> list:
    # rtfgu.kernels.debug: [origin, direction, t, index, kind, shader, normal, colour]
    out = []
    for row in records:
        if math.isnan(row[0]):
            break
        if row[7] < 0:
            out.append(_miss(row[0:3], row[3:6], row[13:16], miss))
        else:
            out.append(_hit(row[0:3], row[3:6], row[7], SHAPES[int(row[8])].name, row[6], row[10:13],
                            row[9], row[13:16]))
    return out


def _from_wgpu(scene, records) -> list:
    # debug_main.wgsl: (origin, t), (direction, shader), (normal, shape), (colour, what)
    shapes = _numbered(scene.with_faces())      # the shape numbers count a Mesh's faces
    out = []
    for (origin_t, direction_shader, normal_shape, color_what) in records:
        what = color_what[3]
        if what == 0.0:
            break
        if what == 1.0:
            index = int(normal_shape[3])
            kind = shape_kind_of(shapes[index])[1] if 0 <= index < len(shapes) else None
            out.append(_hit(origin_t[:3], direction_shader[:3], index, kind.name if kind else None,
                            origin_t[3], normal_shape[:3], direction_shader[3], color_what[:3]))
        else:
            out.append(_miss(origin_t[:3], direction_shader[:3], color_what[:3],
                             "ray direction" if what == 3.0 else "background"))
    return out


def check_path(backend: str, precision, formula):
    """(precision, formula) of a path, each backend's default where None (rtfgu.renderer),
    or a ValueError naming the parameter."""
    if backend not in BACKENDS:
        raise ValueError("backend must be one of %s, got %r" % (", ".join(BACKENDS), backend))
    if precision is None:
        precision = "float32" if backend == "wgpu" else "float64"
    allowed = {"reference": ("float64",), "numba": ("float64", "float32"), "wgpu": ("float32",)}[backend]
    if precision not in allowed:
        raise ValueError("precision: the %s backend computes in %s, got %r"
                         % (backend, " or ".join(allowed), precision))
    if formula is None:
        formula = DEFAULT_FORMULAS[backend]
    if formula not in FORMULAS or (backend == "reference" and formula != "slide"):
        raise ValueError("formula must be one of %s, got %r"
                         % ("slide" if backend == "reference" else ", ".join(FORMULAS), formula))
    return precision, formula


def _trace(scene, backend, precision, formula, pixel=None, rays=None) -> list:
    precision, formula = check_path(backend, precision, formula)
    scene.validate()
    if backend == "reference":
        if pixel is not None:
            x, y, width, height = pixel
            iy = height - 1 - y
            # The pixel's centre ray; a ThinLens's through the lens centre, which is its
            # pinhole ray (the paths trace that one too).
            gen_ray = (PinholeCamera.gen_ray if scene.camera.uses_lens else type(scene.camera).gen_ray)
            rays = [gen_ray(scene.camera, 2 * (x + 0.5) / width - 1, 2 * (iy + 0.5) / height - 1)]
        else:
            rays = [Ray(Float3(*o), Float3(*d), tmin, tmax) for o, d, tmin, tmax in rays]
        return [_reference(scene, r) for r in rays]
    if pixel is None:
        rays = [tuple(o) + tuple(d) + (tmin, tmax) for o, d, tmin, tmax in rays]
    if backend == "numba":
        if importlib.util.find_spec(__package__ + ".kernels") is None:
            raise PathNotInRelease("the numba path is not part of this release of rtfgu (it computes "
                                   "the assignments' functions again)")
        from .kernels.debug import numba_records
        from .layout import compile_scene

        if pixel is not None:
            x, y, width, height = pixel
            pixel = (x, height - 1 - y, width, height)
        records = numba_records(compile_scene(scene, precision), formula, pixel, rays)
        miss = "ray direction" if scene.show_ray_direction else "background"
        return [_from_numba(r, miss) for r in records]
    from .wgsl.assemble import PieceNotInRelease
    from .wgsl.debug import wgpu_records

    try:
        records = wgpu_records(scene, formula, pixel, rays)
    except PieceNotInRelease as error:
        raise PathNotInRelease(str(error)) from None
    return [_from_wgpu(scene, r) for r in records]


def _check_pixel(x, y, width, height) -> None:
    from .options import check_size

    check_size(width, height)
    for name, value, limit in (("X", x, width), ("Y", y, height)):
        if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value < limit:
            raise ValueError("%s must be an integer in [0, %d), got %r" % (name, limit, value))


def trace_pixel(scene, x: int, y: int, width: int, height: int, backend: str = "reference",
                precision: str | None = None, formula: str | None = None) -> list:
    """The bounces of pixel (x, y) (column, row, row 0 at the top) of a width x height
    render of ``scene`` on one path; precision and formula default to the backend's."""
    _check_pixel(x, y, width, height)
    return _trace(scene, backend, precision, formula, pixel=(x, y, width, height))[0]


def trace_rays(scene, rays, backend: str = "reference", precision: str | None = None,
               formula: str | None = None) -> list:
    """The bounces of each ray (origin, direction, tmin, tmax) through ``scene``, the
    camera left out: one list of Bounce per ray, all traced in one call of the path."""
    rays = [(tuple(map(float, o)), tuple(map(float, d)), float(tmin), float(tmax))
            for o, d, tmin, tmax in rays]
    return _trace(scene, backend, precision, formula, rays=rays) if rays else []


def _close(a, b, tolerance: float) -> bool:
    if a is None or b is None or isinstance(a, str) or isinstance(b, str):
        return a == b
    if isinstance(a, tuple):
        return len(a) == len(b) and all(_close(x, y, tolerance) for x, y in zip(a, b))
    if math.isinf(a) or math.isinf(b):
        return a == b
    return abs(a - b) <= tolerance * max(1.0, abs(a), abs(b))


def first_difference(a: list, b: list, tolerance: float = 0.0):
    """The first Difference(bounce, field, value in a, value in b) between two paths'
    bounces, or None: bounce by bounce, field by field in FIELDS order; "bounces" when one
    path ends before the other."""
    for n in range(max(len(a), len(b))):
        if n >= len(a) or n >= len(b):
            return Difference(n, "bounces", len(a), len(b))
        for field in FIELDS:
            x, y = getattr(a[n], field), getattr(b[n], field)
            if not _close(x, y, 0.0 if field in EXACT_FIELDS else tolerance):
                return Difference(n, field, x, y)
    return None


def _fmt(value) -> str:
    if value is None:
        return "-"
    if isinstance(value, tuple):
        return "(%s)" % ", ".join("%.9g" % v for v in value)
    if isinstance(value, float):
        return "%.9g" % value
    return str(value)


def _largest_gap(a, b) -> float:
    if isinstance(a, tuple):
        return max(_largest_gap(x, y) for x, y in zip(a, b))
    return abs(a - b) / max(1.0, abs(a), abs(b))


def report(title: str, traces: dict, tolerances: dict) -> str:
    """The paths side by side, bounce by bounce, against the first one (the reference): a
    cell is "=" when it is the reference's value bit for bit, "~ g" when within the
    path's tolerance (g the largest gap, relative above 1), else the path's own value with
    "!", and "<< first" marks each path's first difference."""
    names = list(traces)
    reference = traces[names[0]]
    firsts = {p: first_difference(reference, traces[p], tolerances[p]) for p in names[1:]}
    depth = max(len(t) for t in traces.values())
    rows = [["bounce"] + names]
    for n in range(depth):
        for field in FIELDS:
            row = ["%d %s" % (n, field)]
            for p in names:
                bounces = traces[p]
                if n >= len(bounces):
                    cell = "(ended)"
                else:
                    value = getattr(bounces[n], field)
                    ref = getattr(reference[n], field) if n < len(reference) else None
                    if p == names[0] or n >= len(reference):
                        cell = _fmt(value)
                    elif value == ref:
                        cell = "="
                    elif _close(ref, value, 0.0 if field in EXACT_FIELDS else tolerances[p]):
                        cell = "~ %.1e" % _largest_gap(ref, value)
                    else:
                        cell = _fmt(value) + " !"
                first = firsts.get(p)
                if first is not None and first.bounce == n and first.field in (field, "bounces") \
                        and (first.field == field or field == FIELDS[0]):
                    cell += " << first"
                row.append(cell)
            rows.append(row)
    widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
    lines = [title, ""]
    for k, row in enumerate(rows):
        if k > 1 and row[0].endswith(" " + FIELDS[0]):
            lines.append("")
        lines.append("  ".join(c.ljust(w) for c, w in zip(row, widths)).rstrip())
    lines.append("")
    for p in names[1:]:
        d = firsts[p]
        tolerance = "exact" if tolerances[p] == 0.0 else "relative %g" % tolerances[p]
        if d is None:
            lines.append("%s agrees with %s (%s)" % (p, names[0], tolerance))
        else:
            lines.append("%s first differs from %s at bounce %d, %s: %r against %r (%s)"
                         % (p, names[0], d.bounce, d.field, d.second, d.first, tolerance))
    return "\n".join(lines)
