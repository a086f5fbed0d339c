"""A student release: the package with every assigned function stubbed in place, and nothing
that computes one a second time.

``build_package(dest, reveal)`` writes ``dest/rtfgu``:

* every ``### BEGIN SOLUTION`` block of an assignment not in ``reveal`` is replaced by its
  stub (rtfgu.grading.generate.transform), the blocks of revealed assignments keep their
  solution without the markers;
* a file whose first line says ``# release: solves a03 a04`` (``// release: ...`` in WGSL)
  computes those assignments' functions again (a numba or WGSL twin, a robust variant, a
  hard-case evaluator) and is left out unless every one of them is revealed; a package whose
  ``__init__.py`` is left out is left out whole;
* ``rtfgu/grading`` is left out: the package a submission runs in holds nothing of the grader.

``write_release(out, reveal)`` writes a whole student repository: that package, plus the
student checker (rtfgu/grading with the hidden tests, the staff-only hint code and the
hidden references left out), the assignments' READMEs, a Makefile and a README.
"""
from __future__ import annotations

import json
import re
import shutil
from pathlib import Path

from .assignments import ASSIGNMENTS, get_assignment
from .generate import PACKAGE_DIR, strip_regions, transform  # noqa: F401  (strip_regions: the release's checks)

MARKER = re.compile(r"^\s*(?:#|//)\s*release: solves\s+(?P<ids>[a0-9 ]+?)\s*$")
MARKER_LINES = 5        # a marker sits on one of a file's first lines
SKIP_NAMES = {"__pycache__", "__generated__", ".pytest_cache"}
SKIP_SUFFIXES = (".pyc", ".nbi", ".nbc")
TEXT_SUFFIXES = (".py", ".wgsl")
# Shown when a student runs a file of the package directly (python rtfgu/shapes/sphere.py).
RUN_GUARD = ('if __name__ == "__main__" and not __package__:\n'
             '    raise SystemExit("%s is part of the rtfgu package and is not run on its own: "\n'
             '                     "test it with `make check A=%s`, render with `make render A=%s`")\n')


def revealed_numbers(reveal) -> set:
    """Assignment numbers of ``reveal`` (ids such as "a03" or "a03_intersections")."""
    return {get_assignment(name).number for name in reveal}


def solves(text: str) -> set:
    """The assignment numbers a file's ``release: solves`` line (among its first
    MARKER_LINES lines) names (empty: none)."""
    for line in text.split("\n", MARKER_LINES)[:MARKER_LINES]:
        m = MARKER.match(line)
        if m:
            return {get_assignment(i).number for i in m.group("ids").split()}
    return set()


def _owner(relpath: str) -> str | None:
    """The assignment (short id) whose student file ``relpath`` is, if any."""
    for a in ASSIGNMENTS.values():
        if relpath in a.files:
            return a.short
    return None


def _skipped(path: Path) -> bool:
    return any(part in SKIP_NAMES for part in path.parts) or path.name.endswith(SKIP_SUFFIXES)


def package_files(reveal=(), package_dir: Path = PACKAGE_DIR) -> dict:
    """relpath (under rtfgu/) -> bytes of every file of the student package."""
    revealed = revealed_numbers(reveal)
    package_dir = Path(package_dir)
    left_out_dirs = []
    files = {}
    for path in sorted(package_dir.rglob("*")):
        rel = path.relative_to(package_dir)
        if not path.is_file() or _skipped(rel) or rel.parts[0] == "grading":
            continue
        if any(rel.parts[:len(d)] == d for d in left_out_dirs):
            continue
        if path.suffix in TEXT_SUFFIXES:
            text = path.read_text()
            needed = solves(text)
            if needed - revealed:
                if rel.name == "__init__.py":
                    left_out_dirs.append(rel.parent.parts)
                    files = {k: v for k, v in files.items()
                             if Path(k).parts[:len(rel.parent.parts)] != rel.parent.parts}
                continue
            text = transform(text, rel.as_posix(), None, revealed=revealed)
            owner = _owner(rel.as_posix())
            if owner and path.suffix == ".py":
                text = _with_run_guard(text, rel.as_posix(), owner)
            files[rel.as_posix()] = text.encode()
        else:
            files[rel.as_posix()] = path.read_bytes()
    return files


def _with_run_guard(text: str, relpath: str, owner: str) -> str:
    """The student file with a guard before its imports: run on its own, it says how to
    test it instead of failing on a relative import."""
    guard = RUN_GUARD % (relpath, owner, owner)
    lines = text.split("\n")
    for i, line in enumerate(lines):
        if line.startswith(("from .", "import ", "from ")) and not line.startswith("from __future__"):
            return "\n".join(lines[:i] + guard.rstrip("\n").split("\n") + lines[i:])
    return text


def build_package(dest, reveal=(), package_dir: Path = PACKAGE_DIR) -> Path:
    """Write the student package to ``dest/rtfgu`` and return that folder."""
    root = Path(dest) / "rtfgu"
    if root.exists():
        shutil.rmtree(root)
    for rel, data in package_files(reveal, package_dir).items():
        target = root / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(data)
    return root


def probe_files(package_dir: Path = PACKAGE_DIR, keep_hidden: bool = True) -> dict:
    """name -> text of the code that runs next to student code: the modules of
    rtfgu/grading/probes (without the hidden tests' ``*_hidden.py`` unless ``keep_hidden``)
    and ``tests.json``, each test's probe by assignment and slug (boot.py's ``check``
    command reads it). Copied into one folder, they form a package of any name."""
    from .checks import checks_for

    folder = Path(package_dir) / "grading" / "probes"
    files = {p.name: p.read_text() for p in sorted(folder.glob("*.py"))
             if keep_hidden or not is_hidden_probe(p.stem)}
    table = {}
    for a in ASSIGNMENTS.values():
        table[a.id] = {c.slug: list(c.probe) for c in checks_for(a.id)
                       if keep_hidden or c.visibility == "visible"}
    files["tests.json"] = json.dumps(table, indent=1, sort_keys=True) + "\n"
    return files


