"""The student checker: an assignment's visible tests on the student's own copy of the
package, without a sandbox (it is the student's own code, on the student's machine).

A student release ships this module with ``assignments``, ``results``, the ``checks`` (the
visible tests and their hints), the visible ``probes`` and the visible references, as the
package ``rtfgu_checker`` beside the student's ``rtfgu``; ``python -m rtfgu_checker check
a03`` is ``make check A=a03``. Each test's probe runs in a new interpreter
(``probes/boot.py``) with the folder holding the student's ``rtfgu`` first on its path; its
answer comes back through a pipe and is judged here, as the grader does. Image tests write
``<out>/diffs/<test>.png`` (checks.images.DIFF_LEGEND says what it shows).
"""
from __future__ import annotations

import json
import os
import re
import select
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from .assignments import ASSIGNMENTS, get_assignment
from .checks import IMAGE_LEVELS, REFERENCE_DIR, checks_for, judge_cases, stored_probe, traces_a_scene
from .checks.images import DIFF_LEGEND, image_differences, judge_image, load_png, write_diff_image, write_png
from .pixels import SUFFIX as PIXELS_SUFFIX, pixel_bounces
from .results import Result, TestResult
from .timeouts import boot_options, stopped_entry, stuck_at, where

PROBES = Path(__file__).resolve().parent / "probes"
FULL_SIZE = "full_size"    # an assignment's full-size references, in its reference folder (a release's)
# The stub of an assignment's function, as probes/support.describe_exception names it.
OTHER_STUB = re.compile(r"NotImplementedError\('(a\d\d): ([^']+)'\)")
ANSWER_LIMIT = 64 * 1024 * 1024


def run_probe(root: Path, probe: tuple, time_limit: float, stopped=(), student_files=()):
    """(data or None, what the code printed, why it failed or None, where a time limit found the
    code in ``student_files`` or None): ``probe`` run by a new interpreter with ``root`` (the
    folder holding the student's rtfgu) first on its path; ``stopped``, the functions earlier
    time limits stopped (rtfgu.grading.timeouts)."""
    module, function, kwargs = probe
    read_fd, write_fd = os.pipe()
    with tempfile.TemporaryFile() as printed, tempfile.TemporaryFile() as dump:
        process = subprocess.Popen(
            [sys.executable] + (["-S"] if sys.flags.no_site else []) + [
                str(PROBES / "boot.py"), str(root), str(PROBES.parent), "", str(write_fd),
                boot_options(dump.fileno(), time_limit, stopped), "probe", module, function, json.dumps(kwargs)],
            stdin=subprocess.DEVNULL, stdout=printed, stderr=subprocess.STDOUT, pass_fds=(write_fd, dump.fileno()),
            cwd=str(root), start_new_session=True)
        os.close(write_fd)
        chunks, size, failure, timed_out = [], 0, None, False
        deadline = time.monotonic() + time_limit
        try:
            while True:
                left = deadline - time.monotonic()
                if left <= 0:
                    failure = "stopped after the time limit of %g s: your code did not finish" % time_limit
                    timed_out = True
                    break
                ready, _, _ = select.select([read_fd], [], [], left)
                if not ready:
                    continue
                chunk = os.read(read_fd, 1 << 16)
                if not chunk:
                    break
                chunks.append(chunk)
                size += len(chunk)
                if size > ANSWER_LIMIT:
                    failure = "the test's answer was larger than %d bytes" % ANSWER_LIMIT
                    break
        finally:
            os.close(read_fd)
            try:
                os.killpg(process.pid, signal.SIGKILL)
            except (ProcessLookupError, PermissionError):
                pass
            process.wait()
        printed.seek(0)
        output = printed.read(4000).decode("utf-8", "replace")
        dump.seek(0)
        stuck = stuck_at(dump.read(16000).decode("utf-8", "replace"), student_files) if timed_out else None
    if failure is None and not chunks:
        failure = "the test process exited (code %s) before it answered" % process.returncode
    if stuck is not None:
        failure += ("; your code was at %s when the time ran out (the later tests do not run that function "
                    "again: a call to it fails at once)" % where(stuck))
    if failure is not None:
        return None, output, failure, stuck
    try:
        return json.loads(b"".join(chunks)), output, None, None
    except ValueError:
        return None, output, "the test's answer was not readable", None


def load_reference(check, reference_dir: Path = REFERENCE_DIR):
    folder = Path(reference_dir) / check.assignment
    if check.kind == "image":
        return load_png(folder / (check.slug + ".png"))
    observations = json.loads((folder / "observations.json").read_text())
    return observations[check.slug]


