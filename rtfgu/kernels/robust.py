"""numba robust single-ray intersections and the batch evaluators of rtfgu.hardcases.

The batch evaluators run the render's own kernels (rtfgu/kernels/intersect.py) for the
formulas the render has: the slide sphere, plane and triangle tests and the robust sphere
(Ray Tracing Gems ch. 7), so the hard cases measure the code that renders. The robust plane
and triangle tests and the spawned-ray offset exist only here; they repeat rtfgu/robust.py
(Woop, Benthin and Wald 2013 for triangles, compensated dot products for planes, PBRT-v4
6.8.6 for spawned rays); see the docstrings there for the reasons and sources.

Every function returns the hit distance t, or inf on a miss: in [tmin, tmax) for the
functions here, in [tmin, tmax] for the render kernels (intersect.py says why; the tie
at tmax changes no hard-case result). They are generic over float32 and float64: every literal
goes through ``F = type(x)``, because a bare numba literal is float64 (or int64) and would
silently promote float32 arithmetic to float64, which would hide exactly the float32
failures these kernels measure. The one deliberate float64 computation is the fallback of
the watertight test for edge functions that round to zero (Woop et al. 2013, section 3).
``error_model="numpy"`` keeps IEEE division (x / 0 is inf or NaN) instead of numba's
default ZeroDivisionError, so that bad input gives a defined miss and never an exception.

Shape parameters, one row per ray (the hard-case families of rtfgu.hardcases):
    sphere    (N, 4)  center, radius
    plane     (N, 6)  point, normal
    triangle  (N, 9)  v0, v1, v2   (the vertices themselves: watertightness needs the same
                                    floats in every triangle that shares them)
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..layout import PLANE, SPHERE, TRIANGLE
from ..shading import SPAWN_EPSILON
from .float3 import cross, lit, row3, sub
from .intersect import (intersect_plane, intersect_sphere, intersect_sphere_robust,
                        intersect_triangle)

SLIDE = 0
ROBUST = 1
FORMULAS = {SLIDE: "slide", ROBUST: "robust"}


@njit(cache=True, error_model="numpy")
def _finite6(a, b, c, d, e, f):
    # x - x is 0 for a finite x and NaN for inf and NaN; the sum carries any NaN through.
    s = a + b + c + d + e + f
    return s - s == type(a)(0.0)


# --- plane ----------------------------------------------------------------------------

@njit(cache=True, error_model="numpy")
def _two_sum(a, b):
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


@njit(cache=True, error_model="numpy")
def _two_product(a, b):
    F = type(a)
    # Veltkamp's splitter 2^ceil(p/2) + 1: 2^12 + 1 for float32 (p = 24), 2^27 + 1 for float64.
    # 1 + 1e-10 rounds to 1 in float32 only; LLVM folds the test to a constant.
    splitter = F(4097.0) if F(1.0) + F(1e-10) == F(1.0) else F(134217729.0)
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
def _dot2_3(x0, x1, x2, y0, y1, y2):
    # "Dot2" for three terms.
    p, s = _two_product(x0, y0)
    p, s = _dot2_add(p, s, x1, y1)
    p, s = _dot2_add(p, s, x2, y2)
    return p + s


@njit(cache=True, error_model="numpy")
def _dot2_6(x0, x1, x2, x3, x4, x5, y0, y1, y2, y3, y4, y5):
    p, s = _two_product(x0, y0)
    p, s = _dot2_add(p, s, x1, y1)
    p, s = _dot2_add(p, s, x2, y2)
    p, s = _dot2_add(p, s, x3, y3)
    p, s = _dot2_add(p, s, x4, y4)
    p, s = _dot2_add(p, s, x5, y5)
    return p + s


@njit(cache=True, error_model="numpy")
def plane_robust(ox, oy, oz, dx, dy, dz, tmin, tmax, px, py, pz, nx, ny, nz):
    """t = ((a - o) . n) / (d . n) with a - o exact (TwoSum) and both dot products
    compensated (Dot2); d . n == 0 and non-finite input are a defined miss."""
    F = type(ox)
    inf = F(math.inf)
    if not (_finite6(ox, oy, oz, dx, dy, dz) and _finite6(px, py, pz, nx, ny, nz)
            and _finite6(tmin, F(0.0), F(0.0), F(0.0), F(0.0), F(0.0))):
        return inf
    denom = _dot2_3(dx, dy, dz, nx, ny, nz)
    if denom == F(0.0):
        return inf
    sx, ex = _two_sum(px, -ox)
    sy, ey = _two_sum(py, -oy)
    sz, ez = _two_sum(pz, -oz)
    num = _dot2_6(sx, sy, sz, ex, ey, ez, nx, ny, nz, nx, ny, nz)
    t = num / denom
    if t >= tmin and t < tmax:
        return t
    return inf


# --- triangle -------------------------------------------------------------------------

@njit(cache=True, error_model="numpy")
def _pick(x, y, z, k):
    if k == 0:
        return x
    if k == 1:
        return y
    return z


@njit(cache=True, error_model="numpy")
def triangle_robust(ox, oy, oz, dx, dy, dz, tmin, tmax,
                    v0x, v0y, v0z, v1x, v1y, v1z, v2x, v2y, v2z):
    """Watertight ray/triangle, Woop, Benthin and Wald, JCGT 2(1), 2013 (non-culling)."""
    F = type(ox)
    inf = F(math.inf)
    zero = F(0.0)
    if not (_finite6(ox, oy, oz, dx, dy, dz) and _finite6(v0x, v0y, v0z, v1x, v1y, v1z)
            and _finite6(v2x, v2y, v2z, tmin, zero, zero)):
        return inf
    adx = abs(dx)
    ady = abs(dy)
    adz = abs(dz)
    if adx > ady:
        kz = 0 if adx > adz else 2
    else:
        kz = 1 if ady > adz else 2
    kx = kz + 1
    if kx == 3:
        kx = 0
    ky = kx + 1
    if ky == 3:
        ky = 0
    dkz = _pick(dx, dy, dz, kz)
    if dkz < zero:
        kx, ky = ky, kx
    Sx = _pick(dx, dy, dz, kx) / dkz
    Sy = _pick(dx, dy, dz, ky) / dkz
    Sz = F(1.0) / dkz
    Ax = v0x - ox
    Ay = v0y - oy
    Az = v0z - oz
    Bx = v1x - ox
    By = v1y - oy
    Bz = v1z - oz
    Cx = v2x - ox
    Cy = v2y - oy
    Cz = v2z - oz
    Akz = _pick(Ax, Ay, Az, kz)
    Bkz = _pick(Bx, By, Bz, kz)
    Ckz = _pick(Cx, Cy, Cz, kz)
    ax = _pick(Ax, Ay, Az, kx) - Sx * Akz
    ay = _pick(Ax, Ay, Az, ky) - Sy * Akz
    bx = _pick(Bx, By, Bz, kx) - Sx * Bkz
    by = _pick(Bx, By, Bz, ky) - Sy * Bkz
    cx = _pick(Cx, Cy, Cz, kx) - Sx * Ckz
    cy = _pick(Cx, Cy, Cz, ky) - Sy * Ckz
    U = cx * by - cy * bx
    V = ax * cy - ay * cx
    W = bx * ay - by * ax
    # A zero-area triangle has exactly zero e0 x e1; the paper's det == 0 test alone lets
    # some through, because U + V + W of a collinear triangle need not round to zero.
    e0x = v1x - v0x
    e0y = v1y - v0y
    e0z = v1z - v0z
    e1x = v2x - v0x
    e1y = v2y - v0y
    e1z = v2z - v0z
    if (e0y * e1z - e0z * e1y == zero and e0z * e1x - e0x * e1z == zero
            and e0x * e1y - e0y * e1x == zero):
        return inf
    if U == zero or V == zero or W == zero:
        # Woop et al. section 3: an edge function that rounds to zero is recomputed in
        # double, so that the edge test stays consistent with the exact one (a no-op in
        # float64).
        U = F(np.float64(cx) * np.float64(by) - np.float64(cy) * np.float64(bx))
        V = F(np.float64(ax) * np.float64(cy) - np.float64(ay) * np.float64(cx))
        W = F(np.float64(bx) * np.float64(ay) - np.float64(by) * np.float64(ax))
    if (U < zero or V < zero or W < zero) and (U > zero or V > zero or W > zero):
        return inf
    det = U + V + W
    if det == zero:
        return inf
    T = U * (Sz * Akz) + V * (Sz * Bkz) + W * (Sz * Ckz)
    t = T / det
    if t >= tmin and t < tmax:
        return t
    return inf


# --- spawned rays (PBRT-v4 6.8.6) -----------------------------------------------------

@njit(cache=True, error_model="numpy")
def gamma(n, x):
    """PBRT's gamma(n) = n u / (1 - n u) in the precision of x (u = half the ulp of 1)."""
    F = type(x)
    u = F(2.0 ** -24) if F(1.0) + F(1e-10) == F(1.0) else F(2.0 ** -53)
    nu = F(n) * u
    return nu / (F(1.0) - nu)


