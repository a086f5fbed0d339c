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
  (one per grading process, from RTFGU_SANDBOX_UID, default 64055, upwards: graders that
  run at once never share one) in a new network namespace when the kernel allows it,
  with a process limit, and every process of that user is killed after the test; the
  reference files are unreadable to it while grading;
* ``rlimits only`` (neither): a new session and the resource limits.

Every child has a CPU, address-space and file-size limit; its output goes to a file in its
scratch folder, its answer (JSON) through a pipe; the parent kills it at the time limit.
RTFGU_ISOLATION=bwrap|user|rlimits forces one (tests use it to check the fallbacks).
"""
from __future__ import annotations

import ctypes
import fcntl
import hashlib
import json
import os
import resource
import select
import shutil
import signal
import stat
import site
import subprocess
import sys
import sysconfig
import tempfile
import time
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

from .archive import find_files, unpack_submission
from .generate import PACKAGE_DIR, student_files
from .release import build_package, probe_files

RESULT_LIMIT = 64 * 1024 * 1024        # bytes of JSON a child may send back
SANDBOX_UID = int(os.environ.get("RTFGU_SANDBOX_UID", "64055"))
ISOLATIONS = ("bwrap", "unprivileged user", "rlimits only")
INSIDE = Path("/sandbox")              # where the package, probes and scratch appear under bwrap
PROBES = "rtfgu_probes"                # the probe package's name in the sandbox
BOOT = PROBES + "/boot.py"


# --- the folder a submission runs in ---------------------------------------------------------

@dataclass
class Workspace:
    root: Path
    package: Path                          # the folder holding rtfgu/ (first on the child's path)
    probes: Path                           # the folder holding rtfgu_probes/
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
    probes = root / "probes" / PROBES
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

BWRAP_ID = 65534                       # the uid and gid the child has inside bwrap (nobody)
SCRATCH_BYTES = 64 * 1024 * 1024       # the writable tmpfs (/tmp) inside bwrap
SHM_BYTES = 16 * 1024 * 1024           # /dev/shm inside bwrap
SYSTEM_DIRS = ("/usr", "/lib", "/lib64", "/lib32", "/libx32", "/bin", "/sbin")
# What the dynamic linker, the interpreter and Mesa's Vulkan loader read from /etc.
ETC_ENTRIES = ("ld.so.cache", "ld.so.conf", "ld.so.conf.d", "nsswitch.conf", "passwd", "group",
               "localtime", "alternatives", "vulkan", "drirc", "glvnd", "OpenCL")
# The CPU count (numpy, llvmpipe's threads) and the cgroup limits are read from /sys.
SYS_DIRS = ("/sys/devices/system/cpu", "/sys/fs/cgroup")


def find_bwrap() -> str | None:
    """RTFGU_BWRAP, then bwrap on PATH, then the copy `make venv` unpacks into .venv/sandbox
    (RTFGU_BWRAP=none: no bwrap, as on a machine without it)."""
    if os.environ.get("RTFGU_BWRAP") == "none":
        return None
    candidates = [os.environ.get("RTFGU_BWRAP"), shutil.which("bwrap"),
                  str(Path(sys.prefix) / "sandbox" / "usr" / "bin" / "bwrap"),
                  str(PACKAGE_DIR.parent / ".venv" / "sandbox" / "usr" / "bin" / "bwrap")]
    for candidate in candidates:
        if candidate and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return candidate
    return None


# bwrap's namespace options: the child is an unprivileged user inside its own user namespace
# where that is allowed, else keeps the caller's uid in the other namespaces. Every capability
# is dropped in both: bwrap started by root keeps them for the child otherwise, and with
# CAP_SYS_ADMIN a child can remount a read-only bind read-write and write through it to the
# grader's files.
BWRAP_NAMESPACES = (["--unshare-all", "--unshare-user", "--uid", str(BWRAP_ID), "--gid", str(BWRAP_ID),
                     "--cap-drop", "ALL"],
                    ["--unshare-all", "--cap-drop", "ALL"])
_BWRAP_WORKS = {}


def _bwrap_namespaces(bwrap: str):
    """The first of BWRAP_NAMESPACES this machine allows, or None (a container may forbid
    user namespaces)."""
    if bwrap not in _BWRAP_WORKS:
        _BWRAP_WORKS[bwrap] = None
        for flags in BWRAP_NAMESPACES:
            try:
                done = subprocess.run([bwrap] + flags + ["--die-with-parent", "--new-session",
                                                         "--ro-bind", "/", "/", "--proc", "/proc",
                                                         "--dev", "/dev", "true"],
                                      capture_output=True, timeout=20)
            except (OSError, subprocess.SubprocessError):
                break
            if done.returncode == 0:
                _BWRAP_WORKS[bwrap] = flags
                break
    return _BWRAP_WORKS[bwrap]


_BWRAP_AS_USER = {}


def _bwrap_for_user(bwrap: str) -> str:
    """A bwrap binary the sandbox user can start: ``bwrap`` itself where any user can reach it
    outside the staff folder (which the fallback closes while it grades, and which holds
    .venv/sandbox), else a copy in the temporary folder owned by the grader's user."""
    if (_reachable_by_others(bwrap) and os.stat(bwrap).st_mode & stat.S_IXOTH
            and not _inside(bwrap, staff_folder())):
        return bwrap
    st = os.stat(bwrap)
    folder = Path(tempfile.gettempdir()) / ("rtfgu-bwrap-%d-%d-%d" % (os.getuid(), st.st_size, st.st_mtime_ns))
    if _owned_and_closed(folder) and (folder / "bwrap").is_file():
        return str(folder / "bwrap")
    build = Path(tempfile.mkdtemp(prefix=folder.name + "-build-"))
    os.chmod(build, 0o755)
    shutil.copyfile(bwrap, build / "bwrap")
    os.chmod(build / "bwrap", 0o755)
    try:
        os.rename(build, folder)
    except OSError:  # another grader made it first, or something else is in the way
        if not (_owned_and_closed(folder) and (folder / "bwrap").is_file()):
            return str(build / "bwrap")
        shutil.rmtree(build, ignore_errors=True)
    return str(folder / "bwrap")


