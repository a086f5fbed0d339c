"""Ray against the lecture-01 "Ray" slides: defaults, fields and the point at t."""
from __future__ import annotations

import math

from rtfgu import RAY_EPSILON, Float3, Ray


def components(v):
    return (v.x, v.y, v.z)


def test_defaults_are_the_slide_defaults():
    # Ray(origin = Float3(0,0,0), direction = Float3(0,0,1), tmin = 0, tmax = INFINITY)
    r = Ray()
    assert components(r.origin) == (0.0, 0.0, 0.0)
    assert components(r.direction) == (0.0, 0.0, 1.0)
    assert r.tmin == 0.0
    assert r.tmax == math.inf


def test_fields_as_given():
    r = Ray(Float3(1, 2, 3), Float3(0, -1, 0), 0.5, 7.0)
    assert components(r.origin) == (1.0, 2.0, 3.0)
    assert components(r.direction) == (0.0, -1.0, 0.0)
    assert (r.tmin, r.tmax) == (0.5, 7.0)


def test_point_at_t_is_origin_plus_t_direction():
    r = Ray(Float3(1, 2, 3), Float3(0, 0.6, -0.8))
    assert components(r(0)) == (1.0, 2.0, 3.0)
    p = r(5)
    assert p.x == 1.0
    assert math.isclose(p.y, 2 + 3.0, abs_tol=1e-15)
    assert math.isclose(p.z, 3 - 4.0, abs_tol=1e-15)
    # a negative t is still a point of the line, behind the origin
    q = r(-10)
    assert math.isclose(q.y, 2 - 6.0, abs_tol=1e-15) and math.isclose(q.z, 3 + 8.0, abs_tol=1e-15)


def test_point_at_t_with_a_non_unit_direction():
    r = Ray(Float3(0, 0, 0), Float3(2, 0, 0))
    assert components(r(1.5)) == (3.0, 0.0, 0.0)


def test_point_at_t_does_not_move_the_ray():
    r = Ray(Float3(1, 1, 1), Float3(1, 0, 0))
    r(3)
    assert components(r.origin) == (1.0, 1.0, 1.0)
    assert components(r.direction) == (1.0, 0.0, 0.0)


def test_ray_epsilon_is_the_slide_value():
    assert RAY_EPSILON == 0.00001
