"""Cameras: the lecture-01 OrthographicCamera line for line, and the 02562 pinhole camera."""
from __future__ import annotations

import math

import pytest

import rtfgu
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


# --- Suffern ch. 11-12: fish-eye, spherical panoramic, stereo -----------------------------
# The simple basis again: eye at the origin looking down -z, up +y, so b1 = +x, b2 = +y,
# v = -z, and Suffern's (u, v, w) = (+x, +y, +z). Expected directions are worked out by
# hand from the book's formulas, their sines and cosines exact (mpmath at 50 digits).

import mpmath  # noqa: E402
import numpy as np  # noqa: E402

from rtfgu import FishEye, Matte, Plane, PointLight, Scene, Sphere, Spherical, StereoCamera  # noqa: E402
from rtfgu.cameras.camera import BLANK_TMAX, BLANK_TMIN  # noqa: E402

mpmath.mp.dps = 50
ORIGIN, LOOK, UP = Float3(0, 0, 0), Float3(0, 0, -1), Float3(0, 1, 0)


def degrees(a):
    return mpmath.pi * a / 180


def is_blank(r):
    return r.tmin == BLANK_TMIN and r.tmax == BLANK_TMAX and BLANK_TMAX < BLANK_TMIN


# FishEye::ray_direction: r = |pn|, psi = r psi_max, (cos alpha, sin alpha) = pn / r,
# d = sin psi cos alpha u + sin psi sin alpha v - cos psi w.
@pytest.mark.parametrize("psi_max, sx, sy, r, cos_a, sin_a", [
    (90, 1.0, 0.0, 1, 1, 0),          # the right edge: 90 degrees to the right
    (90, 0.0, 0.5, 0.5, 0, 1),        # halfway up: 45 degrees up
    (90, 0.6, 0.8, 1, 0.6, 0.8),      # on the circle, alpha with cos 3/5, sin 4/5
    (120, 0.3, -0.4, 0.5, 0.6, -0.8), # r 1/2 of 120: 60 degrees, below and to the right
    (180, 0.0, -1.0, 1, 0, -1),       # psi_max 180 at the circle: straight back
])
def test_fish_eye_direction_by_hand(psi_max, sx, sy, r, cos_a, sin_a):
    psi = degrees(mpmath.mpf(r) * psi_max)
    expected = (mpmath.sin(psi) * cos_a, mpmath.sin(psi) * sin_a, -mpmath.cos(psi))
    ray = FishEye(ORIGIN, LOOK, UP, psi_max=psi_max).gen_ray(sx, sy)
    assert close3(ray.direction, tuple(float(c) for c in expected), tol=1e-15)
    assert components(ray.origin) == (0.0, 0.0, 0.0) and ray.tmax == math.inf


def test_fish_eye_centre_is_the_view_direction_exactly():
    # r = 0: psi = 0 and alpha undefined (the book's 0 / 0); the ray is v, bit for bit.
    cam = FishEye(Float3(2, 1.5, 2), Float3(0, 0.5, 0), Float3(0, 1, 0), psi_max=150)
    assert components(cam.gen_ray(0.0, 0.0).direction) == components(cam.v)


@pytest.mark.parametrize("sx, sy", [(0.8, 0.8), (1.0, 1.0), (-1.0, 0.1), (0.0, -1.0000001)])
def test_fish_eye_outside_the_circle_is_a_blank_ray(sx, sy):
    ray = FishEye(ORIGIN, LOOK, UP).gen_ray(sx, sy)
    assert is_blank(ray) and components(ray.direction) == (0.0, 0.0, -1.0)


