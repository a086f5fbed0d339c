"""The real roots of a quartic: Schwarze's ``SolveQuartic`` (Jochen Schwarze, "Cubic and
Quartic Roots", Graphics Gems I, 1990), which Suffern's ``Torus::hit`` calls (ch. 19, the
book's Maths.cpp), then a few Newton steps on each root.

Schwarze's closed form (Ferrari's method): divide by the t^4 coefficient, substitute
x = y - A/4 to remove the cubic term, take one real root z of the resolvent cubic (Cardano,
``solve_cubic``) and split the quartic into two quadratics (``solve_quadric``). Every step
subtracts nearly equal numbers somewhere, so a root comes out with far fewer correct digits
than the arithmetic carries (a few in float32). Each root is therefore polished by Newton's
method on the quartic as given, c4 t^4 + c3 t^3 + c2 t^2 + c1 t + c0, a step taken only if it
lowers |f(t)| (so a step near a double root, where f' is nearly 0, cannot throw the root
away), at most NEWTON_STEPS times.

rtfgu departs from the book's code in four places, each where rounding would otherwise give
NaN, lose real roots or make up some. (1) The resolvent cubic's largest root z is taken
(Schwarze's s[0], except when the cubic has a double root, where s[0] = 2u may be the smaller
one). (2) u^2 = z^2 - r and v^2 = 2 z - p are >= 0 in exact arithmetic ((2 z - p)(z^2 - r) =
q^2 / 4 and z >= p / 2), so a negative value is taken as 0, where the book returns no root:
a ray through the torus's hole (q = 0, u = 0 exactly) lost all four roots to a u of -1e-16,
and in float32 a resolvent whose largest root rounding has lost (a near-double root that
comes out as a complex pair) lost a ray's hit. (3) Every polished root is verified: it is
kept only if |f(t)| <= RESIDUAL (2^-40; 2^-16 in float32) times |c4| |t|^4 + ... + |c0|,
what rounding can leave of a root, so that a ray along the axis, whose quartic has two
double complex roots ((t^2 + a^2 - b^2)^2 for o = 0), gets no real root out of (2).
(4) ``IsZero`` is |x| < EQN_EPS with EQN_EPS = 1e-90 (the book's) in float64 and 1e-30 in
float32 (Schwarze's bound for "results correct, a double root maybe twice"; 1e-90 is 0 in
float32), and the argument of acos in the casus irreducibilis is clamped to [-1, 1].

The numba twin (rtfgu/kernels/quartic.py) does the same operations in the same order, so a
float64 render equals the lecture layer's bit for bit; the WGSL twin is
rtfgu/wgsl/solve_quartic.wgsl.

``solve_quartic(c0, c1, c2, c3, c4)`` returns (count, roots): the ``count`` real roots,
unsorted, in a tuple of four (the rest 0.0), as the book's (num, s[4]).
"""
from __future__ import annotations

import math

EQN_EPS = 1e-90
NEWTON_STEPS = 3
RESIDUAL = 2.0 ** -40
THIRD = 1.0 / 3.0
TWO_27THS = 2.0 / 27.0
PI_THIRD = math.pi / 3.0


def is_zero(x: float) -> bool:
    return -EQN_EPS < x < EQN_EPS


def cbrt(x: float) -> float:
    """Schwarze's real cube root (his NOCBRT macro): pow of |x|, the sign of x."""
    if x > 0.0:
        return math.pow(x, THIRD)
    if x < 0.0:
        return -math.pow(-x, THIRD)
    return 0.0


def solve_quadric(c0: float, c1: float, c2: float) -> tuple:
    """The real roots of c2 x^2 + c1 x + c0: (count, (s0, s1))."""
    p = c1 / (2.0 * c2)   # normal form x^2 + 2 p x + q = 0
    q = c0 / c2
    D = p * p - q
    if is_zero(D):
        return 1, (-p, 0.0)
    if D > 0.0:
        sqrt_D = math.sqrt(D)
        return 2, (sqrt_D - p, -sqrt_D - p)
    return 0, (0.0, 0.0)


