"""``make bench``: speed and error of every rendering path on a few scenes, against the
lecture layer; prints a table, writes docs/bench.md and the plot docs/bench_speed_error.png.
Its last sections come from benchmarks/sampling.py (the samplers' error against render
time), benchmarks/meshes.py (the numba and WGSL BVH over meshes against Embree and Mitsuba 3) and
benchmarks/path_tracing.py (the path tracer's time to an RMSE of 1/255 against Mitsuba 3).
A script, not a test: nothing is asserted.

Rows are scene x path, a path being backend x precision x sphere formula: the reference
(lecture layer, float64, the slide formula), numba float64 and float32, wgpu float32, each
with formula="slide" and "robust". Every path renders through
rtfgu.render, so the numbers compare. BASELINES are kernels of benchmarks/spheres_only.py
that know only spheres, for the spheres-only scene.

Timing: after a warm-up render per path, RUNS rounds; each round times every path of the
scene once (round-robin, so a change in the machine's load hits every path alike), and the
median is quoted.

Columns:
  rays/s      primary + shadow + secondary rays per second. The counts come from the numba
              kernel's counters: float64 for the reference, the row's own precision and
              formula for numba, and numba float32 (same formula, same size) for wgpu, whose
              shader does not count;
  primary/s   primary rays (pixels) per second;
  speed-up    time per pixel of the reference / time per pixel of the row;
  compile     cold compile time. numba: the first render in a fresh process with an empty
              NUMBA_CACHE_DIR, minus the same render with the cache warm. wgpu: the first
              render with the pipeline cache emptied (rtfgu.wgsl.bench.compile_seconds), with
              Mesa's on-disk shader cache disabled, minus a warm render.
              With two formulas, numba's second row shows "+x s": the compile it adds in
              the same process after the first formula (0 when one kernel serves both);
  max abs, RMSE, 8-bit   error against the float64 reference image before gamma, and the
              share of pixels whose 8-bit colour (rtfgu.image.to_8bit) differs.
"""
from __future__ import annotations

import os

# A cold WGSL compile must not come from Mesa's shader cache on disk (read when the adapter
# is created, so set before anything imports wgpu).
os.environ.setdefault("MESA_SHADER_CACHE_DISABLE", "true")

import argparse  # noqa: E402
import platform  # noqa: E402
import statistics  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from dataclasses import dataclass, field  # noqa: E402
from importlib import metadata  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(HERE))

from rtfgu.image import to_8bit  # noqa: E402
from rtfgu.kernels import render_numba  # noqa: E402
from rtfgu.layout import compile_scene  # noqa: E402
from rtfgu.renderer import render, trace  # noqa: E402
from rtfgu.scenes import SCENES  # noqa: E402

import scenes as bench_scenes  # noqa: E402
import spheres_only  # noqa: E402

RUNS = 5
# (scene name, scene function, width, height); --quick renders QUICK_SIZE instead.
SCENE_TABLE = [
    ("default_lambertian_shadows", SCENES["default_lambertian_shadows"], 256, 256),
    ("default_glossy_sphere", SCENES["default_glossy_sphere"], 256, 256),
    ("random_spheres_64", bench_scenes.random_spheres_64, 1024, 1024),
    ("lecture01_flat_colors", SCENES["lecture01_flat_colors"], 256, 256),
]
QUICK_SIZE = {256: 32, 1024: 64}
# Kernels that know only spheres: name -> run(flat, width, height); rows on this scene only.
BASELINES = {
    "spheres-only kernel": spheres_only.run_spheres_only,
    "brute-force loop": spheres_only.run_brute_force,
}
BASELINE_SCENE = "random_spheres_64"
QUICK_COMPILE_SCENE = "lecture01_flat_colors"
# The reference renders every REFERENCE_STEP-th row and column of an image larger than
# 256 x 256 (a pure-Python 1024 x 1024 render takes minutes); its time is scaled per pixel
# and the error columns are measured on those pixels.
REFERENCE_STEP = 4
# A wgpu render slower than this (the software adapter on a large image) is benchmarked at
# half the size, and so on; the row says so.
WGPU_MAX_SECONDS = 20.0
@dataclass
class Path_:
    backend: str
    precision: str
    formula: str | None = None  # None: do not pass the keyword

    @property
    def formula_label(self) -> str:
        if self.backend == "reference":
            return "slide"
        return self.formula

    @property
    def label(self) -> str:
        return "%s %s %s" % (self.backend, self.precision, self.formula_label)

    def kwargs(self) -> dict:
        return {} if self.formula is None else {"formula": self.formula}


