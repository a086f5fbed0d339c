"""The student release: nothing in it computes an assigned function, no hidden test or
hidden reference is in it, and its checker fails on the stubs and passes on a solution."""
from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from rtfgu.grading.assignments import ASSIGNMENTS, block_table
from rtfgu.grading.checks import checks_for, traces_a_scene
from rtfgu.grading.generate import PACKAGE_DIR, find_blocks, solution_files, source_text, student_files, write_files
from rtfgu.grading.release import build_package, probe_files, solves, write_release

from planted import apply_replacements, describe

ROOT = Path(__file__).resolve().parent.parent
TRIVIAL = re.compile(r"^(return|return (True|False|result|None|hit)|return (true|false);|else:|else \{|\}|\{|pass|"
                     r"continue|break|\)|\];?|\} else \{)$")


def _idioms() -> set:
    """Lines that the given code (outside solution blocks) of two or more files of the package
    holds: idiom, not solution (``n = math.isqrt(self.num_samples)`` in every grid sampler).
    A twin of an assigned function is one file, so its lines are not among them."""
    files_of = {}
    for path in sorted(PACKAGE_DIR.rglob("*")):
        if not path.is_file() or path.suffix not in (".py", ".wgsl") or "grading" in path.parts:
            continue
        relpath = path.relative_to(PACKAGE_DIR).as_posix()
        text = path.read_text()
        rows = text.split("\n")
        inside = {i for _, begin, end, _ in find_blocks(text, relpath) for i in range(begin, end + 1)}
        for row in {row.strip() for i, row in enumerate(rows) if i not in inside}:
            files_of.setdefault(row, set()).add(relpath)
    return {row for row, files in files_of.items() if len(files) >= 2}


def solution_lines(revealed=()) -> dict:
    """Every non-trivial line of every solution block of an assignment not in ``revealed``
    (short ids) -> "file:function" it stands in. A line that the given code of the same file
    also holds (``while stack:`` in the BVH's build and its traversal), or that of two other
    files (_idioms), reveals nothing."""
    lines = {}
    idioms = _idioms()
    for relpath in sorted({key[0] for key in block_table()}):
        text = source_text(relpath)
        rows = text.split("\n")
        blocks = find_blocks(text, relpath)
        inside = {i for _, begin, end, _ in blocks for i in range(begin, end + 1)}
        given = {row.strip() for i, row in enumerate(rows) if i not in inside}
        for qualname, begin, end, _ in blocks:
            if block_table()[(relpath, qualname)][0].short in revealed:
                continue
            for line in rows[begin + 1:end]:
                s = line.strip()
                if s and not s.startswith(("#", "//")) and not TRIVIAL.match(s) and s not in given \
                        and s not in idioms:
                    lines[s] = "%s:%s" % (relpath, qualname)
    return lines


def solution_lines_in(folder: Path, revealed=()) -> list:
    """The solution lines (solution_lines) found as a line of any text file under ``folder``."""
    wanted = solution_lines(revealed)
    found = []
    for path in sorted(folder.rglob("*")):
        if not path.is_file() or path.suffix in (".png", ".pyc"):
            continue
        code = {line.strip() for line in path.read_text(errors="replace").split("\n")}
        found += ["%s (from %s) in %s" % (s, where, path.relative_to(folder)) for s, where in wanted.items()
                  if s in code]
    return found


