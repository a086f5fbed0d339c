"""Running untrusted student code: a student package, and a new interpreter per test inside
a sandbox.

``prepare`` builds, in a temporary folder, the package the submission runs in: the student
release of the package (rtfgu.grading.release.build_package: the assignment's functions and
every later one stubbed, the earlier ones revealed, no numba or WGSL twin, nothing of the
grader) with the submission's files put over it, and the probe code (the check modules
without their STAFF regions) beside it. A submitted Python file that does not compile is
replaced by its stub, so that it costs only the tests that need it.

``run_child`` starts ``python -I -S -c BOOTSTRAP`` for one test, never a fork of the grader
(whose memory holds the answers), inside the strongest isolation the machine allows:

* ``bwrap`` (bubblewrap): no network, its own PID namespace (nothing outlives the test), a
  read-only view of the system, the interpreter, its site-packages, the student package and
  the probes, and one writable scratch folder; nothing of the grader's checkout;
* ``unprivileged user`` (root without bwrap): the child runs as a user and group of its own
  (one per grading process, from RTFGU_SANDBOX_UID, default 64055, upwards: graders that
  run at once never share one), with no new privileges, a process and CPU limit, and every
  process of that user killed after the test. Where root may make namespaces (and
  RTFGU_FALLBACK_NAMESPACES is not 0) it also gets its own mount, network and IPC
  namespace: the whole file system read-only but its scratch folder, fresh temporary
  folders, and a /proc that shows its own processes only. Without them, what it leaves in
  the world-writable folders is removed after the test. The staff folder, the class folder
  and the submission are unreadable to it while grading, and every work folder is readable
  to its own grading's sandbox group only;
* ``rlimits only`` (neither): a new session and the resource limits.

Every child has a CPU, address-space and file-size limit. Nothing the grader reads back is
named in a folder the child can write: its output goes to an unnamed file the grader opened
and keeps, its answer (JSON) through a pipe; no folder the child must not learn is named in
any command line (the boot arguments arrive on stdin, bwrap's options through --args). The
parent kills it at the time limit. RTFGU_ISOLATION=bwrap|user|rlimits forces one (tests use
it to check the fallbacks).
"""
from __future__ import annotations

import ctypes
import fcntl
import hashlib
import json
import os
import platform
import resource
import select
import shutil
import signal
import stat
import site
import struct
import subprocess
import sys
import sysconfig
import tempfile
import time
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

from .archive import find_files, unpack_submission
from .bytecode import write_bytecode
from .generate import PACKAGE_DIR, student_files
from .release import build_package, probe_files
from .timeouts import boot_options

# Bytes of JSON a child may send back: the largest answer of a solution is a09's, 2.8 MB;
# every answer is parsed and judged by the grader, so its size bounds their time and memory.
RESULT_LIMIT = 8 * 1024 * 1024
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
    for name, text in probe_files(package_dir, hidden_table=False).items():
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
    # Each test's interpreter cannot write the package: it reads the grader's bytecode.
    write_bytecode(package, fresh=[package / "rtfgu" / relpath for relpath in assignment.files]
                   if submission is not None else ())
    write_bytecode(probes)
    _close_tree(root)
    hidden_probes_readable(ws, False)
    return ws


def _close_tree(root: Path) -> None:
    """Make ``root`` and everything in it readable to this grading's sandbox group only
    (root-owned, group the sandbox user's, 0750 / 0640) where the grader is root, else to the
    grader's user only (0700 / 0600): a submission's files and a solved package are never
    readable to another grading's student code."""
    group = _sandbox_group()
    for path in [root] + [p for p in root.rglob("*")]:
        if os.path.islink(path):
            continue
        folder = path.is_dir()
        if group is not None:
            os.chown(path, 0, group)
            os.chmod(path, 0o750 if folder else 0o640)
        else:
            os.chmod(path, 0o700 if folder else 0o600)


