"""Shading and radiometry of 02562 weeks 1-3, each value worked out by hand:
Kepler's inverse square law, Lambert's cosine law with the ambient term, hard shadows,
emission, the Phong lobe, mirror and refraction directions, and the bounded path loop."""
from __future__ import annotations

import math

import pytest

from rtfgu import (BASE_COLOR, GLOSSY, LAMBERTIAN, MIRROR, PHONG, TRANSPARENT, Float3, HitInfo, Material,
                   Matte, OrthographicCamera, Phong, PinholeCamera, Plane, PointLight, Ray, Reflective, Scene,
                   Sphere, Transparent, Whitted, render, trace)
from rtfgu.ray import SPAWN_EPSILON
from rtfgu.tracers import MAX_DEPTH

C = (0.5, 0.4, 0.2)            # the surface colour used below
I = (3.0, 6.0, 9.0)            # a point light's intensity
LIGHT_AT = Float3(1, 2, 0)     # seen from the origin: r^2 = 5, cos(theta) = 2 / sqrt 5


def components(v):
    return (v.x, v.y, v.z)


def close3(v, expected, rel=1e-12, abs_=1e-12):
    got = components(v)
    assert all(math.isclose(a, b, rel_tol=rel, abs_tol=abs_) for a, b in zip(got, expected)), \
        "got %r, expected %r" % (got, expected)
    return True


def floor_scene(material=None, color=C, light_at=LIGHT_AT, intensity=I):
    """The floor y = 0 with one point light; the eye ray below looks straight down at the origin.
    The material is the 02562 diffuse shader's (Matte: ka 0.1, kd 0.9) unless given."""
    scene = Scene(OrthographicCamera(-1, 1, -1, 1))
    scene.shapes.append(Plane(Float3(0, 0, 0), Float3(0, 1, 0), Float3(*color),
                              Matte() if material is None else material))
    scene.lights.append(PointLight(light_at, Float3(*intensity)))
    return scene


def down_at_origin():
    return Ray(Float3(0, 1, 0), Float3(0, -1, 0))


def lambert_by_hand(color=C, intensity=I, r2=5.0, cos_theta=2 / math.sqrt(5)):
    """L_o = rho_d / pi * I / r^2 * cos(theta) + L_a, rho_d = 0.9 colour, L_a = 0.1 colour."""
    return tuple(0.9 * c / math.pi * i / r2 * cos_theta + 0.1 * c for c, i in zip(color, intensity))


# --- Kepler: L_i = I / |p - x|^2 toward the light ------------------------------------------

def test_sample_point_light_kepler():
    light = PointLight(Float3(0, 3, 4), Float3(2, 4, 8))
    sample = light.sample(Float3(0, 0, 0))
    assert sample.dist == 5.0
    close3(sample.L_i, (2 / 25, 4 / 25, 8 / 25))
    close3(sample.w_i, (0.0, 0.6, 0.8))
    # from another point: p - x = (-2, 2, 1), |.| = 3
    sample = light.sample(Float3(2, 1, 3))
    assert sample.dist == pytest.approx(3.0, rel=1e-15)
    close3(sample.L_i, (2 / 9, 4 / 9, 8 / 9))
    close3(sample.w_i, (-2 / 3, 2 / 3, 1 / 3))


def test_kepler_twice_as_far_is_a_quarter():
    light = PointLight(Float3(0, 0, 0), Float3(1, 1, 1))
    near = light.sample(Float3(0, 0, 1.5)).L_i
    far = light.sample(Float3(0, 0, 3.0)).L_i
    assert far.x == pytest.approx(near.x / 4, rel=1e-15)


# --- Lambert's cosine law, ambient, shadows, emission ---------------------------------------

def test_lambertian_radiance_by_hand():
    scene = floor_scene()
    assert scene.shapes[0].material.shader == LAMBERTIAN
    L = trace(scene, down_at_origin())
    close3(L, lambert_by_hand())


def test_lambertian_radiance_by_hand_through_render():
    # A 1x1 image: its only ray is the pinhole camera's centre ray, which goes to lookat.
    scene = floor_scene()
    scene.camera = PinholeCamera(Float3(0, 1, 0), Float3(0, 0, 0), Float3(0, 0, -1))
    image = render(scene, 1, 1)
    assert image.shape == (1, 1, 3)
    assert image[0, 0] == pytest.approx(lambert_by_hand(), rel=1e-12)


def test_lambertian_other_angle():
    # light straight above at height 2: r^2 = 4, cos(theta) = 1
    L = trace(floor_scene(light_at=Float3(0, 2, 0)), down_at_origin())
    close3(L, lambert_by_hand(r2=4.0, cos_theta=1.0))