def test_the_student_package_has_no_solution_line_no_twin_and_no_grader(tmp_path):
    package = build_package(tmp_path, reveal=("a01", "a02"))
    assert package == tmp_path / "rtfgu"
    assert len(solution_lines(("a01", "a02"))) > 40   # the scan looks for something
    assert solution_lines_in(package, ("a01", "a02")) == []
    assert not (package / "kernels").exists() and not (package / "hardcases").exists()
    assert not (package / "robust.py").exists() and not (package / "grading").exists()
    for path in package.rglob("*"):
        assert "__pycache__" not in path.parts and path.suffix not in (".nbi", ".nbc", ".pyc")
        if path.suffix in (".py", ".wgsl"):
            assert not solves(path.read_text()) - {1, 2}, path
    # the revealed assignments keep their solution, the others are stubbed in place
    assert "raise NotImplementedError" not in (package / "float3.py").read_text()
    assert "raise NotImplementedError('a03: Sphere.intersect_p')" in (package / "shapes" / "sphere.py").read_text()
    # every solution revealed: the twins ship
    full = build_package(tmp_path / "all", reveal=tuple(a.short for a in ASSIGNMENTS.values()))
    assert (full / "kernels" / "intersect.py").is_file() and (full / "robust.py").is_file()
    # the numba and WGSL paths look textures up as a07 does: they ship once a07 is revealed
    before = build_package(tmp_path / "a06", reveal=("a01", "a02", "a03", "a04", "a05", "a06"))
    assert not (before / "kernels").exists() and not (before / "wgsl" / "image_texture.wgsl").exists()
    assert "raise NotImplementedError('a07: ImageTexture.get_color')" in (
        before / "textures" / "image_texture.py").read_text()
    assert (full / "kernels" / "textures.py").is_file() and (full / "wgsl" / "image_texture.wgsl").is_file()
    # the numba path traverses a BVH as a08 does: it ships once a08 is revealed
    a07 = build_package(tmp_path / "a07", reveal=("a01", "a02", "a03", "a04", "a05", "a06", "a07"))
    assert not (a07 / "kernels").exists()
    assert "raise NotImplementedError('a08: BVH.intersect')" in (a07 / "accelerators" / "bvh.py").read_text()
    assert "raise NotImplementedError('a08: BBox.hit')" in (a07 / "accelerators" / "bbox.py").read_text()
    # the numba and WGSL paths map samples to the hemisphere as a09 does: they ship once a09 is
    # revealed; the lecture layer's path tracer ships with a04 and a05, calling the a09 stubs
    a08 = build_package(tmp_path / "a08", reveal=("a01", "a02", "a03", "a04", "a05", "a06", "a07", "a08"))
    assert not (a08 / "kernels").exists() and not (a08 / "wgsl" / "hemisphere_map.wgsl").exists()
    assert not (a08 / "wgsl" / "path_trace.wgsl").exists() and (a08 / "tracers" / "path_trace.py").is_file()
    assert "raise NotImplementedError('a09: hemisphere_map')" in (a08 / "sampling" / "maps.py").read_text()
    assert "raise NotImplementedError('a09: Lambertian.sample_f')" in (a08 / "brdfs" / "lambertian.py").read_text()
    assert (full / "kernels" / "sampling.py").is_file() and (full / "wgsl" / "hemisphere_map.wgsl").is_file()


def test_the_probes_hold_no_hint_and_import_nothing_of_the_grader():
    files = probe_files()
    visible = probe_files(keep_hidden=False)
    assert "a03_hidden.py" in files and "a03.py" in files and "boot.py" in files
    assert not [name for name in visible if "hidden" in name]
    assert solution_lines_in(PACKAGE_DIR / "grading" / "probes") == []
    for name, text in files.items():
        if name.endswith(".py"):
            assert "def hint" not in text, name
            assert not re.search(r"^\s*from \.\.|^\s*(from|import) rtfgu\.grading", text, re.M), name

