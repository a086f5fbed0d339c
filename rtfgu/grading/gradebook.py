"""Grading a class: one submission per student (a folder or a zip named for the student),
in parallel over the cores, a results folder per student and a CSV gradebook."""
from __future__ import annotations

import csv
import multiprocessing
import os
from pathlib import Path

from .assignments import get_assignment
from .checks import checks_for


def list_submissions(folder) -> list:
    """(student, path) for every sub-folder or zip file of ``folder``, sorted by name."""
    out = []
    for path in sorted(Path(folder).iterdir()):
        if path.name.startswith("."):
            continue
        if path.is_dir():
            out.append((path.name, path))
        elif path.suffix == ".zip":
            out.append((path.stem, path))
    return out


def _grade_one(job):
    from .grader import grade

    assignment_id, student, path, out_dir, time_limit, memory_mb, require_sandbox = job
    try:
        result = grade(assignment_id, path, Path(out_dir) / student, time_limit=time_limit, memory_mb=memory_mb,
                       require_sandbox=require_sandbox)
        return student, result.score, result.max_score, {t.number: t.score for t in result.tests}, result.cause
    except Exception as error:  # one broken submission must not stop the class
        return student, 0.0, None, {}, "%s: %s" % (type(error).__name__, error)


def grade_all(assignment, submissions, out_dir, *, processes=None, time_limit=None, memory_mb=1024, log=None,
              require_sandbox: bool = False) -> Path:
    """Grade every submission in ``submissions``; write ``out_dir/<student>/results.json`` and
    ``out_dir/gradebook.csv`` (one row per submission; its ``error`` column says why tests
    could not judge the code: a syntax error at file and line, the time limit, the memory
    limit, a crash, or the grading's own failure); return the CSV's path."""
    from .sandbox import choose_isolation, hidden_from_sandbox_user

    a = get_assignment(assignment) if isinstance(assignment, str) else assignment
    out_dir = Path(out_dir)
    isolation = choose_isolation(require_sandbox)  # refuse before any submission is touched
    out_dir.mkdir(parents=True, exist_ok=True)
    if isolation == "unprivileged user":
        # Every student's results and the gradebook: the grader's alone.
        os.chmod(out_dir, 0o700)
    jobs = [(a.id, student, str(path), str(out_dir), time_limit, memory_mb, require_sandbox)
            for student, path in list_submissions(submissions)]
    processes = processes or os.cpu_count() or 1
    checks = checks_for(a.id)
    max_score = sum(c.weight for c in checks)
    rows = []
    # The class folder is named in this process's command line, which every user can read:
    # under the fallback it is closed to the sandbox users (each worker's student code) for
    # the whole run. fork: the workers start with the grader imported; each test still runs
    # in its own child, and each worker has a sandbox user of its own.
    with hidden_from_sandbox_user(isolation, [submissions]), \
            multiprocessing.get_context("fork").Pool(min(processes, max(1, len(jobs)))) as pool:
        for student, score, _, per_test, error in pool.imap(_grade_one, jobs):
            rows.append((student, score, per_test, error))
            if log:
                log("%-30s %6.2f / %g%s" % (student, score, max_score, ("  " + error) if error else ""))
    path = out_dir / "gradebook.csv"
    with open(path, "w", newline="", encoding="utf-8", errors="replace") as f:
        writer = csv.writer(f)
        writer.writerow(["student", "score", "max_score", "percent"] + ["%s %s" % (c.number, c.name) for c in checks]
                        + ["error"])
        for student, score, per_test, error in rows:
            writer.writerow([student, "%g" % score, "%g" % max_score, "%.1f" % (100.0 * score / max_score)]
                            + ["%g" % per_test.get(c.number, 0.0) for c in checks] + [error])
    return path
