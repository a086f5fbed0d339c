"""numba's ``njit`` and ``prange`` for the array loops outside the numba path (the BVH build,
a mesh's per-face checks and bounds), or, where numba is not installed, the function itself
and ``range``: the same loop in plain Python, the same results, slower. ``chunks_of_one()``
hands a ``prange``'s iterations to the threads one at a time (numba.parallel_chunksize(1)),
for loops whose iterations differ in cost; without numba it does nothing. ``threads()``:
how many threads a ``prange`` runs on (numba.get_num_threads()), 1 without numba.
``one_thread()`` runs the ``prange`` loops inside it on the calling thread alone
(numba.set_num_threads(1), the count restored after): a parallel loop ends when every thread
has done its share, and on a machine whose cores are busy with other work (another process, a
test suite's other worker) a thread waits several milliseconds for a core, whatever the loop's
size; a small job is done sooner on the caller's core (docs/bvh.md, "A small mesh's build on
a busy machine")."""
from __future__ import annotations

import contextlib

try:
    from numba import get_num_threads as threads, njit, parallel_chunksize, prange, set_num_threads

    def chunks_of_one():
        return parallel_chunksize(1)

    @contextlib.contextmanager
    def one_thread():
        count = threads()
        set_num_threads(1)
        try:
            yield
        finally:
            set_num_threads(count)
except ImportError:
    prange = range

    def threads():
        return 1

    def njit(*args, **kwargs):
        return args[0] if args and callable(args[0]) else (lambda f: f)

    def chunks_of_one():
        return contextlib.nullcontext()

    def one_thread():
        return contextlib.nullcontext()

__all__ = ["chunks_of_one", "njit", "one_thread", "prange", "threads"]