# Function names that compute an assigned function: the blocks' own names and the names
# their numba and WGSL twins go by. A name also matches with a suffix (intersect_sphere_robust).
TWIN_NAMES = {
    "a01": ("add", "sub", "mul", "neg", "div", "dot", "cross", "normalize", "length", "length_squared"),
    "a02": ("gen_ray", "get_camera_ray"),
    "a03": ("intersect_p", "normal_at", "intersect_plane", "intersect_sphere", "intersect_triangle",
            "normal_plane", "normal_sphere", "normal_triangle", "sphere_roots"),
    "a04": ("sample_point_light", "point_light", "lambertian", "brdf_lambertian", "direct_light"),
    "a05": ("in_shadow", "phong", "brdf_phong", "mirror", "transparent", "glossy", "glossy_lobe",
            "transmitted_direction"),
    "a06": ("intersect_plane", "intersect_sphere", "intersect_triangle"),
    "a07": ("texel", "_texel", "get_color", "texture_image_texture"),
    "a08": ("bbox_hit", "hit_bbox", "box_hit", "box_entry", "slab_test", "intersect_bbox", "intersect_box",
            "intersect_bvh", "bvh_intersect", "traverse_bvh", "bvh_closest", "mesh_closest"),
    "a12": ("sample_area_light_area",),
}
# Block names too common to stand for their assignment in a twin's function names (BBox.hit,
# BVH.intersect: intersect_disk is no BVH traversal; the book's BRDF and light methods f, L,
# rho; Material.shade, Matte.ambient, reflect; a shape's sample: every sampler samples); their
# twins go by the names above.
GENERIC_BLOCK_NAMES = {"hit", "intersect", "f", "L", "rho", "shade", "ambient", "reflect", "get_direction", "sample"}
TWIN_FOLDERS = ("kernels", "wgsl", "hardcases")
_DEF = re.compile(r"^\s*(?:def|fn)\s+(?P<name>\w+)\s*\(", re.M)


def _assigned_names() -> dict:
    """name -> the assignments (short ids) whose functions it computes."""
    names = {}
    for short, aliases in TWIN_NAMES.items():
        for name in aliases:
            names.setdefault(name, set()).add(short)
    for (_, qualname), (a, _) in block_table().items():
        name = qualname.split(".")[-1]
        if not name.startswith("__") and name not in GENERIC_BLOCK_NAMES:
            names.setdefault(name, set()).add(a.short)
    return names


def twin_candidates() -> dict:
    """relpath -> text of every file that may hold a twin (rtfgu/kernels, wgsl, hardcases, robust.py)."""
    paths = [PACKAGE_DIR / "robust.py"]
    for folder in TWIN_FOLDERS:
        paths += [p for p in sorted((PACKAGE_DIR / folder).rglob("*")) if p.suffix in (".py", ".wgsl")
                  and "__pycache__" not in p.parts and "__generated__" not in p.parts]
    return {p.relative_to(PACKAGE_DIR).as_posix(): p.read_text() for p in paths}


def unmarked_twins(files: dict) -> list:
    """(file, function, assignments) for every function in ``files`` (relpath -> text) named
    like an assigned function, outside a solution block, whose file's ``release: solves``
    marker names none of those assignments."""
    names = _assigned_names()
    problems = []
    for rel, text in files.items():
        own_blocks = {q.split(".")[-1] for q, *_ in find_blocks(text, rel)}
        marked = {"a%02d" % n for n in solves(text)}
        for m in _DEF.finditer(text):
            name = m.group("name")
            if name in own_blocks:
                continue   # the student's own file: its block is stubbed in place
            wanted = set()
            for assigned, shorts in names.items():
                if name == assigned or name.startswith(assigned + "_"):
                    wanted |= shorts
            if wanted and not wanted & marked:
                problems.append((rel, name, sorted(wanted)))
    return problems


def test_every_twin_of_an_assigned_function_is_marked():
    problems = unmarked_twins(twin_candidates())
    assert problems == [], ("add a line `# release: solves aNN` (`// release: solves aNN` in WGSL) "
                            "near the top of these files: %s" % problems)


def test_a_twin_without_its_marker_or_with_the_wrong_one_is_found():
    files = twin_candidates()
    unmarked = "\n".join(l for l in files["kernels/intersect.py"].split("\n") if "release: solves" not in l)
    problems = unmarked_twins({"kernels/intersect.py": unmarked})
    assert any(name.startswith("intersect_sphere") and "a03" in shorts for _, name, shorts in problems)
    wrong = files["wgsl/phong.wgsl"].replace("release: solves a05", "release: solves a04")
    assert [p[1] for p in unmarked_twins({"wgsl/phong.wgsl": wrong})] == ["brdf_phong"]
    # the student's own file: the function around its solution block ships stubbed
    assert unmarked_twins({"wgsl/intersect_sphere.wgsl": files["wgsl/intersect_sphere.wgsl"]}) == []
    # a08's twins go by their own names: a BVH's slab test is one, the scene's loop is none
    slab = "def box_entry(nodes, n, origin, inv, tmin, tmax):\n    pass\n"
    assert unmarked_twins({"kernels/bvh.py": slab}) == [("kernels/bvh.py", "box_entry", ["a08"])]
    assert unmarked_twins({"kernels/bvh.py": "# release: solves a08\n" + slab}) == []
    assert unmarked_twins({"wgsl/x.wgsl": "fn intersect_scene(r: Ray) -> bool {\n}\n"}) == []


