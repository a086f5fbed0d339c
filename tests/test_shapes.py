"""Plane, Sphere and Triangle: hits worked out by hand from the slide formulas, the ray
interval [tmin, tmax), and intersect_p's one side effect (it shrinks tmax on a hit)."""
from __future__ import annotations

import itertools
import math

import pytest

from rtfgu import Float3, HitInfo, Plane, Ray, Scene, Shape, Sphere, Triangle

RED = Float3(1, 0, 0)
GREEN = Float3(0, 1, 0)
BLUE = Float3(0, 0, 1)
WHITE = Float3(1, 1, 1)


def components(v):
    return (v.x, v.y, v.z)


def close3(v, expected, tol=1e-12):
    return all(math.isclose(a, b, abs_tol=tol) for a, b in zip(components(v), expected))


def down_z(x=0.0, y=0.0, z=0.0, tmin=0.0, tmax=math.inf):
    return Ray(Float3(x, y, z), Float3(0, 0, -1), tmin, tmax)


def test_shape_is_abstract():
    with pytest.raises(TypeError):
        Shape(RED)


# --- Plane: t = ((a - o) . n) / (d . n) -------------------------------------------------

def test_plane_head_on():
    plane = Plane(Float3(0, 0, -5), Float3(0, 0, 1), RED)
    r = down_z()
    assert plane.intersect_p(r) is True
    assert r.tmax == 5.0


def test_plane_normal_need_not_be_unit_or_face_the_ray():
    # t does not depend on the length or the sign of n: ((a-o).n)/(d.n) scales both alike.
    for normal in (Float3(0, 0, 2), Float3(0, 0, -1), Float3(0, 0, -0.25)):
        r = down_z()
        assert Plane(Float3(3, -7, -5), normal, RED).intersect_p(r)
        assert r.tmax == 5.0


def test_plane_oblique():
    # The floor y = 0 seen from (0, 2, 0) along (1, -1, 0)/sqrt 2: it is 2 sqrt 2 away.
    plane = Plane(Float3(0, 0, 0), Float3(0, 1, 0), GREEN)
    r = Ray(Float3(0, 2, 0), Float3(1, -1, 0) / math.sqrt(2))
    assert plane.intersect_p(r)
    assert r.tmax == pytest.approx(2 * math.sqrt(2), rel=1e-15)
    assert close3(r(r.tmax), (2.0, 0.0, 0.0))


def test_plane_parallel_ray_is_a_miss_without_exception():
    plane = Plane(Float3(0, 0, 0), Float3(0, 1, 0), GREEN)
    above = Ray(Float3(0, 1, 0), Float3(1, 0, 0), 0.0, 50.0)
    assert plane.intersect_p(above) is False
    assert above.tmax == 50.0
    # even a ray lying in the plane: d . n = 0 and (a - o) . n = 0 would be 0/0 in C++
    inside = Ray(Float3(0, 0, 0), Float3(0, 0, 1), 0.0, 50.0)
    assert plane.intersect_p(inside) is False
    assert inside.tmax == 50.0


def test_plane_behind_the_ray_is_a_miss():
    plane = Plane(Float3(0, 0, 5), Float3(0, 0, 1), RED)
    r = down_z(tmax=100.0)
    assert plane.intersect_p(r) is False  # t = -5 < tmin
    assert r.tmax == 100.0


def test_plane_respects_tmin_and_tmax():
    plane = Plane(Float3(0, 0, -5), Float3(0, 0, 1), RED)
    # the interval is [tmin, tmax): t = 5 is in [5, 6) and not in [0, 5)
    assert plane.intersect_p(down_z(tmin=5.0, tmax=6.0))
    assert not plane.intersect_p(down_z(tmax=5.0))
    assert not plane.intersect_p(down_z(tmax=5.0 - 1e-9))
    assert plane.intersect_p(down_z(tmax=5.0 + 1e-9))
    assert not plane.intersect_p(down_z(tmin=5.0 + 1e-9))


