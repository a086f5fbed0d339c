"""The fallback holds what bubblewrap holds: attacks on the grader itself, each graded under
bwrap, under the fallback as root without bwrap (RTFGU_BWRAP=none) as a container that forbids
namespaces runs it (RTFGU_FALLBACK_NAMESPACES=0: the Gradescope case), and under the fallback
with the namespaces root may make here.

Each attack is a03's honest part (solved plane and triangle) with a sphere whose intersect_p
attacks and then gives up as the stub does. Every grading must score exactly what the honest
part scores, test by test; end within its tests' time limits; leave no process and no file of
its sandbox user behind; change nothing outside its scratch folder; and show no byte of
anything the child must not read. A mode that cannot run here is skipped, and says why.
"""
from __future__ import annotations

import json
import os
import signal
import stat
import subprocess
import sys
import tempfile
import textwrap
import time
from contextlib import contextmanager
from pathlib import Path

import pytest

from rtfgu.grading import sandbox
from rtfgu.grading.generate import PACKAGE_DIR, solution_files, student_files, write_files
from rtfgu.grading.grader import REFERENCE_DIR, grade

ROOT = Path(__file__).resolve().parent.parent
SPHERE = "shapes/sphere.py"
STUB_LINE = "        raise NotImplementedError('a03: Sphere.intersect_p')\n"
STAFF_SPHERE = PACKAGE_DIR / SPHERE
OBSERVATIONS = REFERENCE_DIR / "a03_intersections" / "observations.json"
ONLY = ("01_plane_intersect_p_hits_misses_and_the_ray_interv", "02_sphere_intersect_p_rays_that_hit",
        "05_triangle_intersect_p_inside_outside_and_the_ray_",
        "10_sphere_intersect_p_with_directions_that_are_not_")
TIME_LIMIT = 5.0
# What no test message may hold: a line of the solved sphere, a fragment of the stored
# references (as the file holds them), and the start of root's password file.
SOLVED_LINE = next(line for line in solution_files("a03")[SPHERE].splitlines()
                   if "sqrt" in line and "=" in line).strip()
NEEDLE = OBSERVATIONS.read_text()[40:120]
MODES = ("bwrap", "fallback", "fallback with namespaces")


def _skip_unless(mode: str) -> None:
    if mode == "bwrap":
        if not sandbox.bwrap_works(sandbox.find_bwrap()):
            pytest.skip("bubblewrap is not installed or cannot make its namespaces here (Debian package "
                        "bubblewrap; `make venv` fetches it)")
        return
    if os.geteuid() != 0:
        pytest.skip("the fallback runs student code as a sandbox user, which needs the grader to run as root")
    if mode == "fallback with namespaces":
        with _env(RTFGU_FALLBACK_NAMESPACES="1"):
            if not sandbox.fallback_namespaces():
                pytest.skip("root may not make mount, network and IPC namespaces here (no CAP_SYS_ADMIN, or a "
                            "seccomp filter, as in a default Docker container)")


@contextmanager
def _env(**values):
    old = {k: os.environ.get(k) for k in values}
    os.environ.update(values)
    try:
        yield
    finally:
        for k, v in old.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


@pytest.fixture(params=MODES)
def mode(request, monkeypatch):
    _skip_unless(request.param)
    if request.param == "bwrap":
        monkeypatch.setenv("RTFGU_ISOLATION", "bwrap")
    else:
        monkeypatch.setenv("RTFGU_BWRAP", "none")
        monkeypatch.delenv("RTFGU_ISOLATION", raising=False)
        monkeypatch.setenv("RTFGU_FALLBACK_NAMESPACES", "1" if request.param.endswith("namespaces") else "0")
    return request.param


def _isolation(mode: str) -> str:
    return "bwrap" if mode == "bwrap" else "unprivileged user"


def _sphere_with(attack: str) -> str:
    stub = student_files("a03")[SPHERE]
    assert STUB_LINE in stub
    return stub.replace(STUB_LINE, textwrap.indent(textwrap.dedent(attack).strip("\n"), " " * 8) + "\n" + STUB_LINE)


