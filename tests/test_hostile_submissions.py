"""Hostile submissions: each puts a dishonest part into a student file beside an honest part
(a03: solved plane and triangle, and a sphere whose intersect_p attacks and then gives up
as the stub does). Each must score exactly what its honest part scores alone, test by test,
leak nothing into the test messages, and change nothing outside its scratch folder: the
checkout stays as it was, a canary outside stays untouched, no process survives, no
connection is made.

An attack that gets what it is after says so: it returns the right answer (the score rises)
or raises ``LEAKED ...`` (the message shows it). Every attack runs under bubblewrap (skipped,
naming the Debian package, where it cannot run) and the important ones also under the
fallback this machine allows as root (an unprivileged user), with the namespaces root may
make here and without them (RTFGU_FALLBACK_NAMESPACES=0), as a container that forbids them
runs it. tests/test_grader_fallback.py holds the attacks on the grader itself.
"""
from __future__ import annotations

import csv
import json
import os
import re
import socket
import stat
import subprocess
import sys
import tempfile
import textwrap
import threading
import time
import zipfile
from pathlib import Path

import pytest

from rtfgu.grading.archive import unpack_submission
from rtfgu.grading.assignments import get_assignment
from rtfgu.grading.checks import checks_for
from rtfgu.grading.generate import PACKAGE_DIR, solution_files, student_files, write_files
from rtfgu.grading.grader import REFERENCE_DIR, grade
from rtfgu.grading.release import solves
from rtfgu.grading.sandbox import RESULT_LIMIT, bwrap_works, find_bwrap, prepare

ROOT = Path(__file__).resolve().parent.parent
SPHERE = "shapes/sphere.py"
STUB_LINE = "        raise NotImplementedError('a03: Sphere.intersect_p')\n"
STAFF_SPHERE = PACKAGE_DIR / SPHERE
OBSERVATIONS = REFERENCE_DIR / "a03_intersections" / "observations.json"
# A plane test, two sphere tests (one hidden) and the triangle test: enough to see that the
# attack costs nothing beyond its own file and that the rest still scores.
ONLY = ("01_plane_intersect_p_hits_misses_and_the_ray_interv", "02_sphere_intersect_p_rays_that_hit",
        "05_triangle_intersect_p_inside_outside_and_the_ray_",
        "10_sphere_intersect_p_with_directions_that_are_not_")
FALLBACK = "user"
BARE = "user without namespaces"       # the fallback as a container that forbids namespaces runs it


def _skip_without(isolation: str) -> None:
    if isolation == "bwrap":
        if not bwrap_works(find_bwrap()):
            pytest.skip("bubblewrap is not installed or cannot run here (Debian package bubblewrap; "
                        "`make venv` fetches it)")
    elif isolation in (FALLBACK, BARE) and os.geteuid() != 0:
        pytest.skip("the unprivileged-user fallback needs the grader to run as root")


@pytest.fixture(params=["bwrap", FALLBACK, BARE])
def isolation(request, monkeypatch):
    _skip_without(request.param)
    monkeypatch.setenv("RTFGU_ISOLATION", "user" if request.param == BARE else request.param)
    monkeypatch.setenv("RTFGU_FALLBACK_NAMESPACES", "0" if request.param == BARE else "1")
    return request.param


@pytest.fixture
def bwrap(monkeypatch):
    _skip_without("bwrap")
    monkeypatch.setenv("RTFGU_ISOLATION", "bwrap")
    return "bwrap"


def _sphere_with(attack: str) -> str:
    """The stub sphere.py with ``attack`` run at the start of intersect_p."""
    stub = student_files("a03")[SPHERE]
    assert STUB_LINE in stub
    return stub.replace(STUB_LINE, textwrap.indent(textwrap.dedent(attack).strip("\n"), " " * 8) + "\n" + STUB_LINE)


def _submission(folder: Path, attack: str = "") -> Path:
    """Solved plane and triangle (the honest part); the sphere carries the attack."""
    files = dict(solution_files("a03"))
    files[SPHERE] = _sphere_with(attack) if attack else student_files("a03")[SPHERE]
    write_files(files, folder)
    return folder


_HONEST = {}


def honest_scores(isolation: str) -> dict:
    """What the honest part alone scores, test by test, under ``isolation``."""
    if isolation not in _HONEST:
        with tempfile.TemporaryDirectory() as tmp:
            result = grade("a03", _submission(Path(tmp) / "sub"), None, only=ONLY)
        scores = _scores(result)
        assert set(scores) == {"3.1", "3.2", "3.5", "3.10"}
        assert scores["3.1"] > 0 and scores["3.5"] > 0 and scores["3.2"] == scores["3.10"] == 0
        _HONEST[isolation] = scores
    return _HONEST[isolation]


def _scores(result) -> dict:
    return {t.number: t.score for t in result.tests}


def _git_status() -> str:
    return subprocess.run(["git", "status", "--porcelain"], cwd=ROOT, capture_output=True, text=True).stdout


def _staff_digest() -> dict:
    """Files a submission would like to change: the references and the solution. (Whether the
    grader's own source is writable is asked by the attack itself, which says LEAKED if so:
    that source may be edited by people while the tests run.)"""
    paths = [STAFF_SPHERE]
    paths += sorted(OBSERVATIONS.parent.iterdir())
    return {p: p.read_bytes() for p in paths}


def _grade_attack(tmp_path: Path, isolation: str, attack: str, only=ONLY, time_limit=None):
    before, staff = _git_status(), _staff_digest()
    result = grade("a03", _submission(tmp_path / "sub", attack), tmp_path / "out", only=only,
                   time_limit=time_limit)
    assert result.isolation == {"bwrap": "bwrap", FALLBACK: "unprivileged user", BARE: "unprivileged user"}[isolation]
    assert _staff_digest() == staff
    assert _git_status() == before
    for test in result.tests:
        assert "LEAKED" not in test.output, test.output
    return result


# A fragment of the reference file as it is stored (indented JSON): it is in the grader's
# memory, never in a child's (whose answers are compact JSON).
NEEDLE = OBSERVATIONS.read_bytes()[40:120]

