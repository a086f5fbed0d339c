# release: solves a03 a08
"""Ray-shape intersection (lecture 01 "Ray-Plane/Ray-Sphere Intersection", 02562
"Ray-triangle intersection", Suffern ch. 19 "Disks", "Rectangles", "Axis-aligned boxes",
"Open cylinders"), operation for operation as in
rtfgu/shapes/.

For every shape kind of rtfgu.registry: ``intersect_<kind>(origin, direction, tmin, tmax,
*fields)`` returns the hit distance t, or inf on a miss, and ``normal_<kind>(position,
*fields)`` the unit normal; the fields are the kind's layout record in its registry order.
The interval is [tmin, tmax] with tmax included, unlike the slides' [tmin, tmax):
``intersect_scene`` (rtfgu.kernels.dispatch) visits the shapes kind by kind and lets the
earlier shape in Scene.shapes win a tie, for which it needs to see the tie.

Spheres have two formulas, chosen per render: the lecture's quadratic (``intersect_sphere``)
and Ray Tracing Gems ch. 7 (``intersect_sphere_robust``), which keeps its digits for far,
small and grazing spheres in float32 (rtfgu/robust.py says why; rtfgu.hardcases measures
both). Rays from a pinhole eye share o - center and c per sphere (``sphere_eye_terms``),
so the kernels test them with ``sphere_roots``/``sphere_roots_robust`` directly.
"""
from __future__ import annotations

import math

from numba import njit

from ..layout import SPHERE_CENTER, SPHERE_RADIUS
from .float3 import add, cross, dot, lit, neg, normalize, row3, scale, sub
from .next_float import next_up

