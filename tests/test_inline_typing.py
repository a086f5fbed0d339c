"""rtfgu.kernels.inline_typing: an inlined overload is typed once per signature and never
compiled on its own, and the code it inlines is what numba would have inlined (the same
results, the absent/present choice still made per argument type)."""
from __future__ import annotations

import numba.core.typed_passes as typed_passes
import numpy as np
from numba import njit, types
from numba.core.typing.templates import _OverloadFunctionTemplate as OverloadTemplate
from numba.core import event
from numba.extending import overload

import rtfgu.kernels  # noqa: F401  (installs the cache, as a render does)
from rtfgu.kernels.inline_typing import cache_inline_typing, compile_inline_bodies_once


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
    assert compile_inline_bodies_once() is True


def test_an_inlined_overload_is_typed_once_per_signature_and_call_site():
    """numba types ``present`` again each time type propagation revisits a call; with the
    cache it is typed once for the signature, then once per call site as it is inlined."""
    table = np.arange(5.0)
    expected = sum(table.sum() * (2.0 + (2.0 + j) + 4.0 + (2.0 - j)) for j in range(3))
    result, counts = typings_of(njit(four_calls.py_func), table, None, 2.0)
    assert result == expected
    assert counts["_typed_scaled_sum.<locals>.present"] <= 1 + 4, counts
    assert counts["_typed_scaled_sum.<locals>.absent"] <= 1 + 1, counts

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


def fresh_scaled_sum():
    """A new overloaded function of ``scaled_sum``'s body and a kernel of four calls of it:
    a template whose signatures numba has not met yet."""
    def stub(table, k):
        raise NotImplementedError("typed by the overload below")

    overload(stub, inline="always")(_typed_scaled_sum)

    @njit
    def kernel(table, k):
        return stub(table, k) + stub(table, 2 * k) + stub(None, k)
    return kernel


def machine_code_compiles_of(kernel, *args):
    """The result of ``kernel(*args)`` and the names of the functions numba compiled to
    machine code for it (its ``numba:compile`` events), the kernel's own included."""
    names = []

    class Listener(event.Listener):
        def on_start(self, ev):
            names.append(ev.data["dispatcher"].py_func.__qualname__)

        def on_end(self, ev):
            pass

    with event.install_listener("numba:compile", Listener()):
        result = kernel(*args)
    return result, names


def test_an_inlined_overload_is_not_compiled_to_machine_code_on_its_own():
    """numba compiles an ``inline="always"`` overload's body by itself before it inlines
    it, code no call reaches; with compile_inline_bodies_once only the kernel is compiled,
    and it computes the same."""
    table = np.arange(5.0)
    result, names = machine_code_compiles_of(fresh_scaled_sum(), table, 2.0)
    assert result == table.sum() * 6.0
    assert [n for n in names if "present" in n or "absent" in n] == [], names
    assert any(n.endswith("kernel") for n in names), names

    ours = OverloadTemplate._get_jit_decorator
    OverloadTemplate._get_jit_decorator = ours.numba_get_jit_decorator
    try:
        numba_result, numba_names = machine_code_compiles_of(fresh_scaled_sum(), table, 2.0)
    finally:
        OverloadTemplate._get_jit_decorator = ours
    assert numba_result == result
    assert any("present" in n for n in numba_names) and any("absent" in n for n in numba_names), numba_names
