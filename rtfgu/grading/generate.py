"""The student version of the lecture layer, generated from the marked solutions.

Each ``### BEGIN SOLUTION`` ... ``### END SOLUTION`` block (``// ### BEGIN SOLUTION`` in
WGSL) is replaced, at its indentation, by the TODO text and a
``raise NotImplementedError("a03: Sphere.intersect_p")`` (in WGSL a stub that compiles).
A student file of assignment k stubs the blocks of assignment k and of every later
assignment, and keeps the solutions of the earlier ones (released by then).

``assignments/`` holds, for every assignment, its README and its student files under their
paths in the package (``shapes/sphere.py``); it is exactly what ``generate_tree`` returns.
"""
from __future__ import annotations

import re
from pathlib import Path

from .assignments import ASSIGNMENTS, Assignment, block_table, get_assignment

PACKAGE_DIR = Path(__file__).resolve().parent.parent

_BEGIN = re.compile(r"^(?P<indent>[ \t]*)(?://[ \t]*)?### BEGIN SOLUTION\s*$")
_END = re.compile(r"^[ \t]*(?://[ \t]*)?### END SOLUTION\s*$")
_PY_DEF = re.compile(r"^(?P<indent>[ \t]*)(?:async\s+)?def\s+(?P<name>\w+)\s*\(")
_PY_CLASS = re.compile(r"^(?P<indent>[ \t]*)class\s+(?P<name>\w+)\b")
_WGSL_FN = re.compile(r"^(?P<indent>[ \t]*)fn\s+(?P<name>\w+)\s*\(")


def _enclosing_name(lines, index, indent, language):
    """The qualified name of the function around line ``index`` (Class.method or function)."""
    fn_pattern = _WGSL_FN if language == "wgsl" else _PY_DEF
    name, fn_indent = None, None
    for i in range(index - 1, -1, -1):
        m = fn_pattern.match(lines[i])
        if m and len(m.group("indent")) < len(indent):
            name, fn_indent = m.group("name"), len(m.group("indent"))
            break
    if name is None:
        return None
    if language == "python":
        for i in range(i - 1, -1, -1):
            m = _PY_CLASS.match(lines[i])
            if m and len(m.group("indent")) < fn_indent:
                return m.group("name") + "." + name
            if lines[i].strip() and len(lines[i]) - len(lines[i].lstrip()) < fn_indent \
                    and not lines[i].lstrip().startswith(("#", "@", ")", '"', "'")):
                break
    return name


def find_blocks(text: str, filename: str):
    """[(qualname, begin line index, end line index, indent)] of the marked blocks in ``text``."""
    language = "wgsl" if filename.endswith(".wgsl") else "python"
    lines = text.split("\n")
    blocks, open_at = [], None
    for i, line in enumerate(lines):
        m = _BEGIN.match(line)
        if m:
            if open_at is not None:
                raise ValueError("%s line %d: BEGIN SOLUTION inside another block" % (filename, i + 1))
            open_at = (i, m.group("indent"))
        elif _END.match(line):
            if open_at is None:
                raise ValueError("%s line %d: END SOLUTION without BEGIN" % (filename, i + 1))
            qualname = _enclosing_name(lines, open_at[0], open_at[1], language)
            if qualname is None:
                raise ValueError("%s line %d: a solution block outside any function" % (filename, open_at[0] + 1))
            blocks.append((qualname, open_at[0], i, open_at[1]))
            open_at = None
    if open_at is not None:
        raise ValueError("%s line %d: BEGIN SOLUTION without END" % (filename, open_at[0] + 1))
    return blocks


def _stub_lines(assignment: Assignment, block, indent: str, language: str):
    tag = "%s: %s" % (assignment.short, block.qualname)
    if language == "wgsl":
        out = [indent + "// TODO " + tag]
        out += [indent + "//   " + line for line in block.todo.split("\n")]
        out += [indent + line for line in block.stub.split("\n")]
        return out
    out = [indent + "# TODO " + tag]
    out += [indent + "#   " + line for line in block.todo.split("\n")]
    out.append(indent + "raise NotImplementedError(%r)" % tag)
    return out


def transform(text: str, filename: str, stub_from: int | None, language_of=None,
              revealed=None) -> str:
    """The file with every block of an assignment numbered >= ``stub_from`` replaced by its
    stub and every other block's markers removed (the solution kept). ``stub_from=None``
    keeps every solution (the solved student file). With ``revealed`` (a set of assignment
    numbers) instead, every block of an assignment not in it is stubbed."""
    table = block_table()
    language = "wgsl" if filename.endswith(".wgsl") else "python"
    lines = text.split("\n")
    out, cursor = [], 0
    for qualname, begin, end, indent in find_blocks(text, filename):
        key = (filename, qualname)
        if key not in table:
            raise ValueError("%s: the solution block in %s belongs to no assignment "
                             "(add it to rtfgu/grading/assignments.py)" % (filename, qualname))
        assignment, block = table[key]
        out.extend(lines[cursor:begin])
        stub = (assignment.number not in revealed if revealed is not None
                else stub_from is not None and assignment.number >= stub_from)
        if stub:
            out.extend(_stub_lines(assignment, block, indent, language))
        else:
            out.extend(lines[begin + 1:end])
        cursor = end + 1
    out.extend(lines[cursor:])
    return "\n".join(out)