def check(assignment, root=".", out_dir=None, time_limit: float | None = None, log=None, only=None) -> Result:
    """The visible tests of ``assignment`` on the rtfgu package in ``root``; with ``out_dir``,
    summary.txt, results.json and diffs/ are written there."""
    a = get_assignment(assignment) if isinstance(assignment, str) else assignment
    root = Path(root).resolve()
    time_limit = a.time_limit if time_limit is None else time_limit
    out_dir = Path(out_dir) if out_dir is not None else None
    start = time.monotonic()
    result = Result(a.id, str(root / "rtfgu"), isolation="none (your own code, on your machine)")
    stopped = []      # functions a time limit stopped (rtfgu.grading.timeouts)
    for c in checks_for(a.id):
        if c.visibility != "visible" or (only is not None and c.slug not in only):
            continue
        t0 = time.monotonic()
        reference = load_reference(c)
        data, output, failure, stuck = run_probe(
            root, stored_probe(c, reference), c.time_limit or (time_limit * 6 if c.kind == "image" else time_limit),
            stopped, a.files)
        if stuck is not None and all(e[:2] != [stuck[0], stuck[2]] for e in stopped):
            stopped.append(stopped_entry(stuck, c.number))
        image = None
        if failure is not None:
            fraction, lines = 0.0, [failure]
        elif c.kind == "image":
            diff = out_dir / "diffs" / (c.slug + ".png") if out_dir is not None else None
            fraction, lines, image = judge_image(c, data, reference, diff)
        elif c.kind == "statistic":
            try:
                fraction, lines = c.judge(c, data, reference)
            except Exception as error:      # an answer of the wrong form: this test only
                fraction, lines = 0.0, ["the test's answer was not in the form the test writes (%s)"
                                        % type(error).__name__]
        else:
            fraction, lines = judge_cases(c, data, reference)
        other = OTHER_STUB.search("\n".join(lines)) if fraction < 1.0 else None
        if other and other.group(1) != a.short:
            lines.append("This test also runs %s of %s, which your copy does not have yet: it passes here once you "
                         "have written %s (the grader runs it with the solution of %s)."
                         % (other.group(2), other.group(1), other.group(1), other.group(1)))
        if output.strip() and fraction < 1.0:
            lines.append("What your code printed:\n" + output)
        message = "\n".join(lines) if lines else "all cases right"
        if fraction >= 1.0 and c.kind == "cases":
            message = "all %d cases right" % len(reference.get("cases", []))
        test = TestResult(c.number, c.name, float(c.weight), round(c.weight * fraction, 4), c.visibility,
                          message, str(image) if image else None)
        result.tests.append(test)
        if log:
            log("%-5s %-70s %5.2f / %g  (%.1f s)" % (test.number, test.name[:70], test.score, test.max_score,
                                                    time.monotonic() - t0))
    result.execution_time = time.monotonic() - start
    if out_dir is not None:
        result.write(out_dir)
    return result


def _images_of(assignment, root, out_dir, folder: str, what: str, log) -> tuple:
    """(the assignment, the resolved root, the output folder made, or None with a message when
    the assignment has no images to ``what``): what render and html start with."""
    a = get_assignment(assignment) if isinstance(assignment, str) else assignment
    root = Path(root).resolve()
    if not a.images:
        log("%s has no images to %s: its tests are `make check A=%s`" % (a.id, what, a.short))
        return a, root, None
    out = Path(out_dir) if out_dir is not None else root / folder / a.short
    out.mkdir(parents=True, exist_ok=True)
    return a, root, out


def render(assignment, root=".", out_dir=None, width: int = 0, height: int = 0, log=print) -> int:
    """Render the assignment's homework images with the student's code into ``out_dir``
    (default renders/<aNN>); 0 if every image rendered (or there is none), 1 otherwise."""
    a, root, out = _images_of(assignment, root, out_dir, "renders", "render", log)
    if out is None:
        return 0
    failed = 0
    for name in a.images:
        data, output, failure, _ = run_probe(root, ("images", "render_homework",
                                                 {"scene": name, "width": width, "height": height}), 3600)
        if failure is None and "error" in data:
            failure = data["error"]
        if failure is not None:
            log("%s: the render failed: %s%s" % (name, failure, ("\n" + output) if output.strip() else ""))
            failed += 1
            continue
        path = out / (name + ".png")
        write_png(data["image"], path)
        log(str(path) + compare_full_size(a, name, path))
    if failed:
        log("%d of %d images of %s failed to render" % (failed, len(a.images), a.id))
    return 1 if failed else 0


