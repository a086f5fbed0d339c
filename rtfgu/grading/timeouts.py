"""Where a test's code was when its time ran out, and what that spares the later tests.

A test's interpreter (probes/boot.py) asks Python's ``faulthandler`` to write every thread's
traceback to a file the grader holds, ``dump_after(time_limit)`` seconds after it starts:
just before the grader stops it. ``stuck_at`` reads that dump and names the innermost frame in
the student's files (file, line, function). In every later test of the grading that
function is stopped (probes/support.stop_functions): a call raises at once, naming the test
and the place, so the tests and cases that run it fail fast and the rest still count. An
endless loop costs one time limit per submission, not one per test. A dump that names no
student file (the loop is elsewhere, or the dump came too late) stops nothing.

The dump is written by the student's own process, so a submission can forge it; it can only
make its own functions raise (its tests then lose points) or run (as without a dump).
"""
from __future__ import annotations

import json
import re

# The message of a stopped function's call (probes/support.stop_functions), with the test whose
# time limit stopped it.
STOPPED = re.compile(r"was not run: it did not finish in test ([\d.]+)")
# A frame of faulthandler's dump. The dump is the student's process's to write: a function is
# a Python name (or <module>, <lambda>, ...) of at most 100 characters, a line at most 9 digits.
FRAME = re.compile(r'^\s*File "(?P<path>[^"]{1,1000})", line (?P<line>\d{1,9}) in '
                   r'(?P<function><?[A-Za-z_][A-Za-z0-9_]{0,99}>?)\s*$')
MAX_STOPPED = 16       # functions stopped in one grading, at most
MARKER = "/rtfgu/"


def dump_after(time_limit: float) -> float:
    """Seconds after the interpreter starts at which it dumps its tracebacks: 80 % of the
    limit, so that the dump is written before the test is stopped even when the interpreter
    started late."""
    return max(0.2, 0.8 * time_limit)


def stuck_at(dump: str, student_files) -> tuple | None:
    """(file under rtfgu/, line, function) of the innermost frame of ``dump`` (faulthandler's
    text, most recent call first) that is in one of ``student_files``; None if none is."""
    files = set(student_files)
    for line in dump.splitlines():
        m = FRAME.match(line)
        if m and MARKER in m.group("path").replace("\\", "/"):
            relpath = m.group("path").replace("\\", "/").rsplit(MARKER, 1)[1]
            if relpath in files:
                return relpath, int(m.group("line")), m.group("function")
    return None


def where(stuck) -> str:
    return "rtfgu/%s, line %d, in %s" % tuple(stuck[:3])


def boot_options(dump_fd: int | None, time_limit: float, stopped=()) -> str:
    """probes/boot.py's OPTIONS: the dump's file descriptor and time, and the functions stopped
    by earlier tests ([file, function, line, test number], as stopped_entry gives them)."""
    options = {"stopped": [list(s) for s in stopped][:MAX_STOPPED]}
    if dump_fd is not None:
        options["dump"] = [dump_fd, dump_after(time_limit)]
    return json.dumps(options)


def stopped_entry(stuck: tuple, number: str) -> list:
    """[file, function, line, test number] of the function ``stuck`` (stuck_at) found in test
    ``number``, for boot_options."""
    relpath, line, function = stuck
    return [relpath, function, line, number]