def _submission(folder: Path, attack: str = "") -> Path:
    files = dict(solution_files("a03"))
    files[SPHERE] = _sphere_with(attack) if attack else student_files("a03")[SPHERE]
    write_files(files, folder)
    return folder


def _scores(result) -> dict:
    return {t.number: t.score for t in result.tests}


_HONEST = {}


def honest(mode: str, tmp_path: Path, only=ONLY) -> dict:
    key = (mode, only)
    if key not in _HONEST:
        result = _graded(mode, _submission(tmp_path / "honest"), None, only=only)
        scores = _scores(result)
        assert 0 < sum(scores.values()) < sum(t.max_score for t in result.tests)
        _HONEST[key] = scores
    return _HONEST[key]


def _sandbox_processes(uid: int) -> list:
    out = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                if os.stat("/proc/" + entry).st_uid == uid:
                    out.append(entry)
            except OSError:
                pass
    return out


def _sandbox_files(uid: int) -> list:
    """The files of ``uid`` in the world-writable folders (and those inside them)."""
    found = []

    def walk(folder, depth):
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
                found.append(entry.path)
            elif stat.S_ISDIR(st.st_mode) and st.st_mode & stat.S_IWOTH and depth < 8:
                walk(entry.path, depth + 1)
    for folder in sandbox._world_writable_folders():
        walk(folder, 0)
    return found


def _staff_digest() -> dict:
    paths = [STAFF_SPHERE] + sorted(OBSERVATIONS.parent.iterdir())
    return {p: p.read_bytes() for p in paths}


def _git_status() -> str:
    return subprocess.run(["git", "status", "--porcelain", "--", "rtfgu/grading"], cwd=ROOT, capture_output=True,
                          text=True).stdout


class Hung(Exception):
    pass


def _graded(mode: str, submission, out, *, only=ONLY, assignment="a03"):
    """Grade with a watchdog (every test's time limit plus the start of its interpreter, and
    the grader's own work) and check what every grading must leave as it was."""
    tests = len(only) if only else 20
    deadline = int(tests * (TIME_LIMIT + 5) + 30)

    def hung(signum, frame):
        raise Hung("the grading did not end within %d s" % deadline)
    previous = signal.signal(signal.SIGALRM, hung)
    signal.alarm(deadline)
    staff, status = _staff_digest(), _git_status()
    try:
        result = grade(assignment, submission, out, only=only, time_limit=TIME_LIMIT)
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)
    assert result.isolation == _isolation(mode)
    assert _staff_digest() == staff and _git_status() == status
    if os.geteuid() == 0:
        uid = sandbox.sandbox_uid()
        assert _sandbox_processes(uid) == [], "processes of the sandbox user %d are left" % uid
        assert _sandbox_files(uid) == [], "files of the sandbox user %d are left" % uid
    for test in result.tests:
        for secret in (SOLVED_LINE, NEEDLE, "root:"):
            assert secret not in test.output, (test.number, test.output[:3000])
        assert "LEAKED" not in test.output, test.output[:3000]
    return result


@pytest.fixture
def world_readable():
    """A folder any user may pass through and read, as a staff member's home or /srv may be."""
    folder = Path(tempfile.mkdtemp(prefix="rtfgu-world-readable-"))
    os.chmod(folder, 0o755)
    yield folder
    subprocess.run(["rm", "-rf", str(folder)], check=False)


# --- the output file --------------------------------------------------------------------------

