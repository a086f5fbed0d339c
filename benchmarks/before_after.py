"""Speed and error of two versions of rtfgu in one run, on the same machine: the checked-out
tree ("after") and an earlier commit ("before", checked out into a temporary git worktree).

Every configuration (scene, size, backend, precision, formula) is timed in a fresh process
per version, the two versions alternating round by round so that a change in the machine's
load hits both; a process renders once to compile (or load numba's cache), then takes REPS
samples of as many renders as fill SAMPLE_SECONDS, and reports the median time per render. The table gives the median over rounds of each version, their
ratio, and each image's largest difference from the lecture layer's float64 image (on every
4th row and column for the 1024 x 1024 scene), so no speed figure stands without its error.

    python benchmarks/before_after.py --before REV [--suite registry|book|lecture] [--rounds 3] [--out FILE]

``--suite registry`` (the default) times the numba and WGSL paths on CONFIGS; ``--suite book``
times the lecture layer itself (the reference backend, small images) and the flat paths on
the scenes whose materials, lights and tracer the book's classes express (BOOK_CONFIGS);
``--suite lecture`` the reference rows of that suite alone (teapot left out), for more rounds.
"""
from __future__ import annotations

import argparse
import json
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
CONFIGS = [
    ("default_lambertian_shadows", 256, 256),
    ("default_glossy_sphere", 256, 256),
    ("lecture01_flat_colors", 256, 256),
    ("random_spheres_64", 1024, 1024),
]
PATHS = [("numba", "float64", "slide"), ("numba", "float64", "robust"),
         ("numba", "float32", "slide"), ("numba", "float32", "robust"),
         ("wgpu", "float32", "slide"), ("wgpu", "float32", "robust")]
REPS = 5
SAMPLE_SECONDS = 0.25
REFERENCE = [("reference", "float64", "slide")]
FLAT = [("numba", "float64", "slide"), ("numba", "float32", "slide"), ("wgpu", "float32", "robust")]
BOOK_CONFIGS = [
    (("default_lambertian_shadows", 48, 48), REFERENCE), (("default_glossy_sphere", 48, 48), REFERENCE),
    (("default_mirror_sphere", 48, 48), REFERENCE), (("suffern_disks", 48, 48), REFERENCE),
    (("lecture01_flat_colors", 64, 64), REFERENCE), (("teapot", 40, 24), REFERENCE),
    (("default_lambertian_shadows", 256, 256), FLAT), (("default_glossy_sphere", 256, 256), FLAT),
    (("suffern_disks", 256, 256), FLAT), (("teapot", 400, 225), FLAT), (("cornell_box_blocks", 256, 256), FLAT),
]
SUITES = {"registry": [(config, PATHS) for config in CONFIGS], "book": BOOK_CONFIGS,
          # The lecture layer alone, small enough for more rounds (and, with --before HEAD, for
          # the spread between two runs of one version: the noise the other tables sit in).
          "lecture": [(config, paths) for config, paths in BOOK_CONFIGS if paths is REFERENCE and config[0] != "teapot"]}


def _scene(name):
    sys.path.insert(0, str(ROOT / "benchmarks"))
    if name == "random_spheres_64":
        from scenes import random_spheres_64
        return random_spheres_64()
    from rtfgu.scenes import SCENES
    return SCENES[name]()


def worker(args) -> None:
    import rtfgu

    scene = _scene(args.scene)
    kwargs = dict(backend=args.backend, precision=args.precision, formula=args.formula)
    start = time.perf_counter()
    image = rtfgu.render(scene, args.width, args.height, **kwargs)  # compile or load the cache
    start = time.perf_counter()
    image = rtfgu.render(scene, args.width, args.height, **kwargs)
    # A sample is as many renders as fill SAMPLE_SECONDS, so that a 3 ms render is not timed
    # alone against the scheduler's granularity.
    batch = max(1, int(SAMPLE_SECONDS / max(time.perf_counter() - start, 1e-6)))
    times = []
    for _ in range(REPS):
        start = time.perf_counter()
        for _ in range(batch):
            image = rtfgu.render(scene, args.width, args.height, **kwargs)
        times.append((time.perf_counter() - start) / batch)
    np.save(args.image, image)
    print(json.dumps({"seconds": statistics.median(times), "rtfgu": rtfgu.__file__}))


def reference(name, width, height) -> tuple:
    """The lecture layer's image, on every 4th row and column above 256 x 256: (image, step)."""
    import rtfgu

    step = 4 if width > 256 else 1
    scene = _scene(name)
    full = np.zeros((height, width, 3))
    for row in range(0, height, step):
        # One row of the image at a time: rows are independent, the camera is the same.
        for col in range(0, width, step):
            sx = 2 * (col + 0.5) / width - 1
            sy = 2 * ((height - 1 - row) + 0.5) / height - 1
            color = rtfgu.trace(scene, scene.camera.gen_ray(sx, sy))
            full[row, col] = (color.x, color.y, color.z)
    return full, step


