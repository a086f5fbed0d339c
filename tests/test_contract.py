"""Contract tests: every shape kind, every shader and the tie rule on every path (the
``path`` fixture of conftest.py: reference, numba float64 and float32, WGSL), as Mitsuba
3's variant fixtures run one test on every variant. A case traces given rays through a
small scene (rtfgu.debug.trace_rays) and checks the first bounce, so a failure reads
"numba-float32 triangle: hit at tmax", not "N pixels off".

Shape kinds come from rtfgu.registry.SHAPES: each registered kind needs an entry in
SHAPE_CASES (its shape, its rays, an exact oracle in fractions, and a shape for the tie
cases), or test_every_shape_kind_has_cases fails. Expected values are exact: the inputs
are small dyadic numbers, so the hit distances and normals are exact in both precisions.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import numpy as np
import pytest

import mpmath

from rtfgu import (Box, Dielectric, Disk, Emissive, Float3, GlossyReflector, Instance, Material, Matte, OpenCylinder,
                   OrthographicCamera, Phong, Plane, Ray, Rectangle, Reflective, Scene, Sphere, Torus, Transparent,
                   Triangle, trace)
from rtfgu.hardcases.exact import box_t, least_root, torus_quartic
from rtfgu.lights import PointLight
from rtfgu.materials.matte import KA_02562 as AMBIENT_FRACTION, KD_02562 as DIFFUSE_FRACTION
from rtfgu.ray import SPAWN_EPSILON
from rtfgu.registry import SHADERS, SHAPES, shape_kind_of
from rtfgu.shapes.annulus import Annulus
from rtfgu.shapes.concave_part_sphere import ConcavePartSphere
from rtfgu.shapes.convex_part_sphere import ConvexPartSphere
from rtfgu.shapes.mesh import Mesh
from rtfgu.shapes.open_part_cylinder import OpenPartCylinder
from rtfgu.shapes.part import azimuth

INF = math.inf
# How close a path's number must be to the exact one: a float64 path's to the last few
# bits, a float32 path's to a few float32 roundings.
CLOSE = {"float64": 1e-14, "float32": 1e-6}
GREY = (0.5, 0.25, 1.0)


@dataclass(frozen=True)
class Case:
    name: str
    origin: tuple
    direction: tuple
    tmin: float = 0.0
    tmax: float = INF
    hits: bool = True  # what the case is about; test_cases_say_what_they_test checks it

    @property
    def ray(self):
        return self.origin, self.direction, self.tmin, self.tmax


def F(v) -> tuple:
    """A vector (a Float3 or a tuple) in fractions."""
    if isinstance(v, Float3):
        v = (v.x, v.y, v.z)
    return tuple(Fraction(c) for c in v)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def exact_sqrt(q: Fraction) -> Fraction:
    n, d = math.isqrt(q.numerator), math.isqrt(q.denominator)
    assert n * n == q.numerator and d * d == q.denominator, "the test's inputs must keep %s a square" % q
    return Fraction(n, d)


def unit(v) -> tuple:
    length = exact_sqrt(dot(v, v))
    return tuple(c / length for c in v)


def in_range(t, case) -> bool:
    """The slides' interval [tmin, tmax)."""
    return t >= Fraction(case.tmin) and (case.tmax == INF or t < Fraction(case.tmax))


# The oracles: the slide formulas in fractions. (t, unit normal) or None for a miss.
def exact_plane(shape, case):
    o, d, p, n = F(case.origin), F(case.direction), F(shape.point), F(shape.normal)
    if dot(d, n) == 0:
        return None
    t = dot(sub(p, o), n) / dot(d, n)
    return (t, unit(n)) if in_range(t, case) else None


def exact_disk(shape, case):
    hit = exact_plane(Plane(shape.center, shape.normal, GREY), case)
    if hit is None:
        return None
    to_hit = sub(tuple(o + hit[0] * d for o, d in zip(F(case.origin), F(case.direction))),
                 F(shape.center))
    return hit if dot(to_hit, to_hit) <= Fraction(shape.radius) ** 2 else None


def exact_rectangle(shape, case):
    """Suffern's Rectangle::hit in fractions: the plane through p0 with normal a x b, then
    0 <= d . a <= |a|^2 and 0 <= d . b <= |b|^2 (the edges belong to it)."""
    o, d, p0, a, b = F(case.origin), F(case.direction), F(shape.p0), F(shape.a), F(shape.b)
    n = cross(a, b)
    if dot(d, n) == 0:
        return None
    t = dot(sub(p0, o), n) / dot(d, n)
    if not in_range(t, case):
        return None
    to_hit = sub(tuple(oc + t * dc for oc, dc in zip(o, d)), p0)
    if 0 <= dot(to_hit, a) <= dot(a, a) and 0 <= dot(to_hit, b) <= dot(b, b):
        return t, unit(n)
    return None


def exact_box(shape, case):
    """Suffern's slab test in fractions (an axis the ray does not move along bounds nothing
    within its slab); the normal is the outward one of the face nearest to the hit, the
    first of -x, -y, -z, +x, +y, +z (rtfgu.shapes.box)."""
    o, d, p0, p1 = F(case.origin), F(case.direction), F(shape.p0), F(shape.p1)
    t = box_t(o, d, p0, p1, Fraction(case.tmin))
    if t is None or not in_range(t, case):
        return None
    p = tuple(oc + t * dc for oc, dc in zip(o, d))
    distances = [abs(p[k] - p0[k]) for k in range(3)] + [abs(p[k] - p1[k]) for k in range(3)]
    face = distances.index(min(distances))
    return t, tuple(Fraction(-1 if face < 3 else 1) if k == face % 3 else Fraction(0) for k in range(3))


def exact_open_cylinder(shape, case, part=lambda p: True):
    """Suffern's OpenCylinder::hit in fractions: the near root, then the far one, each with
    its height in [y0, y1] (and, for a part, ``part(p)``); a ray parallel to the axis misses;
    the normal (x, 0, z) / r turned toward the ray (-d . n < 0: flipped)."""
    o, d, r = F(case.origin), F(case.direction), Fraction(shape.radius)
    a = d[0] * d[0] + d[2] * d[2]
    if a == 0:
        return None
    b = 2 * (o[0] * d[0] + o[2] * d[2])
    c = o[0] * o[0] + o[2] * o[2] - r * r
    disc = b * b - 4 * a * c
    if disc < 0:
        return None
    for t in sorted(((-b - exact_sqrt(disc)) / (2 * a), (-b + exact_sqrt(disc)) / (2 * a))):
        p = tuple(oc + t * dc for oc, dc in zip(o, d))
        if in_range(t, case) and Fraction(shape.y0) <= p[1] <= Fraction(shape.y1) and part(p):
            n = (p[0] / r, Fraction(0), p[2] / r)
            return t, (tuple(-c for c in n) if dot(d, n) > 0 else n)
    return None


