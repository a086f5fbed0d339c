"""The render's tiles on all cores: ``render.render_kernel`` (compiled with ``nogil=True``)
run in as many Python threads at once, the calling thread one of them, each claiming the
next run of tiles from a shared counter until none is left (dynamic scheduling, as a
work queue hands out a loop's iterations).

This is what numba's ``prange`` over the tiles did, and the image is the same bit for bit:
every tile is rendered by the same code whichever thread claims it (rtfgu.kernels.render).
A loop under ``prange`` makes numba run its parallel pipeline (parfor analysis, a gufunc made
of the loop's body) on every kernel it compiles: the loop's own compile took 3.0-3.8 s of
a kernel's 13-20 s first render, for a body that is one call of render_tile a tile; as a
plain loop it takes 0.8-1.4 s (docs/compile_time.md, "The tiles' loop in threads").

A Python thread is woken, and takes the GIL for its call, about 0.1 ms after it is handed
its work on these machines. Claiming runs, rather than taking a fixed share, lets the
threads already running take a late thread's tiles; and the caller returns once every tile
is done (the counter's second value), not once every thread has returned: a thread that
wakes after the last tile was claimed finds nothing to claim and writes nothing.

The thread count is numba's (``numba.get_num_threads()``: NUMBA_NUM_THREADS, or
``numba.set_num_threads`` in the calling thread), so a render is configured as before.
"""
from __future__ import annotations

import os
import threading
import time
from concurrent.futures import ThreadPoolExecutor, wait

import numba
import numpy as np
from numba import njit, types
from numba.extending import intrinsic, overload

# The counter's values: the next tile to claim, and how many tiles are done.
NEXT, DONE = 0, 1
# Runs a thread claims, about, in a render: more balance the threads' ends better (a thread
# ends at most one run after the last), fewer cost fewer atomic additions on one counter.
RUNS_PER_THREAD = 64
# How long the caller polls for the other threads' last tiles without sleeping (seconds),
# and how long it sleeps between polls after that.
SPIN = 0.002
POLL = 0.0005

_lock = threading.Lock()
# The workers (ThreadPoolExecutor), the process they were made in, and how many they are.
_pool: tuple[ThreadPoolExecutor, int, int] | None = None


def fetch_add(counter, i, count):
    """The value of ``counter[i]`` (a C-contiguous int64 array), to which ``count`` is added
    in the same atomic step. Compiled, one LLVM ``atomicrmw add``, sequentially consistent
    (``_fetch_add``): a thread that reads DONE this way also sees the tiles counted in it.
    As plain Python (NUMBA_DISABLE_JIT=1), under a lock."""
    with _lock:
        value = int(counter[i])
        counter[i] = value + count
    return value


@intrinsic
def _fetch_add(typingctx, counter, i, count):
    """fetch_add compiled."""
    if not (isinstance(counter, types.Array) and counter.dtype == types.int64 and counter.layout == "C"
            and counter.ndim == 1 and isinstance(i, types.Integer) and isinstance(count, types.Integer)):
        return None
    sig = types.int64(counter, i, count)

    def codegen(context, builder, signature, args):
        array = context.make_array(signature.args[0])(context, builder, args[0])
        index = context.cast(builder, args[1], signature.args[1], types.intp)
        step = context.cast(builder, args[2], signature.args[2], types.int64)
        return builder.atomic_rmw("add", builder.gep(array.data, [index]), step, "seq_cst")

    return sig, codegen


@overload(fetch_add, inline="always")
def _typed_fetch_add(counter, i, count):
    return lambda counter, i, count: _fetch_add(counter, i, count)


def claim(counter, run):
    """The first of the next ``run`` tiles (counter[NEXT]), which no other thread then claims."""
    return fetch_add(counter, NEXT, run)


@overload(claim, inline="always")
def _typed_claim(counter, run):
    return lambda counter, run: _fetch_add(counter, NEXT, run)


def finish(counter, count):
    """Count ``count`` more tiles done (counter[DONE]), once their pixels are written."""
    fetch_add(counter, DONE, count)


@overload(finish, inline="always")
def _typed_finish(counter, count):
    def finish_compiled(counter, count):
        _fetch_add(counter, DONE, count)
    return finish_compiled


@njit(cache=True)
def tiles_done(counter) -> int:
    """counter[DONE], read as an atomic step (so the tiles it counts are seen written)."""
    return fetch_add(counter, DONE, 0)


def run_length(n_tiles: int, threads: int) -> int:
    """Tiles a claim takes: about RUNS_PER_THREAD claims a thread, at least one tile."""
    return max(1, n_tiles // (max(1, threads) * RUNS_PER_THREAD))


def _workers(count: int) -> ThreadPoolExecutor:
    """A pool of at least ``count`` threads, made again in a forked child (a pool's threads
    do not survive a fork, and a child submitting to its parent's pool would wait forever)."""
    global _pool
    with _lock:
        if _pool is None or _pool[1] != os.getpid() or _pool[2] < count:
            _pool = (ThreadPoolExecutor(max_workers=count, thread_name_prefix="rtfgu-tiles"), os.getpid(), count)
        return _pool[0]


def run_in_threads(kernel, before: tuple, after: tuple, n_tiles: int, stride: int,
                   threads: int | None = None) -> None:
    """``kernel(*before, (stride, counter, run), *after)`` in ``threads`` threads at once
    (numba's thread count where None; at most one a tile), the calling thread one of them:
    ``counter`` is a new int64 array [next, done] = [0, 0], from which they claim runs of
    ``run`` tiles (``claim``) and to which they count the tiles they finish (``finish``).
    Returns once all ``n_tiles`` tiles are done. An exception of a thread is raised once
    every thread that had tiles has ended, so none still writes to the arrays when the
    caller sees it. Where no thread can be started (a limit on a process's threads), the
    calling thread renders every tile."""
    threads = numba.get_num_threads() if threads is None else threads
    threads = max(1, min(threads, n_tiles))
    counter = np.zeros(2, dtype=np.int64)
    share = (stride, counter, run_length(n_tiles, threads))
    futures = []
    if threads > 1:
        pool = _workers(threads - 1)
        try:
            for _ in range(threads - 1):
                futures.append(pool.submit(kernel, *before, share, *after))
        except RuntimeError:    # "can't start new thread": the threads that started share the tiles
            pass
    try:
        kernel(*before, share, *after)
    except BaseException:
        wait(futures)
        raise
    if futures:
        _wait_for_tiles(counter, n_tiles, futures)


def _wait_for_tiles(counter, n_tiles: int, futures) -> None:
    """Poll until every tile is done, or a thread has failed (then, once all have ended, its
    exception is raised)."""
    start = time.perf_counter()
    while tiles_done(counter) < n_tiles:
        if any(future.done() and future.exception() is not None for future in futures):
            wait(futures)
            for future in futures:
                future.result()
        # Releases the GIL, which a thread needs to start its call.
        time.sleep(0 if time.perf_counter() - start < SPIN else POLL)
    for future in futures:
        if future.done():
            future.result()
