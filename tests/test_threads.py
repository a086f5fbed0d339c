"""The render's tiles in threads (rtfgu.kernels.threads): every tile claimed exactly once
whatever the thread count, the same image bit for bit, an error raised only once every
thread has ended, and a forked child that makes its own workers."""
from __future__ import annotations

import multiprocessing
import sys
import threading
import time

import numpy as np
import pytest
from numba import njit

from rtfgu.kernels import threads
from rtfgu.kernels.threads import claim, finish, run_in_threads, run_length


@njit(nogil=True, cache=True)
def _mark(n, share, marks, owner):
    """A kernel shaped as render_kernel: claims runs of k < n and marks each; ``owner[k]``
    the call that took it (its first claim), to tell the calls apart."""
    _, counter, run = share
    first = claim(counter, run)
    me = first
    while first < n:
        for k in range(first, min(first + run, n)):
            marks[k] += 1
            owner[k] = me
            # Some work a k, so that the threads overlap.
            x = 0.0
            for i in range(2000):
                x += np.sqrt(i + k)
            marks[k] += 0 if x >= 0 else 1
        finish(counter, min(first + run, n) - first)
        first = claim(counter, run)


@pytest.mark.parametrize("n, count", [(1, 4), (7, 3), (1000, 1), (1000, 2), (1000, 7), (4096, 5)])
def test_every_tile_is_claimed_exactly_once(n, count):
    marks = np.zeros(n, dtype=np.int64)
    owner = np.full(n, -1, dtype=np.int64)
    run_in_threads(_mark, (n,), (marks, owner), n, 1, threads=count)
    assert (marks == 1).all()
    assert (owner >= 0).all()


def test_the_atomic_claim_holds_under_contention():
    # Runs of one k and no work between claims: the two threads claim from one counter as
    # fast as they can; a claim that was not atomic would hand a k out twice or skip one.
    @njit(nogil=True)
    def grab(counter, n, out):
        m = 0
        k = claim(counter, 1)
        while k < n:
            out[m] = k
            m += 1
            k = claim(counter, 1)
        return m

    n = 2_000_000
    counter = np.zeros(1, dtype=np.int64)
    outs = [np.full(n, -1, dtype=np.int64) for _ in range(2)]
    taken = {}
    grab(np.zeros(1, dtype=np.int64), 0, outs[0])   # compiled before the threads start
    other = threading.Thread(target=lambda: taken.__setitem__(1, grab(counter, n, outs[1])))
    other.start()
    taken[0] = grab(counter, n, outs[0])
    other.join()
    claimed = np.concatenate([outs[0][:taken[0]], outs[1][:taken[1]]])
    assert len(claimed) == n
    assert np.array_equal(np.sort(claimed), np.arange(n))
    assert counter[0] >= n


def test_plain_python_claims_hold_under_thread_switches():
    # NUMBA_DISABLE_JIT=1 runs claim as Python: its lock keeps the read and the write together
    # however often the interpreter switches threads.
    counter = np.zeros(1, dtype=np.int64)
    got = [[] for _ in range(4)]

    def take(out):
        for _ in range(3000):
            out.append(claim(counter, 1))

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1e-6)
    try:
        workers = [threading.Thread(target=take, args=(out,)) for out in got]
        for worker in workers:
            worker.start()
        for worker in workers:
            worker.join()
    finally:
        sys.setswitchinterval(interval)
    claimed = sorted(k for out in got for k in out)
    assert claimed == list(range(12000))


def test_run_length_is_about_sixty_four_runs_a_thread():
    assert run_length(4096, 2) == 32
    assert run_length(16, 2) == 1
    assert run_length(0, 2) == 1
    assert run_length(10**6, 0) == 10**6 // threads.RUNS_PER_THREAD


def test_an_error_is_raised_once_every_thread_has_ended():
    ended = []

    def kernel(share, marks):
        if threading.current_thread() is threading.main_thread():
            raise ValueError("the calling thread's share failed")
        time.sleep(0.3)
        ended.append(True)

    with pytest.raises(ValueError, match="calling thread"):
        run_in_threads(kernel, (), (None,), 8, 1, threads=2)
    assert ended == [True]


def test_an_error_of_a_worker_reaches_the_caller():
    def kernel(share, marks):
        if threading.current_thread() is not threading.main_thread():
            raise RuntimeError("a worker's share failed")
        marks.append(1)

    marks = []
    with pytest.raises(RuntimeError, match="worker"):
        run_in_threads(kernel, (), (marks,), 8, 1, threads=3)
    assert marks == [1]


def test_the_caller_returns_once_the_tiles_are_done_not_the_threads():
    # A worker that wakes after the caller has claimed every tile finds none, writes nothing,
    # and is not waited for.
    gate = threading.Event()
    returned = []

    def kernel(share, marks):
        _, counter, run = share
        if threading.current_thread() is not threading.main_thread():
            gate.wait(30)
        first = claim(counter, run)
        while first < 16:
            marks[first:first + run] += 1
            finish(counter, min(run, 16 - first))
            first = claim(counter, run)
        if threading.current_thread() is not threading.main_thread():
            returned.append(True)

    marks = np.zeros(16, dtype=np.int64)
    run_in_threads(kernel, (), (marks,), 16, 1, threads=2)
    assert (marks == 1).all()
    assert returned == []
    gate.set()
    for _ in range(300):
        if returned:
            break
        time.sleep(0.01)
    assert returned == [True]
    assert (marks == 1).all()


