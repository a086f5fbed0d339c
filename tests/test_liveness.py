"""rtfgu.kernels.liveness: the live-variable map numba computes with sets, computed with
bit sets, is the same map, on the IR of the kernels' own functions and of loops made to
be awkward (a block that loops on itself, a variable defined in one branch only, code
after a return)."""
from __future__ import annotations

import importlib

import pytest
from numba.core import analysis
from numba.core.compiler import run_frontend

import rtfgu.kernels  # noqa: F401  (installs the bit sets, as a render does)
from rtfgu.kernels import liveness


def awkward_loops(n, flag):
    total = 0.0
    i = 0
    while True:  # the loop's test at its end: a block that is its own successor
        i += 1
        if i > n:
            break
    for j in range(n):
        if flag:
            only_here = j * 2.0  # defined in one branch, used after the loop
        else:
            continue
        for k in range(j):
            total += k
            if total > 100.0:
                break
        total += only_here
    return total
    total += 1.0  # after the return: a block no path reaches


def kernel_functions():
    """Functions of the kernels, the generated dispatch's among them, with their loops and
    branches (a kernel's own IR, every overload inlined, is this IR grown larger)."""
    from rtfgu.kernels import dispatch, quartic, render, torus

    return [awkward_loops, quartic.solve_quartic, torus.intersect_torus, render.trace.py_func,
            render.render_tile.py_func, dispatch._generated.shade.py_func,
            dispatch._generated.in_shadow.py_func]


@pytest.mark.parametrize("function", kernel_functions(), ids=lambda f: f.__name__)
def test_the_bit_sets_give_numbas_live_map(function):
    func_ir = run_frontend(function)
    blocks = func_ir.blocks
    cfg = analysis.compute_cfg_from_blocks(blocks)
    usedefs = analysis.compute_use_defs(blocks)
    numba_own = liveness.compute_live_map.numba_compute_live_map
    expected = numba_own(cfg, blocks, usedefs.usemap, usedefs.defmap)
    got = liveness.compute_live_map(cfg, blocks, usedefs.usemap, usedefs.defmap)
    assert list(got) == list(expected)
    assert got == expected
    assert any(expected.values()), "a function with no live variable tests nothing"


def test_numbas_modules_call_the_bit_sets():
    assert liveness.use_bitset_liveness() is True
    for name in ("numba.core.analysis", "numba.core.ir_utils", "numba.parfors.parfor"):
        assert importlib.import_module(name).compute_live_map is liveness.compute_live_map, name
