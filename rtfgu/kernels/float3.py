"""Float3 for the kernels: a 3-tuple of floats, with the lecture's operators as functions.

Every function does the operations of ``rtfgu.float3`` in the same order, so a kernel in
float64 rounds exactly as the lecture layer does. ``lit(value, like)`` is a constant in the
float type of ``like``: in numba a Python float literal is float64 and an integer is int64,
and either one would promote a float32 expression to float64. Writing every constant as
``lit(0.5, x)`` keeps a float32 kernel in float32 from end to end.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit, types
from numba.extending import overload


def lit(value, like):
    """``value`` as the float type of ``like`` (pure Python: numpy scalar or float)."""
    return type(like)(value)


@overload(lit)
def _lit_overload(value, like):
    if isinstance(like, types.Float):
        cast = np.float32 if like.bitwidth == 32 else np.float64

        def impl(value, like):
            return cast(value)
        return impl
    return None


@njit(cache=True)
def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


@njit(cache=True)
def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


@njit(cache=True)
def neg(a):
    return (-a[0], -a[1], -a[2])


@njit(cache=True)
def mul(a, b):
    """Componentwise product (the slide's Float3 * Float3)."""
    return (a[0] * b[0], a[1] * b[1], a[2] * b[2])


@njit(cache=True)
def scale(a, f):
    """Float3 * scalar."""
    return (a[0] * f, a[1] * f, a[2] * f)


@njit(cache=True)
def div(a, f):
    """Float3 / scalar through the reciprocal, as the slide's operator/: inv = 1.0f / x."""
    inv = lit(1.0, f) / f
    return (a[0] * inv, a[1] * inv, a[2] * inv)


@njit(cache=True)
def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


@njit(cache=True)
def cross(a, b):
    return ((a[1] * b[2]) - (a[2] * b[1]),
            (a[2] * b[0]) - (a[0] * b[2]),
            (a[0] * b[1]) - (a[1] * b[0]))


@njit(cache=True)
def length(a):
    return math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])


@njit(cache=True)
def normalize(a):
    return div(a, length(a))


@njit(cache=True)
def load3(row, offset):
    """Three floats of a layout row as a Float3."""
    return (row[offset], row[offset + 1], row[offset + 2])
