"""The render-level choice of sphere test: ``formula="slide"`` (lecture 01's quadratic) or
``"robust"`` (Ray Tracing Gems ch. 7) on the numba and wgpu paths, and the slide formula only
on the reference.

The float64 agreement of both formulas with the reference on every homework scene is in
test_numba_parity.py (parametrised by formula). Here: the argument itself, the WGSL
assembler's choice of file, and a far, small sphere in float32, where b^2 - 4ac cancels and
the slide formula gets most pixels wrong.
"""
from __future__ import annotations

import numpy as np
import pytest

from rtfgu.cameras import PinholeCamera
from rtfgu.float3 import Float3
from rtfgu.image import to_8bit
from rtfgu.layout import compile_scene
from rtfgu.lights import PointLight
from rtfgu.materials import Matte
from rtfgu.renderer import render
from rtfgu.scene import Scene
from rtfgu.scenes import SCENES
from rtfgu.shapes import Plane, Sphere, Triangle

from wgsl_support import wgpu_device  # noqa: F401  (fixture)

SIZE = 32
DISTANCE = 1e4
# The robust image may miss the reference by more than 1/255 on at most this share of pixels
# (the hit position o + d t still rounds at the eye's scale, ulp(1e4) ~ 1e-3 in float32).
MAX_WRONG_ROBUST = 0.01


def far_small_sphere() -> Scene:
    """A sphere of radius 1 at distance 1e4, filling 80 % of a narrow pinhole view, lit by a
    point light near it (no shadows, so that a self-shadowed hit point does not count). The
    plane and the triangle lie behind the eye, out of every ray's reach: the scene has the
    default scene's kinds, and so the same compiled kernels."""
    eye = Float3(0.0, 0.0, DISTANCE)
    # The image plane's half height 0.5 at camera constant d: tan(half angle) = 0.5 / d.
    camera = PinholeCamera(eye, Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), d=0.4 * DISTANCE)
    scene = Scene(camera)
    scene.background = Float3(0.1, 0.3, 0.6)
    material = Matte()
    behind = 2.0 * DISTANCE
    scene.shapes.append(Plane(Float3(0.0, 0.0, behind), Float3(0.0, 0.0, 1.0),
                              Float3(0.1, 0.7, 0.0), material))
    scene.shapes.append(Triangle(Float3(-1.0, 0.0, behind), Float3(1.0, 0.0, behind),
                                 Float3(0.0, 1.0, behind), Float3(0.4, 0.3, 0.2), material))
    scene.shapes.append(Sphere(Float3(0.0, 0.0, 0.0), 1.0, Float3(0.8, 0.6, 0.4), material))
    scene.lights.append(PointLight(Float3(3.0, 4.0, 5.0), Float3(150.0, 150.0, 150.0)))
    scene.lights[0].set_shadows(False)
    return scene


_reference = {}


def wrong_pixels(image):
    """Pixels with a channel more than 1/255 off the float64 reference after to_8bit."""
    if "image" not in _reference:
        _reference["image"] = to_8bit(render(far_small_sphere(), SIZE, SIZE)).astype(int)
    ref = _reference["image"]
    assert 0.3 < (ref != ref[0, 0]).any(axis=2).mean() < 0.9  # the sphere fills the view
    return int((np.abs(to_8bit(image).astype(int) - ref) > 1).any(axis=2).sum())


def test_far_small_sphere_numba_float32_robust_beats_slide():
    wrong = {f: wrong_pixels(render(far_small_sphere(), SIZE, SIZE, backend="numba",
                                    precision="float32", formula=f))
             for f in ("slide", "robust")}
    assert wrong["robust"] < wrong["slide"], wrong
    assert wrong["robust"] <= MAX_WRONG_ROBUST * SIZE * SIZE, wrong


def test_far_small_sphere_wgpu_robust_beats_slide(wgpu_device):
    wrong = {f: wrong_pixels(render(far_small_sphere(), SIZE, SIZE, backend="wgpu", formula=f))
             for f in ("slide", "robust")}
    assert wrong["robust"] < wrong["slide"], wrong
    assert wrong["robust"] <= MAX_WRONG_ROBUST * SIZE * SIZE, wrong


def test_far_small_sphere_float64_formulas_agree():
    """In float64 the slide formula still has its digits at 1e4: both match the reference."""
    for f in ("slide", "robust"):
        image = render(far_small_sphere(), SIZE, SIZE, backend="numba", precision="float64",
                       formula=f)
        assert wrong_pixels(image) == 0, f


def test_reference_computes_the_slide_formula_only():
    scene = SCENES["lecture01_flat_colors"]()
    assert np.array_equal(render(scene, 4, 4, formula="slide"), render(scene, 4, 4))
    with pytest.raises(ValueError, match="formula"):
        render(scene, 4, 4, formula="robust")


@pytest.mark.parametrize("backend", ["reference", "numba", "wgpu"])
def test_unknown_formula_is_a_value_error(backend):
    with pytest.raises(ValueError, match="formula"):
        render(SCENES["lecture01_flat_colors"](), 4, 4, backend=backend, formula="quadratic")


def test_numba_default_formula_is_the_declared_one():
    from rtfgu.kernels import DEFAULT_SPHERE_FORMULA

    scene = SCENES["default_glossy_sphere"]
    images = {f: render(scene(), 16, 16, backend="numba", formula=f)
              for f in (None, "slide", "robust")}
    assert np.array_equal(images[None], images[DEFAULT_SPHERE_FORMULA])
    # The formulas differ in the last bits on the sphere, so the comparison can fail.
    assert not np.array_equal(images["slide"], images["robust"])


def test_assembler_takes_intersect_sphere_from_the_formula_file():
    from rtfgu.wgsl import assemble
    from rtfgu.registry import SHAPE_BY_NAME
    from rtfgu.wgsl.assemble import DEFAULT_SPHERE_FORMULA

    flat = compile_scene(SCENES["default_glossy_sphere"](), "float32")
    sources = {f: assemble(flat, formula=f) for f in ("slide", "robust")}
    assert "b * b - 4.0 * a * c" in sources["slide"].source
    assert "b * b - 4.0 * a * c" not in sources["robust"].source
    assert "(b / a) * d" in sources["robust"].source
    for f, program in sources.items():
        assert program.source.count("fn intersect_sphere(") == 1
        assert SHAPE_BY_NAME["sphere"].formula_file(f) in program.pieces
    assert assemble(flat).source == sources[DEFAULT_SPHERE_FORMULA].source
    # A student's own intersect_sphere.wgsl is used whatever the formula.
    own = "fn intersect_sphere(r: Ray, hit: ptr<function, HitInfo>, center: vec3f, radius: f32) -> bool { return false; }"
    for f in ("slide", "robust"):
        program = assemble(flat, overrides={"intersect_sphere.wgsl": own}, formula=f)
        assert own in program.source and "(b / a)" not in program.source


def test_wgpu_formulas_both_render_the_default_scene(wgpu_device):
    scene = SCENES["default_glossy_sphere"]
    ref = to_8bit(render(scene(), 24, 24, backend="numba", precision="float32", formula="slide"))
    for f in ("slide", "robust"):
        image = to_8bit(render(scene(), 24, 24, backend="wgpu", formula=f))
        assert (np.abs(image.astype(int) - ref.astype(int)) <= 1).mean() >= 0.99, f
