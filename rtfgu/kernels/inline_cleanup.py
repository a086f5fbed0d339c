"""numba's clean-up after it inlines overloads, without the dead-code elimination that LLVM
does again.

After numba's typed pass ``InlineOverloads`` (numba/core/typed_passes.py) has inlined the
``inline="always"`` overloads of a function, it removes the blocks no branch reaches, runs
``ir_utils.dead_code_elimination`` over the whole function, and merges the blocks left
joined by one jump. A render kernel is one function with every overload inlined into it, so
that elimination walks thousands of statements, their aliases and their liveness, round
after round until nothing changes: 2.9 s of the 31 s three kernels took to compile, with an
empty cache (docs/compile_time.md).

What it removes is statements whose values nothing reads and which have no effect: the
lowered code computes them into registers nobody reads, and LLVM's own passes, which numba
runs on every kernel at -O3, delete them before any machine code is made. So the compiled
code does the same arithmetic in the same order: tests/test_inline_cleanup.py compares the
machine code with numba's pass and with this one, and docs/compile_time.md the 104 homework
images. The unreached blocks and the merged jumps are still handled as numba does.

``skip_dead_code_after_inlining()`` gives ``InlineOverloads.run_pass`` an elimination that
does nothing while it runs; every other caller of numba's elimination keeps it.
"""
from __future__ import annotations

import contextlib


@contextlib.contextmanager
def _without_dead_code_elimination(module):
    numba_own = module.dead_code_elimination
    module.dead_code_elimination = _keep_the_code
    try:
        yield
    finally:
        module.dead_code_elimination = numba_own


def _keep_the_code(func_ir, typemap=None, alias_map=None, arg_aliases=None):
    """In place of ir_utils.dead_code_elimination: leaves the IR as it is."""
    return None


def skip_dead_code_after_inlining() -> bool:
    """Install the wrapper on numba's InlineOverloads pass; True when installed (or already
    installed), False where numba's pass does not have the expected shape."""
    try:   # numba, with the pass and the elimination it calls by this module's name
        from numba.core import typed_passes
        from numba.core.typed_passes import InlineOverloads, dead_code_elimination  # noqa: F401
    except ImportError:
        return False
    run_pass = InlineOverloads.run_pass
    if getattr(run_pass, "_rtfgu_keeps_dead_code", False):
        return True

    def run_pass_keeping_dead_code(self, state):
        with _without_dead_code_elimination(typed_passes):
            return run_pass(self, state)

    run_pass_keeping_dead_code._rtfgu_keeps_dead_code = True
    run_pass_keeping_dead_code.numba_run_pass = run_pass   # numba's own, for the tests
    run_pass_keeping_dead_code.__doc__ = run_pass.__doc__
    InlineOverloads.run_pass = run_pass_keeping_dead_code
    return True
