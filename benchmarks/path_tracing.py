"""The path-tracing section of docs/bench.md: the time each renderer takes to bring the
Cornell box with its blocks to an RMSE of 1/255 against a Mitsuba 3 reference, for rtfgu's
path tracer (numba float32 and float64, WGSL) and Mitsuba 3's ``path`` integrator, in one
run. Writes the plot docs/bench_path_tracing.png.

``benchmarks/bench.py`` puts ``path_tracing_section()`` into docs/bench.md; run alone,

    python benchmarks/path_tracing.py [--quick] [--no-wgpu] [--no-scalar] [--libllvm PATH]

measures this section only and replaces it in docs/bench.md (the text between START and END;
appended when the file has none). A script, not a test: nothing is asserted, and a peer that
cannot run is named in the section with the reason instead of a figure.

Scene: the Cornell box with its blocks, every face a path-traced Matte (kd 1: the albedo is
its colour; rtfgu.scenes.meshes.cornell_box_area_light()'s box), lit by its ceiling quad (one
Rectangle and its AreaLight: cornell_reference.ceiling_lamp) with ``scene.tracer =
PathTrace()`` (max_depth 64, Russian roulette), the scene of benchmarks/cornell_reference.py;
Mitsuba gets it through benchmarks/mitsuba_scene.py (``path`` integrator, max_depth -1:
unbounded, Russian roulette from depth 5).

Reference: tests/data/cornell_mitsuba.npz, SIZE x SIZE, Mitsuba 3 at 65,536 samples per
pixel (seeds 0..63, one per pass). Its own error is the root mean square of its per-pixel
standard error, printed in the section; a render's squared RMSE against it is the render's
own mean squared error plus that square (the two are independent), so it is a floor that
no render goes below.

Peers (``Peer``), every one rendering the same SIZE x SIZE image:
  rtfgu numba float32 / float64   rtfgu.render(scene, SIZE, SIZE, backend="numba", ...,
                                  spp=N, seed=S) in this process.
  rtfgu wgpu float32              the same with backend="wgpu" (Mesa's llvmpipe here).
  Mitsuba 3                       mi.render(scene, spp=N, seed=S) in a worker process
                                  (``python benchmarks/path_tracing.py --worker ...``, line
                                  protocol on stdin/stdout), with the ``independent`` sampler
                                  of mitsuba_scene.to_mitsuba and, as a second row, the
                                  ``stratified`` one. ``llvm_ad_rgb`` when its path tracing
                                  kernel runs: the worker is started with Dr.Jit's own choice
                                  of libLLVM, then with each libLLVM given by --libllvm or
                                  found on the machine (libllvm_candidates), newest first,
                                  until a probe render works (Debian 12's libLLVM 15 aborts
                                  the process: LLVM "Cannot select: fminimum"). ``scalar_rgb``
                                  always runs too (--no-scalar skips it where LLVM works).
                                  In llvm_ad_rgb a render of more than LLVM_CHUNK_SPP samples
                                  per pixel is the mean of renders of LLVM_CHUNK_SPP (one
                                  wavefront of SIZE^2 x spp lanes would not fit in memory).
Pixel sampling differs: rtfgu.renderer.pixel_sampler gives rtfgu Jittered(N) (stratified
pixel positions) for a square N, and every N of LEVELS is a square; Mitsuba's
``independent`` sampler draws every dimension at random, its ``stratified`` sampler
stratifies every dimension's 1D and 2D draws.

Measurement: samples per pixel climb LEVELS (x4 each). At each level every active peer
renders once per round, RUNS rounds (round-robin, so a change in the machine's load hits
every peer alike), each render with its own seed (SEED + 16 level + round; Mitsuba's
reference used 0..63); a peer whose first render at the level took more than LONG_SECONDS
renders it once only. Before the first level each peer renders once (the warm-up: numba,
WGSL and Dr.Jit compile then). Time: the median of the renders' wall times (rtfgu: the
rtfgu.render call, which flattens the scene too; Mitsuba: mi.render and the copy to numpy,
the scene loaded once before). RMSE: over all pixels and channels of the linear radiance,
sqrt of the mean of the renders' mean squared errors. A peer stops climbing once its RMSE
is <= TARGET, or when the next level (4 times the samples) would take more than
MAX_RENDER_SECONDS.

Time to TARGET: log-log interpolation of (time, RMSE) between the last point above and the
first point at or below it; the spp at that point is interpolated alike (log spp against
log RMSE); samples/s = that spp x SIZE^2 / that time. A peer that never reached it gets an
estimate from its last point: MSE = c / N + reference MSE, time proportional to N.
Bias check: the RMSE at the largest spp against its noise-only prediction from the point
before it, ((MSE_prev - ref MSE) N_prev / N + ref MSE)^(1/2): a bias against the reference
would make the measured RMSE stop falling and exceed the prediction.
"""
from __future__ import annotations