def bwrap_as_user(bwrap: str) -> bool:
    """Whether bwrap is started as the grading process's sandbox user rather than as the
    grader's own user: where the grader is root, that user can run this bwrap, and it may
    make a user namespace of its own here. Then the test's processes belong to that user
    outside their namespaces too: RLIMIT_NPROC bounds them (the kernel exempts root, whom
    bwrap started by root maps the child to), and what only root may read stays unreadable."""
    if os.geteuid() != 0 or bwrap is None or _bwrap_namespaces(bwrap) != BWRAP_NAMESPACES[0]:
        return False
    if bwrap not in _BWRAP_AS_USER:
        _BWRAP_AS_USER[bwrap] = False
        uid = sandbox_uid()

        def drop():
            os.setgroups([])
            os.setgid(uid)
            os.setuid(uid)
        try:
            done = subprocess.run([_bwrap_for_user(bwrap)] + BWRAP_NAMESPACES[0] + ["--die-with-parent", "--new-session",
                                                                    "--ro-bind", "/", "/", "--proc", "/proc",
                                                                    "--dev", "/dev", "true"],
                                  capture_output=True, timeout=20, preexec_fn=drop, cwd="/")
            _BWRAP_AS_USER[bwrap] = done.returncode == 0
        except (OSError, subprocess.SubprocessError):
            pass
    return _BWRAP_AS_USER[bwrap]


def bwrap_works(bwrap: str) -> bool:
    """Whether bwrap can make its namespaces here."""
    return bwrap is not None and _bwrap_namespaces(bwrap) is not None


