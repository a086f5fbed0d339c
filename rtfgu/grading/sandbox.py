"""Running untrusted student code: an overlay copy of the package and one child per test.

``build_overlay`` copies the clean package (solutions, without the grader's reference
files) into a temporary folder and puts the submission's files over it. ``run_child``
forks a child that starts its own process group, limits its address space
(RLIMIT_AS), CPU time, and the size of any file it writes (its output goes to a file
capped by RLIMIT_FSIZE), imports the overlay package and runs one observation. The child
answers with JSON bytes through a pipe; the parent waits at most the time limit and then
kills the whole process group. Nothing the child does can change the grader's state.
"""
from __future__ import annotations

import json
import os
import resource
import select
import shutil
import signal
import sys
import time
import zipfile
from dataclasses import dataclass
from pathlib import Path

from .generate import PACKAGE_DIR, student_files

RESULT_LIMIT = 64 * 1024 * 1024        # bytes of JSON a child may send back
SUBMODULES = ("float3", "ray", "cameras", "shapes", "material", "lights", "shading", "scene",
              "renderer", "image", "scenes")


def _ignore(directory, names):
    skip = {"__pycache__", "reference"} if Path(directory).name == "grading" else {"__pycache__"}
    return [n for n in names if n in skip or n.endswith((".pyc", ".nbi", ".nbc"))]


def unpack_submission(submission, tmp: Path) -> Path:
    """A folder with the submission's files: the folder itself, or a zip extracted safely."""
    submission = Path(submission)
    if submission.is_dir():
        return submission
    if submission.is_file() and zipfile.is_zipfile(submission):
        out = tmp / "unzipped"
        with zipfile.ZipFile(submission) as z:
            for info in z.infolist():
                target = (out / info.filename).resolve()
                if info.is_dir() or not str(target).startswith(str(out.resolve())):
                    continue  # folders are implied; a path leaving the folder is ignored
                target.parent.mkdir(parents=True, exist_ok=True)
                target.write_bytes(z.read(info)[:16 * 1024 * 1024])
        return out
    if submission.is_file():
        out = tmp / "single"
        out.mkdir(parents=True, exist_ok=True)
        shutil.copy(submission, out / submission.name)
        return out
    raise ValueError("submission: %s is neither a folder, a zip file nor a file" % submission)


def find_files(assignment, folder: Path) -> dict:
    """relpath -> path of each of the assignment's files found in ``folder``: by its path in
    the package (shapes/sphere.py, also under rtfgu/), else by its file name anywhere."""
    found = {}
    candidates = [p for p in sorted(folder.rglob("*")) if p.is_file() and "__pycache__" not in p.parts
                  and "__MACOSX" not in p.parts]
    for relpath in assignment.files:
        by_path = [p for p in candidates if p.relative_to(folder).as_posix().endswith(relpath)]
        by_name = [p for p in candidates if p.name == Path(relpath).name]
        pick = (by_path or by_name or [None])[0]
        if pick is not None:
            found[relpath] = pick
    return found


def build_overlay(assignment, submission, tmp: Path, package_dir: Path = PACKAGE_DIR):
    """(folder to put first on sys.path, notes for the student) for this submission."""
    tmp = Path(tmp)
    root = tmp / "overlay"
    shutil.copytree(package_dir, root / "rtfgu", ignore=_ignore)
    notes = []
    if submission is None:
        return root, notes
    folder = unpack_submission(submission, tmp)
    found = find_files(assignment, folder)
    stubs = None
    for relpath in assignment.files:
        target = root / "rtfgu" / relpath
        if relpath in found:
            data = found[relpath].read_bytes()
            target.write_bytes(data)
        else:
            stubs = stubs or student_files(assignment, package_dir)
            target.write_text(stubs[relpath])
            notes.append("%s was not in your submission; it was graded as the unsolved stub" % relpath)
    return root, notes


@dataclass
class ChildResult:
    status: str          # "ok", "timeout", "crashed", "too much output", "bad answer"
    data: object         # the decoded JSON answer when status is "ok"
    output: str          # the first part of what the child printed
    seconds: float
    detail: str = ""


