# release: solves a03
"""numba robust single-ray intersections and the batch evaluators of rtfgu.hardcases.

The robust plane and triangle tests and the spawned-ray offset perform rtfgu/robust.py's
operations in the same order, so that in float64 they round alike, bit for bit
(tests/test_robust_parity.py): Woop, Benthin and Wald 2013 for triangles, compensated dot
products (Ogita, Rump and Oishi 2005) for planes, PBRT-v4 6.8.6 for spawned rays; see the
docstrings there for the reasons and sources. The sphere tests, slide and robust (Ray
Tracing Gems ch. 7), are the render's own (rtfgu/kernels/intersect.py), so the hard cases
measure the code that renders.

Every function returns the hit distance t, or inf on a miss: in [tmin, tmax) for the
functions here, in [tmin, tmax] for the render kernels (intersect.py says why; the tie at
tmax changes no hard-case result). They are generic over float32 and float64: every
constant goes through ``lit`` (rtfgu.kernels.float3), because a bare numba literal is
float64 (or int64) and would silently promote float32 arithmetic to float64, which would
hide exactly the float32 failures these kernels measure. The one deliberate float64
computation is the fallback of the watertight test for edge functions that round to zero
(Woop et al. 2013, section 3). ``error_model="numpy"`` keeps IEEE division (x / 0 is inf
or NaN), so bad input gives a defined miss and never an exception. Points and vectors are
Float3 tuples, as in the rest of rtfgu.kernels.

The batch evaluators take one shape per ray as a row of the lecture constructor's
arguments (rtfgu.hardcases.kinds): sphere (center, radius), plane (point, normal),
triangle (v0, v1, v2: the vertices themselves, as watertightness needs the same floats in
every triangle that shares them), disk (center, normal, radius), rectangle (p0, a, b), box (p0, p1), open cylinder (y0, y1, radius),
part sphere (center, radius, phi_min, phi_max, theta_min, theta_max in degrees), annulus
(center, normal, inner_radius, outer_radius).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .float3 import cross, lit, lit_per_precision, normalize, row3, sub
from .next_float import next_down, next_up
from .intersect import (intersect_box, intersect_disk, intersect_open_cylinder, intersect_plane,
                        intersect_rectangle, intersect_sphere,
                        intersect_sphere_robust, intersect_triangle)
from .torus import intersect_torus
from .part_objects import intersect_annulus, intersect_convex_part_sphere


@njit(cache=True, error_model="numpy")
def _finite(a, b):
    """Whether the six components of the Float3s a and b are finite: x - x is 0 for a finite
    x and NaN for inf and NaN, and the sum carries any NaN through."""
    s = a[0] + a[1] + a[2] + b[0] + b[1] + b[2]
    return s - s == lit(0, s)


# --- plane ----------------------------------------------------------------------------

@njit(cache=True, error_model="numpy")
def _two_sum(a, b):
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


@njit(cache=True, error_model="numpy")
def _two_product(a, b):
    # Veltkamp's splitter 2^ceil(p/2) + 1: 2^12 + 1 for float32 (p = 24), 2^27 + 1 for float64.
    splitter = lit_per_precision(4097.0, 134217729.0, a)
    p = a * b
    ca = splitter * a
    ah = ca - (ca - a)
    al = a - ah
    cb = splitter * b
    bh = cb - (cb - b)
    bl = b - bh
    return p, al * bl - (((p - ah * bh) - al * bh) - ah * bl)


@njit(cache=True, error_model="numpy")
def _dot2_add(p, s, x, y):
    # One step of Ogita, Rump and Oishi 2005, "Dot2": add x * y to the sum p with its
    # running error s, both roundings caught exactly by TwoProduct and TwoSum.
    h, r = _two_product(x, y)
    p, q = _two_sum(p, h)
    return p, s + (q + r)


@njit(cache=True, error_model="numpy")
def _dot2_start(x, y):
    # "Dot2" over the three terms of x . y, as (sum, running error).
    p, s = _two_product(x[0], y[0])
    p, s = _dot2_add(p, s, x[1], y[1])
    return _dot2_add(p, s, x[2], y[2])


@njit(cache=True, error_model="numpy")
def _dot2_more(p, s, x, y):
    # "Dot2" continued over the three terms of x . y.
    p, s = _dot2_add(p, s, x[0], y[0])
    p, s = _dot2_add(p, s, x[1], y[1])
    return _dot2_add(p, s, x[2], y[2])


@njit(cache=True, error_model="numpy")
def plane_robust(origin, direction, tmin, tmax, point, normal):
    """t = ((a - o) . n) / (d . n) with a - o exact (TwoSum) and both dot products
    compensated (Dot2); d . n == 0 is a defined miss."""
    p, s = _dot2_start(direction, normal)
    denom = p + s
    if denom == lit(0, denom):
        return lit(math.inf, denom)
    sx, ex = _two_sum(point[0], -origin[0])
    sy, ey = _two_sum(point[1], -origin[1])
    sz, ez = _two_sum(point[2], -origin[2])
    p, s = _dot2_start((sx, sy, sz), normal)
    p, s = _dot2_more(p, s, (ex, ey, ez), normal)
    t = (p + s) / denom
    if t >= tmin and t < tmax:
        return t
    return lit(math.inf, denom)


# --- triangle -------------------------------------------------------------------------

@njit(cache=True, error_model="numpy")
def _pick(v, k):
    # v[k] for a Float3: a branch is cheaper than numba's runtime tuple index.
    if k == 0:
        return v[0]
    if k == 1:
        return v[1]
    return v[2]


@njit(cache=True, error_model="numpy")
def _shear(P, kx, ky, kz, Sx, Sy):
    # The vertex P - o in the ray's frame (Woop et al. 2013, eq. 3): x and y after the shear.
    Pkz = _pick(P, kz)
    return _pick(P, kx) - Sx * Pkz, _pick(P, ky) - Sy * Pkz


@njit(cache=True, error_model="numpy", inline="always")
def ray_shear(direction):
    """Woop et al. 2013 section 3: kz the axis of the largest |direction| component, kx and
    ky the next two (swapped when direction[kz] < 0, to keep the winding, so U, V, W keep
    their sign convention), and the shear Sx = d[kx] / d[kz], Sy = d[ky] / d[kz],
    Sz = 1 / d[kz]. The same for every triangle a ray meets (rtfgu.kernels.mesh)."""
    adx = abs(direction[0])
    ady = abs(direction[1])
    adz = abs(direction[2])
    if adx > ady:
        kz = 0 if adx > adz else 2
    else:
        kz = 1 if ady > adz else 2
    kx = (kz + 1) % 3
    ky = (kx + 1) % 3
    dkz = _pick(direction, kz)
    if dkz < lit(0, dkz):
        kx, ky = ky, kx
    return kx, ky, kz, _pick(direction, kx) / dkz, _pick(direction, ky) / dkz, lit(1, dkz) / dkz


@njit(cache=True, error_model="numpy")
def triangle_robust(origin, direction, tmin, tmax, v0, v1, v2):
    """Watertight ray/triangle, Woop, Benthin and Wald, JCGT 2(1), 2013 (non-culling)."""
    zero = lit(0, tmin)
    inf = lit(math.inf, tmin)
    kx, ky, kz, Sx, Sy, Sz = ray_shear(direction)
    A = sub(v0, origin)
    B = sub(v1, origin)
    C = sub(v2, origin)
    ax, ay = _shear(A, kx, ky, kz, Sx, Sy)
    bx, by = _shear(B, kx, ky, kz, Sx, Sy)
    cx, cy = _shear(C, kx, ky, kz, Sx, Sy)
    U = cx * by - cy * bx
    V = ax * cy - ay * cx
    W = bx * ay - by * ax
    # A zero-area triangle has exactly zero e0 x e1; the paper's det == 0 test alone lets
    # some through, because U + V + W of a collinear triangle need not round to zero.
    n = cross(sub(v1, v0), sub(v2, v0))
    if n[0] == zero and n[1] == zero and n[2] == zero:
        return inf
    if U == zero or V == zero or W == zero:
        # Woop et al. section 3: an edge function that rounds to zero is recomputed in
        # double, so that the edge test stays consistent with the exact one (a no-op in
        # float64).
        U = lit(np.float64(cx) * np.float64(by) - np.float64(cy) * np.float64(bx), tmin)
        V = lit(np.float64(ax) * np.float64(cy) - np.float64(ay) * np.float64(cx), tmin)
        W = lit(np.float64(bx) * np.float64(ay) - np.float64(by) * np.float64(ax), tmin)
    if (U < zero or V < zero or W < zero) and (U > zero or V > zero or W > zero):
        return inf
    det = U + V + W
    if det == zero:
        return inf
    T = U * (Sz * _pick(A, kz)) + V * (Sz * _pick(B, kz)) + W * (Sz * _pick(C, kz))
    t = T / det
    if t >= tmin and t < tmax:
        return t
    return inf


# --- spawned rays (PBRT-v4 6.8.5-6.8.6) -----------------------------------------------

@njit(cache=True, error_model="numpy")
def gamma(n, x):
    """PBRT's gamma(n) = n u / (1 - n u) in the precision of x (u = half the ulp of 1)."""
    nu = lit(n, x) * lit_per_precision(2.0 ** -24, 2.0 ** -53, x)
    return nu / (lit(1, x) - nu)


