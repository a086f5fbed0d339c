"""rtfgu.kernels.inline_copy: the blocks of one inlined body share one copy of its scope,
copied as numba copies them otherwise, and a function that inlines computes what it did."""
from __future__ import annotations

import copy

import numpy as np
from numba import njit
from numba.core import inline_closurecall, ir
from numba.core.compiler import run_frontend

import rtfgu.kernels  # noqa: F401  (installs the shared scope, as a render does)
from rtfgu.kernels import inline_copy


def trace_blocks():
    """The blocks of the ray-cast trace's IR: a body of many blocks and variables."""
    from rtfgu.kernels import render

    blocks = run_frontend(render.trace.py_func).blocks
    assert len(blocks) > 20 and len({id(b.scope) for b in blocks.values()}) == 1
    return blocks


def test_the_blocks_of_one_inlining_share_one_copy_of_their_scope():
    blocks = trace_blocks()
    shim = inline_copy.ScopeOnceCopy(ir.Block)
    with shim.session():
        copies = {label: shim.deepcopy(block) for label, block in blocks.items()}
    scopes = {id(b.scope) for b in copies.values()}
    assert len(scopes) == 1
    original = next(iter(blocks.values())).scope
    shared = next(iter(copies.values())).scope
    assert shared is not original
    assert shared == copy.deepcopy(original)    # equal by value (numba's equality)
    assert set(shared.localvars._con) == set(original.localvars._con)
    for label, block in blocks.items():
        numba_own = copy.deepcopy(block)
        assert copies[label] is not block
        assert copies[label] == numba_own
        assert copies[label].body is not block.body
        # Each statement is a copy, none is shared with the function copied from.
        assert all(a is not b for a, b in zip(copies[label].body, block.body))


def test_each_inlining_copies_the_scope_again_and_outside_one_blocks_are_numbas_copies():
    blocks = trace_blocks()
    shim = inline_copy.ScopeOnceCopy(ir.Block)
    first_block = next(iter(blocks.values()))
    with shim.session():
        a = shim.deepcopy(first_block).scope
        with shim.session():    # an inlining within one, while its body is typed
            inner = shim.deepcopy(first_block).scope
        assert shim.deepcopy(first_block).scope is a
    with shim.session():
        b = shim.deepcopy(first_block).scope
    assert len({id(a), id(inner), id(b), id(first_block.scope)}) == 4
    outside = [shim.deepcopy(block).scope for block in list(blocks.values())[:3]]
    assert len({id(s) for s in outside}) == 3


def test_numbas_inliner_copies_a_body_with_one_scope_a_copy(monkeypatch):
    """An njit function that inlines a body of several blocks: each of the inliner's two
    copies of the body holds one scope (numba's own: one per block), and the result is the
    Python function's."""
    worker = inline_closurecall.InlineWorker
    assert getattr(worker.inline_ir, "_rtfgu_scope_once", False)
    shim = inline_closurecall.copy
    assert isinstance(shim, inline_copy.ScopeOnceCopy)
    seen = []   # (the inlining's session, the scope a block was copied from, its copy's)
    own = shim.deepcopy

    def spy(x, memo=None):
        out = own(x, memo)
        if isinstance(x, ir.Block) and memo is None:
            # The session itself, kept alive here, so that no later session takes its id.
            seen.append((shim._sessions[-1] if shim._sessions else None, id(x.scope), id(out.scope)))
        return out
    monkeypatch.setattr(shim, "deepcopy", spy)

    @njit(inline="always")
    def branches(x):
        if x > 2.0:
            y = x * 2.0
        elif x > 1.0:
            y = x + 1.0
        else:
            y = -x
        for k in range(3):
            if y > 10.0:
                break
            y += k
        return y

    @njit
    def caller(x):
        return branches(x) + branches(x + 1.0)

    values = np.array([-1.0, 0.5, 1.5, 2.5, 9.0])
    assert [caller(v) for v in values] == [caller.py_func(v) for v in values]
    blocks_copied = [s for s in seen if s[0] is not None]
    assert len(blocks_copied) >= 4 * 4     # two call sites, two copies each, several blocks
    # Every copy of a block whose source scope is the same, in one inlining, has one scope.
    by_source = {}
    for session, source, made in blocks_copied:
        by_source.setdefault((id(session), source), set()).add(made)
    assert all(len(made) == 1 for made in by_source.values())


def test_a_copy_made_in_the_session_is_handed_back_and_outside_one_copied():
    blocks = trace_blocks()
    shim = inline_copy.ScopeOnceCopy(ir.Block)
    block = next(iter(blocks.values()))
    with shim.session():
        first = shim.deepcopy(block)
        assert first is not block
        assert shim.deepcopy(first) is first       # inline_ir's second copy, of its first
        assert shim.deepcopy(block) is not first   # the function's own block: copied again
    again = shim.deepcopy(first)                   # outside a session: numba's copy
    assert again is not first and again == first


def test_numbas_callers_of_the_inliner_discard_the_copy_it_returns():
    """The second copy is not made because nothing reads it: every call of inline_ir and
    inline_function in numba's package binds the copy to ``_``, or is inline_function's
    return of inline_ir."""
    import pathlib
    import re

    import numba

    calls = []
    for path in pathlib.Path(numba.__file__).parent.rglob("*.py"):
        text = path.read_text(errors="replace")
        for match in re.finditer(r"[^\n]*\n?[^\n]*\.inline_(?:ir|function)\(", text):
            if re.search(r"def inline_(?:ir|function)\(", match.group(0)):
                continue
            calls.append((path.name, " ".join(match.group(0).split())))
    assert len(calls) >= 3, calls
    for name, line in calls:
        assert (re.search(r"_, _, _, new_blocks = \\? ?inline_worker\.inline_(?:ir|function)\(", line)
                or line.endswith("return self.inline_ir(")), (name, line)