def hidden_probes_readable(ws: Workspace, readable: bool) -> None:
    """Let the sandbox group read the hidden tests' probe modules (``*_hidden.py`` and their
    bytecode) only while a hidden test runs (the grader calls this around each test): a
    visible test's code could otherwise read a hidden test's inputs and show them in its
    message. Where the grader is not root, student code runs as the grader's user, who
    can read them in any case."""
    if _sandbox_group() is None:
        return
    probes = ws.probes / PROBES
    for path in list(probes.glob("*_hidden.py")) + list(probes.glob("__pycache__/*_hidden.*.pyc")):
        os.chmod(path, 0o640 if readable else 0o600)


def _sandbox_group():
    """The group a work folder is readable to: the sandbox user's own where the grader is
    root, else None."""
    return sandbox_uid() if os.geteuid() == 0 else None


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
    .venv/sandbox), else a copy in the grader's runtime folder (root-owned, runtime_folder)."""
    if (_reachable_by_others(bwrap) and os.stat(bwrap).st_mode & stat.S_IXOTH
            and not _inside(bwrap, staff_folder())):
        return bwrap
    st = os.stat(bwrap)
    folder = runtime_folder() / ("bwrap-%d-%d" % (st.st_size, st.st_mtime_ns))
    if (folder / "bwrap").is_file():
        return str(folder / "bwrap")
    build = Path(tempfile.mkdtemp(prefix=folder.name + "-build-", dir=runtime_folder()))
    os.chmod(build, 0o755)
    shutil.copyfile(bwrap, build / "bwrap")
    os.chmod(build / "bwrap", 0o755)
    try:
        os.rename(build, folder)
    except OSError:  # another grader made it first
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
    # The root bwrap builds the view on is a tmpfs without a size; once every mount point is
    # made it is read-only, and /tmp (64 MB) and /dev/shm (16 MB) stay the only writable places.
    cmd += ["--ro-bind", str(ws.package), str(INSIDE / "package"),
            "--ro-bind", str(ws.probes), str(INSIDE / "probes"), "--remount-ro", "/", "--chdir", "/tmp"]
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
            "MKL_NUM_THREADS": "1", "NUMEXPR_NUM_THREADS": "1", "NUMBA_NUM_THREADS": "1",
            "LP_NUM_THREADS": "2", "RTFGU_MEMORY_MB": str(memory_mb)}


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


# Where root keeps what the sandbox users must not change: RTFGU_STATE_DIR, else the first of
# these that can be made safe. Never the world-writable temporary folder, where any user may
# put a file or a folder of their own at a name a grader will use. /var/lib first: the
# runtime copy is hard links where it shares a file system with the site-packages, and /run
# is often a tmpfs, where it would be a copy of every site-package in memory.
GRADER_FOLDERS = ("/var/lib/rtfgu", "/run/rtfgu")
_GRADER_FOLDER = {}


def _root_only_parents(path: Path) -> bool:
    """Whether only root can change what ``path`` names: every folder above it (links
    resolved) is owned by root and writable by no one else."""
    for parent in Path(os.path.realpath(path)).parents:
        st = os.lstat(parent)
        if st.st_uid != 0 or st.st_mode & 0o022:
            return False
    return True


def _root_folder(path: Path, mode: int) -> bool:
    """Make ``path`` a folder of root's with ``mode``; False where it cannot be one safely."""
    try:
        if not _root_only_parents(path):
            return False
        try:
            os.mkdir(path, mode)
        except FileExistsError:
            pass
        st = os.lstat(path)
        if not stat.S_ISDIR(st.st_mode) or st.st_uid != 0:
            return False
        if stat.S_IMODE(st.st_mode) != mode:
            os.chmod(path, mode)
        return True
    except OSError:
        return False


def grader_folder() -> Path:
    """Root's folder (0711) for the fallback: ``state`` (0700: the sandbox users' claims and
    the modes of the folders hidden while grading) and ``runtime`` (0755: the interpreter and
    bwrap copies the sandbox users run). RTFGU_STATE_DIR, else /var/lib/rtfgu, else
    /run/rtfgu; each must lie in folders only root can change."""
    wanted = os.environ.get("RTFGU_STATE_DIR") or ""
    if wanted not in _GRADER_FOLDER:
        candidates = [wanted] if wanted else list(GRADER_FOLDERS)
        for candidate in candidates:
            folder = Path(candidate)
            if (_root_folder(folder, 0o711) and _root_folder(folder / "state", 0o700)
                    and _root_folder(folder / "runtime", 0o755)):
                _GRADER_FOLDER[wanted] = folder
                break
        else:
            raise RuntimeError("the grader keeps the sandbox users' state in a folder only root can change "
                               "(%s); none of them can be made here: set RTFGU_STATE_DIR to a folder whose "
                               "parents are root's and not writable by others" % ", ".join(candidates))
    return _GRADER_FOLDER[wanted]