def is_hidden_probe(module: str) -> bool:
    """Whether probe module ``module`` holds hidden tests' probes (never in a release)."""
    return module.endswith("_hidden")


# --- the student repository ---------------------------------------------------------------

def _checker_files(package_dir: Path) -> dict:
    """relpath (under rtfgu/grading/) -> bytes: the grading package as a student checker."""
    from .checks import checks_for

    grading = Path(package_dir) / "grading"
    files = {}
    for path in sorted(grading.rglob("*")):
        rel = path.relative_to(grading)
        if not path.is_file() or _skipped(rel) or rel.parts[0] in ("reference", "checks"):
            continue
        files[rel.as_posix()] = path.read_bytes()
    for name, text in probe_files(package_dir, keep_hidden=False).items():
        files["checks/" + name] = text.encode()
    for a in ASSIGNMENTS.values():
        folder = grading / "reference" / a.id
        observations_path = folder / "observations.json"
        if not observations_path.is_file():
            continue
        observations = json.loads(observations_path.read_text())
        visible = [c for c in checks_for(a.id) if c.visibility == "visible"]
        kept = {c.slug: observations[c.slug] for c in visible if c.slug in observations}
        files["reference/%s/observations.json" % a.id] = (
            json.dumps(kept, indent=1, sort_keys=True) + "\n").encode()
        for c in visible:
            png = folder / (c.slug + ".png")
            if c.kind == "image" and png.is_file():
                files["reference/%s/%s" % (a.id, png.name)] = png.read_bytes()
    return files


STUDENT_MAKEFILE = """\
# The student's copy of rtfgu: `make check A=a03` runs the visible tests on your code.
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed

.PHONY: check render test venv clean

$(STAMP): setup.cfg pyproject.toml
\ttest -x $(PY) || $(PYTHON) -m venv $(VENV)
\t$(PY) -m pip install --quiet --upgrade pip
\t$(PY) -m pip install --quiet -e '.[test]'
\ttouch $(STAMP)

venv: $(STAMP)

check: $(STAMP)
\t$(PY) -m rtfgu.grading check $(A) rtfgu --out check-results/$(A)

render: $(STAMP)
\t$(PY) -m rtfgu.grading render $(A) rtfgu

test: $(STAMP)
\t$(PY) -m pytest

clean:
\trm -rf $(VENV) renders check-results
"""

STUDENT_TEST = '''"""The visible tests of every assignment, one pytest test each, on your own code."""
import pytest

from rtfgu.grading.assignments import ASSIGNMENTS
from rtfgu.grading.checks import checks_for
from rtfgu.grading.grader import grade

CASES = [(a.id, c.slug) for a in ASSIGNMENTS.values() for c in checks_for(a.id)
         if c.visibility == "visible"]


@pytest.mark.parametrize("assignment,slug", CASES)
def test_visible(assignment, slug, tmp_path):
    result = grade(assignment, "rtfgu", tmp_path, visible_only=True, only=(slug,))
    test = result.tests[0]
    assert test.score == test.max_score, test.output
'''


def _student_readme(reveal) -> str:
    ids = ", ".join(sorted(reveal)) or "none"
    lines = [
        "# rtfgu: your copy",
        "",
        "A teaching ray tracer after Suffern's *Ray Tracing from the Ground Up*. Every function",
        "you write is in the package itself: open the file an assignment names (for example",
        "`rtfgu/shapes/sphere.py`) and replace the `raise NotImplementedError` under each",
        "`# TODO` with your code.",
        "",
        "```",
        "make check A=a03     # the visible tests on your code; diff images in check-results/a03/diffs/",
        "make render A=a03    # the assignment's images, rendered with your code, into renders/a03/",
        "make test            # every assignment's visible tests",
        "```",
        "",
        "The first `make` creates `.venv` and installs the package (Python 3.10 or newer).",
        "Each assignment's README is in `assignments/`. Solutions revealed in this copy: %s." % ids,
        "",
        "The numba and WGSL paths of the full renderer compute the same functions again, so",
        "they are not part of this copy; `rtfgu.render(..., backend=\"reference\")` is yours.",
    ]
    return "\n".join(lines) + "\n"


def write_release(out, reveal=(), package_dir: Path = PACKAGE_DIR) -> list:
    """Write a student repository into ``out``; the files written."""
    from .readme import assignment_readme, index_readme

    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    written = [build_package(out, reveal, package_dir)]
    for rel, data in _checker_files(package_dir).items():
        target = out / "rtfgu" / "grading" / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(data)
        written.append(target)
    extra = {
        "README.md": _student_readme(reveal),
        "Makefile": STUDENT_MAKEFILE,
        "tests/test_visible.py": STUDENT_TEST,
        "assignments/README.md": index_readme(),
        ".gitignore": ".venv/\nrenders/\ncheck-results/\n__pycache__/\n*.pyc\n*.egg-info/\n",
    }
    for a in ASSIGNMENTS.values():
        extra["assignments/%s/README.md" % a.id] = assignment_readme(a)
    root = Path(package_dir).parent
    for name in ("pyproject.toml", "setup.cfg"):
        extra[name] = (root / name).read_text()
    for rel, text in extra.items():
        target = out / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(text)
        written.append(target)
    return written
