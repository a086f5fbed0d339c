# release: solves a01 a03
"""Exact ground truth: rational arithmetic (``fractions.Fraction``) for every decision, and
50-digit ``mpmath`` only for the square root of a sphere's hit distance and the root of a
torus's quartic that Sturm's theorem has isolated.

Every input float (float32 or float64) converts to a Fraction without rounding, so the
truth is that of the very numbers a path receives, not of the values they approximate. No
float computation enters a decision. A hit distance is returned as a double-double
(hi, lo) with hi + lo = t to about 1e-32 relative, so that even float64 errors near one
ulp are measured against something much finer than themselves.
"""
from __future__ import annotations

import math
import warnings
from fractions import Fraction as Q

import mpmath

DIGITS = 50
MISS = (math.inf, 0.0)


def q3(v) -> tuple:
    return (Q(float(v[0])), Q(float(v[1])), Q(float(v[2])))


def finite(*values) -> bool:
    return all(math.isfinite(float(x)) for x in values)


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dd_from_fraction(t: Q) -> tuple[float, float]:
    hi = float(t)
    return hi, float(t - Q(hi))


def dd_from_mpf(t) -> tuple[float, float]:
    with mpmath.workdps(DIGITS):
        hi = float(t)
        return hi, float(t - mpmath.mpf(hi))


def _mpf(x: Q):
    return mpmath.mpf(x.numerator) / x.denominator


def _in_range_rational(t: Q, tmin: float, tmax: float) -> bool:
    return t >= Q(tmin) and (math.isinf(tmax) or t < Q(tmax))


# --- sphere ---------------------------------------------------------------------------

def sphere_roots(o, d, center, radius):
    """The exact roots of (o + t d - c)^2 = r^2 as mpf (t1 <= t2), or None if none are real.
    Also returns the rational (a, b, disc) of t = (-b -+ sqrt(disc)) / a with b = f . d."""
    f = sub(q3(o), q3(center))
    dq = q3(d)
    r = Q(float(radius))
    a = dot(dq, dq)
    b = dot(f, dq)
    c = dot(f, f) - r * r
    disc = b * b - a * c
    if disc < 0:
        return None
    with mpmath.workdps(DIGITS):
        s = mpmath.sqrt(_mpf(disc))
        A, B = _mpf(a), _mpf(b)
        return (-B - s) / A, (-B + s) / A, (a, b, disc)


def _sqrt_ge(sign: int, disc: Q, x: Q) -> bool:
    # sign * sqrt(disc) >= x, decided exactly
    if sign > 0:
        return x <= 0 or disc >= x * x
    return x <= 0 and disc <= x * x


def _sqrt_lt(sign: int, disc: Q, y: Q) -> bool:
    # sign * sqrt(disc) < y, decided exactly
    if sign > 0:
        return y > 0 and disc < y * y
    return y > 0 or disc > y * y


def sphere(o, d, tmin, tmax, center, radius):
    """The least root in [tmin, tmax) as (hi, lo), or MISS; decided in rationals."""
    if not (finite(*o, *d, *center, radius, tmin) and not math.isnan(tmax)):
        return MISS
    for t in _sphere_roots_in_range(o, d, tmin, tmax, center, radius):
        return dd_from_mpf(t)
    return MISS


def _sphere_roots_in_range(o, d, tmin, tmax, center, radius):
    """The sphere's roots (``sphere_roots``) in [tmin, tmax), the near one first; none for a
    radius <= 0 or a zero direction."""
    if float(radius) <= 0 or (d[0] == 0 and d[1] == 0 and d[2] == 0):
        return
    roots = sphere_roots(o, d, center, radius)
    if roots is not None:
        yield from _roots_in_range(roots, tmin, tmax)


def _roots_in_range(roots, tmin, tmax):
    """Of the roots (t1, t2, (a, b, disc)) of a quadratic, t = (-b -+ sqrt(disc)) / a with
    a > 0, those in [tmin, tmax), the least first, decided exactly."""
    t1, t2, (a, b, disc) = roots
    for sign, t in ((-1, t1), (1, t2)):
        if not _sqrt_ge(sign, disc, a * Q(float(tmin)) + b):
            continue
        if not math.isinf(tmax) and not _sqrt_lt(sign, disc, a * Q(float(tmax)) + b):
            continue
        yield t


