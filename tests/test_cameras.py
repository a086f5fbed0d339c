"""Cameras: the lecture-01 OrthographicCamera line for line, and the 02562 pinhole camera."""
from __future__ import annotations

import math

import pytest

from rtfgu import RAY_EPSILON, Camera, Float3, OrthographicCamera, PinholeCamera


def components(v):
    return (v.x, v.y, v.z)


def close3(v, expected, tol=1e-12):
    return all(math.isclose(a, b, abs_tol=tol) for a, b in zip(components(v), expected))


def test_camera_is_abstract():
    with pytest.raises(TypeError):
        Camera()


# --- orthographic ----------------------------------------------------------------------
#   sx = 0.5 + sx / 2;  x = left + (right - left) * sx   (same for y with bottom, top)
#   return Ray(Float3(x, y, hither), Float3(0, 0, -1), 0.00001, yon - hither)

@pytest.mark.parametrize("sx, sy, x, y", [
    (-1, -1, -4.0, -1.0),   # bottom left corner
    (1, -1, 2.0, -1.0),     # bottom right
    (-1, 1, -4.0, 3.0),     # top left
    (1, 1, 2.0, 3.0),       # top right
    (0, 0, -1.0, 1.0),      # centre: halfway between left and right, bottom and top
    (0.5, -0.5, 0.5, 0.0),  # sx -> 0.75: -4 + 6 * 0.75; sy -> 0.25: -1 + 4 * 0.25
])
def test_orthographic_gen_ray(sx, sy, x, y):
    cam = OrthographicCamera(-4.0, 2.0, -1.0, 3.0, hither=0.5, yon=10.0)
    r = cam.gen_ray(sx, sy)
    assert components(r.origin) == (x, y, 0.5)
    assert components(r.direction) == (0.0, 0.0, -1.0)
    assert r.tmin == 0.00001
    assert r.tmax == 10.0 - 0.5


def test_orthographic_defaults_hither_ray_epsilon_yon_infinity():
    cam = OrthographicCamera(-1, 1, -1, 1)
    assert cam.hither == RAY_EPSILON and cam.yon == math.inf
    r = cam.gen_ray(0, 0)
    assert components(r.origin) == (0.0, 0.0, RAY_EPSILON)
    assert r.tmax == math.inf


def test_orthographic_rays_are_independent():
    # Each call returns a fresh ray; shrinking one ray's tmax does not affect the next.
    cam = OrthographicCamera(-1, 1, -1, 1, yon=5.0)
    r = cam.gen_ray(0, 0)
    r.tmax = 1.0
    assert cam.gen_ray(0, 0).tmax == 5.0 - RAY_EPSILON


# --- pinhole ---------------------------------------------------------------------------
# v = normalize(lookat - eye), b1 = normalize(v x up), b2 = b1 x v,
# direction = normalize(b1 * sx * aspect / 2 + b2 * sy / 2 + v * d).

def simple_pinhole(d=1.0, aspect=1.0):
    # Looking down -z from the origin with +y up: then b1 = +x and b2 = +y, worked out as
    # (0,0,-1) x (0,1,0) = (0*0 - (-1)*1, (-1)*0 - 0*0, 0*1 - 0*0) = (1, 0, 0) and
    # (1,0,0) x (0,0,-1) = (0*(-1) - 0*0, 0*0 - 1*(-1), 1*0 - 0*0) = (0, 1, 0).
    return PinholeCamera(Float3(0, 0, 0), Float3(0, 0, -1), Float3(0, 1, 0), d=d, aspect=aspect)


def test_pinhole_simple_basis():
    cam = simple_pinhole()
    assert components(cam.v) == (0.0, 0.0, -1.0)
    assert components(cam.b1) == (1.0, 0.0, 0.0)
    assert components(cam.b2) == (0.0, 1.0, 0.0)