ATTACKS = {
    "delegates to the robust twin": """
        import rtfgu.robust as r
        return r.intersect_sphere_robust(ray, self.center, self.radius)
        """,
    "delegates to the numba kernels": """
        from rtfgu.kernels import intersect
        raise RuntimeError("LEAKED the numba kernels are importable: %r" % intersect)
        """,
    "delegates to the WGSL twin": """
        import os, rtfgu.wgsl
        folder = os.path.dirname(rtfgu.wgsl.__file__)
        for name in ("intersect_sphere.wgsl", "intersect_plane.wgsl", "intersect_triangle.wgsl"):
            if "TODO_a06" not in open(os.path.join(folder, name)).read():
                raise RuntimeError("LEAKED the solved WGSL twin %s" % name)
        """,
    "execs the solved source found on sys.path or in the editable install": """
        import glob, os, re, sys
        places = [os.path.join(p, "rtfgu", "shapes", "sphere.py") for p in sys.path] + [%(staff)r]
        for finder in [f for p in sys.path for f in glob.glob(os.path.join(p, "__editable__*"))]:
            try:
                places += [os.path.join(m, "shapes", "sphere.py") for m in re.findall(r"'(/[^']*rtfgu)'", open(finder).read())]
            except OSError:
                pass
        for place in places:
            try:
                source = open(place).read()
            except OSError:
                continue
            if "raise NotImplementedError('a03: Sphere.intersect_p')" not in source:
                namespace = {"__name__": "rtfgu.shapes.solved", "__package__": "rtfgu.shapes"}
                exec(compile(source, place, "exec"), namespace)
                return namespace["Sphere"].intersect_p(self, ray)
        """ % {"staff": str(STAFF_SPHERE)},
    "reads the references and the reference images": """
        import glob, os
        places = [%(obs)r] + glob.glob(%(folder)r + "/*.png")
        for root in (%(checkout)r, "/autograder/source"):
            places += glob.glob(root + "/rtfgu/grading/reference/*/observations.json")
        for place in places:
            try:
                raise RuntimeError("LEAKED %%s: %%r" %% (place, open(place, "rb").read(40)))
            except OSError:
                pass
        """ % {"obs": str(OBSERVATIONS), "folder": str(OBSERVATIONS.parent), "checkout": str(ROOT)},
    "reads the grader's memory, environment and inherited descriptors": """
        import gc, os, sys
        needle = %(needle)r
        if any(m.startswith("rtfgu.grading") for m in sys.modules) or any(
                type(o).__module__.startswith("rtfgu.grading") for o in gc.get_objects()):
            raise RuntimeError("LEAKED the grader's objects are in this interpreter")
        for fd in range(3, 256):
            try:
                data = os.pread(fd, 1 << 20, 0)
            except OSError:
                continue
            if needle in data:
                raise RuntimeError("LEAKED fd %%d holds the references" %% fd)
        for pid in {os.getppid(), 1, *[int(p) for p in os.listdir("/proc") if p.isdigit()]} - {os.getpid()}:
            for name in ("environ", "cmdline"):
                try:
                    if b"observations" in open("/proc/%%d/%%s" %% (pid, name), "rb").read():
                        raise RuntimeError("LEAKED /proc/%%d/%%s" %% (pid, name))
                except OSError:
                    pass
            try:
                maps = open("/proc/%%d/maps" %% pid).read().splitlines()
                with open("/proc/%%d/mem" %% pid, "rb", buffering=0) as mem:
                    for line in maps:
                        span, perms = line.split()[:2]
                        start, end = (int(x, 16) for x in span.split("-"))
                        if perms.startswith("rw") and end - start < (256 << 20):
                            mem.seek(start)
                            if needle in mem.read(end - start):
                                raise RuntimeError("LEAKED the references in /proc/%%d/mem" %% pid)
            except (OSError, ValueError, OverflowError):
                pass
        """ % {"needle": NEEDLE},
    "writes a fake answer into the pipe early, then crashes": """
        import os, sys
        fd = int(sys.argv[4])
        os.write(fd, b'{"cases": [{"out": {"returned": true, "ray.tmax": 1.0}}]}')
        os._exit(1)
        """,
    "writes extra JSON after the answer": """
        import atexit, os, sys
        fd = int(sys.argv[4])
        os.write(fd, b'{"cases": []}')
        """,
    "edits and deletes files outside scratch": """
        import os
        for place in (%(grader)r, %(obs)r, %(staff)r):
            try:
                os.close(os.open(place, os.O_WRONLY | os.O_APPEND))
                raise RuntimeError("LEAKED %%s is writable" %% place)
            except OSError:
                pass
            try:
                os.rename(place, place + ".moved")
                raise RuntimeError("LEAKED %%s could be moved" %% place)
            except OSError:
                pass
        """ % {"grader": str(PACKAGE_DIR / "grading" / "grader.py"), "obs": str(OBSERVATIONS),
               "staff": str(STAFF_SPHERE)},
}


@pytest.mark.parametrize("name", list(ATTACKS))
def test_an_attack_scores_what_its_honest_part_scores_and_changes_nothing(isolation, tmp_path, name):
    honest = honest_scores(isolation)
    result = _grade_attack(tmp_path, isolation, ATTACKS[name])
    assert _scores(result) == honest, name


def test_the_package_student_code_runs_in_has_no_twin_no_solution_and_no_grader(tmp_path):
    ws = prepare(get_assignment("a03"), _submission(tmp_path / "sub"), tmp_path / "work")
    package = ws.package / "rtfgu"
    for absent in ("robust.py", "kernels", "hardcases", "grading"):
        assert not (package / absent).exists(), absent
    solved = solution_files("a03")[SPHERE]
    body = solved[solved.index("def intersect_p"):solved.index("def normal_at")]
    stubbed = (package / SPHERE).read_text()
    assert body not in stubbed and STUB_LINE in stubbed
    for path in package.rglob("*"):          # a file that solves a03 or later is left out
        if path.is_file() and path.suffix in (".py", ".wgsl"):
            assert max(solves(path.read_text()), default=0) < 3, path
    assert not any(p.name == "observations.json" for p in ws.root.rglob("*"))