def _least_root(roots, tmin, tmax):
    """Of the roots (t1, t2, (a, b, disc)) of a quadratic, t = (-b -+ sqrt(disc)) / a with
    a > 0, the least in [tmin, tmax) as (hi, lo), or MISS."""
    for t in _roots_in_range(roots, tmin, tmax):
        return dd_from_mpf(t)
    return MISS


def instance(o, d, tmin, tmax, scale, translate):
    """The hard cases' instance, the ellipsoid ((p - translate) / scale)^2 = 1
    (rtfgu.hardcases.kinds.ellipsoid): the unit sphere on the object-space ray
    (o - translate) / scale, d / scale, exactly (the paths use the rounded inverse matrix)."""
    if not (finite(*o, *d, *scale, *translate, tmin) and not math.isnan(tmax)):
        return MISS
    if 0.0 in (float(scale[0]), float(scale[1]), float(scale[2])) or (d[0] == 0 and d[1] == 0 and d[2] == 0):
        return MISS
    s, t = q3(scale), q3(translate)
    f = tuple((a - b) / c for a, b, c in zip(q3(o), t, s))
    dq = tuple(a / c for a, c in zip(q3(d), s))
    a, b = dot(dq, dq), dot(f, dq)
    disc = b * b - a * (dot(f, f) - 1)
    if disc < 0:
        return MISS
    with mpmath.workdps(DIGITS):
        root = mpmath.sqrt(_mpf(disc))
        A, B = _mpf(a), _mpf(b)
        return _least_root(((-B - root) / A, (-B + root) / A, (a, b, disc)), tmin, tmax)


# --- plane ----------------------------------------------------------------------------

def _plane_t(o, d, point, normal):
    """t = ((a - o) . n) / (d . n) as a Fraction, None when d . n == 0."""
    n = q3(normal)
    den = dot(q3(d), n)
    if den == 0:
        return None
    return dot(sub(q3(point), q3(o)), n) / den


def plane(o, d, tmin, tmax, point, normal):
    """t = ((a - o) . n) / (d . n) in rationals; d . n == 0 is a miss."""
    if not (finite(*o, *d, *point, *normal, tmin) and not math.isnan(tmax)):
        return MISS
    t = _plane_t(o, d, point, normal)
    if t is not None and _in_range_rational(t, tmin, tmax):
        return dd_from_fraction(t)
    return MISS


# --- triangle -------------------------------------------------------------------------

def triangle(o, d, tmin, tmax, v0, v1, v2):
    """The 02562 barycentric test in rationals, edges and vertices included; a zero-area
    triangle or a ray parallel to its plane is a miss."""
    if not (finite(*o, *d, *v0, *v1, *v2, tmin) and not math.isnan(tmax)):
        return MISS
    oq, dq = q3(o), q3(d)
    p0, p1, p2 = q3(v0), q3(v1), q3(v2)
    e0 = sub(p1, p0)
    e1 = sub(p2, p0)
    n = cross(e0, e1)
    den = dot(dq, n)
    if den == 0:
        return MISS
    a = sub(p0, oq)
    t = dot(a, n) / den
    if not _in_range_rational(t, tmin, tmax):
        return MISS
    c = cross(a, dq)
    beta = dot(c, e1) / den
    gamma = -dot(c, e0) / den
    if beta >= 0 and gamma >= 0 and beta + gamma <= 1:
        return dd_from_fraction(t)
    return MISS


# --- disk -----------------------------------------------------------------------------

def disk(o, d, tmin, tmax, center, normal, radius):
    """The plane of the disk (``plane``), then (p - c) . (p - c) <= r^2 at p = o + t d, in
    rationals: the rim belongs to the disk (Suffern ch. 19; rtfgu.shapes.disk)."""
    if not finite(radius):
        return MISS
    t = plane(o, d, tmin, tmax, center, normal)
    if t == MISS:
        return MISS
    tq = _plane_t(o, d, center, normal)
    p = tuple(oi + tq * di for oi, di in zip(q3(o), q3(d)))
    to_hit = sub(p, q3(center))
    r = Q(float(radius))
    return t if dot(to_hit, to_hit) <= r * r else MISS


# --- rectangle ------------------------------------------------------------------------