@pytest.mark.parametrize("sx, sy, q", [
    (0, 0, (0.0, 0.0, -1.0)),
    (1, 1, (0.5, 0.5, -1.0)),
    (-1, 1, (-0.5, 0.5, -1.0)),
    (1, -1, (0.5, -0.5, -1.0)),
    (0.5, 0, (0.25, 0.0, -1.0)),
])
def test_pinhole_rays_simple(sx, sy, q):
    r = simple_pinhole().gen_ray(sx, sy)
    n = math.sqrt(sum(c * c for c in q))
    assert components(r.origin) == (0.0, 0.0, 0.0)
    assert close3(r.direction, tuple(c / n for c in q))
    assert r.direction.length() == pytest.approx(1.0, abs=1e-15)
    assert r.tmax == math.inf


def test_pinhole_aspect_stretches_x_only():
    # With aspect 2 the image plane is [-1, 1] wide and [-0.5, 0.5] high at distance d = 1.
    r = simple_pinhole(aspect=2.0).gen_ray(1, 1)
    assert close3(r.direction, (1 / 1.5, 0.5 / 1.5, -1 / 1.5))  # |(1, 0.5, -1)| = 1.5
    # sy alone is unaffected by the aspect ratio
    a = simple_pinhole(aspect=1.0).gen_ray(0, 1)
    b = simple_pinhole(aspect=2.0).gen_ray(0, 1)
    assert components(a.direction) == components(b.direction)


def test_pinhole_camera_constant_d():
    # d = 2 doubles the distance to the image plane: q = (0.5, 0.5, -2), |q| = sqrt(4.5).
    r = simple_pinhole(d=2.0).gen_ray(1, 1)
    n = math.sqrt(4.5)
    assert close3(r.direction, (0.5 / n, 0.5 / n, -2 / n))
    # The field of view narrows: the corner ray is closer to the view direction than with d = 1.
    assert -r.direction.z > -simple_pinhole(d=1.0).gen_ray(1, 1).direction.z


def test_pinhole_02562_default_camera_basis():
    # eye (2, 1.5, 2), look-at (0, 0.5, 0), up (0, 1, 0): lookat - eye = (-2, -1, -2), length 3.
    cam = PinholeCamera(Float3(2, 1.5, 2), Float3(0, 0.5, 0), Float3(0, 1, 0), d=1.0)
    assert close3(cam.v, (-2 / 3, -1 / 3, -2 / 3))
    # v x up = (-v.z, 0, v.x) = (2/3, 0, -2/3) -> b1 = (1, 0, -1) / sqrt 2
    s2 = math.sqrt(2)
    assert close3(cam.b1, (1 / s2, 0.0, -1 / s2))
    # b1 x v = (-1/3, 4/3, -1/3) / sqrt 2, already of unit length
    assert close3(cam.b2, (-1 / (3 * s2), 4 / (3 * s2), -1 / (3 * s2)))


def test_pinhole_centre_ray_points_at_lookat():
    cam = PinholeCamera(Float3(2, 1.5, 2), Float3(0, 0.5, 0), Float3(0, 1, 0), d=1.0)
    r = cam.gen_ray(0, 0)
    assert components(r.origin) == (2.0, 1.5, 2.0)
    assert close3(r(3.0), (0.0, 0.5, 0.0))  # |lookat - eye| = 3


def test_pinhole_top_of_image_is_up():
    # sy = 1 tilts the ray toward up, sx = 1 toward b1 (to the right when looking along v).
    cam = PinholeCamera(Float3(2, 1.5, 2), Float3(0, 0.5, 0), Float3(0, 1, 0), d=1.0)
    centre = cam.gen_ray(0, 0).direction
    assert cam.gen_ray(0, 1).direction.y > centre.y
    assert cam.gen_ray(0, -1).direction.y < centre.y


def test_pinhole_rays_do_not_share_the_eye():
    # In C++ the Ray holds its origin by value; moving a generated ray must not move the camera.
    cam = simple_pinhole()
    r = cam.gen_ray(0, 0)
    r.origin += Float3(1, 1, 1)
    assert components(cam.gen_ray(0, 0).origin) == (0.0, 0.0, 0.0)
    assert components(cam.eye) == (0.0, 0.0, 0.0)