def choose_isolation(require_sandbox: bool = False) -> str:
    """The isolation this machine allows (RTFGU_ISOLATION=bwrap|user|rlimits forces one)."""
    forced = os.environ.get("RTFGU_ISOLATION")
    bwrap = find_bwrap()
    have_bwrap = bwrap_works(bwrap)
    if forced:
        wanted = {"bwrap": "bwrap", "user": "unprivileged user", "rlimits": "rlimits only"}.get(forced)
        if wanted is None:
            raise ValueError("RTFGU_ISOLATION must be bwrap, user or rlimits, got %r" % forced)
        if wanted == "bwrap" and not have_bwrap:
            raise ValueError("RTFGU_ISOLATION=bwrap, but bwrap is not installed or cannot run here "
                             "(Debian package bubblewrap)")
        if wanted == "unprivileged user" and os.geteuid() != 0:
            raise ValueError("RTFGU_ISOLATION=user needs the grader to run as root")
        choice = wanted
    elif have_bwrap:
        choice = "bwrap"
    elif os.geteuid() == 0:
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


def _inside(path, folder) -> bool:
    try:
        Path(path).resolve().relative_to(Path(folder).resolve())
        return True
    except ValueError:
        return False


def _bwrap_command(bwrap: str, ws: Workspace, python: str, args: list, memory_mb: int,
                   runtime=None) -> list:
    """The read-only view: the system folders, a few /etc and /sys entries, the interpreter's
    installation, its site-packages (with the staff package hidden should it be installed
    there), the student package and the probes; the only writable folder is a small tmpfs.
    ``runtime``: (site folders, environment) of user_runtime's copy, whose folder is bound
    in place of the interpreter's installation (bwrap run as the sandbox user)."""
    cmd = [bwrap] + _bwrap_namespaces(bwrap) + ["--die-with-parent", "--new-session", "--clearenv"]
    for path in SYSTEM_DIRS:
        if os.path.islink(path):
            cmd += ["--symlink", os.readlink(path), path]
        elif os.path.isdir(path):
            cmd += ["--ro-bind", path, path]
    for name in ETC_ENTRIES:
        path = os.path.join("/etc", name)
        if os.path.lexists(path):
            cmd += ["--ro-bind-try", path, path]
    for path in SYS_DIRS:
        if os.path.exists(path):
            cmd += ["--ro-bind", path, path]
    cmd += ["--proc", "/proc", "--dev", "/dev", "--size", str(SHM_BYTES), "--tmpfs", "/dev/shm",
            "--remount-ro", "/dev", "--size", str(SCRATCH_BYTES), "--tmpfs", "/tmp"]
    shown = []
    prefixes = [sys.base_prefix, os.path.dirname(os.path.dirname(python))] + _site_dirs()
    if runtime is not None:
        prefixes = [os.path.dirname(os.path.dirname(python))] + list(runtime[0])
    for path in prefixes:
        if os.path.isdir(path) and path not in shown and not any(_inside(path, d) for d in SYSTEM_DIRS):
            shown.append(path)
            cmd += ["--ro-bind", path, path]
    if any(_inside(PACKAGE_DIR, d) for d in shown + list(SYSTEM_DIRS)):
        cmd += ["--tmpfs", str(PACKAGE_DIR), "--remount-ro", str(PACKAGE_DIR)]
    cmd += ["--ro-bind", str(ws.package), str(INSIDE / "package"),
            "--ro-bind", str(ws.probes), str(INSIDE / "probes"), "--chdir", "/tmp"]
    env = _child_env(Path("/tmp"), memory_mb)
    if runtime is not None:
        env.update(runtime[1])
    for key, value in env.items():
        cmd += ["--setenv", key, value]
    return cmd + ["--", python, "-I", "-S", str(INSIDE / "probes" / BOOT)] + args


def _child_env(scratch: Path, memory_mb: int = 0) -> dict:
    return {"PATH": "/usr/bin:/bin", "HOME": str(scratch), "TMPDIR": str(scratch),
            "XDG_CACHE_HOME": str(scratch), "MESA_SHADER_CACHE_DISABLE": "true",
            "LANG": "C.UTF-8", "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1",
            "NUMBA_NUM_THREADS": "1", "LP_NUM_THREADS": "2", "RTFGU_MEMORY_MB": str(memory_mb)}


