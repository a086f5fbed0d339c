"""Planted-bug submissions, built from the solution at test time.

Each ``tests/submissions/<name>.py`` describes one submission: a one-line docstring saying what
is wrong, ``ASSIGNMENT`` (the short id, e.g. ``"a03"``) and ``REPLACE``, a list of
``(file, solution text, replacement)``. ``make_submission`` writes the solved student files of the
assignment (the same files as ``python -m rtfgu.grading solution``) and applies the replacements.
A solution text must occur exactly once in its file: when a change in ``rtfgu/`` moves the text a
planted bug replaces, building the submission fails instead of grading an unplanted copy.
"""
from __future__ import annotations

import runpy
from pathlib import Path

from rtfgu.grading.generate import solution_files, write_files

SUBMISSIONS = Path(__file__).resolve().parent / "submissions"


def planted_names() -> list:
    return sorted(p.stem for p in SUBMISSIONS.glob("*.py"))


def describe(name: str) -> dict:
    """The description of planted submission ``name``: its globals (``__doc__``, ``ASSIGNMENT``, ``REPLACE``)."""
    path = SUBMISSIONS / (name + ".py")
    if not path.is_file():
        raise ValueError("no planted submission %r: %s does not exist" % (name, path))
    return runpy.run_path(str(path))


def apply_replacements(files: dict, replace, name: str = "submission") -> dict:
    """Return a copy of ``files`` (relative path -> text) with each ``(file, old, new)`` applied;
    ``old`` must occur exactly once in ``file``."""
    out = dict(files)
    if not replace:
        raise ValueError("%s: REPLACE is empty, so the submission would be the solution" % name)
    for relpath, old, new in replace:
        if relpath not in out:
            raise ValueError("%s: REPLACE names %s, which is not a solution file (%s)"
                             % (name, relpath, ", ".join(sorted(out))))
        count = out[relpath].count(old)
        if count != 1:
            raise ValueError("%s: REPLACE text must occur exactly once in the solution's %s, found %d times: %r"
                             % (name, relpath, count, old))
        out[relpath] = out[relpath].replace(old, new)
    return out


def make_submission(name: str, folder) -> Path:
    """Write planted submission ``name`` (solution plus its bug) into ``folder``; return ``folder``."""
    spec = describe(name)
    files = apply_replacements(solution_files(spec["ASSIGNMENT"]), spec["REPLACE"], name)
    folder = Path(folder)
    write_files(files, folder)
    return folder
