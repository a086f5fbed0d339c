"""The directional light (Suffern's Directional, 02562 worksheet 5) on every path: the same
radiance from one direction everywhere, no inverse square law, and a shadow ray with no
end but the shapes. Expected values are exact: the inputs are dyadic, and with an intensity
of pi the Lambertian term rho_d / pi * L_i * cos is rho_d * cos."""
from __future__ import annotations

import math

import pytest

from rtfgu import Directional, Float3, OrthographicCamera, Plane, Scene, Sphere
from rtfgu.layout import compile_scene
from rtfgu.materials import Matte
from rtfgu.materials.matte import KA_02562 as AMBIENT_FRACTION, KD_02562 as DIFFUSE_FRACTION

CLOSE = {"float64": 1e-14, "float32": 1e-6}
COLOR = (0.5, 0.25, 1.0)


def lit_floor(shadows: bool) -> Scene:
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes.append(Plane(Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), Float3(*COLOR), Matte()))
    # Far along the light's way back from x = 100: it hides that point, 10^6 away, from the light.
    scene.shapes.append(Sphere(Float3(100.0 + 3e5, 4e5, 0.0), 10.0, Float3(1.0), Matte()))
    # Toward the light (3, 4, 0), the light travelling along (-3, -4, 0): w_i = (0.6, 0.8, 0),
    # cos = 0.8 on the floor.
    light = Directional(Float3(3.0, 4.0, 0.0), Float3(math.pi))
    light.set_shadows(shadows)
    scene.lights.append(light)
    return scene


def expected(cos_theta: float) -> tuple:
    return tuple(c * AMBIENT_FRACTION + c * DIFFUSE_FRACTION * cos_theta for c in COLOR)


def close(got, want, precision) -> bool:
    return all(abs(g - w) <= CLOSE[precision] * max(1.0, abs(w)) for g, w in zip(got, want))


@pytest.mark.parametrize("shadows", [False, True])
def test_a_directional_light_lights_a_floor_alike_everywhere(path, shadows):
    rays = [((x, 1.0, z), (0.0, -1.0, 0.0), 0.0, math.inf) for x, z in ((0.0, 0.0), (-50.0, 7.0), (1e4, -3e3))]
    for bounces in path.trace(lit_floor(shadows), rays):
        assert close(bounces[0].color, expected(0.8), path.precision), (path, bounces[0].color)


def test_a_shape_anywhere_along_the_way_back_casts_a_shadow(path):
    rays = [((100.0, 1.0, 0.0), (0.0, -1.0, 0.0), 0.0, math.inf)]
    lit = path.trace(lit_floor(False), rays)[0][0].color
    shadowed = path.trace(lit_floor(True), rays)[0][0].color
    assert close(lit, expected(0.8), path.precision)
    assert close(shadowed, expected(0.0), path.precision), (path, shadowed)


def test_light_from_below_adds_nothing(path):
    scene = lit_floor(False)
    # toward the light (0, -1, 0): it shines up, on the floor's back
    scene.lights[0] = Directional(Float3(0.0, -1.0, 0.0), Float3(math.pi))
    scene.lights[0].set_shadows(False)
    bounce = path.trace(scene, [((0.0, 1.0, 0.0), (0.0, -1.0, 0.0), 0.0, math.inf)])[0][0]
    assert close(bounce.color, expected(0.0), path.precision)


def test_point_and_directional_lights_add_up(path):
    from rtfgu import PointLight

    scene = lit_floor(False)
    scene.lights.append(PointLight(Float3(0.0, 2.0, 0.0), Float3(4 * math.pi)))
    scene.lights[1].set_shadows(False)
    bounce = path.trace(scene, [((0.0, 1.0, 0.0), (0.0, -1.0, 0.0), 0.0, math.inf)])[0][0]
    # The point light 2 above: L_i = 4 pi / 4 = pi, cos = 1.
    want = tuple(a + c * DIFFUSE_FRACTION for a, c in zip(expected(0.8), COLOR))
    assert close(bounce.color, want, path.precision), (path, bounce.color, want)


def test_a_scene_with_only_a_directional_light_lays_out_no_point_lights():
    flat = compile_scene(lit_floor(True))
    assert len(flat.lights["point_light"]) == 0 and len(flat.lights["directional"]) == 1
    assert "directional" in flat.features and "point_light" not in flat.features


@pytest.mark.parametrize("direction, intensity, field", [
    ((0.0, 0.0, 0.0), (1.0, 1.0, 1.0), "Directional.direction"),
    ((0.0, float("nan"), 1.0), (1.0, 1.0, 1.0), "Directional.direction"),
    ((0.0, -1.0, 0.0), (1.0, float("inf"), 1.0), "Directional.intensity"),
])
def test_bad_directional_lights_name_the_field(direction, intensity, field):
    with pytest.raises(ValueError, match=field.replace(".", r"\.")):
        Directional(direction, intensity)
