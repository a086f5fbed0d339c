# release: solves a01
"""Float3 for the kernels: a 3-tuple of floats, with the lecture's operators as functions.

Every function does the operations of ``rtfgu.float3`` in the same order, so a kernel in
float64 rounds exactly as the lecture layer does. ``lit(value, like)`` is a constant in the
float type of ``like``: in numba a Python float literal is float64 and an integer is int64,
and either one would promote a float32 expression to float64. Writing every constant as
``lit(0.5, x)`` keeps a float32 kernel in float32 from end to end.

Every kernel is compiled with ``error_model="numpy"``: a float division by zero gives inf
or NaN (as in C and WGSL) instead of raising, and a function that cannot raise is one LLVM
can inline into its caller, so the small helpers here cost no call in a hot loop. The lecture
layer guards every division a valid scene can reach, and ``render`` refuses an image with a
non-finite pixel.
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


def lit_per_precision(value32, value64, like):
    """``value32`` as a float32 ``like`` is, ``value64`` as a float64 one: a constant whose
    value depends on the precision (Veltkamp's splitter, the unit roundoff), chosen like
    ``lit`` when numba types ``like``, so a float32 kernel pays nothing for the choice."""
    return type(like)(value32 if np.dtype(type(like)).itemsize == 4 else value64)


@overload(lit_per_precision)
def _lit_per_precision_overload(value32, value64, like):
    if isinstance(like, types.Float):
        single = like.bitwidth == 32
        cast = np.float32 if single else np.float64

        def impl(value32, value64, like):
            return cast(value32 if single else value64)
        return impl
    return None


@njit(cache=True, error_model="numpy")
def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


@njit(cache=True, error_model="numpy")
def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


@njit(cache=True, error_model="numpy")
def neg(a):
    return (-a[0], -a[1], -a[2])


@njit(cache=True, error_model="numpy")
def mul(a, b):
    """Componentwise product (the slide's Float3 * Float3)."""
    return (a[0] * b[0], a[1] * b[1], a[2] * b[2])


@njit(cache=True, error_model="numpy")
def scale(a, f):
    """Float3 * scalar."""
    return (a[0] * f, a[1] * f, a[2] * f)


@njit(cache=True, error_model="numpy")
def div(a, f):
    """Float3 / scalar through the reciprocal, as the slide's operator/: inv = 1.0f / x."""
    inv = lit(1.0, f) / f
    return (a[0] * inv, a[1] * inv, a[2] * inv)


@njit(cache=True, error_model="numpy")
def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


@njit(cache=True, error_model="numpy")
def cross(a, b):
    return ((a[1] * b[2]) - (a[2] * b[1]),
            (a[2] * b[0]) - (a[0] * b[2]),
            (a[0] * b[1]) - (a[1] * b[0]))


@njit(cache=True, error_model="numpy")
def length(a):
    return math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])


@njit(cache=True, error_model="numpy")
def normalize(a):
    return div(a, length(a))


@njit(cache=True, error_model="numpy")
def load3(row, offset):
    """Three floats of a layout row as a Float3."""
    return (row[offset], row[offset + 1], row[offset + 2])


@njit(cache=True, error_model="numpy")
def row3(table, i, offset):
    """Three floats of row i of a layout table, indexed directly: a row view (table[i])
    in a hot loop costs numba an array struct per shape."""
    return (table[i, offset], table[i, offset + 1], table[i, offset + 2])