def solve_cubic(c0: float, c1: float, c2: float, c3: float) -> tuple:
    """The real roots of c3 x^3 + c2 x^2 + c1 x + c0 (Cardano): (count, (s0, s1, s2)); with
    three real roots, s0 is the largest."""
    A = c2 / c3   # normal form x^3 + A x^2 + B x + C = 0
    B = c1 / c3
    C = c0 / c3
    # x = y - A/3 leaves y^3 + 3 p y + 2 q = 0
    sq_A = A * A
    p = THIRD * (-THIRD * sq_A + B)
    q = 0.5 * (TWO_27THS * A * sq_A - THIRD * A * B + C)
    cb_p = p * p * p
    D = q * q + cb_p
    if is_zero(D):
        if is_zero(q):   # one triple root
            count, s = 1, (0.0, 0.0, 0.0)
        else:            # a single and a double root
            u = cbrt(-q)
            count, s = 2, (2.0 * u, -u, 0.0)
    elif D < 0.0:        # casus irreducibilis: three real roots
        phi = THIRD * math.acos(min(max(-q / math.sqrt(-cb_p), -1.0), 1.0))
        t = 2.0 * math.sqrt(-p)
        count, s = 3, (t * math.cos(phi), -t * math.cos(phi + PI_THIRD), -t * math.cos(phi - PI_THIRD))
    else:                # one real root
        sqrt_D = math.sqrt(D)
        u = cbrt(sqrt_D - q)
        v = -cbrt(sqrt_D + q)
        count, s = 1, (u + v, 0.0, 0.0)
    sub = THIRD * A
    return count, (s[0] - sub, s[1] - sub, s[2] - sub)


def quartic_value(c0: float, c1: float, c2: float, c3: float, c4: float, t: float) -> float:
    """c4 t^4 + c3 t^3 + c2 t^2 + c1 t + c0 by Horner's rule."""
    return (((c4 * t + c3) * t + c2) * t + c1) * t + c0


def polish_root(c0: float, c1: float, c2: float, c3: float, c4: float, t: float) -> tuple:
    """At most NEWTON_STEPS Newton steps t - f(t) / f'(t), each kept only if |f| drops:
    (t, f(t))."""
    f = quartic_value(c0, c1, c2, c3, c4, t)
    for _ in range(NEWTON_STEPS):
        slope = ((4.0 * c4 * t + 3.0 * c3) * t + 2.0 * c2) * t + c1
        if slope == 0.0:
            break
        t_next = t - f / slope
        f_next = quartic_value(c0, c1, c2, c3, c4, t_next)
        if not abs(f_next) < abs(f):
            break
        t, f = t_next, f_next
    return t, f


def is_root(c0: float, c1: float, c2: float, c3: float, c4: float, t: float, f: float) -> bool:
    """Whether f = f(t) is within RESIDUAL of the size of the terms, |c4| |t|^4 + ... + |c0|:
    a rounding error, not a value of the quartic away from its roots."""
    x = abs(t)
    size = (((abs(c4) * x + abs(c3)) * x + abs(c2)) * x + abs(c1)) * x + abs(c0)
    return abs(f) <= RESIDUAL * size


def solve_quartic(c0: float, c1: float, c2: float, c3: float, c4: float) -> tuple:
    """The real roots of c4 x^4 + c3 x^3 + c2 x^2 + c1 x + c0 (c4 != 0), each polished:
    (count, (s0, s1, s2, s3)), unsorted."""
    A = c3 / c4   # normal form x^4 + A x^3 + B x^2 + C x + D = 0
    B = c2 / c4
    C = c1 / c4
    D = c0 / c4
    # x = y - A/4 leaves y^4 + p y^2 + q y + r = 0
    sq_A = A * A
    p = -0.375 * sq_A + B
    q = 0.125 * sq_A * A - 0.5 * A * B + C
    r = -0.01171875 * sq_A * sq_A + 0.0625 * sq_A * B - 0.25 * A * C + D
    if is_zero(r):
        # no absolute term: y (y^3 + p y + q) = 0
        count, s = solve_cubic(q, p, 0.0, 1.0)
        roots = list(s[:count]) + [0.0]
    else:
        # the largest real root z of the resolvent cubic ...
        count, s = solve_cubic(0.5 * r * p - 0.125 * q * q, -r, -0.5 * p, 1.0)
        z = s[0] if count < 2 else max(s[0], s[1])
        # ... splits the quartic into two quadratics, (y^2 + z)^2 = (v y - sign(q) u)^2 with
        # v^2 = 2 z - p and u^2 = z^2 - r; z >= p / 2 makes both >= 0 but for rounding
        u = z * z - r
        v = 2.0 * z - p
        u = math.sqrt(u) if u > 0.0 else 0.0
        v = math.sqrt(v) if v > 0.0 else 0.0
        n1, s1 = solve_quadric(z - u, -v if q < 0.0 else v, 1.0)
        n2, s2 = solve_quadric(z + u, v if q < 0.0 else -v, 1.0)
        roots = list(s1[:n1]) + list(s2[:n2])
    sub = 0.25 * A
    polished = [polish_root(c0, c1, c2, c3, c4, x - sub) for x in roots]
    roots = [t for t, f in polished if is_root(c0, c1, c2, c3, c4, t, f)]
    return len(roots), tuple(roots + [0.0] * (4 - len(roots)))
