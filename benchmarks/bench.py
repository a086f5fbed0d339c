"""``make bench``: rays per second of every backend on a few scenes, against the lecture
layer; prints a table and writes docs/bench.md. A script, not a test: nothing is asserted.

Rows are (scene, resolution) x BACKENDS: add a backend of rtfgu.renderer.render to BACKENDS
and it gets a row in every scene. BASELINES are kernels of benchmarks/spheres_only.py that
know only spheres, for the spheres-only scene.

Columns:
  rays/s      primary + shadow + secondary rays per second, median of RUNS timed runs after
              a warm-up render (the reference: one run, see REFERENCE_STEP);
  primary/s   primary rays (pixels) per second;
  speed-up    time per pixel of the reference / time per pixel of the row;
  compile     cold compile time: the first render in a fresh process with an empty
              NUMBA_CACHE_DIR, minus the same render with the cache warm;
  max abs, RMSE, 8-bit   error against the float64 reference image before gamma, and the
              share of pixels whose 8-bit colour (rtfgu.image.to_8bit) differs.
Ray counts come from the numba kernel's counters (float64, which is the reference's image).
"""
from __future__ import annotations

import argparse
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from rtfgu.image import to_8bit  # noqa: E402
from rtfgu.kernels import render_numba  # noqa: E402
from rtfgu.layout import compile_scene  # noqa: E402
from rtfgu.renderer import render, trace  # noqa: E402
from rtfgu.scenes import SCENES  # noqa: E402

import scenes as bench_scenes  # noqa: E402
import spheres_only  # noqa: E402

# (backend, precision) rows, in order; "reference" is measured once per scene as the base.
BACKENDS = [
    ("numba", "float64"),
    ("numba", "float32"),
]
# Kernels that know only spheres: name -> run(flat, width, height).
BASELINES = {
    "spheres-only kernel": spheres_only.run_spheres_only,
    "brute-force loop": spheres_only.run_brute_force,
}
# (scene name, scene function, width, height, baselines apply)
SCENE_TABLE = [
    ("default_lambertian_shadows", SCENES["default_lambertian_shadows"], 256, 256, False),
    ("default_glossy_sphere", SCENES["default_glossy_sphere"], 256, 256, False),
    ("random_spheres_64", bench_scenes.random_spheres_64, 1024, 1024, True),
]
RUNS = 5
# The reference renders every REFERENCE_STEP-th row and column of an image larger than
# 256 x 256 (a pure-Python 1024 x 1024 render takes minutes); its time is scaled per pixel
# and the error columns are measured on those pixels.
REFERENCE_STEP = 4
TARGETS = [
    ("numba float64 speed-up on default_lambertian_shadows 256x256", ">= 300x"),
    ("numba float64 primary rays/s on random_spheres_64 1024x1024", ">= 11 M/s"),
]


def reference_render(scene_fn, width, height):
    """(image or sampled pixels, seconds, step): the lecture layer's render, or its pixel
    loop on every step-th row and column for a large image."""
    step = 1 if width * height <= 256 * 256 else REFERENCE_STEP
    scene = scene_fn()
    start = time.perf_counter()
    if step == 1:
        image = render(scene, width, height, backend="reference")
    else:
        # The body of rtfgu.renderer.render_reference on a subset of the pixels.
        rows = range(0, height, step)
        cols = range(0, width, step)
        image = np.zeros((height, width, 3))
        for iy in rows:
            for ix in cols:
                sx = 2 * (ix + 0.5) / width - 1
                sy = 2 * (iy + 0.5) / height - 1
                color = trace(scene, scene.camera.gen_ray(sx, sy))
                image[height - 1 - iy, ix] = (color.x, color.y, color.z)
    seconds = time.perf_counter() - start
    return image, seconds * step * step, step


def sampled(image, height, step):
    """The pixels the reference computed (rows counted from the bottom, as it does)."""
    if step == 1:
        return image
    rows = [height - 1 - iy for iy in range(0, height, step)]
    return image[rows][:, ::step]


def median_seconds(fn):
    fn()  # warm-up (and compile, if the cache is cold)
    times = []
    for _ in range(RUNS):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


COLD_SCRIPT = r"""
import sys, time
sys.path.insert(0, {root!r}); sys.path.insert(0, {bench!r})
from rtfgu.renderer import render
import scenes as bench_scenes
from rtfgu.scenes import SCENES
fn = SCENES.get({name!r}) or getattr(bench_scenes, {name!r})
scene = fn()
start = time.perf_counter(); render(scene, 8, 8, backend={backend!r}, precision={precision!r})
cold = time.perf_counter() - start
start = time.perf_counter(); render(scene, 8, 8, backend={backend!r}, precision={precision!r})
print(cold - (time.perf_counter() - start))
"""


def cold_compile_seconds(name, backend, precision):
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache)
        script = COLD_SCRIPT.format(root=str(ROOT), bench=str(Path(__file__).parent),
                                    name=name, backend=backend, precision=precision)
        done = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True,
                              text=True)
    if done.returncode != 0:
        return None
    return float(done.stdout.split()[-1])


