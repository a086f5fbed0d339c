"""A student release: the package with every assigned function stubbed in place, and nothing
that computes one a second time.

``build_package(dest, reveal)`` writes ``dest/rtfgu``:

* every ``### BEGIN SOLUTION`` block of an assignment not in ``reveal`` is replaced by its
  stub (rtfgu.grading.generate.transform), the blocks of revealed assignments keep their
  solution without the markers;
* a file with a line ``# release: solves a03 a04`` (``// release: ...`` in WGSL) among its
  first MARKER_LINES lines
  computes those assignments' functions again (a numba or WGSL twin, a robust variant, a
  hard-case evaluator) and is left out unless every one of them is revealed; a package whose
  ``__init__.py`` is left out is left out whole;
* ``rtfgu/grading`` is left out: the package a submission runs in holds nothing of the grader.

``write_release(out, reveal)`` writes a whole student repository: that package, the student
checker ``rtfgu_checker/`` (the visible tests only: their checks and hints, probes and
references, run by rtfgu.grading.local), the assignments' READMEs, a Makefile and a README.
"""
from __future__ import annotations

import json
import os
import re
import shutil
from pathlib import Path

from .assignments import ASSIGNMENTS, get_assignment
from .generate import PACKAGE_DIR, strip_regions, transform, write_files
from .local import FULL_SIZE
from .pixels import SUFFIX as PIXELS_SUFFIX, expected_pixels

MARKER = re.compile(r"^\s*(?:#|//)\s*release: solves\s+(?P<ids>[a0-9 ]+?)\s*$")
MARKER_LINES = 5        # a marker sits on one of a file's first lines
SKIP_NAMES = {"__pycache__", "__generated__", ".pytest_cache"}
SKIP_SUFFIXES = (".pyc", ".nbi", ".nbc")
TEXT_SUFFIXES = (".py", ".wgsl")
# Shown when a student runs a file of the package directly (python rtfgu/shapes/sphere.py).
RUN_GUARD = ('if __name__ == "__main__" and not __package__:\n'
             '    raise SystemExit("rtfgu/%s is part of the rtfgu package and is not run on its own: "\n'
             '                     "%s")\n')


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


def _owners(relpath: str) -> list:
    """The assignments whose student file ``relpath`` is (brdfs/lambertian.py: a04 and a09)."""
    return [a for a in ASSIGNMENTS.values() if relpath in a.files]


def how_to_run(assignments) -> str:
    """What a student runs instead of a file of ``assignments``: their tests, and their
    images when they have any."""
    def command(target, shorts):
        return "`make %s A=%s`" % (target, shorts[0]) + "".join(" (or A=%s)" % s for s in shorts[1:])

    text = "test it with " + command("check", [a.short for a in assignments])
    rendered = [a.short for a in assignments if a.images]
    if rendered:
        text += ", render it with " + command("render", rendered)
    return text


def _skipped(path: Path) -> bool:
    return any(part in SKIP_NAMES for part in path.parts) or path.name.endswith(SKIP_SUFFIXES)


def _package_paths(package_dir: Path) -> list:
    """Every path under ``package_dir`` but the grader (grading/) and the folders never
    shipped (SKIP_NAMES: the numba cache's thousands of files among them), in sorted order."""
    found = []
    for folder, dirs, names in os.walk(package_dir):
        top = folder == str(package_dir)
        dirs[:] = [d for d in dirs if d not in SKIP_NAMES and not (top and d == "grading")]
        found.extend(Path(folder, name) for name in dirs + names)
    return sorted(found)


def package_files(reveal=(), package_dir: Path = PACKAGE_DIR) -> dict:
    """relpath (under rtfgu/) -> bytes of every file of the student package."""
    revealed = revealed_numbers(reveal)
    package_dir = Path(package_dir)
    left_out_dirs = []
    files = {}
    for path in _package_paths(package_dir):
        rel = path.relative_to(package_dir)
        if not path.is_file() or _skipped(rel):
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
            owners = _owners(rel.as_posix())
            if owners and path.suffix == ".py":
                text = _with_run_guard(text, rel.as_posix(), owners)
            files[rel.as_posix()] = text.encode()
        else:
            files[rel.as_posix()] = path.read_bytes()
    return files


