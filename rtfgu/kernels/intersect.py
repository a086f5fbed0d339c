"""Ray-shape intersection (lecture 01 "Ray-Plane/Ray-Sphere Intersection", 02562
"Ray-triangle intersection"), operation for operation as in rtfgu/shapes/.

Each function returns the hit distance t, or inf on a miss. The interval is [tmin, tmax]
with tmax included, unlike the slides' [tmin, tmax): the lecture loop visits the shapes in
Scene order and keeps the first of two equal distances, while ``intersect_scene`` visits
them kind by kind and breaks such a tie by the Scene index, for which it needs to see it.

Spheres have two formulas, chosen per render by ``sphere_formula``: SPHERE_SLIDE, the
lecture's quadratic (``intersect_sphere``), and SPHERE_ROBUST, Ray Tracing Gems ch. 7
(``intersect_sphere_robust``), which keeps its digits for far, small and grazing spheres in
float32 (rtfgu/robust.py says why; rtfgu.hardcases measures both). The choice is an
argument, not a separate kernel: one compiled kernel serves both formulas, and the branch on
it goes the same way for every ray.
"""
from __future__ import annotations

import math

from numba import njit

from ..layout import (PLANE, PLANE_NORMAL, PLANE_POINT, SPHERE, SPHERE_CENTER, SPHERE_RADIUS,
                      TRI_E0, TRI_E1, TRI_N, TRI_V0, TRIANGLE)
from .float3 import add, cross, dot, lit, row3, scale, sub

# sphere_formula values (as rtfgu.kernels.robust.SLIDE / ROBUST, and FORMULAS below).
SPHERE_SLIDE = 0
SPHERE_ROBUST = 1
SPHERE_FORMULAS = {"slide": SPHERE_SLIDE, "robust": SPHERE_ROBUST}


@njit(cache=True, error_model="numpy")
def intersect_plane(origin, direction, tmin, tmax, point, normal):
    # t = ((a - o) . n) / (d . n), written as on the slide with A, B, C.
    A = dot(origin, normal)
    B = dot(direction, normal)
    C = dot(point, normal)
    if B == lit(0, B):
        return lit(math.inf, B)  # parallel to the plane
    t = (C - A) / B
    if t >= tmin and t <= tmax:
        return t
    return lit(math.inf, B)


@njit(cache=True, error_model="numpy")
def intersect_triangle(origin, direction, tmin, tmax, v0, e0, e1, n):
    # 02562 barycentric test: beta, gamma from ((v0 - o) x w) . e / (w . n).
    denom = dot(direction, n)
    if denom == lit(0, denom):
        return lit(math.inf, denom)
    a = sub(v0, origin)
    t = dot(a, n) / denom
    if not (t >= tmin and t <= tmax):
        return lit(math.inf, denom)
    c = cross(a, direction)
    beta = dot(c, e1) / denom
    gamma = -dot(c, e0) / denom
    zero = lit(0, denom)
    if beta >= zero and gamma >= zero and beta + gamma <= lit(1, denom):
        return t
    return lit(math.inf, denom)


@njit(cache=True, error_model="numpy")
def sphere_roots(temp, c, direction, tmin, tmax):
    """The sphere test from temp = o - center and c = temp . temp - r^2: the part of
    ``intersect_sphere`` that depends on the direction. Rays that share an origin (a pinhole
    camera's primary rays) share temp and c, computed once per frame, with the same bits."""
    a = dot(direction, direction)
    b = lit(2, a) * dot(temp, direction)
    disc = b * b - lit(4, a) * a * c
    if disc < lit(0, a):
        return lit(math.inf, a)
    e = math.sqrt(disc)
    denom = lit(2, a) * a
    # The least t in range: the near root first, then the far one (a ray from inside).
    t = (-b - e) / denom
    if t >= tmin and t <= tmax:
        return t
    t = (-b + e) / denom
    if t >= tmin and t <= tmax:
        return t
    return lit(math.inf, a)


