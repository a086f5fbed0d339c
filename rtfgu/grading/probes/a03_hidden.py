"""Probes of a03's hidden tests."""
from __future__ import annotations

from .a03 import INF, _sphere_cases
from .support import Cases, boolean, num


def observe_sphere_long_directions(rt):
    return _sphere_cases(rt, [
        ((0, 0, -3), 1.0, (0, 0, 0), (0, 0, -2), 1e-5, INF),
        ((1, 2, -5), 2.0, (0, 0, 0), (0.6, 1.2, -3.0), 1e-5, INF),
        ((0, 0, -3), 1.0, (0.5, 0, 0), (0, 0, -0.25), 1e-5, INF),
    ])


def _closest_case(rt, cases, label, shapes, o, d):
    """The slide's inner loop over ``shapes()`` for the ray from ``o`` along ``d``: every
    shape in turn, the last one that reports a hit is the closest."""
    F = rt.Float3

    def run():
        ray = rt.Ray(F(*o), F(*d))
        last = -1
        for i, shape in enumerate(shapes()):
            if boolean(shape.intersect_p(ray), "intersect_p's return value"):
                last = i
        return {"closest shape": last, "ray.tmax": num(ray.tmax, "ray.tmax")}
    cases.run(label, run, o=list(o), d=list(d))


def observe_closest(rt):
    """The closest hit among five shapes. All shapes lie in front of the rays (rays from
    z = 5 toward -z). In the first scene the triangle in front covers most of the others;
    in the second each kind is the nearest on some rays: a sphere first in the list, in the
    middle and last, the plane behind everything, and the triangle in front of a sphere."""
    cases = Cases()
    F = rt.Float3

    def shapes():
        return [rt.Sphere(F(0, 0, -2), 1.0, F(1, 0, 0)), rt.Sphere(F(0.5, 0.3, -1), 0.6, F(0, 1, 0)),
                rt.Plane(F(0, 0, -4), F(0, 0.3, 1), F(0, 0, 1)),
                rt.Triangle(F(-2, -2, 0.5), F(2, -2, 0.5), F(0, 2, 0.5), F(1, 1, 0)),
                rt.Sphere(F(-1, -1, -1.5), 0.8, F(1, 0, 1))]

    for px, py in [(0, 0), (0.5, 0.3), (-1, -1), (1.8, 1.8), (-0.3, 1.2), (2.5, -2.5), (0.1, -0.9)]:
        _closest_case(rt, cases, "the ray toward (%g, %g, 0) through two spheres, a plane, a triangle and a sphere"
                      % (px, py), shapes, (px * 0.2, py * 0.2, 5.0), (px, py, -5.0))

    def spread():
        return [rt.Sphere(F(-1.5, 0, -1), 0.75, F(1, 0, 0)), rt.Plane(F(0, 0, -5), F(0, 0, 1), F(0, 0, 1)),
                rt.Triangle(F(0.5, -1, 0), F(2.5, -1, 0), F(1.5, 1, 0), F(1, 1, 0)),
                rt.Sphere(F(0, 1.5, -3), 0.5, F(0, 1, 0)), rt.Sphere(F(1.5, 0, -3), 1.25, F(1, 0, 1))]

    what = "a sphere (-1.5, 0, -1), a plane z = -5, a triangle at z = 0, a sphere (0, 1.5, -3) and a sphere (1.5, 0, -3)"
    for o, d, nearest in [((-1.5, 0.25, 5), (0, 0, -2), "the first sphere"),
                          ((-1, -0.5, 5), (-0.25, 0.25, -3), "the first sphere, obliquely"),
                          ((3, 3, 5), (0, 0, -0.5), "the plane alone"),
                          ((-3, 0, 5), (1, 1, -4), "the plane, past the spheres"),
                          ((1.5, 0, 5), (0, 0, -1), "the triangle, in front of the last sphere"),
                          ((1.75, -0.5, 5), (-0.125, 0, -2), "the triangle, obliquely"),
                          ((0, 1.5, 5), (0, 0, -4), "the middle sphere"),
                          ((0.25, 1.25, 5), (-0.03125, 0.03125, -1), "the middle sphere, obliquely"),
                          ((1.5, -1.125, 5), (0, 0, -2), "the last sphere, below the triangle"),
                          ((2.5, -0.5, 5), (-0.25, 0, -8), "the last sphere, beside the triangle")]:
        _closest_case(rt, cases, "the ray from (%g, %g, %g) along (%g, %g, %g) toward %s, among %s"
                      % (tuple(o) + tuple(d) + (nearest, what)), spread, o, d)
    return cases.result()
