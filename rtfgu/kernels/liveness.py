"""numba's live-variable analysis with bit sets: the same answer, in far less time.

numba finds which variables are live at the entry of each block of a function's IR
(``numba.core.analysis.compute_live_map``) by two fixed points over Python sets of
variable names: the definitions that reach each block, then liveness pushed backwards.
Dead-code elimination runs it after every round of inlining (``ir_utils.remove_dead``),
and the post-processor once more (``postproc.VariableLifetime.livemap``). A kernel here
is one function with every overload inlined into it, up to a thousand blocks and tens of
thousands of variables, and the sets of reaching definitions hold most of them: each
union copies thousands of strings, and the first fixed point alone was 11-17 % of a pixel
debugger kernel's compile (sampled with py-spy; docs/compile_time.md).

``compute_live_map`` below makes the same passes in the same order, each set a Python
integer with a bit per variable, so a union is one machine-word loop in C. The result
is the same map (block label to the set of names live at its entry), built from the same
equations: both iterate from the same start until a whole pass changes nothing, which is
the least fixed point either way. ``use_bitset_liveness()`` puts it where numba's
modules call it (analysis, ir_utils, postproc through analysis, parfors.parfor);
tests/test_liveness.py compares the two on real kernels' IR.
"""
from __future__ import annotations

_MODULES = ("numba.core.analysis", "numba.core.ir_utils", "numba.parfors.parfor")


def compute_live_map(cfg, blocks, var_use_map, var_def_map):
    """numba.core.analysis.compute_live_map's contract: the variables that must be alive
    at the ENTRY of each block, a dict {label: set of names} in the order of ``blocks``."""
    names = []
    index = {}

    def bits(variables):
        mask = 0
        for name in variables:
            i = index.get(name)
            if i is None:
                i = index[name] = len(names)
                names.append(name)
            mask |= 1 << i
        return mask

    uses = {label: bits(variables) for label, variables in var_use_map.items()}
    defs = {label: bits(variables) for label, variables in var_def_map.items()}
    topo_order = cfg.topo_order()
    successors = {label: [out for out, _ in cfg.successors(label)] for label in topo_order}
    predecessors = {label: [inc for inc, _ in cfg.predecessors(label)] for label in topo_order}

    # The definitions reachable at the entry of each block (numba's def_reach).
    reach = {}
    changed = True
    while changed:
        changed = False
        for label in topo_order:
            here = reach.get(label, 0) | defs[label] | uses[label]
            if here != reach.get(label, 0):
                reach[label] = here
                changed = True
            for out in successors[label]:
                there = reach.get(out, 0)
                if here | there != there:
                    reach[out] = here | there
                    changed = True

    # Liveness pushed backwards, kept to the definitions that reach (numba's liveness).
    live = {label: uses[label] for label in blocks.keys()}
    changed = True
    while changed:
        changed = False
        for label in reversed(topo_order):
            for inc in predecessors[label]:
                before = live[inc]
                after = before | (live[label] & reach.get(inc, 0) & ~defs[inc])
                if after != before:
                    live[inc] = after
                    changed = True
    return {label: _names(mask, names) for label, mask in live.items()}


def _names(mask: int, names: list) -> set:
    """The names whose bits are set in ``mask``."""
    found = set()
    digits = bin(mask)[:1:-1]   # bit 0 first
    i = digits.find("1")
    while i >= 0:
        found.add(names[i])
        i = digits.find("1", i + 1)
    return found


def use_bitset_liveness() -> bool:
    """Put ``compute_live_map`` where numba's modules look it up; True when installed (or
    already installed), False where numba has no such function."""
    import importlib

    try:
        analysis = importlib.import_module("numba.core.analysis")
    except ImportError:
        return False
    numba_own = getattr(analysis, "compute_live_map", None)
    if numba_own is None:
        return False
    if numba_own is compute_live_map:
        return True
    for name in _MODULES:
        module = importlib.import_module(name)
        if getattr(module, "compute_live_map", None) is numba_own:
            module.compute_live_map = compute_live_map
    compute_live_map.numba_compute_live_map = numba_own
    return True