@njit(cache=True, error_model="numpy")
def sphere_point_error(p, center):
    g5 = gamma(5, p[0])
    g3 = gamma(3, p[0])
    qx = abs(p[0] - center[0])
    qy = abs(p[1] - center[1])
    qz = abs(p[2] - center[2])
    return (g5 * qx + g3 * (qx + abs(center[0])), g5 * qy + g3 * (qy + abs(center[1])),
            g5 * qz + g3 * (qz + abs(center[2])))


@njit(cache=True, error_model="numpy")
def triangle_point_error(v0, v1, v2):
    g7 = gamma(7, v0[0])
    return (g7 * (abs(v0[0]) + abs(v1[0]) + abs(v2[0])), g7 * (abs(v0[1]) + abs(v1[1]) + abs(v2[1])),
            g7 * (abs(v0[2]) + abs(v1[2]) + abs(v2[2])))


@njit(cache=True, error_model="numpy")
def plane_point_error(p, point):
    g7 = gamma(7, p[0])
    return (g7 * (abs(p[0]) + abs(point[0])), g7 * (abs(p[1]) + abs(point[1])),
            g7 * (abs(p[2]) + abs(point[2])))


@njit(cache=True, error_model="numpy")
def _away(x, o):
    if o > lit(0, x):
        return next_up(x)
    if o < lit(0, x):
        return next_down(x)
    return x