def rectangle(o, d, tmin, tmax, p0, a, b):
    """Suffern's Rectangle::hit in rationals: the plane through p0 with normal a x b, then
    0 <= (p - p0) . a <= |a|^2 and 0 <= (p - p0) . b <= |b|^2 at p = o + t d; the edges
    belong to the rectangle (Suffern ch. 19; rtfgu.shapes.rectangle)."""
    if not (finite(*o, *d, *p0, *a, *b, tmin) and not math.isnan(tmax)):
        return MISS
    aq, bq = q3(a), q3(b)
    n = cross(aq, bq)
    den = dot(q3(d), n)
    if den == 0:
        return MISS
    t = dot(sub(q3(p0), q3(o)), n) / den
    if not _in_range_rational(t, tmin, tmax):
        return MISS
    to_hit = sub(tuple(oi + t * di for oi, di in zip(q3(o), q3(d))), q3(p0))
    if 0 <= dot(to_hit, aq) <= dot(aq, aq) and 0 <= dot(to_hit, bq) <= dot(bq, bq):
        return dd_from_fraction(t)
    return MISS


# --- box ------------------------------------------------------------------------------

def box_t(o, d, p0, p1, tmin):
    """The slab test on rationals (3-tuples of Fractions; ``tmin`` a Fraction): t0 if
    t0 >= tmin, else t1, where t0 < t1; None when the ray misses the box."""
    t0 = t1 = None
    for axis in range(3):
        if d[axis] == 0:
            if not p0[axis] <= o[axis] <= p1[axis]:
                return None
            continue
        near, far = sorted(((p0[axis] - o[axis]) / d[axis], (p1[axis] - o[axis]) / d[axis]))
        t0 = near if t0 is None else max(t0, near)
        t1 = far if t1 is None else min(t1, far)
    if t0 is None or not t0 < t1:
        return None
    return t0 if t0 >= tmin else t1


def box(o, d, tmin, tmax, p0, p1):
    """Suffern's slab test in rationals: the largest entering t0 and the smallest leaving t1,
    a hit when t0 < t1, at t0 or (from inside) at t1; an axis the ray does not move along
    bounds nothing when o is within its slab, and misses otherwise (rtfgu.shapes.box)."""
    if not (finite(*o, *d, *p0, *p1, tmin) and not math.isnan(tmax)):
        return MISS
    t = box_t(q3(o), q3(d), q3(p0), q3(p1), Q(float(tmin)))
    return dd_from_fraction(t) if t is not None and _in_range_rational(t, tmin, tmax) else MISS


# --- open cylinder --------------------------------------------------------------------

def _sqrt_cmp(sign: int, disc: Q, x: Q) -> int:
    """The sign of sign * sqrt(disc) - x, decided exactly."""
    if sign > 0:
        if x < 0:
            return 1
        return (disc > x * x) - (disc < x * x)
    if x > 0:
        return -1
    return (disc < x * x) - (disc > x * x)


def open_cylinder(o, d, tmin, tmax, y0, y1, radius):
    """Suffern's OpenCylinder::hit decided in rationals: the roots t = (-b' -+ sqrt(disc)) / a
    of a t^2 + 2 b' t + c = 0 in x and z (a = d_x^2 + d_z^2, b' = o_x d_x + o_z d_z, disc =
    b'^2 - a c), the near one first, each when t is in [tmin, tmax) and o_y + t d_y in
    [y0, y1]; every comparison is one of sqrt(disc) with a rational. A ray parallel to the
    axis misses (rtfgu.shapes.open_cylinder)."""
    if not (finite(*o, *d, y0, y1, radius, tmin) and not math.isnan(tmax)):
        return MISS
    oq, dq = q3(o), q3(d)
    r, lo, hi = Q(float(radius)), Q(float(y0)), Q(float(y1))
    a = dq[0] * dq[0] + dq[2] * dq[2]
    if a == 0:
        return MISS
    b = oq[0] * dq[0] + oq[2] * dq[2]
    c = oq[0] * oq[0] + oq[2] * oq[2] - r * r
    disc = b * b - a * c
    if disc < 0:
        return MISS

    def t_at_least(sign, x):     # t >= x  <=>  sign sqrt(disc) >= a x + b
        return _sqrt_cmp(sign, disc, a * x + b) >= 0

    def t_at_most(sign, x):
        return _sqrt_cmp(sign, disc, a * x + b) <= 0

    for sign in (-1, 1):
        if not t_at_least(sign, Q(float(tmin))):
            continue
        if not math.isinf(tmax) and not _sqrt_cmp(sign, disc, a * Q(float(tmax)) + b) < 0:
            continue
        # y0 <= o_y + t d_y <= y1
        if dq[1] == 0:
            height_ok = lo <= oq[1] <= hi
        elif dq[1] > 0:
            height_ok = t_at_least(sign, (lo - oq[1]) / dq[1]) and t_at_most(sign, (hi - oq[1]) / dq[1])
        else:
            height_ok = t_at_most(sign, (lo - oq[1]) / dq[1]) and t_at_least(sign, (hi - oq[1]) / dq[1])
        if height_ok:
            with mpmath.workdps(DIGITS):
                return dd_from_mpf((-_mpf(b) + sign * mpmath.sqrt(_mpf(disc))) / _mpf(a))
    return MISS