@njit(cache=True, error_model="numpy")
def sphere_point_error(px, py, pz, cx, cy, cz):
    g5 = gamma(5, px)
    g3 = gamma(3, px)
    qx = abs(px - cx)
    qy = abs(py - cy)
    qz = abs(pz - cz)
    return (g5 * qx + g3 * (qx + abs(cx)), g5 * qy + g3 * (qy + abs(cy)),
            g5 * qz + g3 * (qz + abs(cz)))


@njit(cache=True, error_model="numpy")
def triangle_point_error(v0x, v0y, v0z, v1x, v1y, v1z, v2x, v2y, v2z):
    g7 = gamma(7, v0x)
    return (g7 * (abs(v0x) + abs(v1x) + abs(v2x)), g7 * (abs(v0y) + abs(v1y) + abs(v2y)),
            g7 * (abs(v0z) + abs(v1z) + abs(v2z)))


@njit(cache=True, error_model="numpy")
def plane_point_error(px, py, pz, ax, ay, az):
    g7 = gamma(7, px)
    return (g7 * (abs(px) + abs(ax)), g7 * (abs(py) + abs(ay)), g7 * (abs(pz) + abs(az)))


@njit(cache=True, error_model="numpy")
def _away(x, o):
    F = type(x)
    if o > F(0.0):
        return np.nextafter(x, F(math.inf))
    if o < F(0.0):
        return np.nextafter(x, F(-math.inf))
    return x