def test_an_output_file_replaced_by_a_link_shows_nothing_it_points_to(mode, tmp_path):
    # The grader once read the test's output back by its name in the child's own folder, as
    # root and following links: a link put there showed any file root can read.
    attack = """
        import glob, os
        targets = [%(sphere)r, %(obs)r, "/etc/shadow"]
        names = set(os.listdir(".")) | {"output.txt", "stdout.txt", "stderr.txt"}
        for place in ["/proc/self/fd/1", "/proc/self/fd/2"]:
            try:
                names.add(os.readlink(place).replace(" (deleted)", ""))
            except OSError:
                pass
        for i, name in enumerate(sorted(names)):
            try:
                os.unlink(name)
            except OSError:
                pass
            try:
                os.symlink(targets[i %% len(targets)], name)
            except OSError:
                pass
        print("the output was replaced by links")
        """ % {"sphere": str(STAFF_SPHERE), "obs": str(OBSERVATIONS)}
    want = honest(mode, tmp_path)
    result = _graded(mode, _submission(tmp_path / "sub", attack), tmp_path / "out")
    assert _scores(result) == want
    assert any("the output was replaced by links" in t.output for t in result.tests)


def test_an_output_file_replaced_by_a_named_pipe_does_not_stop_the_grader(mode, tmp_path):
    # Opened by name, a FIFO without a writer blocked the grader for ever.
    attack = """
        import os
        for name in set(os.listdir(".")) | {"output.txt"}:
            try:
                os.unlink(name)
            except OSError:
                pass
            try:
                os.mkfifo(name)
            except OSError:
                pass
        print("the output was replaced by a named pipe")
        """
    want = honest(mode, tmp_path)
    start = time.monotonic()
    result = _graded(mode, _submission(tmp_path / "sub", attack), tmp_path / "out")
    assert _scores(result) == want
    assert time.monotonic() - start < len(ONLY) * (TIME_LIMIT + 5)
    assert any("the output was replaced by a named pipe" in t.output for t in result.tests)


# --- another submission graded at the same time ---------------------------------------------

PEER = textwrap.dedent("""
    import sys, time
    from pathlib import Path
    from rtfgu.grading.assignments import get_assignment
    from rtfgu.grading.sandbox import choose_isolation, prepare, run_child, work_folder
    isolation = choose_isolation()
    with work_folder() as tmp:
        ws = prepare(get_assignment("a03"), sys.argv[1], tmp / "work")
        print(tmp, flush=True)
        child = run_child(ws, tmp / "scratch" / "peer", ["check", get_assignment("a03").id, sys.argv[2]], isolation=isolation,
                          time_limit=float(sys.argv[3]))
        print(child.status, flush=True)
    """)


def test_a_submission_graded_at_the_same_time_cannot_be_read_or_run(mode, tmp_path):
    # A peer's grading runs in another process (as grade-all's workers do), its test still
    # running: the attack is told where the peer's package lies (no command line may say it),
    # and reads, or runs, the peer's solved sphere if it can.
    peer = dict(solution_files("a03"))
    peer[SPHERE] = peer[SPHERE].replace("    def intersect_p(self, ray: Ray) -> bool:\n",
                                        "    def intersect_p(self, ray: Ray) -> bool:\n"
                                        "        import time; time.sleep(12)\n", 1)
    write_files(peer, tmp_path / "peer")
    want = honest(mode, tmp_path)
    helper = subprocess.Popen([sys.executable, "-c", PEER, str(tmp_path / "peer"), ONLY[1], "14"],
                              stdout=subprocess.PIPE, text=True, cwd=str(ROOT), env=dict(os.environ))
    try:
        work = helper.stdout.readline().strip()
        assert work, "the peer's grader did not start"
        time.sleep(1.5)                       # its test's interpreter is running now
        seen = [p for p in os.listdir("/proc") if p.isdigit() and work.encode() in _cmdline(p)]
        assert seen == [], "the peer's work folder is named in the command lines of %s" % seen
        attack = """
            import glob, os
            places = [%(sphere)r] + glob.glob(%(pattern)r)
            for pid in [p for p in os.listdir("/proc") if p.isdigit()]:
                try:
                    words = open("/proc/%%s/cmdline" %% pid, "rb").read().split(b"\\0")
                except OSError:
                    continue
                for word in words:
                    if b"rtfgu-grade-" in word:
                        text = word.decode(errors="replace")
                        raise RuntimeError("LEAKED a work folder in the command line of %%s: %%s" %% (pid, text))
            for place in places:
                try:
                    source = open(place).read()
                except OSError:
                    continue
                if "NotImplementedError('a03: Sphere.intersect_p')" not in source:
                    source = source.replace("import time; time.sleep(12)", "pass")
                    namespace = {"__name__": "rtfgu.shapes.peer", "__package__": "rtfgu.shapes"}
                    exec(compile(source, place, "exec"), namespace)
                    return namespace["Sphere"].intersect_p(self, ray)
            """ % {"sphere": str(Path(work) / "work" / "package" / "rtfgu" / SPHERE),
                   "pattern": str(Path(tempfile.gettempdir()) / "rtfgu-grade-*" / "work" / "package" / "rtfgu" / SPHERE)}
        result = _graded(mode, _submission(tmp_path / "sub", attack), tmp_path / "out")
        assert helper.poll() is None, "the peer's grading ended before the attack's: nothing was tested"
        assert _scores(result) == want
    finally:
        out, _ = helper.communicate(timeout=60)
    assert helper.returncode == 0 and "timeout" in out