# --- the student repository -------------------------------------------------------------------

REVEALED = ("a01", "a02")


@pytest.fixture(scope="module")
def release(tmp_path_factory):
    out = tmp_path_factory.mktemp("release")
    write_release(out, reveal=REVEALED)
    return out


def _env(release) -> dict:
    """The release first, then the site-packages read without their .pth files (-S): the
    editable install of this checkout must not fill in what the release leaves out."""
    import site

    return dict(os.environ, PYTHONPATH=os.pathsep.join([str(release)] + site.getsitepackages()))


def _run(release, *args, timeout=300):
    """The release's own checker (python -S -m rtfgu_checker ...) with our interpreter."""
    return subprocess.run([sys.executable, "-S", "-m", "rtfgu_checker"] + list(args), cwd=release,
                          env=_env(release), capture_output=True, text=True, timeout=timeout)


def test_no_solution_line_is_anywhere_in_the_release(release):
    assert solution_lines_in(release, REVEALED) == []
    assert solution_lines_in(release / "rtfgu", ()) != []   # the revealed a01, a02 are there


def test_no_twin_no_hidden_probe_no_hidden_reference_and_no_solving_hint_in_the_release(release):
    names = {p.relative_to(release).as_posix() for p in release.rglob("*") if p.is_file()}
    assert not [n for n in names if n.startswith(("rtfgu/kernels/", "rtfgu/hardcases/", "rtfgu/grading/"))]
    assert "rtfgu/robust.py" not in names
    assert not [n for n in names if "hidden" in n or "mistakes" in n or "sandbox" in n or "grader" in n]
    checker = release / "rtfgu_checker"
    code = "\n".join(p.read_text() for p in checker.rglob("*.py"))
    assert not re.search(r"^\s*# ### BEGIN HIDDEN\s*$", code, re.M) and 'visibility="hidden"' not in code
    hints = "\n".join(p.read_text() for p in (checker / "checks").glob("*.py"))
    assert "b * b" not in hints and "math.sqrt" not in hints   # no quadratic, no root in any hint
    for a in ASSIGNMENTS.values():
        hidden = [c for c in checks_for(a.id) if c.visibility != "visible"]
        visible = [c for c in checks_for(a.id) if c.visibility == "visible"]
        folder = checker / "reference" / a.id
        stored = json.loads((folder / "observations.json").read_text())
        assert set(stored) == {c.slug for c in visible if c.kind in ("cases", "statistic")}
        for c in hidden:
            assert not (folder / (c.slug + ".png")).exists()
            assert c.name not in code
            if (folder / "known.json").exists():
                assert c.slug not in (folder / "known.json").read_text()
    for n in ("Makefile", "README.md", "setup.cfg", "pyproject.toml", "assignments/a03_intersections/README.md",
              "tests/test_visible.py"):
        assert n in names, n
    setup = (release / "setup.cfg").read_text()
    assert "pytest" in setup and "mpmath" not in setup and "numba" not in setup   # numba: its path is left out
    # Every other runtime dependency and data file of the staff package (textures' images, meshes).
    import configparser
    staff = configparser.ConfigParser()
    staff.read(Path(__file__).resolve().parent.parent / "setup.cfg")
    for requirement in staff["options"]["install_requires"].split():
        assert requirement.startswith("numba") or requirement in setup, requirement
    assert staff["options.package_data"]["rtfgu"].strip() in setup
    makefile = (release / "Makefile").read_text()
    for target in ("check:", "render:", "test:"):
        assert target in makefile