def exact_torus(shape, case):
    """Suffern's Torus::hit exactly: the least real root of the book's quartic in
    [tmin, tmax), decided by Sturm's theorem in fractions and given at 50 digits
    (rtfgu.hardcases.exact.least_root); the normal is the gradient of
    (|p|^2 + a^2 - b^2)^2 - 4 a^2 (x^2 + z^2), normalised, at 50 digits."""
    o, d, a, b = F(case.origin), F(case.direction), Fraction(shape.a), Fraction(shape.b)
    t = least_root(torus_quartic(o, d, a, b), Fraction(case.tmin), None if case.tmax == INF else Fraction(case.tmax))
    if t is None:
        return None
    with mpmath.workdps(50):
        tm = mpmath.mpf(t.numerator) / t.denominator if isinstance(t, Fraction) else t
        p = [mpmath.mpf(oc.numerator) / oc.denominator + tm * mpmath.mpf(dc.numerator) / dc.denominator
             for oc, dc in zip(o, d)]
        k = p[0] ** 2 + p[1] ** 2 + p[2] ** 2 - mpmath.mpf(a) ** 2 - mpmath.mpf(b) ** 2
        g = (p[0] * k, p[1] * (k + 2 * mpmath.mpf(a) ** 2), p[2] * k)
        length = mpmath.sqrt(g[0] ** 2 + g[1] ** 2 + g[2] ** 2)
        return t, tuple(x / length for x in g)


def exact_triangle(shape, case):
    o, d = F(case.origin), F(case.direction)
    v0, e0, e1 = F(shape.v0), F(shape.e0), F(shape.e1)
    n = cross(e0, e1)
    if dot(d, n) == 0:
        return None
    a = sub(v0, o)
    t = dot(a, n) / dot(d, n)
    c = cross(a, d)
    beta, gamma = dot(c, e1) / dot(d, n), -dot(c, e0) / dot(d, n)
    if in_range(t, case) and beta >= 0 and gamma >= 0 and beta + gamma <= 1:
        return t, unit(n)
    return None


def exact_sphere(shape, case, part=lambda p: True):
    o, d, c = F(case.origin), F(case.direction), F(shape.center)
    r = Fraction(shape.radius)
    temp = sub(o, c)
    a, b, cc = dot(d, d), 2 * dot(temp, d), dot(temp, temp) - r * r
    disc = b * b - 4 * a * cc
    if disc < 0:
        return None
    for t in sorted(((-b - exact_sqrt(disc)) / (2 * a), (-b + exact_sqrt(disc)) / (2 * a))):
        if in_range(t, case) and part(tuple(oc + t * dc - cc_ for oc, dc, cc_ in zip(o, d, c))):
            return t, tuple((oc + t * dc - cc_) / r for oc, dc, cc_ in zip(o, d, c))
    return None


def phi_in_range(shape, p) -> bool:
    """The book's azimuth test: phi = atan2(x, z) in [0, 2 pi) of the exact point (its
    coordinates are small dyadic numbers, exact as floats) within the shape's [phi_min, phi_max]."""
    return shape.phi_min <= azimuth(Float3(*(float(x) for x in p))) <= shape.phi_max


def exact_part_sphere(shape, case):
    """Suffern's ConvexPartSphere::hit in fractions: the near root, then the far one, each
    when its point p - c has r cos(theta_max) <= y <= r cos(theta_min) (the cosines the
    shape keeps, exactly) and its azimuth in range; a ConcavePartSphere's normal points in."""
    r = Fraction(shape.radius)

    def part(p):
        return r * Fraction(shape.cos_theta_max) <= p[1] <= r * Fraction(shape.cos_theta_min) and phi_in_range(shape, p)

    hit = exact_sphere(shape, case, part)
    if hit is None or not isinstance(shape, ConcavePartSphere):
        return hit
    return hit[0], tuple(-c for c in hit[1])


def exact_open_part_cylinder(shape, case):
    return exact_open_cylinder(shape, case, lambda p: phi_in_range(shape, p))


def exact_annulus(shape, case):
    """The plane, then r_i^2 <= (p - c) . (p - c) <= r_o^2 (both rims belong to it)."""
    hit = exact_plane(Plane(shape.center, shape.normal, GREY), case)
    if hit is None:
        return None
    to_hit = sub(tuple(o + hit[0] * d for o, d in zip(F(case.origin), F(case.direction))), F(shape.center))
    return hit if Fraction(shape.inner_radius) ** 2 <= dot(to_hit, to_hit) <= Fraction(shape.outer_radius) ** 2 else None


def exact_mesh(shape, case):
    """A mesh face: the triangle through its vertices (the watertight test it uses has the
    slide triangle's exact answer: both accept the closed triangle)."""
    return exact_triangle(shape._triangle, case)


def exact_instance(shape, case):
    """Suffern's Instance::hit in fractions: the object's oracle on the ray through the
    inverse matrix (its float entries, exactly), then the object's normal through the inverse
    transpose, normalised (in floats: the length need not be rational)."""
    m = [[Fraction(c) for c in row] for row in shape.inv_matrix.m]
    o, d = F(case.origin), F(case.direction)
    inner = Case(case.name, tuple(m[r][0] * o[0] + m[r][1] * o[1] + m[r][2] * o[2] + m[r][3] for r in range(3)),
                 tuple(m[r][0] * d[0] + m[r][1] * d[1] + m[r][2] * d[2] for r in range(3)), case.tmin, case.tmax)
    hit = SHAPE_CASES[shape_kind_of(shape.object)[1].name].exact(shape.object, inner)
    if hit is None:
        return None
    t, n = hit
    world = tuple(m[0][c] * n[0] + m[1][c] * n[1] + m[2][c] * n[2] for c in range(3))
    length = math.sqrt(dot(world, world))
    return t, tuple(float(c) / length for c in world)


def mesh_face(v0, v1, v2, material):
    """Face 0 of a one-face mesh (the registry's "mesh" kind)."""
    return Mesh(np.array([v0, v1, v2], dtype=float), np.array([(0, 1, 2)]), GREY, material=material).triangles()[0]