# --- the unprivileged-user fallback -------------------------------------------------------

def staff_folder() -> Path:
    """What the sandbox user may not read while it runs: the folder holding the staff package
    (the checkout, or the autograder's source folder), or the package alone where that folder
    is shared (a site-packages, a system folder)."""
    parent = PACKAGE_DIR.parent.resolve()
    shared = [Path(d).resolve() for d in _site_dirs() + [sys.base_prefix]] + [Path("/")]
    if parent in shared or any(_inside(parent, d) for d in SYSTEM_DIRS):
        return PACKAGE_DIR
    return parent


def _reachable_by_others(path) -> bool:
    """Whether a user other than the owner can reach ``path`` (every folder above it
    searchable, itself readable)."""
    path = Path(path).resolve()
    try:
        if any(not os.stat(p).st_mode & stat.S_IXOTH for p in path.parents):
            return False
        return bool(os.stat(path).st_mode & stat.S_IROTH)
    except OSError:
        return False


def _link_tree(src: Path, dst: Path, skip=()) -> None:
    """``dst`` as hard links to ``src``'s files (copies where a link cannot be made or the
    file is not readable by others), without the folders named in ``skip`` and without links
    that lead out of ``src``."""
    src = Path(src)
    for root, dirs, files in os.walk(src):
        here = Path(root)
        dirs[:] = [d for d in dirs if d not in skip and str(here / d) not in skip and d != "__editable__"
                   and not os.path.islink(here / d)]
        out = dst / here.relative_to(src)
        out.mkdir(parents=True, exist_ok=True)
        os.chmod(out, 0o755)
        for name in files:
            source, target = here / name, out / name
            if os.path.islink(source):
                link = os.readlink(source)
                if not os.path.isabs(link) and _inside(source.parent / link, src):
                    os.symlink(link, target)
                continue
            mode = os.stat(source).st_mode
            if mode & stat.S_IROTH:
                try:
                    os.link(source, target)
                    continue
                except OSError:
                    pass
            shutil.copyfile(source, target)
            os.chmod(target, 0o755 if mode & stat.S_IXUSR else 0o644)


STDLIB_SKIP = ("site-packages", "dist-packages", "test", "idlelib", "tkinter", "turtledemo", "ensurepip")


def _owned_and_closed(path: Path) -> bool:
    try:
        st = os.lstat(path)
    except OSError:
        return False
    return stat.S_ISDIR(st.st_mode) and st.st_uid == os.getuid() and not st.st_mode & 0o022