def source_text(relpath: str, package_dir: Path = PACKAGE_DIR) -> str:
    return (package_dir / relpath).read_text()


def student_files(assignment, package_dir: Path = PACKAGE_DIR) -> dict:
    """relpath -> text of the assignment's files as the student gets them (stubs)."""
    a = get_assignment(assignment) if isinstance(assignment, str) else assignment
    return {f: transform(source_text(f, package_dir), f, a.number) for f in a.files}


def solution_files(assignment, package_dir: Path = PACKAGE_DIR) -> dict:
    """relpath -> text of the assignment's files solved, laid out as a submission."""
    a = get_assignment(assignment) if isinstance(assignment, str) else assignment
    return {f: transform(source_text(f, package_dir), f, None) for f in a.files}


def check_markers(package_dir: Path = PACKAGE_DIR) -> None:
    """Every block in the table is marked in its file exactly once, and every marked block
    is in the table; a ValueError naming the block otherwise."""
    table = block_table()
    seen = {}
    for relpath in sorted({key[0] for key in table}):
        for qualname, *_ in find_blocks(source_text(relpath, package_dir), relpath):
            seen[(relpath, qualname)] = seen.get((relpath, qualname), 0) + 1
    for key in table:
        if seen.get(key, 0) != 1:
            raise ValueError("solution block %s:%s is marked %d times (expected once)"
                             % (key[0], key[1], seen.get(key, 0)))
    for key in seen:
        if key not in table:
            raise ValueError("%s: the marked block in %s belongs to no assignment" % key)


def write_files(files: dict, out_dir) -> list:
    out_dir = Path(out_dir)
    written = []
    for relpath, text in files.items():
        path = out_dir / relpath
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
        written.append(path)
    return written


def generate_tree(package_dir: Path = PACKAGE_DIR) -> dict:
    """relpath (under assignments/) -> text: every assignment's README and student files."""
    from .readme import assignment_readme, index_readme

    check_markers(package_dir)
    tree = {"README.md": index_readme()}
    for a in ASSIGNMENTS.values():
        tree[a.id + "/README.md"] = assignment_readme(a)
        for relpath, text in student_files(a, package_dir).items():
            tree[a.id + "/" + relpath] = text
    return tree


def _existing(out_dir: Path) -> dict:
    found = {}
    if out_dir.is_dir():
        for path in sorted(out_dir.rglob("*")):
            if path.is_file() and "__pycache__" not in path.parts:
                found[path.relative_to(out_dir).as_posix()] = path.read_text()
    return found


def compare_tree(out_dir) -> list:
    """Differences between ``out_dir`` and what the generator produces, in words."""
    want = generate_tree()
    have = _existing(Path(out_dir))
    problems = []
    for relpath in sorted(set(want) | set(have)):
        if relpath not in have:
            problems.append("missing: %s" % relpath)
        elif relpath not in want:
            problems.append("not generated (remove it): %s" % relpath)
        elif want[relpath] != have[relpath]:
            problems.append("differs from the generator: %s" % relpath)
    return problems


def write_tree(out_dir) -> list:
    """Write the generated tree to ``out_dir``, removing files the generator no longer makes."""
    out_dir = Path(out_dir)
    tree = generate_tree()
    for relpath in _existing(out_dir):
        if relpath not in tree:
            (out_dir / relpath).unlink()
    return write_files(tree, out_dir)


_REGION = re.compile(r"^[ \t]*#[ \t]*### (?P<edge>BEGIN|END) (?P<tag>HIDDEN|STAFF)\s*$")


def strip_regions(text: str, tags, filename: str = "") -> str:
    """``text`` without the lines between ``# ### BEGIN TAG`` and ``# ### END TAG`` for every
    TAG in ``tags`` (the markers of the other tags removed, their lines kept). HIDDEN marks
    the hidden tests of a check module (left out of a student release), STAFF grader code
    that must not run next to student code (left out of the release and of the sandbox)."""
    out, inside = [], None
    for number, line in enumerate(text.split("\n"), start=1):
        m = _REGION.match(line)
        if m:
            if m.group("edge") == "BEGIN":
                if inside is not None:
                    raise ValueError("%s line %d: BEGIN %s inside %s" % (filename, number, m.group("tag"), inside))
                inside = m.group("tag")
            else:
                if inside != m.group("tag"):
                    raise ValueError("%s line %d: END %s without BEGIN" % (filename, number, m.group("tag")))
                inside = None
            continue
        if inside is None or inside not in tags:
            out.append(line)
    if inside is not None:
        raise ValueError("%s: BEGIN %s without END" % (filename, inside))
    return "\n".join(out)