def test_the_solved_source_and_the_references_are_not_visible_in_the_sandbox(bwrap, tmp_path):
    # A walk over everything the child can see (minus /proc, /sys, /dev) finds no solved
    # sphere, no reference file, no twin and nothing of the checkout. The walk gets a time
    # limit far above what it needs (a few seconds), so a loaded machine cannot cut it short.
    attack = """
        import os, time
        end = time.monotonic() + 45
        for root, dirs, files in os.walk("/"):
            dirs[:] = [d for d in dirs if os.path.join(root, d) not in ("/proc", "/sys", "/dev")]
            if time.monotonic() > end:
                raise RuntimeError("the walk did not finish")
            for name in files:
                path = os.path.join(root, name)
                if root.startswith(%(checkout)r) or root.endswith(("/rtfgu/kernels", "/rtfgu/grading")) or \\
                        name in ("observations.json", "known.json") and "reference" in root:
                    raise RuntimeError("LEAKED %%s" %% path)
                if name in ("sphere.py", "robust.py"):
                    try:
                        text = open(path).read()
                    except OSError:
                        continue
                    if "def intersect_sphere" + "_robust" in text or "def intersect_p" in text and \\
                            "NotImplementedError('a03: Sphere.intersect_p')" not in text:
                        raise RuntimeError("LEAKED the solved sphere at %%s" %% path)
        raise RuntimeError("walked everything")
        """ % {"checkout": str(ROOT / "rtfgu")}
    result = _grade_attack(tmp_path, "bwrap", attack, only=ONLY[1:2], time_limit=60)
    assert "walked everything" in result.tests[0].output
    assert result.tests[0].score == 0


def test_no_process_outlives_its_test_and_nothing_outside_scratch_is_written(isolation, tmp_path):
    honest = honest_scores(isolation)
    token = "rtfgu-survivor-%d-%s" % (os.getpid(), isolation)
    markers = Path(tempfile.mkdtemp(prefix="rtfgu-markers-"))
    os.chmod(markers, 0o1777)                # any user may add a file here, as in /tmp
    canary = markers / "canary.txt"
    canary.write_text("untouched")
    attack = """
        import os, subprocess, sys
        later = "import os, sys, time; time.sleep(3); open(os.path.join(%(markers)r, str(os.getpid())), 'w').write(sys.argv[1])"
        subprocess.Popen([sys.executable, "-c", later, %(token)r], start_new_session=True,
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        if os.fork() == 0:
            os.setsid()
            if os.fork() == 0:
                os.execv(sys.executable, [sys.executable, "-c", later, %(token)r])
            os._exit(0)
        for place in (%(canary)r, %(results)r):
            try:
                open(place, "w").write("changed")
            except OSError:
                pass
        """ % {"markers": str(markers), "token": token, "canary": str(canary),
               "results": str(tmp_path / "out" / "results.json")}
    try:
        result = _grade_attack(tmp_path, isolation, attack)
        results_json = (tmp_path / "out" / "results.json").read_text()
        time.sleep(4)
        assert _scores(result) == honest
        assert canary.read_text() == "untouched"
        assert sorted(p.name for p in markers.iterdir()) == ["canary.txt"]
        assert (tmp_path / "out" / "results.json").read_text() == results_json
        alive = subprocess.run(["pgrep", "-f", token], capture_output=True, text=True).stdout.strip()
        assert alive == "", "a process of the submission survived: %s" % alive
    finally:
        for pid in subprocess.run(["pgrep", "-f", token], capture_output=True, text=True).stdout.split():
            os.kill(int(pid), 9)
        for p in markers.iterdir():
            p.unlink()
        markers.rmdir()


def test_no_connection_leaves_the_sandbox(isolation, tmp_path):
    honest = honest_scores(isolation)
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(5)
    server.settimeout(0.2)
    port = server.getsockname()[1]
    accepted, stop = [], threading.Event()

    def accept():
        while not stop.is_set():
            try:
                accepted.append(server.accept())
            except OSError:
                pass

    thread = threading.Thread(target=accept)
    thread.start()
    attack = """
        import socket
        for host in ("127.0.0.1", "localhost", "10.0.2.2", "1.1.1.1"):
            s = socket.socket()
            s.settimeout(1)
            try:
                s.connect((host, %d))
                s.send(b"answers?")
                raise RuntimeError("LEAKED connected to %%s" %% host)
            except OSError:
                pass
        """ % port
    try:
        result = _grade_attack(tmp_path, isolation, attack)
        time.sleep(0.5)
    finally:
        stop.set()
        thread.join()
        server.close()
    assert accepted == []
    assert _scores(result) == honest


def test_a_gigabyte_of_output_costs_that_test_only_and_the_grader_output_stays_small(isolation, tmp_path, capfd):
    honest = honest_scores(isolation)
    attack = """
        import os, sys
        block = "y" * (64 << 20)
        for place in ["/proc/%d/fd/1" % os.getppid(), "/proc/%d/fd/2" % os.getppid(), "/proc/1/fd/1"]:
            try:
                with open(place, "w") as f:
                    for _ in range(16):
                        f.write(block)
            except OSError:
                pass
        for _ in range(16):
            try:
                sys.stdout.write(block)
                sys.stdout.flush()
            except OSError:
                pass
        raise RuntimeError("z" * (16 << 20))
        """
    result = _grade_attack(tmp_path, isolation, attack)
    assert _scores(result) == honest
    out, err = capfd.readouterr()
    assert len(out) + len(err) < 100_000
    assert all(len(t.output) < 20_000 for t in result.tests)
    assert (tmp_path / "out" / "results.json").stat().st_size < 200_000


def _zip(path: Path, entries) -> Path:
    """entries: (name, text) or (name, ("link", target)) for a symbolic link entry."""
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in entries:
            if isinstance(data, tuple):
                info = zipfile.ZipInfo(name)
                info.external_attr = (stat.S_IFLNK | 0o777) << 16
                z.writestr(info, data[1])
            else:
                z.writestr(name, data)
    return path