def errors(image, ref, height, step):
    image = sampled(image, height, step)
    ref = sampled(ref, height, step)
    diff = image - ref
    differ = np.any(to_8bit(image) != to_8bit(ref), axis=2)
    return np.abs(diff).max(), float(np.sqrt(np.mean(diff * diff))), differ.mean()


def fmt_rate(x):
    return "%.2f M" % (x / 1e6) if x >= 1e5 else "%.0f k" % (x / 1e3)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(ROOT / "docs" / "bench.md"))
    parser.add_argument("--no-compile", action="store_true", help="skip the cold compile column")
    args = parser.parse_args(argv)

    import numba
    header = ("| scene | resolution | backend | precision | rays/s | primary/s | speed-up "
              "| compile | max abs | RMSE | 8-bit differ |")
    lines = [header, "|" + "---|" * 11]
    findings = {}
    for name, scene_fn, width, height, with_baselines in SCENE_TABLE:
        _, counts = render_numba(scene_fn(), width, height, "float64", with_counts=True)
        ref, ref_seconds, step = reference_render(scene_fn, width, height)
        pixels = width * height
        note = "" if step == 1 else " (every %dth row and column)" % step
        rows = [("reference" + note, "float64", ref_seconds, ref, None)]
        for backend, precision in BACKENDS:
            def run(backend=backend, precision=precision):
                return render(scene_fn(), width, height, backend=backend, precision=precision)
            try:
                image = run()
                seconds = median_seconds(run)
            except Exception as error:  # a backend that cannot run here gets a row saying so
                lines.append("| %s | %dx%d | %s | %s | not run: %s |||||||"
                             % (name, width, height, backend, precision, error))
                continue
            compile_s = None if args.no_compile else cold_compile_seconds(name, backend, precision)
            rows.append((backend, precision, seconds, image, compile_s))
        if with_baselines:
            for label, run_baseline in BASELINES.items():
                for precision in ("float64", "float32"):
                    def run(run_baseline=run_baseline, precision=precision):
                        flat = compile_scene(scene_fn(), precision)
                        return run_baseline(flat, width, height)
                    image = run()
                    rows.append((label, precision, median_seconds(run), image, None))
        for backend, precision, seconds, image, compile_s in rows:
            speedup = ref_seconds / seconds
            max_abs, rmse, differ = errors(image, ref, height, step)
            lines.append("| %s | %dx%d | %s | %s | %s | %s | %s | %s | %.2g | %.2g | %.4f %% |" % (
                name, width, height, backend, precision, fmt_rate(counts.total / seconds),
                fmt_rate(pixels / seconds), "%.0fx" % speedup,
                "-" if compile_s is None else "%.1f s" % compile_s, max_abs, rmse, 100 * differ))
            findings[(name, backend, precision)] = (speedup, pixels / seconds)
        lines.append("| | | rays per frame: %d primary, %d shadow, %d secondary |||||||||"
                     % (counts.primary, counts.shadow, counts.secondary))
        print("\n".join(lines[-len(rows) - 1:]), flush=True)

    checks = []
    s = findings.get(("default_lambertian_shadows", "numba", "float64"))
    if s:
        checks.append("- numba float64 on default_lambertian_shadows 256x256: %.0fx the reference "
                      "(target >= 300x): %s" % (s[0], "met" if s[0] >= 300 else "NOT met"))
    s = findings.get(("random_spheres_64", "numba", "float64"))
    if s:
        checks.append("- numba float64 on random_spheres_64 1024x1024: %.1f M primary rays/s "
                      "(target >= 11 M/s): %s" % (s[1] / 1e6, "met" if s[1] >= 11e6 else "NOT met"))
    load = os.getloadavg() if hasattr(os, "getloadavg") else ("?",)
    text = "\n".join([
        "# Benchmark",
        "",
        "`make bench` (benchmarks/bench.py) on %s, %d CPUs, numba %s with %d threads, "
        "load average %s at the end. Timings are medians of %d runs after a warm-up; the "
        "reference is one run. Columns are explained in benchmarks/bench.py."
        % (platform.processor() or platform.machine(), os.cpu_count(), numba.__version__,
           numba.get_num_threads(), ", ".join("%.2f" % x for x in load), RUNS),
        "",
        *lines,
        "",
        "Targets:",
        "",
        *checks,
        "",
    ])
    try:
        from hardcases_report import hardcases_markdown
    except ImportError:
        hardcases_markdown = None
    if hardcases_markdown is not None:
        try:
            text += "\n" + hardcases_markdown() + "\n"
        except Exception as error:
            text += "\n(The hard-case section failed: %s)\n" % error
    Path(args.out).parent.mkdir(parents=True, exist_ok=True)
    Path(args.out).write_text(text)
    print("\n".join(checks))
    print("wrote", args.out)


if __name__ == "__main__":
    main()