# --- torus ----------------------------------------------------------------------------

def torus_quartic(o, d, a, b) -> tuple:
    """The coefficients (c0, ..., c4) of Suffern's quartic for the ray o + t d and the torus of
    sweep radius a and tube radius b about the y axis (rtfgu.shapes.torus), in rationals."""
    sum_d_sqrd = dot(d, d)
    e = dot(o, o) - a * a - b * b
    f = dot(o, d)
    four_a_sqrd = 4 * a * a
    return (e * e - four_a_sqrd * (b * b - o[1] * o[1]), 4 * f * e + 2 * four_a_sqrd * o[1] * d[1],
            2 * sum_d_sqrd * e + 4 * f * f + four_a_sqrd * d[1] * d[1], 4 * sum_d_sqrd * f, sum_d_sqrd * sum_d_sqrd)


def _poly_value(c, x):
    value = 0
    for coefficient in reversed(c):
        value = value * x + coefficient
    return value


def _poly_rem(n, m):
    """The remainder of n / m (coefficients lowest first, m's leading one non-zero)."""
    n = list(n)
    while len(n) >= len(m):
        factor = n[-1] / m[-1]
        shift = len(n) - len(m)
        for k in range(len(m)):
            n[shift + k] -= factor * m[k]
        n.pop()
    while n and n[-1] == 0:
        n.pop()
    return n


def _sturm(c) -> list:
    """Sturm's sequence p, p', -rem(p, p'), ... (coefficients lowest first)."""
    seq = [list(c), [k * c[k] for k in range(1, len(c))]]
    while len(seq[-1]) > 0:
        r = _poly_rem(seq[-2], seq[-1])
        if not r:
            break
        seq.append([-x for x in r])
    return seq


def _sign_changes(values) -> int:
    signs = [v > 0 for v in values if v != 0]
    return sum(1 for x, y in zip(signs, signs[1:]) if x != y)


def _changes_at(seq, x) -> int:
    if x is None:   # + infinity: the signs of the leading coefficients
        return _sign_changes([p[-1] for p in seq])
    return _sign_changes([_poly_value(p, x) for p in seq])


def least_root(c, tmin: Q, tmax) -> Q | object | None:
    """The least real root of the polynomial c (rationals, lowest first, c[-1] != 0) in
    [tmin, tmax) (tmax a Fraction or None for infinity), or None: decided exactly by
    Sturm's theorem (distinct roots in (lo, hi] = V(lo) - V(hi) where neither is a root),
    the root isolated by bisection and then given by mpmath's polyroots at 50 digits."""
    if _poly_value(c, tmin) == 0:
        return tmin
    seq = _sturm(c)
    bound = 1 + max(abs(x / c[-1]) for x in c[:-1])   # Cauchy's bound on every root
    hi = bound if tmax is None or tmax > bound else tmax
    if hi <= tmin:
        return None

    def count(lo, up):   # distinct roots in (lo, up), up not a root or the hi end
        n = _changes_at(seq, lo) - _changes_at(seq, up)
        return n - (1 if _poly_value(c, up) == 0 else 0)

    lo = tmin
    if count(lo, hi) == 0:
        return None
    # bisect until the least root is the only one in (lo, hi) and the interval is narrow
    for _ in range(200):
        if count(lo, hi) == 1 and hi - lo <= Q(1, 2 ** 40) * max(1, abs(lo)):
            break
        mid = (lo + hi) / 2
        if _poly_value(c, mid) == 0 and count(lo, mid) == 0:
            return mid
        if count(lo, mid) >= 1:
            hi = mid
        else:
            lo = mid
    with mpmath.workdps(DIGITS):
        with warnings.catch_warnings():   # mpmath 1.4 would rather take the lowest first (asc=True)
            warnings.simplefilter("ignore", DeprecationWarning)
            roots = mpmath.polyroots([_mpf(x) for x in reversed(c)], maxsteps=200, extraprec=200)
        middle = _mpf((lo + hi) / 2)
        return min((mpmath.re(r) for r in roots), key=lambda r: abs(r - middle))