def state_folder() -> Path:
    """Root-owned, mode 0700: what no sandbox user may read or change."""
    return grader_folder() / "state"


def runtime_folder() -> Path:
    """Root-owned, mode 0755: what the sandbox users run but may not change."""
    return grader_folder() / "runtime"


def _names_the_staff_package(name: str) -> bool:
    """An editable install's finder and the staff package's metadata: they name the checkout
    (direct_url.json, the finder's mapping) and the child never reads them (-S)."""
    return name.startswith("__editable__") or name.startswith("rtfgu-") and name.endswith((".dist-info", ".egg-info"))


def _link_tree(src: Path, dst: Path, skip=()) -> None:
    """``dst`` as hard links to ``src``'s files (copies where a link cannot be made or the
    file is not readable by others), without the folders named in ``skip``, without what
    names the staff package, and without links that lead out of ``src``."""
    src = Path(src)
    for root, dirs, files in os.walk(src):
        here = Path(root)
        dirs[:] = [d for d in dirs if d not in skip and str(here / d) not in skip and not _names_the_staff_package(d)
                   and not os.path.islink(here / d)]
        out = dst / here.relative_to(src)
        out.mkdir(parents=True, exist_ok=True)
        os.chmod(out, 0o755)
        for name in files:
            if _names_the_staff_package(name):
                continue
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


def user_runtime():
    """(interpreter, site folders, environment) the sandbox user can run with the staff folder
    hidden: the grader's own where that user can reach them, else a cached tree of hard links
    to them (the interpreter, its libpython and standard library, the site-packages without
    the staff package) in the runtime folder (root-owned, runtime_folder), reused by later
    graders."""
    python, sites = os.path.realpath(sys.executable), _site_dirs()
    stdlib = sysconfig.get_paths()["stdlib"]
    hidden = staff_folder()
    if all(_reachable_by_others(p) and not _inside(p, hidden) for p in [python, stdlib] + sites):
        return python, sites, {}
    libdir = sysconfig.get_config_var("LIBDIR") or os.path.join(sys.base_prefix, "lib")
    key = repr((2, python, stdlib, sites, [os.stat(p).st_mtime_ns for p in [python, stdlib] + sites]))
    root = runtime_folder() / ("python-%s" % hashlib.sha256(key.encode()).hexdigest()[:16])
    version = "python%d.%d" % sys.version_info[:2]
    runtime_python = root / "bin" / os.path.basename(python)
    runtime_sites = [root / ("site%d" % i) for i in range(len(sites))]
    env = {"LD_LIBRARY_PATH": str(root / "lib")}
    if (root / ".complete").exists():
        return str(runtime_python), [str(s) for s in runtime_sites], env
    build = Path(tempfile.mkdtemp(prefix=root.name + "-build-", dir=runtime_folder()))
    try:
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
        os.rename(build, root)
    except OSError:  # another grader built it first
        shutil.rmtree(build, ignore_errors=True)
        if not (root / ".complete").exists():
            raise
    return str(runtime_python), [str(s) for s in runtime_sites], env


def _open_own(path: Path) -> int:
    """``path`` opened for reading and writing, a regular file of the grader's user that no
    one else can write (made afresh if it is not)."""
    fd = os.open(path, os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW, 0o600)
    st = os.fstat(fd)
    if st.st_uid == os.geteuid() and stat.S_ISREG(st.st_mode) and st.st_nlink == 1 and not st.st_mode & 0o022:
        return fd
    os.close(fd)
    os.unlink(path)
    return os.open(path, os.O_RDWR | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o600)