def user_runtime():
    """(interpreter, site folders, environment) the sandbox user can run with the staff folder
    hidden: the grader's own where that user can reach them, else a cached tree of hard links
    to them (the interpreter, its libpython and standard library, the site-packages without
    the staff package) in the temporary folder, owned by the grader's user."""
    python, sites = os.path.realpath(sys.executable), _site_dirs()
    stdlib = sysconfig.get_paths()["stdlib"]
    hidden = staff_folder()
    if all(_reachable_by_others(p) and not _inside(p, hidden) for p in [python, stdlib] + sites):
        return python, sites, {}
    libdir = sysconfig.get_config_var("LIBDIR") or os.path.join(sys.base_prefix, "lib")
    key = repr((python, stdlib, sites, [os.stat(p).st_mtime_ns for p in [python, stdlib] + sites]))
    root = Path(tempfile.gettempdir()) / ("rtfgu-runtime-%d-%s" % (os.getuid(), hashlib.sha256(key.encode()).hexdigest()[:16]))
    version = "python%d.%d" % sys.version_info[:2]
    runtime_python = root / "bin" / os.path.basename(python)
    runtime_sites = [root / ("site%d" % i) for i in range(len(sites))]
    env = {"LD_LIBRARY_PATH": str(root / "lib")}
    if _owned_and_closed(root) and (root / ".complete").exists():
        return str(runtime_python), [str(s) for s in runtime_sites], env
    build = Path(tempfile.mkdtemp(prefix=root.name + "-build-"))
    os.chmod(build, 0o755)
    (build / "bin").mkdir()
    shutil.copyfile(python, build / "bin" / os.path.basename(python))
    os.chmod(build / "bin" / os.path.basename(python), 0o755)
    (build / "lib").mkdir()
    for lib in Path(libdir).glob("libpython*"):
        if lib.is_file():
            shutil.copyfile(lib, build / "lib" / lib.name)
            os.chmod(build / "lib" / lib.name, 0o755)
    _link_tree(Path(stdlib), build / "lib" / version, STDLIB_SKIP)
    for folder, target in zip(sites, runtime_sites):
        _link_tree(Path(folder), build / target.name, (str(PACKAGE_DIR),))
    (build / ".complete").write_text("")
    try:
        os.rename(build, root)
    except OSError:  # another grader built it first, or a stale folder is in the way
        if not (_owned_and_closed(root) and (root / ".complete").exists()):
            root, runtime_python = build, build / "bin" / os.path.basename(python)
            runtime_sites = [build / s.name for s in runtime_sites]
            env = {"LD_LIBRARY_PATH": str(build / "lib")}
        else:
            shutil.rmtree(build, ignore_errors=True)
    return str(runtime_python), [str(s) for s in runtime_sites], env


def _open_own(path: Path) -> int:
    """``path`` opened for reading and writing, a regular file of the grader's user that no
    one else can write (made afresh if it is not: a sandbox user may have put a file of its
    own there first, in a world-writable temporary folder)."""
    fd = os.open(path, os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW, 0o600)
    st = os.fstat(fd)
    if st.st_uid == os.geteuid() and stat.S_ISREG(st.st_mode) and st.st_nlink == 1 and not st.st_mode & 0o022:
        return fd
    os.close(fd)
    os.unlink(path)
    return os.open(path, os.O_RDWR | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o600)


@contextmanager
def hidden_from_sandbox_user(isolation: str):
    """While grading under ``unprivileged user``, the staff folder is mode 0700 (the sandbox
    user cannot read the solutions, the references or the grader); graders that overlap
    share it through a state file, and the last one out restores the mode."""
    if isolation != "unprivileged user":
        yield
        return
    folder = str(staff_folder())
    state_path = Path(tempfile.gettempdir()) / ("rtfgu-hidden-%d.json" % os.getuid())

    def update(change):
        fd = _open_own(state_path)
        with os.fdopen(fd, "r+") as f:
            fcntl.flock(f, fcntl.LOCK_EX)
            try:
                state = json.loads(f.read() or "{}")
            except ValueError:
                state = {}
            entry = state.get(folder) or {"mode": stat.S_IMODE(os.stat(folder).st_mode), "pids": []}
            entry["pids"] = [p for p in entry["pids"] if _alive(p)]
            change(entry)
            if entry["pids"]:
                state[folder] = entry
                os.chmod(folder, 0o700)
            else:
                state.pop(folder, None)
                os.chmod(folder, entry["mode"])
            f.seek(0)
            f.truncate()
            f.write(json.dumps(state))

    update(lambda entry: entry["pids"].append(os.getpid()))
    try:
        yield
    finally:
        update(lambda entry: entry["pids"].remove(os.getpid()) if os.getpid() in entry["pids"] else None)


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
        return True
    except ProcessLookupError:
        return False
    except PermissionError:
        return True


@contextmanager
def work_folder(prefix: str = "rtfgu-grade-"):
    """A temporary folder the sandbox user may pass through (mode 0711) but not list."""
    with tempfile.TemporaryDirectory(prefix=prefix) as tmp:
        os.chmod(tmp, 0o711)
        yield Path(tmp)


UID_SLOTS = 256                        # sandbox users: SANDBOX_UID .. SANDBOX_UID + UID_SLOTS - 1
_UID_CLAIM = {}                        # pid -> (uid, the open lock file that holds it)


