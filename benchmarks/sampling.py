"""The sampling section of docs/bench.md: for each of Suffern's samplers on each fast path,
the RMSE against a 4096-spp image as a function of render time, and which sampler reaches
an RMSE of 1/255 first. Writes the plot docs/bench_sampling.png.

``benchmarks/bench.py`` puts ``sampling_section()`` into docs/bench.md; run alone,

    python benchmarks/sampling.py [--quick] [--no-wgpu]

measures this section only and replaces it in docs/bench.md (the text between START and END;
appended when the file has none). A script, not a test: nothing is asserted.

Measured: every sampler x path x spp in SPP. The images are rendered once first (that render
gives the RMSE and leaves every kernel and shader compiled, so compile time is not in the
figures), then RUNS rounds time each of them (round-robin, so a change in the machine's load
hits all alike); the median of the rounds is quoted. In a round, a render shorter than
MIN_SECONDS is repeated until MIN_SECONDS have passed and the mean counts. A time is the wall
time of rtfgu.render with the sampler already built: the sample sets are made once per
sampler by the lecture layer (pure Python) and are not counted.

A sample costs the same with every sampler, so the samplers are ranked by the samples per
pixel at which their RMSE reaches 1/255 (the same on every path); each path's time to get
there is reported next to it.

Error: RMSE over every pixel and channel of the linear radiance before gamma (what
rtfgu.render returns, unclamped), against REFERENCE_SPP samples per pixel of numba float64
(equal to the lecture layer within 1e-9) with Jittered. 1/255 is therefore one step of an
8-bit encoding of the linear value, not of the gamma-corrected PNG. The reference's own noise
is estimated by a second REFERENCE_SPP image with MultiJittered and other seeds.
"""
from __future__ import annotations

import argparse
import math
import os
import statistics
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(HERE))

import rtfgu  # noqa: E402
from rtfgu.scenes import SCENES  # noqa: E402
from rtfgu.scenes.sampling import star  # noqa: E402

from bench import cpu_model, gpu_adapter, replace_section  # noqa: E402

START = "<!-- sampling section: benchmarks/sampling.py -->"
END = "<!-- end of sampling section -->"

SAMPLERS = (rtfgu.Regular, rtfgu.Jittered, rtfgu.NRooks, rtfgu.MultiJittered, rtfgu.Hammersley)
SPP = (1, 4, 16, 64, 256)  # squares: Regular, Jittered and MultiJittered need them
REFERENCE_SPP = 4096
THRESHOLD = 1 / 255
TIE = 1.05  # samplers needing at most 5 % more samples than the first share the first place
RUNS = 5
MIN_SECONDS = 0.05
SIZE, QUICK_SIZE = 128, 32
PATHS = (("numba", "float64"), ("numba", "float32"), ("wgpu", "float32"))
PATH_STYLE = {"numba float64": ("-", "o"), "numba float32": ("--", "s"),
              "wgpu float32": (":", "^")}


def default_scene(sampler):
    """Worksheet 3's anti-aliasing scene (default_antialiasing_*) with ``sampler``."""
    scene = SCENES["default_antialiasing_1"]()
    scene.sampler = sampler
    return scene


# (name, a function of the sampler giving the scene, what it is)
SCENE_TABLE = [
    ("star", star, "Suffern's 48-wedge star (`rtfgu.scenes.sampling.star`, as in the "
                   "`suffern_samplers_*` scenes)"),
    ("default scene", default_scene, "the 02562 default scene with shadows (as in the "
                                     "`default_antialiasing_*` scenes)"),
]


def rmse(image, ref) -> float:
    return float(np.sqrt(np.mean((image - ref) ** 2)))


def crossing(points):
    """(seconds, spp) where the RMSE first falls to THRESHOLD, interpolated in log-log
    between the measured points [(spp, seconds, rmse)] in order of spp; None if it does not."""
    spp, seconds, error = points[0]
    if error <= THRESHOLD:
        return seconds, spp
    for (s0, t0, e0), (s1, t1, e1) in zip(points, points[1:]):
        if e0 > THRESHOLD >= e1:
            f = math.log(THRESHOLD / e0) / math.log(e1 / e0)
            return t0 * (t1 / t0) ** f, s0 * (s1 / s0) ** f
    return None