@contextmanager
def hidden_from_sandbox_user(isolation: str, extra=()):
    """While grading under ``unprivileged user``, the staff folder and the paths in ``extra``
    (the submission, the class folder, a result folder) are closed to everyone but their
    owner (a folder 0700, a file 0600): the sandbox user cannot read the solutions, the
    references, the grader, or any student's files. Graders that overlap share this through
    a state file in the state folder (root-owned, 0700), and the last one out restores each
    path's mode."""
    if isolation != "unprivileged user":
        yield
        return
    paths = [str(staff_folder())]
    for path in extra:
        if path is not None and os.path.lexists(path) and not os.path.islink(path):
            real = os.path.realpath(path)
            if real not in paths:
                paths.append(real)
    state_path = state_folder() / "hidden.json"

    def update(change):
        fd = _open_own(state_path)
        with os.fdopen(fd, "r+") as f:
            fcntl.flock(f, fcntl.LOCK_EX)
            try:
                state = json.loads(f.read() or "{}")
            except ValueError:
                state = {}
            for path in paths:
                if not os.path.exists(path):
                    state.pop(path, None)
                    continue
                entry = state.get(path) or {"mode": stat.S_IMODE(os.stat(path).st_mode), "pids": []}
                entry["pids"] = [p for p in entry["pids"] if _alive(p)]
                change(entry)
                if entry["pids"]:
                    state[path] = entry
                    os.chmod(path, 0o700 if os.path.isdir(path) else 0o600)
                else:
                    state.pop(path, None)
                    os.chmod(path, entry["mode"])
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
    """A temporary folder for one grading: where the grader is root, root's with the group of
    this process's sandbox user and mode 0710 (that user may pass through, no other sandbox
    user may enter, no one may list it); else the grader's own, 0700."""
    with tempfile.TemporaryDirectory(prefix=prefix) as tmp:
        group = _sandbox_group()
        if group is not None:
            os.chown(tmp, 0, group)
            os.chmod(tmp, 0o710)
        else:
            os.chmod(tmp, 0o700)
        yield Path(tmp)


UID_SLOTS = 256                        # sandbox users: SANDBOX_UID .. SANDBOX_UID + UID_SLOTS - 1
_UID_CLAIM = {}                        # pid -> (uid, the open lock file whose byte it holds)


def sandbox_uid() -> int:
    """The sandbox user (and group, the same number) of this grading process: the first uid
    from SANDBOX_UID whose byte of the claims file (state folder, root's alone) no other
    live process has locked. Graders that run at once (grade-all's workers, two graders on
    one machine) get different users, so killing every process of one's user after a test
    never touches another's test, and one submission's processes cannot reach another's.
    The claim lasts as long as this process; a new claim first ends every process and
    removes every file a crashed earlier grader's tests left as that user."""
    pid = os.getpid()
    if pid in _UID_CLAIM:
        return _UID_CLAIM[pid][0]
    fd = os.open(state_folder() / "uids.lock", os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW | os.O_CLOEXEC, 0o600)
    for slot in range(UID_SLOTS):
        try:
            fcntl.lockf(fd, fcntl.LOCK_EX | fcntl.LOCK_NB, 1, slot)
        except OSError:
            continue
        uid = SANDBOX_UID + slot
        _UID_CLAIM[pid] = (uid, fd)
        _kill_user(uid)
        clean_user_files(uid)
        remove_stale_work_folders(uid)
        return uid
    os.close(fd)
    raise RuntimeError("all %d sandbox users (uid %d and up) are taken by other graders"
                       % (UID_SLOTS, SANDBOX_UID))


# --- namespaces for the fallback, where root may make them ---------------------------------

CLONE_NEWNS, CLONE_NEWIPC, CLONE_NEWNET = 0x00020000, 0x08000000, 0x40000000
MS_NOSUID, MS_NODEV, MS_NOEXEC, MS_REMOUNT, MS_BIND, MS_REC, MS_PRIVATE = 2, 4, 8, 32, 4096, 16384, 1 << 18
MOUNT_ATTR_RDONLY, AT_RECURSIVE, AT_FDCWD, SYS_MOUNT_SETATTR = 0x1, 0x8000, -100, 442
PR_SET_NO_NEW_PRIVS = 38
# The world-writable folders: covered by fresh tmpfs mounts in the namespace, else cleaned
# of the sandbox user's files after each test.
SHARED_TMP = ("/tmp", "/var/tmp", "/dev/shm", "/run/lock", "/var/lock", "/dev/mqueue")
_NAMESPACES = {}                       # pid -> whether this process's fallback children get them


