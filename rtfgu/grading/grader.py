"""Grading one submission: the student package, one sandboxed interpreter per test, judge,
diff images.

The reference observations (``rtfgu/grading/reference/<assignment>/``) are what the
solution gives for every test; they are regenerated only on request
(``python -m rtfgu.grading references``). The grader reads them into memory before any
student code runs; the package the code runs in never contains them (rtfgu.grading.sandbox),
and the grader checks afterwards that their files are unchanged (restoring them if a
submission reached them). Only numbers come back from the child; the judging is here.
"""
from __future__ import annotations

import hashlib
import json
import os
import random
import time
from pathlib import Path

import numpy as np

from ..image import read_png
from .assignments import get_assignment
from .checks import checks_for, drawn_inputs, judge_cases
from .checks.images import judge_image, neighbourhood_difference  # noqa: F401  (tests import it here)
from .results import Result, TestResult
from .sandbox import (choose_isolation, hidden_from_sandbox_user, hidden_probes_readable, prepare, run_child,
                      work_folder)
from .timeouts import STOPPED, stopped_entry, stuck_at, where

REFERENCE_DIR = Path(__file__).resolve().parent / "reference"
MESSAGE_LIMIT = 8000                   # characters of one test's message in the results


def writable(text: str) -> str:
    """``text`` as UTF-8 can hold it: a lone surrogate (a student's exception message can hold
    one, "\\ud800", and JSON carries it) becomes "?", so that results.json, summary.txt and the
    gradebook can be written."""
    return text.encode("utf-8", "replace").decode("utf-8")


# --- references ----------------------------------------------------------------------------

def reference_paths(assignment):
    folder = REFERENCE_DIR / assignment.id
    return folder, folder / "observations.json"


def compute_references(assignment, time_limit: float = 120.0) -> list:
    """Run every test on the solution and store what it gives; returns the files written."""
    a = get_assignment(assignment) if isinstance(assignment, str) else assignment
    folder, obs_path = reference_paths(a)
    folder.mkdir(parents=True, exist_ok=True)
    observations, written = {}, []
    isolation = choose_isolation()
    with hidden_from_sandbox_user(isolation), work_folder("rtfgu-ref-") as tmp:
        ws = prepare(a, None, tmp / "work")
        hidden_probes_readable(ws, True)         # the solution's run: every test's probe
        for check in checks_for(a.id):
            if check.draw is not None:            # one draw, for the student checker
                observations[check.slug] = drawn_inputs(check, random.Random(0))[1]
                continue
            if check.reference is not None:       # an exact truth, or the staff renderer's estimate
                observations[check.slug] = check.reference()
                continue
            child = run_child(ws, tmp / "scratch" / check.slug, probe_command(a, check),
                              isolation=isolation, time_limit=time_limit, memory_mb=0)
            if child.status != "ok" or "error" in child.data or any("error" in c for c in child.data.get("cases", [])):
                raise RuntimeError("the solution fails %s (%s): %s %s %s" % (
                    check.name, child.status, child.detail, json.dumps(child.data)[:2000], child.output))
            if check.kind == "image":
                from ..image import write_png

                path = folder / (check.slug + ".png")
                write_png(np.asarray(child.data["image"]), path)
                written.append(path)
            else:
                observations[check.slug] = child.data
    _replace(obs_path, (json.dumps(observations, indent=1, sort_keys=True) + "\n").encode())
    written.append(obs_path)
    return written


def load_references(assignment) -> dict:
    """slug -> reference observation (uint8 image for image tests), plus the raw bytes of
    every reference file so that they can be checked and restored."""
    folder, obs_path = reference_paths(assignment)
    if not obs_path.is_file():
        raise ValueError("assignment %s has no reference observations; run "
                         "`python -m rtfgu.grading references %s`" % (assignment.id, assignment.short))
    files = {p: p.read_bytes() for p in sorted(folder.iterdir()) if p.is_file()}
    observations = json.loads(files[obs_path])
    refs = {}
    for check in checks_for(assignment.id):
        if check.kind == "image":
            path = folder / (check.slug + ".png")
            if path not in files:
                raise ValueError("reference image %s is missing; run `python -m rtfgu.grading references %s`"
                                 % (path, assignment.short))
            refs[check.slug] = read_png(path)
        else:
            if check.slug not in observations:
                raise ValueError("reference for %r is missing; run `python -m rtfgu.grading references %s`"
                                 % (check.name, assignment.short))
            refs[check.slug] = observations[check.slug]
    return refs, files