def _with_run_guard(text: str, relpath: str, owners: list) -> str:
    """The student file with a guard before its imports: run on its own, it says how to
    test it instead of failing on a relative import."""
    guard = RUN_GUARD % (relpath, how_to_run(owners))
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


def probe_files(package_dir: Path = PACKAGE_DIR, keep_hidden: bool = True, hidden_table: bool | None = None) -> dict:
    """name -> text of the code that runs next to student code: the modules of
    rtfgu/grading/probes (without the hidden tests' ``*_hidden.py`` unless ``keep_hidden``)
    and ``tests.json``, each test's probe by assignment and slug (boot.py's ``check``
    command reads it), the hidden tests' among them where ``hidden_table`` (by default
    ``keep_hidden``; the grader leaves them out: their inputs are in its own call of the probe,
    and every test's code could read the table). Copied into one folder, they form a package
    of any name."""
    from .checks import checks_for

    folder = Path(package_dir) / "grading" / "probes"
    files = {p.name: p.read_text() for p in sorted(folder.glob("*.py"))
             if keep_hidden or not is_hidden_probe(p.stem)}
    table = {}
    for a in ASSIGNMENTS.values():
        table[a.id] = {c.slug: list(c.probe) for c in checks_for(a.id)
                       if (keep_hidden if hidden_table is None else hidden_table) or c.visibility == "visible"}
    files["tests.json"] = json.dumps(table, indent=1, sort_keys=True) + "\n"
    return files


def is_hidden_probe(module: str) -> bool:
    """Whether probe module ``module`` holds hidden tests' probes (never in a release)."""
    return module.endswith("_hidden")


# --- the student repository ---------------------------------------------------------------

CHECKER = "rtfgu_checker"              # the student checker's package in a release
CHECKER_MODULES = ("assignments.py", "results.py", "local.py", "pixels.py", "timeouts.py")


def checker_files(package_dir: Path = PACKAGE_DIR) -> dict:
    """relpath (under rtfgu_checker/) -> bytes: the student checker. It holds the visible
    tests only: their checks and hints (rtfgu/grading/checks without the HIDDEN regions),
    their probes (no ``*_hidden.py``), their reference observations, known mistakes and
    images; rtfgu.grading.local runs them."""
    from .checks import checks_for, traces_a_scene

    grading = Path(package_dir) / "grading"
    files = {
        "__init__.py": b'"""The student checker: the visible tests of every assignment, run on your rtfgu\n'
                       b'(python -m rtfgu_checker check a03, or make check A=a03)."""\n',
        "__main__.py": b"import sys\n\nfrom .local import main\n\nsys.exit(main())\n",
    }
    for name in CHECKER_MODULES:
        files[name] = (grading / name).read_bytes()
    for path in sorted((grading / "checks").glob("*.py")):
        files["checks/" + path.name] = strip_regions(path.read_text(), ("HIDDEN", "STAFF"), path.name).encode()
    for name, text in probe_files(package_dir, keep_hidden=False).items():
        if name.endswith(".py"):
            files["probes/" + name] = text.encode()
    for a in ASSIGNMENTS.values():
        folder = grading / "reference" / a.id
        visible = [c for c in checks_for(a.id) if c.visibility == "visible"]
        for name in ("observations.json", "known.json"):
            if (folder / name).is_file():
                data = json.loads((folder / name).read_text())
                kept = {c.slug: data[c.slug] for c in visible if c.slug in data}
                files["reference/%s/%s" % (a.id, name)] = (json.dumps(kept, indent=1, sort_keys=True) + "\n").encode()
        for c in visible:
            png = folder / (c.slug + ".png")
            if c.kind == "image" and png.is_file():
                files["reference/%s/%s" % (a.id, png.name)] = png.read_bytes()
                if traces_a_scene(c):
                    files["reference/%s/%s%s" % (a.id, c.slug, PIXELS_SUFFIX)] = expected_pixels(c)
    return files