def test_plane_normal_at_is_unit():
    plane = Plane(Float3(0, 0, 0), Float3(0, 3, 4), RED)
    assert close3(plane.normal_at(Float3(9, 9, 9)), (0.0, 0.6, 0.8))


# --- Sphere: a t^2 + b t + c = 0, the least root in [tmin, tmax) ---------------------------

def unit_sphere_at_minus_5():
    return Sphere(Float3(0, 0, -5), 1.0, BLUE)


def test_sphere_near_root():
    # o - c = (0, 0, 5), d = (0, 0, -1): a = 1, b = -10, c = 24, roots 4 and 6
    r = down_z()
    assert unit_sphere_at_minus_5().intersect_p(r)
    assert r.tmax == 4.0


def test_sphere_off_axis():
    # x = 0.6 from the axis: the ray meets z = -5 + 0.8 (0.6^2 + 0.8^2 = 1), so t = 4.2
    r = down_z(x=0.6)
    assert unit_sphere_at_minus_5().intersect_p(r)
    assert r.tmax == pytest.approx(4.2, rel=1e-14)


def test_sphere_non_unit_direction():
    # d = (0, 0, -2): a = 4, b = -20, c = 24, roots 2 and 3
    r = Ray(Float3(0, 0, 0), Float3(0, 0, -2))
    assert unit_sphere_at_minus_5().intersect_p(r)
    assert r.tmax == 2.0


def test_sphere_ray_starting_inside_gets_the_far_root():
    # from the centre the roots are -1 and +1; the near one is behind the origin
    r = down_z(z=-5.0)
    assert unit_sphere_at_minus_5().intersect_p(r)
    assert r.tmax == 1.0
    # from z = -4.5: roots -0.5 and 1.5
    r = down_z(z=-4.5)
    assert unit_sphere_at_minus_5().intersect_p(r)
    assert r.tmax == 1.5


def test_sphere_tangent_and_near_miss():
    r = down_z(x=1.0)  # discriminant exactly 0: one touching point at t = 5
    assert unit_sphere_at_minus_5().intersect_p(r)
    assert r.tmax == 5.0
    r = down_z(x=1.0 + 1e-6, tmax=100.0)
    assert not unit_sphere_at_minus_5().intersect_p(r)
    assert r.tmax == 100.0


def test_sphere_behind_the_ray_is_a_miss():
    r = down_z(z=-10.0, tmax=100.0)  # roots -6 and -4
    assert not unit_sphere_at_minus_5().intersect_p(r)
    assert r.tmax == 100.0


def test_sphere_respects_tmin_and_tmax():
    s = unit_sphere_at_minus_5()
    assert not s.intersect_p(down_z(tmax=4.0))          # 4 is not in [0, 4)
    assert s.intersect_p(down_z(tmax=4.0 + 1e-9))
    r = down_z(tmin=4.0 + 1e-9)                          # near root excluded: far root 6
    assert s.intersect_p(r) and r.tmax == 6.0
    assert not s.intersect_p(down_z(tmin=4.0 + 1e-9, tmax=6.0))
    assert not s.intersect_p(down_z(tmin=6.0 + 1e-9))


def test_sphere_normal_at():
    s = Sphere(Float3(1, 2, 3), 2.0, BLUE)
    assert close3(s.normal_at(Float3(1, 4, 3)), (0.0, 1.0, 0.0))
    assert close3(s.normal_at(Float3(1, 2, 1)), (0.0, 0.0, -1.0))


# --- Triangle: 02562 barycentric formula ------------------------------------------------
# v0 = (0,0,-2), v1 = (1,0,-2), v2 = (0,1,-2): e0 = +x, e1 = +y, n = +z. For a ray from
# (x, y, 0) along -z: a = v0 - o = (-x, -y, -2), a x w = (y, -x, 0), w . n = -1, so
# beta = ((a x w) . e1) / (w . n) = x and gamma = -((a x w) . e0) / (w . n) = y.