def _world_writable_folders() -> list:
    out = []
    for path in SHARED_TMP + (tempfile.gettempdir(),):
        try:
            st = os.lstat(path)
        except OSError:
            continue
        real = os.path.realpath(path)
        if stat.S_ISDIR(st.st_mode) and st.st_mode & stat.S_IWOTH and real not in out:
            out.append(real)
    return out


def _libc():
    return ctypes.CDLL(None, use_errno=True)


def _check(result, what: str) -> None:
    if result != 0:
        errno = ctypes.get_errno()
        raise OSError(errno, "%s: %s" % (what, os.strerror(errno)))


def _mount_setattr(libc, path: str, set_flags: int, clear_flags: int, recursive: bool) -> None:
    attr = ctypes.create_string_buffer(struct.pack("QQQQ", set_flags, clear_flags, 0, 0))
    _check(libc.syscall(SYS_MOUNT_SETATTR, AT_FDCWD, path.encode(), AT_RECURSIVE if recursive else 0, attr, 32),
           "mount_setattr %s" % path)


def _enter_namespaces(views: list, writable: str) -> None:
    """Runs between fork and exec as root: a mount, network and IPC namespace of the child's
    own, every mount in it read-only, fresh tmpfs mounts over the world-writable folders, the
    folders in ``views`` (the student package, the probes) bound back read-only where a tmpfs
    covered them, ``writable`` (the scratch folder) bound writable, and a /proc that shows
    only the sandbox user's own processes. Raises if any step fails."""
    libc = _libc()
    _check(libc.unshare(CLONE_NEWNS | CLONE_NEWNET | CLONE_NEWIPC), "unshare")
    _check(libc.mount(None, b"/", None, MS_REC | MS_PRIVATE, None), "make / private")
    binds = [(path, os.open(path, os.O_PATH | os.O_CLOEXEC), False) for path in views]
    binds.append((writable, os.open(writable, os.O_PATH | os.O_CLOEXEC), True))
    _mount_setattr(libc, "/", MOUNT_ATTR_RDONLY, 0, True)
    for folder in _world_writable_folders():
        size = SHM_BYTES if folder == "/dev/shm" else SCRATCH_BYTES
        _check(libc.mount(b"tmpfs", folder.encode(), b"tmpfs", MS_NOSUID | MS_NODEV,
                          ("size=%d,mode=1777" % size).encode()), "tmpfs on %s" % folder)
    for path, fd, rw in binds:
        os.makedirs(path, exist_ok=True)
        _check(libc.mount(("/proc/self/fd/%d" % fd).encode(), path.encode(), None, MS_BIND | MS_REC, None),
               "bind %s" % path)
        os.close(fd)
        _mount_setattr(libc, path, 0 if rw else MOUNT_ATTR_RDONLY, MOUNT_ATTR_RDONLY if rw else 0, not rw)
    _check(libc.mount(b"proc", b"/proc", b"proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, b"hidepid=2"), "proc")
    os.chdir(writable)


def fallback_namespaces() -> bool:
    """Whether the fallback's children get _enter_namespaces here: root may unshare and mount
    (CAP_SYS_ADMIN; a container usually forbids it), and RTFGU_FALLBACK_NAMESPACES is not 0.
    Tried once per process by running ``true`` that way."""
    if os.environ.get("RTFGU_FALLBACK_NAMESPACES", "") == "0" or os.geteuid() != 0:
        return False
    pid = os.getpid()
    if pid not in _NAMESPACES:
        _NAMESPACES[pid] = False
        true = shutil.which("true") or "/bin/true"
        with tempfile.TemporaryDirectory(prefix="rtfgu-namespaces-") as tmp:
            view, scratch = Path(tmp) / "view", Path(tmp) / "scratch"
            view.mkdir()
            scratch.mkdir()

            def enter():
                _enter_namespaces([str(view)], str(scratch))
            try:
                done = subprocess.run([true], preexec_fn=enter, capture_output=True, timeout=20, cwd=tmp)
                _NAMESPACES[pid] = done.returncode == 0
            except (OSError, subprocess.SubprocessError):
                pass
    return _NAMESPACES[pid]


NPROC = 64                             # processes (threads count) of a test at most


def _preexec(limits: dict, isolation: str, uid=None, namespaces=None):
    """Runs between fork and exec (nothing of the student's runs before exec). ``namespaces``:
    (views, writable) for _enter_namespaces, or None."""
    def run():
        resource.setrlimit(resource.RLIMIT_FSIZE, (limits["output"], limits["output"]))
        resource.setrlimit(resource.RLIMIT_CPU, (limits["cpu"], limits["cpu"] + 1))
        if limits["memory"]:
            resource.setrlimit(resource.RLIMIT_AS, (limits["memory"], limits["memory"]))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        # No POSIX message queue can be made: one outlives its test, and without namespaces the
        # next student graded as the same user would open it (/dev/mqueue need not be mounted
        # for the sweep to see it).
        resource.setrlimit(resource.RLIMIT_MSGQUEUE, (0, 0))
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # an oversized write fails with an error instead
        if uid is not None:                            # the sandbox user (bwrap's, or the fallback's)
            if isolation == "unprivileged user":
                if namespaces is not None:
                    _enter_namespaces(*namespaces)
                else:
                    try:
                        _libc().unshare(CLONE_NEWNET)
                    except Exception:
                        pass
            os.setgroups([])
            os.setgid(uid)
            os.setuid(uid)
            resource.setrlimit(resource.RLIMIT_NPROC, (NPROC, NPROC))
            if isolation == "unprivileged user":       # no setuid or setgid program gives anything back
                _check(_libc().prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0), "no_new_privs")
    return run


# keyctl(2): its system call's number, by machine (the C library has no wrapper of it).
SYS_KEYCTL = {"x86_64": 250, "aarch64": 219, "i686": 288, "i386": 288}
KEYCTL_CLEAR = 7
KEY_SPEC_USER_KEYRING = -4
KEY_SPEC_USER_SESSION_KEYRING = -5


def _kill_user(uid: int) -> None:
    """Kill every process of ``uid`` (a sandbox user: only test processes), and empty its user
    and user-session keyrings: the kernel keeps them per user, not per process, so keys a test
    added (add_key(2)) would be read by the next student graded as the same user."""
    syscall = _libc().syscall if platform.machine() in SYS_KEYCTL else None   # looked up before the fork
    pid = os.fork()
    if pid == 0:  # pragma: no cover (the child)
        try:
            os.setgid(uid)
            os.setuid(uid)
            os.kill(-1, signal.SIGKILL)
            if syscall is not None:
                number = SYS_KEYCTL[platform.machine()]
                syscall(number, KEYCTL_CLEAR, KEY_SPEC_USER_KEYRING)
                syscall(number, KEYCTL_CLEAR, KEY_SPEC_USER_SESSION_KEYRING)
        except BaseException:
            pass
        os._exit(0)
    os.waitpid(pid, 0)


SWEEP_DEPTH = 8                        # world-writable folders inside world-writable folders looked into


def remove_stale_work_folders(gid: int, folder: str | None = None) -> list:
    """Remove the work folders (work_folder: root's, group ``gid``) that a grader holding this
    sandbox user left when it was killed before it could remove them: their packages are
    readable by the group, so the next submission graded as that user would find another
    student's files there. Called when the user is claimed, when no live grader holds it.
    Returns the folders removed."""
    folder = folder or tempfile.gettempdir()
    removed = []
    try:
        entries = list(os.scandir(folder))
    except OSError:
        return removed
    for entry in entries:
        if not entry.name.startswith("rtfgu-grade-"):
            continue
        try:
            st = entry.stat(follow_symlinks=False)
        except OSError:
            continue
        if stat.S_ISDIR(st.st_mode) and st.st_uid == os.geteuid() and st.st_gid == gid:
            shutil.rmtree(entry.path, ignore_errors=True)
            removed.append(entry.path)
    return removed


def clean_user_files(uid: int) -> list:
    """Remove what ``uid`` (a sandbox user, none of whose processes runs) left outside its
    scratch folder: its files and folders in the world-writable folders (and in the
    world-writable folders inside them), and its System V shared memory, semaphores and
    message queues. Returns the paths removed. A test that ran in its own namespaces left
    nothing there; one that did not could, and the next submission graded as the same user
    must not find it."""
    removed = []

    def sweep(folder: str, depth: int) -> None:
        try:
            entries = list(os.scandir(folder))
        except OSError:
            return
        for entry in entries:
            try:
                st = entry.stat(follow_symlinks=False)
            except OSError:
                continue
            if st.st_uid == uid:
                if stat.S_ISDIR(st.st_mode):
                    shutil.rmtree(entry.path, ignore_errors=True)
                else:
                    try:
                        os.unlink(entry.path)
                    except OSError:
                        continue
                removed.append(entry.path)
            elif stat.S_ISDIR(st.st_mode) and st.st_mode & stat.S_IWOTH and depth < SWEEP_DEPTH:
                sweep(entry.path, depth + 1)

    for folder in _world_writable_folders():
        sweep(folder, 0)
    removed += _remove_ipc(uid)
    return removed


IPC_RMID = 0


def _remove_ipc(uid: int) -> list:
    """The System V IPC objects of ``uid`` (in this IPC namespace), removed."""
    removed = []
    libc = None
    for kind, uid_column in (("shm", 7), ("sem", 4), ("msg", 7)):
        try:
            with open("/proc/sysvipc/" + kind) as f:
                rows = f.read().splitlines()[1:]
        except OSError:
            continue
        for row in rows:
            fields = row.split()
            try:
                if int(fields[uid_column]) != uid:
                    continue
                ident = int(fields[1])
            except (IndexError, ValueError):
                continue
            libc = libc or _libc()
            if kind == "shm":
                libc.shmctl(ident, IPC_RMID, None)
            elif kind == "sem":
                libc.semctl(ident, 0, IPC_RMID)
            else:
                libc.msgctl(ident, IPC_RMID, None)
            removed.append("%s %d" % (kind, ident))
    return removed


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
            _libc().prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)
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
    dump: str = ""       # the child's tracebacks shortly before its time limit (rtfgu.grading.timeouts)