def find_test(assignment, test):
    """The visible test of ``assignment`` that ``test`` names: its number ("3.8" or "8") or
    its slug; a ValueError listing the visible image tests otherwise."""
    a = get_assignment(assignment) if isinstance(assignment, str) else assignment
    visible = [c for c in checks_for(a.id) if c.visibility == "visible"]
    for c in visible:
        if str(test) in (c.number, c.number.split(".")[1], c.slug):
            return c
    raise ValueError("%s has no visible test %r; its image tests are: %s" % (
        a.short, test, ", ".join("%s (%s)" % (c.number, c.name) for c in visible if c.kind == "image") or "none"))


def debug_pixel(assignment, test, x: int, y: int, root=".", reference_dir: Path = REFERENCE_DIR) -> tuple:
    """(report, differs): pixel (x, y) (column, row 0 at the top) of image test ``test``
    traced through the student's code beside what the solution computes there, bounce by
    bounce (the ray, the shape hit, t, the normal, the shader and the colour it adds), from
    the expected paths the release holds (rtfgu.grading.pixels)."""
    a = get_assignment(assignment) if isinstance(assignment, str) else assignment
    c = find_test(a, test)
    if c.kind != "image":
        raise ValueError("test %s (%s) is not an image test: `make check A=%s` shows its cases"
                         % (c.number, c.name, a.short))
    if not traces_a_scene(c):
        raise ValueError("test %s (%s) renders an image of its own, whose pixels debug-pixel does not trace; "
                         "its diff image shows where it differs" % (c.number, c.name))
    module, function, kwargs = c.probe
    width, height = kwargs["width"], kwargs["height"]
    for name, value, limit in (("X", x, width), ("Y", y, height)):
        if not 0 <= value < limit:
            raise ValueError("%s must be in [0, %d) for the %dx%d image of test %s, got %d"
                             % (name, limit, width, height, c.number, value))
    path = Path(reference_dir) / a.id / (c.slug + PIXELS_SUFFIX)
    if not path.is_file():
        raise ValueError("this copy holds no expected pixels for test %s (%s)" % (c.number, path))
    title = ("%s test %s (%s): pixel (%d, %d) of the %dx%d test image, row 0 at the top"
             % (a.short, c.number, c.name, x, y, width, height))
    probe = ("images", "debug_pixel", dict(kwargs, x=x, y=y, expected=pixel_bounces(path, x, y),
                                           rtol=c.rtol, title=title))
    data, output, failure, _ = run_probe(Path(root).resolve(), probe, c.time_limit or a.time_limit * 6)
    if failure is None and "error" in data:
        failure = data["error"]
    if failure is not None and failure.startswith("PathNotInRelease"):
        raise ValueError("test %s's image is rendered on a path whose debugger this copy leaves out: %s"
                         % (c.number, failure))
    if failure is not None:
        raise ValueError("tracing the pixel with your code failed: %s%s"
                         % (failure, ("\n" + output) if output.strip() else ""))
    return data["report"], bool(data["differs"])


def html(assignment, root=".", out_dir=None, width: int = 0, height: int = 0, log=print) -> int:
    """Write the assignment's homework images as WebGPU pages made from the student's own
    package (``python -m rtfgu export-html``: the WGSL the student wrote, assembled as the wgpu
    path assembles it, with the slides' sphere test, intersect_sphere.wgsl, as a06's image test
    renders) into ``out_dir`` (default html/<aNN>); 0 if every page was written."""
    a, root, out = _images_of(assignment, root, out_dir, "html", "make pages of", log)
    if out is None:
        return 0
    failed = 0
    for name in a.images:
        page = out / (name + ".html")
        size = (["--width", str(width)] if width else []) + (["--height", str(height)] if height else [])
        done = subprocess.run([sys.executable] + (["-S"] if sys.flags.no_site else []) +
                              ["-m", "rtfgu", "export-html", name, "-o", str(page), "--formula", "slide"] + size,
                              cwd=str(root), capture_output=True, text=True, timeout=600)
        if done.returncode != 0:
            failed += 1
            log("%s: the page could not be made: %s" % (name, (done.stderr or done.stdout).strip()[-2000:]))
            continue
        log(str(page))
    if failed < len(a.images):
        log("open a page in a browser with WebGPU (Chrome or Edge; Firefox with dom.webgpu.enabled)")
    return 1 if failed else 0