@dataclass(frozen=True)
class KindCases:
    shape: object        # a function of the material: the kind's shape for `cases`
    cases: tuple
    exact: object        # (shape, case) -> (t, normal) or None
    coincident: object   # a function of the material: a shape whose first hit by TIE_RAY is at t = 2,
                         # or None for a kind no such shape of which meets the ray transversally


# Every tie shape is first hit by this ray at (0.25, 0.25, 0), t = 2.
TIE_RAY = ((0.25, 0.25, 2.0), (0.0, 0.0, -1.0), 0.0, INF)

SHAPE_CASES = {
    "plane": KindCases(
        lambda m: Plane((0.0, 0.0, 0.0), (0.0, 0.0, 2.0), GREY, m),
        (Case("hit", (0.25, 0.5, 3.0), (0.0, 0.0, -1.0)),
         Case("oblique hit", (1.0, 2.0, 4.0), (1.0, 1.0, -2.0)),
         Case("hit from below", (0.5, 0.5, -1.5), (0.0, 0.0, 1.0)),
         Case("hit at tmin", (0.0, 0.0, 3.0), (0.0, 0.0, -1.0), tmin=3.0),
         Case("miss behind the ray", (0.0, 0.0, 3.0), (0.0, 0.0, 1.0), hits=False),
         Case("ray parallel to the plane", (0.0, 0.0, 1.0), (1.0, 0.5, 0.0), hits=False),
         Case("ray in the plane", (0.0, 0.0, 0.0), (1.0, 0.0, 0.0), hits=False),
         Case("hit at tmax", (0.0, 0.0, 3.0), (0.0, 0.0, -1.0), tmax=3.0, hits=False)),
        exact_plane,
        lambda m: Plane((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), GREY, m)),
    "triangle": KindCases(
        lambda m: Triangle((0.0, 0.0, 0.0), (2.0, 0.0, 0.0), (0.0, 2.0, 0.0), GREY, m),
        (Case("hit", (0.5, 0.25, 2.0), (0.0, 0.0, -1.0)),
         Case("oblique hit", (0.0, 0.0, 1.0), (0.5, 0.25, -1.0)),
         Case("hit on the edge beta + gamma = 1", (1.0, 1.0, 2.0), (0.0, 0.0, -1.0)),
         Case("hit on the edge gamma = 0", (1.0, 0.0, 2.0), (0.0, 0.0, -1.0)),
         Case("hit on a vertex", (0.0, 2.0, 2.0), (0.0, 0.0, -1.0)),
         Case("miss beyond the edge", (1.25, 1.0, 2.0), (0.0, 0.0, -1.0), hits=False),
         Case("miss beside the triangle", (-0.25, 0.5, 2.0), (0.0, 0.0, -1.0), hits=False),
         Case("ray parallel to the triangle", (0.5, 0.25, 1.0), (1.0, 0.0, 0.0), hits=False),
         Case("hit at tmax", (0.5, 0.25, 2.0), (0.0, 0.0, -1.0), tmax=2.0, hits=False)),
        exact_triangle,
        lambda m: Triangle((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), GREY, m)),
    "sphere": KindCases(
        lambda m: Sphere((0.0, 0.0, 0.0), 1.0, GREY, m),
        (Case("hit", (0.0, 0.0, 5.0), (0.0, 0.0, -1.0)),
         Case("hit along an axis", (-4.0, 0.0, 0.0), (1.0, 0.0, 0.0)),
         Case("hit from inside (the far root)", (0.0, 0.0, 0.0), (0.0, 0.0, -1.0)),
         Case("tangent ray (the rim)", (1.0, 0.0, 5.0), (0.0, 0.0, -1.0)),
         Case("miss beside the sphere", (2.0, 0.0, 5.0), (0.0, 0.0, -1.0), hits=False),
         Case("miss behind the ray", (0.0, 0.0, -5.0), (0.0, 0.0, -1.0), hits=False),
         Case("hit at tmax (the far root beyond it)", (0.0, 0.0, 5.0), (0.0, 0.0, -1.0), tmax=4.0,
              hits=False)),
        exact_sphere,
        lambda m: Sphere((0.25, 0.25, -1.0), 1.0, GREY, m)),
    "disk": KindCases(
        lambda m: Disk((0.0, 0.0, 0.0), (0.0, 0.0, 2.0), 1.0, GREY, m),
        (Case("hit", (0.5, 0.0, 2.0), (0.0, 0.0, -1.0)),
         Case("oblique hit", (0.0, 0.0, 2.0), (0.25, 0.25, -1.0)),
         Case("hit on the rim", (1.0, 0.0, 2.0), (0.0, 0.0, -1.0)),
         Case("miss beyond the rim", (1.0, 0.25, 2.0), (0.0, 0.0, -1.0), hits=False),
         Case("ray parallel to the disk", (0.0, 0.0, 1.0), (1.0, 0.0, 0.0), hits=False),
         Case("hit at tmax", (0.5, 0.0, 2.0), (0.0, 0.0, -1.0), tmax=2.0, hits=False)),
        exact_disk,
        lambda m: Disk((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 1.0, GREY, m)),
    "rectangle": KindCases(
        lambda m: Rectangle((0.0, 0.0, 0.0), (2.0, 0.0, 0.0), (0.0, 1.0, 0.0), GREY, m),
        (Case("hit", (0.5, 0.5, 2.0), (0.0, 0.0, -1.0)),
         Case("oblique hit", (0.0, 0.0, 2.0), (0.5, 0.25, -1.0)),
         Case("hit from behind", (1.5, 0.25, -1.0), (0.0, 0.0, 1.0)),
         Case("hit on the edge d . a = |a|^2", (2.0, 0.5, 2.0), (0.0, 0.0, -1.0)),
         Case("hit on the edge d . b = 0", (1.0, 0.0, 2.0), (0.0, 0.0, -1.0)),
         Case("hit on the corner p0 + a + b", (2.0, 1.0, 2.0), (0.0, 0.0, -1.0)),
         Case("miss beyond the edge", (2.25, 0.5, 2.0), (0.0, 0.0, -1.0), hits=False),
         Case("miss beside the edge d . b = 0", (1.0, -0.25, 2.0), (0.0, 0.0, -1.0), hits=False),
         Case("ray parallel to the rectangle", (0.5, 0.5, 1.0), (1.0, 0.0, 0.0), hits=False),
         Case("grazing ray in its plane", (-1.0, 0.5, 0.0), (1.0, 0.0, 0.0), hits=False),
         Case("hit at tmax", (0.5, 0.5, 2.0), (0.0, 0.0, -1.0), tmax=2.0, hits=False)),
        exact_rectangle,
        lambda m: Rectangle((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), GREY, m)),
    "box": KindCases(
        lambda m: Box((0.0, 0.0, 0.0), (2.0, 1.0, 1.0), GREY, m),
        (Case("hit", (0.5, 0.5, 3.0), (0.0, 0.0, -1.0)),
         Case("oblique hit", (0.0, 0.0, 3.0), (0.5, 0.25, -1.0)),
         Case("hit on the face -y", (1.5, -2.0, 0.25), (0.0, 1.0, 0.0)),
         Case("hit from inside (the leaving face)", (1.0, 0.5, 0.5), (1.0, 0.0, 0.0)),
         Case("hit on the edge of +x and +z", (2.0, 0.5, 3.0), (0.0, 0.0, -1.0)),
         Case("grazing ray touching an edge only (t0 = t1)", (3.0, 0.5, 0.0), (-1.0, 0.0, 1.0), hits=False),
         Case("miss beside the box", (2.25, 0.5, 3.0), (0.0, 0.0, -1.0), hits=False),
         Case("ray parallel to a face, outside its slab", (0.5, 0.5, 2.0), (1.0, 0.0, 0.0), hits=False),
         Case("miss behind the ray", (0.5, 0.5, -3.0), (0.0, 0.0, -1.0), hits=False),
         Case("hit at tmax", (0.5, 0.5, 3.0), (0.0, 0.0, -1.0), tmax=2.0, hits=False)),
        exact_box,
        lambda m: Box((-1.0, -1.0, -2.0), (1.0, 1.0, 0.0), GREY, m)),
    "open_cylinder": KindCases(
        lambda m: OpenCylinder(-1.0, 1.0, 1.0, GREY, m),
        (Case("hit", (0.0, 0.0, 5.0), (0.0, 0.0, -1.0)),
         Case("oblique hit", (0.0, 0.5, 3.0), (0.0, 0.125, -1.0)),
         Case("hit from inside (the normal turned toward the ray)", (0.0, 0.0, 0.0), (1.0, 0.0, 0.0)),
         Case("inside seen through the open end (the far root)", (-3.0, 2.0, 0.0), (1.0, -0.375, 0.0)),
         Case("hit on the rim y = y1", (0.0, 1.0, 5.0), (0.0, 0.0, -1.0)),
         Case("tangent ray (grazing)", (1.0, 0.0, 5.0), (0.0, 0.0, -1.0)),
         Case("miss above the rim", (0.0, 1.25, 5.0), (0.0, 0.0, -1.0), hits=False),
         Case("miss beside the cylinder", (1.25, 0.0, 5.0), (0.0, 0.0, -1.0), hits=False),
         Case("ray parallel to the axis", (1.0, -5.0, 0.0), (0.0, 1.0, 0.0), hits=False),
         Case("hit at tmax (the far root beyond it)", (0.0, 0.0, 5.0), (0.0, 0.0, -1.0), tmax=4.0,
              hits=False)),
        exact_open_cylinder,
        lambda m: OpenCylinder(-1.0, 1.0, 0.25, GREY, m)),
    # Torus(2, 1): the outer equator at 3, the inner one at 1, the top of the tube at y = 1.
    "torus": KindCases(
        lambda m: Torus(2.0, 1.0, GREY, m),
        (Case("hit on the outer equator", (0.0, 0.0, 5.0), (0.0, 0.0, -1.0)),
         Case("hit on the top of the tube", (2.0, 5.0, 0.0), (0.0, -1.0, 0.0)),
         Case("oblique hit", (4.0, 3.0, 2.0), (-1.0, -1.25, -1.0)),
         Case("hit from a far origin", (96.0, 0.5, 0.25), (-1.0, 0.0, 0.0)),
         Case("hit on the inner equator from the centre", (0.0, 0.0, 0.0), (1.0, 0.0, 0.0)),
         Case("hit from inside the tube (the far root)", (2.0, 0.0, 0.0), (0.0, 0.25, 1.0)),
         Case("near-grazing hit below the top of the tube", (0.0, 0.9375, 5.0), (0.0, 0.0, -1.0)),
         Case("grazing miss above the top of the tube", (0.0, 1.0078125, 5.0), (0.0, 0.0, -1.0), hits=False),
         Case("miss through the hole along the axis", (0.0, 5.0, 0.0), (0.0, -1.0, 0.0), hits=False),
         Case("miss through the hole near the inner rim", (0.5, 5.0, 0.0), (-0.125, -1.0, 0.0), hits=False),
         Case("miss beside the torus", (3.25, 0.0, 5.0), (0.0, 0.0, -1.0), hits=False),
         Case("hit at tmax (the next root beyond it)", (0.0, 0.0, 5.0), (0.0, 0.0, -1.0), tmax=2.0, hits=False)),
        exact_torus,
        None),   # every torus about the y axis through TIE_RAY's hit point is tangent to the ray
    **{name: KindCases(
        # The quarter of the sphere of radius 5 with x >= 0 (phi 0..180) and y <= 0 (theta 90..180).
        lambda m, cls=cls: cls((0.0, 0.0, 0.0), 5.0, 0.0, 180.0, 90.0, 180.0, GREY, m),
        (Case("hit within the angles", (9.0, -4.0, 0.0), (-1.0, 0.0, 0.0)),
         Case("near root outside the angles, the far one within", (-9.0, -4.0, 0.0), (1.0, 0.0, 0.0)),
         Case("hit from inside (the far root)", (0.0, -4.0, 0.0), (1.0, 0.0, 0.0)),
         Case("hit on the rim phi = phi_max", (0.0, -3.0, -9.0), (0.0, 0.0, 1.0)),
         Case("hit on the rim theta = theta_min (y = 0)", (3.0, 0.0, 9.0), (0.0, 0.0, -1.0)),
         Case("both roots above the part (y > 0)", (9.0, 4.0, 0.0), (-1.0, 0.0, 0.0), hits=False),
         Case("both roots beside the part (x < 0)", (-3.0, 0.0, 9.0), (0.0, 0.0, -1.0), hits=False),
         Case("miss beside the sphere", (6.0, -4.0, 9.0), (0.0, 0.0, -1.0), hits=False),
         Case("hit at tmax (the far root outside the angles)", (9.0, -4.0, 0.0), (-1.0, 0.0, 0.0), tmax=6.0,
              hits=False)),
        exact_part_sphere,
        lambda m, cls=cls: cls((0.25, 0.25, -1.0), 1.0, 0.0, 180.0, 0.0, 180.0, GREY, m))
       for name, cls in (("convex_part_sphere", ConvexPartSphere), ("concave_part_sphere", ConcavePartSphere))},
    "open_part_cylinder": KindCases(
        # The half of the cylinder of radius 5 with x >= 0 (phi 0..180), y in [-1, 1].
        lambda m: OpenPartCylinder(-1.0, 1.0, 5.0, 0.0, 180.0, GREY, m),
        (Case("hit within the angles", (9.0, 0.0, 3.0), (-1.0, 0.0, 0.0)),
         Case("near root outside the angles, the far one within (seen inside)", (-9.0, 0.0, 3.0),
              (1.0, 0.0, 0.0)),
         Case("hit on the rim phi = phi_max", (0.0, 0.0, -9.0), (0.0, 0.0, 1.0)),
         Case("hit on the rim phi = phi_min", (0.0, 0.5, 9.0), (0.0, 0.0, -1.0)),
         Case("both roots beside the part (x < 0)", (-3.0, 0.0, 9.0), (0.0, 0.0, -1.0), hits=False),
         Case("miss above the rim", (9.0, 2.0, 3.0), (-1.0, 0.0, 0.0), hits=False),
         Case("ray parallel to the axis", (4.0, -5.0, 3.0), (0.0, 1.0, 0.0), hits=False),
         Case("hit at tmax (the far root outside the angles)", (9.0, 0.0, 3.0), (-1.0, 0.0, 0.0), tmax=5.0,
              hits=False)),
        exact_open_part_cylinder,
        lambda m: OpenPartCylinder(-1.0, 1.0, 0.25, 0.0, 180.0, GREY, m)),
    "annulus": KindCases(
        lambda m: Annulus((0.0, 0.0, 0.0), (0.0, 0.0, 2.0), 0.5, 1.0, GREY, m),
        (Case("hit", (0.75, 0.0, 2.0), (0.0, 0.0, -1.0)),
         Case("oblique hit", (0.0, 0.0, 2.0), (0.25, 0.25, -1.0)),
         Case("hit from behind", (0.0, -0.75, -1.0), (0.0, 0.0, 1.0)),
         Case("hit on the inner rim", (0.5, 0.0, 2.0), (0.0, 0.0, -1.0)),
         Case("hit on the outer rim", (0.0, 1.0, 2.0), (0.0, 0.0, -1.0)),
         Case("miss through the hole", (0.25, 0.25, 2.0), (0.0, 0.0, -1.0), hits=False),
         Case("miss beyond the outer rim", (1.0, 0.25, 2.0), (0.0, 0.0, -1.0), hits=False),
         Case("ray parallel to the annulus", (0.75, 0.0, 1.0), (1.0, 0.0, 0.0), hits=False),
         Case("hit at tmax", (0.75, 0.0, 2.0), (0.0, 0.0, -1.0), tmax=2.0, hits=False)),
        exact_annulus,
        lambda m: Annulus((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 0.25, 1.0, GREY, m)),
    "mesh": KindCases(
        lambda m: mesh_face((0.0, 0.0, 0.0), (2.0, 0.0, 0.0), (0.0, 2.0, 0.0), m),
        (Case("hit", (0.5, 0.25, 2.0), (0.0, 0.0, -1.0)),
         Case("oblique hit", (0.0, 0.0, 1.0), (0.5, 0.25, -1.0)),
         Case("hit on the edge beta + gamma = 1", (1.0, 1.0, 2.0), (0.0, 0.0, -1.0)),
         Case("hit on the edge gamma = 0", (1.0, 0.0, 2.0), (0.0, 0.0, -1.0)),
         Case("hit on a vertex", (0.0, 2.0, 2.0), (0.0, 0.0, -1.0)),
         Case("hit on the edge beta = 0", (0.0, 0.5, 2.0), (0.0, 0.0, -1.0)),
         Case("miss beyond the edge", (1.25, 1.0, 2.0), (0.0, 0.0, -1.0), hits=False),
         Case("miss beside the face", (-0.25, 0.5, 2.0), (0.0, 0.0, -1.0), hits=False),
         Case("ray parallel to the face", (0.5, 0.25, 1.0), (1.0, 0.0, 0.0), hits=False),
         Case("hit at tmax", (0.5, 0.25, 2.0), (0.0, 0.0, -1.0), tmax=2.0, hits=False)),
        exact_mesh,
        lambda m: mesh_face((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), m)),
    # The unit sphere scaled by (2, 1, 1) and moved by (1, 0, 0): the ellipsoid
    # (x - 1)^2 / 4 + y^2 + z^2 = 1 (Suffern ch. 21).
    "instance": KindCases(
        lambda m: Instance(Sphere((0.0, 0.0, 0.0), 1.0, GREY, m)).scale(2.0, 1.0, 1.0).translate(1.0, 0.0, 0.0),
        (Case("hit", (-5.0, 0.0, 0.0), (1.0, 0.0, 0.0)),
         Case("oblique hit (the normal through the inverse transpose)", (-3.0, 0.0, 3.0), (2.0, -0.5, -2.0)),
         Case("hit from inside (the far root)", (1.0, 0.0, 0.0), (1.0, 0.0, 0.0)),
         Case("tangent ray at the end of the long axis", (3.0, 0.0, 5.0), (0.0, 0.0, -1.0)),
         Case("miss beside the ellipsoid", (3.25, 0.0, 5.0), (0.0, 0.0, -1.0), hits=False),
         Case("miss behind the ray", (-5.0, 0.0, 0.0), (-1.0, 0.0, 0.0), hits=False),
         Case("hit at tmax (the far root beyond it)", (-5.0, 0.0, 0.0), (1.0, 0.0, 0.0), tmax=4.0, hits=False)),
        exact_instance,
        # The box [-1, 1]^3 flattened to z in [-1, 0]: its top at z = 0.
        lambda m: Instance(Box((-1.0, -1.0, -1.0), (1.0, 1.0, 1.0), GREY, m)).scale(1.0, 1.0, 0.5).translate(0.0, 0.0, -0.5)),
}

# More instances on every path (test_instance_contract): a rotated box, a sheared rectangle.
INSTANCE_CASES = {
    "rotated box": KindCases(   # the box [0, 2] x [0, 1] x [0, 1] turned to x in [-1, 0], y in [0, 2]
        lambda m: Instance(Box((0.0, 0.0, 0.0), (2.0, 1.0, 1.0), GREY, m)).rotate_z(90.0),
        (Case("hit on the face turned to +y", (-0.5, 5.0, 0.5), (0.0, -1.0, 0.0)),
         Case("oblique hit on the face turned to -x", (-3.0, 1.0, 0.5), (1.0, 0.25, 0.0)),
         Case("miss where the box was before the turn", (1.5, 0.5, 5.0), (0.0, 0.0, -1.0), hits=False)),
        exact_instance, None),
    "sheared rectangle": KindCases(   # the unit square in z = 0 sheared by hxz = 1: z = x
        lambda m: Instance(Rectangle((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), GREY, m)).shear(hxz=1.0),
        (Case("hit", (0.5, 0.5, 3.0), (0.0, 0.0, -1.0)),
         Case("oblique hit", (0.0, 0.25, 2.0), (0.5, 0.0, -1.0)),
         Case("hit on the edge x = 1", (1.0, 0.5, 3.0), (0.0, 0.0, -1.0)),
         Case("miss beyond the sheared edge", (1.25, 0.5, 3.0), (0.0, 0.0, -1.0), hits=False)),
        exact_instance, None),
}

SHAPE_NAMES = [kind.name for kind in SHAPES]
SHAPE_CASE_IDS = [(kind, case.name) for kind in SHAPE_NAMES
                  for case in (SHAPE_CASES[kind].cases if kind in SHAPE_CASES else ())]
# Every formula a kind registers (rtfgu.registry.ShapeKind.formulas) keeps the same contract:
# the robust sphere is the slide's sphere computed in another order, not another shape.
FORMULA_CASE_IDS = [(kind.name, formula, case) for kind in SHAPES for formula in kind.formulas
                    for name, case in SHAPE_CASE_IDS if name == kind.name]


def _scene(shapes, lights=(), background=(0.0, 0.0, 0.0)):
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))  # the rays are given: no pixel is traced
    scene.shapes = list(shapes)
    scene.lights = list(lights)
    scene.background = Float3(*background)
    return scene