# Formula ids of a render (rtfgu.kernels.dispatch.FORMULAS): the slide's and the robust one.
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
    rtfgu.kernels.robust.batch adds one): a zero direction gives NaN, and NaN fails
    every comparison. The direction is scaled by a power of two first, and the roots back
    (rtfgu.robust.direction_scale): exact, so the roots are bit for bit the same, but d . d
    cannot overflow or underflow."""
    s = math.ldexp(lit(1, radius), -math.frexp(max(abs(direction[0]), abs(direction[1]), abs(direction[2])))[1])
    direction = scale(direction, s)
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
        t0 = c / q * s
        t1 = q * inv_a * s
    # The least t in range: the near root if it is, else the far one (a ray from inside).
    near = min(t0, t1)
    t = near if near >= tmin and near <= tmax else max(t0, t1)
    return t if t >= tmin and t <= tmax else lit(math.inf, a)


@njit(cache=True, error_model="numpy")
def intersect_sphere_robust(origin, direction, tmin, tmax, center, radius):
    # f = o - center and c = f . f - r^2 as in intersect_sphere, then Ray Tracing Gems ch. 7.
    f = sub(origin, center)
    return sphere_roots_robust(f, dot(f, f) - radius * radius, radius, direction, tmin, tmax)


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


@njit(cache=True, error_model="numpy")
def plane_hit_offset(origin, direction, tmin, tmax, center, normal):
    """The first step of Disk.intersect_p and Annulus.intersect_p: (t, (p - c) . (p - c)) for
    the ray's hit p = o + d t of the plane through ``center`` (intersect_plane), (inf, inf)
    for a miss. The caller keeps t where the squared distance from the center is in range."""
    t = intersect_plane(origin, direction, tmin, tmax, center, normal)
    if t == lit(math.inf, t):
        return t, t
    to_hit = sub(add(origin, scale(direction, t)), center)
    return t, dot(to_hit, to_hit)


@njit(cache=True, error_model="numpy")
def intersect_disk(origin, direction, tmin, tmax, center, normal, radius):
    # The plane of the disk, then (p - c) . (p - c) <= r^2 at p = o + d t (plane_hit_offset).
    t, d2 = plane_hit_offset(origin, direction, tmin, tmax, center, normal)
    if d2 <= radius * radius:
        return t
    return lit(math.inf, t)


@njit(cache=True, error_model="numpy")
def intersect_rectangle(origin, direction, tmin, tmax, p0, a, b, normal):
    # Suffern's Rectangle::hit: the plane through p0 (intersect_plane), then
    # 0 <= d . a <= |a|^2 and 0 <= d . b <= |b|^2 for d = o + t w - p0.
    t = intersect_plane(origin, direction, tmin, tmax, p0, normal)
    if t == lit(math.inf, t):
        return t
    d = sub(add(origin, scale(direction, t)), p0)
    zero = lit(0, t)
    ddota = dot(d, a)
    if ddota < zero or ddota > dot(a, a):
        return lit(math.inf, t)
    ddotb = dot(d, b)
    if ddotb < zero or ddotb > dot(b, b):
        return lit(math.inf, t)
    return t


@njit(cache=True, error_model="numpy")
def intersect_box(origin, direction, tmin, tmax, p0, p1):
    # Suffern's Box::hit, the slab test: t0 the largest entering t, t1 the smallest leaving
    # t, a hit when t0 < t1; an axis the ray does not move along bounds nothing when o is
    # within the slab (rtfgu.shapes.box).
    t0 = lit(-math.inf, tmin)
    t1 = lit(math.inf, tmin)
    zero = lit(0, tmin)
    for axis in range(3):
        o = origin[axis]
        d = direction[axis]
        lo = p0[axis]
        hi = p1[axis]
        if d == zero:
            if o < lo or o > hi:
                return lit(math.inf, tmin)
            continue
        a = lit(1, d) / d
        if a >= zero:
            t_near = (lo - o) * a
            t_far = (hi - o) * a
        else:
            t_near = (hi - o) * a
            t_far = (lo - o) * a
        if t_near > t0:
            t0 = t_near
        if t_far < t1:
            t1 = t_far
    if not t0 < t1:
        return lit(math.inf, tmin)
    t = t0 if t0 >= tmin else t1
    if t >= tmin and t <= tmax:
        return t
    return lit(math.inf, tmin)


@njit(cache=True, error_model="numpy")
def box_face(position, p0, p1):
    """The face (0-5: -x, -y, -z, +x, +y, +z) nearest to the point, the first at equal distances."""
    face = 0
    best = abs(position[0] - p0[0])
    for k in range(1, 6):
        distance = abs(position[k % 3] - (p0[k] if k < 3 else p1[k - 3]))
        if distance < best:
            face = k
            best = distance
    return face


@njit(cache=True, error_model="numpy")
def intersect_open_cylinder(origin, direction, tmin, tmax, y0, y1, radius):
    # Suffern's OpenCylinder::hit: the ray projected onto the xz plane meets the sphere of
    # radius r about the origin (intersect_sphere: the same quadratic) where the ray meets the
    # infinite cylinder; the near root, then the far one, counts when o_y + t d_y is within
    # [y0, y1]. A ray parallel to the axis misses.
    zero = lit(0, radius)
    if direction[0] == zero and direction[2] == zero:
        return lit(math.inf, radius)
    flat_origin = (origin[0], zero, origin[2])
    flat_direction = (direction[0], zero, direction[2])
    center = (zero, zero, zero)
    t = intersect_sphere(flat_origin, flat_direction, tmin, tmax, center, radius)
    for _ in range(2):
        if t == lit(math.inf, radius):
            return t
        y_hit = origin[1] + t * direction[1]
        if y_hit >= y0 and y_hit <= y1:
            return t
        t = intersect_sphere(flat_origin, flat_direction, next_up(t), tmax, center, radius)
    return lit(math.inf, radius)


@njit(cache=True, error_model="numpy")
def normal_plane(position, point, normal):
    return normalize(normal)


@njit(cache=True, error_model="numpy")
def normal_triangle(position, v0, e0, e1, n):
    return normalize(n)


@njit(cache=True, error_model="numpy")
def normal_sphere(position, center, radius):
    return normalize(sub(position, center))


@njit(cache=True, error_model="numpy")
def normal_disk(position, center, normal, radius):
    return normalize(normal)


@njit(cache=True, error_model="numpy")
def normal_rectangle(position, p0, a, b, normal):
    return normal


@njit(cache=True, error_model="numpy")
def normal_box(position, p0, p1):
    # Box.normal_at: the outward normal of the face nearest to the point.
    face = box_face(position, p0, p1)
    zero = lit(0, position[0])
    sign = lit(-1, zero) if face < 3 else lit(1, zero)
    axis = face % 3
    return (sign if axis == 0 else zero, sign if axis == 1 else zero, sign if axis == 2 else zero)


@njit(cache=True, error_model="numpy")
def normal_open_cylinder(position, direction, y0, y1, radius):
    # OpenCylinder.hit_normal: (x, 0, z) normalised, flipped toward the ray (-d . n < 0).
    n = normalize((position[0], lit(0, radius), position[2]))
    if dot(direction, n) > lit(0, radius):
        return neg(n)
    return n
