"""The next float above or below a float (IEEE 754's nextUp and nextDown), computed where
it is used.

numba lowers ``np.nextafter`` to a call of a C function of its own (``numba_nextafterf``),
which LLVM cannot inline: the caller's vector registers are all lost across it (the x86-64
calling convention saves none), so a loop that calls it keeps its vectors on the stack and
loads them again after every call. The wide BVH's traversal calls it at every leaf (the tie
rule tests a face up to the float above the best t: rtfgu.kernels.mesh.mesh_closest), and
its node loop then loaded the ray's splatted origin and 1 / direction from memory at every
node. ``next_up`` steps the float's bits instead (a float's bits, read as a signed integer,
are ordered as the floats are), with no call; ``next_down`` is -next_up(-x) (negation is
exact). Both give np.nextafter's float for every input (tests/test_next_float.py).
"""
from __future__ import annotations

import math

import numpy as np
from llvmlite import ir
from numba import types
from numba.extending import intrinsic, overload


def next_up(x):
    """The least float of ``x``'s type greater than ``x`` (``np.nextafter(x, inf)``): NaN and
    +inf are returned as they are, -inf gives the most negative finite float, +0 and -0 the
    least positive subnormal, -(least subnormal) gives -0."""
    return np.nextafter(x, type(x)(math.inf))


@intrinsic
def _next_up_bits(typingctx, x):
    if not isinstance(x, types.Float):
        return None

    def codegen(context, builder, signature, args):
        (value,) = args
        real = value.type
        bits_type = ir.IntType(32 if isinstance(real, ir.FloatType) else 64)
        bits = builder.bitcast(value, bits_type)
        one = ir.Constant(bits_type, 1)
        # Below zero the bits' magnitude shrinks toward -0, above it grows toward +inf.
        negative = builder.icmp_signed("<", bits, ir.Constant(bits_type, 0))
        stepped = builder.select(negative, builder.sub(bits, one), builder.add(bits, one))
        stepped = builder.select(builder.fcmp_ordered("==", value, ir.Constant(real, 0.0)), one, stepped)
        kept = builder.or_(builder.fcmp_unordered("uno", value, value),
                           builder.fcmp_ordered("==", value, ir.Constant(real, math.inf)))
        return builder.select(kept, value, builder.bitcast(stepped, real))
    return x(x), codegen


@overload(next_up)
def _next_up_overload(x):
    if isinstance(x, types.Float):
        return lambda x: _next_up_bits(x)


def next_down(x):
    """The greatest float of ``x``'s type less than ``x`` (``np.nextafter(x, -inf)``)."""
    return np.nextafter(x, type(x)(-math.inf))


@overload(next_down)
def _next_down_overload(x):
    if isinstance(x, types.Float):
        return lambda x: -_next_up_bits(-x)