_RUNS = {}


def _shape_runs(path, kind, formula):
    """The shape of ``kind`` and the bounces of every case of it on ``path`` with
    ``formula``, all traced in one call of the path (one WGSL dispatch)."""
    if (path.label, kind, formula) not in _RUNS:
        entry = SHAPE_CASES[kind]
        scene = _scene([entry.shape(Matte())])
        _RUNS[path.label, kind, formula] = (scene.shapes[0], dict(zip(
            (c.name for c in entry.cases), path.trace(scene, [c.ray for c in entry.cases], formula))))
    return _RUNS[path.label, kind, formula]


def _close(got, exact, precision) -> bool:
    tolerance = CLOSE[precision]
    return all(abs(g - float(e)) <= tolerance * max(1.0, abs(float(e)))
               for g, e in zip(got if isinstance(got, tuple) else (got,),
                               exact if isinstance(exact, tuple) else (exact,)))


def test_every_shape_kind_has_cases():
    missing = [name for name in SHAPE_NAMES if name not in SHAPE_CASES]
    assert not missing, ("registered shape kinds without contract cases in tests/test_contract.py "
                         "SHAPE_CASES: %s" % ", ".join(missing))


@pytest.mark.parametrize("kind,case", SHAPE_CASE_IDS, ids=["%s: %s" % k for k in SHAPE_CASE_IDS])
def test_cases_say_what_they_test(kind, case):
    """The oracle agrees with each case's name: a "hit" hits, a miss (parallel, at tmax,
    beyond the rim) misses."""
    entry = SHAPE_CASES[kind]
    c = next(c for c in entry.cases if c.name == case)
    assert (entry.exact(entry.shape(Matte()), c) is not None) == c.hits


