"""Probes of a03's visible tests: ray-plane, ray-sphere, ray-triangle intersection and the
normals (lecture 01, "Ray-Plane Intersection", "Ray-Sphere Intersection"; 02562 week 2)."""
from __future__ import annotations

import math

from .support import Cases, boolean, num, vec

INF = math.inf


def _ray_label(o, d, tmin, tmax):
    return "the ray from (%g, %g, %g) along (%g, %g, %g) with tmin %g, tmax %s" % (
        tuple(o) + tuple(d) + (tmin, "infinity" if tmax == INF else "%g" % tmax))


def _hit_case(rt, cases, label, make_shape, o, d, tmin=1e-5, tmax=INF, **inputs):
    def run():
        F = rt.Float3
        ray = rt.Ray(F(*o), F(*d), tmin, tmax)
        hit = boolean(make_shape().intersect_p(ray), "intersect_p's return value")
        return {"returned": hit, "ray.tmax": num(ray.tmax, "ray.tmax")}
    cases.run("%s and %s" % (label, _ray_label(o, d, tmin, tmax)), run,
              o=list(o), d=list(d), tmin=tmin, tmax=tmax, **inputs)


def observe_plane(rt):
    cases = Cases()
    F = rt.Float3
    for a, n in [((0, -1, 0), (0, 1, 0)), ((0, 0, -4), (0, 0.5, 2))]:
        def make(a=a, n=n):
            return rt.Plane(F(*a), F(*n), F(1, 1, 1))
        label = "the plane through (%g, %g, %g) with normal (%g, %g, %g)" % (tuple(a) + tuple(n))
        _hit_case(rt, cases, label, make, (0, 0, 0), (0, -0.6, -0.8))
        _hit_case(rt, cases, label, make, (0, 0, 0), (0, 0.6, 0.8))            # points away: behind
        _hit_case(rt, cases, label, make, (0, 0, 0), (0, -0.6, -0.8), 1e-5, 0.5)  # beyond tmax
        _hit_case(rt, cases, label, make, (3, 2, 1), (-1, -1, -1), 1e-5, 100.0)
    parallel = lambda: rt.Plane(F(0, -1, 0), F(0, 1, 0), F(1, 1, 1))
    _hit_case(rt, cases, "the plane through (0, -1, 0) with normal (0, 1, 0)", parallel, (0, 0, 0), (1, 0, 0))
    return cases.result()


def _sphere_label(c, r):
    return "the sphere at (%g, %g, %g) with radius %g" % (tuple(c) + (r,))


def _sphere_cases(rt, rays):
    cases = Cases()
    F = rt.Float3
    for c, r, o, d, tmin, tmax in rays:
        _hit_case(rt, cases, _sphere_label(c, r), lambda c=c, r=r: rt.Sphere(F(*c), r, F(1, 1, 1)),
                  o, d, tmin, tmax, center=list(c), radius=r)
    return cases.result()


def observe_sphere_hits(rt):
    return _sphere_cases(rt, [
        ((0, 0, -3), 1.0, (0, 0, 0), (0, 0, -1), 1e-5, INF),
        ((0, 0, -3), 1.0, (0.5, 0.5, 0), (0, 0, -1), 1e-5, INF),
        ((1, 2, -5), 2.0, (0, 0, 0), (0.2, 0.4, -1.0), 1e-5, INF),
        ((0, 0.5, 0), 0.3, (2, 1.5, 2), (-0.6666667, -0.3333333, -0.6666667), 1e-5, INF),
    ])


def observe_sphere_misses(rt):
    return _sphere_cases(rt, [
        ((0, 0, -3), 1.0, (0, 0, 0), (0, 1, 0), 1e-5, INF),
        ((0, 0, -3), 1.0, (1.5, 0, 0), (0, 0, -1), 1e-5, INF),
        ((0, 0, -3), 1.0, (0, 0, 0), (0.6, 0, -0.8), 1e-5, INF),
        ((1, 2, -5), 0.5, (0, 0, 0), (0, 0, -1), 1e-5, INF),
    ])


def observe_sphere_interval(rt):
    return _sphere_cases(rt, [
        ((0, 0, 3), 1.0, (0, 0, 0), (0, 0, -1), 1e-5, INF),          # the sphere is behind the ray
        ((0, 0, -3), 1.0, (0, 0, -3), (0, 0, -1), 1e-5, INF),        # starts at the centre: far side
        ((0, 0, -3), 1.0, (0, 0, -2.5), (0, 0, -1), 1e-5, INF),      # starts inside
        ((0, 0, -3), 1.0, (0, 0, 0), (0, 0, -1), 1e-5, 1.5),         # both roots beyond tmax
        ((0, 0, -3), 1.0, (0, 0, 0), (0, 0, -1), 2.5, INF),          # tmin past the near root
        ((0, 0, -3), 1.0, (0, 0, 0), (0, 0, -1), 1e-5, 3.0),         # near root in, far root out
    ])