def mean_seconds(run) -> float:
    """The mean time of ``run()``, repeated until MIN_SECONDS have passed."""
    count, start = 0, time.perf_counter()
    while True:
        run()
        count += 1
        elapsed = time.perf_counter() - start
        if elapsed >= MIN_SECONDS:
            return elapsed / count


def measure(scene_fn, size, paths, runs, log):
    """{(sampler name, path label): [(spp, median seconds, rmse)]}, the RMSE between the two
    reference images, and a note per path that cannot render the scene here."""
    def reference(sampler, seed):
        return rtfgu.render(scene_fn(sampler), size, size, backend="numba",
                            precision="float64", seed=seed)
    ref = reference(rtfgu.Jittered(REFERENCE_SPP, seed=1), seed=1)
    ref_noise = rmse(reference(rtfgu.MultiJittered(REFERENCE_SPP, seed=2), seed=2), ref)
    log("  references done; they differ by RMSE %.2g" % ref_noise)

    failed = {}
    for backend, precision in paths:
        try:
            rtfgu.render(scene_fn(rtfgu.Jittered(4)), 8, 8, backend=backend, precision=precision)
        except Exception as error:  # the section says which path did not run, and why
            failed["%s %s" % (backend, precision)] = str(error).splitlines()[0]
    paths = [p for p in paths if "%s %s" % p not in failed]
    cases = []  # (sampler name, path label, spp, run)
    for cls in SAMPLERS:
        for spp in SPP:
            scene = scene_fn(cls(spp))  # the sets are made here, outside the timing
            for backend, precision in paths:
                def run(scene=scene, backend=backend, precision=precision):
                    return rtfgu.render(scene, size, size, backend=backend, precision=precision)
                cases.append((cls.__name__, "%s %s" % (backend, precision), spp, run))
    errors = {(name, label, spp): rmse(run(), ref) for name, label, spp, run in cases}
    times = {key: [] for key in errors}
    for number in range(runs):
        for name, label, spp, run in cases:
            times[(name, label, spp)].append(mean_seconds(run))
        log("  round %d of %d done" % (number + 1, runs))
    curves = {}
    for (name, label, spp), error in errors.items():
        curves.setdefault((name, label), []).append(
            (spp, statistics.median(times[(name, label, spp)]), error))
    return curves, ref_noise, failed


def plot(results, size, title, path):
    import matplotlib
    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(results), figsize=(6.5 * len(results), 5.6), sharey=True,
                             squeeze=False)
    colour = {cls.__name__: plt.get_cmap("tab10")(i) for i, cls in enumerate(SAMPLERS)}
    for ax, (scene, (curves, ref_noise, _)) in zip(axes[0], results.items()):
        for (name, label), points in curves.items():
            linestyle, marker = PATH_STYLE[label]
            ax.plot([t for _, t, _ in points], [e for _, _, e in points], linestyle=linestyle,
                    marker=marker, markersize=4, color=colour[name], label="%s, %s" % (name, label))
        ax.axhline(THRESHOLD, color="black", linewidth=0.8)
        ax.annotate("1/255", (0.01, THRESHOLD), xycoords=("axes fraction", "data"),
                    xytext=(0, 3), textcoords="offset points", fontsize=8)
        ax.axhline(ref_noise, color="0.6", linewidth=0.8, linestyle="--")
        ax.annotate("the two %d-spp references differ by this" % REFERENCE_SPP,
                    (0.01, ref_noise), xycoords=("axes fraction", "data"), xytext=(0, 3),
                    textcoords="offset points", fontsize=7, color="0.4")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("render time, s (median; %dx%d; spp %s)"
                      % (size, size, ", ".join(map(str, SPP))))
        ax.set_title(scene, fontsize=10)
        ax.grid(True, which="major", alpha=0.3)
    axes[0][0].set_ylabel("RMSE against %d spp (linear radiance, before gamma)" % REFERENCE_SPP)
    handles = [plt.Line2D([], [], color=c, label=n) for n, c in colour.items()]
    handles += [plt.Line2D([], [], color="black", linestyle=ls, marker=m, markersize=4, label=p)
                for p, (ls, m) in PATH_STYLE.items()]
    fig.legend(handles=handles, loc="lower center", ncol=len(handles), fontsize=8,
               frameon=False, bbox_to_anchor=(0.5, -0.04))
    fig.suptitle("rtfgu samplers: error against render time on %s" % title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)


