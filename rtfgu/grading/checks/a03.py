"""a03: ray-plane, ray-sphere, ray-triangle intersection and the closest hit
(lecture 01, "Ray-Plane Intersection", "Ray-Sphere Intersection"; 02562 week 2)."""
from __future__ import annotations

import math

from . import Check, image_check, register
from .child import Cases, boolean, num, vec

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


def _interval_hint(inputs, want, got):
    """Hints every shape shares: the interval and what a miss leaves alone."""
    if got.get("returned") is True and want["returned"] is False:
        t = got.get("ray.tmax")
        if isinstance(t, float) and t < inputs["tmin"]:
            return ("you accepted t = %.6g, which is less than ray.tmin = %g (behind the ray's start): "
                    "a hit needs tmin <= t < tmax" % (t, inputs["tmin"]))
        if isinstance(t, float) and t >= inputs["tmax"]:
            return "you accepted t = %.6g, which is not less than ray.tmax = %g: a hit needs tmin <= t < tmax" % (
                t, inputs["tmax"])
    if got.get("returned") is want["returned"] is False and got.get("ray.tmax") != want["ray.tmax"]:
        return "on a miss, intersect_p must leave ray.tmax as it was"
    if got.get("returned") is True and want["returned"] is True and got.get("ray.tmax") == inputs["tmax"]:
        return "on a hit, intersect_p must set ray.tmax to the hit distance t"
    return None


# --- plane ---------------------------------------------------------------------------

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


# --- sphere --------------------------------------------------------------------------

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


# ### BEGIN HIDDEN
def observe_sphere_long_directions(rt):
    return _sphere_cases(rt, [
        ((0, 0, -3), 1.0, (0, 0, 0), (0, 0, -2), 1e-5, INF),
        ((1, 2, -5), 2.0, (0, 0, 0), (0.6, 1.2, -3.0), 1e-5, INF),
        ((0, 0, -3), 1.0, (0.5, 0, 0), (0, 0, -0.25), 1e-5, INF),
    ])
# ### END HIDDEN


# ### BEGIN STAFF
def _roots(inputs, disc_sign=-1.0):
    o, d, c, r = inputs["o"], inputs["d"], inputs["center"], inputs["radius"]
    oc = [o[i] - c[i] for i in range(3)]
    a = sum(x * x for x in d)
    b = 2 * sum(oc[i] * d[i] for i in range(3))
    cc = sum(x * x for x in oc) - r * r
    disc = b * b + disc_sign * 4 * a * cc
    if disc < 0:
        return a, b, cc, disc, ()
    e = math.sqrt(disc)
    return a, b, cc, disc, ((-b - e) / (2 * a), (-b + e) / (2 * a))
# ### END STAFF


# ### BEGIN STAFF
def hint_sphere(inputs, want, got):
    t = got.get("ray.tmax")
    a, b, c, disc, roots = _roots(inputs)
    _, _, _, wrong_disc, wrong_roots = _roots(inputs, +1.0)
    if isinstance(t, float) and got.get("returned") is True and any(
            abs(t - w) < 1e-6 * max(1.0, abs(w)) for w in wrong_roots) and not any(
            abs(t - w) < 1e-6 * max(1.0, abs(w)) for w in roots):
        return ("your t is a root of b^2 + 4ac instead of the discriminant b^2 - 4ac: "
                "check the sign in the discriminant")
    if want["returned"] is False and got.get("returned") is True and disc < 0:
        return ("this ray misses the sphere (b^2 - 4ac = %.6g < 0) but your code reports a hit: "
                "check the discriminant, b^2 - 4ac, and its sign" % disc)
    interval = _interval_hint(inputs, want, got)
    if interval:
        return interval
    if isinstance(t, float) and len(roots) == 2 and abs(t - roots[1]) < 1e-6 * max(1.0, abs(t)) \
            and want["ray.tmax"] != t:
        return "you returned the far root; the near one, (-b - sqrt(b^2 - 4ac)) / 2a, comes first when it is in range"
    if isinstance(t, float) and a != 1.0 and any(abs(t - w * a) < 1e-6 * max(1.0, abs(t)) for w in roots):
        return "your t is off by the factor d . d: keep a = d . d in the quadratic (the direction need not be a unit vector)"
    if isinstance(t, float) and a != 1.0:
        disc_one = b * b - 4 * c
        if disc_one >= 0:
            e = math.sqrt(disc_one)
            if any(abs(t - w) < 1e-6 * max(1.0, abs(t)) for w in ((-b - e) / 2, (-b + e) / 2)):
                return ("your t solves t^2 + b t + c = 0, as if a = d . d were 1; here d . d = %.6g: keep a in "
                        "the quadratic, the direction need not be a unit vector" % a)
    return None