def test_make_check_fails_on_the_stubs_and_passes_once_a_solution_is_written(release, tmp_path):
    done = _run(release, "check", "a03")
    assert done.returncode == 1, done.stdout + done.stderr
    assert "this part is not written yet" in done.stdout
    assert "hidden" not in done.stdout.lower()
    write_files(solution_files("a03"), release / "rtfgu")
    done = _run(release, "check", "a03")
    assert done.returncode == 0, done.stdout + done.stderr
    visible = sum(c.weight for c in checks_for("a03") if c.visibility == "visible")
    assert "total %g / %g" % (visible, visible) in done.stdout
    diffs = release / "check-results" / "a03" / "diffs"
    assert sorted(p.name for p in diffs.iterdir()) == sorted(
        c.slug + ".png" for c in checks_for("a03") if c.kind == "image" and c.visibility == "visible")
    assert str(diffs) in done.stdout or "check-results/a03/diffs" in done.stdout


def test_the_release_checker_gives_the_a_is_one_hint(release):
    spec = describe("a03_sphere_a_is_one")
    write_files(apply_replacements(solution_files("a03"), spec["REPLACE"], "a03_sphere_a_is_one"),
                release / "rtfgu")
    try:
        done = _run(release, "check", "a03")
        assert done.returncode == 1
        assert "as if a = d . d were 1" in done.stdout, done.stdout
    finally:
        write_files(solution_files("a03"), release / "rtfgu")


def test_make_render_says_when_there_is_nothing_to_render_and_fails_when_a_render_fails(release, tmp_path):
    done = _run(release, "render", "a01")
    assert done.returncode == 0 and "has no images to render" in done.stdout
    own = tmp_path / "release"          # a04's scene meets a03's shapes first: a copy with a03 solved
    shutil.copytree(release, own)
    write_files(solution_files("a03"), own / "rtfgu")
    done = _run(own, "render", "a04", "--width", "8", "--height", "8")
    assert done.returncode == 1
    assert "the render failed" in done.stdout and "a04: " in done.stdout and "failed to render" in done.stdout


def test_debug_pixel_compares_the_students_code_with_the_expected_values_at_the_failing_pixel(release, tmp_path):
    """A failing image test names `make debug-pixel A T X Y`; it traces that pixel through the
    student's code beside the solution's bounces, which the release holds for every pixel of
    every visible image test (and for no hidden one), and marks the first difference."""
    own = tmp_path / "release"
    shutil.copytree(release, own)
    spec = describe("a03_triangle_gamma_sign")
    write_files(apply_replacements(solution_files("a03"), spec["REPLACE"], "a03_triangle_gamma_sign"), own / "rtfgu")
    done = _run(own, "check", "a03")
    found = re.search(r"`make debug-pixel A=a03 T=(3\.8) X=(\d+) Y=(\d+)`", done.stdout)
    assert done.returncode == 1 and found, done.stdout
    test, x, y = found.groups()
    done = _run(own, "debug-pixel", "a03", test, x, y)
    assert done.returncode == 1, done.stdout + done.stderr
    assert "pixel (%s, %s) of the 48x48 test image" % (x, y) in done.stdout
    first = [line for line in done.stdout.splitlines() if "<< first" in line]
    assert len(first) == 1 and first[0].startswith("0 shape"), done.stdout
    assert re.search(r"^0 kind\s+triangle\s+\w+ !$", done.stdout, re.M), done.stdout
    write_files(solution_files("a03"), own / "rtfgu")
    done = _run(own, "debug-pixel", "a03", "8", x, y)        # the test's number within a03 will do
    assert done.returncode == 0 and "agrees with expected" in done.stdout, done.stdout + done.stderr
    # Where the student has no code yet, and what an image test is not.
    write_files(student_files("a03"), own / "rtfgu")
    done = _run(own, "debug-pixel", "a03", "3.8", x, y)
    assert done.returncode == 2 and "not written yet" in done.stderr
    done = _run(release, "debug-pixel", "a03", "3.2", "0", "0")
    assert done.returncode == 2 and "is not an image test" in done.stderr
    done = _run(release, "debug-pixel", "a03", "3.8", "48", "0")
    assert done.returncode == 2 and "X must be in [0, 48)" in done.stderr
    assert "debug-pixel:" in (release / "Makefile").read_text()
    assert "make debug-pixel A=a03 T=3.8 X=16 Y=32" in (release / "README.md").read_text()
    for a in ASSIGNMENTS.values():
        stored = {p.name for p in (release / "rtfgu_checker" / "reference" / a.id).glob("*.pixels.npz")}
        assert stored == {c.slug + ".pixels.npz" for c in checks_for(a.id)
                          if traces_a_scene(c) and c.visibility == "visible"}, a.id