def _cmdline(pid: str) -> bytes:
    try:
        with open("/proc/%s/cmdline" % pid, "rb") as f:
            return f.read()
    except OSError:
        return b""


def test_grade_all_keeps_each_students_files_from_the_others(mode, tmp_path, world_readable):
    # The class folder is named in grade-all's command line; it lies in a folder anyone may
    # read. The attacker is told where its classmate's files and results are.
    from rtfgu.grading.gradebook import grade_all

    klass = world_readable / "class"
    write_files(solution_files("a03"), klass / "ann")
    attack = """
        for place in (%(sphere)r, %(results)r):
            try:
                source = open(place).read()
            except OSError:
                continue
            raise RuntimeError("LEAKED %%s" %% place)
        """ % {"sphere": str(klass / "ann" / SPHERE), "results": str(world_readable / "out" / "ann" / "results.json")}
    _submission(klass / "bob", attack)
    for folder in [klass] + [p for p in klass.rglob("*")]:
        os.chmod(folder, 0o755 if folder.is_dir() else 0o644)
    modes = {p: stat.S_IMODE(os.stat(p).st_mode) for p in [klass, klass / "ann", klass / "bob"]}
    want = _scores(_graded(mode, _submission(tmp_path / "honest-all"), None, only=None))
    path = grade_all("a03", klass, world_readable / "out", processes=2, time_limit=TIME_LIMIT)
    rows = {row.split(",")[0]: row for row in path.read_text().splitlines()[1:]}
    bob = json.loads((world_readable / "out" / "bob" / "results.json").read_text())
    assert {t["number"]: t["score"] for t in bob["tests"]} == want
    assert all("LEAKED" not in t.get("output", "") for t in bob["tests"]), bob
    assert rows["ann"].split(",")[1] == "17"
    assert {p: stat.S_IMODE(os.stat(p).st_mode) for p in modes} == modes   # put back as they were
    if mode != "bwrap":
        assert not stat.S_IMODE(os.stat(world_readable / "out").st_mode) & 0o077


# --- what a test leaves in the shared temporary folders -------------------------------------