def paths(with_wgpu: bool) -> list:
    formulas = ("slide", "robust")
    out = [Path_(backend="reference", precision="float64")]
    for precision in ("float64", "float32"):
        out += [Path_("numba", precision, f) for f in formulas]
    if with_wgpu:
        out += [Path_("wgpu", "float32", f) for f in formulas]
    return out


# ---- sections of docs/bench.md that a part of the bench rewrites on its own -------------

def replace_section(text: str, section: str, start: str, end: str) -> str:
    """``text`` with the part from the line ``start`` to the line ``end`` replaced by
    ``section`` (which holds both), or ``section`` appended when there is no such part."""
    if start in text and end in text:
        before, rest = text.split(start, 1)
        after = rest.split(end, 1)[1].lstrip("\n")
        return before + section + ("\n" + after if after else "")
    return text.rstrip("\n") + "\n\n" + section


# ---- the machine ------------------------------------------------------------------------

def cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def version(package: str) -> str:
    try:
        return metadata.version(package)
    except metadata.PackageNotFoundError:
        return "not installed"


def gpu_adapter():
    """(adapter description, None) or (None, the reason there is none)."""
    try:
        from rtfgu.wgsl.device import adapter_description
        return adapter_description(), None
    except Exception as error:  # NoAdapterError names the package to install
        return None, str(error)


# ---- timing and error -------------------------------------------------------------------

def reference_render(scene, width, height):
    """(image, step): the lecture layer's render, or its pixel loop on every step-th row and
    column for an image larger than 256 x 256."""
    step = 1 if width * height <= 256 * 256 else REFERENCE_STEP
    if step == 1:
        return render(scene, width, height, backend="reference"), 1
    # The body of rtfgu.renderer.render_reference on a subset of the pixels.
    image = np.zeros((height, width, 3))
    for iy in range(0, height, step):
        for ix in range(0, width, step):
            sx = 2 * (ix + 0.5) / width - 1
            sy = 2 * (iy + 0.5) / height - 1
            color = trace(scene, scene.camera.gen_ray(sx, sy))
            image[height - 1 - iy, ix] = (color.x, color.y, color.z)
    return image, step


def sampled(image, height, step):
    """The pixels the reference computed (rows counted from the bottom, as it does)."""
    if step == 1:
        return image
    rows = [height - 1 - iy for iy in range(0, height, step)]
    return image[rows][:, ::step]


def errors(image, ref, height, step):
    image = sampled(image, height, step)
    ref = sampled(ref, height, step)
    diff = image - ref
    differ = np.any(to_8bit(image) != to_8bit(ref), axis=2)
    return float(np.abs(diff).max()), float(np.sqrt(np.mean(diff * diff))), float(differ.mean())


def timed(fn):
    start = time.perf_counter()
    result = fn()
    return result, time.perf_counter() - start


COLD_SCRIPT = r"""
import sys, time
sys.path.insert(0, {root!r}); sys.path.insert(0, {bench!r})
from rtfgu.renderer import render
import scenes as bench_scenes
from rtfgu.scenes import SCENES
fn = SCENES.get({name!r}) or getattr(bench_scenes, {name!r})
scene = fn()
for extra in {kwargs_list!r}:
    kw = dict(backend={backend!r}, precision={precision!r}, **extra)
    start = time.perf_counter(); render(scene, 8, 8, **kw)
    cold = time.perf_counter() - start
    start = time.perf_counter(); render(scene, 8, 8, **kw)
    print(cold - (time.perf_counter() - start))
"""


