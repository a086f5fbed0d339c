# release: solves a03
"""What the generated dispatch module (rtfgu.kernels.dispatch) needs besides numba."""
from __future__ import annotations

from types import SimpleNamespace

from numba import types


def as_python(typed, *args):
    """Run the body that the overload ``typed`` picks for ``args``, as plain Python: the
    kernels also run with the JIT disabled (NUMBA_DISABLE_JIT=1), where an overload's stub
    is called directly. Only whether an argument is None decides the pick (a tuple's
    elements too, as ``types``)."""
    return typed(*[_kind(arg) for arg in args])(*args)


def _kind(arg):
    """What the pick sees of ``arg``: types.none for None, a tuple's kinds as ``types``."""
    if arg is None:
        return types.none
    if isinstance(arg, tuple):
        return SimpleNamespace(types=tuple(_kind(a) for a in arg))
    return object()
