"""rtfgu.kernels.inline_frontend: an inline="always" function's untyped IR is made once a
process and copied at every call site, unchanged by the inlinings, and a function that
inlines it compiles to the machine code numba's own inliner gives."""
from __future__ import annotations

import io
import re

from numba import njit
from numba.core import inline_closurecall

import rtfgu.kernels  # noqa: F401  (installs the kept IR, as a render does)


@njit(inline="always")
def _inner(x):
    return x * x + 1.0


@njit(inline="always")
def _outer(x):
    y = _inner(x) - 2.0
    if y > 0.0:
        return _inner(y)
    return y


def callers():
    """Two new dispatchers (no cache) that inline _outer, and through it _inner."""
    @njit
    def first(x):
        return _outer(x) + 1.0

    @njit
    def second(x):
        return _outer(x + 1.0) * 3.0
    return first, second


def machine_code(dispatcher) -> list:
    asm = next(iter(dispatcher.inspect_asm().values()))
    return [re.sub(r"_ZN\S+", "SYMBOL", line) for line in asm.splitlines()
            if line.startswith("\t") and not line.startswith("\t.")]


def test_the_kept_ir_is_installed_and_numbas_own_kept_beside_it():
    worker = inline_closurecall.InlineWorker
    assert getattr(worker.inline_function, "_rtfgu_untyped_once", False)
    assert not getattr(worker.inline_function.numba_inline_function, "_rtfgu_untyped_once", False)


def python_outer(x):
    """_outer in plain Python, for the expected values."""
    def inner(v):
        return v * v + 1.0
    y = inner(x) - 2.0
    return inner(y) if y > 0.0 else y


def dumps(kept) -> list:
    out = []
    for callee_ir in kept.values():
        text = io.StringIO()
        callee_ir.dump(file=text)
        out.append(text.getvalue())
    return out


def test_the_front_end_runs_once_a_function_and_its_ir_is_not_changed_by_an_inlining(monkeypatch):
    worker = inline_closurecall.InlineWorker
    made = []
    own = worker.run_untyped_passes

    def counting(self, func, enable_ssa=False):
        made.append(func.__name__)
        return own(self, func, enable_ssa)
    monkeypatch.setattr(worker, "run_untyped_passes", counting)
    kept = worker.inline_function.kept
    kept.clear()
    first, second = callers()
    assert first(3.0) == python_outer(3.0) + 1.0
    # _outer inlined into first, _inner twice into _outer: each function's front end once.
    assert sorted(made) == ["_inner", "_outer"]
    before = dumps(kept)
    assert len(before) == 2
    assert second(3.0) == python_outer(4.0) * 3.0
    assert first(-0.5) == python_outer(-0.5) + 1.0    # the branch with y <= 0
    assert sorted(made) == ["_inner", "_outer"]        # second's inlining used the kept IR
    assert dumps(kept) == before                       # which its inlining did not change


def test_a_caller_compiles_to_numbas_machine_code(monkeypatch):
    ours, _ = callers()
    ours(2.0)
    worker = inline_closurecall.InlineWorker
    monkeypatch.setattr(worker, "inline_function", worker.inline_function.numba_inline_function)
    numba_own, _ = callers()
    numba_own(2.0)
    assert ours(2.0) == numba_own(2.0) == python_outer(2.0) + 1.0
    code = machine_code(ours)
    assert len(code) > 0 and code == machine_code(numba_own)
