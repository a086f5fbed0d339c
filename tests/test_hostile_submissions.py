"""Hostile a03 submissions: each puts an attack into Sphere.intersect_p and then gives up as
the unsolved stub does, beside an honest plane and triangle. Each must score exactly what
its honest part scores, test by test, and change nothing outside its scratch folder: the
checkout stays clean, no process survives, no connection is made.

Run under bubblewrap (skipped, naming the Debian package, where it cannot run) and, for
the attacks a weaker isolation also stops, under the fallback."""
from __future__ import annotations

import os
import socket
import subprocess
import sys
import threading
import time
import zipfile
from pathlib import Path

import pytest

from rtfgu.grading.generate import PACKAGE_DIR, solution_files, student_files, write_files
from rtfgu.grading.grader import grade
from rtfgu.grading.sandbox import bwrap_works, find_bwrap

ROOT = Path(__file__).resolve().parent.parent
SPHERE = "shapes/sphere.py"
HEAD = "    def intersect_p(self, ray: Ray) -> bool:\n"
STUB = "        raise NotImplementedError('a03: Sphere.intersect_p')\n"


def _bwrap():
    bwrap = find_bwrap()
    if bwrap is None or not bwrap_works(bwrap):
        pytest.skip("bubblewrap is not installed or cannot run here (Debian package bubblewrap; "
                    "`make venv` fetches it)")


@pytest.fixture
def bwrap(monkeypatch):
    _bwrap()
    monkeypatch.setenv("RTFGU_ISOLATION", "bwrap")


def _submission(folder: Path, attack: str = "") -> Path:
    """Solved plane and triangle; a sphere whose intersect_p runs ``attack`` and then raises
    as the stub does."""
    files = dict(solution_files("a03"))
    stub = student_files("a03")[SPHERE]
    start = stub.index(HEAD) + len(HEAD)
    body = "".join("        " + line + "\n" for line in attack.strip("\n").split("\n")) if attack else ""
    files[SPHERE] = stub[:start] + body + stub[start:]
    write_files(files, folder)
    return folder


def _scores(result) -> dict:
    return {t.number: t.score for t in result.tests}


@pytest.fixture(scope="module")
def honest(tmp_path_factory):
    _bwrap()
    folder = tmp_path_factory.mktemp("honest")
    os.environ["RTFGU_ISOLATION"] = "bwrap"
    try:
        result = grade("a03", _submission(folder / "sub"), folder / "out")
    finally:
        del os.environ["RTFGU_ISOLATION"]
    scores = _scores(result)
    assert 0 < sum(scores.values()) < result.max_score  # the honest part earns some, not all
    return scores


def _git_status() -> str:
    return subprocess.run(["git", "status", "--porcelain"], cwd=ROOT, capture_output=True, text=True).stdout


ATTACKS = {
    "delegates to the robust twin": "import rtfgu.robust as r\nreturn r.intersect_sphere_robust(ray, self.center, self.radius)",
    "delegates to the numba kernels": "from rtfgu.kernels import intersect\nreturn bool(intersect)",
    "execs the solved source from the checkout":
        "src = open(%r).read()\nns = {}\nexec(src, ns)" % str(PACKAGE_DIR / SPHERE),
    "reads the references": "import glob\nfor p in glob.glob('/**/observations.json', recursive=True):\n"
                            "    raise RuntimeError(open(p).read()[:100])",
    "reads the grader's memory and environment":
        "import os\nfor pid in (os.getppid(), 1):\n    for name in ('environ', 'cmdline', 'maps'):\n"
        "        try:\n            open('/proc/%d/%s' % (pid, name)).read()\n        except OSError:\n            pass",
    "writes a fake answer into every pipe":
        "import os\nfor fd in range(3, 64):\n    try:\n        os.write(fd, b'{\"cases\": [{\"out\": {}}]}')\n"
        "    except OSError:\n        pass",
    "floods the grader's stdout through /proc":
        "import os\nfor path in ('/proc/%d/fd/1' % os.getppid(), '/proc/1/fd/1'):\n    try:\n"
        "        with open(path, 'w') as f:\n            f.write('x' * (64 << 20))\n    except OSError:\n        pass",
}


@pytest.mark.parametrize("name", list(ATTACKS))
def test_an_attack_scores_what_its_honest_part_scores_and_changes_nothing(bwrap, honest, tmp_path, name):
    before = _git_status()
    result = grade("a03", _submission(tmp_path / "sub", ATTACKS[name]), tmp_path / "out")
    assert result.isolation == "bwrap"
    assert _scores(result) == honest, name
    assert _git_status() == before


def test_no_process_outlives_its_test_and_nothing_outside_scratch_is_written(bwrap, honest, tmp_path):
    token = "rtfgu-survivor-%d" % os.getpid()
    canary = tmp_path / "canary.txt"
    canary.write_text("untouched")
    later = "import time; time.sleep(4); open(%r, 'w').write('x')" % str(canary)
    attack = ("import subprocess, sys\n"
              "subprocess.Popen([sys.executable, '-c', %r, %r], start_new_session=True)\n"
              "for path in (%r, %r):\n"
              "    try:\n        open(path, 'w').write('changed')\n    except OSError:\n        pass"
              % (later, token, str(canary), str(PACKAGE_DIR / "grading" / "grader.py")))
    compile(attack, "attack", "exec")
    before = _git_status()
    result = grade("a03", _submission(tmp_path / "sub", attack), tmp_path / "out")
    time.sleep(5)
    assert _scores(result) == honest
    assert canary.read_text() == "untouched"
    assert _git_status() == before
    alive = subprocess.run(["pgrep", "-f", token], capture_output=True, text=True).stdout.strip()
    assert alive == "", "a process of the submission survived: %s" % alive