def unit_triangle():
    return Triangle(Float3(0, 0, -2), Float3(1, 0, -2), Float3(0, 1, -2), RED)


def test_triangle_interior_hit():
    r = down_z(0.25, 0.25)
    assert unit_triangle().intersect_p(r)
    assert r.tmax == 2.0


@pytest.mark.parametrize("x, y", [
    (0.5, 0.0), (0.0, 0.5), (0.5, 0.5),   # on the edges gamma = 0, beta = 0, beta + gamma = 1
    (0.0, 0.0), (1.0, 0.0), (0.0, 1.0),   # the vertices
])
def test_triangle_edges_are_inside(x, y):
    r = down_z(x, y)
    assert unit_triangle().intersect_p(r)
    assert r.tmax == 2.0


@pytest.mark.parametrize("x, y", [
    (0.5, -1e-9),           # gamma < 0
    (-1e-9, 0.5),           # beta < 0
    (0.5 + 1e-9, 0.5),      # beta + gamma > 1
    (0.6, 0.6), (2.0, 2.0), (-0.1, -0.1),
])
def test_triangle_just_outside_the_edges(x, y):
    r = down_z(x, y, tmax=100.0)
    assert not unit_triangle().intersect_p(r)
    assert r.tmax == 100.0


def test_triangle_from_the_back():
    r = Ray(Float3(0.25, 0.25, -4), Float3(0, 0, 1))
    assert unit_triangle().intersect_p(r)
    assert r.tmax == 2.0


def test_triangle_parallel_ray_is_a_miss_without_exception():
    r = Ray(Float3(0.25, 0.25, -2), Float3(1, 0, 0), 0.0, 100.0)
    assert not unit_triangle().intersect_p(r)
    assert r.tmax == 100.0


def test_triangle_respects_tmin_and_tmax():
    t = unit_triangle()
    assert not t.intersect_p(down_z(0.25, 0.25, tmax=2.0))
    assert t.intersect_p(down_z(0.25, 0.25, tmax=2.0 + 1e-9))
    assert t.intersect_p(down_z(0.25, 0.25, tmin=2.0))
    assert not t.intersect_p(down_z(0.25, 0.25, tmin=2.0 + 1e-9))


def test_triangle_02562_default_triangle():
    # (-0.2, 0.1, 0.9), (0.2, 0.1, 0.9), (-0.2, 0.1, -0.1) lies in y = 0.1: e0 = (0.4, 0, 0),
    # e1 = (0, 0, -1). A ray down from (0, 1, 0.5) meets y = 0.1 at t = 0.9, at
    # v0 + 0.5 e0 + 0.4 e1: beta = 0.5, gamma = 0.4, inside.
    tri = Triangle(Float3(-0.2, 0.1, 0.9), Float3(0.2, 0.1, 0.9), Float3(-0.2, 0.1, -0.1), RED)
    r = Ray(Float3(0, 1, 0.5), Float3(0, -1, 0))
    assert tri.intersect_p(r)
    assert r.tmax == pytest.approx(0.9, rel=1e-15)
    # x = 0.1, z = 0.1: beta = 0.75, gamma = 0.8, sum > 1: outside
    assert not tri.intersect_p(Ray(Float3(0.1, 1, 0.1), Float3(0, -1, 0)))


def test_triangle_normal_at():
    # n = e0 x e1 = x cross y = +z, whatever side the ray comes from
    assert close3(unit_triangle().normal_at(Float3(0.2, 0.2, -2)), (0.0, 0.0, 1.0))


# --- intersect_p shrinks tmax on a hit and changes nothing else ---------------------------

SHAPES_AND_HITS = [
    (lambda: Plane(Float3(0, 0, -5), Float3(0, 0, 1), RED), 5.0),
    # the ray passes sqrt(0.05^2 + 0.1^2) from the centre: t = 5 - sqrt(1 - 0.0125)
    (lambda: Sphere(Float3(0.1, 0.2, -5), 1.0, RED), 5 - math.sqrt(1 - 0.0125)),
    (lambda: Triangle(Float3(-1, -1, -3), Float3(1, -1, -3), Float3(0, 1, -3), RED), 3.0),
]