def test_folders_planted_where_locks_once_lay_stop_no_later_grading(mode, tmp_path):
    # A sandbox user could once fill every lock name of the world-writable temporary folder
    # with folders of its own, and no later grading on the machine found a free sandbox user.
    names = ["rtfgu-sandbox-uid-%d.lock" % (sandbox.SANDBOX_UID + k) for k in range(sandbox.UID_SLOTS)]
    names += ["rtfgu-hidden-0.json", "rtfgu-runtime-0-planted"]
    attack = """
        import os, tempfile
        for folder in {tempfile.gettempdir(), "/tmp", "/var/tmp", "/dev/shm"}:
            for name in %(names)r:
                try:
                    os.mkdir(os.path.join(folder, name))
                except OSError:
                    pass
        for place in ("/run/rtfgu/state/uids.lock", "/run/rtfgu/state/hidden.json", "/run/rtfgu/runtime/planted"):
            try:
                open(place, "w").write("planted")
                raise RuntimeError("LEAKED %%s is writable" %% place)
            except OSError:
                pass
        """ % {"names": names}
    want = honest(mode, tmp_path)
    result = _graded(mode, _submission(tmp_path / "sub", attack), tmp_path / "out")
    assert _scores(result) == want
    planted = [os.path.join(d, n) for d in ("/tmp", "/var/tmp", "/dev/shm", tempfile.gettempdir()) for n in names
               if os.path.lexists(os.path.join(d, n)) and os.lstat(os.path.join(d, n)).st_uid != os.geteuid()]
    assert planted == []
    # A grading in a new process (a new claim of a sandbox user) still runs.
    script = ("from rtfgu.grading.grader import grade\n"
              "import sys\n"
              "r = grade('a03', sys.argv[1], None, only=sys.argv[2].split(','), time_limit=%r)\n"
              "print(r.isolation, ';'.join('%%s=%%s' %% (t.number, t.score) for t in r.tests))\n" % TIME_LIMIT)
    done = subprocess.run([sys.executable, "-c", script, str(_submission(tmp_path / "later")), ",".join(ONLY)],
                          capture_output=True, text=True, timeout=300, cwd=str(ROOT))
    assert done.returncode == 0, done.stderr[-3000:]
    isolation, scores = done.stdout.strip().splitlines()[-1].rsplit(" ", 1)
    assert isolation == _isolation(mode)
    assert {k: float(v) for k, v in (s.split("=") for s in scores.split(";"))} == want


def test_what_a_test_leaves_in_the_shared_folders_is_gone_before_the_next_student(mode, tmp_path):
    # A file in /tmp or /dev/shm, or a System V segment, outlived its test; the next student
    # graded by the same worker runs as the same sandbox user and could read it.
    attack = """
        import ctypes, os
        for folder in ("/tmp", "/var/tmp", "/dev/shm"):
            try:
                with open(os.path.join(folder, "rtfgu-left-behind-%%d" %% os.getpid()), "w") as f:
                    f.write(open(__file__).read())
                os.makedirs(os.path.join(folder, "rtfgu-left-folder-%%d" %% os.getpid(), "inner"))
            except OSError:
                pass
        ctypes.CDLL(None).shmget(0x5eed0000 + os.getpid() %% 4096, 4096, 0o1666)
        """
    want = honest(mode, tmp_path)
    result = _graded(mode, _submission(tmp_path / "sub", attack), tmp_path / "out")
    assert _scores(result) == want
    if os.geteuid() == 0:
        uid = sandbox.sandbox_uid()
        with open("/proc/sysvipc/shm") as f:
            owners = [int(row.split()[7]) for row in f.read().splitlines()[1:]]
        assert uid not in owners


# keyctl(2) and add_key(2) by machine (the C library wraps neither).
KEY_CALLS = {"x86_64": (250, 248), "aarch64": (219, 217)}