def sandbox_uid() -> int:
    """The sandbox user of this grading process: the first uid from SANDBOX_UID on whose lock
    file no other live process holds. Graders that run at once (grade-all's workers, two
    graders on one machine) get different users, so killing every process of one's user
    after a test never touches another's test, and one submission's processes cannot reach
    another's. The claim lasts as long as this process."""
    pid = os.getpid()
    if pid in _UID_CLAIM:
        return _UID_CLAIM[pid][0]
    folder = Path(tempfile.gettempdir())
    for slot in range(UID_SLOTS):
        uid = SANDBOX_UID + slot
        try:
            fd = os.open(folder / ("rtfgu-sandbox-uid-%d.lock" % uid), os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW, 0o600)
        except OSError:
            continue
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            os.close(fd)
            continue
        _UID_CLAIM[pid] = (uid, fd)
        return uid
    raise RuntimeError("all %d sandbox users (uid %d and up) are taken by other graders"
                       % (UID_SLOTS, SANDBOX_UID))


CLONE_NEWNET = 0x40000000
NPROC = 64                             # processes (threads count) of a test at most


def _preexec(limits: dict, isolation: str, uid=None):
    """Runs between fork and exec (nothing of the student's runs before exec)."""
    def run():
        resource.setrlimit(resource.RLIMIT_FSIZE, (limits["output"], limits["output"]))
        resource.setrlimit(resource.RLIMIT_CPU, (limits["cpu"], limits["cpu"] + 1))
        if limits["memory"]:
            resource.setrlimit(resource.RLIMIT_AS, (limits["memory"], limits["memory"]))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # an oversized write fails with an error instead
        if uid is not None:                            # the sandbox user (bwrap's, or the fallback's)
            if isolation == "unprivileged user":
                try:
                    ctypes.CDLL(None, use_errno=True).unshare(CLONE_NEWNET)
                except Exception:
                    pass
            os.setgroups([])
            os.setgid(uid)
            os.setuid(uid)
            resource.setrlimit(resource.RLIMIT_NPROC, (NPROC, NPROC))
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


PR_SET_CHILD_SUBREAPER = 36
_SUBREAPERS = set()                    # pids of the grading processes that are subreapers


def _become_subreaper() -> None:
    """Make this grading process the reaper of what its tests leave behind: a test's processes
    that outlive their parent (bwrap's init once the outer bwrap has gone, a daemon killed
    after the test) are re-parented here instead of to PID 1, which in a container may never
    reap them. Unreaped, they stay zombies of the sandbox user and count towards its
    RLIMIT_NPROC, until forking fails in later tests."""
    if os.getpid() not in _SUBREAPERS:
        try:
            ctypes.CDLL(None, use_errno=True).prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)
        except Exception:
            pass
        _SUBREAPERS.add(os.getpid())


