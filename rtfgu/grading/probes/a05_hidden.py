"""Probes of a05's hidden tests."""
from __future__ import annotations

from .a05 import _shadow_case
from .support import Cases


def observe_occluders_more(rt):
    cases = Cases()
    F = rt.Float3

    def shapes():
        return [rt.Sphere(F(0, 1, 0), 0.5, F(1, 1, 1)), rt.Sphere(F(2, 1, 0), 0.5, F(1, 1, 1)),
                rt.Triangle(F(-1, 2, -1), F(1, 2, -1), F(0, 2, 1), F(1, 1, 1)), rt.Plane(F(0, -1, 0), F(0, 1, 0), F(1, 1, 1))]

    for point, light in [((0, 0, 0), (0, 3, 0)), ((2, 0, 0), (2, 3, 0)), ((1, 0, 0), (1, 3, 0)),
                         ((0, 0, 0), (0, 1.8, 0)), ((0, 0, 0), (0, 0.4, 0)), ((3, 0, 0), (0, 3, 0)),
                         ((-2, 0, 0), (0, 3, 0))]:
        _shadow_case(rt, cases, "in_shadow from (%g, %g, %g) toward a light at (%g, %g, %g) among two spheres, "
                     "a triangle and a plane" % (tuple(point) + tuple(light)), shapes, point, light)
    return cases.result()