@njit(cache=True, error_model="numpy")
def offset_ray_origin(p, p_error, n, w):
    """PBRT-v4 OffsetRayOrigin: p + (|n| . p_error) n toward w, rounded away from p."""
    d = abs(n[0]) * p_error[0] + abs(n[1]) * p_error[1] + abs(n[2]) * p_error[2]
    sx = n[0] * d
    sy = n[1] * d
    sz = n[2] * d
    if w[0] * n[0] + w[1] * n[1] + w[2] * n[2] < lit(0, d):
        sx = -sx
        sy = -sy
        sz = -sz
    return _away(p[0] + sx, sx), _away(p[1] + sy, sy), _away(p[2] + sz, sz)


# --- batch evaluators -----------------------------------------------------------------
# Per kind and formula an adapter (origin, direction, tmin, tmax, shapes, i) -> t for the
# shape in row i, and per kind a test (origin, direction, tmin, shapes, i) -> bool that the
# ray and the row are finite. The render relies on compile_scene for finite input; the
# hard cases include non-finite rays and shapes, which the robust formulas answer with a
# miss: ``batch`` runs them behind the kind's test, the slide formulas behind ``_any``.

@njit(cache=True, error_model="numpy")
def _any(o, d, tmin, shapes, i):
    return True


@njit(cache=True, error_model="numpy")
def sphere_finite(o, d, tmin, shapes, i):
    return _finite(o, d) and _finite(row3(shapes, i, 0), (shapes[i, 3], tmin, lit(0, tmin)))


@njit(cache=True, error_model="numpy")
def triangle_finite(o, d, tmin, shapes, i):
    return (_finite(o, d) and _finite(row3(shapes, i, 0), row3(shapes, i, 3))
            and _finite(row3(shapes, i, 6), (tmin, tmin, tmin)))


@njit(cache=True, error_model="numpy")
def sphere_slide(o, d, tmin, tmax, shapes, i):
    return intersect_sphere(o, d, tmin, tmax, row3(shapes, i, 0), shapes[i, 3])