STUDENT_MAKEFILE = """\
# Your copy of rtfgu. A is an assignment (a03 or a03_intersections).
#   make check A=a03    the assignment's visible tests on your code (diff images in check-results/a03/diffs/)
#   make render A=a03   the assignment's images rendered with your code, into renders/a03/, each
#                       compared with its full-size reference (renders/a03/<image>_diff.png where they differ)
#                       (W=48 H=48: at the size of the image tests, whose pixels their messages name)
#   make html A=a06     the assignment's images as WebGPU pages of your code (your WGSL), into html/a06/
#   make debug-pixel A=a03 T=3.8 X=16 Y=32
#                       one pixel of image test 3.8, traced through your code beside the expected values
#   make test [A=a03]   every assignment's (or one's) visible tests, through pytest
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed

.PHONY: check render html debug-pixel test venv clean

# pip's and setuptools' chatter goes to .venv/install.log, shown only if the install fails.
$(STAMP): setup.cfg pyproject.toml
\t@test -x $(PY) || $(PYTHON) -m venv $(VENV)
\t@echo "installing rtfgu and what it needs into $(VENV), once (log: $(VENV)/install.log)"
\t@{ $(PY) -m pip install --quiet --upgrade pip && $(PY) -m pip install --quiet -e '.[test]'; } \\
\t  > $(VENV)/install.log 2>&1 || { cat $(VENV)/install.log; exit 1; }
\t@touch $(STAMP)

venv: $(STAMP)

check: $(STAMP)
\t$(PY) -m rtfgu_checker check $(A)

render: $(STAMP)
\t$(PY) -m rtfgu_checker render $(A) $(if $(W),--width $(W)) $(if $(H),--height $(H))

html: $(STAMP)
\t$(PY) -m rtfgu_checker html $(A) $(if $(W),--width $(W)) $(if $(H),--height $(H))

debug-pixel: $(STAMP)
\t$(PY) -m rtfgu_checker debug-pixel $(A) $(T) $(X) $(Y)

test: $(STAMP)
\t$(PY) -m pytest $(if $(A),-k $(A))

clean:
\trm -rf $(VENV) renders check-results html
"""

STUDENT_TEST = '''"""Every assignment's visible tests on your code, one pytest test each (make test)."""
import pytest

from rtfgu_checker.assignments import ASSIGNMENTS
from rtfgu_checker.checks import checks_for
from rtfgu_checker.local import check

# A test's id starts with its assignment's id (a03_intersections-...): `pytest -k a03` selects a03's.
CASES = [(a.id, c.slug) for a in ASSIGNMENTS.values() for c in checks_for(a.id) if c.visibility == "visible"]


@pytest.mark.parametrize("assignment,test", CASES)
def test_visible(assignment, test):
    result = check(assignment, ".", only=(test,))
    assert result.tests and result.tests[0].status == "passed", result.tests[0].output
'''

STUDENT_SETUP = """\
[metadata]
name = rtfgu
version = 0.1.0
description = Your copy of rtfgu, a teaching ray tracer after Suffern's Ray Tracing from the Ground Up

[options]
packages = find_namespace:
python_requires = >=3.10
include_package_data = True
install_requires =
%(requires)s

[options.packages.find]
include = rtfgu, rtfgu.*, rtfgu_checker, rtfgu_checker.*

[options.package_data]
rtfgu = %(package_data)s
rtfgu_checker = reference/*/*, reference/*/full_size/*

[options.extras_require]
test =
    pytest>=7
# Jupyter for notebooks/ and rtfgu.show: pip install -e '.[notebook]', then jupyter lab
notebook =
    ipykernel>=6
    jupyterlab>=4

[tool:pytest]
testpaths = tests
addopts = -ra
"""