import argparse
import copy
import glob
import json
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from importlib import metadata
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(HERE))

START = "<!-- path tracing section: benchmarks/path_tracing.py -->"
END = "<!-- end of path tracing section -->"

REFERENCE = ROOT / "tests" / "data" / "cornell_mitsuba.npz"
SIZE = 64
TARGET = 1.0 / 255.0
LEVELS = [4 ** k for k in range(8)]            # 1 .. 16384 samples per pixel
QUICK_LEVELS = [1, 4, 16, 64]
RUNS = 3
LONG_SECONDS = 10.0
WARMUP_MAX_SPP = 64
MAX_RENDER_SECONDS = 60.0
SEED = 1000
LLVM_CHUNK_SPP = 4096
# libLLVM shared libraries tried after Dr.Jit's own choice, newest major version first.
LIBLLVM_PATTERNS = ("/usr/lib/llvm-*/lib/libLLVM*.so*", "/usr/lib/*/libLLVM*.so*",
                    "/usr/lib/libLLVM*.so*", "/usr/local/lib/libLLVM*.so*",
                    "/usr/local/opt/llvm/lib/libLLVM*.dylib", "/opt/homebrew/opt/llvm/lib/libLLVM*.dylib",
                    "~/.rustup/toolchains/*/lib/libLLVM*.so*")
MAX_LIBLLVM_TRIES = 3
MESSAGE = "@@path_tracing "   # the worker's protocol lines on stdout start with this


def version(package: str) -> str:
    try:
        return metadata.version(package)
    except metadata.PackageNotFoundError:
        return "not installed"


def cornell_scene():
    """The scene of the reference (benchmarks/cornell_reference.py), path traced."""
    from cornell_reference import cornell_scene as reference_scene
    from rtfgu import PathTrace
    scene = reference_scene()
    scene.tracer = PathTrace()
    return scene


def load_reference(path: Path = REFERENCE):
    """(mean, rms of its per-pixel standard error, description)."""
    data = np.load(path)
    mean = data["mean"].astype(np.float64)
    if mean.shape != (SIZE, SIZE, 3):
        raise ValueError("%s: the reference is %s, not %dx%d" % (path, mean.shape, SIZE, SIZE))
    rms_stderr = float(np.sqrt(np.mean(data["stderr"].astype(np.float64) ** 2)))
    about = "Mitsuba %s %s, `path` max_depth %d, %d spp in %d passes (seeds 0..%d)" % (
        data["mitsuba_version"], data["variant"], int(data["max_depth"]), int(data["spp"]),
        int(data["passes"]), int(data["passes"]) - 1)
    return mean, rms_stderr, about


# ---- the Mitsuba worker (a separate process: a libLLVM of its own, and an abort of the
# ---- LLVM backend kills the worker, not the bench) ----------------------------------------

def send(message: dict) -> None:
    sys.stdout.write(MESSAGE + json.dumps(message) + "\n")
    sys.stdout.flush()