@njit(cache=True, error_model="numpy")
def offset_ray_origin(px, py, pz, ex, ey, ez, nx, ny, nz, wx, wy, wz):
    """PBRT-v4 OffsetRayOrigin: p + (|n| . p_error) n toward w, rounded away from p."""
    F = type(px)
    d = abs(nx) * ex + abs(ny) * ey + abs(nz) * ez
    sx = d * nx
    sy = d * ny
    sz = d * nz
    if wx * nx + wy * ny + wz * nz < F(0.0):
        sx = -sx
        sy = -sy
        sz = -sz
    return _away(px + sx, sx), _away(py + sy, sy), _away(pz + sz, sz)


# --- batch evaluators -----------------------------------------------------------------

@njit(cache=True, error_model="numpy")
def batch_sphere(formula, origins, directions, tmin, tmax, shapes):
    """The render's sphere tests, one ray per row. The robust one runs behind a finiteness
    test: the render kernel relies on compile_scene for finite input, and the hard cases
    include non-finite rays and spheres, which must be a defined miss."""
    n = origins.shape[0]
    out = np.empty(n, dtype=origins.dtype)
    for i in range(n):
        o = row3(origins, i, 0)
        d = row3(directions, i, 0)
        center = row3(shapes, i, 0)
        radius = shapes[i, 3]
        if formula == ROBUST:
            if (_finite6(o[0], o[1], o[2], d[0], d[1], d[2])
                    and _finite6(center[0], center[1], center[2], radius, tmin[i], lit(0, radius))):
                out[i] = intersect_sphere_robust(o, d, tmin[i], tmax[i], center, radius)
            else:
                out[i] = lit(math.inf, radius)
        else:
            out[i] = intersect_sphere(o, d, tmin[i], tmax[i], center, radius)
    return out