def test_escaping_and_link_entries_of_a_zip_are_not_unpacked(tmp_path):
    files = dict(solution_files("a03"))
    outside = tmp_path / "a" / "outside.txt"
    absolute = tmp_path / "absolute.txt"
    archive = _zip(tmp_path / "sub.zip", [("shapes/plane.py", files["shapes/plane.py"]),
                                          ("../outside.txt", "x"), ("shapes/../../../outside.txt", "x"),
                                          (str(absolute), "x"),
                                          ("shapes/sphere.py", ("link", str(STAFF_SPHERE))),
                                          ("shapes/triangle.py", files["shapes/triangle.py"])])
    notes = []
    out = unpack_submission(archive, tmp_path / "a" / "b", notes)
    found = sorted(p.relative_to(out).as_posix() for p in out.rglob("*") if p.is_file())
    assert found == ["shapes/plane.py", "shapes/triangle.py"]
    assert not outside.exists() and not absolute.exists()
    assert sum("outside the submission folder" in n for n in notes) == 3
    assert any("shapes/sphere.py is a link" in n for n in notes)


def test_links_in_a_submitted_folder_are_not_followed(bwrap, tmp_path):
    honest = honest_scores("bwrap")
    folder = _submission(tmp_path / "sub")
    (folder / "shapes" / "sphere.py").unlink()
    (folder / "shapes" / "sphere.py").symlink_to(STAFF_SPHERE)        # the solved file, by a link
    (folder / "solved").symlink_to(STAFF_SPHERE.parent, target_is_directory=True)
    result = grade("a03", folder, tmp_path / "out", only=ONLY)
    assert _scores(result) == honest
    assert any("sphere.py is a link" in n for n in result.notes)


def test_a_zip_bomb_costs_no_memory_and_the_rest_is_graded(bwrap, tmp_path):
    honest = honest_scores("bwrap")
    files = dict(solution_files("a03"))
    files[SPHERE] = student_files("a03")[SPHERE]
    archive = _zip(tmp_path / "sub.zip", [(name, text) for name, text in files.items()])
    with zipfile.ZipFile(archive, "a", zipfile.ZIP_DEFLATED) as z, \
            z.open("bomb.bin", "w", force_zip64=True) as f:
        chunk = bytes(1 << 20)
        for _ in range(2048):  # 2 GiB of zeros, about 2 MB compressed
            f.write(chunk)
    assert archive.stat().st_size < 4 << 20
    with zipfile.ZipFile(archive) as z:
        assert z.getinfo("bomb.bin").file_size == 2 << 30
    # The peak resident memory of this process's own address space (VmHWM): getrusage's
    # ru_maxrss would also count the pytest worker it was spawned from (Linux keeps the
    # larger of the old and the new image's peak across execve).
    script = textwrap.dedent("""
        import sys
        from rtfgu.grading.grader import grade
        r = grade("a03", sys.argv[1], sys.argv[2], only=sys.argv[3].split(","))
        with open("/proc/self/status") as status:
            print(next(line.split()[1] for line in status if line.startswith("VmHWM:")))
        print(";".join("%s=%s" % (t.number, t.score) for t in r.tests))
        print("|".join(r.notes))
        """)
    done = subprocess.run([sys.executable, "-c", script, str(archive), str(tmp_path / "out"), ",".join(ONLY)],
                          capture_output=True, text=True, timeout=600, cwd=tmp_path,
                          env=dict(os.environ, RTFGU_ISOLATION="bwrap"))
    assert done.returncode == 0, done.stderr
    peak_kb, scores, notes = done.stdout.strip().split("\n")[-3:]
    # Unpacked naively the bomb alone would take 2 GiB; the grader process (interpreter,
    # numpy, Pillow) stays far below that whatever the archive declares.
    assert int(peak_kb) < 1536 * 1024, "the grader used %s kB" % peak_kb
    assert {k: float(v) for k, v in (item.split("=") for item in scores.split(";"))} == honest
    assert "unpacks to more than 32 MB (at bomb.bin)" in notes


@pytest.mark.parametrize("isolation_name", ["bwrap", FALLBACK])
def test_a_syntax_error_costs_only_the_tests_that_need_that_file(isolation_name, tmp_path, monkeypatch):
    _skip_without(isolation_name)
    monkeypatch.setenv("RTFGU_ISOLATION", isolation_name)
    files = dict(solution_files("a03"))
    files["shapes/triangle.py"] = files["shapes/triangle.py"].replace("        denom = dot(", "        denom = = dot(", 1)
    assert "= = dot(" in files["shapes/triangle.py"]
    write_files(files, tmp_path / "sub")
    result = grade("a03", tmp_path / "sub", tmp_path / "out")
    by_number = {t.number: t for t in result.tests}
    assert by_number["3.5"].score == 0
    assert "SyntaxError in shapes/triangle.py, line" in by_number["3.5"].output
    for number in ("3.1", "3.2", "3.3", "3.4", "3.10"):
        assert by_number[number].score == by_number[number].max_score, by_number[number].output
    line = int(by_number["3.5"].output.split("line ")[1].split(":")[0])
    assert "= = dot(" in files["shapes/triangle.py"].split("\n")[line - 1]


def test_an_a01_file_that_execs_the_solution_at_import_scores_what_its_honest_part_scores(isolation, tmp_path):
    # float3.py solved (honest); ray.py is the stub with an attack at import time.
    attack = textwrap.dedent("""
        import os as _os
        for _place in (%r, _os.path.join(_os.path.dirname(__file__), "..", "..", "..", "rtfgu", "ray.py")):
            try:
                exec(compile(open(_place).read(), _place, "exec"))
                raise RuntimeError("LEAKED the solved ray.py at %%s" %% _place)
            except OSError:
                pass
        """ % str(PACKAGE_DIR / "ray.py"))
    honest_files = dict(solution_files("a01"))
    honest_files["ray.py"] = student_files("a01")["ray.py"]
    write_files(honest_files, tmp_path / "honest")
    honest = _scores(grade("a01", tmp_path / "honest", None))
    hostile_files = dict(honest_files)
    hostile_files["ray.py"] = honest_files["ray.py"].replace("\nclass Ray:", attack + "\n\nclass Ray:", 1)
    assert attack in hostile_files["ray.py"]
    write_files(hostile_files, tmp_path / "hostile")
    before, staff = _git_status(), _staff_digest()
    result = grade("a01", tmp_path / "hostile", tmp_path / "out")
    assert _scores(result) == honest and 0 < sum(honest.values())
    assert all("LEAKED" not in t.output for t in result.tests)
    assert _git_status() == before and _staff_digest() == staff