@njit(cache=True, error_model="numpy")
def sphere_robust(o, d, tmin, tmax, shapes, i):
    return intersect_sphere_robust(o, d, tmin, tmax, row3(shapes, i, 0), shapes[i, 3])


@njit(cache=True, error_model="numpy")
def plane_slide(o, d, tmin, tmax, shapes, i):
    return intersect_plane(o, d, tmin, tmax, row3(shapes, i, 0), row3(shapes, i, 3))


@njit(cache=True, error_model="numpy")
def plane_robust_row(o, d, tmin, tmax, shapes, i):
    # Tests finiteness itself (ADAPTERS pairs it with _any), before the compensated sums.
    point = row3(shapes, i, 0)
    normal = row3(shapes, i, 3)
    if _finite(o, d) and _finite(point, normal) and _finite((tmin, tmin, tmin), (tmin, tmin, tmin)):
        return plane_robust(o, d, tmin, tmax, point, normal)
    return lit(math.inf, tmin)


@njit(cache=True, error_model="numpy")
def triangle_slide(o, d, tmin, tmax, shapes, i):
    # e0 = v1 - v0, e1 = v2 - v0 and n = e0 x e1 rounded in the rows' precision, as
    # compile_scene stores them in rtfgu.layout.
    v0 = row3(shapes, i, 0)
    e0 = sub(row3(shapes, i, 3), v0)
    e1 = sub(row3(shapes, i, 6), v0)
    return intersect_triangle(o, d, tmin, tmax, v0, e0, e1, cross(e0, e1))


@njit(cache=True, error_model="numpy")
def triangle_robust_row(o, d, tmin, tmax, shapes, i):
    return triangle_robust(o, d, tmin, tmax, row3(shapes, i, 0), row3(shapes, i, 3), row3(shapes, i, 6))


@njit(cache=True, error_model="numpy")
def disk_slide(o, d, tmin, tmax, shapes, i):
    return intersect_disk(o, d, tmin, tmax, row3(shapes, i, 0), row3(shapes, i, 3), shapes[i, 6])


@njit(cache=True, error_model="numpy")
def rectangle_slide(o, d, tmin, tmax, shapes, i):
    # The normal normalize(a x b) rounded in the rows' precision.
    a = row3(shapes, i, 3)
    b = row3(shapes, i, 6)
    return intersect_rectangle(o, d, tmin, tmax, row3(shapes, i, 0), a, b, normalize(cross(a, b)))


@njit(cache=True, error_model="numpy")
def box_slide(o, d, tmin, tmax, shapes, i):
    return intersect_box(o, d, tmin, tmax, row3(shapes, i, 0), row3(shapes, i, 3))


@njit(cache=True, error_model="numpy")
def open_cylinder_slide(o, d, tmin, tmax, shapes, i):
    return intersect_open_cylinder(o, d, tmin, tmax, shapes[i, 0], shapes[i, 1], shapes[i, 2])


@njit(cache=True, error_model="numpy")
def torus_slide(o, d, tmin, tmax, shapes, i):
    return intersect_torus(o, d, tmin, tmax, shapes[i, 0], shapes[i, 1])


@njit(cache=True, error_model="numpy")
def convex_part_sphere_slide(o, d, tmin, tmax, shapes, i):
    # The angles in degrees: radians and cosines in float64, then rounded to the rows'
    # precision, as the lecture class computes them and compile_scene stores them.
    radians = np.float64(math.pi / 180.0)
    theta_min = np.float64(shapes[i, 6]) * radians
    theta_max = np.float64(shapes[i, 7]) * radians
    return intersect_convex_part_sphere(o, d, tmin, tmax, row3(shapes, i, 0), shapes[i, 3],
                                        lit(np.float64(shapes[i, 4]) * radians, tmin),
                                        lit(np.float64(shapes[i, 5]) * radians, tmin),
                                        lit(math.cos(theta_min), tmin), lit(math.cos(theta_max), tmin))


@njit(cache=True, error_model="numpy")
def annulus_slide(o, d, tmin, tmax, shapes, i):
    return intersect_annulus(o, d, tmin, tmax, row3(shapes, i, 0), row3(shapes, i, 3), shapes[i, 6], shapes[i, 7])