def test_lambertian_light_below_the_surface_gives_ambient_only():
    L = trace(floor_scene(light_at=Float3(1, -2, 0)), down_at_origin())
    close3(L, tuple(0.1 * c for c in C))


def test_two_lights_add():
    scene = floor_scene()
    scene.lights.append(PointLight(Float3(0, 2, 0), Float3(1, 1, 1)))
    L = trace(scene, down_at_origin())
    first = lambert_by_hand()
    second = tuple(0.9 * c / math.pi * 1 / 4 for c in C)   # r^2 = 4, cos = 1, no second ambient
    close3(L, tuple(a + b for a, b in zip(first, second)))


def test_shadowed_point_gets_ambient_only():
    scene = floor_scene()
    # a ball on the segment from the origin to the light (its centre is the midpoint)
    scene.shapes.append(Sphere(Float3(0.5, 1, 0), 0.2, Float3(1, 1, 1)))
    L = trace(scene, down_at_origin())
    close3(L, tuple(0.1 * c for c in C))
    # the same scene without shadow rays sees the light through the ball
    for light in scene.lights:
        light.set_shadows(False)
    close3(trace(scene, down_at_origin()), lambert_by_hand())


def test_occluder_beyond_the_light_casts_no_shadow():
    scene = floor_scene()
    # on the same line but past the light (t = 2 sqrt 5 > dist = sqrt 5)
    scene.shapes.append(Sphere(Float3(2, 4, 0), 0.5, Float3(1, 1, 1)))
    close3(trace(scene, down_at_origin()), lambert_by_hand())


def test_emission_adds():
    e = (0.25, 0.5, 1.0)
    L = trace(floor_scene(Matte(emission=Float3(*e))), down_at_origin())
    close3(L, tuple(a + b for a, b in zip(lambert_by_hand(), e)))


# --- Phong: (rho_d / pi + rho_s (s + 2) / (2 pi) max(w_o . w_r, 0)^s) L_i cos(theta) + L_a ---

def test_phong_lobe_by_hand():
    rho_s = (0.3, 0.2, 0.1)
    s = 4.0
    scene = floor_scene(Phong(cs=Float3(*rho_s), exp=s), light_at=Float3(1, 1, 0), intensity=(2, 2, 2))
    assert scene.shapes[0].material.shader == PHONG
    # Eye at (-1, 2, 0) looking at the origin: w_o = (-1, 2, 0)/sqrt 5. Light direction
    # w_i = (1, 1, 0)/sqrt 2, r^2 = 2, cos(theta) = 1/sqrt 2, mirrored w_r = (-1, 1, 0)/sqrt 2,
    # so w_o . w_r = 3 / sqrt 10 and (w_o . w_r)^4 = 81 / 100.
    r = Ray(Float3(-1, 2, 0), Float3(1, -2, 0) / math.sqrt(5))
    L = trace(scene, r)
    lobe = 0.81
    expected = tuple(0.1 * c + (0.9 * c / math.pi + rs * (s + 2) / (2 * math.pi) * lobe)
                     * (2 / 2) * (1 / math.sqrt(2)) for c, rs in zip(C, rho_s))
    close3(L, expected, rel=1e-9)
    # and the lobe matters: without specular the value is the Lambertian one only
    plain = trace(floor_scene(Phong(cs=Float3(0.0), exp=s), light_at=Float3(1, 1, 0), intensity=(2, 2, 2)),
                  Ray(Float3(-1, 2, 0), Float3(1, -2, 0) / math.sqrt(5)))
    close3(plain, lambert_by_hand(intensity=(2, 2, 2), r2=2.0, cos_theta=1 / math.sqrt(2)),
           rel=1e-9)


# --- mirror and refraction: the next ray of the path -----------------------------------------

def first_hit(scene, r):
    hit = HitInfo()
    assert scene.intersect(r, hit)
    return hit


class RaysSent(Whitted):
    """A tracer that traces nothing: it notes every ray a material's ``shade`` sends on (with
    its depth) and returns black for it, so that ``shade`` returns what the hit itself adds."""

    def __init__(self):
        super().__init__()
        self.sent = []

    def trace_ray(self, ray, depth=0):
        self.sent.append((ray, depth))
        return Float3(0.0)


def shade(scene, r):
    """Shade the first hit of the eye ray ``r``: (the radiance the hit adds, the rays its
    material sends on, one level deeper)."""
    tracer = RaysSent()
    scene.tracer = tracer
    tracer.world = scene
    hit = first_hit(scene, r)
    hit.ray, hit.scene = r, scene
    result = hit.material.shade(hit)
    assert all(depth == 1 for _, depth in tracer.sent)
    return result, [ray for ray, _ in tracer.sent]