# ### END STAFF


# --- triangle ------------------------------------------------------------------------

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
        _hit_case(rt, cases, label, make, above, to(centroid, above))                       # centroid
        _hit_case(rt, cases, label, make, above, to((v[0][0] - 0.3, v[0][1], v[0][2] - 0.3), above))  # outside by v0
        _hit_case(rt, cases, label, make, above, to((v[1][0] + 0.3, v[1][1], v[1][2] + 0.05), above))
        _hit_case(rt, cases, label, make, above, to(above, centroid))                      # pointing away
        _hit_case(rt, cases, label, make, above, to(centroid, above), 1e-5, 0.5)            # beyond tmax
    def slide_triangle():
        return rt.Triangle(F(*TRIANGLE[0]), F(*TRIANGLE[1]), F(*TRIANGLE[2]), F(1, 1, 1))
    label = "the triangle %s" % (TRIANGLE,)
    _hit_case(rt, cases, label, slide_triangle, (0.9, 0.9, 0), (0, 0, -1))
    # The boundaries the slides define, with inputs whose arithmetic is exact: a ray in the
    # triangle's plane (w . n = 0) misses; a point on the edge v1 v2 (beta + gamma = 1
    # exactly) is inside; a hit at t = tmax is outside [tmin, tmax).
    _hit_case(rt, cases, label + " (a ray in its plane, parallel to it)", slide_triangle,
              (-2, -0.5, -3), (1, 0, 0))
    _hit_case(rt, cases, label + " (through the edge v1 v2, beta + gamma = 1)", slide_triangle,
              (0.5, 0, 0), (0, 0, -1))
    _hit_case(rt, cases, label + " (the hit at exactly t = tmax = 3)", slide_triangle,
              (0, 0, 0), (0, 0, -1), 1e-5, 3.0)
    return cases.result()


def hint_triangle(inputs, want, got):
    if want["returned"] is False and got.get("returned") is True and isinstance(got.get("ray.tmax"), float) \
            and inputs["tmin"] <= got["ray.tmax"] < inputs["tmax"]:
        return ("the ray meets the triangle's plane outside the triangle: a hit needs beta >= 0, "
                "gamma >= 0 and beta + gamma <= 1")
    return _interval_hint(inputs, want, got)


# --- normals -------------------------------------------------------------------------

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


def hint_normals(inputs, want, got):
    length = got.get("its length")
    if isinstance(length, float) and abs(length - 1.0) > 1e-6:
        return ("your normal has length %.6g, not 1: normal_at must return a unit vector "
                "(normalize it; for a sphere, divide position - center by the radius)" % length)
    return None


# --- the closest hit over many shapes -------------------------------------------------------

# ### BEGIN HIDDEN
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
# ### END HIDDEN


register("a03_intersections", [
    Check("Plane.intersect_p: hits, misses and the ray interval", 2, observe_plane, hint=_interval_hint,
          needs=("shapes/plane.py",)),
    Check("Sphere.intersect_p: rays that hit", 2, observe_sphere_hits, hint="hint_sphere",
          needs=("shapes/sphere.py",)),
    Check("Sphere.intersect_p: rays that miss", 1, observe_sphere_misses, hint="hint_sphere",
          needs=("shapes/sphere.py",)),
    Check("Sphere.intersect_p: only t in [tmin, tmax) counts", 2, observe_sphere_interval, hint="hint_sphere",
          needs=("shapes/sphere.py",)),
    Check("Triangle.intersect_p: inside, outside and the ray interval", 2, observe_triangle, hint=hint_triangle,
          needs=("shapes/triangle.py",)),
    Check("normal_at: unit normals of sphere, plane and triangle", 1, observe_normals, hint=hint_normals),
    image_check("image: lecture 01 scene, the closest hit in flat colours", 2, "lecture01_flat_colors"),
    image_check("image: 02562 default scene in flat colours", 2, "default_flat_colors"),
    # ### BEGIN HIDDEN
    Check("the closest hit among five shapes", 2, observe_closest, visibility="hidden", hint=_interval_hint),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    Check("Sphere.intersect_p with directions that are not unit vectors", 1, observe_sphere_long_directions,
          visibility="hidden", hint="hint_sphere", needs=("shapes/sphere.py",)),
    # ### END HIDDEN
])