@pytest.mark.parametrize("kind,formula,case", FORMULA_CASE_IDS,
                         ids=["%s %s: %s" % k for k in FORMULA_CASE_IDS])
def test_shape_contract(path, kind, formula, case):
    if path.backend == "reference" and formula != "slide":
        pytest.skip("the lecture layer computes the slide formula only")
    shape, runs = _shape_runs(path, kind, formula)
    c = next(c for c in SHAPE_CASES[kind].cases if c.name == case)
    exact = SHAPE_CASES[kind].exact(shape, c)
    first = runs[case][0]
    where = "%s %s%s: %s" % (path.label, kind, "" if formula == "slide" else " (%s)" % formula, case)
    if exact is None:
        assert first.shape is None, "%s: expected a miss, got shape %s at t = %r" % (where, first.shape, first.t)
        return
    t, normal = exact
    assert first.shape == 0 and first.kind == kind, "%s: expected a hit on the %s, got %r" % (where, kind, first)
    assert _close(first.t, t, path.precision), "%s: t = %r, exactly %s" % (where, first.t, t)
    assert _close(first.normal, normal, path.precision), (
        "%s: normal %r, exactly %s" % (where, first.normal, tuple(map(str, normal))))


INSTANCE_CASE_IDS = [(name, case.name) for name, entry in INSTANCE_CASES.items() for case in entry.cases]