def worker_main(variant: str, sampler: str) -> int:
    """Load the scene in ``variant`` with ``sampler``, say so, then answer every line
    {"spp", "seed", "out"} of stdin: render, save the mean image (float64 .npy) to out,
    reply {"seconds"}."""
    from mitsuba_scene import _mitsuba, to_mitsuba
    mi = _mitsuba(variant)
    import drjit as dr
    llvm = variant.startswith("llvm")
    scene_dict = to_mitsuba(cornell_scene(), SIZE, SIZE, 1, seed=SEED)
    scene_dict["sensor"]["sampler"]["type"] = sampler
    mscene = mi.load_dict(scene_dict)
    libllvm = ""
    if llvm:
        libllvm = "libLLVM %s" % ".".join(map(str, dr.detail.llvm_version()))
    send({"variant": mi.variant(), "threads": dr.thread_count() if llvm else os.cpu_count(),
          "libllvm": libllvm})
    for line in sys.stdin:
        if not line.strip():
            continue
        command = json.loads(line)
        spp, seed = int(command["spp"]), int(command["seed"])
        chunks = max(1, -(-spp // LLVM_CHUNK_SPP)) if llvm else 1
        start = time.perf_counter()
        image = None
        for k in range(chunks):
            part = np.array(mi.render(mscene, spp=spp // chunks, seed=seed + 100_000 * k),
                            dtype=np.float64)
            image = part if image is None else image + part
        image /= chunks
        seconds = time.perf_counter() - start
        np.save(command["out"], image)
        send({"seconds": seconds, "chunks": chunks})
    return 0


class WorkerDied(RuntimeError):
    pass


def abort_reason(stderr_text: str) -> str:
    """The line of a worker's stderr that says why it stopped."""
    for pattern in (r"(LLVM ERROR: .*)", r"(Cannot select: .*)", r"(\w*Error: .*)"):
        found = re.findall(pattern, stderr_text)
        if found:
            return re.sub(r" ?0x[0-9a-f]+:?,?", "", found[-1]).strip()[:160]
    lines = [x.strip() for x in stderr_text.splitlines() if x.strip()]
    return lines[-1][:160] if lines else "no message"


class Worker:
    """A Mitsuba worker process; ``render(spp, seed)`` -> (image, seconds)."""

    def __init__(self, variant: str, sampler: str, libllvm: str | None = None):
        env = dict(os.environ)
        if libllvm is not None:
            env["DRJIT_LIBLLVM_PATH"] = libllvm
        self.dir = tempfile.TemporaryDirectory(prefix="rtfgu_path_bench_")
        self.stderr = open(os.path.join(self.dir.name, "stderr.txt"), "w+")
        self.process = subprocess.Popen(
            [sys.executable, str(Path(__file__).resolve()), "--worker", variant, sampler],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=self.stderr, text=True, env=env)
        self.info = self._receive()

    def _receive(self) -> dict:
        while True:
            line = self.process.stdout.readline()
            if not line:
                self.process.wait()
                self.stderr.seek(0)
                raise WorkerDied("the Mitsuba worker exited (%s): %s" % (
                    self.process.returncode, abort_reason(self.stderr.read())))
            if line.startswith(MESSAGE):
                return json.loads(line[len(MESSAGE):])

    def render(self, spp: int, seed: int):
        out = os.path.join(self.dir.name, "image.npy")
        self.process.stdin.write(json.dumps({"spp": spp, "seed": seed, "out": out}) + "\n")
        self.process.stdin.flush()
        reply = self._receive()
        return np.load(out), float(reply["seconds"])

    def close(self) -> None:
        if self.process.poll() is None:
            self.process.stdin.close()
            try:
                self.process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.process.kill()
        self.stderr.close()
        self.dir.cleanup()


def llvm_major(path: str) -> int:
    found = re.search(r"LLVM(?:\.so)?[-.]?(\d+)", os.path.basename(path))
    return int(found.group(1)) if found else 0


def is_shared_library(path: str) -> bool:
    """An ELF or Mach-O file (not a linker script such as Rust's libLLVM-N-rust-*.so)."""
    try:
        with open(path, "rb") as f:
            magic = f.read(4)
    except OSError:
        return False
    return magic in (b"\x7fELF", b"\xcf\xfa\xed\xfe", b"\xfe\xed\xfa\xcf")


def libllvm_candidates(given=()) -> list:
    """libLLVM shared libraries to try: ``given`` first, then those LIBLLVM_PATTERNS find,
    newest major version first, one per real file."""
    seen, out = set(), []
    found = [p for pattern in LIBLLVM_PATTERNS for p in glob.glob(os.path.expanduser(pattern))]
    for path in list(given) + sorted(found, key=llvm_major, reverse=True):
        real = os.path.realpath(path)
        if is_shared_library(real) and real not in seen:
            seen.add(real)
            out.append(path)
    return out


def start_llvm(sampler: str, given, log):
    """(worker, libLLVM path or None for Dr.Jit's own choice, [(tried, why it failed)]).
    worker is None when no libLLVM renders the scene."""
    tried = []
    env_path = os.environ.get("DRJIT_LIBLLVM_PATH")
    candidates = [None] + [p for p in libllvm_candidates(given) if p != env_path]
    discovered = 0
    for path in candidates:
        if path is not None and path not in given:
            discovered += 1
            if discovered > MAX_LIBLLVM_TRIES:
                break
        label = path or (env_path and "DRJIT_LIBLLVM_PATH=%s" % env_path) or "Dr.Jit's default libLLVM"
        worker = None
        try:
            worker = Worker("llvm_ad_rgb", sampler, path)
            worker.render(1, SEED)       # the probe: a whole path tracing kernel
            log("Mitsuba llvm_ad_rgb renders with %s (%s)" % (label, worker.info["libllvm"]))
            return worker, path, tried
        except Exception as error:
            tried.append((label, str(error)))
            log("Mitsuba llvm_ad_rgb with %s: %s" % (label, error))
            if worker is not None:
                worker.close()
    return None, None, tried


# ---- peers and points -------------------------------------------------------------------

@dataclass
class Point:
    spp: int
    times: list = field(default_factory=list)
    mses: list = field(default_factory=list)

    @property
    def seconds(self) -> float:
        return statistics.median(self.times)

    @property
    def rmse(self) -> float:
        return math.sqrt(statistics.fmean(self.mses))


@dataclass
class Peer:
    system: str          # "rtfgu numba", "rtfgu wgpu", "Mitsuba 3"
    precision: str
    method: str          # variant and sampler
    render: object = None        # render(spp, seed) -> (image, seconds)
    close: object = None
    failed: str = ""
    note: str = ""
    points: list = field(default_factory=list)
    stopped: str = ""    # why it stopped climbing
    warmup: float = float("nan")   # seconds of the warm-up renders, compile included

    @property
    def label(self) -> str:
        return "%s %s" % (self.system, self.precision)

    @property
    def active(self) -> bool:
        return not self.failed and not self.stopped


def rtfgu_peer(backend: str, precision: str, scene, sobol: bool = False) -> Peer:
    """rtfgu's render: Jittered(spp) at the pixels and the random stream elsewhere, or with
    ``sobol`` the scene's sampler Sobol(spp), whose stream draws every 2D sample."""
    from rtfgu import Sobol, render

    if sobol:
        scene = copy.copy(scene)
        scene.sampler = Sobol(1)

    def run(spp, seed):
        start = time.perf_counter()
        image = render(scene, SIZE, SIZE, backend=backend, precision=precision, spp=spp, seed=seed)
        return image, time.perf_counter() - start
    method = "PathTrace, Sobol(spp) stream" if sobol else "PathTrace, Jittered(spp) pixel sampler"
    return Peer("rtfgu " + backend, precision, method, run)


def worker_peer(worker: Worker, sampler: str, why: str = "") -> Peer:
    info = worker.info
    method = "%s, %s sampler" % (info["variant"], sampler)
    note = "%d threads" % info["threads"]
    if info.get("libllvm"):
        note += ", %s" % info["libllvm"]
        if info["variant"].startswith("llvm"):
            note += "; over %d spp: mean of renders of %d" % (LLVM_CHUNK_SPP, LLVM_CHUNK_SPP)
    if why:
        note += "; " + why
    return Peer("Mitsuba 3", "float32", method, worker.render, worker.close, note=note)


def measure(peers, reference, ref_mse, levels, runs, log) -> None:
    """Fill every peer's points (the module's docstring: Measurement)."""
    for peer in peers:
        if peer.failed:
            continue
        try:
            # One render at every level up to WARMUP_MAX_SPP: the kernels of one sample and
            # of several (numba), and WGSL pipelines first built at a new spp, compile here.
            start = time.perf_counter()
            for spp in levels:
                if spp <= WARMUP_MAX_SPP:
                    peer.render(spp, SEED)
            peer.warmup = time.perf_counter() - start
        except Exception as error:  # the section says which peer did not run, and why
            peer.failed = str(error).splitlines()[0] if str(error) else repr(error)
            log("%s %s: not run: %s" % (peer.label, peer.method, peer.failed))
    for index, spp in enumerate(levels):
        todo = [p for p in peers if p.active]
        if not todo:
            break
        for peer in todo:
            peer.points.append(Point(spp))
        for number in range(runs):
            for peer in todo:
                point = peer.points[-1]
                if peer.failed or (number > 0 and point.times[0] > LONG_SECONDS):
                    continue
                try:
                    image, seconds = peer.render(spp, SEED + 16 * index + number)
                except Exception as error:
                    peer.failed = "at %d spp: %s" % (spp, str(error).splitlines()[0])
                    peer.points.pop()
                    log("%s: %s" % (peer.label, peer.failed))
                    continue
                point.times.append(seconds)
                point.mses.append(float(np.mean((image - reference) ** 2)))
        for peer in todo:
            if peer.failed:
                continue
            point = peer.points[-1]
            log("  %-22s %-36s %6d spp: %8.3f s, RMSE %.5f (%d run%s)" % (
                peer.label, peer.method, spp, point.seconds, point.rmse, len(point.times),
                "" if len(point.times) == 1 else "s"))
            if point.rmse <= TARGET:
                peer.stopped = "reached"
            elif index + 1 < len(levels) and point.seconds * levels[index + 1] / spp > MAX_RENDER_SECONDS:
                peer.stopped = "time"
    for peer in peers:
        if peer.active and peer.points:
            peer.stopped = "levels"


@dataclass
class Result:
    reached: bool
    seconds: float
    spp: float
    estimated: bool = False     # extrapolated beyond the last point


def time_to_target(peer: Peer, ref_mse: float):
    """Result for TARGET, or None without points."""
    pts = peer.points
    if not pts:
        return None
    for i, p in enumerate(pts):
        if p.rmse <= TARGET:
            if i == 0:
                return Result(True, p.seconds, p.spp)
            a = pts[i - 1]
            f = (math.log(TARGET) - math.log(a.rmse)) / (math.log(p.rmse) - math.log(a.rmse))
            seconds = math.exp(math.log(a.seconds) + f * (math.log(p.seconds) - math.log(a.seconds)))
            spp = math.exp(math.log(a.spp) + f * (math.log(p.spp) - math.log(a.spp)))
            return Result(True, seconds, spp)
    last = pts[-1]
    own = last.rmse ** 2 - ref_mse
    if own <= 0 or TARGET ** 2 <= ref_mse:
        return Result(False, float("nan"), float("nan"), True)
    spp = own * last.spp / (TARGET ** 2 - ref_mse)
    return Result(False, last.seconds * spp / last.spp, spp, True)


def noise_prediction(peer: Peer, ref_mse: float):
    """(measured RMSE at the largest spp, its noise-only prediction from the point before)."""
    if len(peer.points) < 2:
        return None
    a, b = peer.points[-2], peer.points[-1]
    predicted = math.sqrt(max(a.rmse ** 2 - ref_mse, 0.0) * a.spp / b.spp + ref_mse)
    return b.rmse, predicted


# ---- the section ------------------------------------------------------------------------

def fmt_rate(x) -> str:
    return "%.2f M" % (x / 1e6) if x >= 1e5 else "%.0f k" % (x / 1e3)


def fmt_seconds(x) -> str:
    return "%.3g s" % x


def result_cells(peer: Peer, result) -> list:
    if result is None:
        return ["-", "-", "-"]
    if result.reached:
        return [fmt_seconds(result.seconds), "%.0f" % result.spp,
                fmt_rate(result.spp * SIZE * SIZE / result.seconds)]
    last = peer.points[-1]
    why = {"time": "the next level would take over %.0f s" % MAX_RENDER_SECONDS,
           "levels": "the last level"}.get(peer.stopped, peer.stopped)
    estimate = ("; est. %s at %.0f spp by 1/spp noise" % (fmt_seconds(result.seconds), result.spp)
                if result.seconds == result.seconds else "")
    return ["not reached within %d spp (%s)%s" % (last.spp, why, estimate), "-",
            fmt_rate(last.spp * SIZE * SIZE / last.seconds) + " (at %d spp)" % last.spp]


def main_table(peers, results, ref_mse) -> list:
    lines = ["| backend | precision | method | time to RMSE 1/255 | spp there | samples/s "
             "| RMSE at the largest spp | noise-only prediction there | warm-up | note |",
             "|---|---|---|---:|---:|---:|---:|---:|---:|---|"]
    for peer in peers:
        if peer.failed and not peer.points:
            lines.append("| %s | %s | %s | - | - | - | - | - | - | not run: %s |" % (
                peer.system, peer.precision, peer.method, peer.failed))
            continue
        cells = result_cells(peer, results.get(id(peer)))
        pred = noise_prediction(peer, ref_mse)
        last = peer.points[-1]
        lines.append("| %s | %s | %s | %s | %s | %s | %.5f (%d spp) | %s | %s | %s |" % (
            peer.system, peer.precision, peer.method, cells[0], cells[1], cells[2], last.rmse,
            last.spp, "%.5f" % pred[1] if pred else "-", fmt_seconds(peer.warmup),
            "; ".join(x for x in (peer.note, peer.failed and "stopped: " + peer.failed) if x)))
    return lines


def points_table(peers) -> list:
    levels = sorted({p.spp for peer in peers for p in peer.points})
    lines = ["| backend | precision | method | %s |" % " | ".join("%d spp" % s for s in levels),
             "|---|---|---|%s" % ("---:|" * len(levels))]
    for peer in peers:
        if not peer.points:
            continue
        by = {p.spp: p for p in peer.points}
        cells = ["%s, %.4f" % (fmt_seconds(by[s].seconds), by[s].rmse) if s in by else "-"
                 for s in levels]
        lines.append("| %s | %s | %s | %s |" % (peer.system, peer.precision, peer.method,
                                               " | ".join(cells)))
    return lines


def verdicts(peers, results) -> list:
    """The ratio rtfgu numba / Mitsuba of the times to TARGET, and the target's verdict
    (rtfgu's numba path no later than Mitsuba 3 LLVM)."""
    out = []
    mitsuba = [p for p in peers if p.system == "Mitsuba 3" and results.get(id(p))]
    numba = [p for p in peers if p.system == "rtfgu numba" and results.get(id(p))]
    for n in numba:
        rn = results[id(n)]
        for m in mitsuba:
            rm = results[id(m)]
            if rn.seconds != rn.seconds or rm.seconds != rm.seconds:
                continue
            est = " (estimated)" if rn.estimated or rm.estimated else ""
            llvm = m.method.startswith("llvm")
            verdict = ""
            if llvm and est:
                verdict = ": no verdict on the target (no later than Mitsuba 3 LLVM) from estimates"
            elif llvm:
                verdict = ": the target (no later than Mitsuba 3 LLVM) is %s" % (
                    "met" if rn.seconds <= rm.seconds else "NOT met")
            out.append("- rtfgu numba %s (%s) / Mitsuba 3 %s: %s / %s = %.2f%s%s." % (
                n.precision, n.method, m.method, fmt_seconds(rn.seconds), fmt_seconds(rm.seconds),
                rn.seconds / rm.seconds, est, verdict))
    if not any(p.method.startswith("llvm") for p in mitsuba):
        out.append("- Mitsuba 3's LLVM variant did not run here: no LLVM verdict.")
    return out


def plot(peers, results, ref_rms, title, path):
    import matplotlib
    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt

    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 5.4))
    colors = plt.get_cmap("tab10")
    markers = "os^Dv<>p"
    drawn = [p for p in peers if p.points]
    for j, peer in enumerate(drawn):
        label = "%s %s (%s)" % (peer.system, peer.precision, peer.method)
        t = [p.seconds for p in peer.points]
        r = [p.rmse for p in peer.points]
        s = [p.spp for p in peer.points]
        style = dict(color=colors(j), marker=markers[j % len(markers)], markersize=4, lw=1.2)
        ax.plot(t, r, label=label, **style)
        bx.plot(s, r, label=label, **style)
        result = results.get(id(peer))
        if result is not None and result.reached:
            ax.plot([result.seconds], [TARGET], marker="x", color=colors(j), markersize=9, mew=2)
    all_t = [p.seconds for peer in drawn for p in peer.points]
    all_r = [p.rmse for peer in drawn for p in peer.points]
    if all_t:
        lo, hi = min(all_t), max(all_t)
        # The 1/sqrt(t) guide through the middle of the points.
        t0 = math.sqrt(lo * hi)
        r0 = math.exp(statistics.median(math.log(x) for x in all_r))
        ts = np.geomspace(lo, hi, 50)
        ax.plot(ts, r0 * np.sqrt(t0 / ts), color="gray", ls="--", lw=1, label="1/sqrt(t) guide")
    for a, x in ((ax, "wall time of a render (s, median)"), (bx, "samples per pixel")):
        a.axhline(TARGET, color="black", lw=1)
        a.axhline(ref_rms, color="black", lw=0.8, ls=":")
        a.set_xscale("log")
        a.set_yscale("log")
        a.set_xlabel(x)
        a.grid(True, which="both", alpha=0.3)
    ax.text(ax.get_xlim()[0], TARGET * 1.08, " RMSE 1/255", fontsize=8, va="bottom")
    ax.text(ax.get_xlim()[0], ref_rms * 1.08, " the reference's RMS standard error", fontsize=8,
            va="bottom")
    ax.set_ylabel("RMSE against the Mitsuba reference (linear radiance)")
    ax.set_title("RMSE against time (x: time to 1/255, interpolated)", fontsize=9)
    bx.set_title("RMSE against samples per pixel", fontsize=9)
    handles, labels = ax.get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=3, fontsize=7, frameon=False)
    fig.suptitle("Cornell box with blocks, %dx%d, path traced; %s" % (SIZE, SIZE, title), fontsize=9)
    fig.tight_layout(rect=(0, 0.1, 1, 1))
    fig.savefig(path, dpi=110)
    plt.close(fig)