# Spherical::ray_direction: lambda = pn.x lambda_max, psi = pn.y psi_max, phi = pi - lambda,
# theta = pi/2 - psi, d = sin theta sin phi u + cos theta v + sin theta cos phi w.
@pytest.mark.parametrize("lambda_max, psi_max, sx, sy", [
    (180, 90, 0.5, 0.0),      # 90 degrees to the right: +x
    (180, 90, 1.0, 0.0),      # the image's right edge looks straight back: +z
    (180, 90, 0.0, 1.0),      # the top edge looks straight up: +y
    (180, 90, 1 / 3, 1 / 3),  # longitude 60, latitude 30: (3/4, 1/2, -sqrt(3)/4)
    (120, 60, -0.25, -0.5),   # longitude -30, latitude -30
])
def test_spherical_direction_by_hand(lambda_max, psi_max, sx, sy):
    phi = mpmath.pi - degrees(mpmath.mpf(sx) * lambda_max)
    theta = mpmath.pi / 2 - degrees(mpmath.mpf(sy) * psi_max)
    expected = (mpmath.sin(theta) * mpmath.sin(phi), mpmath.cos(theta), mpmath.sin(theta) * mpmath.cos(phi))
    ray = Spherical(ORIGIN, LOOK, UP, lambda_max=lambda_max, psi_max=psi_max).gen_ray(sx, sy)
    assert close3(ray.direction, tuple(float(c) for c in expected), tol=1e-15)


def test_spherical_latitude_60_longitude_60_is_three_quarters():
    ray = Spherical(ORIGIN, LOOK, UP).gen_ray(1 / 3, 1 / 3)
    assert close3(ray.direction, (0.75, 0.5, -math.sqrt(3) / 4), tol=1e-15)


def test_spherical_centre_is_the_view_direction_exactly():
    cam = Spherical(Float3(2, 1.5, 2), Float3(0, 0.5, 0), Float3(0, 1, 0), lambda_max=100, psi_max=40)
    assert components(cam.gen_ray(0.0, 0.0).direction) == components(cam.v)


# StereoCamera: eye at the origin looking at (0, 0, -2), d = 1, beta with tan(beta / 2) = 1/4:
# the eyes at x = -/+ r tan(beta / 2) = -/+ 1/2, each window shifted by d tan(beta / 2) = 1/4.
# Views of 10 x 10 pixels and a gap of 2: the image is 22 pixels wide.
BETA = 2 * math.degrees(math.atan(0.25))


def stereo(viewing="parallel", gap=2):
    return StereoCamera(ORIGIN, Float3(0, 0, -2), UP, d=1.0, hres=10, vres=10, pixel_gap=gap, beta=BETA,
                        viewing=viewing)


def column_sx(c, width=22):
    return 2 * c / width - 1


@pytest.mark.parametrize("viewing, c, eye_x, q", [
    ("parallel", 5, -0.5, (0.25, 0.0, -1.0)),       # centre of the left view: the left eye
    ("parallel", 17, 0.5, (-0.25, 0.0, -1.0)),      # centre of the right view: the right eye
    ("parallel", 0, -0.5, (-0.25, 0.0, -1.0)),      # left edge: u = -aspect / 2 + 1/4
    ("parallel", 22, 0.5, (0.25, 0.0, -1.0)),       # right edge: u = aspect / 2 - 1/4
    ("transverse", 5, 0.5, (-0.25, 0.0, -1.0)),     # cross-eyed: the right eye's view on the left
    ("transverse", 17, -0.5, (0.25, 0.0, -1.0)),
])
def test_stereo_rays_by_hand(viewing, c, eye_x, q):
    ray = stereo(viewing).gen_ray(column_sx(c), 0.0)
    n = math.sqrt(sum(x * x for x in q))
    assert close3(ray.origin, (eye_x, 0.0, 0.0), tol=1e-15)
    assert close3(ray.direction, tuple(x / n for x in q), tol=1e-15)


@pytest.mark.parametrize("viewing", ["parallel", "transverse"])
def test_stereo_views_meet_at_lookat(viewing):
    cam = stereo(viewing)
    for c in (5, 17):
        ray = cam.gen_ray(column_sx(c), 0.0)
        assert close3(ray(-2.0 / ray.direction.z), (0.0, 0.0, -2.0), tol=1e-14)


def test_stereo_gap_is_blank_and_the_image_size_is_the_books():
    cam = stereo(gap=2)
    assert cam.image_size == (22, 10)
    for c in (10.5, 11.0, 11.5):
        assert is_blank(cam.gen_ray(column_sx(c), 0.3))
    assert not is_blank(cam.gen_ray(column_sx(9.5), 0.3)) and not is_blank(cam.gen_ray(column_sx(12.5), 0.3))
    # No gap: the views touch.
    assert not is_blank(stereo(gap=0).gen_ray(0.0, 0.0))


