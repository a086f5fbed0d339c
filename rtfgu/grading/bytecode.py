"""The bytecode of the package and probes a test's interpreter imports, written by the grader.

Each test runs in a new interpreter (rtfgu.grading.sandbox.run_child), which imports the
student package and the probes from folders it may not write: bwrap binds them read-only,
and the sandbox user of the fallback cannot write the root-owned work folder. Python then
compiled every module it imports again, in every test, and kept nothing: a test took
0.25-0.3 s under bwrap, and 0.13-0.15 s once it reads the grader's files
(docs/grading_sandbox.md, "Time per submission"). ``write_bytecode`` writes each module's ``__pycache__`` file before the
first test, so a test's interpreter reads it instead (PEP 3147 names, as
``importlib.util.cache_from_source`` gives them).

The files are hash-checked pycs (PEP 552, ``py_compile.PycInvalidationMode.CHECKED_HASH``):
the interpreter uses one only while its source still has the hash it was made from, and
otherwise compiles the source as before; no modification time is involved. The code is
compiled as the import system compiles a source (``compile(source, path, "exec",
dont_inherit=True)``, at optimisation level 0, which the tests' interpreters run at), and the
import system puts the file's own path into it when it loads it. The staff's files are the same
in every grading: their code is compiled once per grader process and kept, by the source's
hash. A submission's files are compiled for their grading only and not kept (a
grade-all process would otherwise keep every student's code).
"""
from __future__ import annotations

import hashlib
import importlib.util
import marshal
from pathlib import Path

FLAGS_CHECKED_HASH = (0b11).to_bytes(4, "little")   # hash-based, checked against the source
_KEPT: dict = {}                                     # sha256 of a staff source -> marshalled code


def pyc_bytes(source: bytes, filename: str, keep: bool = True) -> bytes | None:
    """The hash-checked pyc of ``source``, or None where it does not compile (the test's
    interpreter then reports the error as it would have)."""
    key = hashlib.sha256(source).digest()
    code = _KEPT.get(key)
    if code is None:
        try:
            code = marshal.dumps(compile(source, filename, "exec", dont_inherit=True, optimize=0))
        except (SyntaxError, ValueError):
            return None
        if keep:
            _KEPT[key] = code
    return importlib.util.MAGIC_NUMBER + FLAGS_CHECKED_HASH + importlib.util.source_hash(source) + code


def write_bytecode(folder, fresh=()) -> int:
    """Write the pyc of every ``*.py`` under ``folder`` (links left alone) beside it in
    ``__pycache__``; ``fresh``: paths whose code is not kept for later gradings (a
    submission's). Returns the number written."""
    fresh = {Path(p) for p in fresh}
    written = 0
    for path in sorted(Path(folder).rglob("*.py")):
        if path.is_symlink() or not path.is_file() or "__pycache__" in path.parts:
            continue
        data = pyc_bytes(path.read_bytes(), str(path), keep=path not in fresh)
        if data is None:
            continue
        target = Path(importlib.util.cache_from_source(str(path)))
        target.parent.mkdir(exist_ok=True)
        target.write_bytes(data)
        written += 1
    return written