@njit(cache=True, error_model="numpy")
def intersect_sphere(origin, direction, tmin, tmax, center, radius):
    # a t^2 + b t + c = 0 with a = d.d, b = 2 (o - c).d, c = (o - c).(o - c) - r^2
    temp = sub(origin, center)
    c = dot(temp, temp) - radius * radius
    return sphere_roots(temp, c, direction, tmin, tmax)


@njit(cache=True, error_model="numpy")
def sphere_roots_robust(temp, c, radius, direction, tmin, tmax):
    """Ray Tracing Gems ch. 7 (Haines, Guenther and Akenine-Moeller 2019, eqs. 7.5-7.8)
    from temp = f = o - center and c = f . f - r^2, as ``sphere_roots``: with b' = -f . d,
    the discriminant a (r^2 - |f + (b'/a) d|^2) is the squared distance from the centre to
    the line (no b^2 - 4ac cancellation), and the roots c / q and q / a with
    q = b' + sign(b') sqrt(disc) subtract no two nearly equal numbers. The inputs are finite
    (compile_scene refuses anything else), so it needs no finiteness test (the hard cases'
    rtfgu.kernels.robust.batch_sphere adds one): a zero direction gives NaN, and NaN fails
    every comparison."""
    a = dot(direction, direction)
    # Through 1 / a, which depends on the ray only: inlined in intersect_scene's loop over
    # the spheres it is computed once per ray, and a miss costs no division (two roundings
    # instead of one in b'/a and q/a, which changes nothing about the cancellation).
    inv_a = lit(1, a) / a
    b = -dot(temp, direction)
    l = add(temp, scale(direction, b * inv_a))
    disc = a * ((radius * radius) - dot(l, l))
    zero = lit(0, a)
    if disc < zero:
        return lit(math.inf, a)
    root = math.sqrt(disc)
    q = b + root if b >= zero else b - root
    if q == zero:
        # b' = 0 and disc = 0: the origin is the tangent point, both roots are 0.
        t0 = zero
        t1 = zero
    else:
        t0 = c / q
        t1 = q * inv_a
    if t0 > t1:
        t0, t1 = t1, t0
    if t0 >= tmin and t0 <= tmax:
        return t0
    if t1 >= tmin and t1 <= tmax:
        return t1
    return lit(math.inf, a)


@njit(cache=True, error_model="numpy")
def intersect_sphere_robust(origin, direction, tmin, tmax, center, radius):
    # f = o - center and c = f . f - r^2 as in intersect_sphere, then Ray Tracing Gems ch. 7.
    temp = sub(origin, center)
    c = dot(temp, temp) - radius * radius
    return sphere_roots_robust(temp, c, radius, direction, tmin, tmax)


@njit(cache=True, error_model="numpy")
def sphere_test(sphere_formula, origin, direction, tmin, tmax, center, radius):
    """The render's sphere test: the formula that ``sphere_formula`` names."""
    if sphere_formula == SPHERE_ROBUST:
        return intersect_sphere_robust(origin, direction, tmin, tmax, center, radius)
    return intersect_sphere(origin, direction, tmin, tmax, center, radius)


@njit(cache=True, error_model="numpy")
def sphere_eye_terms(eye, spheres, out):
    """temp = eye - center and c = temp . temp - r^2 for every sphere, once per frame."""
    for i in range(spheres.shape[0]):
        temp = sub(eye, row3(spheres, i, SPHERE_CENTER))
        radius = spheres[i, SPHERE_RADIUS]
        out[i, 0] = temp[0]
        out[i, 1] = temp[1]
        out[i, 2] = temp[2]
        out[i, 3] = dot(temp, temp) - radius * radius