@njit(cache=True, error_model="numpy")
def batch_plane(formula, origins, directions, tmin, tmax, shapes):
    n = origins.shape[0]
    out = np.empty(n, dtype=origins.dtype)
    for i in range(n):
        o = origins[i]
        d = directions[i]
        s = shapes[i]
        if formula == ROBUST:
            out[i] = plane_robust(o[0], o[1], o[2], d[0], d[1], d[2], tmin[i], tmax[i],
                                  s[0], s[1], s[2], s[3], s[4], s[5])
        else:
            out[i] = intersect_plane(row3(origins, i, 0), row3(directions, i, 0), tmin[i],
                                     tmax[i], row3(shapes, i, 0), row3(shapes, i, 3))
    return out


@njit(cache=True, error_model="numpy")
def batch_triangle(formula, origins, directions, tmin, tmax, shapes):
    """The slide test is the render's, on e0 = v1 - v0, e1 = v2 - v0 and n = e0 x e1 as in
    rtfgu.layout, computed here in the rows' own precision."""
    n = origins.shape[0]
    out = np.empty(n, dtype=origins.dtype)
    for i in range(n):
        o = origins[i]
        d = directions[i]
        s = shapes[i]
        if formula == ROBUST:
            out[i] = triangle_robust(o[0], o[1], o[2], d[0], d[1], d[2], tmin[i], tmax[i],
                                     s[0], s[1], s[2], s[3], s[4], s[5], s[6], s[7], s[8])
        else:
            v0 = row3(shapes, i, 0)
            e0 = sub(row3(shapes, i, 3), v0)
            e1 = sub(row3(shapes, i, 6), v0)
            out[i] = intersect_triangle(row3(origins, i, 0), row3(directions, i, 0), tmin[i],
                                        tmax[i], v0, e0, e1, cross(e0, e1))
    return out


@njit(cache=True, error_model="numpy")
def batch_spawn(formula, kind, positions, normals, directions, shapes):
    """Origins and tmin of secondary rays leaving ``positions`` (on the shapes of ``kind``):
    the slide's fixed SPAWN_EPSILON as tmin, or PBRT's offset origin with tmin 0."""
    n = positions.shape[0]
    F = positions.dtype.type
    origins = np.empty_like(positions)
    tmin = np.empty(n, dtype=positions.dtype)
    for i in range(n):
        p = positions[i]
        if formula != ROBUST:
            origins[i, 0] = p[0]
            origins[i, 1] = p[1]
            origins[i, 2] = p[2]
            tmin[i] = F(SPAWN_EPSILON)
            continue
        s = shapes[i]
        if kind == SPHERE:
            ex, ey, ez = sphere_point_error(p[0], p[1], p[2], s[0], s[1], s[2])
        elif kind == TRIANGLE:
            ex, ey, ez = triangle_point_error(s[0], s[1], s[2], s[3], s[4], s[5], s[6], s[7], s[8])
        else:
            ex, ey, ez = plane_point_error(p[0], p[1], p[2], s[0], s[1], s[2])
        nn = normals[i]
        w = directions[i]
        ox, oy, oz = offset_ray_origin(p[0], p[1], p[2], ex, ey, ez, nn[0], nn[1], nn[2],
                                       w[0], w[1], w[2])
        origins[i, 0] = ox
        origins[i, 1] = oy
        origins[i, 2] = oz
        tmin[i] = F(0.0)
    return origins, tmin


BATCH = {SPHERE: batch_sphere, PLANE: batch_plane, TRIANGLE: batch_triangle}
