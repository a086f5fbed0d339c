# release: solves a03
"""Robust ray/shape intersection, next to the slide formulas of ``rtfgu.shapes``.

The slide formulas are exact in real arithmetic and fail in floating point in known places:
the sphere quadratic loses the discriminant to cancellation when the sphere is far away or
small (b^2 and 4ac agree in most of their digits), the barycentric triangle test lets rays
through the edges and vertices that two triangles share, a plane test divides by a d . n
whose sign is noise for nearly parallel rays, and a fixed ``SPAWN_EPSILON`` is too small at
large coordinates (the ray hits the surface it leaves) and too large in tiny scenes (it
skips a real hit just beyond). Each function below fixes one of these and cites its source;
the test suite ``tests/test_hardcases*.py`` measures both versions on ``rtfgu.hardcases``.

All functions follow ``Shape.intersect_p``: True on a hit in [ray.tmin, ray.tmax), and then
``ray.tmax`` is the hit distance. They run in Python floats (float64). The numba versions,
for float32 and float64, are in ``rtfgu.kernels.intersect`` (the sphere, which the render
kernel uses) and ``rtfgu.kernels.robust`` (triangle, plane, spawn offset); they perform the
same operations in the same order, so that in float64 both give the same bits
(tests/test_robust_parity.py). The WGSL ones are ``rtfgu/wgsl/robust_*.wgsl``.
"""
from __future__ import annotations

import math

from .float3 import Float3, as_float3, dot
from .ray import Ray
from .shapes.plane import Plane
from .shapes.sphere import Sphere

WHITE = (1.0, 1.0, 1.0)

# Unit roundoff u (half an ulp of 1) of each precision, and PBRT's gamma(n) = n u / (1 - n u),
# the bound on the relative error of n chained roundings (PBRT-v4, section 6.8.1).
UNIT_ROUNDOFF = {"float64": 2.0 ** -53, "float32": 2.0 ** -24}


def gamma(n: int, precision: str = "float64") -> float:
    u = UNIT_ROUNDOFF[precision]
    return (n * u) / (1.0 - n * u)


def _accept(ray: Ray, t: float) -> bool:
    if t >= ray.tmin and t < ray.tmax:
        ray.tmax = t
        return True
    return False


# --- sphere ---------------------------------------------------------------------------

def intersect_sphere_robust(ray: Ray, center, radius: float) -> bool:
    """Ray/sphere after Haines, Guenther and Akenine-Moeller, "Precision Improvements for
    Ray/Sphere Intersection", Ray Tracing Gems, chapter 7 (2019), eqs. 7.5-7.8.

    With f = o - c, a = d . d and b' = -f . d:
    - the discriminant is a (r^2 - |f + (b'/a) d|^2): the squared distance from the centre to
      the line, instead of b^2 - 4ac, whose two terms cancel for a far or small sphere;
    - the roots are t0 = c / q and t1 = q / a with q = b' + sign(b') sqrt(disc), which never
      subtracts two nearly equal numbers (the near root of the slide formula does when the
      origin is close to the surface).

    Both divisions by a go through 1 / a, as in the render kernel
    (rtfgu.kernels.intersect.sphere_roots_robust, where 1 / a depends on the ray only and is
    computed once for all spheres): the two compute the same operations in the same order.

    The direction is first scaled by the power of two s = 2^-e that brings its largest
    component into [0.5, 1) (``direction_scale``), and the roots found for s d are scaled
    back by s. Multiplying by a power of two is exact, so every operation below rounds as it
    did for d itself and the roots are bit for bit those of d; but d . d no longer overflows
    or underflows for a direction of any length (1e-150 or 1e150 in float64, 1e-30 or 1e30
    in float32).
    """
    sphere = Sphere(center, radius, WHITE)  # refuses what the lecture's Sphere refuses
    center, radius = sphere.center, sphere.radius
    f = ray.origin - center
    s = direction_scale(ray.direction)
    d = ray.direction * s
    a = dot(d, d)
    inv_a = 1.0 / a
    b = -dot(f, d)
    c = dot(f, f) - radius * radius
    l = f + d * (b * inv_a)
    disc = a * (radius * radius - dot(l, l))
    if disc < 0.0:
        return False
    root = math.sqrt(disc)
    q = b + root if b >= 0.0 else b - root
    if q == 0.0:
        # b' = 0 and disc = 0: the origin is the tangent point, both roots are 0.
        t0 = t1 = 0.0
    else:
        t0 = c / q * s
        t1 = q * inv_a * s
    if t0 > t1:
        t0, t1 = t1, t0
    return _accept(ray, t0) or _accept(ray, t1)


def direction_scale(d) -> float:
    """The power of two 2^-e with e the exponent of d's largest component (math.frexp):
    s d has its largest component in [0.5, 1); 1 for the zero vector."""
    return math.ldexp(1.0, -math.frexp(max(abs(d.x), abs(d.y), abs(d.z)))[1])


