"""Whether two arrays hold the same bytes, read on all cores: what a render compares to know
that nothing changed since the last (a scene's BVH and its Mesh's face groups are kept
while their arrays are equal to the copies taken when they were made, rtfgu.layout._cached,
Mesh.surfaces). For a 1.31 M-triangle mesh that is some 150 MB read at every render.

numpy releases the GIL while it compares, so a big array is compared in slices of CHUNK
bytes on a few threads at once; equal bytes are equal values, and where they differ (a -0
for a 0) the caller only makes again what it would have kept."""
from __future__ import annotations

import os

from .lazy_import import numpy as np

CHUNK = 1 << 22
_POOL = None


def _pool():
    """The comparing threads, started at the first big comparison (a ThreadPoolExecutor;
    concurrent.futures is imported then, not with the package)."""
    global _POOL
    if _POOL is None:
        from concurrent.futures import ThreadPoolExecutor
        _POOL = ThreadPoolExecutor(max_workers=min(8, os.cpu_count() or 1), thread_name_prefix="rtfgu-same")
    return _POOL


def _words(a: np.ndarray) -> np.ndarray:
    flat = a.reshape(-1).view(np.uint8)
    return flat.view(np.uint64) if flat.size % 8 == 0 else flat


def same_arrays(pairs) -> bool:
    """True where every (a, b) of ``pairs`` has the same dtype, shape and bytes (a view that
    is not contiguous: the same values)."""
    slices = []
    for a, b in pairs:
        if a.dtype != b.dtype or a.shape != b.shape:
            return False
        if not (a.flags.c_contiguous and b.flags.c_contiguous):
            if not np.array_equal(a, b):
                return False
            continue
        x, y = _words(a), _words(b)
        if a.nbytes < 2 * CHUNK:
            if not np.array_equal(x, y):
                return False
            continue
        step = CHUNK // x.itemsize
        slices += [(x[i:i + step], y[i:i + step]) for i in range(0, x.size, step)]
    if not slices:
        return True
    return all(_pool().map(lambda pair: np.array_equal(pair[0], pair[1]), slices))