def run_worker(tree: Path, config, path, image: Path) -> dict:
    name, width, height = config
    backend, precision, formula = path
    env = dict(os.environ, PYTHONPATH=str(tree), RTFGU_CACHE_DIR=str(image.parent / ("cache-" + tree.name)))
    command = [sys.executable, __file__, "--worker", "--scene", name, "--width", str(width),
               "--height", str(height), "--backend", backend, "--precision", precision,
               "--formula", formula, "--image", str(image)]
    done = subprocess.run(command, env=env, cwd=str(image.parent), capture_output=True, text=True)
    if done.returncode != 0:
        return {"error": (done.stderr.strip().splitlines() or ["failed"])[-1]}
    result = json.loads(done.stdout.strip().splitlines()[-1])
    if not result["rtfgu"].startswith(str(tree)):
        raise RuntimeError("the worker imported rtfgu from %s, not from %s" % (result["rtfgu"], tree))
    return result


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", help="the earlier commit (a git revision)")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--suite", default="registry", choices=sorted(SUITES))
    parser.add_argument("--out", default=None, help="write the markdown table here")
    parser.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    for name in ("scene", "backend", "precision", "formula", "image"):
        parser.add_argument("--" + name, help=argparse.SUPPRESS)
    parser.add_argument("--width", type=int, help=argparse.SUPPRESS)
    parser.add_argument("--height", type=int, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.worker:
        worker(args)
        return 0
    if not args.before:
        parser.error("--before REV is required")
    start = time.time()
    load = [os.getloadavg()[0]]
    with tempfile.TemporaryDirectory(prefix="rtfgu-before-after-") as tmp:
        tmp = Path(tmp)
        before = tmp / "before"
        subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", str(before), args.before],
                       check=True, capture_output=True)
        trees = {"before": before, "after": ROOT}
        try:
            rows = []
            for config, paths in SUITES[args.suite]:
                ref, step = reference(*config)
                for path in paths:
                    seconds = {"before": [], "after": []}
                    errors = {}
                    for _ in range(args.rounds):
                        for version, tree in trees.items():
                            image_path = tmp / ("%s.npy" % version)
                            result = run_worker(tree, config, path, image_path)
                            if "error" in result:
                                errors[version] = result["error"]
                                continue
                            seconds[version].append(result["seconds"])
                            image = np.load(image_path)
                            errors[version] = float(np.abs(image[::step, ::step] - ref[::step, ::step]).max())
                    rows.append((config, path, seconds, errors))
                    print(format_row(config, path, seconds, errors), flush=True)
        finally:
            subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(before)],
                           capture_output=True)
    load.append(os.getloadavg()[0])
    text = report(args.before, args.suite, args.out, rows, load, time.time() - start, args.rounds)
    if args.out:
        Path(args.out).write_text(text)
    print(text)
    return 0


def _rate(config, seconds):
    _, width, height = config
    if not seconds:
        return "-"
    rate = width * height / statistics.median(seconds)
    return "%.2f M" % (rate / 1e6) if rate >= 1e5 else "%.2f k" % (rate / 1e3)


def format_row(config, path, seconds, errors) -> str:
    name, width, height = config
    backend, precision, formula = path
    ratio = "-"
    if seconds["before"] and seconds["after"]:
        ratio = "%.2f" % (statistics.median(seconds["before"]) / statistics.median(seconds["after"]))

    def err(version):
        e = errors.get(version)
        return e if isinstance(e, str) else ("%.2g" % e if e is not None else "-")
    return "| %s | %dx%d | %s | %s | %s | %s | %s | %s | %s | %s |" % (
        name, width, height, backend, precision, formula, _rate(config, seconds["before"]),
        _rate(config, seconds["after"]), ratio, err("before"), err("after"))


TITLES = {"registry": "the kind registry", "book": "the lecture layer in Suffern's classes",
          "lecture": "the lecture layer in Suffern's classes: the reference backend"}


def report(before, suite, out, rows, load, seconds, rounds) -> str:
    lines = [
        "# Speed before and after %s" % TITLES[suite],
        "",
        "Generated by `python benchmarks/before_after.py --before %s --suite %s --rounds %d --out %s`; "
        "never edited by hand." % (before, suite, rounds, out),
        "",
        "- Machine: %s, %d cores; load average %.2f at the start, %.2f at the end; whole run %.0f s."
        % (platform.processor() or platform.machine(), os.cpu_count(), load[0], load[1], seconds),
        "- before: commit `%s`; after: this tree. Each cell: median over %d rounds of the median of "
        "%d samples (each about %.2f s of renders) in a fresh process, the versions alternating."
        % (before, rounds, REPS, SAMPLE_SECONDS),
        "- primary rays/s (pixels per second); speed-up = before time / after time (above 1: "
        "after is faster). max abs: the largest difference from the lecture layer's float64 image "
        "before gamma (every 4th row and column at 1024 x 1024).",
        "",
        "| scene | resolution | backend | precision | formula | before primary/s | after primary/s "
        "| speed-up | max abs before | max abs after |",
        "|---|---|---|---|---|---:|---:|---:|---:|---:|",
    ]
    lines += [format_row(*row) for row in rows]
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.exit(main())
