"""How long a render has left, from the pace of its passes (the command line's progress bar and
``rtfgu.show`` in a notebook).

The first report of a render also holds its start-up (numba compiling its kernels, wgpu its
WGSL program, a BVH being built), which the later passes do not repeat: the time left is the
pace measured since the first report, times what remains, and is unknown until a second report.
"""
from __future__ import annotations

import time


class TimeLeft:
    """``update(done, total)`` after each report; ``elapsed`` and ``left()`` (seconds, or None
    while there is no pace yet) after it."""

    def __init__(self):
        self.start = time.perf_counter()
        self.elapsed = 0.0
        self._first = None      # (elapsed, done) at the first report with work done
        self._done = self._total = 0

    def update(self, done: int, total: int) -> None:
        self.elapsed = time.perf_counter() - self.start
        self._done, self._total = done, total
        if done and self._first is None:
            self._first = (self.elapsed, done)

    def left(self):
        if self._done >= self._total:
            return 0.0
        if self._first is None or self._done <= self._first[1]:
            return None
        pace = (self.elapsed - self._first[0]) / (self._done - self._first[1])
        return pace * (self._total - self._done)

    def describe(self) -> str:
        """"done", "12.3 s left" or "estimating the time left"."""
        left = self.left()
        if self._done >= self._total:
            return "done"
        return "estimating the time left" if left is None else "%.1f s left" % left