def test_the_wgsl_assignment_runs_on_the_software_adapter_inside_bwrap(bwrap, tmp_path):
    probe = subprocess.run([sys.executable, "-c", "from rtfgu.wgsl.device import adapter_description as a; print(a())"],
                           capture_output=True, text=True, cwd=ROOT)
    if probe.returncode != 0:
        pytest.skip("no WebGPU adapter (wgpu, Mesa llvmpipe: Debian packages libgl1-mesa-dri libegl1 "
                    "mesa-vulkan-drivers): " + probe.stderr.strip().splitlines()[-1])
    files = dict(solution_files("a06"))
    stubs = student_files("a06")
    files["wgsl/intersect_sphere.wgsl"] = stubs["wgsl/intersect_sphere.wgsl"]
    write_files(files, tmp_path / "sub")
    result = grade("a06", tmp_path / "sub", tmp_path / "out", time_limit=60)
    assert result.isolation == "bwrap"
    assert 0 < result.score < result.max_score
    assert not any("adapter" in t.output.lower() and t.score == 0 and "sphere" not in t.name.lower()
                   for t in result.tests), [t.output for t in result.tests]


def test_require_sandbox_refuses_to_grade_without_bwrap(tmp_path, monkeypatch):
    from rtfgu.grading import sandbox

    monkeypatch.setattr(sandbox, "find_bwrap", lambda: None)
    monkeypatch.delenv("RTFGU_ISOLATION", raising=False)
    with pytest.raises(ValueError, match="require-sandbox.*bubblewrap"):
        grade("a03", _submission(tmp_path / "sub"), tmp_path / "out", require_sandbox=True)
    assert not (tmp_path / "out").exists()  # refused before anything ran
    run = subprocess.run([sys.executable, "-m", "rtfgu.grading", "grade", "a03", str(tmp_path / "sub"),
                          "--out", str(tmp_path / "out"), "--require-sandbox"],
                         capture_output=True, text=True, cwd=ROOT,
                         env=dict(os.environ, RTFGU_BWRAP="none", RTFGU_ISOLATION=""))
    assert run.returncode == 2 and "Debian package bubblewrap" in run.stderr, run.stderr
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("variant", [0, 1])
def test_the_child_has_no_capability_to_remount_its_view_writable(bwrap, tmp_path, monkeypatch, variant):
    # bwrap started by root keeps every capability for the child unless told otherwise; with
    # CAP_SYS_ADMIN the child could remount a read-only bind read-write and write through it.
    # Both namespace variants (a user namespace of its own, and none where that is forbidden)
    # must leave it none.
    from rtfgu.grading import sandbox

    monkeypatch.setattr(sandbox, "BWRAP_NAMESPACES", sandbox.BWRAP_NAMESPACES[variant:variant + 1])
    monkeypatch.setattr(sandbox, "_BWRAP_WORKS", {})
    site = next(p for p in sandbox._site_dirs() if os.path.isdir(p))
    marker = Path(site) / ("rtfgu-remounted-%d.txt" % os.getpid())
    attack = """
        import subprocess
        caps = [l for l in open("/proc/self/status") if l.startswith("CapEff:")][0].split()[1]
        for place in (%(site)r, "/usr", "/sandbox/package"):
            subprocess.run(["mount", "-o", "remount,rw,bind", place], capture_output=True)
        try:
            open(%(marker)r, "w").write("written through the sandbox")
        except OSError:
            pass
        if int(caps, 16):
            raise RuntimeError("LEAKED the child holds capabilities %%s" %% caps)
        """ % {"site": site, "marker": str(marker)}
    try:
        result = _grade_attack(tmp_path, "bwrap", attack, only=ONLY[1:2])
        assert "LEAKED" not in result.tests[0].output
        assert not marker.exists()
    finally:
        if marker.exists():
            marker.unlink()


def test_a_test_cannot_start_more_than_a_few_dozen_processes(isolation, tmp_path):
    # A fork bomb stops at the process limit: the test's processes belong to a sandbox user
    # outside their namespaces too (under bwrap not root, whom the kernel exempts from it).
    from rtfgu.grading.sandbox import NPROC, bwrap_as_user

    if isolation == "bwrap" and not bwrap_as_user(find_bwrap()):
        pytest.skip("bwrap cannot run as an unprivileged user here (not root, or no user namespaces for it)")
    attack = """
        import subprocess
        started = []
        for _ in range(%d):
            try:
                started.append(subprocess.Popen(["sleep", "30"]))
            except OSError:
                break
        raise RuntimeError("started %%d;" %% len(started))
        """ % (3 * NPROC)
    result = _grade_attack(tmp_path, isolation, attack, only=ONLY[1:2])
    message = result.tests[0].output
    started = int(message.split("started ")[1].split(";")[0])
    assert 0 < started < NPROC, message


def test_the_notes_about_a_zips_entries_stay_short_whatever_their_number_and_names(tmp_path, monkeypatch, capfd):
    # Entry names are the student's to choose (up to 64 KB each, control characters too); the
    # result quotes a few of them, shortened.
    monkeypatch.setenv("RTFGU_ISOLATION", "rlimits")
    archive = tmp_path / "sub.zip"
    with zipfile.ZipFile(archive, "w") as z:
        for name, text in solution_files("a03").items():
            z.writestr(name, text)
        for i in range(400):
            z.writestr(zipfile.ZipInfo("../" * 10 + "\x1b[2J%d" % i + "x" * 30000), "outside")
    result = grade("a03", archive, tmp_path / "out", only=ONLY[:1])
    assert result.score == result.max_score > 0
    assert len(result.notes) <= 25 and "more notes" in " ".join(result.notes)
    assert "\x1b" not in " ".join(result.notes)
    assert (tmp_path / "out" / "results.json").stat().st_size < 20_000
    assert len(result.summary()) < 20_000