@njit(cache=True, error_model="numpy", inline="always")
def intersect_scene(origin, direction, tmin, tmax, planes, plane_index, triangles,
                    triangle_index, spheres, sphere_index, sphere_eye, candidates, n_candidates,
                    from_eye, sphere_formula):
    """``intersect_scene``: the nearest hit over all shapes, as (t, scene index, shape kind,
    row in that kind's array), scene index -1 on a miss. A kind whose array is None is not in
    the scene and compiles to nothing. For a ray from the eye (``from_eye``) the spheres
    tested are the rows ``candidates[:n_candidates]``, with temp and c from ``sphere_eye``;
    otherwise every sphere. ``sphere_formula`` is SPHERE_SLIDE or SPHERE_ROBUST."""
    best = -1
    kind = -1
    row = -1
    # A hit replaces the nearest so far if nearer, or as near and earlier in Scene.shapes.
    if planes is not None:
        for i in range(planes.shape[0]):
            t = intersect_plane(origin, direction, tmin, tmax, row3(planes, i, PLANE_POINT),
                                row3(planes, i, PLANE_NORMAL))
            idx = plane_index[i]
            if t < tmax or (t == tmax and idx < best):
                tmax = t
                best = idx
                kind = PLANE
                row = i
    if triangles is not None:
        for i in range(triangles.shape[0]):
            t = intersect_triangle(origin, direction, tmin, tmax, row3(triangles, i, TRI_V0),
                                   row3(triangles, i, TRI_E0), row3(triangles, i, TRI_E1),
                                   row3(triangles, i, TRI_N))
            idx = triangle_index[i]
            if t < tmax or (t == tmax and idx < best):
                tmax = t
                best = idx
                kind = TRIANGLE
                row = i
    if spheres is not None:
        # One loop per formula and kind of ray: the formula is the same for every sphere,
        # and a test of it inside a loop cost the slide formula 5-15 % on 64 spheres.
        if from_eye and sphere_formula == SPHERE_ROBUST:
            for k in range(n_candidates):
                i = candidates[k]
                t = sphere_roots_robust(row3(sphere_eye, i, 0), sphere_eye[i, 3],
                                        spheres[i, SPHERE_RADIUS], direction, tmin, tmax)
                idx = sphere_index[i]
                if t < tmax or (t == tmax and idx < best):
                    tmax = t
                    best = idx
                    kind = SPHERE
                    row = i
        elif from_eye:
            for k in range(n_candidates):
                i = candidates[k]
                t = sphere_roots(row3(sphere_eye, i, 0), sphere_eye[i, 3], direction, tmin, tmax)
                idx = sphere_index[i]
                if t < tmax or (t == tmax and idx < best):
                    tmax = t
                    best = idx
                    kind = SPHERE
                    row = i
        elif sphere_formula == SPHERE_ROBUST:
            for i in range(spheres.shape[0]):
                t = intersect_sphere_robust(origin, direction, tmin, tmax,
                                            row3(spheres, i, SPHERE_CENTER),
                                            spheres[i, SPHERE_RADIUS])
                idx = sphere_index[i]
                if t < tmax or (t == tmax and idx < best):
                    tmax = t
                    best = idx
                    kind = SPHERE
                    row = i
        else:
            for i in range(spheres.shape[0]):
                t = intersect_sphere(origin, direction, tmin, tmax,
                                     row3(spheres, i, SPHERE_CENTER), spheres[i, SPHERE_RADIUS])
                idx = sphere_index[i]
                if t < tmax or (t == tmax and idx < best):
                    tmax = t
                    best = idx
                    kind = SPHERE
                    row = i
    return tmax, best, kind, row


@njit(cache=True, error_model="numpy")
def in_shadow(position, w_i, tmin, tmax, planes, triangles, spheres, sphere_formula):
    """A shadow ray: is any shape hit in [tmin, tmax)? (rtfgu.shading.in_shadow)"""
    if planes is not None:
        for i in range(planes.shape[0]):
            if intersect_plane(position, w_i, tmin, tmax, row3(planes, i, PLANE_POINT),
                               row3(planes, i, PLANE_NORMAL)) < tmax:
                return True
    if triangles is not None:
        for i in range(triangles.shape[0]):
            if intersect_triangle(position, w_i, tmin, tmax, row3(triangles, i, TRI_V0),
                                  row3(triangles, i, TRI_E0), row3(triangles, i, TRI_E1),
                                  row3(triangles, i, TRI_N)) < tmax:
                return True
    if spheres is not None:
        for i in range(spheres.shape[0]):
            if sphere_test(sphere_formula, position, w_i, tmin, tmax,
                           row3(spheres, i, SPHERE_CENTER), spheres[i, SPHERE_RADIUS]) < tmax:
                return True
    return False