def test_a_message_queue_or_a_key_a_test_leaves_is_not_found_by_the_next_student(mode, tmp_path):
    # A POSIX message queue and the kernel's keyrings belong to a user, not to a folder: the
    # next student graded by the same worker runs as the same sandbox user, and could read
    # what the test before left there (without namespaces /dev/mqueue need not be mounted for
    # the grader to see a queue; a user's keyring lives as long as the user).
    import platform
    if platform.machine() not in KEY_CALLS:
        pytest.skip("keyctl's system call number is not known for %s" % platform.machine())
    keyctl, add_key = KEY_CALLS[platform.machine()]
    leave = """
        import ctypes, os
        libc = ctypes.CDLL(None, use_errno=True)
        libc.syscall.restype = ctypes.c_long
        q = libc.mq_open(b"/rtfgu-left-queue", os.O_CREAT | os.O_RDWR, 0o600, None)
        if q >= 0:
            libc.mq_send(q, b"left by the student before", 26, 0)
        for keyring in (-4, -5):      # the user's keyring and its session keyring
            libc.syscall(%(add_key)d, b"user", b"rtfgu-left-key", b"left", 4, ctypes.c_long(keyring))
        """ % {"add_key": add_key}
    look = """
        import ctypes, os
        libc = ctypes.CDLL(None, use_errno=True)
        libc.syscall.restype = ctypes.c_long
        if libc.mq_open(b"/rtfgu-left-queue", os.O_RDONLY, 0, None) >= 0:
            raise RuntimeError("LEAKED: the message queue of the student before")
        for keyring in (-4, -5):      # KEYCTL_SEARCH
            if libc.syscall(%(keyctl)d, 10, ctypes.c_long(keyring), b"user", b"rtfgu-left-key", 0) >= 0:
                raise RuntimeError("LEAKED: a key of the student before")
        try:
            listed = open("/proc/keys").read()
        except OSError:
            listed = ""
        if "rtfgu-left-key" in listed:
            raise RuntimeError("LEAKED: a key of the student before, in /proc/keys")
        """ % {"keyctl": keyctl}
    want = honest(mode, tmp_path)
    first = _graded(mode, _submission(tmp_path / "first", leave), tmp_path / "out-first")
    assert _scores(first) == want
    second = _graded(mode, _submission(tmp_path / "second", look), tmp_path / "out-second")
    for test in second.tests:
        assert "LEAKED" not in test.output, test.output
    assert _scores(second) == want


# --- the solved copies the staff commands write -----------------------------------------------

def test_the_solved_copies_the_staff_commands_write_are_closed_to_student_code(mode, tmp_path, world_readable):
    solved, bundle = world_readable / "solved", world_readable / "dist" / "autograder.zip"
    for command in (["solution", "a03", str(solved)], ["autograder-zip", "a03", "--out", str(bundle)]):
        done = subprocess.run([sys.executable, "-m", "rtfgu.grading"] + command, capture_output=True, text=True,
                              cwd=str(ROOT))
        assert done.returncode == 0, done.stderr
    written = [solved] + list(solved.rglob("*"))
    assert all(stat.S_IMODE(os.stat(p).st_mode) == (0o700 if p.is_dir() else 0o600) for p in written)
    assert stat.S_IMODE(os.stat(bundle).st_mode) == 0o600
    attack = """
        import zipfile
        try:
            source = open(%(sphere)r).read()
        except OSError:
            source = None
        if source is None:
            try:
                source = zipfile.ZipFile(%(bundle)r).read("rtfgu/shapes/sphere.py").decode()
            except (OSError, KeyError):
                source = None
        if source is not None:
            namespace = {"__name__": "rtfgu.shapes.solved", "__package__": "rtfgu.shapes"}
            exec(compile(source, "solved", "exec"), namespace)
            return namespace["Sphere"].intersect_p(self, ray)
        """ % {"sphere": str(solved / SPHERE), "bundle": str(bundle)}
    want = honest(mode, tmp_path)
    result = _graded(mode, _submission(tmp_path / "sub", attack), tmp_path / "out")
    assert _scores(result) == want


# --- the limits every test runs under ---------------------------------------------------------

def test_threads_processes_and_cpu_are_bounded_per_test(mode, tmp_path):
    attack = """
        import os, resource
        threads = [os.environ.get(k) for k in ("NUMBA_NUM_THREADS", "OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS",
                                               "MKL_NUM_THREADS")]
        cpu, nproc = resource.getrlimit(resource.RLIMIT_CPU)[1], resource.getrlimit(resource.RLIMIT_NPROC)[1]
        raise RuntimeError("LIMITS %s %d %d END" % (",".join(str(t) for t in threads), cpu, nproc))
        """
    result = _graded(mode, _submission(tmp_path / "sub", attack), tmp_path / "out", only=ONLY[1:2])
    threads, cpu, nproc = result.tests[0].output.split("LIMITS ")[1].split(" END")[0].split()
    assert threads == "1,1,1,1"
    assert 0 < int(cpu) <= TIME_LIMIT + 3
    if mode != "bwrap" or sandbox.bwrap_as_user(sandbox.find_bwrap()):
        assert 0 < int(nproc) <= sandbox.NPROC
