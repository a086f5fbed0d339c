"""Running untrusted student code: a student package, and a new interpreter per test inside
a sandbox.

``prepare`` builds, in a temporary folder, the package the submission runs in: the student
release of the package (rtfgu.grading.release.build_package: the assignment's functions and
every later one stubbed, the earlier ones revealed, no numba or WGSL twin, nothing of the
grader) with the submission's files put over it, and the probe code (the check modules
without their STAFF regions) beside it. A submitted Python file that does not compile is
replaced by its stub, so that it costs only the tests that need it.

``run_child`` starts ``python -I -S boot.py`` for one test, never a fork of the grader (whose
memory holds the answers), inside the strongest isolation the machine allows:

* ``bwrap`` (bubblewrap): no network, its own PID namespace (nothing outlives the test), a
  read-only view of the system, the interpreter, its site-packages, the student package and
  the probes, and one writable scratch folder; nothing of the grader's checkout;
* ``unprivileged user`` (root without bwrap): the child runs as a user of its own
  (RTFGU_SANDBOX_UID, default 64055) in a new network namespace when the kernel allows it,
  with a process limit, and every process of that user is killed after the test; the
  reference files are unreadable to it while grading;
* ``rlimits only`` (neither): a new session and the resource limits.

Every child has a CPU, address-space and file-size limit; its output goes to a file in its
scratch folder, its answer (JSON) through a pipe; the parent kills it at the time limit.
RTFGU_ISOLATION=bwrap|user|rlimits forces one (tests use it to check the fallbacks).
"""
from __future__ import annotations

import ctypes
import json
import os
import resource
import select
import shutil
import signal
import site
import stat
import subprocess
import sys
import sysconfig
import time
import zipfile
from dataclasses import dataclass, field
from pathlib import Path

from .generate import PACKAGE_DIR, student_files
from .release import build_package, probe_files

RESULT_LIMIT = 64 * 1024 * 1024        # bytes of JSON a child may send back
ARCHIVE_FILES = 500                    # entries of a submitted archive that are read at most
ARCHIVE_BYTES = 32 * 1024 * 1024       # decompressed bytes of a submitted archive at most
FILE_BYTES = 4 * 1024 * 1024           # bytes of one submitted file at most
SANDBOX_UID = int(os.environ.get("RTFGU_SANDBOX_UID", "64055"))
ISOLATIONS = ("bwrap", "unprivileged user", "rlimits only")
INSIDE = Path("/sandbox")              # where the package, probes and scratch appear under bwrap
BOOT = "rtfgu_checks/boot.py"


# --- the submission ----------------------------------------------------------------------

def unpack_submission(submission, tmp: Path, notes: list) -> Path:
    """A folder with the submission's regular files: a copy of the folder (links not
    followed), a zip extracted safely, or a single file."""
    submission = Path(submission)
    out = Path(tmp) / "submission"
    out.mkdir(parents=True, exist_ok=True)
    if submission.is_dir():
        _copy_folder(submission, out, notes)
    elif submission.is_file() and zipfile.is_zipfile(submission):
        _extract_zip(submission, out, notes)
    elif submission.is_file():
        shutil.copyfile(submission, out / submission.name)
    else:
        raise ValueError("submission: %s is neither a folder, a zip file nor a file" % submission)
    return out


def _copy_folder(folder: Path, out: Path, notes: list) -> None:
    total, count = 0, 0
    for root, dirs, files in os.walk(folder, followlinks=False):
        dirs[:] = [d for d in dirs if not os.path.islink(os.path.join(root, d)) and d != "__pycache__"]
        for name in files:
            path = Path(root) / name
            if path.is_symlink() or not path.is_file():
                notes.append("%s is a link; it was ignored" % path.relative_to(folder))
                continue
            count += 1
            size = path.stat().st_size
            if count > ARCHIVE_FILES or total + size > ARCHIVE_BYTES or size > FILE_BYTES:
                notes.append("the submission has more files or bytes than the grader reads; %s and "
                             "later files were ignored" % path.relative_to(folder))
                return
            total += size
            target = out / path.relative_to(folder)
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(path, target)