def test_stereo_beta_zero_is_the_pinhole_twice():
    cam = StereoCamera(Float3(2, 1.5, 2), Float3(0, 0.5, 0), UP, d=1.3, hres=8, vres=10, pixel_gap=0, beta=0.0)
    pinhole = PinholeCamera(Float3(2, 1.5, 2), Float3(0, 0.5, 0), UP, d=1.3, aspect=0.8)
    for view_sx in (-0.75, 0.0, 0.5):
        for half in (0, 1):     # the same point of the left and of the right view
            c = (view_sx + 1) / 2 * 8 + 8 * half
            a, b = cam.gen_ray(c / 8 - 1, 0.25), pinhole.gen_ray(view_sx, 0.25)
            assert close3(a.origin, components(b.origin), tol=1e-15)
            assert close3(a.direction, components(b.direction), tol=1e-15)


@pytest.mark.parametrize("make, field", [
    (lambda: FishEye(ORIGIN, LOOK, UP, psi_max=0.0), "FishEye.psi_max"),
    (lambda: FishEye(ORIGIN, LOOK, UP, psi_max=180.5), "FishEye.psi_max"),
    (lambda: FishEye(ORIGIN, LOOK, UP, psi_max=float("nan")), "FishEye.psi_max"),
    (lambda: FishEye(ORIGIN, ORIGIN, UP), "FishEye.lookat"),
    (lambda: FishEye(ORIGIN, LOOK, Float3(0, 0, 1)), "FishEye.up"),
    (lambda: Spherical(ORIGIN, LOOK, UP, lambda_max=0.0), "Spherical.lambda_max"),
    (lambda: Spherical(ORIGIN, LOOK, UP, lambda_max=float("inf")), "Spherical.lambda_max"),
    (lambda: Spherical(ORIGIN, LOOK, UP, psi_max=91.0), "Spherical.psi_max"),
    (lambda: Spherical(ORIGIN, LOOK, UP, psi_max=float("nan")), "Spherical.psi_max"),
    (lambda: Spherical(Float3(float("nan"), 0, 0), LOOK, UP), "Spherical.eye"),
    (lambda: StereoCamera(ORIGIN, LOOK, UP, pixel_gap=-1), "StereoCamera.pixel_gap"),
    (lambda: StereoCamera(ORIGIN, LOOK, UP, pixel_gap=2.5), "StereoCamera.pixel_gap"),
    (lambda: StereoCamera(ORIGIN, LOOK, UP, hres=0), "StereoCamera.hres"),
    (lambda: StereoCamera(ORIGIN, LOOK, UP, vres=-4), "StereoCamera.vres"),
    (lambda: StereoCamera(ORIGIN, LOOK, UP, beta=float("nan")), "StereoCamera.beta"),
    (lambda: StereoCamera(ORIGIN, LOOK, UP, beta=180.0), "StereoCamera.beta"),
    (lambda: StereoCamera(ORIGIN, LOOK, UP, d=0.0), "StereoCamera.d"),
    (lambda: StereoCamera(ORIGIN, LOOK, UP, viewing="crossed"), "StereoCamera.viewing"),
])
def test_bad_camera_names_the_field(make, field):
    with pytest.raises(ValueError, match=field.replace(".", r"\.")):
        make()


# --- the ch. 11-12 cameras on every path ----------------------------------------------------

def _stage(camera):
    scene = Scene(camera)
    scene.background = Float3(0.1, 0.3, 0.6)
    scene.shapes.append(Plane(Float3(0, 0, 0), Float3(0, 1, 0), Float3(0.8), Matte()))
    scene.shapes.append(Sphere(Float3(0, 1, 0), 1.0, Float3(0.8, 0.2, 0.1), Matte()))
    scene.lights.append(PointLight(Float3(2, 4, 3), Float3(50, 50, 50)))
    return scene