def test_mirror_direction():
    scene = floor_scene(Reflective())
    assert scene.shapes[0].material.shader == MIRROR
    result, sent = shade(scene, Ray(Float3(0, 1, 0), Float3(1, -1, 0) / math.sqrt(2)))
    close3(result, (0.0, 0.0, 0.0))                       # a mirror adds only its emission
    assert len(sent) == 1                                 # the path continues, along one ray
    r = sent[0]
    close3(r.origin, (1.0, 0.0, 0.0))                     # d - 2 (d . n) n flips the y
    close3(r.direction, (1 / math.sqrt(2), 1 / math.sqrt(2), 0.0))
    assert r.tmin == SPAWN_EPSILON and r.tmax == math.inf  # a fresh interval for the new ray


def test_mirror_shows_what_it_reflects():
    scene = floor_scene(Reflective(emission=Float3(0.05, 0.05, 0.05)))
    # the reflected ray from (1, 0, 0) along (1, 1, 0)/sqrt 2 goes through (2, 1, 0)
    scene.shapes.append(Sphere(Float3(2, 1, 0), 0.3, Float3(0.2, 0.4, 0.6)))
    L = trace(scene, Ray(Float3(0, 1, 0), Float3(1, -1, 0) / math.sqrt(2)))
    close3(L, (0.25, 0.45, 0.65))
    # with nothing to reflect, the background
    scene.shapes.pop()
    scene.background = Float3(0.1, 0.3, 0.6)
    close3(trace(scene, Ray(Float3(0, 1, 0), Float3(1, -1, 0) / math.sqrt(2))), (0.15, 0.35, 0.65))


def refract_at_floor(origin, direction):
    scene = floor_scene(Transparent(ior=1.5))
    assert scene.shapes[0].material.shader == TRANSPARENT
    result, sent = shade(scene, Ray(origin, direction))
    close3(result, (0.0, 0.0, 0.0))
    assert len(sent) == 1                                 # one ray goes on: refracted, or mirrored
    r = sent[0]
    assert r.tmin == SPAWN_EPSILON and r.tmax == math.inf
    return r


def test_refraction_entering():
    # From above (d . n < 0: outside) at 45 degrees into index 1.5: sin(theta_t) =
    # sin(45)/1.5 = sqrt 2 / 3, cos(theta_t) = sqrt(1 - 2/9) = sqrt 7 / 3.
    r = refract_at_floor(Float3(0, 1, 0), Float3(1, -1, 0) / math.sqrt(2))
    close3(r.origin, (1.0, 0.0, 0.0))
    close3(r.direction, (math.sqrt(2) / 3, -math.sqrt(7) / 3, 0.0))


def test_refraction_leaving():
    # From inside the medium (below the floor, d . n > 0) at 30 degrees: Snell's
    # 1.5 sin(30) = sin(theta_t) = 0.75, cos(theta_t) = sqrt(1 - 0.5625).
    r = refract_at_floor(Float3(0, -1, 0), Float3(0.5, math.sqrt(3) / 2, 0))
    close3(r.origin, (1 / math.sqrt(3), 0.0, 0.0))
    close3(r.direction, (0.75, math.sqrt(0.4375), 0.0))


def test_total_internal_reflection():
    # From inside at sin(theta_i) = 0.8 > 1/1.5 (the critical angle): mirrored back inside.
    r = refract_at_floor(Float3(0, -0.6, 0), Float3(0.8, 0.6, 0))
    close3(r.origin, (0.8, 0.0, 0.0))
    close3(r.direction, (0.8, -0.6, 0.0))


def test_refraction_through_a_sphere_deviates_by_twice_the_bend():
    # A ray at height h = 0.5 into a unit glass sphere: theta_i = asin(0.5) at both surfaces
    # and theta_t = asin(0.5 / 1.5); it leaves turned toward the axis by 2 (theta_i - theta_t).
    scene = Scene(OrthographicCamera(-1, 1, -1, 1))
    scene.shapes.append(Sphere(Float3(0, 0, -5), 1.0, Float3(0, 0, 0), Transparent(ior=1.5)))
    r = Ray(Float3(0, 0.5, 0), Float3(0, 0, -1))
    for _ in range(2):  # in, then out
        _, sent = shade(scene, r)
        assert len(sent) == 1
        r = sent[0]
    delta = 2 * (math.asin(0.5) - math.asin(1 / 3))
    close3(r.direction, (0.0, -math.sin(delta), -math.cos(delta)), rel=1e-9, abs_=1e-12)
    assert abs((r.origin - Float3(0, 0, -5)).length() - 1.0) < 1e-12  # it left from the surface
    hit = HitInfo()
    assert not scene.intersect(r, hit)  # and does not hit the sphere a third time


