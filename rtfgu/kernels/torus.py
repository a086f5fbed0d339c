# release: solves a08
"""The torus on the numba path (Suffern ch. 19, "Tori"): rtfgu.shapes.torus.Torus operation
for operation, so that a float64 kernel rounds exactly as the lecture layer does.

``intersect_torus(origin, direction, tmin, tmax, a, b)`` returns the least root of the
book's quartic in [tmin, tmax], or inf; the ray is first tested against the torus's box
(``bbox_hit``, BBox.hit with the box Torus.bounds gives) and the quartic is written for the
ray from where it enters it, with a unit direction (rtfgu/shapes/torus.py says why). The roots come from
rtfgu.kernels.quartic (Schwarze's SolveQuartic and Newton steps).
"""
from __future__ import annotations

import math

from numba import njit

from ..accelerators.bbox import PAD, WIDEN, WIDEN32
from .float3 import add, div, length, lit, lit_per_precision, normalize, scale
from .quartic import solve_quartic

# A float32 box grows by 2^-20 of its size (as rtfgu.layout grows a sphere's), since PAD
# (2^-32) is below float32's resolution.
PAD32 = 2.0 ** -20


@njit(cache=True, error_model="numpy")
def bbox_hit(origin, direction, tmin, tmax, p0, p1):
    """BBox.hit: the t at which the ray enters the box p0..p1 within [tmin, tmax], or inf."""
    widen = lit_per_precision(WIDEN32, WIDEN, tmin)
    t0 = tmin
    t1 = tmax
    for k in range(3):
        o = origin[k]
        w = direction[k]
        if w == lit(0.0, w):
            if o < p0[k] or o > p1[k]:
                return lit(math.inf, tmin)
            continue
        t_near = (p0[k] - o) / w
        t_far = (p1[k] - o) / w
        if t_near > t_far:
            t_near, t_far = t_far, t_near
        t_far *= widen
        t0 = max(t0, t_near)
        t1 = min(t1, t_far)
        if t0 > t1:
            return lit(math.inf, tmin)
    return t0


@njit(cache=True, error_model="numpy")
def torus_box(a, b):
    """Torus.bounds: the book's box grown by PAD (float64) or PAD32 (float32) of a + b."""
    pad = lit_per_precision(PAD32, PAD, a) * (lit(0.0, a) + max(a + b, b, a + b))
    hi = (a + b + pad, b + pad, a + b + pad)
    return (-hi[0], -hi[1], -hi[2]), hi


@njit(cache=True, error_model="numpy")
def intersect_torus(origin, direction, tmin, tmax, a, b):
    # Suffern's Torus::hit: the box, then the quartic c4 s^4 + ... + c0 for the ray from the
    # box's entry o' = o + t_box d along d' = d / |d|, and the least t_box + s / |d| in range.
    p0, p1 = torus_box(a, b)
    t_box = bbox_hit(origin, direction, tmin, tmax, p0, p1)
    inf = lit(math.inf, tmin)
    if t_box == inf:
        return inf
    o = add(origin, scale(direction, t_box))
    size = length(direction)
    d = div(direction, size)
    sum_d_sqrd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
    e = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - a * a - b * b
    f = o[0] * d[0] + o[1] * d[1] + o[2] * d[2]
    four = lit(4.0, a)
    two = lit(2.0, a)
    four_a_sqrd = four * a * a
    count, s0, s1, s2, s3 = solve_quartic(e * e - four_a_sqrd * (b * b - o[1] * o[1]),
                                          four * f * e + two * four_a_sqrd * o[1] * d[1],
                                          two * sum_d_sqrd * e + four * f * f + four_a_sqrd * d[1] * d[1],
                                          four * sum_d_sqrd * f,
                                          sum_d_sqrd * sum_d_sqrd)
    t = inf
    for k in range(count):   # the least root in range; the roots are unsorted
        s = s0 if k == 0 else (s1 if k == 1 else (s2 if k == 2 else s3))
        t_hit = t_box + s / size
        if t_hit >= tmin and t_hit <= tmax and t_hit < t:
            t = t_hit
    return t


@njit(cache=True, error_model="numpy")
def normal_torus(position, a, b):
    # Torus.normal_at: the book's compute_normal, the gradient of the implicit function.
    param_squared = a * a + b * b
    x = position[0]
    y = position[1]
    z = position[2]
    sum_squared = x * x + y * y + z * z
    four = lit(4.0, a)
    return normalize((four * x * (sum_squared - param_squared),
                      four * y * (sum_squared - param_squared + lit(2.0, a) * a * a),
                      four * z * (sum_squared - param_squared)))