@pytest.mark.parametrize("name,case", INSTANCE_CASE_IDS, ids=["%s: %s" % k for k in INSTANCE_CASE_IDS])
def test_instance_contract(path, name, case):
    entry = INSTANCE_CASES[name]
    c = next(c for c in entry.cases if c.name == case)
    key = (path.label, "instance " + name, "slide")
    if key not in _RUNS:   # every case of the shape in one call of the path
        scene = _scene([entry.shape(Matte())])
        _RUNS[key] = (scene.shapes[0], dict(zip((e.name for e in entry.cases),
                                                path.trace(scene, [e.ray for e in entry.cases], "slide"))))
    shape, runs = _RUNS[key]
    exact = entry.exact(shape, c)
    assert (exact is not None) == c.hits, "the oracle disagrees with the case's name"
    first = runs[case][0]
    where = "%s instance (%s): %s" % (path.label, name, case)
    if exact is None:
        assert first.shape is None, "%s: expected a miss, got shape %s at t = %r" % (where, first.shape, first.t)
        return
    assert first.shape == 0 and first.kind == "instance", "%s: expected a hit, got %r" % (where, first)
    assert _close(first.t, exact[0], path.precision), "%s: t = %r, exactly %s" % (where, first.t, exact[0])
    assert _close(first.normal, exact[1], path.precision), "%s: normal %r, exactly %r" % (where, first.normal, exact[1])