@pytest.mark.parametrize("answer", ['{"cases": [1, 2, 3, 4]}', '{"error": ["not", "text"]}',
                                    '{"cases": [{"error": {"a": 1}}, {"error": null}, {}, {}]}',
                                    '{"image": [["x"]]}'])
def test_a_malformed_answer_written_into_the_pipe_costs_that_test_only(bwrap, tmp_path, answer):
    # Student code can reach the answer pipe and exit cleanly after writing to it; whatever
    # it wrote is judged as the test's answer and must not stop the grader.
    attack = """
        import os, sys
        os.write(int(sys.argv[4]), %r.encode())
        os._exit(0)
        """ % answer
    result = _grade_attack(tmp_path, "bwrap", attack)
    assert _scores(result) == honest_scores("bwrap")


UNWRITABLE = {
    # deeper than the JSON parser's stack: json.loads raises RecursionError, not ValueError
    "nested": """
        import os, sys
        os.write(int(sys.argv[4]), b"[" * 100000 + b"]" * 100000)
        os._exit(0)
        """,
    # a lone surrogate in the message, which UTF-8 cannot hold (summary.txt, the gradebook)
    "surrogate": """
        raise RuntimeError("\\ud800 in the message")
        """,
}
# an answer past the size the grader reads, in the form the probe writes
UNWRITABLE["oversized"] = """
    import os, sys
    body = b'{"cases": [' + b'0, ' * (%d // 3 + 1) + b'0]}'
    os.write(int(sys.argv[4]), body)
    os._exit(0)
    """ % RESULT_LIMIT


@pytest.mark.parametrize("attack", list(UNWRITABLE))
def test_an_answer_the_grader_cannot_parse_or_write_costs_that_test_only(isolation, tmp_path, attack):
    # An answer nested past the parser's stack, one past the size the grader reads, and a
    # message UTF-8 cannot hold: each once stopped the whole grading (no results.json, or
    # results.json and no summary.txt, and grade-all's gradebook gave the student 0).
    result = _grade_attack(tmp_path, isolation, UNWRITABLE[attack])
    assert _scores(result) == honest_scores(isolation)
    assert json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["score"] == result.score
    summary = (tmp_path / "out" / "summary.txt").read_text(encoding="utf-8")
    assert "total %g" % result.score in summary
    if attack == "surrogate":
        assert "? in the message" in summary


def _stubs_answering_score_nothing(tmp_path, aid: str, numbers, answers) -> None:
    """The stubs of assignment ``aid``, each (file, stub line, answer) of ``answers`` writing
    its answer into the pipe and exiting before its stub line: tests ``numbers`` (run alone)
    each score nothing, their answers not in the form the test writes."""
    files = dict(student_files(aid))
    for relpath, stub, answer in answers:
        indent = stub[:len(stub) - len(stub.lstrip())]
        attack = "".join(indent + line + "\n" for line in (
            "import json, os, sys", "os.write(int(sys.argv[4]), json.dumps(%r).encode())" % (answer,), "os._exit(0)"))
        assert files[relpath].count(stub) == 1
        files[relpath] = files[relpath].replace(stub, attack + stub)
    write_files(files, tmp_path / "sub")
    only = tuple(c.slug for c in checks_for(aid) if c.number in numbers)
    result = grade(aid[:3], tmp_path / "sub", None, only=only)
    assert [t.number for t in result.tests] == list(numbers)
    for test in result.tests:
        assert test.score == 0, (test.number, test.output)
        assert "not in the form the test writes" in test.output, test.output


def test_sets_or_a_histogram_in_place_of_what_the_test_asked_for_score_nothing(isolation, tmp_path):
    # The a10 judges took each answer's own word for its sets' sizes: an answer written into
    # the pipe by the stub (not by the probe) with sets of one point, which have every
    # structure, scored the tests of the sampler's structure, its shuffles and its seeds; and
    # millions of such sets took the judge minutes.
    # Likewise the disk's test took the probe's histogram, whose truth is flat.
    forged = {"sets": [{"num_samples": 1, "num_sets": 1, "points": [[0.5, 0.5]]}] * 4,
              "runs": [{"seed": 10, "points": [[0.5, 0.5]]}, {"seed": 10, "points": [[0.5, 0.5]]},
                       {"seed": 17, "points": [[0.25, 0.25]]}],
              "counts": [[128] * 8] * 8, "count": 8192, "n_bad": 0, "bad": [], "points": [[0.0, 0.0]] * 64}
    _stubs_answering_score_nothing(tmp_path, "a10_samplers", ("10.1", "10.2", "10.3", "10.5", "10.6"), [
        ("sampling/multi_jittered.py", "        raise NotImplementedError('a10: MultiJittered.generate_samples')\n",
         forged),
        ("sampling/maps.py", "    raise NotImplementedError('a10: concentric_map')\n", forged)])


