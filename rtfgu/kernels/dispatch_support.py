# release: solves a03
"""What the generated dispatch module (rtfgu.kernels.dispatch) needs besides numba."""
from __future__ import annotations

from numba import types


def as_python(typed, *args):
    """Run the body that the overload ``typed`` picks for ``args``, as plain Python: the
    kernels also run with the JIT disabled (NUMBA_DISABLE_JIT=1), where an overload's stub
    is called directly. Only whether an argument is None decides the pick."""
    kinds = [types.none if arg is None else object() for arg in args]
    return typed(*kinds)(*args)
