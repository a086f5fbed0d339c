"""The student tree: generated from the marked solutions, committed exactly as generated."""
from __future__ import annotations

import ast
from pathlib import Path

import pytest

from rtfgu.grading.assignments import ASSIGNMENTS, block_table, get_assignment
from rtfgu.grading.generate import (PACKAGE_DIR, check_markers, compare_tree, find_blocks, solution_files,
                                    source_text, student_files, transform)

ROOT = Path(__file__).resolve().parent.parent
PYTHON_IDS = [a.id for a in ASSIGNMENTS.values() if a.language == "python"]


def test_committed_assignments_are_exactly_what_the_generator_writes():
    problems = compare_tree(ROOT / "assignments")
    assert problems == [], "run `make assignments`:\n" + "\n".join(problems)


def test_every_block_is_marked_once_and_belongs_to_one_assignment():
    check_markers()
    assert len(ASSIGNMENTS) >= 6 or len(PYTHON_IDS) >= 5
    ids = list(ASSIGNMENTS)
    assert ids == sorted(ids)  # the course order a01, a02, ...
    for a in ASSIGNMENTS.values():
        assert a.blocks, a.id


@pytest.mark.parametrize("aid", PYTHON_IDS)
def test_stubs_raise_not_implemented_at_the_block_indentation(aid):
    a = get_assignment(aid)
    files = student_files(a)
    for block in a.blocks:
        text = files[block.file]
        tag = "%s: %s" % (a.short, block.qualname)
        line = next(l for l in text.split("\n") if "NotImplementedError(%r)" % tag in l)
        # The stub sits where the solution's first line sat, at the same indentation.
        src = source_text(block.file)
        begin = next(b for q, b, e, ind in find_blocks(src, block.file) if q == block.qualname)
        indent = src.split("\n")[begin][: len(src.split("\n")[begin]) - len(src.split("\n")[begin].lstrip())]
        assert line == indent + "raise NotImplementedError(%r)" % tag
        assert "# TODO " + tag in text
        assert "BEGIN SOLUTION" not in text
        ast.parse(text)  # a stub file is valid Python


@pytest.mark.parametrize("aid", PYTHON_IDS)
def test_solution_files_are_the_source_without_the_marker_lines(aid):
    for relpath, text in solution_files(aid).items():
        src = source_text(relpath)
        kept = [l for l in src.split("\n") if "### BEGIN SOLUTION" not in l and "### END SOLUTION" not in l]
        assert text == "\n".join(kept)


def test_later_assignments_are_stubbed_and_earlier_ones_kept_in_a_shared_file():
    a04 = student_files("a04")["brdfs/lambertian.py"]
    a09 = student_files("a09")["brdfs/lambertian.py"]
    assert "NotImplementedError('a04: Lambertian.f')" in a04
    assert "NotImplementedError('a09: Lambertian.sample_f')" in a04     # not yet released in a04
    assert "NotImplementedError('a04: Lambertian.f')" not in a09        # a04's solution is released by a09
    assert "NotImplementedError('a09: Lambertian.sample_f')" in a09


def test_transform_keeps_nested_indentation_and_rejects_unknown_blocks():
    text = ("class Sphere:\n    def intersect_p(self, ray):\n        if True:\n            ### BEGIN SOLUTION\n"
            "            return 1\n            ### END SOLUTION\n")
    out = transform(text, "shapes/sphere.py", 3)
    assert "            raise NotImplementedError('a03: Sphere.intersect_p')" in out.split("\n")
    with pytest.raises(ValueError, match="belongs to no assignment"):
        transform(text.replace("intersect_p", "bounce"), "shapes/sphere.py", 3)
    with pytest.raises(ValueError, match="without END"):
        find_blocks("def f():\n    ### BEGIN SOLUTION\n    return 1\n", "x.py")


def test_readmes_name_the_task_formulas_slides_and_images():
    for a in ASSIGNMENTS.values():
        readme = (ROOT / "assignments" / a.id / "README.md").read_text()
        for heading in ("## Task", "## Formulas", "## Slides", "## Hand in", "make check A=%s" % a.short):
            assert heading in readme, (a.id, heading)
        for image in a.images:
            assert image + ".png" in readme
    assert "discriminant" in (ROOT / "assignments/a03_intersections/README.md").read_text()


def test_block_table_covers_the_lecture_layer_files():
    files = {key[0] for key in block_table()}
    for f in ("float3.py", "ray.py", "cameras/orthographic.py", "cameras/pinhole.py", "shapes/plane.py",
              "shapes/sphere.py", "shapes/triangle.py", "lights/point_light.py", "lights/light.py",
              "brdfs/lambertian.py", "brdfs/glossy_specular.py", "brdfs/perfect_specular.py",
              "btdfs/perfect_transmitter.py", "materials/matte.py", "materials/reflective.py",
              "textures/image_texture.py", "accelerators/bbox.py", "accelerators/bvh.py", "sampling/maps.py"):
        assert f in files
        assert (PACKAGE_DIR / f).is_file()


def test_wgsl_stubs_name_their_todo_and_keep_the_signature():
    files = student_files("a06")
    for name in ("intersect_plane", "intersect_sphere", "intersect_triangle"):
        text = files["wgsl/%s.wgsl" % name]
        assert "return TODO_a06_%s;" % name in text
        assert "fn %s(r: Ray, hit: ptr<function, HitInfo>" % name in text
        assert "BEGIN SOLUTION" not in text


def test_a08_stubs_the_slab_test_and_the_traversal_and_keeps_the_build():
    files = student_files("a08")
    bvh, bbox = files["accelerators/bvh.py"], files["accelerators/bbox.py"]
    for name in ("def _build", "def _best_split", "def _median_split", "def leaves", "LEAF_SIZE = 4"):
        assert name in bvh, name
    assert "raise NotImplementedError('a08: BVH.intersect')" in bvh and "stack.append(near)" not in bvh
    assert "raise NotImplementedError('a08: BBox.hit')" in bbox and "\n            t_far *= WIDEN\n" not in bbox
    for name in ("def of_points", "def union", "def surface_area", "WIDEN = ", "def padded"):
        assert name in bbox, name
    # the solution's lines are those of the lecture layer, without the markers
    assert "\n            t_far *= WIDEN\n" in solution_files("a08")["accelerators/bbox.py"]