def numba_cold_compile_seconds(name, precision, path_list):
    """{path label: seconds} for the numba paths of ``precision`` in ``path_list``: one fresh
    process with an empty NUMBA_CACHE_DIR renders each path in turn, so the first path's
    figure is its cold compile and a later path's is the compile it adds (0 when the formula
    is a run-time argument of the same kernel)."""
    mine = [p for p in path_list if p.backend == "numba" and p.precision == precision]
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache)
        script = COLD_SCRIPT.format(root=str(ROOT), bench=str(HERE), name=name,
                                    backend="numba", precision=precision,
                                    kwargs_list=[p.kwargs() for p in mine])
        done = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True,
                              text=True)
    if done.returncode != 0:
        print("cold compile failed for %s numba %s:\n%s" % (name, precision, done.stderr[-2000:]))
        return {}
    # A later path's difference can come out a hair below zero (timer noise): clamp it.
    return {p.label: (max(0.0, float(x)) if i else float(x), i > 0)
            for i, (p, x) in enumerate(zip(mine, done.stdout.split()))}


def wgpu_cold_compile_seconds(scene, path):
    from rtfgu.wgsl.bench import compile_seconds

    def tiny():
        render(scene, 8, 8, backend="wgpu", precision="float32", **path.kwargs())

    cold = compile_seconds(tiny)
    _, warm = timed(tiny)
    return cold - warm


def ray_counts(scene, width, height, precision, formula):
    """The numba kernel's RayCounts (primary, shadow, secondary) for this render."""
    kwargs = {} if formula is None else {"formula": formula}
    return render_numba(scene, width, height, precision, with_counts=True, **kwargs)[1]


@dataclass
class Row:
    scene: str
    width: int
    height: int
    backend: str
    precision: str
    formula: str
    note: str = ""
    times: list = field(default_factory=list)
    scale: float = 1.0  # full-frame seconds per timed second (the sampled reference)
    rays: int = 0
    primary: int = 0
    compile_s: float | None = None
    compile_added: bool = False  # compile_s is what this path adds after another one
    max_abs: float = float("nan")
    rmse: float = float("nan")
    differ: float = float("nan")
    speedup: float = float("nan")
    is_path: bool = True  # False for the spheres-only baselines

    @property
    def seconds(self) -> float:
        return statistics.median(self.times) * self.scale

    @property
    def rays_per_s(self) -> float:
        return self.rays / self.seconds

    @property
    def primary_per_s(self) -> float:
        return self.primary / self.seconds

    @property
    def label(self) -> str:
        return "%s %s %s" % (self.backend, self.precision, self.formula)


def fmt_rate(x):
    return "%.2f M" % (x / 1e6) if x >= 1e5 else "%.0f k" % (x / 1e3)


