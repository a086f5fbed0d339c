"""LLVM's optimisation of a kernel run once, not twice.

numba (0.68.1, the version read) optimises a compiled function's LLVM IR twice: LLVM's
function pipeline on each function of the module as numba adds it to its library
(``CPUCodeLibrary._optimize_functions``, numba/core/codegen.py, "to reduce memory usage and
improve module-level optimization"), then, once the library's modules are linked, the whole
module pipeline at the same level (``_optimize_final_module``), which runs the function
pipeline again over every function. A kernel (``render_tile`` and the parallel loop
``render_kernel`` of rtfgu.kernels.render, the pixel debugger's ``trace_records``) holds
every overload inlined, thousands of blocks, and the first of these runs was a tenth of its
compile.

``optimize_kernels_once()`` leaves a module that defines one of those kernels to the module
pipeline alone. Every other module is optimised as numba does: rtfgu's small functions
(the BVH's traversals, called once a ray) as well, since for them the two runs make faster
code (the binary tree's traversal, optimised by the module pipeline alone, traced 0.6-0.74x
the rays a second in one bench.md run), and numba's helpers and a user's own functions.
LLVM's passes do not change a floating-point result without fast-math flags, which the
kernels do not set, so the images are the same bit for bit (the parity tests compare them);
the kernels' speed, measured on four scenes, stayed within this machine's spread
(docs/compile_time.md).
"""
from __future__ import annotations

_INSTALLED = "_rtfgu_once"
# The kernels, as numba's mangled names hold them: the package, then each name's length
# and the name (``_ZN5rtfgu7kernels6render11render_tile...``).
PACKAGE = "5rtfgu"
KERNELS = ("render_tile", "render_kernel", "trace_records")


def is_kernel_module(ll_module) -> bool:
    """Whether the LLVM module defines one of the KERNELS (not only calls it)."""
    marks = ["%d%s" % (len(name), name) for name in KERNELS]
    return any(PACKAGE in f.name and any(mark in f.name for mark in marks)
               for f in ll_module.functions if not f.is_declaration)


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
        if not is_kernel_module(ll_module):
            return optimize_functions(self, ll_module)
        # What numba's function passes set besides optimising; the module passes optimise.
        ll_module.data_layout = self._codegen._data_layout
        return None

    setattr(optimize_functions_once, _INSTALLED, True)
    optimize_functions_once.numba_optimize_functions = optimize_functions   # for the tests
    optimize_functions_once.__doc__ = optimize_functions.__doc__
    CPUCodeLibrary._optimize_functions = optimize_functions_once
    return True