def _replace(path: Path, data: bytes) -> None:
    """Write ``path`` whole or not at all (a grader reading it at the same time sees the old
    or the new file, never a half-written one)."""
    tmp = path.with_name(".%s.%d.tmp" % (path.name, os.getpid()))
    tmp.write_bytes(data)
    os.replace(tmp, path)


def _digest(files: dict) -> dict:
    return {p: hashlib.sha256(b).hexdigest() for p, b in files.items()}


# --- grading -------------------------------------------------------------------------------

def _child_failure(child, time_limit, memory_mb) -> tuple:
    """(the test's message, the gradebook's short cause) for a test whose process gave no
    answer."""
    if child.status == "timeout":
        return ("stopped after the time limit of %g s: your code did not finish (an endless loop, or far "
                "too slow)" % time_limit, "time limit (%g s)" % time_limit)
    if child.status == "too much output":
        return "stopped: " + child.detail, child.status
    if child.status == "crashed":
        cause = "memory limit (%d MB)" % memory_mb if "MemoryError" in child.output else "crash: " + child.detail
        return "the test process died: %s (the memory limit is %d MB)" % (child.detail, memory_mb), cause
    return "the test gave no usable answer: %s" % child.detail, child.status


def _needs(check, a) -> tuple:
    return tuple(check.needs) or a.files


def grade(assignment, submission, out_dir=None, *, fmt_name: str = "gradescope", visible_only: bool = False,
          time_limit: float | None = None, memory_mb: int = 1024, output_limit: int = 1024 * 1024,
          log=None, require_sandbox: bool = False, only=None, seed=None) -> Result:
    """Grade ``submission`` (a folder, a zip file, or None for the solution) and, if
    ``out_dir`` is given, write results.json, summary.txt and diffs/ there. ``only``: the
    slugs of the tests to run (the rest are left out of the result). ``seed``: the inputs
    that tests with ``draw`` draw when they run (default: the operating system's randomness,
    new for every grading)."""
    a = get_assignment(assignment) if isinstance(assignment, str) else assignment
    time_limit = a.time_limit if time_limit is None else time_limit
    isolation = choose_isolation(require_sandbox)
    start = time.monotonic()
    refs, ref_files = load_references(a)
    digest = _digest(ref_files)
    result = Result(a.id, str(submission), isolation=isolation)
    out_dir = Path(out_dir) if out_dir is not None else None
    if out_dir is not None and isolation == "unprivileged user":
        # The diff images written while grading hold reference images (hidden tests' too), and
        # another submission's sandbox user may be running at the same time (grade-all).
        out_dir.mkdir(parents=True, exist_ok=True)
        os.chmod(out_dir, 0o700)
    # The submission itself is closed too while its tests run: its path is in this process's
    # command line, which every user can read, and a grading beside this one runs another
    # student's code.
    hidden = [submission] if submission is not None else []
    with hidden_from_sandbox_user(isolation, hidden), work_folder() as tmp:
        ws = prepare(a, submission, tmp / "work")
        result.notes.extend(ws.notes)
        stopped = []          # functions a time limit stopped (rtfgu.grading.timeouts)
        for check in checks_for(a.id):
            if visible_only and check.visibility != "visible":
                continue
            if only is not None and check.slug not in only:
                continue
            rng = random.SystemRandom() if seed is None else random.Random("%s/%s" % (seed, check.slug))
            test, stuck = _run_check(a, check, ws, tmp, refs, out_dir, isolation,
                                     time_limit, memory_mb, output_limit, log, rng, stopped)
            result.tests.append(test)
            if stuck is not None and all(e[:2] != [stuck[0], stuck[2]] for e in stopped):
                stopped.append(stopped_entry(stuck, check.number))
    now = _digest({p: p.read_bytes() if p.exists() else b"" for p in ref_files})
    if now != digest:
        for path, data in ref_files.items():
            _replace(path, data)
        for test in result.tests:
            test.score = 0.0
            test.output = "the submission wrote to the grader's reference files; they were restored\n" + test.output
        result.notes.append("The submission changed the grader's reference files: they were restored "
                            "and the submission scores 0.")
    result.execution_time = time.monotonic() - start
    if out_dir is not None:
        result.write(out_dir, fmt_name)
    return result