def test_a_histogram_or_a_sum_in_place_of_the_samples_scores_nothing(isolation, tmp_path):
    # The a09 probes once sent the judge their samples binned or summed, and a stub that
    # wrote the known truths (flat counts, the integrals' values) into the pipe, or put a
    # probe of its own in the probe's place, scored the tests of the map and of sample_f. The
    # judge now bins and sums every sample itself, and takes as many as the test drew.
    flat = {"sets": [{"axis": [0.0, 0.0, 1.0], "e": 1.0, "counts": [[128] * 8] * 8, "bad": [], "n_bad": 0,
                      "directions": [[0.0, 0.0, 1.0]] * 64}]}
    truths = {"1": 1.0, "cos": 2.0 / 3.0, "cos^2": 0.5, "lateral": 2.0 / (3.0 * 3.141592653589793)}
    summed = {"sets": [{"normal": n, "rho": [r] * 3, "f": [r / 3.141592653589793] * 3, "count": 8192, "used": 8192,
                        "directions": flat["sets"][0], "bad_pdf": [], "n_bad_pdf": 0,
                        "sums": {g: [[8192 * t, 8192 * t * t]] * 3 for g, t in truths.items()},
                        "samples": [[r / 3.141592653589793] * 3 + [0.0, 0.0, 1.0, 1.0 / 3.141592653589793]] * 64}
                       for n, r in (([0.0, 0.0, 1.0], 0.5), ([0.0, 0.0, -1.0], 0.8))]}
    _stubs_answering_score_nothing(tmp_path, "a09_path_tracing", ("9.1", "9.3"), [
        ("sampling/maps.py", "    raise NotImplementedError('a09: hemisphere_map')\n", flat),
        ("brdfs/lambertian.py", "        raise NotImplementedError('a09: Lambertian.sample_f')\n", summed)])


def test_a_visible_test_cannot_read_the_hidden_tests_inputs(isolation, tmp_path):
    # The hidden tests' probe modules and the probes' table of every test's inputs were in
    # every test's sandbox: a visible test's code read them and showed them in its message
    # (a hidden test's inputs, to special-case them in the next submission). The table now
    # holds the visible tests only, and the hidden modules are readable to the sandbox user
    # while a hidden test runs (the grader runs as root here; as another user, student code
    # runs as that user and can read them).
    hidden = sorted(c.slug for c in checks_for("a03_intersections") if c.visibility != "visible")
    attack = """
        import glob, json, os, sys
        import rtfgu_probes
        folder = os.path.dirname(rtfgu_probes.__file__)
        table = json.load(open(os.path.join(folder, "tests.json")))
        if set(table["a03_intersections"]) & set(%r):
            raise RuntimeError("LEAKED: a hidden test's inputs in the probes' table")
        if "rtfgu_probes.a03_hidden" not in sys.modules:      # a visible test
            for path in glob.glob(os.path.join(folder, "*_hidden.py")) + glob.glob(
                    os.path.join(folder, "__pycache__", "*_hidden.*.pyc")):
                try:
                    open(path, "rb").read()
                except OSError:
                    continue
                raise RuntimeError("LEAKED: %%s is readable in a visible test" %% os.path.basename(path))
        """ % (hidden,)
    result = _grade_attack(tmp_path, isolation, attack)
    assert _scores(result) == honest_scores(isolation)


def test_a_bvh_that_tests_every_shape_through_references_taken_at_import_loses_the_traversal_test(
        isolation, tmp_path):
    # a08's hidden traversal test counts box and shape tests through wrappers of BBox.hit and
    # of the shapes' intersect_p. A BVH.intersect that ignored its tree and called the shapes'
    # tests through references taken when its module was imported (before the wrapping), with
    # one counted box test a ray, passed it with its shape tests uncounted. The shapes' tests
    # are now wrapped before the student's module is imported.
    files = dict(solution_files("a08"))
    head = "        if self.root is None:\n            return best\n        stack = [self.root]\n"
    assert files["accelerators/bvh.py"].count(head) == 1
    files["accelerators/bvh.py"] = files["accelerators/bvh.py"].replace(head, (
        "        if self.root is None:\n            return best\n"
        "        self.root.bbox.hit(ray)\n"
        "        for i, shape in enumerate(self.shapes):\n"
        "            if _RAW[type(shape)](shape, ray):\n"
        "                best = i\n"
        "        return best\n")) + (
        "\n\nfrom ..shapes.sphere import Sphere as _S\n"
        "from ..shapes.triangle import Triangle as _T\n"
        "_RAW = {_S: _S.intersect_p, _T: _T.intersect_p}\n")
    write_files(files, tmp_path / "sub")
    traversal = [c for c in checks_for("a08_bvh") if c.probe[:2] == ("a08_hidden", "observe_traversal")]
    assert len(traversal) == 1
    result = grade("a08", tmp_path / "sub", None, only=(traversal[0].slug,))
    assert result.tests[0].score == 0, result.tests[0].output
    assert "shape tests over its" in result.tests[0].output, result.tests[0].output


def test_no_process_of_the_sandbox_user_is_left_after_its_tests_not_even_a_zombie(bwrap, tmp_path):
    # Killing a test's namespace leaves processes without a parent; in a container PID 1 may
    # never reap them, and as zombies of the sandbox user they would count towards its
    # process limit until forking fails in later tests. The grader reaps them itself.
    from rtfgu.grading import sandbox

    if not sandbox.bwrap_as_user(find_bwrap()):
        pytest.skip("bwrap runs as root here, not as a sandbox user")
    with sandbox.work_folder() as tmp:
        ws = prepare(get_assignment("a03"), _submission(tmp_path / "sub"), tmp / "work")
        for i in range(20):
            assert sandbox.run_child(ws, tmp / "scratch" / str(i), ["check", "a03", ONLY[1]],
                                     isolation="bwrap").status == "ok"
    uid = sandbox.sandbox_uid()
    time.sleep(0.5)
    sandbox._reap_orphans(uid)
    left = [p for p in os.listdir("/proc") if p.isdigit() and _uid_of(p) == uid]
    assert left == [], "processes of the sandbox user %d are left: %s" % (uid, left)


def _uid_of(pid: str):
    try:
        return os.stat("/proc/" + pid).st_uid
    except OSError:
        return None