def _staff_requirements(package_dir) -> tuple:
    """The staff setup.cfg's runtime dependencies and the package's data files, so that a
    release installs what the package it carries needs (textures' images, meshes, trimesh)."""
    import configparser

    config = configparser.ConfigParser()
    config.read(Path(package_dir).parent / "setup.cfg")
    requires = [line.strip() for line in config["options"]["install_requires"].splitlines() if line.strip()]
    return requires, config["options.package_data"]["rtfgu"].strip()

def full_size_references(log=None) -> dict:
    """relpath (under rtfgu_checker/) -> PNG bytes: every assignment's homework images at their
    registered size, rendered by the solution, for ``make render A=..`` to compare the student's
    renders with (rtfgu.grading.local.render). The numba path in float64 with the slide's
    formulas computes the lecture layer's images bit for bit (tests/test_numba_parity.py) and
    fast; the lecture layer renders them where numba is not installed."""
    import io

    from ..image import to_8bit
    from ..renderer import render
    from ..scenes import get_scene
    from PIL import Image

    try:
        import numba  # noqa: F401
        path = {"backend": "numba", "precision": "float64", "formula": "slide"}
    except ImportError:
        path = {"backend": "reference"}
    files, images = {}, {}
    for a in ASSIGNMENTS.values():
        for name in a.images:
            if name not in images:
                if log:
                    log("rendering the reference of %s (%s)" % (name, path["backend"]))
                fn = get_scene(name)
                out = io.BytesIO()
                Image.fromarray(to_8bit(render(fn(), *fn.size, **path)), mode="RGB").save(out, format="PNG")
                images[name] = out.getvalue()
            files["reference/%s/%s/%s.png" % (a.id, FULL_SIZE, name)] = images[name]
    return files


def _student_readme(reveal, assignments) -> str:
    ids = ", ".join(sorted(get_assignment(r).short for r in reveal)) or "none"
    lines = [
        "# rtfgu: your copy",
        "",
        "A teaching ray tracer after Suffern's *Ray Tracing from the Ground Up*. Every function an",
        "assignment asks for is in the package itself: open the file its README names (for",
        "example `rtfgu/shapes/sphere.py` for a03) and replace each `raise NotImplementedError`",
        "under a `# TODO` with your code. Change nothing else in the file: the grader runs your",
        "file inside this same package.",
        "",
        "```",
        "make check A=a03     # a03's visible tests on your code",
        "make render A=a03    # a03's images rendered with your code, into renders/a03/, each compared",
        "                     # with the reference (renders/a03/<image>_diff.png where they differ)",
        "make test            # every assignment's visible tests (pytest); make test A=a03: a03's only",
        "```",
        "",
        "The first `make` creates `.venv` and installs the package and pytest (Python 3.10 or",
        "newer). `make check` prints each test's points and, for a test that fails, what your",
        "code gave back and what it should have, often with a hint. It writes",
        "`check-results/<aNN>/summary.txt`, and for every image test a diff image",
        "`check-results/<aNN>/diffs/<test>.png`: your render | the reference | the pixels that",
        "differ: red where yours has a colour the reference lacks near there, blue where the",
        "reference has one yours lacks (a missing object). The grader runs these tests and hidden",
        "ones like them.",
        "",
        "A failing image test names its worst pixel and the command that traces it through your",
        "code beside what the solution computes there, ray by ray: the shape hit, t, the normal,",
        "the shader and the colour, with the first value that differs marked:",
        "",
        "```",
        "make debug-pixel A=a03 T=3.8 X=16 Y=32    # test 3.8, column 16, row 32 (row 0 at the top)",
        "```",
        "",
        "`make html A=a06` writes the assignment's images as web pages that render your WGSL with",
        "WebGPU in the browser, as the 02562 worksheets do (`html/a06/`; Chrome or Edge).",
        "",
        "`notebooks/first_render.ipynb` renders a scene and shows it as it refines, traces a pixel",
        "and changes a material: `.venv/bin/pip install -e '.[notebook]'`, then `.venv/bin/jupyter lab`.",
        "Outside a notebook `rtfgu.show(scene, w, h)` writes the image to `rtfgu_show.png` and says so.",
        "",
        "A file of the package is not a program: `python rtfgu/shapes/sphere.py` only tells you",
        "to run `make check`. To try your code yourself, `.venv/bin/python -c 'import rtfgu; ...'`",
        "from this folder; `rtfgu.render(scene, w, h)` renders with the lecture layer.",
        "",
        "## Assignments",
        "",
    ]
    for a in assignments:
        lines.append("- `%s`: %s, in %s (README: `assignments/%s/README.md`)"
                     % (a.short, a.title, ", ".join("`rtfgu/%s`" % f for f in a.files), a.id))
    lines += [
        "",
        "Solutions revealed in this copy (their functions are written for you): %s." % ids,
        "",
        "The numba and WGSL paths of the full renderer compute the assignments' functions again,",
        "so they are not part of this copy: `rtfgu.render(..., backend=\"numba\")` says so.",
    ]
    return "\n".join(lines) + "\n"