@njit(cache=True, error_model="numpy")
def instance_slide(o, d, tmin, tmax, shapes, i):
    """The hard cases' instance (rtfgu.hardcases.kinds.ellipsoid): the unit sphere on the ray
    through the inverse matrix that Instance.scale then translate compose, 1 / s and
    (1 / s) (-t) per axis, in the rows' precision."""
    one = lit(1.0, tmin)
    inv = (one / shapes[i, 0], one / shapes[i, 1], one / shapes[i, 2])
    moved = (inv[0] * -shapes[i, 3], inv[1] * -shapes[i, 4], inv[2] * -shapes[i, 5])
    origin = (inv[0] * o[0] + moved[0], inv[1] * o[1] + moved[1], inv[2] * o[2] + moved[2])
    zero = lit(0.0, tmin)
    return intersect_sphere(origin, (inv[0] * d[0], inv[1] * d[1], inv[2] * d[2]), tmin, tmax,
                            (zero, zero, zero), one)


# Not cached: numba 0.68.1 keeps the cached signatures of a function whose arguments are
# other jitted functions by weak references to those functions' types (a limit of numba's cache),
# and a process after the one that filled the cache could not save into it: a KeyError, then
# "underlying object has vanished" (docs/compile_time.md). Each compiles in about 0.3 s.
@njit(error_model="numpy")
def batch(adapter, finite, origins, directions, tmin, tmax, shapes):
    """t of ray i against the shape in row i of ``shapes`` through ``adapter``, or inf
    where ``finite`` says the input is not finite."""
    out = np.empty(origins.shape[0], dtype=origins.dtype)
    for i in range(origins.shape[0]):
        o = row3(origins, i, 0)
        d = row3(directions, i, 0)
        if finite(o, d, tmin[i], shapes, i):
            out[i] = adapter(o, d, tmin[i], tmax[i], shapes, i)
        else:
            out[i] = lit(math.inf, tmin[i])
    return out


@njit(cache=True, error_model="numpy")
def sphere_error(p, shapes, i):
    return sphere_point_error(p, row3(shapes, i, 0))


@njit(cache=True, error_model="numpy")
def plane_error(p, shapes, i):
    return plane_point_error(p, row3(shapes, i, 0))


@njit(cache=True, error_model="numpy")
def triangle_error(p, shapes, i):
    return triangle_point_error(row3(shapes, i, 0), row3(shapes, i, 3), row3(shapes, i, 6))


@njit(error_model="numpy")     # not cached, as batch
def batch_spawn(point_error, positions, normals, directions, shapes):
    """PBRT's offset origins of secondary rays leaving ``positions`` on the shape in row i
    of ``shapes``, whose point error ``point_error(p, shapes, i)`` bounds; tmin is 0."""
    origins = np.empty_like(positions)
    for i in range(positions.shape[0]):
        p = row3(positions, i, 0)
        o = offset_ray_origin(p, point_error(p, shapes, i), row3(normals, i, 0),
                              row3(directions, i, 0))
        origins[i, 0] = o[0]
        origins[i, 1] = o[1]
        origins[i, 2] = o[2]
    return origins


# (kind name, formula) -> (adapter, finiteness test) for ``batch``, and kind name -> point
# error for ``batch_spawn``, for rtfgu.hardcases.
ADAPTERS = {("sphere", "slide"): (sphere_slide, _any), ("sphere", "robust"): (sphere_robust, sphere_finite),
            ("plane", "slide"): (plane_slide, _any), ("plane", "robust"): (plane_robust_row, _any),
            ("triangle", "slide"): (triangle_slide, _any),
            ("triangle", "robust"): (triangle_robust_row, triangle_finite),
            ("disk", "slide"): (disk_slide, _any), ("rectangle", "slide"): (rectangle_slide, _any),
            ("box", "slide"): (box_slide, _any), ("open_cylinder", "slide"): (open_cylinder_slide, _any),
            ("torus", "slide"): (torus_slide, _any),
            ("convex_part_sphere", "slide"): (convex_part_sphere_slide, _any), ("annulus", "slide"): (annulus_slide, _any),
            ("instance", "slide"): (instance_slide, _any)}
POINT_ERRORS = {"sphere": sphere_error, "plane": plane_error, "triangle": triangle_error}