def path_tracing_section(plot_path=None, quick=False, with_wgpu=True, log=print,
                         scalar=True, libllvm=()) -> str:
    """Measure, write the plot at ``plot_path`` (None: no plot), and return the markdown
    section (from START to END) for a file in ``plot_path``'s folder."""
    import numba
    from bench import cpu_model, gpu_adapter
    started = time.perf_counter()
    load_start = os.getloadavg()
    levels = QUICK_LEVELS if quick else LEVELS
    runs = 1 if quick else RUNS
    reference, ref_rms, ref_about = load_reference()
    ref_mse = ref_rms ** 2
    log("path tracing: the reference's RMS standard error %.5f = %.2f x 1/255: an RMSE of 1/255 "
        "against it takes %.2f x the samples of an own error of 1/255"
        % (ref_rms, ref_rms / TARGET, TARGET ** 2 / max(TARGET ** 2 - ref_mse, 1e-300)))

    scene = cornell_scene()
    peers = [rtfgu_peer("numba", "float32", scene), rtfgu_peer("numba", "float64", scene),
             rtfgu_peer("numba", "float32", scene, sobol=True)]
    adapter, no_adapter = (None, "--no-wgpu") if not with_wgpu else gpu_adapter()
    if adapter is not None:
        peers.append(rtfgu_peer("wgpu", "float32", scene))
        peers[-1].note = adapter
    else:
        peers.append(Peer("rtfgu wgpu", "float32", "PathTrace", failed=no_adapter))

    why_not_llvm = ""
    libllvm_used = None
    try:
        import mitsuba  # noqa: F401  (only that it is installed; the workers use it)
        worker, libllvm_used, tried = start_llvm("independent", list(libllvm), log)
        if worker is not None:
            peers.append(worker_peer(worker, "independent"))
            try:
                peers.append(worker_peer(Worker("llvm_ad_rgb", "stratified", libllvm_used),
                                         "stratified"))
            except Exception as error:
                peers.append(Peer("Mitsuba 3", "float32", "llvm_ad_rgb, stratified sampler",
                                  failed=str(error)))
        if tried:
            why_not_llvm = "; ".join("%s: %s" % kv for kv in tried)
        if worker is None or scalar:
            why = "" if worker is not None else "llvm_ad_rgb did not run"
            try:
                peers.append(worker_peer(Worker("scalar_rgb", "independent"), "independent", why))
                if worker is None:
                    peers.append(worker_peer(Worker("scalar_rgb", "stratified"), "stratified", why))
            except Exception as error:
                peers.append(Peer("Mitsuba 3", "float32", "scalar_rgb", failed=str(error)))
    except ImportError as error:
        peers.append(Peer("Mitsuba 3", "float32", "-", failed="%s (`make bench` installs the "
                                                              "bench extra)" % error))
    try:
        measure(peers, reference, ref_mse, levels, runs, log)
    finally:
        for peer in peers:
            if peer.close is not None:
                peer.close()
    results = {id(p): time_to_target(p, ref_mse) for p in peers}
    load_end = os.getloadavg()
    seconds = time.perf_counter() - started

    machine = "%s, %d cores, numba %d threads" % (cpu_model(), os.cpu_count(),
                                                 numba.get_num_threads())
    figure = []
    if plot_path is not None:
        try:
            plot(peers, results, ref_rms, machine, Path(plot_path))
            figure = ["![RMSE against time and samples per pixel](%s)" % Path(plot_path).name, ""]
            log("wrote %s" % plot_path)
        except ImportError as error:  # no matplotlib: the tables still get written
            figure = ["(No plot: %s. `make bench` installs matplotlib.)" % error, ""]
    llvm_line = ("Mitsuba's `llvm_ad_rgb` ran with %s" % (
        "DRJIT_LIBLLVM_PATH=%s" % libllvm_used if libllvm_used else "Dr.Jit's own libLLVM")
        if any(p.method.startswith("llvm") and p.points for p in peers)
        else "Mitsuba's `llvm_ad_rgb` did not run; `scalar_rgb` did")
    if why_not_llvm:
        llvm_line += " (tried before: %s)" % why_not_llvm
    lines = [
        START,
        "## Path tracing: time to an RMSE of 1/255",
        "",
        "Generated by benchmarks/path_tracing.py%s (also part of `make bench`); never edited by "
        "hand." % (" --quick" if quick else ""),
        "",
        "- Scene: the Cornell box with its blocks (rtfgu.scenes.meshes.cornell_box_area_light()'s: "
        "every face a Matte of kd 1) lit by its ceiling quad (its two triangles one Rectangle and "
        "its AreaLight, benchmarks/cornell_reference.py's `ceiling_lamp`: one shadow ray a vertex, "
        "as Mitsuba's one emitter), `scene.tracer = PathTrace()`; Mitsuba 3 gets it through "
        "benchmarks/mitsuba_scene.py (`path` integrator, max_depth -1). %dx%d, every peer the "
        "same image." % (SIZE, SIZE),
        "- Reference: tests/data/cornell_mitsuba.npz (%s). Its RMS standard error is %.5f = "
        "%.2f x 1/255; it adds in quadrature to every render's own error (a render's RMSE "
        "against it never goes below it), so an RMSE of 1/255 here is an own error of %.5f."
        % (ref_about, ref_rms, ref_rms / TARGET, math.sqrt(max(TARGET ** 2 - ref_mse, 0.0))),
        "- RMSE: over all pixels and channels of the linear radiance (no gamma), the root of "
        "the mean of the runs' squared errors; every render has its own seed (>= %d)." % SEED,
        "- Time: wall time of one render at N samples per pixel, median of %d round(s) "
        "(round-robin over the peers; a render over %.0f s is run once) after the warm-up: "
        "a render per peer at every N up to %d (\"warm-up\": their time, compile included). "
        "rtfgu: the rtfgu.render call; Mitsuba: mi.render and the copy to numpy in a worker "
        "process, the scene loaded before. N "
        "climbs %s until the RMSE is <= 1/255 or the next N would take over %.0f s." % (
            runs, LONG_SECONDS, WARMUP_MAX_SPP, ", ".join(map(str, levels)), MAX_RENDER_SECONDS),
        "- Time to 1/255: log-log interpolation between the two points around it (spp alike); "
        "samples/s = that spp x %d pixels / that time. Noise-only prediction: the RMSE at the "
        "largest spp expected from the point before it if the error fell as 1/sqrt(spp) "
        "(the reference's part held fixed); a measured RMSE well above it is a bias." % (
            SIZE * SIZE),
        "- Pixel sampling: rtfgu takes Jittered(N) (one sample in each cell of a sqrt(N) x "
        "sqrt(N) grid over the pixel, rtfgu.renderer.pixel_sampler); Mitsuba's `independent` "
        "sampler (mitsuba_scene.to_mitsuba's) draws at random; its `stratified` sampler "
        "stratifies every dimension. A pixel on the light's edge (radiance up to %.1f) "
        "converges much faster with stratified pixel positions." % float(reference.max()),
        "- %s." % llvm_line,
        "- Peers: mitsuba %s, drjit %s, numba %s, wgpu %s." % (
            version("mitsuba"), version("drjit"), version("numba"), version("wgpu")),
        "- Machine: %s; load average %.2f at the start, %.2f at the end; %.0f s in all."
        % (machine, load_start[0], load_end[0], seconds),
        "",
        *figure,
        *main_table(peers, results, ref_mse),
        "",
        *verdicts(peers, results),
        "",
        "### Every point: median time, RMSE",
        "",
        *points_table(peers),
        "",
        END,
    ]
    return "\n".join(lines) + "\n"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(ROOT / "docs" / "bench.md"))
    parser.add_argument("--quick", action="store_true",
                        help="a check that everything runs: %s spp, 1 run" % QUICK_LEVELS)
    parser.add_argument("--no-wgpu", action="store_true", help="skip the wgpu row")
    parser.add_argument("--no-scalar", action="store_true",
                        help="skip Mitsuba's scalar_rgb where llvm_ad_rgb runs")
    parser.add_argument("--libllvm", action="append", default=[],
                        help="a libLLVM shared library for Mitsuba's llvm_ad_rgb, tried after "
                             "Dr.Jit's own choice and before those found on the machine")
    parser.add_argument("--worker", nargs=2, metavar=("VARIANT", "SAMPLER"), help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.worker:
        return worker_main(*args.worker)
    from bench import replace_section  # not in the worker, which needs no numba
    out = Path(args.out)
    started = time.perf_counter()

    def log(message):
        print("[%5.0f s] %s" % (time.perf_counter() - started, message), flush=True)

    section = path_tracing_section(out.parent / "bench_path_tracing.png", args.quick,
                                   not args.no_wgpu, log, scalar=not args.no_scalar,
                                   libllvm=args.libllvm)
    print(section)
    out.write_text(replace_section(out.read_text() if out.exists() else "", section, START, END))
    log("wrote %s" % out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
