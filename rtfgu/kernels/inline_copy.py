"""Copy an inlined function's IR in time that grows with its size, not with its size squared.

Every kind's code reaches a kernel by inlining (``inline="always"``, rtfgu.kernels.dispatch),
and numba (0.68.1, the version read) copies the IR of the function it inlines at each call
site (``InlineWorker.inline_ir``, numba/core/inline_closurecall.py: its nested ``copy_ir``),
twice: the copy it changes and an unchanged one it returns. It copies each block with a
``copy.deepcopy`` of its own. A block holds its function's scope, and the scope every
variable of the function, so each block's copy copied every variable again, into a scope
of its own: a body of B blocks and V variables cost B x V. The inliner then looks for the
body's scopes (``_get_all_scopes``), comparing the B copies with one another by value, and
finds them equal: one scope.

``copy_inlined_scope_once()`` makes the copies of one inlining share one copy of the scope,
made with the first block's: each block is still copied with a ``deepcopy`` of its own (its
statements and variables as numba copies them), the scope and its variables taken from that
first copy. The body's blocks then hold one scope, as the function they were copied from
does, and the renames the inliner makes in it (``scope.redefine``) are seen by every block.
Measured on render kernels (float32, an empty cache, one process each): compile and first
render of ``default_lambertian_shadows`` 13.4 s against 15.2 s, ``suffern_29_uv_mesh``
63.4 s against 71.8 s; the images equal bit for bit (docs/compile_time.md).

The second of the inliner's two copies is a copy of the first, made before the first is
changed, and ``inline_ir`` only returns it: its two callers in numba (``InlineInlinables``
through ``inline_function``, and ``InlineOverloads``) discard it
(``_, _, _, new_blocks = ...``; tests/test_inline_copy.py reads them). Within a session, a
block that is itself one of the session's copies is handed back as it is, so that copy costs
nothing; the body inlined is the first copy, as in numba.
"""
from __future__ import annotations

import contextlib
import copy as _copy

_INSTALLED = "_rtfgu_scope_once"


class ScopeOnceCopy:
    """What numba's inliner finds as its module ``copy``: ``copy``'s functions, with
    ``deepcopy`` of a block, within ``session()``, sharing the copy of its scope that the
    session's first block of that scope made; a block the session made is not copied again."""

    def __init__(self, ir_block):
        self._block = ir_block
        self._sessions = []

    def __getattr__(self, name):
        return getattr(_copy, name)

    @contextlib.contextmanager
    def session(self):
        """A context in which the blocks copied share their scope's copy: one inlining's
        (an inlining within it, while its body is typed, has a session of its own)."""
        self._sessions.append(({}, {}))
        try:
            yield
        finally:
            self._sessions.pop()

    def deepcopy(self, x, memo=None):
        if memo is not None or not self._sessions or not isinstance(x, self._block):
            return _copy.deepcopy(x, memo)
        seeds, made = self._sessions[-1]
        if id(x) in made:       # the copy inline_ir returns and its callers discard
            return x
        seed = seeds.get(id(x.scope))
        if seed is None:
            memo = {}
            out = _copy.deepcopy(x, memo)
            # The scope's copy and its variables' copies, which every later block of this
            # scope takes instead of copying them again.
            seed = {id(x.scope): memo[id(x.scope)]}
            variables = getattr(getattr(x.scope, "localvars", None), "_con", {})
            seed.update((id(v), memo[id(v)]) for v in variables.values() if id(v) in memo)
            seeds[id(x.scope)] = seed
        else:
            out = _copy.deepcopy(x, dict(seed))
        made[id(out)] = out     # kept alive while the session lasts: its id names it alone
        return out


def copy_inlined_scope_once() -> bool:
    """Install the shared scope in numba's inliner; True when installed (or already
    installed), False where numba's inliner does not have the expected shape (numba's own
    copy is then left as it is)."""
    try:
        from numba.core import inline_closurecall, ir
    except ImportError:
        return False
    worker = getattr(inline_closurecall, "InlineWorker", None)
    inline_ir = getattr(worker, "inline_ir", None)
    if inline_ir is None:
        return False
    if getattr(inline_ir, _INSTALLED, False):
        return True
    if getattr(inline_closurecall, "copy", None) is not _copy:   # not the module it copies with
        return False
    shim = ScopeOnceCopy(ir.Block)

    def inline_ir_sharing_the_scope(self, *args, **kwargs):
        with shim.session():
            return inline_ir(self, *args, **kwargs)

    setattr(inline_ir_sharing_the_scope, _INSTALLED, True)
    inline_ir_sharing_the_scope.numba_inline_ir = inline_ir   # numba's own, for the tests
    inline_ir_sharing_the_scope.__doc__ = inline_ir.__doc__
    inline_closurecall.copy = shim
    worker.inline_ir = inline_ir_sharing_the_scope
    return True