# Shaders: one hit on the plane z = 0 at the origin by a ray at 3-4-5 angles, one point light
# at (3, 0, 4): w_i = (0.6, 0, 0.8), n . w_i = 0.8, L_i = I / 25 = (1, 2, 3) (Kepler), and
# the light's mirror direction w_r = w_o, so the Phong lobe is at its peak (cos^s = 1).
SHADER_RAY = ((-1.5, 0.0, 2.0), (0.6, 0.0, -0.8), 0.0, INF)
LIGHT = PointLight((3.0, 0.0, 4.0), (25.0, 50.0, 75.0))
L_I, COS_THETA = (1.0, 2.0, 3.0), 0.8
SPECULAR, SHININESS, IOR, EMISSION = (0.25, 0.5, 0.75), 4.0, 1.5, (0.125, 0.25, 0.0625)
BACKGROUND = (0.1, 0.3, 0.6)


def lambertian_color():
    # 02562 "Sampling light in the shader": L_e + rho_d / pi L_i (n . w_i) + L_a
    return tuple(e + AMBIENT_FRACTION * c + DIFFUSE_FRACTION * c / math.pi * L * COS_THETA
                 for e, c, L in zip(EMISSION, GREY, L_I))


def phong_color():
    # 02562 worksheet 3: (rho_d / pi + rho_s (s + 2) / (2 pi) (w_o . w_r)^s) L_i (n . w_i) + L_a
    return tuple(e + AMBIENT_FRACTION * c
                 + (DIFFUSE_FRACTION * c / math.pi + s * (SHININESS + 2) / (2 * math.pi)) * L * COS_THETA
                 for e, c, s, L in zip(EMISSION, GREY, SPECULAR, L_I))


def refracted():
    # Snell's law entering with eta = 1 / ior: d eta + n (eta cos_i - cos_t)
    d, eta, cos_i = SHADER_RAY[1], 1 / IOR, 0.8
    cos_t = math.sqrt(1 - eta * eta * (1 - cos_i * cos_i))
    return (d[0] * eta, 0.0, d[2] * eta + (eta * cos_i - cos_t))


def mirrored():
    # d - 2 (d . n) n: the z of the ray flips
    return (0.6, 0.0, 0.8)


def glowing_dielectric():
    """Glass that also glows: L_e set as load_obj sets an MTL material's Ke."""
    material = Dielectric(IOR)
    material.emission = Float3(*EMISSION)
    return material


# Per registered shader: (its material, the colour its first bounce adds, the directions of
# the rays it sends on, in the order the lecture layer's Whitted traces them; none when the
# shader ends the path).
SHADER_CASES = {
    "base_color": (lambda: Material(emission=EMISSION), lambda: GREY, ()),
    "lambertian": (lambda: Matte(emission=EMISSION), lambertian_color, ()),
    "phong": (lambda: Phong(cs=SPECULAR, exp=SHININESS, emission=EMISSION), phong_color, ()),
    "mirror": (lambda: Reflective(emission=EMISSION), lambda: EMISSION, (mirrored,)),
    "transparent": (lambda: Transparent(ior=IOR, emission=EMISSION), lambda: EMISSION, (refracted,)),
    "glossy": (lambda: Transparent(ior=IOR, ka=AMBIENT_FRACTION, kd=DIFFUSE_FRACTION, ks=1.0, cs=SPECULAR,
                                   exp=SHININESS, emission=EMISSION), phong_color, (refracted,)),
    "emissive": (lambda: Emissive(1.0, EMISSION), lambda: EMISSION, ()),  # Suffern's Emissive: L_e only
    # Whitted follows both of a Dielectric's rays, the reflected one first (Fresnel-weighted:
    # test_dielectric_under_whitted_is_fresnel_weighted); numba and WGSL refuse it outside
    # PathTrace (FLAT_REFUSED).
    "dielectric": (glowing_dielectric, lambda: EMISSION, (mirrored, refracted)),
    # Suffern's Reflective with a Phong part: Phong, then the mirror ray (weighted by kr cr)
    "reflective": (lambda: Reflective(kr=0.5, ka=AMBIENT_FRACTION, kd=DIFFUSE_FRACTION, ks=1.0, cs=SPECULAR,
                                      exp=SHININESS, emission=EMISSION), phong_color, (mirrored,)),
    # the ray-cast tracers shade it as phong
    "glossy_reflector": (lambda: GlossyReflector(cs=SPECULAR, exp=SHININESS, emission=EMISSION), phong_color, ()),
}
SHADER_NAMES = [kind.name for kind in SHADERS]
# Shaders the numba and WGSL paths render under PathTrace only: under the ray-cast tracers
# they send two rays, and compile_scene refuses them, naming the shape's material.
FLAT_REFUSED = {"dielectric"}


def test_every_shader_has_a_case():
    missing = [name for name in SHADER_NAMES if name not in SHADER_CASES]
    assert not missing, "registered shaders without a contract case in SHADER_CASES: %s" % ", ".join(missing)


def _shader_scene(shader):
    material = SHADER_CASES[shader][0]()
    return _scene([Plane((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), GREY, material)], [LIGHT], BACKGROUND)


@pytest.mark.parametrize("shader", SHADER_NAMES)
def test_shader_contract(path, shader):
    kind = next(k for k in SHADERS if k.name == shader)
    scene = _shader_scene(shader)
    assert scene.shapes[0].material.shader == kind.id
    where = "%s %s: one hit, one light" % (path.label, shader)
    if shader in FLAT_REFUSED and path.backend != "reference":
        with pytest.raises(ValueError, match=r"Scene\.shapes\[0\]\.material") as error:
            path.trace(scene, [SHADER_RAY])
        assert type(scene.shapes[0].material).__name__ in str(error.value), (
            "%s: the refusal should name the material: %s" % (where, error.value))
        return
    bounces = path.trace(scene, [SHADER_RAY])[0]
    _, color, next_directions = SHADER_CASES[shader]
    first = bounces[0]
    assert first.shape == 0 and first.shader == shader, "%s: %r" % (where, first)
    assert _close(first.color, color(), path.precision), (
        "%s: colour %r, the lecture's formula gives %r" % (where, first.color, color()))
    if not next_directions:
        assert len(bounces) == 1, "%s: the shader ends the path, got %d bounces" % (where, len(bounces))
        return
    assert len(bounces) == 1 + len(next_directions), (
        "%s: the next rays leave the scene, got %d bounces" % (where, len(bounces)))
    for bounce, direction in zip(bounces[1:], next_directions):
        assert _close(bounce.direction, direction(), path.precision), (
            "%s: next direction %r, expected %r" % (where, bounce.direction, direction()))
        assert bounce.shape is None and _close(bounce.color, BACKGROUND, path.precision)
        assert abs(bounce.origin[2]) <= CLOSE[path.precision] < SPAWN_EPSILON