def bench_scene(name, scene_fn, width, height, path_list, runs, measure_compile, log):
    """The rows of one scene, every path timed round-robin."""
    scene = scene_fn()
    counts_cache = {}

    def counts(w, h, precision, formula):
        key = (w, h, precision, formula)
        if key not in counts_cache:
            counts_cache[key] = ray_counts(scene, w, h, precision, formula)
        return counts_cache[key]

    ref_image, step = reference_render(scene, width, height)
    refs = {(width, height): (ref_image, step)}
    rows, runners, cold = [], [], {}
    for path in path_list:
        row = Row(name, width, height, path.backend, path.precision, path.formula_label)
        if measure_compile and path.backend == "numba":
            if path.precision not in cold:
                cold[path.precision] = numba_cold_compile_seconds(name, path.precision, path_list)
            row.compile_s, row.compile_added = cold[path.precision].get(path.label, (None, False))
        elif measure_compile and path.backend == "wgpu":
            try:
                row.compile_s = wgpu_cold_compile_seconds(scene, path)
            except Exception as error:  # the render below says what fails, in the row
                log("  wgpu compile failed: %s" % error)
        if path.backend == "reference":
            row.scale = step * step
            if step > 1:
                row.note = "every %dth row and column, time scaled per pixel" % step

            def run(w=width, h=height):
                return reference_render(scene, w, h)[0]
            image = ref_image
            c = counts(width, height, "float64", "slide")
        else:
            def run(path=path, w=width, h=height):
                return render(scene, w, h, backend=path.backend, precision=path.precision,
                              **path.kwargs())
            try:
                image, seconds = timed(run)  # the warm-up
                if path.backend == "wgpu":
                    image, seconds = timed(run)
                    while seconds > WGPU_MAX_SECONDS and row.width > 64:
                        row.width //= 2
                        row.height //= 2
                        run = (lambda path=path, w=row.width, h=row.height:
                               render(scene, w, h, backend="wgpu", precision="float32",
                                      **path.kwargs()))
                        image, seconds = timed(run)
                    if row.width != width:
                        row.note = ("rendered at %dx%d: %dx%d took over %.0f s per run"
                                    % (row.width, row.height, width, height, WGPU_MAX_SECONDS))
            except Exception as error:  # a path that cannot run here gets a row saying so
                row.note = "not run: %s" % error
                rows.append(row)
                continue
            if path.backend == "wgpu":
                c = counts(row.width, row.height, "float32", path.formula)
                row.note = "; ".join(filter(None, [row.note, "ray counts of numba float32"]))
            else:
                c = counts(width, height, path.precision, path.formula)
        if (row.width, row.height) not in refs:
            refs[(row.width, row.height)] = reference_render(scene, row.width, row.height)
        ref, ref_step = refs[(row.width, row.height)]
        row.max_abs, row.rmse, row.differ = errors(image, ref, row.height, ref_step)
        row.rays, row.primary = c.total, c.primary
        rows.append(row)
        runners.append((row, run))
    if name == BASELINE_SCENE:
        for label, run_baseline in BASELINES.items():
            for precision in ("float64", "float32"):
                row = Row(name, width, height, label, precision, "-", is_path=False)

                def run(run_baseline=run_baseline, precision=precision):
                    return run_baseline(compile_scene(scene_fn(), precision), width, height)
                image = run()
                row.max_abs, row.rmse, row.differ = errors(image, ref_image, height, step)
                c = counts(width, height, precision, None)
                row.rays, row.primary = c.total, c.primary
                rows.append(row)
                runners.append((row, run))
    for row, run in runners:
        if row.backend == "wgpu":
            run()  # measuring the other formula's compile emptied the pipeline cache
    for number in range(runs):
        for row, run in runners:
            row.times.append(timed(run)[1])
        log("  %s: round %d of %d done" % (name, number + 1, runs))
    base = next(r for r in rows if r.backend == "reference")
    for row in rows:
        if row.times:
            row.speedup = (base.seconds / (base.width * base.height)) / (
                row.seconds / (row.width * row.height))
    return rows, counts(width, height, "float64", None)


def row_markdown(r: Row) -> str:
    if not r.times:
        return "| %s | %dx%d | %s | %s | %s | %s |||||||| " % (
            r.scene, r.width, r.height, r.backend, r.precision, r.formula, r.note)
    compile_s = "-" if r.compile_s is None else "%s%.1f s" % ("+" if r.compile_added else "",
                                                               r.compile_s)
    return "| %s | %dx%d | %s | %s | %s | %s | %s | %.0fx | %s | %.2g | %.2g | %.4f %% | %s |" % (
        r.scene, r.width, r.height, r.backend, r.precision, r.formula, fmt_rate(r.rays_per_s),
        fmt_rate(r.primary_per_s), r.speedup, compile_s, r.max_abs, r.rmse, 100 * r.differ,
        r.note)


HEADER = ["| scene | resolution | backend | precision | formula | rays/s | primary/s | speed-up "
          "| compile | max abs | RMSE | 8-bit differ | note |",
          "|---|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---|"]