def test_the_release_checker_names_where_an_endless_loop_is_and_waits_for_it_once(release, tmp_path):
    own = tmp_path / "release"
    shutil.copytree(release, own)
    spec = describe("a03_infinite_loop")
    write_files(apply_replacements(solution_files("a03"), spec["REPLACE"], "a03_infinite_loop"), own / "rtfgu")
    done = _run(own, "check", "a03", "--time-limit", "2")
    assert done.returncode == 1
    assert re.search(r"time limit of 2 s: your code did not finish; your code was at rtfgu/shapes/triangle.py, "
                     r"line \d+, in normal_at", done.stdout), done.stdout
    summary = (own / "check-results" / "a03" / "summary.txt").read_text()
    assert "Triangle.normal_at was not run: it did not finish in test 3.6" in summary, summary
    assert summary.count("time limit of 2 s") == 1, summary


def test_make_render_compares_with_the_full_size_reference_the_release_holds(release, tmp_path):
    own = tmp_path / "release"
    shutil.copytree(release, own)
    spec = describe("a03_triangle_gamma_sign")
    write_files(apply_replacements(solution_files("a03"), spec["REPLACE"], "a03_triangle_gamma_sign"), own / "rtfgu")
    done = _run(own, "render", "a03")
    assert done.returncode == 0, done.stdout + done.stderr
    assert "lecture01_flat_colors.png: the same as the reference" in done.stdout      # no triangle in it
    found = re.search(r"default_flat_colors.png: (\d+) pixels differ from the reference; default_flat_colors_diff.png",
                      done.stdout)
    assert found and int(found.group(1)) > 1000, done.stdout
    from PIL import Image
    assert Image.open(own / "renders" / "a03" / "default_flat_colors_diff.png").size == (3 * 512 + 4, 512)
    done = _run(own, "render", "a03", "--width", "32", "--height", "32")
    assert "the reference is 512x512 (`make render A=a03` without W and H compares with it)" in done.stdout
    write_files(solution_files("a03"), own / "rtfgu")
    done = _run(own, "render", "a03")
    assert done.stdout.count("the same as the reference") == 2, done.stdout
    for a in ASSIGNMENTS.values():
        held = sorted(p.stem for p in (release / "rtfgu_checker" / "reference" / a.id / "full_size").glob("*.png"))
        assert held == sorted(a.images), a.id


