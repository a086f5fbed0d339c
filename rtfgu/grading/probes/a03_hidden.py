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


def observe_closest(rt):
    """The slide's inner loop: every shape in turn, the last one that reports a hit is the
    closest. All shapes lie in front of the rays (z < 0, rays from z = 5 toward -z)."""
    cases = Cases()
    F = rt.Float3

    def shapes():
        return [rt.Sphere(F(0, 0, -2), 1.0, F(1, 0, 0)), rt.Sphere(F(0.5, 0.3, -1), 0.6, F(0, 1, 0)),
                rt.Plane(F(0, 0, -4), F(0, 0.3, 1), F(0, 0, 1)),
                rt.Triangle(F(-2, -2, 0.5), F(2, -2, 0.5), F(0, 2, 0.5), F(1, 1, 0)),
                rt.Sphere(F(-1, -1, -1.5), 0.8, F(1, 0, 1))]

    for px, py in [(0, 0), (0.5, 0.3), (-1, -1), (1.8, 1.8), (-0.3, 1.2), (2.5, -2.5), (0.1, -0.9)]:
        def run(px=px, py=py):
            ray = rt.Ray(F(px * 0.2, py * 0.2, 5.0), F(px, py, -5.0))
            last = -1
            for i, shape in enumerate(shapes()):
                if boolean(shape.intersect_p(ray), "intersect_p's return value"):
                    last = i
            return {"closest shape": last, "ray.tmax": num(ray.tmax, "ray.tmax")}
        cases.run("the ray toward (%g, %g, 0) through two spheres, a plane, a triangle and a sphere" % (px, py), run)
    return cases.result()