def torus(o, d, tmin, tmax, a, b):
    """Suffern's Torus::hit decided in rationals: the least root of the quartic in
    [tmin, tmax) (least_root), as a double-double; a zero direction misses."""
    if not (finite(*o, *d, a, b, tmin) and not math.isnan(tmax)):
        return MISS
    oq, dq = q3(o), q3(d)
    c = torus_quartic(oq, dq, Q(float(a)), Q(float(b)))
    if c[4] == 0:
        return MISS
    t = least_root(c, Q(float(tmin)), None if math.isinf(tmax) else Q(float(tmax)))
    if t is None:
        return MISS
    return dd_from_fraction(t) if isinstance(t, Q) else dd_from_mpf(t)


# --- part sphere and annulus (Suffern ch. 19, "Part objects") ---------------------------

# Within this many degrees (or units of y / r) of a bound, a 50-digit angle is on the bound,
# which belongs to the part: a point the inputs put exactly on a rim (atan2(0, -1) = 180).
ANGLE_TIE = mpmath.mpf(10) ** -40


def _in_part(o, d, center, radius, t, phi_min, phi_max, theta_min, theta_max) -> bool:
    """Whether the point o + t d (t an mpf) of the sphere is within the part's angles, in
    degrees as the constructor took them: the book's r cos(theta_max) <= y <= r cos(theta_min)
    and phi = atan2(x, z) in [phi_min, phi_max], at 50 digits."""
    with mpmath.workdps(DIGITS):
        p = [mpmath.mpf(float(o[k])) + t * mpmath.mpf(float(d[k])) - mpmath.mpf(float(center[k])) for k in range(3)]
        y = p[1] / mpmath.mpf(float(radius))
        if y > mpmath.cos(mpmath.radians(float(theta_min))) + ANGLE_TIE:
            return False
        if y < mpmath.cos(mpmath.radians(float(theta_max))) - ANGLE_TIE:
            return False
        phi = mpmath.degrees(mpmath.atan2(p[0], p[2]))
        if phi < 0:
            phi += 360
        return float(phi_min) - ANGLE_TIE <= phi <= float(phi_max) + ANGLE_TIE


def convex_part_sphere(o, d, tmin, tmax, center, radius, phi_min, phi_max, theta_min, theta_max):
    """The sphere's roots in [tmin, tmax) decided in rationals (``sphere``), the near one
    first, each kept when its point is within the part's angles (``_in_part``)."""
    if not (finite(*o, *d, *center, radius, phi_min, phi_max, theta_min, theta_max, tmin) and not math.isnan(tmax)):
        return MISS
    for t in _sphere_roots_in_range(o, d, tmin, tmax, center, radius):
        if _in_part(o, d, center, radius, t, phi_min, phi_max, theta_min, theta_max):
            return dd_from_mpf(t)
    return MISS


def annulus(o, d, tmin, tmax, center, normal, inner_radius, outer_radius):
    """The plane of the annulus (``plane``), then r_i^2 <= (p - c) . (p - c) <= r_o^2 at
    p = o + t d, in rationals: both rims belong to it (rtfgu.shapes.annulus)."""
    if not finite(inner_radius, outer_radius):
        return MISS
    t = plane(o, d, tmin, tmax, center, normal)
    if t == MISS:
        return MISS
    tq = _plane_t(o, d, center, normal)
    to_hit = sub(tuple(oi + tq * di for oi, di in zip(q3(o), q3(d))), q3(center))
    d2 = dot(to_hit, to_hit)
    return t if Q(float(inner_radius)) ** 2 <= d2 <= Q(float(outer_radius)) ** 2 else MISS
