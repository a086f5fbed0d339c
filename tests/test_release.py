"""The student release: nothing in it computes an assigned function, no hidden test or
hidden reference is in it, and its checker fails on the stubs and passes on a solution."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from rtfgu.grading.assignments import block_table
from rtfgu.grading.generate import PACKAGE_DIR, find_blocks, source_text
from rtfgu.grading.release import build_package, probe_files, solves

ROOT = Path(__file__).resolve().parent.parent
TRIVIAL = re.compile(r"^(return|return (True|False|result|None|hit)|return (true|false);|else:|else \{|\}|\{|pass|"
                     r"continue|break|\)|\];?|\} else \{)$")


def solution_lines(revealed=()) -> dict:
    """Every non-trivial line of every solution block of an assignment not in ``revealed``
    (short ids) -> "file:function" it stands in."""
    lines = {}
    for relpath in sorted({key[0] for key in block_table()}):
        text = source_text(relpath)
        rows = text.split("\n")
        for qualname, begin, end, _ in find_blocks(text, relpath):
            if block_table()[(relpath, qualname)][0].short in revealed:
                continue
            for line in rows[begin + 1:end]:
                s = line.strip()
                if s and not s.startswith(("#", "//")) and not TRIVIAL.match(s):
                    lines[s] = "%s:%s" % (relpath, qualname)
    return lines


def solution_lines_in(folder: Path, revealed=()) -> list:
    """The solution lines (solution_lines) found as a line of any text file under ``folder``."""
    wanted = solution_lines(revealed)
    found = []
    for path in sorted(folder.rglob("*")):
        if not path.is_file() or path.suffix in (".png", ".pyc"):
            continue
        code = {line.strip() for line in path.read_text(errors="replace").split("\n")}
        found += ["%s (from %s) in %s" % (s, where, path.relative_to(folder)) for s, where in wanted.items()
                  if s in code]
    return found


def test_the_student_package_has_no_solution_line_no_twin_and_no_grader(tmp_path):
    package = build_package(tmp_path, reveal=("a01", "a02"))
    assert package == tmp_path / "rtfgu"
    assert len(solution_lines(("a01", "a02"))) > 40   # the scan looks for something
    assert solution_lines_in(package, ("a01", "a02")) == []
    assert not (package / "kernels").exists() and not (package / "hardcases").exists()
    assert not (package / "robust.py").exists() and not (package / "grading").exists()
    for path in package.rglob("*"):
        assert "__pycache__" not in path.parts and path.suffix not in (".nbi", ".nbc", ".pyc")
        if path.suffix in (".py", ".wgsl"):
            assert not solves(path.read_text()) - {1, 2}, path
    # the revealed assignments keep their solution, the others are stubbed in place
    assert "raise NotImplementedError" not in (package / "float3.py").read_text()
    assert "raise NotImplementedError('a03: Sphere.intersect_p')" in (package / "shapes" / "sphere.py").read_text()
    # every solution revealed: the twins ship
    full = build_package(tmp_path / "all", reveal=("a01", "a02", "a03", "a04", "a05", "a06"))
    assert (full / "kernels" / "intersect.py").is_file() and (full / "robust.py").is_file()


def test_the_probes_hold_no_hint_and_import_nothing_of_the_grader():
    files = probe_files()
    visible = probe_files(keep_hidden=False)
    assert "a03_hidden.py" in files and "a03.py" in files and "boot.py" in files
    assert not [name for name in visible if "hidden" in name]
    for name, text in files.items():
        if name.endswith(".py"):
            assert "def hint" not in text, name
            assert not re.search(r"^\s*from \.\.|^\s*(from|import) rtfgu\.grading", text, re.M), name

# Function names that compute an assigned function: the blocks' own names and the names
# their numba and WGSL twins go by. A name also matches with a suffix (intersect_sphere_robust).
TWIN_NAMES = {
    "a01": ("add", "sub", "mul", "neg", "div", "dot", "cross", "normalize", "length", "length_squared"),
    "a02": ("gen_ray", "get_camera_ray"),
    "a03": ("intersect_p", "normal_at", "intersect_plane", "intersect_sphere", "intersect_triangle",
            "normal_plane", "normal_sphere", "normal_triangle", "sphere_roots"),
    "a04": ("sample_point_light", "lambertian", "brdf_lambertian", "direct_light"),
    "a05": ("in_shadow", "phong", "brdf_phong", "mirror", "transparent", "glossy"),
    "a06": ("intersect_plane", "intersect_sphere", "intersect_triangle"),
}
TWIN_FOLDERS = ("kernels", "wgsl", "hardcases")
_DEF = re.compile(r"^\s*(?:def|fn)\s+(?P<name>\w+)\s*\(", re.M)


def _assigned_names() -> dict:
    """name -> the assignments (short ids) whose functions it computes."""
    names = {}
    for short, aliases in TWIN_NAMES.items():
        for name in aliases:
            names.setdefault(name, set()).add(short)
    for (_, qualname), (a, _) in block_table().items():
        name = qualname.split(".")[-1]
        if not name.startswith("__"):
            names.setdefault(name, set()).add(a.short)
    return names


def twin_candidates() -> dict:
    """relpath -> text of every file that may hold a twin (rtfgu/kernels, wgsl, hardcases, robust.py)."""
    paths = [PACKAGE_DIR / "robust.py"]
    for folder in TWIN_FOLDERS:
        paths += [p for p in sorted((PACKAGE_DIR / folder).rglob("*")) if p.suffix in (".py", ".wgsl")
                  and "__pycache__" not in p.parts and "__generated__" not in p.parts]
    return {p.relative_to(PACKAGE_DIR).as_posix(): p.read_text() for p in paths}


def unmarked_twins(files: dict) -> list:
    """(file, function, assignments) for every function in ``files`` (relpath -> text) named
    like an assigned function, outside a solution block, whose file's ``release: solves``
    marker names none of those assignments."""
    names = _assigned_names()
    problems = []
    for rel, text in files.items():
        own_blocks = {q.split(".")[-1] for q, *_ in find_blocks(text, rel)}
        marked = {"a%02d" % n for n in solves(text)}
        for m in _DEF.finditer(text):
            name = m.group("name")
            if name in own_blocks:
                continue   # the student's own file: its block is stubbed in place
            wanted = set()
            for assigned, shorts in names.items():
                if name == assigned or name.startswith(assigned + "_"):
                    wanted |= shorts
            if wanted and not wanted & marked:
                problems.append((rel, name, sorted(wanted)))
    return problems


def test_every_twin_of_an_assigned_function_is_marked():
    problems = unmarked_twins(twin_candidates())
    assert problems == [], ("add a line `# release: solves aNN` (`// release: solves aNN` in WGSL) "
                            "near the top of these files: %s" % problems)


def test_a_twin_without_its_marker_or_with_the_wrong_one_is_found():
    files = twin_candidates()
    unmarked = "\n".join(l for l in files["kernels/intersect.py"].split("\n") if "release: solves" not in l)
    problems = unmarked_twins({"kernels/intersect.py": unmarked})
    assert any(name.startswith("intersect_sphere") and "a03" in shorts for _, name, shorts in problems)
    wrong = files["wgsl/phong.wgsl"].replace("release: solves a05", "release: solves a04")
    assert [p[1] for p in unmarked_twins({"wgsl/phong.wgsl": wrong})] == ["brdf_phong"]
    # the student's own file: the function around its solution block ships stubbed
    assert unmarked_twins({"wgsl/intersect_sphere.wgsl": files["wgsl/intersect_sphere.wgsl"]}) == []