def _extract_zip(archive: Path, out: Path, notes: list) -> None:
    """Entries checked one by one: a path that leaves ``out`` once resolved, a link, the
    entries past ARCHIVE_FILES and the bytes past ARCHIVE_BYTES (counted while reading: an
    entry's declared size may lie) are not extracted."""
    root = out.resolve()
    total = 0
    with zipfile.ZipFile(archive) as z:
        for count, info in enumerate(z.infolist(), start=1):
            if count > ARCHIVE_FILES:
                notes.append("the archive has more than %d entries; the rest were ignored" % ARCHIVE_FILES)
                return
            mode = info.external_attr >> 16
            if info.is_dir():
                continue
            if stat.S_ISLNK(mode):
                notes.append("%s is a link; it was ignored" % info.filename)
                continue
            target = (root / info.filename).resolve()
            try:
                target.relative_to(root)
            except ValueError:
                notes.append("%s points outside the submission folder; it was ignored" % info.filename)
                continue
            target.parent.mkdir(parents=True, exist_ok=True)
            written = 0
            with z.open(info) as source, open(target, "wb") as sink:
                while True:
                    chunk = source.read(1 << 16)
                    if not chunk:
                        break
                    written += len(chunk)
                    total += len(chunk)
                    if written > FILE_BYTES or total > ARCHIVE_BYTES:
                        break
                    sink.write(chunk)
            if written > FILE_BYTES or total > ARCHIVE_BYTES:
                target.unlink()
                notes.append("the archive unpacks to more than %d MB (at %s); the rest was ignored"
                             % (ARCHIVE_BYTES // (1024 * 1024), info.filename))
                return


def find_files(assignment, folder: Path) -> dict:
    """relpath -> path of each of the assignment's files found in ``folder``: by its path in
    the package (shapes/sphere.py, also under rtfgu/), else by its file name anywhere."""
    found = {}
    candidates = [p for p in sorted(folder.rglob("*")) if p.is_file() and not p.is_symlink()
                  and "__pycache__" not in p.parts and "__MACOSX" not in p.parts]
    for relpath in assignment.files:
        by_path = [p for p in candidates if p.relative_to(folder).as_posix().endswith(relpath)]
        by_name = [p for p in candidates if p.name == Path(relpath).name]
        pick = (by_path or by_name or [None])[0]
        if pick is not None:
            found[relpath] = pick
    return found


# --- the folder a submission runs in ---------------------------------------------------------

@dataclass
class Workspace:
    root: Path
    package: Path                          # the folder holding rtfgu/ (first on the child's path)
    probes: Path                           # the folder holding rtfgu_checks/
    notes: list = field(default_factory=list)
    broken: dict = field(default_factory=dict)   # relpath -> why the file was not used


def earlier(assignment) -> tuple:
    """The assignments before ``assignment``: revealed in the package it is graded in."""
    from .assignments import ASSIGNMENTS

    return tuple(a.short for a in ASSIGNMENTS.values() if a.number < assignment.number)


def prepare(assignment, submission, tmp, package_dir: Path = PACKAGE_DIR, reveal=None) -> Workspace:
    """The package and probes for ``submission`` (None: the solution, every block revealed)."""
    from .assignments import ASSIGNMENTS

    root = Path(tmp)
    package = root / "package"
    if submission is None:
        reveal = tuple(a.short for a in ASSIGNMENTS.values())
    elif reveal is None:
        reveal = earlier(assignment)
    build_package(package, reveal, package_dir)
    probes = root / "probes" / "rtfgu_checks"
    probes.mkdir(parents=True)
    for name, text in probe_files(package_dir).items():
        (probes / name).write_text(text)
    ws = Workspace(root, package, probes.parent)
    if submission is not None:
        folder = unpack_submission(submission, root, ws.notes)
        found = find_files(assignment, folder)
        stubs = student_files(assignment, package_dir)
        for relpath in assignment.files:
            target = package / "rtfgu" / relpath
            if relpath not in found:
                ws.notes.append("%s was not in your submission; it was graded as the unsolved stub" % relpath)
                continue
            data = found[relpath].read_bytes()
            if relpath.endswith(".py"):
                try:
                    compile(data, relpath, "exec", dont_inherit=True)
                except (SyntaxError, ValueError) as error:
                    line = getattr(error, "lineno", None)
                    ws.broken[relpath] = "%s in %s, line %s: %s" % (
                        type(error).__name__, relpath, line if line is not None else "?",
                        getattr(error, "msg", str(error)))
                    target.write_text(stubs[relpath])
                    continue
            target.write_bytes(data)
    for path in [root] + [p for p in root.rglob("*")]:
        os.chmod(path, 0o755 if path.is_dir() else 0o644)
    return ws


# --- isolation -------------------------------------------------------------------------------

def find_bwrap() -> str | None:
    candidates = [os.environ.get("RTFGU_BWRAP"), shutil.which("bwrap"),
                  str(Path(sys.prefix) / "sandbox" / "usr" / "bin" / "bwrap"),
                  str(Path(sys.executable).parent.parent / "sandbox" / "usr" / "bin" / "bwrap")]
    for candidate in candidates:
        if candidate and os.access(candidate, os.X_OK):
            return candidate
    return None


_BWRAP_WORKS = {}


def bwrap_works(bwrap: str) -> bool:
    """Whether bwrap can make its namespaces here (a container may forbid user namespaces)."""
    if bwrap not in _BWRAP_WORKS:
        try:
            done = subprocess.run([bwrap, "--unshare-all", "--ro-bind", "/", "/", "--proc", "/proc",
                                   "--dev", "/dev", "true"], capture_output=True, timeout=20)
            _BWRAP_WORKS[bwrap] = done.returncode == 0
        except (OSError, subprocess.SubprocessError):
            _BWRAP_WORKS[bwrap] = False
    return _BWRAP_WORKS[bwrap]


_USER_WORKS = {}


def user_works() -> bool:
    """Whether the sandbox user can start this interpreter (it may live in a folder only root
    can enter, as pyenv's under /root)."""
    if "ok" not in _USER_WORKS:
        def drop():
            os.setgroups([])
            os.setgid(SANDBOX_UID)
            os.setuid(SANDBOX_UID)
        try:
            done = subprocess.run([os.path.realpath(sys.executable), "-I", "-S", "-c", "pass"],
                                  preexec_fn=drop, capture_output=True, timeout=20, cwd="/")
            _USER_WORKS["ok"] = done.returncode == 0
        except (OSError, subprocess.SubprocessError):
            _USER_WORKS["ok"] = False
    return _USER_WORKS["ok"]


def choose_isolation(require_sandbox: bool = False) -> str:
    """The isolation this machine allows (RTFGU_ISOLATION=bwrap|user|rlimits forces one)."""
    forced = os.environ.get("RTFGU_ISOLATION")
    bwrap = find_bwrap()
    have_bwrap = bwrap is not None and bwrap_works(bwrap)
    if forced:
        wanted = {"bwrap": "bwrap", "user": "unprivileged user", "rlimits": "rlimits only"}.get(forced)
        if wanted is None:
            raise ValueError("RTFGU_ISOLATION must be bwrap, user or rlimits, got %r" % forced)
        if wanted == "bwrap" and not have_bwrap:
            raise ValueError("RTFGU_ISOLATION=bwrap, but bwrap is not installed or cannot run here "
                             "(Debian package bubblewrap)")
        if wanted == "unprivileged user" and (os.geteuid() != 0 or not user_works()):
            raise ValueError("RTFGU_ISOLATION=user needs the grader to run as root, with an interpreter "
                             "the user %d can run" % SANDBOX_UID)
        choice = wanted
    elif have_bwrap:
        choice = "bwrap"
    elif os.geteuid() == 0 and user_works():
        choice = "unprivileged user"
    else:
        choice = "rlimits only"
    if require_sandbox and choice != "bwrap":
        raise ValueError("--require-sandbox: bubblewrap is %s, so student code would run with "
                         "'%s' only; install the Debian package bubblewrap (or run `make venv`, which "
                         "fetches it) on a machine that allows user namespaces"
                         % ("not installed" if bwrap is None else "installed but cannot run here", choice))
    return choice


def _site_dirs() -> list:
    """The folders the child imports numpy, Pillow (and wgpu) from: the grader's own."""
    dirs = [p for p in sys.path if p.rstrip("/").endswith(("site-packages", "dist-packages"))]
    dirs += list(site.getsitepackages()) + [sysconfig.get_paths()["purelib"], sysconfig.get_paths()["platlib"]]
    out = []
    for d in dirs:
        if d and os.path.isdir(d) and d not in out:
            out.append(d)
    return out


def _bwrap_command(bwrap: str, ws: Workspace, scratch: Path, python: str, args: list) -> list:
    cmd = [bwrap, "--unshare-all", "--die-with-parent", "--new-session", "--clearenv",
           "--proc", "/proc", "--dev", "/dev", "--tmpfs", "/tmp"]
    for path in ("/usr", "/lib", "/lib64", "/lib32", "/bin", "/sbin", "/etc"):
        if os.path.exists(path):
            cmd += ["--ro-bind", path, path]
    for path in ("/sys/devices/system/cpu", "/sys/fs/cgroup"):
        if os.path.exists(path):
            cmd += ["--ro-bind", path, path]
    prefixes = {sys.base_prefix, os.path.dirname(os.path.dirname(python))}
    for path in sorted(prefixes) + _site_dirs():
        if os.path.exists(path) and not path.startswith(("/usr", "/lib")):
            cmd += ["--ro-bind", path, path]
    cmd += ["--ro-bind", str(ws.package), str(INSIDE / "package"),
            "--ro-bind", str(ws.probes), str(INSIDE / "probes"),
            "--bind", str(scratch), str(INSIDE / "scratch"),
            "--chdir", str(INSIDE / "scratch")]
    for key, value in _child_env(INSIDE / "scratch").items():
        cmd += ["--setenv", key, value]
    return cmd + ["--", python, "-I", "-S", str(INSIDE / "probes" / BOOT)] + args


def _child_env(scratch: Path, memory_mb: int = 0) -> dict:
    return {"PATH": "/usr/bin:/bin", "HOME": str(scratch), "TMPDIR": str(scratch),
            "LANG": "C.UTF-8", "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1",
            "NUMBA_NUM_THREADS": "1", "RTFGU_MEMORY_MB": str(memory_mb)}


CLONE_NEWNET = 0x40000000


def _preexec(limits: dict, isolation: str):
    def run():
        resource.setrlimit(resource.RLIMIT_FSIZE, (limits["output"], limits["output"]))
        resource.setrlimit(resource.RLIMIT_CPU, (limits["cpu"], limits["cpu"] + 1))
        if limits["memory"]:
            resource.setrlimit(resource.RLIMIT_AS, (limits["memory"], limits["memory"]))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # an oversized write fails with an error instead
        if isolation == "unprivileged user":
            try:
                ctypes.CDLL(None, use_errno=True).unshare(CLONE_NEWNET)
            except Exception:
                pass
            os.setgroups([])
            os.setgid(SANDBOX_UID)
            os.setuid(SANDBOX_UID)
            resource.setrlimit(resource.RLIMIT_NPROC, (64, 64))
    return run


def _kill_user(uid: int) -> None:
    """Kill every process of ``uid`` (the fallback's sandbox user: only test processes)."""
    pid = os.fork()
    if pid == 0:  # pragma: no cover (the child)
        try:
            os.setgid(uid)
            os.setuid(uid)
            os.kill(-1, signal.SIGKILL)
        except BaseException:
            pass
        os._exit(0)
    os.waitpid(pid, 0)


@dataclass
class ChildResult:
    status: str          # "ok", "timeout", "crashed", "too much output", "bad answer"
    data: object         # the decoded JSON answer when status is "ok"
    output: str          # the first part of what the child printed
    seconds: float
    detail: str = ""


def run_child(ws: Workspace, scratch: Path, probe: list, *, isolation: str, time_limit: float = 10.0,
              memory_mb: int = 1024, output_limit: int = 1024 * 1024) -> ChildResult:
    """Run one probe (["check", assignment id, slug] or ["render", scene, width, height]) in a
    new interpreter under ``isolation``; its answer is JSON through a pipe."""
    scratch = Path(scratch)
    scratch.mkdir(parents=True, exist_ok=True)
    python = os.path.realpath(sys.executable)
    read_fd, write_fd = os.pipe()
    os.set_inheritable(write_fd, True)
    if isolation == "bwrap":
        package, probes, where = INSIDE / "package", INSIDE / "probes", INSIDE / "scratch"
    else:
        package, probes, where = ws.package, ws.probes, scratch
    args = [str(package), str(probes), os.pathsep.join(_site_dirs()), str(write_fd)] + [str(p) for p in probe]
    if isolation == "bwrap":
        command = _bwrap_command(find_bwrap(), ws, scratch, python, args)
        env = {}
    else:
        command = [python, "-I", "-S", str(probes / BOOT)] + args
        env = _child_env(scratch, memory_mb)
    if isolation == "unprivileged user":
        os.chown(scratch, SANDBOX_UID, SANDBOX_UID)
    # The interpreter, numpy and the renderer take about 0.6 GB of address space before the
    # test's own memory_mb (0: no limit; llvmpipe reserves far more).
    limits = {"output": output_limit, "cpu": int(time_limit) + 2,
              "memory": (memory_mb + 768) * 1024 * 1024 if memory_mb else 0}
    output_path = scratch / "output.txt"
    start = time.monotonic()
    with open(output_path, "wb") as output:
        process = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=output, stderr=output,
                                   pass_fds=(write_fd,), cwd=str(scratch), env=env or _child_env(where, memory_mb),
                                   start_new_session=True, preexec_fn=_preexec(limits, isolation))
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
            os.killpg(process.pid, signal.SIGKILL)   # the child and anything it started
        except (ProcessLookupError, PermissionError):
            pass
        process.wait()
        if isolation == "unprivileged user":
            _kill_user(SANDBOX_UID)
    seconds = time.monotonic() - start
    output = _read_output(output_path)
    if status is None:
        out_size = output_path.stat().st_size if output_path.exists() else 0
        if out_size >= output_limit:
            status, detail = "too much output", "your code printed %d bytes or more; the limit is %d" % (
                output_limit, output_limit)
    if status is None and not chunks:
        code = process.returncode
        status = "crashed"
        if code < 0:
            detail = {signal.SIGXCPU: "it used more than its CPU time",
                      signal.SIGSEGV: "it crashed (segmentation fault)"}.get(-code, "it was killed by signal %d" % -code)
        else:
            detail = "it exited (exit code %d) before the test finished" % code
    if status is None:
        try:
            data = json.loads(b"".join(chunks))
        except ValueError:
            return ChildResult("bad answer", None, output, seconds, "the test's answer was not readable")
        if not isinstance(data, dict):
            return ChildResult("bad answer", None, output, seconds, "the test's answer was not an object")
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