def test_rtfgu_show_in_a_release_renders_with_the_lecture_layer_and_says_where_the_image_is(release, tmp_path):
    own = tmp_path / "release"
    shutil.copytree(release, own)
    write_files(solution_files("a05"), own / "rtfgu")          # a05's scene meets a03-a05's functions
    write_files(solution_files("a04"), own / "rtfgu")
    write_files(solution_files("a03"), own / "rtfgu")
    done = subprocess.run([sys.executable, "-S", "-c", "import rtfgu\nfrom rtfgu.scenes import get_scene\n"
                           "rtfgu.show(get_scene('default_phong_sphere')(), 12, 8)"],
                          cwd=own, env=_env(own), capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert "rtfgu.show: wrote rtfgu_show.png (12x8, 1 sample, reference backend" in done.stdout, done.stdout
    assert (own / "rtfgu_show.png").is_file()
    notebook = json.loads((release / "notebooks" / "first_render.ipynb").read_text())
    assert notebook["cells"] and all(not c.get("outputs") for c in notebook["cells"] if c["cell_type"] == "code")
    assert "notebook =" in (release / "setup.cfg").read_text() and "jupyter lab" in (release / "README.md").read_text()


def test_make_html_in_a_release_shows_the_students_own_wgsl_in_the_browser(release, tmp_path):
    """`make html A=a06` writes a WebGPU page from the student's intersect_*.wgsl: in headless
    Chromium the solution's page shows the reference image, a planted sphere bug a wrong one."""
    from rtfgu.browser import headless
    from rtfgu.grading.checks.images import image_differences

    try:
        headless.find_chromium()
    except headless.BrowserNotFound as error:
        pytest.skip(str(error))
    pages, wrong = {}, [("wgsl/intersect_sphere.wgsl", "let disc = b * b - 4.0 * a * c;",
                         "let disc = b * b + 4.0 * a * c;")]
    for label, files in (("solution", solution_files("a06")),
                         ("planted", apply_replacements(solution_files("a06"), wrong, "a06_disc_plus"))):
        own = tmp_path / label
        shutil.copytree(release, own)
        write_files(files, own / "rtfgu")
        done = _run(own, "html", "a06", "--width", "32", "--height", "32")   # the image test's size
        assert done.returncode == 0, done.stdout + done.stderr
        pages[label] = (own / "html" / "a06" / "default_flat_colors.html").read_text()
    assert "b * b + 4.0 * a * c" in pages["planted"] and "b * b + 4.0 * a * c" not in pages["solution"]
    results = headless.render_pages(pages, timeout=120)
    (test,) = [c for c in checks_for("a06") if c.kind == "image"]
    reference = np.asarray(Image.open(PACKAGE_DIR / "grading" / "reference" / test.assignment /
                                      (test.slug + ".png")).convert("RGB"))
    counts = {}
    for label in pages:
        _, canvas = headless.result_images(results[label])
        counts[label] = int((np.maximum(*image_differences(canvas, reference)) > 8).sum())
    assert counts["solution"] == 0 and counts["planted"] > 20, counts


def test_make_release_names_the_visible_tests_students_cannot_pass_with_the_assignments_own_code():
    """Found by running them in the release: a09's furnace and Cornell box render with a03's
    shapes and a04's (and a05's) materials; in a release revealing nothing, a06's image needs
    a WGSL camera that the release carries once a02 is revealed."""
    from rtfgu.grading.release_gaps import release_gaps, report

    gaps = {g.test: g for g in release_gaps(("a01", "a02"), ["a09"])}
    assert gaps["9.4"].needs == ["a03", "a04"] and gaps["9.5"].needs == ["a03", "a04", "a05"]
    assert "9.1" not in gaps and "9.6" not in gaps                 # the map alone: a09's own code
    assert all(not g.left_out and not g.failure for g in gaps.values())
    lines = report(list(gaps.values()))
    visible = [c for c in checks_for("a09") if c.visibility == "visible"]
    assert lines[0].startswith("warning: a09: %d of its %d visible tests (%g of %g points) cannot pass" % (
        len(gaps), len(visible), sum(g.points for g in gaps.values()), sum(c.weight for c in visible)))
    assert "  9.5 (3 points): runs a03, a04, a05" in lines
    (gap,) = release_gaps((), ["a06"])
    assert gap.test == "6.4" and gap.left_out == [("wgsl/camera_pinhole.wgsl", ["a02"])], gap
    assert "left out of this release until a02 is revealed" in gap.describe()


def test_make_render_and_make_check_without_an_assignment_say_what_they_need(release):
    for command in ("render", "check"):
        done = _run(release, command)
        assert done.returncode == 2
        assert "make %s needs an assignment: make %s A=a03" % (command, command) in done.stderr
        assert "a01" in done.stderr and "a09" in done.stderr and "usage:" not in done.stderr


def test_every_release_readme_names_the_files_the_student_edits_where_they_are(release):
    # In a release the student edits rtfgu/<file> in place; assignments/<id>/ holds only the README.
    readmes = [release / "assignments" / "README.md"] + sorted((release / "assignments").glob("*/README.md"))
    assert len(readmes) == len(ASSIGNMENTS) + 1
    for readme in readmes:
        text = readme.read_text()
        assert "on your files in assignments/" not in text, readme
        for path, later in re.findall(r"`(rtfgu/[\w/]+\.(?:py|wgsl))`( \(not in this copy yet: it comes with "
                                      r"the release that reveals a\d\d)?", text):
            assert (release / path).is_file() != bool(later), (readme, path)
    a03 = (release / "assignments" / "a03_intersections" / "README.md").read_text()
    assert "`rtfgu/shapes/sphere.py`" in a03 and "on your files in rtfgu/" in a03
    assert sorted(p.name for p in (release / "assignments" / "a03_intersections").iterdir()) == ["README.md"]


def _data_folders_outside_the_packages(root: Path) -> list:
    """The folders holding package data that the setup.cfg of ``root`` does not list as
    packages: setuptools warns about each (about 40 lines apiece), burying a first `make`."""
    import configparser

    import setuptools

    config = configparser.ConfigParser()
    config.read(root / "setup.cfg")
    find = {"find:": setuptools.find_packages, "find_namespace:": setuptools.find_namespace_packages}
    include = [name.strip() for name in config["options.packages.find"]["include"].split(",")]
    packages = set(find[config["options"]["packages"].strip()](where=str(root), include=include))
    outside = set()
    for package, patterns in config["options.package_data"].items():
        for pattern in patterns.split(","):
            for path in (root / package.replace(".", "/")).glob(pattern.strip()):
                outside.add(".".join(path.parent.relative_to(root).parts))
    return sorted(outside - packages)


def test_the_first_make_is_quiet_no_data_folder_outside_the_packages_and_pip_in_a_log(release):
    assert _data_folders_outside_the_packages(release) == []
    assert _data_folders_outside_the_packages(PACKAGE_DIR.parent) == []
    for makefile in (release / "Makefile", PACKAGE_DIR.parent / "Makefile"):
        text = makefile.read_text()
        assert "> $(VENV)/install.log 2>&1 || { cat $(VENV)/install.log; exit 1; }" in text, makefile
        # make render A=a03 W=48 H=48: the size of the image tests, whose messages name its pixels
        assert "render $(A) $(if $(W),--width $(W)) $(if $(H),--height $(H))" in text, makefile


def test_running_a_student_file_directly_says_how_to_run_it(release):
    # a04's and a01's files: the a03 tests above replace the a03 files with the solution
    done = subprocess.run([sys.executable, "rtfgu/lights/point_light.py"], cwd=release, capture_output=True,
                          text=True, timeout=60)
    assert done.returncode != 0
    assert "make check A=a04" in done.stderr and "make render A=a04" in done.stderr
    assert "relative import" not in done.stderr
    done = subprocess.run([sys.executable, "rtfgu/float3.py"], cwd=release, capture_output=True,
                          text=True, timeout=60)
    assert "make check A=a01" in done.stderr and "render" not in done.stderr   # a01 has no images


def test_make_test_runs_the_visible_tests_of_one_assignment_on_the_students_code(release):
    assert "-m pytest $(if $(A),-k $(A))" in (release / "Makefile").read_text()
    done = subprocess.run([sys.executable, "-S", "-m", "pytest", "-q", "-p", "no:cacheprovider", "-k", "a01"],
                          cwd=release, env=_env(release), capture_output=True, text=True, timeout=300)
    visible = [c for c in checks_for("a01") if c.visibility == "visible"]
    assert done.returncode == 0 and "%d passed" % len(visible) in done.stdout, done.stdout + done.stderr


def test_the_release_renders_with_the_reference_and_says_the_other_paths_are_not_in_it(release):
    script = ("import rtfgu\nfrom rtfgu.scenes import SCENES\n"
              "for backend in ('numba', 'wgpu'):\n"
              "    try:\n        rtfgu.render(SCENES['default_lambertian'](), 4, 4, backend=backend)\n"
              "    except Exception as e:\n        print(backend, e)\n"
              "print(rtfgu.render(SCENES['default_ray_directions'](), 4, 4).shape)\n")
    done = subprocess.run([sys.executable, "-S", "-c", script], cwd=release, capture_output=True, text=True,
                          timeout=120, env=_env(release))
    assert done.stdout.count("not part of this release") == 2, done.stdout + done.stderr
    assert "(4, 4, 3)" in done.stdout
