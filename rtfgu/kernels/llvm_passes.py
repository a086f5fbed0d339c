"""LLVM's optimisation of a kernel run once, not twice.

numba (0.68.1, the version read) optimises a compiled function's LLVM IR twice: LLVM's
function pipeline on each function of the module as numba adds it to its library
(``CPUCodeLibrary._optimize_functions``, numba/core/codegen.py, "to reduce memory usage and
improve module-level optimization"), then, once the library's modules are linked, the whole
module pipeline at the same level (``_optimize_final_module``), which runs the function
pipeline again over every function. The kernels' functions hold every overload inlined,
thousands of blocks, and the first of these runs is a tenth of a kernel's compile.

``optimize_kernels_once()`` leaves rtfgu's own modules to the module pipeline alone: a
module that defines a function of rtfgu's (its mangled name holds "rtfgu", as numba names a
function by its module: ``_ZN5rtfgu7kernels...``, the generated dispatch's
``rtfgu_dispatch_...``) is not run through the function pipeline first. Every other module
(numba's own helpers, a user's functions) is optimised as numba does. LLVM's passes do not
change a floating-point result without fast-math flags, which the kernels do not set, so the
images are the same bit for bit (the parity tests compare them); the speed, measured on four
scenes' kernels, is within this machine's spread of a few per cent (docs/compile_time.md).
"""
from __future__ import annotations

_INSTALLED = "_rtfgu_once"
MARK = "rtfgu"


def is_rtfgu_module(ll_module) -> bool:
    """Whether the LLVM module defines a function of rtfgu's (see the module's docstring)."""
    return any(MARK in function.name for function in ll_module.functions if not function.is_declaration)


def optimize_kernels_once() -> bool:
    """Install; True when installed (or already installed), False where numba's code
    library does not have the expected shape (numba's own passes then run as they do)."""
    try:
        from numba.core.codegen import CPUCodeLibrary
    except ImportError:
        return False
    optimize_functions = getattr(CPUCodeLibrary, "_optimize_functions", None)
    if optimize_functions is None or not hasattr(CPUCodeLibrary, "_optimize_final_module"):
        return False
    if getattr(optimize_functions, _INSTALLED, False):
        return True

    def optimize_functions_once(self, ll_module):
        if not is_rtfgu_module(ll_module):
            return optimize_functions(self, ll_module)
        # What numba's function passes set besides optimising; the module passes optimise.
        ll_module.data_layout = self._codegen._data_layout
        return None

    setattr(optimize_functions_once, _INSTALLED, True)
    optimize_functions_once.numba_optimize_functions = optimize_functions   # for the tests
    optimize_functions_once.__doc__ = optimize_functions.__doc__
    CPUCodeLibrary._optimize_functions = optimize_functions_once
    return True
