"""numba's ``njit`` for the array loops outside the numba path (the BVH build, a mesh's
per-face checks and bounds), or, where numba is not installed, the function itself: the
same loop in plain Python, the same results, slower."""
from __future__ import annotations

try:
    from numba import njit
except ImportError:
    def njit(*args, **kwargs):
        return args[0] if args and callable(args[0]) else (lambda f: f)

__all__ = ["njit"]
