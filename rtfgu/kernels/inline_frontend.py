"""The untyped IR of an ``inline="always"`` function made once a process, not at every call.

numba (0.68.1, the version read) inlines an ``njit(inline="always")`` function in its
untyped pass ``InlineInlinables`` (numba/core/untyped_passes.py) through
``InlineWorker.inline_function`` (numba/core/inline_closurecall.py): at every call site it
runs the whole front end on the function again (its bytecode read into IR, then the untyped
passes, among them ``InlineInlinables`` on the functions it calls, and so on down), and
hands the IR to ``inline_ir``, which copies it before it changes anything ("Always copy the
callee IR, it gets mutated"). The kernels of a process (one per scene and precision) inline
the same few dozen functions (the pixel's camera ray, the random stream, the trace), each
made again in every kernel.

``untyped_ir_once()`` keeps the IR the front end made for each function and gives that to
``inline_ir`` at later calls, which copies it as before. The IR depends on the function
(its bytecode, and the globals it read when first made: as numba's dispatcher compiles a
plain ``njit`` function once a process with the globals of that moment), the typing
context and the compile flags; the key holds those, less ``enable_ssa``, which
``run_untyped_passes`` sets to False on the caller's flags before it reads them (kept
here as numba leaves it). Measured on the 52 homework scenes in both precisions (empty
caches, two processes at once): docs/compile_time.md; the images are the same bytes.
"""
from __future__ import annotations

_INSTALLED = "_rtfgu_untyped_once"


def flags_key(flags):
    """The compile flags' values as a hashable tuple, less ``enable_ssa``; options that are
    objects (the parallel, fast-math and inline options) by their attributes."""
    key = []
    for name, value in sorted(flags.values().items()):
        if name == "enable_ssa":
            continue
        try:
            hash(value)
            key.append((name, value))
        except TypeError:
            key.append((name, type(value).__name__, repr(sorted(vars(value).items()))))
    return tuple(key)


def untyped_ir_once() -> bool:
    """Install the kept IR in numba's inliner; True when installed (or already installed),
    False where numba's inliner does not have the expected shape."""
    try:
        from numba.core import inline_closurecall
    except ImportError:
        return False
    worker = getattr(inline_closurecall, "InlineWorker", None)
    inline_function = getattr(worker, "inline_function", None)
    if inline_function is None or not hasattr(worker, "run_untyped_passes") or not hasattr(worker, "inline_ir"):
        return False
    if getattr(inline_function, _INSTALLED, False):
        return True
    kept = {}

    def inline_function_once(self, caller_ir, block, i, function, arg_typs=None):
        try:
            key = (function, self.typingctx, self._compiler_pipeline, flags_key(self.flags))
            hash(key)
        except (AttributeError, TypeError):     # flags of another shape: numba's own
            return inline_function(self, caller_ir, block, i, function, arg_typs)
        callee_ir = kept.get(key)
        if callee_ir is None:
            callee_ir = kept[key] = self.run_untyped_passes(function)
        else:
            self.flags.enable_ssa = False        # as run_untyped_passes leaves the caller's flags
        return self.inline_ir(caller_ir, block, i, callee_ir, function.__code__.co_freevars, arg_typs=arg_typs)

    setattr(inline_function_once, _INSTALLED, True)
    inline_function_once.numba_inline_function = inline_function   # numba's own, for the tests
    inline_function_once.kept = kept
    inline_function_once.__doc__ = inline_function.__doc__
    worker.inline_function = inline_function_once
    return True