# --- plane ----------------------------------------------------------------------------
# Error-free transformations: a + b = s + e and a * b = p + e exactly (Knuth's TwoSum,
# Dekker's TwoProduct with Veltkamp's split), and the compensated dot product Dot2 of
# Ogita, Rump and Oishi, "Accurate Sum and Dot Product", SIAM J. Sci. Comput. 26(6), 2005:
# as accurate as if computed in twice the working precision, so its sign is right unless
# the exact dot product is (nearly) zero.

_SPLITTER = 134217729.0  # 2^27 + 1 for float64


def two_sum(a: float, b: float) -> tuple[float, float]:
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def _split(a: float) -> tuple[float, float]:
    c = _SPLITTER * a
    hi = c - (c - a)
    return hi, a - hi


def two_product(a: float, b: float) -> tuple[float, float]:
    p = a * b
    ah, al = _split(a)
    bh, bl = _split(b)
    return p, al * bl - (((p - ah * bh) - al * bh) - ah * bl)


def dot2(xs, ys) -> float:
    """Compensated dot product (Ogita, Rump and Oishi 2005, Algorithm 5.3 "Dot2")."""
    p, s = two_product(xs[0], ys[0])
    for x, y in zip(xs[1:], ys[1:]):
        h, r = two_product(x, y)
        p, q = two_sum(p, h)
        s += q + r
    return p + s


def intersect_plane_robust(ray: Ray, point, normal) -> bool:
    """Ray/plane t = ((a - o) . n) / (d . n) (lecture 01, "Ray-Plane Intersection") with
    both dot products compensated (Dot2, Ogita, Rump and Oishi 2005) and a - o kept exact as
    the pair of TwoSum, so that the sign of t is right for nearly parallel rays and for
    origins close to the plane. A ray with d . n == 0 is a defined miss (it never meets the
    plane, or lies in it, which we do not count as a hit)."""
    plane = Plane(point, normal, WHITE)  # refuses what the lecture's Plane refuses
    point, n = plane.point, plane.normal
    o, d = ray.origin, ray.direction
    denom = dot2((d.x, d.y, d.z), (n.x, n.y, n.z))
    if denom == 0.0:
        return False
    sx, ex = two_sum(point.x, -o.x)
    sy, ey = two_sum(point.y, -o.y)
    sz, ez = two_sum(point.z, -o.z)
    num = dot2((sx, sy, sz, ex, ey, ez), (n.x, n.y, n.z, n.x, n.y, n.z))
    return _accept(ray, num / denom)


# --- triangle -------------------------------------------------------------------------

def _max_dim(v: Float3) -> int:
    ax, ay, az = abs(v.x), abs(v.y), abs(v.z)
    if ax > ay:
        return 0 if ax > az else 2
    return 1 if ay > az else 2


def intersect_triangle_watertight(ray: Ray, v0, v1, v2) -> bool:
    """Watertight ray/triangle after Woop, Benthin and Wald, "Watertight Ray/Triangle
    Intersection", JCGT 2(1), 2013 (the non-culling variant of their Listing 1).

    The vertices are moved into a frame where the ray starts at the origin and runs along +z
    (a translation, a permutation and a shear); the edge functions U, V, W are then 2D cross
    products of vertex pairs. Two triangles that share an edge compute that edge's function
    from the same two transformed vertices with the operands swapped, so the values are exact
    negatives of each other and a ray through the edge is accepted by at least one of them.
    The barycentric slide test has no such property: each triangle rounds its own e0, e1, n.
    A zero-area triangle (e0 x e1 == 0, or det == 0) is a defined miss."""
    return watertight_hit(ray, as_float3(v0, "v0"), as_float3(v1, "v1"), as_float3(v2, "v2"))


def watertight_hit(ray: Ray, v0: Float3, v1: Float3, v2: Float3) -> bool:
    """intersect_triangle_watertight of vertices already checked (a mesh's faces, checked when
    the mesh was made). Written on components, as the paper's listing is: the coordinates
    picked by index (kx, ky, kz) from tuples, each operation the one of the listing, in its
    order, so the numba path's copy (rtfgu.kernels.robust.ray_shear and rtfgu.kernels.mesh)
    rounds alike."""
    o, d = ray.origin, ray.direction
    dv = (d.x, d.y, d.z)
    kz = _max_dim(d)
    kx = (kz + 1) % 3
    ky = (kx + 1) % 3
    if dv[kz] < 0.0:
        kx, ky = ky, kx  # keep the winding, so U, V, W keep their sign convention
    Sx = dv[kx] / dv[kz]
    Sy = dv[ky] / dv[kz]
    Sz = 1.0 / dv[kz]
    ox, oy, oz = o.x, o.y, o.z
    A = (v0.x - ox, v0.y - oy, v0.z - oz)
    B = (v1.x - ox, v1.y - oy, v1.z - oz)
    C = (v2.x - ox, v2.y - oy, v2.z - oz)
    Ax = A[kx] - Sx * A[kz]
    Ay = A[ky] - Sy * A[kz]
    Bx = B[kx] - Sx * B[kz]
    By = B[ky] - Sy * B[kz]
    Cx = C[kx] - Sx * C[kz]
    Cy = C[ky] - Sy * C[kz]
    U = Cx * By - Cy * Bx
    V = Ax * Cy - Ay * Cx
    W = Bx * Ay - By * Ax
    # A zero-area triangle has exactly zero e0 x e1; the paper's det == 0 test alone lets
    # some through, because U + V + W of a collinear triangle need not round to zero.
    e0x, e0y, e0z = v1.x - v0.x, v1.y - v0.y, v1.z - v0.z
    e1x, e1y, e1z = v2.x - v0.x, v2.y - v0.y, v2.z - v0.z
    if (e0y * e1z) - (e0z * e1y) == 0.0 and (e0z * e1x) - (e0x * e1z) == 0.0 \
            and (e0x * e1y) - (e0y * e1x) == 0.0:
        return False
    if (U < 0.0 or V < 0.0 or W < 0.0) and (U > 0.0 or V > 0.0 or W > 0.0):
        return False
    det = U + V + W
    if det == 0.0:
        return False
    T = U * (Sz * A[kz]) + V * (Sz * B[kz]) + W * (Sz * C[kz])
    return _accept(ray, T / det)