def robust_cost_markdown(rows) -> list:
    """Whole renders: rays/s of the robust sphere formula against the slide one, per scene
    and path (only when rtfgu.render takes the formula keyword)."""
    by = {(r.scene, r.width, r.backend, r.precision, r.formula): r for r in rows if r.times}
    out = []
    for (scene, width, backend, precision, formula), r in by.items():
        if formula != "robust":
            continue
        slide = by.get((scene, width, backend, precision, "slide"))
        if slide is not None:
            out.append("| %s | %dx%d | %s | %s | %s | %s | %.2f |" % (
                scene, r.width, r.height, backend, precision, fmt_rate(slide.rays_per_s),
                fmt_rate(r.rays_per_s), r.rays_per_s / slide.rays_per_s))
    if not out:
        return []
    return ["### Speed cost of the robust sphere formula in whole renders", "",
            "Median rays/s of the same render with formula=\"slide\" and formula=\"robust\" "
            "(from the table above).", "",
            "| scene | resolution | backend | precision | slide rays/s | robust rays/s "
            "| robust / slide |", "|---|---|---|---|---:|---:|---:|", *out, ""]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(ROOT / "docs" / "bench.md"))
    parser.add_argument("--plot", default=None,
                        help="the PNG (default: bench_speed_error.png next to --out)")
    parser.add_argument("--quick", action="store_true",
                        help="a check that everything runs: small sizes, 1 run, cold compile "
                             "on %s only, 2000 hard-case rays" % QUICK_COMPILE_SCENE)
    parser.add_argument("--no-compile", action="store_true", help="skip the cold compile column")
    parser.add_argument("--no-wgpu", action="store_true", help="skip the wgpu rows")
    args = parser.parse_args(argv)
    out = Path(args.out)
    plot_path = Path(args.plot) if args.plot else out.parent / "bench_speed_error.png"
    runs = 1 if args.quick else RUNS
    started = time.perf_counter()

    def log(message):
        print("[%5.0f s] %s" % (time.perf_counter() - started, message), flush=True)

    import numba
    adapter, no_adapter = (None, "--no-wgpu") if args.no_wgpu else gpu_adapter()
    machine = "%s, %d cores" % (cpu_model(), os.cpu_count())
    load_start = os.getloadavg()
    log("%s; adapter: %s" % (machine, adapter or no_adapter))
    path_list = paths(with_wgpu=adapter is not None)
    if adapter is not None:
        # The driver's one-time start-up (llvmpipe sets up LLVM at the first pipeline) is no
        # scene's compile: pay it before the first measured one.
        render(SCENES["lecture01_flat_colors"](), 8, 8, backend="wgpu")

    all_rows, lines, findings = [], list(HEADER), {}
    for name, scene_fn, width, height in SCENE_TABLE:
        if args.quick:
            width, height = QUICK_SIZE[width], QUICK_SIZE[height]
        # --quick measures the cold compile on the cheapest scene only (about 12 s a path).
        measure_compile = not args.no_compile and (name == QUICK_COMPILE_SCENE or not args.quick)
        log("%s %dx%d" % (name, width, height))
        rows, counts = bench_scene(name, scene_fn, width, height, path_list, runs,
                                   measure_compile, log)
        all_rows += rows
        new = [row_markdown(r) for r in rows]
        new.append("| | | rays per frame (numba float64): %d primary, %d shadow, %d secondary "
                   "||||||||||" % (counts.primary, counts.shadow, counts.secondary))
        lines += new
        print("\n".join(new), flush=True)
        for r in rows:
            if r.times:
                findings.setdefault((r.scene, r.width, r.backend, r.precision), []).append(r)

    checks = []
    for scene, w, what, target, value in (
            ("default_lambertian_shadows", 256, "speed-up over the reference", 300,
             lambda r: r.speedup),
            ("random_spheres_64", 1024, "primary rays/s (M)", 11, lambda r: r.primary_per_s / 1e6)):
        for r in findings.get((scene, w, "numba", "float64"), []):
            v = value(r)
            checks.append("- numba float64 %s on %s %dx%d: %s %.1f (target >= %d): %s"
                          % (r.formula, scene, w, w, what, v, target, "met" if v >= target else "NOT met"))

    hard_rays = 2000 if args.quick else 200_000
    hard_md, hard_points = None, []
    try:
        import hardcases_report
        log("hard cases")
        hard_md = hardcases_report.hardcases_markdown(rays=hard_rays)
        hard_points = hardcases_report.speed_error_points(rays=hard_rays)
    except Exception as error:
        hard_md = "## Hard cases\n\n(The hard-case section failed: %s)\n" % error

    import sampling
    try:
        sampling_md = sampling.sampling_section(out.parent / "bench_sampling.png", args.quick,
                                                not args.no_wgpu, log)
    except Exception as error:
        sampling_md = "%s\n## Sampling\n\n(The sampling section failed: %s)\n%s\n" % (
            sampling.START, error, sampling.END)

    import meshes
    try:
        meshes_md = meshes.meshes_section(out.parent / "bench_meshes.png", args.quick, log)
    except Exception as error:
        meshes_md = "%s\n## Meshes and the BVH\n\n(The mesh section failed: %s)\n%s\n" % (
            meshes.START, error, meshes.END)

    import path_tracing
    try:
        path_tracing_md = path_tracing.path_tracing_section(
            out.parent / "bench_path_tracing.png", args.quick, not args.no_wgpu, log)
    except Exception as error:
        path_tracing_md = ("%s\n## Path tracing: time to an RMSE of 1/255\n\n(The path-tracing "
                           "section failed: %s)\n%s\n" % (path_tracing.START, error,
                                                           path_tracing.END))

    versions = "Python %s, numpy %s, numba %s (%d threads), wgpu %s" % (
        platform.python_version(), np.__version__, numba.__version__, numba.get_num_threads(),
        version("wgpu"))
    title = "%s; GPU adapter: %s" % (machine, adapter or "none")
    plot_note = []
    out.parent.mkdir(parents=True, exist_ok=True)
    try:
        import plot as bench_plot
        bench_plot.speed_error_plot(all_rows, hard_points, title, plot_path)
        plot_note = ["![speed against error](%s)" % os.path.relpath(plot_path, out.parent), "",
                     "Left: one point per scene x path (backend, precision, sphere formula); x is "
                     "the RMSE against the float64 reference image before gamma (an exact match "
                     "is drawn at the floor marked \"exact\"), y is rays/s. Right: the hard-case "
                     "batch evaluators, wrong hit/miss decisions over all families against rays/s.",
                     ""]
        log("wrote %s" % plot_path)
    except Exception as error:  # no matplotlib: the table still gets written
        plot_note = ["(No plot: %s. `make bench` installs matplotlib.)" % error, ""]
    load_end = os.getloadavg()
    text = "\n".join([
        "# Benchmark",
        "",
        "Generated by `make bench` (benchmarks/bench.py%s); never edited by hand." % (
            " --quick" if args.quick else ""),
        "",
        "- Machine: %s; load average %s at the start, %s at the end." % (
            machine, "%.2f" % load_start[0], "%.2f" % load_end[0]),
        "- %s." % versions,
        "- GPU adapter: %s." % (adapter or "none (%s)" % no_adapter),
        "- Timing: a warm-up render per path, then %d round(s) that time every path of a scene "
        "once each (round-robin); medians quoted. Whole run: %.0f s." % (
            runs, time.perf_counter() - started),
        "- rays/s counts primary, shadow and secondary rays with the numba kernel's counters; "
        "the wgpu rows use the counts of numba float32 with the same formula on the same scene "
        "and size (the shader does not count). Columns are explained in benchmarks/bench.py.",
        "- formula: the sphere intersection, the slides' quadratic (\"slide\") or Ray Tracing "
        "Gems ch. 7 (\"robust\"); the reference has the slide formula only.",
        "",
        *plot_note,
        *lines,
        "",
        *robust_cost_markdown(all_rows),
        "Targets of the numba path (rays/s it must reach on these scenes):",
        "",
        *(checks or ["- not measured at these sizes (--quick)"]),
        "",
        hard_md or "",
        "",
        sampling_md,
        meshes_md,
        path_tracing_md,
    ])
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(text)
    print("\n".join(checks))
    log("wrote %s" % out)


if __name__ == "__main__":
    main()
