"""Bad input never reaches the kernels: the numba backend raises the lecture layer's own
ValueError for what the lecture layer rejects, and the compile step (rtfgu.layout) names the
field for what only a flat layout cannot hold."""
from __future__ import annotations

import math

import pytest

from rtfgu import Float3, PointLight, Sphere
from rtfgu.renderer import render
from rtfgu.scenes import SCENES
from rtfgu.shapes import Shape


def default():
    return SCENES["default_lambertian_shadows"]()


def spoil_camera(scene):
    scene.camera = "camera"


def spoil_shape(scene):
    scene.shapes.append((0, 0, 0))


def spoil_light(scene):
    scene.lights.append(Float3(0, 1, 0))


def spoil_background(scene):
    scene.background = (math.nan, 0.0, 0.0)


@pytest.mark.parametrize("spoil", [spoil_camera, spoil_shape, spoil_light, spoil_background])
def test_scene_errors_are_the_lecture_layers(spoil):
    messages = []
    for backend in ("reference", "numba"):
        scene = default()
        spoil(scene)
        with pytest.raises(ValueError) as error:
            render(scene, 8, 8, backend=backend)
        messages.append(str(error.value))
    assert messages[0] == messages[1]
    assert messages[0].startswith("Scene.")


@pytest.mark.parametrize("width, height", [(0, 8), (8, -1), (True, 8), (8, 2.5)])
def test_size_errors_are_the_lecture_layers(width, height):
    messages = []
    for backend in ("reference", "numba"):
        with pytest.raises(ValueError) as error:
            render(default(), width, height, backend=backend)
        messages.append(str(error.value))
    assert messages[0] == messages[1]


def test_unknown_precision_is_refused():
    with pytest.raises(ValueError, match="precision"):
        render(default(), 8, 8, backend="numba", precision="float16")


def test_a_value_spoiled_after_construction_is_named():
    # The constructor checked the radius; a later assignment is caught by the compile step.
    scene = default()
    sphere = next(s for s in scene.shapes if isinstance(s, Sphere))
    sphere.radius = math.nan
    with pytest.raises(ValueError, match="spheres"):
        render(scene, 8, 8, backend="numba")


@pytest.mark.filterwarnings("ignore:overflow encountered")
def test_a_value_that_overflows_float32_is_named():
    scene = default()
    scene.lights[0] = PointLight(Float3(0.0, 1.0, 0.0), Float3(1e39, 1e39, 1e39))
    assert render(scene, 4, 4, backend="numba", precision="float64").shape == (4, 4, 3)
    with pytest.raises(ValueError, match="lights.*float32"):
        render(scene, 4, 4, backend="numba", precision="float32")


def test_a_shape_the_layout_does_not_know_is_named():
    class Disk(Shape):
        def intersect_p(self, ray):
            return False

        def normal_at(self, position):
            return Float3(0, 1, 0)

    scene = default()
    scene.shapes.append(Disk(Float3(1, 1, 1)))
    with pytest.raises(ValueError, match=r"Scene.shapes\[3\].*Disk"):
        render(scene, 8, 8, backend="numba")