def test_glass_sphere_on_axis_shows_what_is_behind():
    scene = Scene(OrthographicCamera(-1, 1, -1, 1))
    scene.shapes.append(Sphere(Float3(0, 0, -5), 1.0, Float3(0, 0, 0), Transparent(ior=1.5)))
    scene.shapes.append(Plane(Float3(0, 0, -10), Float3(0, 0, 1), Float3(0.3, 0.6, 0.9)))
    close3(trace(scene, Ray(Float3(0, 0, 0), Float3(0, 0, -1))), (0.3, 0.6, 0.9))


def test_glossy_is_phong_then_refraction():
    rho_s = (0.3, 0.2, 0.1)
    glossy = Transparent(ior=1.5, ka=0.1, kd=0.9, ks=1.0, cs=Float3(*rho_s), exp=4.0)
    assert glossy.shader == GLOSSY
    scene = floor_scene(glossy, light_at=Float3(1, 1, 0), intensity=(2, 2, 2))
    result, sent = shade(scene, Ray(Float3(-1, 2, 0), Float3(1, -2, 0) / math.sqrt(5)))
    expected = tuple(0.1 * c + (0.9 * c / math.pi + rs * 6 / (2 * math.pi) * 0.81) / math.sqrt(2)
                     for c, rs in zip(C, rho_s))
    close3(result, expected, rel=1e-9)
    # entering with sin(theta_i) = 1/sqrt 5: sin(theta_t) = 1 / (1.5 sqrt 5)
    sin_t = 1 / (1.5 * math.sqrt(5))
    assert len(sent) == 1                                 # the path continues, refracted
    close3(sent[0].direction, (sin_t, -math.sqrt(1 - sin_t ** 2), 0.0), rel=1e-9, abs_=1e-12)


# --- shade dispatch and the path loop ------------------------------------------------------

def test_base_color_ends_the_path_with_the_colour():
    scene = floor_scene(Material(), color=(0.7, 0.1, 0.3))
    assert scene.shapes[0].material.shader == BASE_COLOR
    result, sent = shade(scene, down_at_origin())
    close3(result, (0.7, 0.1, 0.3))
    assert sent == []  # the path stops here


def test_hit_info_starts_empty():
    hit = HitInfo()
    assert hit.has_hit is False and hit.dist == 0.0
    assert hit.shader == BASE_COLOR


def test_miss_is_background():
    scene = floor_scene()
    scene.background = Float3(0.1, 0.3, 0.6)
    close3(trace(scene, Ray(Float3(0, 1, 0), Float3(0, 1, 0))), (0.1, 0.3, 0.6))


def test_show_ray_direction():
    scene = floor_scene()
    scene.show_ray_direction = True
    close3(trace(scene, Ray(Float3(0, 1, 0), Float3(0.6, 0, -0.8))), (0.8, 0.5, 0.1))


class CountingScene(Scene):
    def __init__(self, camera=None):
        super().__init__(camera)
        self.calls = 0

    def intersect(self, ray, hit):
        self.calls += 1
        return super().intersect(ray, hit)


def test_path_loop_stops_after_max_depth():
    # Two facing mirrors, y = 0 and y = 1: the ray bounces between them forever.
    assert MAX_DEPTH == 10
    scene = CountingScene(OrthographicCamera(-1, 1, -1, 1))
    glow = Reflective(emission=Float3(0.01, 0.02, 0.03))
    scene.shapes.append(Plane(Float3(0, 0, 0), Float3(0, 1, 0), Float3(1, 1, 1), glow))
    scene.shapes.append(Plane(Float3(0, 1, 0), Float3(0, -1, 0), Float3(1, 1, 1), glow))
    scene.background = Float3(100.0)
    L = trace(scene, Ray(Float3(0, 0.5, 0), Float3(1, 1, 0) / math.sqrt(2)))
    assert scene.calls == MAX_DEPTH
    # every bounce adds the mirrors' emission once, and the background is never reached
    close3(L, (0.1, 0.2, 0.3))


def test_path_loop_stops_at_the_first_miss():
    scene = CountingScene(OrthographicCamera(-1, 1, -1, 1))
    scene.shapes.append(Plane(Float3(0, 0, 0), Float3(0, 1, 0), Float3(1, 1, 1), Reflective()))
    scene.background = Float3(0.2)
    L = trace(scene, Ray(Float3(0, 1, 0), Float3(1, -1, 0) / math.sqrt(2)))
    assert scene.calls == 2  # the mirror, then the sky
    close3(L, (0.2, 0.2, 0.2))
