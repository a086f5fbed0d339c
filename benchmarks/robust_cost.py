"""The speed cost of the robust sphere test (Ray Tracing Gems ch. 7) against the slide's
quadratic in full renders: the figures behind the default formula of the numba and wgpu
paths (docs/robust_defaults.md). A script, not a test: nothing is asserted.

    python benchmarks/robust_cost.py [--runs 7]

Per (scene, size, backend, precision): one warm-up render per formula, then ``--runs``
rounds, each timing the slide and the robust render once, in alternating order, so that a
change in the machine's load hits both alike; the median of each is quoted. rays/s counts
primary + shadow + secondary rays from the numba kernel's counters for the same formula and
precision (numba float32 for wgpu, whose shader does not count). Prints a markdown table.
"""
from __future__ import annotations

import argparse
import os
import platform
import statistics
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
sys.path.insert(0, str(HERE))

from rtfgu.kernels import render_numba  # noqa: E402
from rtfgu.renderer import render  # noqa: E402
from rtfgu.scenes import SCENES  # noqa: E402
from scenes import random_spheres_64  # noqa: E402

FORMULAS = ("slide", "robust")

CASES = (
    ("default_lambertian_shadows", SCENES["default_lambertian_shadows"], 256, 256, "numba", "float64"),
    ("default_lambertian_shadows", SCENES["default_lambertian_shadows"], 256, 256, "numba", "float32"),
    ("default_glossy_sphere", SCENES["default_glossy_sphere"], 256, 256, "numba", "float64"),
    ("default_glossy_sphere", SCENES["default_glossy_sphere"], 256, 256, "numba", "float32"),
    ("random_spheres_64", random_spheres_64, 1024, 1024, "numba", "float64"),
    ("random_spheres_64", random_spheres_64, 1024, 1024, "numba", "float32"),
    ("default_glossy_sphere", SCENES["default_glossy_sphere"], 128, 128, "wgpu", "float32"),
)


def measure(scene_fn, width, height, backend, precision, runs):
    scene = scene_fn()
    rays = {}
    for f in FORMULAS:
        _, counts = render_numba(scene_fn(), width, height, precision, with_counts=True, formula=f)
        rays[f] = counts.total
        render(scene, width, height, backend=backend, precision=precision, formula=f)  # warm-up
    times = {f: [] for f in FORMULAS}
    for k in range(runs):
        order = FORMULAS if k % 2 == 0 else FORMULAS[::-1]
        for f in order:
            start = time.perf_counter()
            render(scene, width, height, backend=backend, precision=precision, formula=f)
            times[f].append(time.perf_counter() - start)
    return {f: rays[f] / statistics.median(times[f]) for f in FORMULAS}, times


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=7)
    args = parser.parse_args(argv)
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print("%s, %d cores, load %.2f at start, median of %d interleaved runs\n"
          % (platform.processor() or platform.machine(), os.cpu_count(), load, args.runs))
    print("| scene | size | backend | precision | slide rays/s | robust rays/s | robust / slide |")
    print("|---|---|---|---|---:|---:|---:|")
    for name, fn, w, h, backend, precision in CASES:
        speed, _ = measure(fn, w, h, backend, precision, args.runs)
        print("| %s | %dx%d | %s | %s | %.3g | %.3g | %.2f |"
              % (name, w, h, backend, precision, speed["slide"], speed["robust"],
                 speed["robust"] / speed["slide"]), flush=True)
    if hasattr(os, "getloadavg"):
        print("\nload %.2f at the end" % os.getloadavg()[0])


if __name__ == "__main__":
    main()
