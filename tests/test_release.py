"""A student release: the package with every assigned function stubbed in place and nothing
that computes one again; its checker runs the visible tests only, on the student's own code."""
from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from rtfgu.grading.assignments import ASSIGNMENTS, block_table
from rtfgu.grading.checks import checks_for
from rtfgu.grading.generate import PACKAGE_DIR, find_blocks, solution_files, source_text, write_files
from rtfgu.grading.release import solves, write_release

TRIVIAL = re.compile(r"^(return|return (True|False|result|None)|return (true|false);|else:|\}|\{|pass|continue|break|"
                     r"// ### (BEGIN|END) SOLUTION|### (BEGIN|END) SOLUTION|\)|\];?)$")


def _solution_lines() -> dict:
    """Every non-trivial line of every solution block -> where it stands."""
    lines = {}
    for relpath in sorted({key[0] for key in block_table()}):
        text = source_text(relpath)
        rows = text.split("\n")
        for qualname, begin, end, _ in find_blocks(text, relpath):
            for line in rows[begin + 1:end]:
                s = line.strip()
                if s and not s.startswith(("#", "//")) and not TRIVIAL.match(s) and len(s) > 12:
                    lines[s] = "%s:%s" % (relpath, qualname)
    return lines


@pytest.fixture(scope="module")
def release(tmp_path_factory):
    out = tmp_path_factory.mktemp("release")
    write_release(out, reveal=("a01", "a02"))
    return out


def _release_files(release):
    return [p for p in release.rglob("*") if p.is_file() and "__pycache__" not in p.parts]


def test_no_line_of_an_unrevealed_solution_is_in_the_release(release):
    revealed = {"a01", "a02"}
    wanted = {s: where for s, where in _solution_lines().items()
              if block_table()[(where.split(":")[0], where.split(":")[1])][0].short not in revealed}
    assert len(wanted) > 40  # the test looks for something
    found = []
    for path in _release_files(release):
        if path.suffix not in (".py", ".wgsl", ".md", ".json", ".txt", ""):
            continue
        code = {line.strip() for line in path.read_text(errors="replace").split("\n")
                if not line.strip().startswith(("#", "//"))}
        found += ["%s (from %s) in %s" % (s, where, path.relative_to(release)) for s, where in wanted.items()
                  if s in code]
    assert found == []


def test_no_twin_no_hidden_test_and_no_hidden_reference_is_in_the_release(release):
    package = release / "rtfgu"
    assert not (package / "kernels").exists() and not (package / "hardcases").exists()
    assert not (package / "robust.py").exists()
    for path in package.rglob("*"):
        if path.suffix in (".py", ".wgsl"):
            assert not solves(path.read_text()) - {1, 2}, path
    checks_text = "\n".join(p.read_text() for p in (package / "grading" / "checks").glob("*.py"))
    assert "### BEGIN HIDDEN" not in checks_text and "### BEGIN STAFF" not in checks_text
    assert "def hint_sphere" not in checks_text and "def _roots" not in checks_text
    for a in ASSIGNMENTS.values():
        hidden = [c for c in checks_for(a.id) if c.visibility != "visible"]
        observations = (package / "grading" / "reference" / a.id / "observations.json").read_text()
        for c in hidden:
            assert c.slug not in observations
            assert not (package / "grading" / "reference" / a.id / (c.slug + ".png")).exists()
    # the earlier assignments' solutions are revealed, the later ones stubbed in place
    assert "raise NotImplementedError" not in (package / "float3.py").read_text()
    assert "raise NotImplementedError('a03: Sphere.intersect_p')" in (package / "shapes" / "sphere.py").read_text()


def test_every_kernel_or_wgsl_file_that_defines_an_assigned_function_is_marked():
    names = {qualname.split(".")[-1] for _, qualname in block_table()}
    names |= {"gen_ray", "get_camera_ray", "sample_point_light", "brdf_lambertian", "brdf_phong", "direct_light",
              "intersect_plane", "intersect_sphere", "intersect_triangle", "in_shadow", "mirror", "transparent"}
    names -= {"__add__", "__sub__", "__mul__", "__truediv__", "__neg__", "__call__", "length"}
    unmarked = []
    for folder in ("kernels", "wgsl", "hardcases"):
        for path in sorted((PACKAGE_DIR / folder).glob("*")):
            if path.suffix not in (".py", ".wgsl"):
                continue
            text = path.read_text()
            defined = set(re.findall(r"^(?:def|fn) (\w+)\(", text, re.M)) & names
            defined = {d for d in defined if not (path.suffix == ".wgsl" and "### BEGIN SOLUTION" in text)}
            if defined and not solves(text):
                unmarked.append("%s defines %s" % (path.relative_to(PACKAGE_DIR), ", ".join(sorted(defined))))
    assert unmarked == []


def _env(release):
    """The release first and the site-packages without their .pth files (-S): our venv's
    editable install of the staff package must not fill in what the release leaves out."""
    import site

    return {"PYTHONPATH": os.pathsep.join([str(release)] + site.getsitepackages()), "PATH": "/usr/bin:/bin"}


def _check(release, assignment):
    return subprocess.run([sys.executable, "-S", "-m", "rtfgu.grading", "check", assignment, "rtfgu"],
                          cwd=release, env=_env(release), capture_output=True, text=True, timeout=300)


def test_make_check_fails_on_the_stubs_and_passes_once_the_student_writes_a_solution(release):
    done = _check(release, "a03")
    assert done.returncode == 1, done.stdout + done.stderr
    assert "not written yet" in done.stdout
    assert "hidden" not in done.stdout.lower().replace("hidden test", "")
    write_files(solution_files("a03"), release / "rtfgu")
    done = _check(release, "a03")
    assert done.returncode == 0, done.stdout + done.stderr
    assert "a03_intersections: 14 / 14 points" in done.stdout
    assert (release / "check-results" / "a03" / "diffs").is_dir()


def test_running_a_student_file_directly_says_how_to_run_it(release):
    done = subprocess.run([sys.executable, "rtfgu/lights.py"], cwd=release, capture_output=True,
                          text=True, timeout=60)
    assert done.returncode != 0
    assert "make check A=a04" in done.stderr and "relative import" not in done.stderr


def test_the_release_renders_with_the_reference_and_says_the_other_paths_are_not_in_it(release):
    script = ("import rtfgu\nfrom rtfgu.scenes import SCENES\n"
              "try:\n    rtfgu.render(SCENES['lecture01_flat_colors'](), 4, 4, backend='numba')\n"
              "except Exception as e:\n    print(type(e).__name__, e)\n")
    done = subprocess.run([sys.executable, "-S", "-c", script], cwd=release, env=_env(release),
                          capture_output=True, text=True, timeout=120)
    assert "not part of this release" in done.stdout, done.stdout + done.stderr