def _notebook_without_outputs(path: Path) -> str:
    """The notebook with its outputs cleared: the course tree's saved images come from paths a
    release does not carry; the student's first run makes their own."""
    notebook = json.loads(path.read_text())
    for cell in notebook["cells"]:
        if cell["cell_type"] == "code":
            cell["outputs"], cell["execution_count"] = [], None
    return json.dumps(notebook, indent=1) + "\n"


def write_release(out, reveal=(), package_dir: Path = PACKAGE_DIR) -> list:
    """Write a student repository into ``out``: the package (build_package), the student
    checker (checker_files) as rtfgu_checker/, the assignments' READMEs, a Makefile, a
    setup.cfg with the runtime dependencies and pytest, a pytest file and a README.
    Returns the files written."""
    from .readme import assignment_readme, index_readme

    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    package = build_package(out, reveal, package_dir)
    written = [p for p in sorted(package.rglob("*")) if p.is_file()]
    for rel, data in dict(checker_files(package_dir), **full_size_references()).items():
        target = out / CHECKER / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(data)
        written.append(target)
    # A student file that computes an unrevealed assignment's function again (it carries a
    # marker) is left out with the rest: its README says which reveal brings it.
    revealed = revealed_numbers(reveal)
    absent = {f: sorted("a%02d" % n for n in solves((Path(package_dir) / f).read_text()) - revealed)
              for a in ASSIGNMENTS.values() for f in a.files if not (package / f).is_file()}
    requires, package_data = _staff_requirements(package_dir)
    if not (package / "kernels").is_dir():
        requires = [r for r in requires if not r.startswith("numba")]
    extra = {
        "README.md": _student_readme(reveal, list(ASSIGNMENTS.values())),
        "Makefile": STUDENT_MAKEFILE,
        "setup.cfg": STUDENT_SETUP % {"requires": "\n".join("    " + r for r in requires),
                                      "package_data": package_data},
        "pyproject.toml": (Path(package_dir).parent / "pyproject.toml").read_text(),
        "tests/test_visible.py": STUDENT_TEST,
        "assignments/README.md": index_readme(release=True, absent=absent),
        ".gitignore": ".venv/\nrenders/\ncheck-results/\nhtml/\n__pycache__/\n*.pyc\n*.egg-info/\n",
        "notebooks/first_render.ipynb": _notebook_without_outputs(Path(package_dir).parent / "notebooks"
                                                                  / "first_render.ipynb"),
    }
    for a in ASSIGNMENTS.values():
        extra["assignments/%s/README.md" % a.id] = assignment_readme(a, release=True, absent=absent)
    written += write_files(extra, out)
    return written
