"""The WGSL path's compile time, for benchmarks/bench.py (``make bench``; never run by the
tests)."""
from __future__ import annotations

import time

from .runner import _PIPELINES


def compile_seconds(first_render) -> float:
    """Seconds ``first_render()`` takes with the process's pipeline cache emptied: the
    compile of the scene's pipeline, including the driver's compile at the first dispatch.
    ``first_render`` should compile, upload and dispatch a tiny (8 x 8) image; benchmarks/bench.py
    times ``rtfgu.render(..., backend="wgpu")`` with it."""
    _PIPELINES.clear()  # time a real compile
    start = time.perf_counter()
    first_render()
    return time.perf_counter() - start