TRIANGLE = ((-1, -1, -3), (1, -1, -3), (0, 1, -3))


def observe_triangle(rt):
    cases = Cases()
    F = rt.Float3
    for v in (TRIANGLE, ((-0.2, 0.1, 0.9), (0.2, 0.1, 0.9), (-0.2, 0.1, -0.1))):
        def make(v=v):
            return rt.Triangle(F(*v[0]), F(*v[1]), F(*v[2]), F(1, 1, 1))
        label = "the triangle %s" % (tuple(v),)
        centroid = [sum(p[i] for p in v) / 3 for i in range(3)]
        above = (centroid[0], centroid[1] + 2, centroid[2] + 0.5)
        to = lambda p, o: tuple(p[i] - o[i] for i in range(3))
        corners = dict(v0=list(v[0]), v1=list(v[1]), v2=list(v[2]))   # the known mistakes' inputs
        _hit_case(rt, cases, label, make, above, to(centroid, above), **corners)            # centroid
        _hit_case(rt, cases, label, make, above, to((v[0][0] - 0.3, v[0][1], v[0][2] - 0.3), above),
                  **corners)                                                                  # outside by v0
        _hit_case(rt, cases, label, make, above, to((v[1][0] + 0.3, v[1][1], v[1][2] + 0.05), above), **corners)
        _hit_case(rt, cases, label, make, above, to(above, centroid), **corners)           # pointing away
        _hit_case(rt, cases, label, make, above, to(centroid, above), 1e-5, 0.5, **corners)  # beyond tmax
    def slide_triangle():
        return rt.Triangle(F(*TRIANGLE[0]), F(*TRIANGLE[1]), F(*TRIANGLE[2]), F(1, 1, 1))
    label = "the triangle %s" % (TRIANGLE,)
    corners = dict(v0=list(TRIANGLE[0]), v1=list(TRIANGLE[1]), v2=list(TRIANGLE[2]))
    _hit_case(rt, cases, label, slide_triangle, (0.9, 0.9, 0), (0, 0, -1), **corners)
    # The boundaries the slides define, with inputs whose arithmetic is exact: a ray in the
    # triangle's plane (w . n = 0) misses; a point on the edge v1 v2 (beta + gamma = 1
    # exactly) is inside; a hit at t = tmax is outside [tmin, tmax).
    _hit_case(rt, cases, label + " (a ray in its plane, parallel to it)", slide_triangle,
              (-2, -0.5, -3), (1, 0, 0), **corners)
    _hit_case(rt, cases, label + " (through the edge v1 v2, beta + gamma = 1)", slide_triangle,
              (0.5, 0, 0), (0, 0, -1), **corners)
    _hit_case(rt, cases, label + " (the hit at exactly t = tmax = 3)", slide_triangle,
              (0, 0, 0), (0, 0, -1), 1e-5, 3.0, **corners)
    return cases.result()


def observe_normals(rt):
    cases = Cases()
    F = rt.Float3

    def normal_case(label, make, point):
        def run():
            n = vec(make().normal_at(F(*point)), "normal_at's result")
            return {"normal": n, "its length": math.sqrt(sum(x * x for x in n))}
        cases.run("%s at (%g, %g, %g)" % ((label,) + tuple(point)), run)

    for c, r, p in [((0, 0.5, 0), 0.3, (0, 0.8, 0)), ((1, 2, -5), 2.0, (1, 2, -3)),
                    ((0, 0, -3), 1.0, (0.6, 0, -2.2))]:
        normal_case("the sphere at (%g, %g, %g) with radius %g: normal_at" % (tuple(c) + (r,)),
                    lambda c=c, r=r: rt.Sphere(F(*c), r, F(1, 1, 1)), p)
    normal_case("the plane with normal (0, 2, 0): normal_at", lambda: rt.Plane(F(0, 0, 0), F(0, 2, 0), F(1, 1, 1)),
                (3, 0, 1))
    normal_case("the triangle %s: normal_at" % (TRIANGLE,), lambda: rt.Triangle(
        F(*TRIANGLE[0]), F(*TRIANGLE[1]), F(*TRIANGLE[2]), F(1, 1, 1)), (0, 0, -3))
    return cases.result()