def test_a_forged_traceback_dump_can_only_stop_the_students_own_functions(isolation, tmp_path):
    """The dump that names where a looping test was (rtfgu.grading.timeouts) is written by the
    student's process, which can find its descriptor in its own command line: a forged dump with
    an overlong name, a frame outside the student's files and megabytes of junk only stops the
    student's own Plane.intersect_p for the later tests; the grading ends, its texts stay short."""
    honest = honest_scores(isolation)
    attack = """
        import json, os, sys
        fd = json.loads(sys.argv[5])["dump"][0]
        fake = ('File "/x/rtfgu/shapes/plane.py", line 5 in ' + "f" * 200 + "\\n"
                'File "/x/rtfgu/../grading/grader.py", line 1 in grade\\n'
                'File "/x/rtfgu/shapes/plane.py", line 27 in intersect_p\\n')
        os.write(fd, fake.encode() + b"z" * (4 << 20))
        while True:
            pass
        """
    result = grade("a03", _submission(tmp_path / "sub", attack), tmp_path / "out", time_limit=2.0,
                   only=ONLY + ("03_sphere_intersect_p_rays_that_miss",))
    scores = _scores(result)
    assert {k: v for k, v in scores.items() if k != "3.3"} == honest
    tests = {t.number: t for t in result.tests}
    assert tests["3.2"].cause == "time limit (2 s) at shapes/plane.py:27"
    assert "f" * 101 not in json.dumps([t.output for t in result.tests])
    assert all(len(t.output) < 20_000 for t in result.tests)
    # 3.3 calls Sphere.intersect_p, which loops again: the forged frame did not stop it.
    assert scores["3.3"] == 0 and "time limit of 2 s" in tests["3.3"].output


def test_the_gradebook_error_column_names_why_tests_could_not_judge_the_code(tmp_path, isolation):
    # Staff sort a class of 300 by this column: a syntax error at its file and line, the time
    # limit, an exception raised as a whole; empty for a submission that was judged.
    from rtfgu.grading.gradebook import grade_all

    solved = solution_files("a04")
    rho = "        return self.surface_color(self.cd, sr) * self.kd\n"
    assert rho in solved["brdfs/lambertian.py"]
    variants = {
        "alice": {},
        "dave": {"materials/matte.py": solved["materials/matte.py"].replace(
            "    def ambient(self, sr, wo)", "    def ambient(self, sr, wo", 1)},
        "erin": {"brdfs/lambertian.py": solved["brdfs/lambertian.py"].replace(
            rho, "        while True:\n            pass\n", 1)},
        "fred": {"lights/point_light.py": solved["lights/point_light.py"] + "\nraise RuntimeError('boom')\n"},
    }
    for student, changed in variants.items():
        write_files(dict(solved, **changed), tmp_path / "class" / student)
    line = solved["materials/matte.py"].splitlines().index("    def ambient(self, sr, wo) -> Float3:") + 1
    # An honest test takes well under a second alone; the limit leaves room for a loaded
    # machine (the suite's other worker compiling kernels), where 1 s timed honest tests out.
    path = grade_all("a04", tmp_path / "class", tmp_path / "out", processes=2, time_limit=5)
    errors = {r["student"]: r["error"] for r in csv.DictReader(open(path))}
    assert errors["alice"] == ""
    assert errors["dave"].startswith("SyntaxError in materials/matte.py, line %d" % line), errors["dave"]
    # The loop's line (from the traceback dumped before the limit); the later tests that call
    # the stopped function fail at once, naming the test that found it.
    loop = solved["brdfs/lambertian.py"].splitlines().index(rho.rstrip("\n")) + 1
    # Under load a test may run out of its time before it reaches the loop: it is counted
    # without a line, before the one that names the loop.
    assert re.match(r"(time limit \(5 s\) \(\d+ tests?\); )?time limit \(5 s\) at brdfs/lambertian.py:(%d|%d) "
                    r"\(1 test\); time limit in test 4\.\d+ \(\d+ tests?\)" % (loop, loop + 1),
                    errors["erin"]), errors["erin"]
    assert "exception: RuntimeError: boom" in errors["fred"], errors["fred"]


def test_a_killed_graders_work_folder_is_removed_when_its_sandbox_user_is_claimed_again(tmp_path):
    """A grader killed mid-grading leaves its work folder (root's, readable by the group of
    its sandbox user): the next grader to claim that user removes it before any submission
    runs as that user, and leaves every other folder alone."""
    from rtfgu.grading import sandbox

    stale = tmp_path / "rtfgu-grade-stale"
    other_group = tmp_path / "rtfgu-grade-other"
    unrelated = tmp_path / "rtfgu-release-gaps-x"
    for folder, gid in ((stale, 64999), (other_group, 64998), (unrelated, 64999)):
        (folder / "work" / "package").mkdir(parents=True)
        (folder / "work" / "package" / "sphere.py").write_text("solved\n")
        os.chown(folder, os.geteuid(), gid)
    removed = sandbox.remove_stale_work_folders(64999, str(tmp_path))
    assert removed == [str(stale)] and not stale.exists()
    assert other_group.exists() and unrelated.exists()


def test_bytecode_planted_for_the_next_tests_is_never_run(isolation, tmp_path):
    """The grader writes the bytecode of the package a test imports (rtfgu.grading.bytecode).
    A submission that replaces it, for the honest files the later tests import, with code
    that matches their sources' hashes and does something else, cannot: the folders are
    read-only to it in every mode, and the later tests score what the honest part scores."""
    honest = honest_scores(isolation)
    attack = """
        import importlib.util, marshal, os
        import rtfgu
        for name in ("shapes/triangle.py", "shapes/plane.py"):
            source = os.path.join(os.path.dirname(rtfgu.__file__), name)
            data = open(source, "rb").read()
            bad = (importlib.util.MAGIC_NUMBER + (3).to_bytes(4, "little") + importlib.util.source_hash(data)
                   + marshal.dumps(compile("raise RuntimeError('LEAKED: a planted pyc ran')", source, "exec")))
            target = importlib.util.cache_from_source(source)
            for plant in (lambda: open(target, "wb").write(bad),
                          lambda: (os.unlink(target), open(target, "wb").write(bad)),
                          lambda: (os.rename(os.path.dirname(target), os.path.dirname(target) + "-old"),
                                   os.mkdir(os.path.dirname(target)), open(target, "wb").write(bad))):
                try:
                    plant()
                except OSError:
                    pass
        """
    result = _grade_attack(tmp_path, isolation, attack)
    assert _scores(result) == honest
    assert all("planted pyc" not in t.output for t in result.tests)