def fmt_seconds(s: float) -> str:
    return "%.3g s" % s


def fmt_spp(spp: float) -> str:
    return "%.1f" % spp if spp < 10 else "%.0f" % spp


def findings(scene, curves, labels):
    """Which sampler reaches THRESHOLD with the fewest samples per pixel (ranked on the first
    path; the others after it), and the time each path takes with it."""
    if not labels:
        return []
    hits = {name: crossing(points) for (name, label), points in curves.items()
            if label == labels[0]}
    reached = sorted((hit[1], name) for name, hit in hits.items() if hit is not None)
    if not reached:
        return ["- %s: no sampler reaches 1/255 up to %d spp." % (scene, SPP[-1])]
    spp, first = reached[0]
    tied = [(s, name) for s, name in reached[1:] if s <= spp * TIE]
    others = ["%s %s spp" % (name, fmt_spp(s)) for s, name in reached[1 + len(tied):]]
    others += ["%s not up to %d spp" % (name, SPP[-1]) for name, hit in hits.items() if hit is None]
    times = []
    for label in labels:
        hit = crossing(curves[(first, label)])
        times.append("%s **%s**" % (label, "not reached" if hit is None else fmt_seconds(hit[0])))
    ties = "".join(", tied with **%s** at %s spp (within %.0f %%)" % (name, fmt_spp(s),
                                                                    100 * (TIE - 1))
                   for s, name in tied)
    then = "; then %s" % ", ".join(others) if others else ""
    return ["- %s: **%s** reaches 1/255 first, at about %s spp%s%s. Time to get there with %s: "
            "%s." % (scene, first, fmt_spp(spp), ties, then, first, ", ".join(times))]


def table_order(item):
    """Rows by path, then samplers in the order of SAMPLERS."""
    (name, label), _ = item
    return ["%s %s" % p for p in PATHS].index(label), [c.__name__ for c in SAMPLERS].index(name)


def table(results):
    head = ["| scene | path | sampler | %s | reaches 1/255 |" % " | ".join(
                "%d spp: RMSE (time)" % s for s in SPP),
            "|---|---|---|%s---:|" % ("---:|" * len(SPP))]
    rows = []
    for scene, (curves, _, _) in results.items():
        for (name, label), points in sorted(curves.items(), key=table_order):
            hit = crossing(points)
            cells = ["%.2g (%s)" % (e, fmt_seconds(t)) for _, t, e in points]
            rows.append("| %s | %s | %s | %s | %s |" % (
                scene, label, name, " | ".join(cells),
                "no" if hit is None else "%s, %s spp" % (fmt_seconds(hit[0]), fmt_spp(hit[1]))))
    return head + rows


