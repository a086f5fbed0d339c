"""rtfgu.kernels.inline_cleanup: numba's InlineOverloads pass leaves the statements nobody
reads to LLVM, and the machine code is the same as numba's own pass gives."""
from __future__ import annotations

import re

import numpy as np
from numba import njit
from numba.core import ir_utils, typed_passes
from numba.extending import overload

import rtfgu.kernels  # noqa: F401  (installs the pass, as a render does)


def wasteful(x):
    """An inlined overload that computes two values nobody reads (typed below)."""
    raise NotImplementedError


@overload(wasteful, inline="always")
def _typed_wasteful(x):
    def impl(x):
        unused = x * 3.0 + 1.0          # noqa: F841  (dead: the point of the test)
        also = np.sqrt(abs(x))          # noqa: F841
        return x + 1.0
    return impl


def a_function():
    """A new dispatcher each call (no cache), so each compiles under the pass installed now."""
    @njit
    def f(x):
        return wasteful(wasteful(x)) * 2.0
    return f


def compiled(monkeypatch=None) -> tuple:
    """(statements in the typed IR, machine code instructions without symbol names, f(1.5)),
    with numba's own InlineOverloads pass where ``monkeypatch`` is given."""
    if monkeypatch is not None:
        monkeypatch.setattr(typed_passes.InlineOverloads, "run_pass",
                            typed_passes.InlineOverloads.run_pass.numba_run_pass)
    f = a_function()
    value = f(1.5)
    result = next(iter(f.overloads.values()))
    statements = sum(len(block.body) for block in result.type_annotation.blocks.values())
    asm = next(iter(f.inspect_asm().values()))
    code = [re.sub(r"_ZN\S+", "SYMBOL", line) for line in asm.splitlines()
            if line.startswith("\t") and not line.startswith("\t.")]
    return statements, code, value


def test_the_pass_is_installed_and_numbas_own_is_kept_beside_it():
    run_pass = typed_passes.InlineOverloads.run_pass
    assert getattr(run_pass, "_rtfgu_keeps_dead_code", False)
    assert not getattr(run_pass.numba_run_pass, "_rtfgu_keeps_dead_code", False)
    # Outside the pass numba's elimination is untouched.
    assert typed_passes.dead_code_elimination is ir_utils.dead_code_elimination


def test_the_dead_statements_stay_in_numbas_ir_and_leave_llvms_code_unchanged(monkeypatch):
    ours_statements, ours_code, ours_value = compiled()
    with monkeypatch.context() as m:
        numba_statements, numba_code, numba_value = compiled(m)
    assert ours_value == numba_value == 7.0
    # The two inlined bodies' four dead values and what computes them stay in numba's IR ...
    assert ours_statements > numba_statements
    # ... and LLVM removes them: the same instructions, in the same order.
    assert len(ours_code) > 0
    assert ours_code == numba_code