def test_dielectric_under_whitted_is_fresnel_weighted():
    """The lecture layer's Whitted follows both rays of a Dielectric: L_e + R L(w_r) +
    (1 - R) L(w_t), Fresnel's R for unpolarised light, the refracted ray's light absorbed
    over its length inside (Bouguer: exp(-sigma_a s)). The reflected ray sees the background,
    the refracted one a flat colour on the plane z = -1 inside."""
    absorption, inside = (0.5, 0.25, 0.125), (0.75, 0.5, 0.25)
    material = glowing_dielectric()
    material.set_absorption(absorption)
    scene = _shader_scene("dielectric")
    scene.shapes[0].material = material
    scene.shapes.append(Plane((0.0, 0.0, -1.0), (0.0, 0.0, 1.0), inside, Material()))
    L = trace(scene, Ray(Float3(*SHADER_RAY[0]), Float3(*SHADER_RAY[1])))
    eta, cos_i = 1 / IOR, 0.8
    cos_t = math.sqrt(1 - eta * eta * (1 - cos_i * cos_i))
    r_perp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t)
    r_par = (cos_i - eta * cos_t) / (cos_i + eta * cos_t)
    R = (r_perp * r_perp + r_par * r_par) / 2
    assert 0.0 < R < 0.1                              # glass at 37 degrees reflects a few per cent
    s = 1.0 / -refracted()[2]                         # the refracted ray's length down to z = -1
    expected = tuple(e + R * b + (1 - R) * c * math.exp(-a * s)
                     for e, b, c, a in zip(EMISSION, BACKGROUND, inside, absorption))
    assert _close((L.x, L.y, L.z), expected, "float64"), "Whitted's dielectric: %r, by hand %r" % (L, expected)


# Ties: two shapes of different kinds first hit by TIE_RAY at exactly the same t: the one
# earlier in Scene.shapes wins, on every path, in both orders.
TIE_PAIRS = [(a, b) for i, a in enumerate(SHAPE_NAMES) for b in SHAPE_NAMES[i + 1:]]
TIE_CASES = [(a, b) for a, b in TIE_PAIRS] + [(b, a) for a, b in TIE_PAIRS]


@pytest.mark.parametrize("first,second", TIE_CASES, ids=["%s before %s" % c for c in TIE_CASES])
def test_tie_earlier_shape_wins(path, first, second):
    for name in (first, second):
        if name not in SHAPE_CASES:
            pytest.fail("registered shape kind %s has no coincident shape in SHAPE_CASES" % name)
        if SHAPE_CASES[name].coincident is None:
            pytest.skip("the %s meets TIE_RAY only tangentially; test_torus_tie_with_a_plane covers it" % name)
    shapes = [SHAPE_CASES[name].coincident(Matte()) for name in (first, second)]
    for shape in shapes:  # the case itself: each shape alone is hit at exactly t = 2
        alone = SHAPE_CASES[shape_kind_of(shape)[1].name].exact(shape, Case("tie", *TIE_RAY))
        assert alone is not None and alone[0] == 2
    hit = path.trace(_scene(shapes), [TIE_RAY])[0][0]
    assert (hit.shape, hit.kind) == (0, first), (
        "%s tie, %s before %s in Scene.shapes: the %s (Scene.shapes[%s]) won at t = %r"
        % (path.label, first, second, hit.kind, hit.shape, hit.t))
    assert hit.t == 2.0


@pytest.mark.parametrize("torus_first", [True, False], ids=["torus before plane", "plane before torus"])
def test_torus_tie_with_a_plane(path, torus_first):
    """The tie rule for the torus, on a ray that meets it transversally: straight down onto
    the top of the tube of Torus(2, 1) at (2, 1, 0), t = 4, where the plane y = 1 touches it."""
    torus = Torus(2.0, 1.0, GREY, Matte())
    plane = Plane((0.0, 1.0, 0.0), (0.0, 1.0, 0.0), GREY, Matte())
    ray = ((2.0, 5.0, 0.0), (0.0, -1.0, 0.0), 0.0, INF)
    assert exact_torus(torus, Case("tie", *ray))[0] == 4
    shapes = [torus, plane] if torus_first else [plane, torus]
    hit = path.trace(_scene(shapes), [ray])[0][0]
    first = "torus" if torus_first else "plane"
    assert (hit.shape, hit.kind) == (0, first), "%s: the %s (Scene.shapes[%s]) won at t = %r" % (
        path.label, hit.kind, hit.shape, hit.t)
    assert hit.t == 4.0


def test_torus_texture_coordinates_pick_the_checker_square_on_every_path(path):
    """Torus.texcoord (u about the y axis, v about the tube from the outer equator) picks
    the checker's square on every path: points of Torus(2, 1) at (phi, theta), seen along
    their normals, far from a square's edge."""
    from rtfgu.textures import Checker

    red, blue = Float3(1.0, 0.0, 0.0), Float3(0.0, 0.0, 1.0)
    scene = _scene([Torus(2.0, 1.0, Float3(0.0), Material(cd=Checker(red, blue, size=0.125)))])
    rays, want = [], []
    for phi, theta in ((0.3, 0.2), (2.0, -0.5), (4.0, 1.2), (5.3, 0.55)):
        n = (math.cos(theta) * math.sin(phi), math.sin(theta), math.cos(theta) * math.cos(phi))
        p = ((2 + math.cos(theta)) * math.sin(phi), math.sin(theta), (2 + math.cos(theta)) * math.cos(phi))
        rays.append((tuple(pc + 5 * nc for pc, nc in zip(p, n)), tuple(-c for c in n), 0.0, INF))
        cells = (phi / (2 * math.pi) / 0.125, (theta % (2 * math.pi)) / (2 * math.pi) / 0.125)
        assert all(0.01 < c - math.floor(c) < 0.99 for c in cells)   # far from an edge
        want.append(red if (math.floor(cells[0]) + math.floor(cells[1])) % 2 == 0 else blue)
    assert red in want and blue in want
    for k, (bounces, colour) in enumerate(zip(path.trace(scene, rays), want)):
        assert bounces[0].kind == "torus" and bounces[0].color == (colour.x, colour.y, colour.z), (
            "%s ray %d: %r" % (path.label, k, bounces[0]))