def test_where_no_thread_can_start_the_caller_renders_every_tile(monkeypatch):
    class NoThreads:
        def submit(self, *args):
            raise RuntimeError("can't start new thread")

    monkeypatch.setattr(threads, "_workers", lambda count: NoThreads())
    marks = np.zeros(100, dtype=np.int64)
    owner = np.full(100, -1, dtype=np.int64)
    run_in_threads(_mark, (100,), (marks, owner), 100, 1, threads=4)
    assert (marks == 1).all()
    assert (owner == 0).all()


def _in_child(queue):
    marks = np.zeros(64, dtype=np.int64)
    owner = np.full(64, -1, dtype=np.int64)
    run_in_threads(_mark, (64,), (marks, owner), 64, 1, threads=2)
    queue.put(int(marks.sum()))


@pytest.mark.skipif(sys.platform != "linux", reason="fork is the start method under test")
def test_a_forked_child_makes_its_own_workers():
    run_in_threads(_mark, (64,), (np.zeros(64, dtype=np.int64), np.zeros(64, dtype=np.int64)), 64, 1,
                   threads=2)
    assert threads._pool is not None
    context = multiprocessing.get_context("fork")
    queue = context.Queue()
    child = context.Process(target=_in_child, args=(queue,))
    child.start()
    child.join(60)
    if child.is_alive():
        child.kill()
        pytest.fail("the child waited on its parent's worker threads")
    assert child.exitcode == 0
    assert queue.get(timeout=5) == 64


def test_the_render_kernel_is_a_plain_loop_without_the_gil():
    # The parallel pipeline is what this module saves every kernel's compile.
    from rtfgu.kernels.render import render_kernel
    assert not render_kernel.targetoptions.get("parallel")
    assert render_kernel.targetoptions.get("nogil")


@pytest.mark.parametrize("precision", ["float64", "float32"])
def test_images_and_counts_are_the_same_for_any_thread_count(precision):
    from rtfgu.kernels import COUNTS, NumbaAccumulator, kernel_arguments, render_kernel
    from rtfgu.scenes import SCENES

    accumulate = NumbaAccumulator(SCENES["default_glossy_sphere"](), 48, 48, precision)
    args, tiles = kernel_arguments(accumulate.flat, 48, 48)
    seen = []
    for count in (1, 2, 3, 9):
        sums = np.full((48, 48, 3), np.nan)
        counts = np.zeros((tiles, COUNTS), dtype=np.int64)
        run_in_threads(render_kernel, args[:-1], (sums, counts), tiles, args[-1], threads=count)
        seen.append((sums.tobytes(), counts.tobytes()))
    assert np.isfinite(np.frombuffer(seen[0][0])).all()
    assert np.frombuffer(seen[0][1], dtype=np.int64).reshape(tiles, COUNTS)[:, 0].sum() == 48 * 48
    assert all(s == seen[0] for s in seen)


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("shape, count", [((1, 3, 3), 4), ((37, 5, 3), 2), ((300, 41, 3), 1), ((300, 41, 3), 2),
                                          ((300, 41, 3), 7)])
def test_the_mean_image_is_the_division_in_the_sums_precision_on_any_thread_count(dtype, shape, count, monkeypatch):
    """mean_image shares its rows between the threads as the tiles are (a small image's made by
    the caller alone): every value is the sums' own division (not float64's), and the values
    not finite (inf, NaN and an overflow of the division) are counted once each."""
    import numba

    from rtfgu.kernels.render import mean_image
    rng = np.random.default_rng(len(shape) + shape[0] + count)
    sums = (rng.random(shape) * 3).astype(dtype)
    sums.reshape(-1)[rng.choice(sums.size, min(5, sums.size), replace=False)] = [np.inf, -np.inf, np.nan, 7, 1][
        :min(5, sums.size)]
    n = dtype(0.3) if dtype == np.float32 else dtype(3)
    if dtype == np.float32:
        sums.reshape(-1)[-1] = np.finfo(np.float32).max         # / 0.3 overflows float32, not float64
    monkeypatch.setattr(numba, "get_num_threads", lambda: count)
    out = np.full(shape, -1.0)
    bad = mean_image(sums, n, out)
    with np.errstate(over="ignore", invalid="ignore"):
        want = (sums / n).astype(np.float64)
    assert out.tobytes() == want.tobytes()
    assert bad == int((~np.isfinite(want)).sum()) > 0


def test_one_thread_runs_numba_loops_on_the_caller_and_gives_the_count_back():
    """rtfgu.jit.one_thread: numba's thread count is 1 inside, and what it was after, an error
    raised inside included; a build of at most TASK_FLOOR primitives runs on one thread,
    a larger one on all."""
    import numba

    from rtfgu.accelerators import flat_bvh
    from rtfgu.jit import one_thread
    before = numba.get_num_threads()
    with one_thread():
        assert numba.get_num_threads() == 1
    assert numba.get_num_threads() == before
    with pytest.raises(KeyError):
        with one_thread():
            raise KeyError("inside")
    assert numba.get_num_threads() == before
    seen = []
    with flat_bvh._threads_for(flat_bvh.TASK_FLOOR):
        seen.append(numba.get_num_threads())
    with flat_bvh._threads_for(flat_bvh.TASK_FLOOR + 1):
        seen.append(numba.get_num_threads())
    assert seen == [1, before]
