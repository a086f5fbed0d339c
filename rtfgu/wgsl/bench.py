"""Benchmark rows for the WGSL path (``make bench``; never run by the tests).

``bench_rows()`` yields one dict per homework scene: the adapter, the time to compile the
scene's pipeline (including the driver's compile at the first dispatch), camera rays per
second at the homework size (best of ``repeats``), and the error against the float64
reference at a smaller size (the pure-Python reference is slow). ``python -m
rtfgu.wgsl.bench`` prints them as a table.
"""
from __future__ import annotations

import time

import numpy as np

from ..image import to_8bit
from ..layout import compile_scene
from ..renderer import render_reference
from ..scenes import SCENES
from .assemble import assemble
from .device import adapter_description
from .runner import _PIPELINES, compile_program


def compile_seconds(first_render) -> float:
    """Seconds ``first_render()`` takes with the process's pipeline cache emptied: the
    compile of the scene's pipeline, including the driver's compile at the first dispatch.
    ``first_render`` should compile, upload and dispatch a tiny (8 x 8) image; benchmarks/bench.py
    times ``rtfgu.render(..., backend="wgpu")`` with it."""
    _PIPELINES.clear()  # time a real compile
    start = time.perf_counter()
    first_render()
    return time.perf_counter() - start


def bench_rows(names=None, repeats: int = 3, error_size: int = 64):
    adapter = adapter_description()
    for name in names or list(SCENES):
        fn = SCENES[name]
        width, height = fn.size
        flat = compile_scene(fn(), "float32")
        program = assemble(flat)

        def first_render():
            compiled = compile_program(program)
            compiled.upload(flat)
            compiled.render(8, 8)

        compile_s = compile_seconds(first_render)
        compiled = compile_program(program)  # the pipeline just compiled
        best = float("inf")
        for _ in range(repeats):
            start = time.perf_counter()
            compiled.render(width, height)
            best = min(best, time.perf_counter() - start)
        small = compiled.render(error_size, error_size).astype(np.float64)
        reference = render_reference(fn(), error_size, error_size)
        within = (np.abs(to_8bit(small).astype(int) - to_8bit(reference).astype(int)).max(axis=2)
                  <= 1).mean()
        yield {
            "path": "wgpu float32",
            "adapter": adapter,
            "scene": name,
            "size": "%dx%d" % (width, height),
            "compile_s": compile_s,
            "seconds": best,
            "camera_rays_per_s": width * height / best,
            "max_abs_error_vs_float64": float(np.abs(small - reference).max()),
            "pixels_within_1_255": float(within),
        }


def main() -> None:
    rows = list(bench_rows())
    print("adapter: %s" % rows[0]["adapter"])
    print("%-28s %-8s %9s %9s %14s %12s %9s" % ("scene", "size", "compile s", "render s",
                                               "camera rays/s", "max |err|", "within"))
    for r in rows:
        print("%-28s %-8s %9.2f %9.3f %14.3g %12.2e %8.2f%%" % (
            r["scene"], r["size"], r["compile_s"], r["seconds"], r["camera_rays_per_s"],
            r["max_abs_error_vs_float64"], 100 * r["pixels_within_1_255"]))


if __name__ == "__main__":
    main()
