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
from collections import namedtuple
from types import FunctionType

import numpy as np
from numba import njit
from numba.extending import overload

from ..accelerators.bbox import PAD, WIDEN32, BBox
from .float3 import add, div, length, lit, lit_per_precision, normalize, scale
from .quartic import solve_quartic

# A float32 box grows by 2^-20 of its size (as rtfgu.layout grows a sphere's), since PAD
# (2^-32) is below float32's resolution.
PAD32 = 2.0 ** -20


# BBox.hit (rtfgu/accelerators/bbox.py) itself, compiled: its ``self`` is a _Box and its
# ``ray`` a _Ray of tuples, which index and read as Float3 and Ray do, so a float64 kernel
# rounds as the lecture layer. A float32 kernel compiles it with WIDEN read as float32's
# 1 + 2 gamma_3 (WIDEN32), so that it computes in float32 throughout.
_Box = namedtuple("_Box", ("p0", "p1"))
_Ray = namedtuple("_Ray", ("origin", "direction", "tmin", "tmax"))
LECTURE_HIT = {64: njit(error_model="numpy")(BBox.hit),
               32: njit(error_model="numpy")(FunctionType(BBox.hit.__code__,
                                                          dict(BBox.hit.__globals__, WIDEN=np.float32(WIDEN32)),
                                                          BBox.hit.__name__))}


def box_hit_in_precision(box, ray):
    """LECTURE_HIT for the float type of ray.tmin (plain Python: the kernels also run with
    the JIT disabled, where this is called directly)."""
    return LECTURE_HIT[np.dtype(type(ray.tmin)).itemsize * 8](box, ray)


@overload(box_hit_in_precision)
def _box_hit_in_precision_overload(box, ray):
    hit = LECTURE_HIT[ray.types[2].bitwidth]

    def impl(box, ray):
        return hit(box, ray)
    return impl


@njit(cache=True, error_model="numpy")
def bbox_hit(origin, direction, tmin, tmax, p0, p1):
    """BBox.hit: the t at which the ray enters the box p0..p1 within [tmin, tmax], or inf."""
    return lit(box_hit_in_precision(_Box(p0, p1), _Ray(origin, direction, tmin, tmax)), tmin)


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