@pytest.mark.parametrize("make, t_hit", SHAPES_AND_HITS, ids=["plane", "sphere", "triangle"])
def test_intersect_p_changes_only_tmax(make, t_hit):
    shape = make()
    origin = Float3(0.05, 0.1, 0.0)
    direction = Float3(0, 0, -1)
    r = Ray(origin, direction, 0.25, 50.0)
    assert shape.intersect_p(r)
    assert components(r.origin) == (0.05, 0.1, 0.0)
    assert components(r.direction) == (0.0, 0.0, -1.0)
    assert r.tmin == 0.25
    assert r.tmax == pytest.approx(t_hit, rel=1e-14)
    # the shape is not changed either: a fresh ray gets the same answer from it
    again = Ray(origin, direction, 0.25, 50.0)
    assert shape.intersect_p(again) and again.tmax == r.tmax


@pytest.mark.parametrize("make, t_hit", SHAPES_AND_HITS, ids=["plane", "sphere", "triangle"])
def test_intersect_p_changes_nothing_on_a_miss(make, t_hit):
    shape = make()
    origin = Float3(0.05, 0.1, 0.0)
    direction = Float3(0, 0, 1)  # away from every shape above
    r = Ray(origin, direction, 0.25, 50.0)
    assert not shape.intersect_p(r)
    assert components(r.origin) == (0.05, 0.1, 0.0)
    assert components(r.direction) == (0.0, 0.0, 1.0)
    assert (r.tmin, r.tmax) == (0.25, 50.0)


# --- the closest hit regardless of the order of the shapes --------------------------------

def stacked_shapes():
    """Along the ray from the origin down -z: triangle at t = 3, sphere at 4 (centre -5),
    another sphere at 6 (centre -7.5), plane at 10; each in its own colour."""
    return [
        Plane(Float3(0, 0, -10), Float3(0, 0, 1), WHITE),
        Sphere(Float3(0, 0, -7.5), 1.5, GREEN),
        Sphere(Float3(0, 0, -5), 1.0, BLUE),
        Triangle(Float3(-0.5, -0.5, -3), Float3(0.5, -0.5, -3), Float3(0, 0.5, -3), RED),
    ]


@pytest.mark.parametrize("order", list(itertools.permutations(range(4))))
def test_closest_hit_regardless_of_order(order):
    shapes = [stacked_shapes()[i] for i in order]
    # the slide's loop: every hit shrinks tmax, so the last shape to report a hit is nearest
    r = down_z()
    hit_shape = None
    for shape in shapes:
        if shape.intersect_p(r):
            hit_shape = shape
    assert isinstance(hit_shape, Triangle) and r.tmax == 3.0

    # and Scene.intersect, which fills the HitInfo from that shape
    scene = Scene()
    scene.shapes = shapes
    hit = HitInfo()
    assert scene.intersect(down_z(), hit)
    assert hit.has_hit and hit.dist == 3.0
    assert components(hit.color) == (1.0, 0.0, 0.0)
    assert components(hit.position) == (0.0, 0.0, -3.0)
    assert components(hit.normal) == (0.0, 0.0, 1.0)

    # a ray that passes beside the triangle finds the blue sphere at t = 4
    hit = HitInfo()
    assert scene.intersect(down_z(x=0.0, y=-0.75), hit)
    assert components(hit.color) == (0.0, 0.0, 1.0)
    assert hit.dist == pytest.approx(5 - math.sqrt(1 - 0.75 ** 2), rel=1e-14)


def test_scene_intersect_miss_leaves_hit_empty():
    scene = Scene()
    scene.shapes = stacked_shapes()
    hit = HitInfo()
    r = Ray(Float3(0, 0, 0), Float3(0, 0, 1), 0.0, math.inf)
    assert scene.intersect(r, hit) is False
    assert hit.has_hit is False
    assert r.tmax == math.inf