# --- spawned rays ---------------------------------------------------------------------

def sphere_point_error(p, center, precision: str = "float64") -> Float3:
    """A bound on the error of a computed point on a sphere: PBRT-v4's gamma(5) |p - c| for
    the reprojected point in the sphere's frame (section 6.8.5), plus gamma(3) (|p - c| + |c|)
    for the translation to world space (the bound of Transform::operator() with error)."""
    g5, g3 = gamma(5, precision), gamma(3, precision)
    q = as_float3(p, "p") - as_float3(center, "center")
    c = center if isinstance(center, Float3) else as_float3(center, "center")
    return Float3(g5 * abs(q.x) + g3 * (abs(q.x) + abs(c.x)),
                  g5 * abs(q.y) + g3 * (abs(q.y) + abs(c.y)),
                  g5 * abs(q.z) + g3 * (abs(q.z) + abs(c.z)))


def triangle_point_error(v0, v1, v2, precision: str = "float64") -> Float3:
    """PBRT-v4's triangle bound gamma(7) (|b0 p0| + |b1 p1| + |b2 p2|) (section 6.8.5), taken
    at its largest over barycentrics in [0, 1]: gamma(7) (|p0| + |p1| + |p2|)."""
    g7 = gamma(7, precision)
    v0, v1, v2 = as_float3(v0, "v0"), as_float3(v1, "v1"), as_float3(v2, "v2")
    return Float3(g7 * (abs(v0.x) + abs(v1.x) + abs(v2.x)),
                  g7 * (abs(v0.y) + abs(v1.y) + abs(v2.y)),
                  g7 * (abs(v0.z) + abs(v1.z) + abs(v2.z)))


def plane_point_error(p, point, precision: str = "float64") -> Float3:
    """The triangle's bound with the hit point and the plane's point in the vertices' place:
    gamma(7) (|p| + |a|). (PBRT has no infinite plane; this is our choice, of the same form.)"""
    g7 = gamma(7, precision)
    p, a = as_float3(p, "p"), as_float3(point, "point")
    return Float3(g7 * (abs(p.x) + abs(a.x)), g7 * (abs(p.y) + abs(a.y)), g7 * (abs(p.z) + abs(a.z)))


def offset_ray_origin(p, p_error, n, w) -> Float3:
    """PBRT-v4 section 6.8.6, "Robust Spawned Ray Origins" (OffsetRayOrigin): move p along
    the geometric normal n, to the side that w leaves toward, by the projection of the error
    box onto the normal, d = |n| . p_error; then round each component away from p so that
    the rounding of p + offset cannot bring it back inside the error box. The spawned ray
    starts there with tmin = 0: it cannot re-hit the surface it leaves, and any real hit
    further than the tiny offset is kept (a fixed epsilon fails in both ways)."""
    p, e = as_float3(p, "p"), as_float3(p_error, "p_error")
    n, w = as_float3(n, "n"), as_float3(w, "w")
    dist = abs(n.x) * e.x + abs(n.y) * e.y + abs(n.z) * e.z
    offset = n * dist
    if dot(w, n) < 0.0:
        offset = -offset
    po = p + offset
    out = []
    for pi, oi in zip(po, offset):
        if oi > 0.0:
            pi = math.nextafter(pi, math.inf)
        elif oi < 0.0:
            pi = math.nextafter(pi, -math.inf)
        out.append(pi)
    return Float3(*out)


def spawn_ray_robust(p, p_error, n, w, tmax: float = math.inf) -> Ray:
    """A secondary ray (shadow, mirror, refraction) from a hit point: offset origin, tmin 0."""
    return Ray(offset_ray_origin(p, p_error, n, w), as_float3(w, "w"), 0.0, tmax)
