"""The real roots of a quartic for the kernels: rtfgu.shapes.quartic (Schwarze's
``SolveQuartic``, Graphics Gems I, as Suffern's ``Torus::hit`` calls it, then Newton
steps on each root), operation for operation, so that a float64 kernel rounds exactly as
the lecture layer does; the constants are ``lit`` in the precision of the coefficients,
EQN_EPS is 1e-30 in float32 (1e-90 is 0 there) and RESIDUAL 2^-16."""
from __future__ import annotations

import math

from numba import njit

from ..shapes.quartic import EQN_EPS, NEWTON_STEPS, PI_THIRD, RESIDUAL, THIRD, TWO_27THS
from .float3 import lit, lit_per_precision

EQN_EPS32 = 1e-30
RESIDUAL32 = 2.0 ** -16


@njit(cache=True, error_model="numpy")
def is_zero(x):
    eps = lit_per_precision(EQN_EPS32, EQN_EPS, x)
    return -eps < x and x < eps


@njit(cache=True, error_model="numpy")
def cbrt(x):
    zero = lit(0.0, x)
    if x > zero:
        return math.pow(x, lit(THIRD, x))
    if x < zero:
        return -math.pow(-x, lit(THIRD, x))
    return zero


@njit(cache=True, error_model="numpy")
def solve_quadric(c0, c1, c2):
    """(count, s0, s1): the real roots of c2 x^2 + c1 x + c0."""
    zero = lit(0.0, c0)
    p = c1 / (lit(2.0, c0) * c2)
    q = c0 / c2
    D = p * p - q
    if is_zero(D):
        return 1, -p, zero
    if D > zero:
        sqrt_D = math.sqrt(D)
        return 2, sqrt_D - p, -sqrt_D - p
    return 0, zero, zero


@njit(cache=True, error_model="numpy")
def solve_cubic(c0, c1, c2, c3):
    """(count, s0, s1, s2): the real roots of c3 x^3 + c2 x^2 + c1 x + c0 (Cardano)."""
    zero = lit(0.0, c0)
    one = lit(1.0, c0)
    third = lit(THIRD, c0)
    A = c2 / c3
    B = c1 / c3
    C = c0 / c3
    sq_A = A * A
    p = third * (-third * sq_A + B)
    q = lit(0.5, c0) * (lit(TWO_27THS, c0) * A * sq_A - third * A * B + C)
    cb_p = p * p * p
    D = q * q + cb_p
    if is_zero(D):
        if is_zero(q):
            count, s0, s1, s2 = 1, zero, zero, zero
        else:
            u = cbrt(-q)
            count, s0, s1, s2 = 2, lit(2.0, c0) * u, -u, zero
    elif D < zero:
        phi = third * math.acos(min(max(-q / math.sqrt(-cb_p), -one), one))
        t = lit(2.0, c0) * math.sqrt(-p)
        pi_third = lit(PI_THIRD, c0)
        count, s0, s1, s2 = 3, t * math.cos(phi), -t * math.cos(phi + pi_third), -t * math.cos(phi - pi_third)
    else:
        sqrt_D = math.sqrt(D)
        u = cbrt(sqrt_D - q)
        v = -cbrt(sqrt_D + q)
        count, s0, s1, s2 = 1, u + v, zero, zero
    sub = third * A
    return count, s0 - sub, s1 - sub, s2 - sub


@njit(cache=True, error_model="numpy")
def quartic_value(c0, c1, c2, c3, c4, t):
    return (((c4 * t + c3) * t + c2) * t + c1) * t + c0


@njit(cache=True, error_model="numpy")
def polish_root(c0, c1, c2, c3, c4, t):
    """(t, f(t)) after at most NEWTON_STEPS Newton steps, each kept only if |f| drops."""
    f = quartic_value(c0, c1, c2, c3, c4, t)
    for _ in range(NEWTON_STEPS):
        slope = ((lit(4.0, t) * c4 * t + lit(3.0, t) * c3) * t + lit(2.0, t) * c2) * t + c1
        if slope == lit(0.0, t):
            break
        t_next = t - f / slope
        f_next = quartic_value(c0, c1, c2, c3, c4, t_next)
        if not abs(f_next) < abs(f):
            break
        t = t_next
        f = f_next
    return t, f


@njit(cache=True, error_model="numpy")
def is_root(c0, c1, c2, c3, c4, t, f):
    x = abs(t)
    size = (((abs(c4) * x + abs(c3)) * x + abs(c2)) * x + abs(c1)) * x + abs(c0)
    return abs(f) <= lit_per_precision(RESIDUAL32, RESIDUAL, t) * size


@njit(cache=True, error_model="numpy")
def _keep(c0, c1, c2, c3, c4, x, roots):
    """roots = (count, s0, s1, s2, s3) with x polished and appended if it is a root."""
    t, f = polish_root(c0, c1, c2, c3, c4, x)
    n, s0, s1, s2, s3 = roots
    if not is_root(c0, c1, c2, c3, c4, t, f):
        return roots
    if n == 0:
        return 1, t, s1, s2, s3
    if n == 1:
        return 2, s0, t, s2, s3
    if n == 2:
        return 3, s0, s1, t, s3
    return 4, s0, s1, s2, t


@njit(cache=True, error_model="numpy")
def solve_quartic(c0, c1, c2, c3, c4):
    """(count, s0, s1, s2, s3): the real roots of c4 x^4 + ... + c0, each polished and
    verified, unsorted (rtfgu.shapes.quartic.solve_quartic)."""
    zero = lit(0.0, c0)
    one = lit(1.0, c0)
    half = lit(0.5, c0)
    eighth = lit(0.125, c0)
    A = c3 / c4
    B = c2 / c4
    C = c1 / c4
    D = c0 / c4
    sq_A = A * A
    p = lit(-0.375, c0) * sq_A + B
    q = eighth * sq_A * A - half * A * B + C
    r = lit(-0.01171875, c0) * sq_A * sq_A + lit(0.0625, c0) * sq_A * B - lit(0.25, c0) * A * C + D
    if is_zero(r):
        n, s0, s1, s2 = solve_cubic(q, p, zero, one)
        # the roots of the cubic, then 0
        if n == 1:
            s1 = zero
        elif n == 2:
            s2 = zero
        s3 = zero
        count = n + 1
    else:
        n, z0, z1, z2 = solve_cubic(half * r * p - eighth * q * q, -r, -half * p, one)
        z = z0 if n < 2 else max(z0, z1)
        u = z * z - r
        v = lit(2.0, c0) * z - p
        u = math.sqrt(u) if u > zero else zero
        v = math.sqrt(v) if v > zero else zero
        n1, a0, a1 = solve_quadric(z - u, -v if q < zero else v, one)
        n2, b0, b1 = solve_quadric(z + u, v if q < zero else -v, one)
        # the first quadratic's roots, then the second's, in s0..s3
        count = n1 + n2
        s0 = a0 if n1 > 0 else b0
        s1 = a1 if n1 == 2 else (b0 if n1 == 1 else b1)
        s2 = b0 if n1 == 2 else b1
        s3 = b1
    sub = lit(0.25, c0) * A
    roots = (0, zero, zero, zero, zero)
    if count > 0:
        roots = _keep(c0, c1, c2, c3, c4, s0 - sub, roots)
    if count > 1:
        roots = _keep(c0, c1, c2, c3, c4, s1 - sub, roots)
    if count > 2:
        roots = _keep(c0, c1, c2, c3, c4, s2 - sub, roots)
    if count > 3:
        roots = _keep(c0, c1, c2, c3, c4, s3 - sub, roots)
    return roots
