"""The grader writes the bytecode of a test's package and probes (rtfgu.grading.bytecode):
a test's interpreter, which may not write them, imports every module from it, and uses none
whose source changed since."""
from __future__ import annotations

import hashlib
import os
import subprocess
import sys
from pathlib import Path

from rtfgu.grading import bytecode
from rtfgu.grading.assignments import get_assignment
from rtfgu.grading.generate import solution_files, write_files
from rtfgu.grading.probes.boot import SUBMODULES
from rtfgu.grading.sandbox import PROBES, _site_dirs, prepare


def _imports(ws, extra: str = "") -> str:
    """What ``python -I -S -B -v`` says while it imports the probes and the package as a
    test's interpreter does (boot.py), the workspace read-only to it as under bwrap (-B)."""
    code = ("import sys, importlib\n"
            "sys.path[:0] = %r\n"
            "importlib.import_module(%r)\n"
            "importlib.import_module(%r)\n"
            "for name in %r:\n"
            "    importlib.import_module('rtfgu.' + name)\n" % (
                [str(ws.package), str(ws.probes)] + _site_dirs(), PROBES, PROBES + ".support", SUBMODULES)) + extra
    done = subprocess.run([sys.executable, "-I", "-S", "-B", "-v", "-c", code], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr[-2000:]
    return done.stderr


def _compiled_from_source(log: str, roots) -> list:
    """The modules under ``roots`` that the interpreter compiled from their source."""
    roots = tuple(str(r) for r in roots)
    return [line for line in log.splitlines()
            if line.startswith("# code object from ") and ".pyc" not in line and roots and
            any(r in line for r in roots)]


def _from_bytecode(log: str, roots) -> list:
    return [line for line in log.splitlines()
            if line.startswith("# code object from ") and ".pyc" in line and any(str(r) in line for r in roots)]


def test_a_tests_interpreter_imports_the_package_and_the_probes_from_the_graders_bytecode(tmp_path):
    ws = prepare(get_assignment("a05"), None, tmp_path / "work")
    log = _imports(ws)
    roots = (ws.package, ws.probes)
    assert _compiled_from_source(log, roots) == []
    loaded = _from_bytecode(log, roots)
    assert any("float3" in line for line in loaded) and any("support" in line for line in loaded)
    assert len(loaded) > 40


def test_a_module_changed_after_its_bytecode_was_written_runs_its_source(tmp_path):
    """Hash-checked pycs: the bytecode of an earlier source is never run."""
    ws = prepare(get_assignment("a05"), None, tmp_path / "work")
    float3 = ws.package / "rtfgu" / "float3.py"
    os.chmod(float3, 0o600)
    float3.write_text(float3.read_text() + "\nCHANGED_AFTER_THE_BYTECODE = 1\n")
    log = _imports(ws, "import rtfgu.float3\nassert rtfgu.float3.CHANGED_AFTER_THE_BYTECODE == 1\n")
    compiled = _compiled_from_source(log, (ws.package, ws.probes))
    assert len(compiled) == 1 and compiled[0].endswith(os.path.join("rtfgu", "float3.py")), compiled


def test_a_submissions_code_is_compiled_for_its_grading_only(tmp_path):
    """The staff's files are compiled once per grader process; a submission's files are not
    kept for later gradings (a grade-all would keep every student's code)."""
    aid = "a01_float3_ray"
    folder = tmp_path / "submission"
    files = solution_files(aid)
    relpath = next(p for p in get_assignment(aid).files if p.endswith(".py"))
    files[relpath] = files[relpath] + "\n# a student's own line %s\n" % tmp_path.name
    write_files(files, folder)
    ws = prepare(get_assignment(aid), folder, tmp_path / "work")
    source = (ws.package / "rtfgu" / relpath).read_bytes()
    assert b"a student's own line" in source
    assert hashlib.sha256(source).digest() not in bytecode._KEPT
    log = _imports(ws)
    assert _compiled_from_source(log, (ws.package, ws.probes)) == []
    # a staff file of the same package is kept
    staff = (ws.package / "rtfgu" / "scene.py").read_bytes()
    assert hashlib.sha256(staff).digest() in bytecode._KEPT


def test_a_file_that_does_not_compile_gets_no_bytecode(tmp_path):
    (tmp_path / "bad.py").write_text("def broken(:\n")
    (tmp_path / "good.py").write_text("X = 1\n")
    assert bytecode.write_bytecode(tmp_path) == 1
    assert sorted(p.name.split(".")[0] for p in (tmp_path / "__pycache__").iterdir()) == ["good"]
    assert Path(tmp_path / "bad.py").read_text() == "def broken(:\n"


def test_a_tests_interpreter_imports_no_pillow(tmp_path):
    """Pillow is imported where a PNG is written or read (rtfgu.image, rtfgu.notebook), not by
    the modules every test's interpreter imports: 14 ms of each test's 0.15 s otherwise."""
    ws = prepare(get_assignment("a05"), None, tmp_path / "work")
    log = _imports(ws, "assert 'PIL' not in sys.modules, sorted(m for m in sys.modules if 'PIL' in m)\n"
                       "from rtfgu.image import read_png, write_png\n"
                       "import numpy\n"
                       "write_png(numpy.full((2, 3, 3), 0.5), %r)\n"
                       "assert read_png(%r).shape == (2, 3, 3)\n"
                       "assert 'PIL' in sys.modules\n" % (str(tmp_path / "a.png"), str(tmp_path / "a.png")))
    assert "import 'PIL" in log