EYE, AT = Float3(0, 1.5, 5), Float3(0, 1, 0)
CAMERAS = {
    "fish_eye": (lambda: FishEye(EYE, AT, UP, psi_max=100), (15, 13)),
    "spherical": (lambda: Spherical(EYE, AT, UP, lambda_max=150, psi_max=70), (18, 9)),
    "stereo": (lambda: StereoCamera(EYE, AT, UP, d=1.5, hres=8, vres=9, pixel_gap=3, beta=12,
                                    viewing="transverse"), (19, 9)),
}


@pytest.mark.parametrize("show_ray_direction", [False, True], ids=["shaded", "ray_direction"])
@pytest.mark.parametrize("name", sorted(CAMERAS))
def test_new_cameras_render_alike_on_every_path(path, name, show_ray_direction):
    """numba float64 equals the lecture layer bit for bit, float32 and WGSL are within 1/255;
    the ray-direction image compares the directions themselves (a blank ray shows v's)."""
    make, (width, height) = CAMERAS[name]
    scene = _stage(make())
    scene.show_ray_direction = show_ray_direction
    reference = rtfgu.render(scene, width, height)
    image = rtfgu.render(scene, width, height, path.backend, path.precision)
    error = np.abs(image - reference).max()
    assert error == 0.0 if path.precision == "float64" else error <= 1 / 255, (path, error)


@pytest.mark.parametrize("name", ["fish_eye", "stereo"])
def test_pixels_a_camera_sees_nothing_through_show_the_background(path, name):
    make, (width, height) = CAMERAS[name]
    scene = _stage(make())
    image = rtfgu.render(scene, width, height, path.backend, path.precision)
    if name == "fish_eye":
        blank = [(0, 0), (0, width - 1), (height - 1, 0), (height - 1, width - 1)]   # the corners
    else:
        blank = [(row, col) for row in range(height) for col in (8, 9, 10)]      # the 3-pixel gap
    for row, col in blank:
        assert np.array_equal(image[row, col], np.float32([0.1, 0.3, 0.6]).astype(np.float64)
                              if path.precision == "float32" else [0.1, 0.3, 0.6]), (path, row, col)
    # Beside them the camera sees: the sphere at the fish-eye's centre, the floor on both
    # sides of the gap.
    seen = [(height // 2, width // 2)] if name == "fish_eye" else [(height - 1, 7), (height - 1, 11)]
    for row, col in seen:
        assert not np.allclose(image[row, col], [0.1, 0.3, 0.6], atol=0.01), (path, row, col)


@pytest.mark.parametrize("name", sorted(CAMERAS))
def test_a_scene_compiles_only_its_own_camera(name):
    """The WGSL program holds the scene's camera piece and no other camera's."""
    from rtfgu.layout import compile_scene
    from rtfgu.wgsl.assemble import pieces

    features = compile_scene(_stage(CAMERAS[name][0]())).features
    cameras = [piece for piece, _ in pieces(features) if piece.startswith("camera_")]
    assert cameras == ["camera_%s.wgsl" % name]


@pytest.mark.parametrize("name", sorted(CAMERAS))
def test_numba_float64_gen_ray_is_the_lecture_ray_bit_for_bit(name):
    """rtfgu.kernels.camera.gen_ray on the camera's layout row against gen_ray of the class,
    at the centre, on the edges, outside the fish-eye's circle and in the stereo gap."""
    from rtfgu.kernels.camera import gen_ray
    from rtfgu.layout import CAMERA_WIDTH, compile_camera

    camera = CAMERAS[name][0]()
    kind, row = compile_camera(camera)
    row = np.ascontiguousarray(row.reshape(CAMERA_WIDTH))
    rng = np.random.default_rng(7)
    points = [(0.0, 0.0), (1.0, 0.0), (-1.0, 1.0), (0.6, 0.8), (0.8, 0.8), (1.0, 1.0), (0.0, -0.37)]
    points += [tuple(p) for p in rng.uniform(-1.0, 1.0, size=(200, 2))]
    for sx, sy in points:
        expected = camera.gen_ray(sx, sy)
        origin, direction, tmin, tmax = gen_ray(kind, row, sx, sy)
        assert origin == components(expected.origin), (sx, sy)
        assert direction == components(expected.direction), (sx, sy)
        assert (tmin, tmax) == (expected.tmin, expected.tmax), (sx, sy)
