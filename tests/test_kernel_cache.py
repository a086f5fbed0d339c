"""The numba cache's folder is named by rtfgu.kernels.dispatch.kernel_version: a hash of what
the compiled kernels depend on. numba checks only the file of the function it loads from
its cache, and it compiles the values of the globals a kernel reads into the code, so the
version must change with every value a kernel imports from the rest of the package (a
tracer's depth, the wide BVH's rows, the layout's offsets), and need not change with a
lecture file no kernel reads."""
from __future__ import annotations

import ast
import shutil
import subprocess
import sys
from pathlib import Path

import rtfgu
from rtfgu.kernels import dispatch

PACKAGE = Path(rtfgu.__file__).resolve().parent


def _imports_by_ast() -> list:
    """(module, names) of the kernels' ``from ..module import`` statements, read by Python's
    own parser."""
    found = set()
    for path in sorted((PACKAGE / "kernels").glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            if isinstance(node, ast.ImportFrom) and node.level == 2:
                module = "rtfgu" + ("." + node.module if node.module else "")
                if module != "rtfgu.kernels" and not module.startswith("rtfgu.kernels."):
                    found.add((module, tuple(sorted(alias.name for alias in node.names))))
    return sorted(found)


def test_kernel_imports_finds_every_import_the_parser_finds():
    found = dispatch.kernel_imports()
    assert found == _imports_by_ast()
    modules = {module for module, _ in found}
    # Constants compiled into the kernels, each from a file outside the kernels' folder.
    assert {"rtfgu.accelerators.wide_bvh", "rtfgu.tracers.path_trace", "rtfgu.noise.lattice_noise",
            "rtfgu.layout", "rtfgu.registry"} <= modules


def test_package_imports_reads_parentheses_aliases_comments_and_indented_imports():
    text = ("from ..layout import (A,  # the first\n    B as C,\n    D)\n"
            "from ..registry import E  # a comment\n"
            "def f():\n    from ..x.y import F, G\n"
            "from . import kernel_local\nfrom .. import layout\n"
            "text = 'from ..inside import a string'\n")
    assert dispatch.package_imports(text) == [
        ("rtfgu.layout", ("A", "B", "D")), ("rtfgu.registry", ("E",)), ("rtfgu.x.y", ("F", "G")),
        ("rtfgu", ("layout",))]


VERSION = """
import sys
sys.path.insert(0, sys.argv[1])
import rtfgu
assert rtfgu.__file__.startswith(sys.argv[1]), rtfgu.__file__
from rtfgu.kernels.dispatch import kernel_version
print(kernel_version())
"""


def _version(root: Path) -> str:
    done = subprocess.run([sys.executable, "-c", VERSION, str(root)], capture_output=True, text=True, timeout=120,
                          env={"PATH": "/usr/bin:/bin", "RTFGU_CACHE_DIR": str(root / "cache"),
                               "NUMBA_CACHE_DIR": ""})
    assert done.returncode == 0, done.stderr
    return done.stdout.strip()


def test_a_constant_a_kernel_imports_names_a_new_cache_folder_and_a_lecture_comment_does_not(tmp_path):
    shutil.copytree(PACKAGE, tmp_path / "rtfgu", ignore=shutil.ignore_patterns("__pycache__", "__generated__"))
    before = _version(tmp_path)
    # A comment in a lecture file that no kernel imports from: the kernels are the same.
    sphere = tmp_path / "rtfgu" / "shapes" / "sphere.py"
    sphere.write_text(sphere.read_text() + "\n# a comment\n")
    assert _version(tmp_path) == before
    # The path tracer's Russian roulette depth, which the numba path tracer compiles in.
    tracer = tmp_path / "rtfgu" / "tracers" / "path_trace.py"
    text = tracer.read_text()
    assert text.count("\nROULETTE_DEPTH = ") == 1
    start = text.index("\nROULETTE_DEPTH = ") + len("\nROULETTE_DEPTH = ")
    end = text.index("\n", start)
    tracer.write_text(text[:start] + str(int(text[start:end].split()[0]) + 1) + text[end:])
    changed = _version(tmp_path)
    assert changed != before
    # The wide BVH's node layout, read by the traversal.
    wide = tmp_path / "rtfgu" / "accelerators" / "wide_bvh.py"
    wide.write_text(wide.read_text() + "\n# a comment\n")
    assert _version(tmp_path) != changed