# The child's whole command line besides the interpreter: its boot arguments (the folders of
# the package, the probes and the site-packages, the answer pipe, the probe) come as JSON on
# stdin, which is then /dev/null for the student's code.
BOOTSTRAP = ("import json, os, runpy, sys\n"
             "argv = json.loads(sys.stdin.buffer.read())\n"
             "null = os.open(os.devnull, os.O_RDONLY)\n"
             "os.dup2(null, 0)\n"
             "os.close(null)\n"
             "sys.argv = argv\n"
             "runpy.run_path(argv[0], run_name='__main__')\n")
PIPE_BYTES = 60000                     # what is written into a pipe before its reader starts, at most


def _pipe_with(data: bytes) -> int:
    """The read end of a pipe that holds ``data`` and is closed for writing."""
    if len(data) > PIPE_BYTES:
        raise ValueError("%d bytes of arguments do not fit a pipe" % len(data))
    read_fd, write_fd = os.pipe()
    try:
        os.write(write_fd, data)
    finally:
        os.close(write_fd)
    return read_fd


def run_child(ws: Workspace, scratch: Path, probe: list, *, isolation: str, time_limit: float = 10.0,
              memory_mb: int = 1024, output_limit: int = 1024 * 1024, stopped=()) -> ChildResult:
    """Run one probe (["check", assignment id, slug], ["probe", module, function, kwargs as
    JSON] or ["render", scene, width, height]) in a new interpreter under ``isolation``; its
    answer is JSON through a pipe, its output goes to an unnamed file the grader keeps open
    (at most ``output_limit`` bytes). ``scratch`` is the child's working folder under the
    fallback (its own, mode 0700). ``stopped``: the student functions earlier time limits
    stopped (rtfgu.grading.timeouts); the result holds the child's tracebacks on a timeout."""
    scratch = Path(scratch)
    scratch.parent.mkdir(parents=True, exist_ok=True)
    scratch.mkdir(exist_ok=True)
    if not stat.S_ISDIR(os.lstat(scratch).st_mode):
        raise RuntimeError("the scratch folder %s is not a folder" % scratch)
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
    dump = tempfile.TemporaryFile(dir=str(scratch.parent))     # the tracebacks before the limit
    dump_fd = os.dup(dump.fileno())
    boot = [str(probes / BOOT), str(package), str(probes), os.pathsep.join(sites), str(write_fd),
            boot_options(dump_fd, time_limit, stopped)] + [str(p) for p in probe]
    command = [python, "-I", "-S", "-c", BOOTSTRAP]
    fds = [read_fd, write_fd, dump_fd]
    pass_fds = [write_fd, dump_fd]
    namespaces = None
    if isolation == "bwrap":
        bwrap = find_bwrap()
        full = _bwrap_command(_bwrap_for_user(bwrap) if as_user else bwrap, ws, python, [], memory_mb,
                              (sites, extra_env) if as_user else None)
        options = full[1:full.index("--")]
        args_fd = _pipe_with(b"".join(o.encode() + b"\0" for o in options))
        fds.append(args_fd)
        pass_fds.append(args_fd)
        command = [full[0], "--args", str(args_fd), "--"] + command
        env = {}
    else:
        env = dict(_child_env(scratch, memory_mb), **extra_env)
        if isolation == "unprivileged user" and fallback_namespaces():
            namespaces = ([str(ws.package), str(ws.probes)], str(scratch))
    uid = sandbox_uid() if as_user else None
    if uid is not None:
        os.chown(scratch, uid, uid)
        os.chmod(scratch, 0o700)
    # The interpreter, numpy and the renderer take about 0.6 GB of address space before the
    # test's own memory_mb (0: no limit; llvmpipe reserves far more).
    limits = {"output": output_limit, "cpu": int(time_limit) + 2,
              "memory": (memory_mb + 768) * 1024 * 1024 if memory_mb else 0}
    boot_fd = _pipe_with(json.dumps(boot).encode())
    fds.append(boot_fd)
    output = tempfile.TemporaryFile(dir=str(scratch.parent))   # no name: nothing to replace or link
    start = time.monotonic()
    try:
        process = subprocess.Popen(command, stdin=boot_fd, stdout=output, stderr=output,
                                   pass_fds=tuple(pass_fds), cwd=str(scratch), env=env, start_new_session=True,
                                   preexec_fn=_preexec(limits, isolation, uid, namespaces))
    except BaseException:
        output.close()
        dump.close()
        os.close(read_fd)
        raise
    finally:
        for fd in fds[1:]:
            os.close(fd)
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
        if isolation == "unprivileged user" and uid is not None:
            clean_user_files(uid)
        with output:
            out_size = os.fstat(output.fileno()).st_size
            out_text = _read_output(output.fileno())
        with dump:
            dump_text = _read_output(dump.fileno(), 16000) if status == "timeout" else ""
    seconds = time.monotonic() - start
    if status is None and out_size >= output_limit:
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
        except (ValueError, RecursionError):   # nested deeper than the parser's stack: not the probe's
            return ChildResult("bad answer", None, out_text, seconds, "the test's answer was not readable")
        if not isinstance(data, dict):
            return ChildResult("bad answer", None, out_text, seconds, "the test's answer was not an object")
        return ChildResult("ok", data, out_text, seconds)
    return ChildResult(status, None, out_text, seconds, detail, dump_text)


def _read_output(fd: int, limit: int = 2000) -> str:
    """The first ``limit`` characters of the output file open at ``fd`` (read by position:
    the descriptor the grader made, never a path)."""
    try:
        data = os.pread(fd, limit + 1, 0)
    except OSError:
        return ""
    text = data[:limit].decode("utf-8", "replace")
    return text + ("\n[... output cut]" if len(data) > limit else "")
