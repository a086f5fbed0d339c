"""rtfgu's path tracer against a peer renderer: the Cornell box with its blocks, lit by its
ceiling quad as an area light, rendered by Mitsuba 3 (its ``path`` integrator) at 65,536
samples per pixel (tests/data/cornell_mitsuba.npz, written by benchmarks/cornell_reference.py
with the bench extra; Mitsuba is not needed to run this test).

Per pixel and channel, z = (rtfgu - Mitsuba) / sqrt(se_rtfgu^2 + se_Mitsuba^2), each
standard error from independent renders (seeds). Agreement within the combined Monte Carlo
error means z is about standard normal: its mean near 0 and few |z| above 3. The bounds
allow for heavy tails: rare bright paths make a pixel's mean skewed (a render that misses
them is dark and has a small spread, so z leans negative), and rtfgu's standard error comes
from SEEDS renders (Student's t with SEEDS - 1 degrees of freedom: 0.9 % beyond 3 for 15).
The median ratio rtfgu / Mitsuba over all pixels is known to about 0.05 %, so a bias of 1 %
of the radiance fails it (test_a_one_percent_bias_is_caught). Pixels darker than 1e-3 (the
box's open front) are left out.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from benchmark_scripts import benchmark_script
from rtfgu import PathTrace, render
from rtfgu.scenes.meshes import cornell_box_area_light

DATA = Path(__file__).resolve().parent / "data" / "cornell_mitsuba.npz"
SEEDS = 16
SPP = {"numba": 256, "wgpu": 128}      # per seed; llvmpipe is slower


def cornell():
    """The box with its blocks, every face a path-traced Matte (kd 1: its albedo is its
    colour, as Mitsuba's diffuse reflectance), path traced to full depth, no sampler of its
    own (render's spp)."""
    scene = cornell_box_area_light()
    scene.tracer = PathTrace()
    scene.sampler = None
    return scene


def benchmark_scene():
    """benchmarks/cornell_reference.py's scene: the box of cornell(), its lamp's two
    triangles one Rectangle (ceiling_lamp)."""
    scene = benchmark_script("cornell_reference").cornell_scene()
    scene.tracer = PathTrace()
    return scene


def z_scores(path, bias=1.0, scene=cornell):
    peer = np.load(DATA)
    size = int(peer["width"])
    images = np.array([render(scene(), size, size, backend=path.backend, precision=path.precision,
                              spp=SPP[path.backend], seed=1000 + seed) for seed in range(SEEDS)])
    mean = images.mean(axis=0) * bias
    stderr = images.std(axis=0, ddof=1) * bias / np.sqrt(SEEDS)
    lit = peer["mean"] > 1e-3
    z = (mean[lit] - peer["mean"][lit]) / np.sqrt(stderr[lit] ** 2 + peer["stderr"][lit].astype(float) ** 2)
    return z, mean[lit] / peer["mean"][lit]


def agrees(z, ratio) -> list:
    """The failed criteria, empty when rtfgu agrees with Mitsuba within the Monte Carlo error."""
    failed = []
    if abs(z.mean()) > 0.25:
        failed.append("mean z %.3f (|mean| > 0.25)" % z.mean())
    if (np.abs(z) > 3).mean() > 0.03:
        failed.append("%.2f %% of |z| > 3 (> 3 %%)" % (100 * (np.abs(z) > 3).mean()))
    if abs(np.median(ratio) - 1) > 0.005:
        failed.append("median ratio rtfgu / Mitsuba %.4f" % np.median(ratio))
    return failed


def test_the_reference_is_precise():
    peer = np.load(DATA)
    lit = peer["mean"] > 1e-3
    assert int(peer["spp"]) >= 16384
    assert np.median(peer["stderr"][lit] / peer["mean"][lit]) < 0.01
    assert np.all(np.isfinite(peer["mean"]))


def test_rtfgu_agrees_with_mitsuba_per_pixel(fast_path):
    z, ratio = z_scores(fast_path)
    failed = agrees(z, ratio)
    assert not failed, "%s against Mitsuba 3: %s" % (fast_path.label, "; ".join(failed))


@pytest.mark.parametrize("bias", [0.99, 1.01])
def test_a_one_percent_bias_is_caught(bias):
    class Numba:
        backend, precision = "numba", "float32"
    z, ratio = z_scores(Numba(), bias)
    assert agrees(z, ratio), "a %+.0f %% bias passed the comparison" % (100 * (bias - 1))


def test_the_benchmarks_rectangle_lamp_agrees_with_mitsuba():
    """The path-tracing benchmark's scene lights the box with one Rectangle where the quad's
    two triangles were (one shadow ray a vertex instead of two): the same light, so the
    same image as the reference, which Mitsuba made from the triangles."""
    class Numba:
        backend, precision = "numba", "float32"
    scene = benchmark_scene()
    lamps = [light.shape for light in scene.lights]
    assert [type(shape).__name__ for shape in lamps] == ["Rectangle"]
    assert lamps[0].normal.y == -1.0                     # facing down, into the box, as the triangles
    assert not any(type(s).__name__ == "MeshTriangle" and s.material is lamps[0].material for s in scene.shapes)
    z, ratio = z_scores(Numba(), scene=benchmark_scene)
    failed = agrees(z, ratio)
    assert not failed, "the rectangle lamp against Mitsuba 3: %s" % "; ".join(failed)


def test_the_rectangle_lamp_is_refused_for_other_lights():
    from rtfgu.lights import PointLight
    from rtfgu.float3 import Float3
    scene = benchmark_scene()
    scene.lights.append(PointLight(Float3(0.3, 0.5, 0.3), Float3(1.0)))
    with pytest.raises(ValueError, match="ceiling_lamp: the scene's lights"):
        benchmark_script("cornell_reference").ceiling_lamp(scene)