def sampling_section(plot_path, quick=False, with_wgpu=True, log=print) -> str:
    """Measure, write the plot at ``plot_path``, and return the markdown section (from START
    to END) for a file in ``plot_path``'s folder."""
    import numba
    started = time.perf_counter()
    load_start = os.getloadavg()
    size, runs = (QUICK_SIZE, 1) if quick else (SIZE, RUNS)
    adapter, no_adapter = gpu_adapter() if with_wgpu else (None, "--no-wgpu")
    paths = [p for p in PATHS if p[0] != "wgpu" or adapter is not None]
    labels = ["%s %s" % p for p in paths]
    results = {}
    for scene, scene_fn, _ in SCENE_TABLE:
        log("sampling: %s %dx%d" % (scene, size, size))
        results[scene] = measure(scene_fn, size, paths, runs, log)
    load_end = os.getloadavg()
    machine = "%s, %d cores, numba %d threads; GPU adapter: %s" % (
        cpu_model(), os.cpu_count(), numba.get_num_threads(), adapter or "none (%s)" % no_adapter)
    plot_path = Path(plot_path)
    try:
        plot(results, size, machine, plot_path)
        figure = ["![RMSE against render time per sampler and path](%s)" % plot_path.name, ""]
    except ImportError as error:  # no matplotlib: the table still gets written
        figure = ["(No plot: %s. `make bench` installs matplotlib.)" % error, ""]
    lines = [
        START,
        "## Sampling: error against render time",
        "",
        "Generated by benchmarks/sampling.py%s (also part of `make bench`); never edited by hand."
        % (" --quick" if quick else ""),
        "",
        "- Scenes at %dx%d: %s; each with every sampler at %s samples per pixel (seed 0)." % (
            size, size, " and ".join(about for _, _, about in SCENE_TABLE),
            ", ".join(map(str, SPP))),
        "- Error: RMSE over all pixels and channels of the linear radiance before gamma "
        "(unclamped), against %d spp of numba float64 (equal to the lecture layer within "
        "1e-9) with Jittered(%d), sampler and render seed 1. The threshold 1/255 is in the "
        "same linear units. RMSE weighs Regular's moiré and the other samplers' noise alike. The "
        "reference's own noise: a second %d-spp image (MultiJittered, sampler and render "
        "seed 2) differs from it by RMSE %s." % (
            REFERENCE_SPP, REFERENCE_SPP, REFERENCE_SPP,
            " and ".join("%.2g (%s)" % (noise, scene) for scene, (_, noise, _) in results.items())),
        "- Time: wall time of `rtfgu.render`, median of %d round(s), each timing every "
        "sampler x path x spp (round-robin; a render under %.2g s is repeated for %.2g s and "
        "its mean counts). Compile is excluded (every image is rendered once before the "
        "rounds; the compile times are in the first table), and so is making the sample sets "
        "(the lecture layer's sampler, built once). The samples and the time at 1/255 are "
        "interpolated in log-log between the two measured points around it." % (
            runs, MIN_SECONDS, MIN_SECONDS),
        "- Machine: %s; load average %.2f at the start, %.2f at the end; %.0f s in all."
        % (machine, load_start[0], load_end[0], time.perf_counter() - started),
        "",
        *figure,
        "Which sampler reaches an RMSE of 1/255 first, and how long each path takes to get "
        "there. A sample costs the same with every sampler (the table), so the samplers are "
        "ranked by the samples per pixel they need, which is the same on every path:",
        "",
    ]
    for scene, (curves, _, failed) in results.items():
        lines += findings(scene, curves, [label for label in labels if label not in failed])
        lines += ["- %s, %s: not run: %s" % (scene, label, why) for label, why in failed.items()]
    lines += ["", *table(results), "", END]
    return "\n".join(lines) + "\n"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(ROOT / "docs" / "bench.md"))
    parser.add_argument("--quick", action="store_true", help="%dx%d, 1 run" % (QUICK_SIZE,
                                                                              QUICK_SIZE))
    parser.add_argument("--no-wgpu", action="store_true", help="skip the wgpu path")
    args = parser.parse_args(argv)
    out = Path(args.out)
    started = time.perf_counter()

    def log(message):
        print("[%5.0f s] %s" % (time.perf_counter() - started, message), flush=True)

    section = sampling_section(out.parent / "bench_sampling.png", args.quick,
                               not args.no_wgpu, log)
    print(section)
    out.write_text(replace_section(out.read_text() if out.exists() else "", section, START, END))
    log("wrote %s" % out)


if __name__ == "__main__":
    main()