def probe_command(a, check) -> list:
    """The boot command of ``check``'s probe: a visible test's by its slug (boot.py looks it up
    in the probes' table, as the student checker does), a hidden test's with its inputs, which
    the table the sandbox holds leaves out."""
    if check.visibility == "visible":
        return ["check", a.id, check.slug]
    module, function = check.probe[:2]
    return ["probe", module, function, json.dumps(check.probe[2] if len(check.probe) > 2 else {})]


def _run_check(a, check, ws, tmp, refs, out_dir, isolation, time_limit, memory_mb, output_limit, log, rng,
               stopped=()):
    """(the test's result, where a time limit found the student's code or None)."""
    time_limit = check.time_limit or time_limit
    probe, reference = probe_command(a, check), refs[check.slug]
    if check.draw is not None:
        (module, function, kwargs), reference = drawn_inputs(check, rng)
        probe = ["probe", module, function, json.dumps(kwargs)]
    broken = [ws.broken[f] for f in _needs(check, a) if f in ws.broken]
    stuck = None
    diff_path = out_dir / "diffs" / (check.slug + ".png") if out_dir is not None and check.kind == "image" else None
    image_path = None
    seconds = 0.0
    cause = ""
    if broken:
        fraction, lines = 0.0, ["this test runs a file that does not compile, so it was not run: " + b
                                for b in broken]
        cause = "; ".join(broken)
        output = ""
    else:
        memory = memory_mb if check.memory_mb is None else check.memory_mb
        hidden_probes_readable(ws, check.visibility != "visible")
        try:
            child = run_child(ws, tmp / "scratch" / check.slug, probe, isolation=isolation,
                              time_limit=time_limit, memory_mb=memory, output_limit=output_limit, stopped=stopped)
        finally:
            hidden_probes_readable(ws, False)
        seconds, output = child.seconds, child.output
        if child.status != "ok":
            failure, cause = _child_failure(child, time_limit, memory)
            fraction, lines = 0.0, [failure]
            stuck = stuck_at(child.dump, a.files) if child.status == "timeout" else None
            if stuck is not None:
                lines.append("Your code was at %s when the time ran out; the later tests do not run that "
                             "function again (a call to it fails at once)." % where(stuck))
                cause += " at %s:%d" % stuck[:2]
        else:
            raised = child.data.get("error")
            if isinstance(raised, str):   # the student's code raised as a whole (probes/boot.py)
                stopped_in = STOPPED.search(raised)
                cause = ("memory limit (%d MB)" % memory if raised.startswith("MemoryError")
                         else "time limit in test %s" % stopped_in.group(1) if stopped_in
                         else "exception: " + (raised.splitlines() or [""])[0][:120])
            # The answer is the child's to write (student code can reach the pipe): one that
            # does not have the shape the probe gives costs this test only.
            try:
                if check.kind == "image":
                    fraction, lines, image_path = judge_image(check, child.data, reference, diff_path)
                elif check.kind == "statistic" or check.judge is not None:   # a judge of its own
                    fraction, lines = check.judge(check, child.data, reference)
                else:
                    fraction, lines = judge_cases(check, child.data, reference)
                lines = [str(line) for line in lines]
            except Exception as error:
                fraction, lines, image_path = 0.0, [
                    "the test's answer was not in the form the test writes (%s); was something else "
                    "written to its pipe?" % type(error).__name__], None
                cause = "bad answer"
    if not 0.0 <= fraction <= 1.0:       # a judge's NaN (the answer's numbers) scores nothing
        fraction = 0.0 if not fraction > 1.0 else 1.0
    if fraction >= 1.0:
        cause = ""
    if output.strip() and fraction < 1.0:
        lines.append("What your code printed:\n" + output)
    message = "\n".join(lines) if lines else "all cases right"
    if len(message) > MESSAGE_LIMIT:  # the child's error texts are the student's to choose
        message = message[:MESSAGE_LIMIT] + "\n[... message cut at %d characters]" % MESSAGE_LIMIT
    message, cause = writable(message), writable(cause)
    if fraction >= 1.0 and check.kind == "cases" and check.judge is None:
        message = "all %d cases right" % len(refs[check.slug].get("cases", [])) or message
    test = TestResult(check.number, check.name, float(check.weight), round(check.weight * fraction, 4),
                      check.visibility, message, str(image_path) if image_path else None, cause)
    if log:
        log("%-5s %-70s %5.2f / %g  (%.2f s)" % (test.number, test.name[:70], test.score, test.max_score, seconds))
    return test, stuck