def test_no_connection_leaves_the_sandbox(bwrap, honest, tmp_path):
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(5)
    server.settimeout(0.2)
    port = server.getsockname()[1]
    accepted = []

    def accept():
        end = time.time() + 30
        while time.time() < end and not stop.is_set():
            try:
                accepted.append(server.accept())
            except OSError:
                pass
    stop = threading.Event()
    thread = threading.Thread(target=accept)
    thread.start()
    attack = ("import socket\ns = socket.socket()\ns.settimeout(2)\n"
              "try:\n    s.connect(('127.0.0.1', %d))\n    s.send(b'answers?')\nexcept OSError:\n    pass" % port)
    try:
        result = grade("a03", _submission(tmp_path / "sub", attack), tmp_path / "out")
    finally:
        stop.set()
        thread.join()
        server.close()
    assert accepted == []
    assert _scores(result) == honest


def test_printing_a_gigabyte_costs_that_test_only_and_the_grader_output_stays_small(bwrap, honest, tmp_path, capfd):
    attack = "import sys\nfor _ in range(1024):\n    sys.stdout.write('y' * (1 << 20))"
    result = grade("a03", _submission(tmp_path / "sub", attack), tmp_path / "out")
    assert _scores(result) == honest
    out, err = capfd.readouterr()
    assert len(out) + len(err) < 100_000
    assert all(len(t.output) < 20_000 for t in result.tests)


def _zip(path: Path, entries) -> Path:
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in entries:
            if isinstance(data, int):  # a link entry pointing at data's text
                info = zipfile.ZipInfo(name)
                info.external_attr = (0o120777 << 16)
                z.writestr(info, "/etc/passwd")
            else:
                z.writestr(name, data)
    return path


def test_a_zip_bomb_and_escaping_entries_are_not_unpacked(bwrap, honest, tmp_path):
    files = dict(solution_files("a03"))
    files[SPHERE] = student_files("a03")[SPHERE]
    entries = [("shapes/" + Path(k).name, v) for k, v in files.items()]
    entries += [("../escaped.txt", "outside"), ("/tmp/%s-absolute.txt" % tmp_path.name, "outside"),
                ("shapes/link.py", 1)]
    archive = _zip(tmp_path / "sub.zip", entries)
    with zipfile.ZipFile(archive, "a", zipfile.ZIP_DEFLATED) as z, z.open("bomb.bin", "w", force_zip64=True) as f:
        chunk = bytes(1 << 20)
        for _ in range(2048):  # 2 GiB of zeros, about 2 MB compressed
            f.write(chunk)
    assert archive.stat().st_size < 8 << 20
    script = ("import resource, sys\nfrom rtfgu.grading.grader import grade\n"
              "r = grade('a03', sys.argv[1], sys.argv[2])\n"
              "print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)\n"
              "print(';'.join('%s=%s' % (t.number, t.score) for t in r.tests))\n"
              "print('|'.join(r.notes))")
    done = subprocess.run([sys.executable, "-c", script, str(archive), str(tmp_path / "out")],
                          capture_output=True, text=True, timeout=600,
                          env=dict(os.environ, RTFGU_ISOLATION="bwrap"))
    assert done.returncode == 0, done.stderr
    peak_kb, scores, notes = done.stdout.strip().split("\n")[-3:]
    assert int(peak_kb) < 600 * 1024, "the grader used %s kB" % peak_kb
    assert dict(item.split("=") for item in scores.split(";")) == {k: str(v) for k, v in honest.items()}
    assert not (tmp_path / "escaped.txt").exists() and not Path("/tmp/%s-absolute.txt" % tmp_path.name).exists()
    assert "outside the submission folder" in notes and "link" in notes and "MB" in notes


@pytest.mark.parametrize("isolation", ["bwrap", "rlimits"])
def test_a_syntax_error_costs_only_the_tests_that_need_that_file(isolation, tmp_path, monkeypatch):
    if isolation == "bwrap":
        _bwrap()
    monkeypatch.setenv("RTFGU_ISOLATION", isolation)
    files = dict(solution_files("a03"))
    files["shapes/triangle.py"] = files["shapes/triangle.py"].replace("        denom = dot(", "        denom = = dot(", 1)
    write_files(files, tmp_path / "sub")
    result = grade("a03", tmp_path / "sub", tmp_path / "out")
    by_number = {t.number: t for t in result.tests}
    assert by_number["3.5"].score == 0
    assert "SyntaxError in shapes/triangle.py, line" in by_number["3.5"].output
    for number in ("3.1", "3.2", "3.3", "3.4"):
        assert by_number[number].score == by_number[number].max_score, by_number[number].output
    line = int(by_number["3.5"].output.split("line ")[1].split(":")[0])
    assert "= = dot(" in files["shapes/triangle.py"].split("\n")[line - 1]


def test_require_sandbox_refuses_to_grade_without_bwrap(tmp_path, monkeypatch):
    from rtfgu.grading import sandbox

    monkeypatch.setattr(sandbox, "find_bwrap", lambda: None)
    monkeypatch.delenv("RTFGU_ISOLATION", raising=False)
    with pytest.raises(ValueError, match="require-sandbox.*bubblewrap"):
        grade("a03", _submission(tmp_path / "sub"), tmp_path / "out", require_sandbox=True)
    assert not (tmp_path / "out").exists()  # refused before anything ran