def compare_full_size(a, name: str, path: Path, reference_dir: Path = REFERENCE_DIR) -> str:
    """What the render at ``path`` is beside the full-size reference a release holds for it
    (rtfgu.grading.release.full_size_references): a diff image next to it when they differ,
    as the image tests judge (checks.images); "" where there is no reference."""
    reference_path = Path(reference_dir) / a.id / FULL_SIZE / (name + ".png")
    if not reference_path.is_file():
        return ""
    mine, reference = load_png(path), load_png(reference_path)
    if mine.shape != reference.shape:
        return ": the reference is %dx%d (`make render A=%s` without W and H compares with it)" % (
            reference.shape[1], reference.shape[0], a.short)
    wrong, missing = image_differences(mine, reference)
    bad = (np.maximum(wrong, missing) > IMAGE_LEVELS).sum()
    if bad == 0:
        return ": the same as the reference, allowing a one-pixel shift"
    diff = path.with_name(path.stem + "_diff.png")
    write_diff_image(mine, reference, wrong, missing, diff, scale=1)
    return ": %d pixels differ from the reference; %s is %s" % (bad, diff.name, DIFF_LEGEND)


def main(argv=None) -> int:
    import argparse

    parser = argparse.ArgumentParser(prog="python -m rtfgu_checker",
                                     description="the visible tests and the images of an assignment, on your code")
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("list", help="the assignments")
    p = sub.add_parser("check", help="the visible tests of an assignment (make check A=a03)")
    p.add_argument("assignment", nargs="?")
    p.add_argument("--root", default=".", help="the folder holding your rtfgu/ (default: here)")
    p.add_argument("--out", default=None, help="default check-results/<aNN>")
    p.add_argument("--time-limit", type=float, default=None, help="seconds per test")
    for command, what, folder in (("render", "the assignment's images, rendered with your code (make render A=a03)",
                                    "renders"),
                                   ("html", "the assignment's images as WebGPU pages of your code (make html A=a06)",
                                    "html")):
        p = sub.add_parser(command, help=what)
        p.add_argument("assignment", nargs="?")
        p.add_argument("--root", default=".")
        p.add_argument("--out", default=None, help="default %s/<aNN>" % folder)
        p.add_argument("--width", type=int, default=0)
        p.add_argument("--height", type=int, default=0)
    p = sub.add_parser("debug-pixel", help="one pixel of an image test, traced through your code beside the "
                                           "expected values (make debug-pixel A=a03 T=3.8 X=16 Y=32)")
    p.add_argument("assignment", nargs="?")
    p.add_argument("test", nargs="?", help="the test's number (3.8, or 8) as make check prints it")
    p.add_argument("x", nargs="?", type=int, help="column, 0 at the left")
    p.add_argument("y", nargs="?", type=int, help="row, 0 at the top")
    p.add_argument("--root", default=".")
    args = parser.parse_args(argv)
    try:
        if args.command == "debug-pixel" and None in (args.assignment, args.test, args.x, args.y):
            parser.exit(2, "make debug-pixel needs A, T (the test's number), X and Y: a failing image test's "
                           "message gives them, e.g. make debug-pixel A=a03 T=3.8 X=16 Y=32\n")
        if args.command == "debug-pixel":
            report, differs = debug_pixel(args.assignment, args.test, args.x, args.y, args.root)
            print(report)
            return 1 if differs else 0
        if args.command == "list":
            for a in ASSIGNMENTS.values():
                print("%-40s %s" % (a.id, a.title))
            return 0
        if args.assignment is None:   # `make render` or `make check` without A=
            parser.exit(2, "make %s needs an assignment: make %s A=a03 (or A=a03_intersections); "
                           "the assignments are:\n%s\n" % (args.command, args.command, "\n".join(
                               "  %-6s %s" % (a.short, a.title) for a in ASSIGNMENTS.values())))
        a = get_assignment(args.assignment)
        if args.command == "render":
            return render(a, args.root, args.out, args.width, args.height)
        if args.command == "html":
            return html(a, args.root, args.out, args.width, args.height)
        out = args.out or str(Path(args.root) / "check-results" / a.short)
        result = check(a, args.root, out, args.time_limit, log=lambda line: print(line, flush=True))
        print(result.summary())
        if any(t.image for t in result.tests):
            print("diff images (%s): %s" % (DIFF_LEGEND, Path(out) / "diffs"))
        return 0 if result.score >= result.max_score - 1e-9 else 1
    except ValueError as error:
        parser.exit(2, "error: %s\n" % error)