def _vm_bytes() -> int:
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("VmSize:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    return 0


_BOOT = ("import sys; sys.path.insert(0, sys.argv[1]); "
         "from rtfgu.grading.sandbox import answer_fresh; answer_fresh(*sys.argv[2:])")


def _observe_and_answer(observe, overlay, write_fd, extra_modules, describe_exception) -> None:
    sys.path.insert(0, str(overlay))
    import importlib

    importlib.invalidate_caches()
    try:
        rt = importlib.import_module("rtfgu")
        if not Path(rt.__file__).resolve().is_relative_to(Path(overlay).resolve()):
            raise RuntimeError("the grader imported rtfgu from %s, not from the overlay" % rt.__file__)
        for name in SUBMODULES + tuple(extra_modules):
            importlib.import_module("rtfgu." + name)
        data = observe(rt)
    except BaseException as error:  # the student's import or code failed as a whole
        data = {"error": describe_exception(error)}
    payload = json.dumps(data).encode()
    view = memoryview(payload)
    while view:
        n = os.write(write_fd, view[:1 << 16])
        view = view[n:]


def answer_fresh(assignment_id: str, slug: str, write_fd: str, *extra_modules) -> None:
    """The entry of a fresh child (``Check.fresh``): find the check and answer as _child does."""
    from .checks import checks_for
    from .checks.child import describe_exception

    check = next(c for c in checks_for(assignment_id) if c.slug == slug)
    _observe_and_answer(check.observe, Path(sys.path[0]), int(write_fd), extra_modules, describe_exception)
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(0)


def _child(write_fd: int, overlay: Path, scratch: Path, observe, time_limit: float, memory_mb: int,
           output_limit: int, extra_modules, fresh=None) -> None:
    """In the forked child: limit, isolate, import the overlay package, observe, answer."""
    status = 0
    from .checks.child import describe_exception

    try:
        os.setsid()
        os.chdir(scratch)
        out = os.open(scratch / "output.txt", os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
        os.dup2(out, 1)
        os.dup2(out, 2)
        sys.stdout = open(1, "w", closefd=False, buffering=1)
        sys.stderr = open(2, "w", closefd=False, buffering=1)
        sys.stdin = open(os.devnull)
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)   # an oversized write fails with an error instead
        signal.signal(signal.SIGINT, signal.SIG_DFL)
        signal.signal(signal.SIGTERM, signal.SIG_DFL)
        resource.setrlimit(resource.RLIMIT_FSIZE, (output_limit, output_limit))
        cpu = int(time_limit) + 2
        resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 1))
        if memory_mb:
            limit = _vm_bytes() + memory_mb * 1024 * 1024
            resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
        os.environ.update(HOME=str(scratch), TMPDIR=str(scratch), RTFGU_MEMORY_MB=str(memory_mb))
        if fresh is not None:
            # A newly started interpreter: the parent's GPU driver state must not be inherited.
            os.set_inheritable(write_fd, True)
            os.execv(sys.executable, [sys.executable, "-c", _BOOT, str(overlay), fresh[0], fresh[1],
                                      str(write_fd)] + list(extra_modules))
        for name in [m for m in sys.modules if m == "rtfgu" or m.startswith("rtfgu.")]:
            del sys.modules[name]
        _observe_and_answer(observe, overlay, write_fd, extra_modules, describe_exception)
    except BaseException:
        status = 3
    finally:
        try:
            sys.stdout.flush()
            sys.stderr.flush()
        except BaseException:
            pass
        os._exit(status)


def run_child(overlay: Path, scratch: Path, observe, *, time_limit: float = 10.0, memory_mb: int = 1024,
              output_limit: int = 1024 * 1024, extra_modules=(), fresh=None) -> ChildResult:
    """Run ``observe`` in a sandboxed child; ``fresh=(assignment id, check slug)`` starts a new
    interpreter for it instead of running it in the forked copy of the grader."""
    scratch = Path(scratch)
    scratch.mkdir(parents=True, exist_ok=True)
    sys.stdout.flush()
    sys.stderr.flush()
    read_fd, write_fd = os.pipe()
    start = time.monotonic()
    pid = os.fork()
    if pid == 0:  # pragma: no cover (the child)
        os.close(read_fd)
        _child(write_fd, overlay, scratch, observe, time_limit, memory_mb, output_limit, extra_modules, fresh)
    os.close(write_fd)
    chunks, size, status, detail = [], 0, None, ""
    deadline = start + time_limit
    try:
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                status = "timeout"
                break
            ready, _, _ = select.select([read_fd], [], [], min(left, 0.5))
            if not ready:
                continue
            chunk = os.read(read_fd, 1 << 16)
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
            if size > RESULT_LIMIT:
                status, detail = "bad answer", "the test's answer was larger than %d bytes" % RESULT_LIMIT
                break
    finally:
        os.close(read_fd)
        try:
            os.killpg(pid, signal.SIGKILL)   # the child and anything it started
        except (ProcessLookupError, PermissionError):
            pass
        _, wait_status = os.waitpid(pid, 0)
    seconds = time.monotonic() - start
    output = _read_output(scratch / "output.txt")
    if status is None and size >= 0:
        out_size = (scratch / "output.txt").stat().st_size if (scratch / "output.txt").exists() else 0
        if out_size >= output_limit:
            status, detail = "too much output", "your code printed %d bytes or more; the limit is %d" % (
                output_limit, output_limit)
    if status is None:
        if os.WIFSIGNALED(wait_status) and not chunks:
            sig = os.WTERMSIG(wait_status)
            status = "crashed"
            detail = {signal.SIGXCPU: "it used more than its CPU time",
                      signal.SIGSEGV: "it crashed (segmentation fault)"}.get(sig, "it was killed by signal %d" % sig)
        elif not chunks:
            status, detail = "crashed", "it exited (exit code %d) before the test finished" % os.WEXITSTATUS(wait_status)
    if status is None:
        try:
            data = json.loads(b"".join(chunks))
        except ValueError:
            return ChildResult("bad answer", None, output, seconds, "the test's answer was not readable")
        return ChildResult("ok", data, output, seconds)
    return ChildResult(status, None, output, seconds, detail)


def _read_output(path: Path, limit: int = 2000) -> str:
    try:
        with open(path, "rb") as f:
            data = f.read(limit + 1)
    except OSError:
        return ""
    text = data[:limit].decode("utf-8", "replace")
    return text + ("\n[... output cut]" if len(data) > limit else "")
