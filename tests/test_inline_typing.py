"""rtfgu.kernels.inline_typing: an inlined overload is typed once per signature, and the
code it inlines is what numba would have inlined (the same results, the absent/present
choice still made per argument type)."""
from __future__ import annotations

import numba.core.typed_passes as typed_passes
import numpy as np
from numba import njit, types
from numba.core.typing.templates import _OverloadFunctionTemplate as OverloadTemplate
from numba.extending import overload

import rtfgu.kernels  # noqa: F401  (installs the cache, as a render does)
from rtfgu.kernels.inline_typing import cache_inline_typing


def scaled_sum(table, k):
    raise NotImplementedError("typed by the overload below")


@overload(scaled_sum, inline="always")
def _typed_scaled_sum(table, k):
    if isinstance(table, types.NoneType):
        def absent(table, k):
            return 0.0
        return absent

    def present(table, k):
        total = 0.0
        for i in range(table.shape[0]):
            total += table[i] * k
        return total
    return present


@njit
def four_calls(table, other, k):
    # Four call sites of one signature, in a loop (type propagation revisits them), and one
    # of another (``other`` may be None).
    total = 0.0
    for j in range(3):
        total += scaled_sum(table, k) + scaled_sum(table, k + j)
        total += scaled_sum(table, 2 * k) + scaled_sum(table, k - j)
    return total + scaled_sum(other, k)


def typings_of(function, *args):
    """How many times numba types each function while compiling ``function(*args)``."""
    counts = {}
    original = typed_passes.type_inference_stage

    def counting(typingctx, targetctx, interp, args_, return_type, locals={}, raise_errors=True):
        name = interp.func_id.func_qualname
        counts[name] = counts.get(name, 0) + 1
        return original(typingctx, targetctx, interp, args_, return_type, locals, raise_errors)

    typed_passes.type_inference_stage = counting
    try:
        result = function(*args)
    finally:
        typed_passes.type_inference_stage = original
    return result, counts


def test_the_cache_is_installed():
    assert cache_inline_typing() is True


def test_an_inlined_overload_is_typed_once_per_signature_and_call_site():
    """numba types ``present`` again each time type propagation revisits a call; with the
    cache it is typed once for the signature (twice the first time: numba compiles the
    overload's dispatcher to resolve it), then once per call site as it is inlined."""
    table = np.arange(5.0)
    expected = sum(table.sum() * (2.0 + (2.0 + j) + 4.0 + (2.0 - j)) for j in range(3))
    result, counts = typings_of(njit(four_calls.py_func), table, None, 2.0)
    assert result == expected
    assert counts["_typed_scaled_sum.<locals>.present"] <= 2 + 4, counts
    assert counts["_typed_scaled_sum.<locals>.absent"] <= 2 + 1, counts

    cached = OverloadTemplate.generic
    OverloadTemplate.generic = cached.numba_generic
    try:
        uncached, numba_counts = typings_of(njit(four_calls.py_func), table, None, 2.0)
    finally:
        OverloadTemplate.generic = cached
    assert uncached == expected
    assert numba_counts["_typed_scaled_sum.<locals>.present"] > counts["_typed_scaled_sum.<locals>.present"]


def test_each_argument_type_still_gets_its_own_body():
    table = np.arange(4.0)
    assert four_calls(table, table, 1.0) == four_calls(table, None, 1.0) + table.sum()
    as_float32 = table.astype(np.float32)
    assert four_calls(as_float32, as_float32, 1.0) == four_calls(table, table, 1.0)