def _reap_orphans(uid) -> None:
    """Reap the zombie children of this process that a test left: those of the sandbox user
    ``uid`` and bwrap processes. Other children are left to whoever waits for them."""
    me = str(os.getpid())
    try:
        entries = [e for e in os.listdir("/proc") if e.isdigit()]
    except OSError:
        return
    for entry in entries:
        try:
            with open("/proc/%s/stat" % entry) as f:
                text = f.read()
            comm = text[text.index("(") + 1:text.rindex(")")]
            state, ppid = text[text.rindex(")") + 2:].split()[:2]
            if ppid != me or state != "Z" or not (comm == "bwrap" or os.stat("/proc/" + entry).st_uid == uid):
                continue
            os.waitpid(int(entry), os.WNOHANG)
        except (OSError, ValueError, ChildProcessError):
            continue


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
    new interpreter under ``isolation``; its answer is JSON through a pipe, its output goes to
    ``scratch``/output.txt (at most ``output_limit`` bytes)."""
    scratch = Path(scratch)
    scratch.mkdir(parents=True, exist_ok=True)
    _become_subreaper()
    python, sites, extra_env = os.path.realpath(sys.executable), _site_dirs(), {}
    as_user = isolation == "unprivileged user" or (isolation == "bwrap" and bwrap_as_user(find_bwrap()))
    if as_user:
        python, sites, extra_env = user_runtime()
    read_fd, write_fd = os.pipe()
    if isolation == "bwrap":
        package, probes = INSIDE / "package", INSIDE / "probes"
    else:
        package, probes = ws.package, ws.probes
    args = [str(package), str(probes), os.pathsep.join(sites), str(write_fd)] + [str(p) for p in probe]
    if isolation == "bwrap":
        bwrap = find_bwrap()
        command = _bwrap_command(_bwrap_for_user(bwrap) if as_user else bwrap, ws, python, args, memory_mb,
                                 (sites, extra_env) if as_user else None)
        env = {}
    else:
        command = [python, "-I", "-S", str(probes / BOOT)] + args
        env = dict(_child_env(scratch, memory_mb), **extra_env)
    uid = sandbox_uid() if as_user else None
    if uid is not None:
        os.chown(scratch, uid, uid)
    # The interpreter, numpy and the renderer take about 0.6 GB of address space before the
    # test's own memory_mb (0: no limit; llvmpipe reserves far more).
    limits = {"output": output_limit, "cpu": int(time_limit) + 2,
              "memory": (memory_mb + 768) * 1024 * 1024 if memory_mb else 0}
    output_path = scratch / "output.txt"
    start = time.monotonic()
    try:
        with open(output_path, "wb") as output:
            process = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=output, stderr=output,
                                       pass_fds=(write_fd,), cwd=str(scratch), env=env,
                                       start_new_session=True, preexec_fn=_preexec(limits, isolation, uid))
    finally:
        os.close(write_fd)
    chunks, size, status, detail = [], 0, None, ""
    deadline = start + time_limit
    try:
        while True:
            if size > RESULT_LIMIT:
                status, detail = "bad answer", "the test's answer was larger than %d bytes" % RESULT_LIMIT
                break
            left = deadline - time.monotonic()
            if left <= 0:
                status = "timeout"
                break
            ready, _, _ = select.select([read_fd], [], [], min(left, 0.1))
            if not ready:
                if process.poll() is not None:   # exited; a process it left may hold the pipe open
                    os.set_blocking(read_fd, False)
                    try:
                        chunk = os.read(read_fd, 1 << 16)
                    except BlockingIOError:
                        break
                    os.set_blocking(read_fd, True)
                    if not chunk:
                        break
                    chunks.append(chunk)
                    size += len(chunk)
                continue
            chunk = os.read(read_fd, 1 << 16)
            if not chunk:
                try:
                    process.wait(max(0.0, min(deadline - time.monotonic(), 5.0)))
                except subprocess.TimeoutExpired:
                    pass
                break
            chunks.append(chunk)
            size += len(chunk)
    finally:
        os.close(read_fd)
        try:
            os.killpg(process.pid, signal.SIGKILL)   # the child (under bwrap: its namespace) and its group
        except (ProcessLookupError, PermissionError):
            pass
        process.wait()
        if uid is not None:
            _kill_user(uid)                          # whatever left the group
        _reap_orphans(uid)
    seconds = time.monotonic() - start
    output = _read_output(output_path)
    if status is None:
        out_size = output_path.stat().st_size if output_path.exists() else 0
        if out_size >= output_limit:
            status, detail = "too much output", "your code printed %d bytes or more; the limit is %d" % (
                output_limit, output_limit)
    if status is None and process.returncode != 0:
        code = process.returncode
        status = "crashed"
        if code < 0:
            detail = {signal.SIGXCPU: "it used more than its CPU time",
                      signal.SIGSEGV: "it crashed (segmentation fault)"}.get(-code, "it was killed by signal %d" % -code)
        else:
            detail = "it exited (exit code %d) before the test finished" % code
    if status is None and not chunks:
        status, detail = "crashed", "it exited before the test finished"
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
