"""The autograder: full marks for the solution, zero for the stubs, planted bugs caught by
the tests meant to catch them, untrusted code contained, and the output formats."""
from __future__ import annotations

import csv
import json
import math
import os
import shutil
import stat
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pytest

from rtfgu.grading.assignments import ASSIGNMENTS, get_assignment
from rtfgu.grading.generate import solution_files, student_files, write_files
from rtfgu.grading.checks import checks_for
from rtfgu.grading.checks.images import image_differences, judge_image
from rtfgu.grading.grader import REFERENCE_DIR, grade, neighbourhood_difference
from rtfgu.grading.results import validate_gradescope

from planted import apply_replacements, describe, make_submission, planted_names

ROOT = Path(__file__).resolve().parent.parent
PYTHON_IDS = [a.id for a in ASSIGNMENTS.values() if a.language == "python"]
LIMIT = 5.0


def _by_number(result):
    return {t.number: t for t in result.tests}


@pytest.fixture(scope="module")
def solved(tmp_path_factory):
    """aid -> (folder of solved files, result of grading them)."""
    out = {}
    for aid in PYTHON_IDS:
        folder = tmp_path_factory.mktemp("solution_" + aid)
        write_files(solution_files(aid), folder)
        results = tmp_path_factory.mktemp("results_" + aid)
        out[aid] = (folder, results, grade(aid, folder, results, time_limit=LIMIT))
    return out


@pytest.mark.parametrize("aid", PYTHON_IDS)
def test_the_solution_scores_full_marks(solved, aid):
    _, _, result = solved[aid]
    failed = [(t.name, t.output) for t in result.tests if t.status != "passed"]
    assert failed == []
    assert result.score == result.max_score > 0
    assert any(t.visibility == "hidden" for t in result.tests)
    assert any(t.visibility == "visible" for t in result.tests)


@pytest.mark.parametrize("aid", PYTHON_IDS)
def test_fresh_stubs_score_zero_and_the_grader_finishes(tmp_path, aid):
    write_files(student_files(aid), tmp_path / "stubs")
    result = grade(aid, tmp_path / "stubs", tmp_path / "out", time_limit=LIMIT)
    assert len(result.tests) == len(_by_number(result)) > 0
    assert result.score == 0
    assert all("not written yet" in t.output or "NotImplementedError" in t.output for t in result.tests)
    validate_gradescope(json.loads((tmp_path / "out" / "results.json").read_text()))


# submission, assignment, {test number: words the message must contain}; every other test keeps its points
PLANTED = [
    ("a03_discriminant_sign", "a03", {"3.2": "b^2 - 4ac", "3.3": "discriminant", "3.4": "discriminant",
                                      "3.7": "pixels", "3.8": "pixels", "3.9": "closest shape should be",
                                      "3.10": "discriminant"}),
    ("a03_missing_tmin", "a03", {"3.4": "less than ray.tmin"}),
    ("a03_unnormalised_normal", "a03", {"3.6": "unit vector"}),
    ("a03_sphere_a_is_one", "a03", {"3.2": "as if a = d . d were 1", "3.9": "should be",
                                    "3.10": "as if a = d . d were 1"}),
    ("a03_triangle_parallel_hits", "a03", {"3.5": "in its plane, parallel to it"}),
    ("a03_triangle_open_edges", "a03", {"3.5": "the edge v1 v2 left out (beta + gamma < 1) gives that here"}),
    # The classic barycentric slips: the hint names them with the exact beta and gamma; the diff
    # image counts the triangle missing where the reference has it.
    ("a03_triangle_gamma_sign", "a03", {"3.5": "a flipped sign of gamma, a flipped sign of beta or e0 and e1 "
                                               "swapped gives that here",
                                        "3.8": "35 unlike every reference pixel near them, 22 more are details",
                                        "3.9": "closest shape should be"}),
    ("a03_triangle_swapped_edges", "a03", {"3.5": "(beta = 0.333333, gamma = 0.333333",
                                           "3.8": "30 unlike every reference pixel near them, 28 more are details",
                                           "3.9": "closest shape should be"}),
    ("a03_triangle_closed_tmax", "a03", {"3.5": "t = tmax = 3"}),
    ("a02_half_pixel_offset", "a02", {"2.1": "half-pixel offset", "2.3": "pixels", "2.5": "half-pixel offset"}),
    ("a04_missing_cosine", "a04", {"4.2": "cosine term", "4.4": "pixels", "4.5": "should be"}),
    ("a05_shadow_acne", "a05", {"5.2": "shadow acne", "5.6": "pixels"}),
    ("a07_no_half_texel_shift", "a07", {"7.4": "half-texel shift", "7.5": "half-texel shift",
                                        "7.6": "half-texel shift", "7.8": "pixels", "7.9": "half-texel shift",
                                        "7.10": "half-texel shift", "7.12": "pixels"}),
    ("a07_clamp_wraps", "a07", {"7.2": "opposite edge", "7.6": "opposite edge", "7.8": "pixels",
                                "7.10": "opposite edge", "7.11": "pixels"}),
    ("a07_v_not_flipped", "a07", {"7.3": "upside down", "7.4": "upside down", "7.5": "upside down",
                                  "7.6": "upside down", "7.7": "pixels", "7.8": "pixels", "7.9": "upside down",
                                  "7.10": "upside down", "7.11": "pixels", "7.12": "pixels"}),
    ("a08_slab_no_swap", "a08", {"8.2": "swap t_near and t_far", "8.3": "swap t_near and t_far",
                                 "8.4": "swap t_near and t_far", "8.5": "BBox.hit", "8.6": "found nothing",
                                 "8.7": "BBox.hit", "8.8": "BBox.hit", "8.9": "swap t_near and t_far",
                                 "8.10": "swap t_near and t_far", "8.11": "BBox.hit", "8.12": "BBox.hit"}),
    ("a08_slab_ignores_tmax", "a08", {"8.3": "start with t1 = ray.tmax"}),
    ("a08_first_hit_found", "a08", {"8.7": "stopped at the first hit found", "8.8": "earlier one",
                                    "8.11": "first hit found"}),
    ("a08_no_tie_rule", "a08", {"8.8": "math.nextafter", "8.11": "math.nextafter"}),
    ("a08_box_no_inside", "a08", {"8.14": "this ray starts inside the box"}),
    ("a09_pdf_mismatch", "a09", {"9.3": "(n . w_i) / pi for cosine-weighted", "9.4": "biased", "9.5": "biased",
                                 "9.7": "pdf must be their density (n . w_i) / pi",
                                 "9.9": "(n . w_i) / pi for cosine-weighted"}),
    ("a09_exponent_off_by_one", "a09", {"9.1": "(1 - y)^(1 / (e + 1))", "9.2": "e = 10", "9.3": "g = cos",
                                        "9.6": "not where Suffern's map puts them",
                                        "9.7": "estimates the cell's solid angle", "9.9": "g = cos"}),
    ("a10_mj_not_shuffled", "a10", {"10.2": "in the canonical arrangement's order"}),
    ("a10_mj_y_like_x", "a10", {"10.1": "(jittered: one point per grid cell)", "10.2": "are not multi-jittered",
                                "10.6": "(jittered: one point per grid cell)"}),
    ("a10_mj_own_random", "a10", {"10.3": "made other points the second time"}),
    # The polar map is uniform on the disk too: only the values (and the hint) tell it apart.
    ("a10_concentric_polar", "a10", {"10.4": "this is the polar map", "10.7": "this is the polar map"}),
    ("a10_concentric_no_pi_over_4", "a10", {"10.4": "multiply it by pi / 4", "10.5": "not uniform on the disk",
                                            "10.7": "multiply it by pi / 4"}),
    ("a11_fresnel_summed", "a11", {"11.1": "reflects their mean", "11.3": "should be", "11.4": "pixels",
                                   "11.5": "reflects their mean", "11.6": "should be"}),
    ("a11_fresnel_schlick", "a11", {"11.1": "Schlick's approximation", "11.3": "should be", "11.4": "pixels",
                                    "11.5": "Schlick's approximation", "11.6": "should be"}),
    ("a11_bouguer_plus", "a11", {"11.2": "with the minus sign", "11.3": "should be", "11.4": "pixels",
                                 "11.6": "should be"}),
    ("a11_shade_no_tir", "a11", {"11.3": "only the reflected ray goes on", "11.6": "only the reflected ray goes on"}),
    ("a11_shade_weights_swapped", "a11", {"11.3": "should be", "11.4": "pixels", "11.6": "should be"}),
    ("a12_triangle_no_sqrt", "a12", {"12.1": "without the square root of u", "12.2": "not uniform by area",
                                     "12.3": "should be", "12.6": "pixels"}),
    ("a12_G_unsquared", "a12", {"12.4": "divides by the distance squared", "12.6": "pixels",
                                "12.8": "divides by the distance squared"}),
    # L G / pdf is computed in one expression (incident): a wrong pdf alone leaves the image.
    ("a12_pdf_area", "a12", {"12.4": "the density 1 / A", "12.8": "the density 1 / A"}),
    ("a12_incident_no_cosine", "a12", {"12.4": "should be", "12.6": "pixels", "12.8": "should be"}),
    ("a12_direction_to_corner", "a12", {"12.3": "should be", "12.6": "pixels"}),
    ("a12_tracer_shade", "a12", {"12.5": "should be"}),
    ("a13_vector_translated", "a13", {"13.1": "a direction (w = 0) does not move", "13.3": "should be",
                                      "13.4": "should be", "13.5": "pixels"}),
    ("a13_normal_no_transpose", "a13", {"13.1": "goes through its transpose", "13.4": "should be", "13.5": "pixels",
                                        "13.7": "should be"}),
    ("a13_compose_order", "a13", {"13.2": "the order of the products matters", "13.3": "should be",
                                  "13.5": "pixels", "13.6": "the order of the products matters",
                                  "13.7": "should be"}),
    ("a13_direction_normalized", "a13", {"13.3": "is normalised", "13.4": "should be", "13.5": "pixels",
                                         "13.7": "should be"}),
    ("a13_forward_ray", "a13", {"13.3": "should be", "13.4": "should be", "13.5": "pixels", "13.7": "should be"}),
    # Each passes every test but the contract's: the distributions and means are right.
    ("a09_own_rng", "a09", {"9.6": "gave another direction the second time"}),
    ("a09_tuned_pdf", "a09", {"9.7": "pdf must be their density (n . w_i) / pi"}),
    # Half the density, with NaN on a few samples: a NaN sum is beyond every limit, not within it.
    ("a09_nan_samples", "a09", {"9.3": "is not a finite number", "9.4": "are not finite numbers",
                                "9.5": "are not finite numbers", "9.7": "the sum of 1 / (N pdf) estimates",
                                "9.9": "is not a finite number"}),
]


@pytest.mark.parametrize("name,aid,caught", PLANTED, ids=[p[0] for p in PLANTED])
def test_planted_bugs_lose_the_tests_that_should_catch_them_and_keep_the_rest(tmp_path, name, aid, caught):
    result = grade(aid, make_submission(name, tmp_path / name), tmp_path / "out", time_limit=LIMIT)
    for number, test in _by_number(result).items():
        if number in caught:
            assert test.score < test.max_score, (number, test.name)
            assert caught[number] in test.output, (number, test.output)
        else:
            assert test.score == test.max_score, (number, test.name, test.output)
    # every image test wrote its diff image
    for test in result.tests:
        if test.name.startswith("image:"):
            assert Path(test.image).is_file()


def test_the_a08_planted_bugs_score_less_than_full_marks_and_the_solution_full_marks(solved, tmp_path):
    """The figures of a08 (18 points): every planted bug loses points, the solution none."""
    _, _, solution = solved["a08_bvh"]
    assert solution.score == solution.max_score == 18
    scores = {}
    for name in ("a08_slab_no_swap", "a08_slab_ignores_tmax", "a08_first_hit_found", "a08_no_tie_rule"):
        result = grade("a08", make_submission(name, tmp_path / name), None, time_limit=LIMIT)
        scores[name] = result.score
    assert all(0 < score < 18 for score in scores.values()), scores
    assert scores["a08_slab_no_swap"] < scores["a08_first_hit_found"] < scores["a08_slab_ignores_tmax"], scores


def test_a09_a_correct_but_noisy_sampler_scores_full_marks_and_is_told_it_is_noisier(tmp_path):
    """The uniform hemisphere with its own pdf is unbiased: the statistical tests pass it, and
    the image test reports its variance against the reference's (more than 1)."""
    result = grade("a09", make_submission("a09_uniform_hemisphere", tmp_path / "noisy"), None, time_limit=LIMIT)
    assert result.score == result.max_score, [(t.number, t.output) for t in result.tests if t.score < t.max_score]
    image = _by_number(result)["9.5"]
    ratio = float(image.output.split("its variance per sample is ")[1].split(" times")[0])
    assert ratio > 1.1 and "less noisy" in image.output


def test_a08_box_references_are_the_exact_slab_test():
    """Every stored answer of a08's box tests is that of exact arithmetic (the slab test in
    fractions, rtfgu.grading.mistakes.slab_exact): the same hit or miss and, for a hit, the
    entry t to within two ulps (exactly, where every number is a short multiple of a power of
    two). The rounding cases are real: without widening t_far the float test misses them."""
    from rtfgu.grading.checks import checks_for
    from rtfgu.grading.mistakes import _slab_float, slab_exact

    stored = json.loads((REFERENCE_DIR / "a08_bvh" / "observations.json").read_text())
    checked, exact_to_the_bit, rescued = 0, 0, 0
    for check in checks_for("a08"):
        if check.known != "slab":
            continue
        for case in stored[check.slug]["cases"]:
            i, t = case["in"], case["out"]["t"]
            args = (i["p0"], i["p1"], i["o"], i["d"], i["tmin"], i["tmax"])
            want = slab_exact(*args)
            if math.isinf(want):
                assert t == want, case["label"]
            else:
                assert abs(t - want) <= 2 * math.ulp(want), (case["label"], t, want)
            exact_to_the_bit += t == want
            rescued += math.isfinite(want) and math.isinf(_slab_float(*args, widen=False))
            checked += 1
    assert checked >= 55 and exact_to_the_bit >= checked - 3 and rescued >= 3
    # the exact test itself, on a face, an edge, a zero-thickness box and a -0 component
    assert slab_exact([0, 0, 0], [1, 1, 1], [-1, 0, 0.5], [1, 0, 0], 0, math.inf) == 1.0
    assert slab_exact([0, 0, 0], [1, 1, 1], [-1, -1, 0.5], [1, 1, 0], 0, math.inf) == 1.0
    assert slab_exact([0, 0, 0], [1, 1, 1], [-1, -1.5, 0.5], [1, 1, 0], 0, math.inf) == 1.5
    assert slab_exact([0, 0, 0], [1, 1, 1], [-1, -2.5, 0.5], [1, 1, 0], 0, math.inf) == math.inf
    assert slab_exact([0, 0, 1], [2, 2, 1], [1, 1, 3], [0, 0, -1], 0, math.inf) == 2.0
    assert slab_exact([0, 0, 0], [1, 1, 1], [-1, 0.5, 0.5], [1, -0.0, 0], 0, 0.5) == math.inf


def test_a08_bvh_references_are_the_exact_closest_hit():
    """Every stored answer of a08's BVH tests is the exact closest hit over the scene's shapes
    (each shape's test in rationals, rtfgu.hardcases.exact; the least t in [tmin, tmax), of
    equal ts the earlier shape), whatever order the BVH was put in. The ties are real."""
    from rtfgu.grading.checks import checks_for
    from rtfgu.grading.probes import a08, a08_hidden
    from rtfgu.hardcases import exact

    scenes = dict(a08.SCENES, **a08_hidden.SCENES)
    stored = json.loads((REFERENCE_DIR / "a08_bvh" / "observations.json").read_text())
    checked, hits, ties = 0, 0, 0
    for check in checks_for("a08"):
        if not check.probe[1].startswith("observe_bvh"):
            continue
        for case in stored[check.slug]["cases"]:
            i = case["in"]
            ray = (i["o"], i["d"], i["tmin"], i["tmax"])
            found = []
            for shape in scenes[i["scene"]]():
                if shape[0] == "sphere":
                    found.append(exact.sphere(*ray, shape[1], shape[2]))
                else:
                    found.append(exact.triangle(*ray, *shape[1:]))
            best = min(range(len(found)), key=lambda k: (found[k], k), default=-1)
            if best >= 0 and found[best] == exact.MISS:
                best = -1
            assert case["out"]["shape"] == best, case["label"]
            if best < 0:
                assert case["out"]["ray.tmax"] == i["tmax"], case["label"]
            else:
                t = found[best][0] + found[best][1]
                assert abs(case["out"]["ray.tmax"] - t) <= 1e-12 * abs(t), case["label"]
                hits += 1
                ties += found.count(found[best]) > 1
            checked += 1
    assert checked >= 240 and hits >= 120 and ties >= 30, (checked, hits, ties)


def test_every_planted_submission_is_the_solution_with_its_one_described_bug():
    names = planted_names()
    assert {p[0] for p in PLANTED} | {"a03_infinite_loop", "a03_misbehaving", "a03_writes_references",
                                      "a06_endless_loop", "a06_slow_loop", "a09_uniform_hemisphere"} == set(names)
    for name in names:
        spec = describe(name)
        assert spec["__doc__"] and "\n" not in spec["__doc__"].strip(), name   # says what the bug is, in a line
        solution = solution_files(spec["ASSIGNMENT"])
        planted = apply_replacements(solution, spec["REPLACE"], name)
        assert set(planted) == set(solution)
        assert sorted(f for f in solution if planted[f] != solution[f]) == sorted({r[0] for r in spec["REPLACE"]})


def test_a_planted_bug_whose_text_is_gone_from_the_solution_or_ambiguous_is_an_error():
    solution = solution_files("a03")
    with pytest.raises(ValueError, match="exactly once in the solution's shapes/sphere.py, found 0 times"):
        apply_replacements(solution, [("shapes/sphere.py", "disc = b * b - 4.0 * a * c", "disc = 0")], "x")
    with pytest.raises(ValueError, match="found 2 times"):
        apply_replacements(solution, [("shapes/sphere.py", "if t >= ray.tmin and t < ray.tmax:", "if True:")], "x")
    with pytest.raises(ValueError, match="shapes/cube.py, which is not a solution file"):
        apply_replacements(solution, [("shapes/cube.py", "a", "b")], "x")
    with pytest.raises(ValueError, match="no planted submission 'a03_nothing'"):
        describe("a03_nothing")


def test_an_endless_loop_costs_one_time_limit_names_its_place_and_the_other_tests_run(tmp_path):
    """Triangle.normal_at never returns: the normals test (3.6) and the default-scene image (3.8)
    call it. 3.6 waits out the limit and names the line of the loop (from the traceback dumped
    just before the limit); in 3.8 the stopped function fails at once, naming 3.6; the tests
    that never call it keep their points."""
    result = grade("a03", make_submission("a03_infinite_loop", tmp_path / "sub"), tmp_path / "out", time_limit=2.0)
    tests = _by_number(result)
    loop = solution_files("a03")["shapes/triangle.py"].split("\n").index("        return normalize(self.n)") + 1
    assert tests["3.6"].score == 0 and "time limit of 2 s" in tests["3.6"].output
    at = [n for n in (loop, loop + 1) if "rtfgu/shapes/triangle.py, line %d, in normal_at" % n in tests["3.6"].output]
    assert at, tests["3.6"].output                         # the loop's `while True:` or its `pass`
    assert tests["3.6"].cause == "time limit (2 s) at shapes/triangle.py:%d" % at[0]
    assert tests["3.8"].score == 0 and tests["3.8"].cause == "time limit in test 3.6"
    assert "Triangle.normal_at was not run: it did not finish in test 3.6" in tests["3.8"].output
    assert "time limit of 2 s" not in tests["3.8"].output      # it did not wait out a limit of its own
    for number in ("3.1", "3.2", "3.3", "3.4", "3.5", "3.7", "3.9", "3.10"):
        assert tests[number].score == tests[number].max_score, tests[number].output


def test_memory_printing_and_wrong_types_cost_only_their_tests(tmp_path):
    # Memory touched for the first time fills at some 160 MB/s on these virtual machines, so
    # the gigabyte the hoard reaches before its MemoryError took over 5 s once beside a busy
    # worker: the limit is four times the others', so that the test sees the MemoryError.
    result = grade("a03", make_submission("a03_misbehaving", tmp_path / "sub"), tmp_path / "out",
                   time_limit=4 * LIMIT, memory_mb=256)
    tests = _by_number(result)
    assert tests["3.1"].score == 0 and "MemoryError" in tests["3.1"].output          # 64 GB of bytearrays
    assert tests["3.5"].score == 0 and "printed" in tests["3.5"].output              # megabytes of printing
    assert tests["3.3"].score == 0 and "True or False" in tests["3.3"].output        # returns 0, not False
    assert tests["3.6"].score < 1 and "should be a Float3" in tests["3.6"].output    # returns a tuple
    assert tests["3.2"].score == tests["3.2"].max_score                              # the rest still counts


def test_a_submission_cannot_change_the_reference_files(tmp_path, monkeypatch):
    # With rlimits only (no sandbox) student code can reach the checkout: the grader notices
    # the change, restores the file and scores the submission 0. The references graded
    # against are a copy: the checkout's stay untouched for the tests beside this one (a
    # test in another worker that checks `git status` would see the file changed).
    from rtfgu.grading import grader, sandbox

    copy = tmp_path / "reference"
    shutil.copytree(REFERENCE_DIR / "a03_intersections", copy / "a03_intersections")
    monkeypatch.setattr(grader, "REFERENCE_DIR", copy)
    target = copy / "a03_intersections" / "observations.json"
    before = target.read_bytes()
    child_env = sandbox._child_env
    monkeypatch.setattr(sandbox, "_child_env", lambda *a: dict(child_env(*a), RTFGU_ATTACK_PATH=str(target)))
    monkeypatch.setenv("RTFGU_ISOLATION", "rlimits")
    result = grade("a03", make_submission("a03_writes_references", tmp_path / "sub"), tmp_path / "out",
                   time_limit=LIMIT)
    assert result.isolation == "rlimits only"
    assert target.read_bytes() == before
    assert result.score == 0
    assert any("reference files" in note for note in result.notes)


def test_results_json_has_gradescopes_fields_and_prairielearn_is_written_from_the_same_model(solved, tmp_path):
    folder, results, result = solved["a03_intersections"]
    data = json.loads((results / "results.json").read_text())
    validate_gradescope(data)
    assert data["score"] == result.score
    assert [t["number"] for t in data["tests"]] == [t.number for t in result.tests]
    assert (results / "summary.txt").read_text().startswith("a03_intersections: 17 / 17 points")
    assert len(list((results / "diffs").glob("*.png"))) == sum(t.name.startswith("image:") for t in result.tests)
    with pytest.raises(ValueError, match="tests\\[0\\].status"):
        bad = json.loads(json.dumps(data))
        bad["tests"][0]["status"] = "ok"
        validate_gradescope(bad)

    result.write(tmp_path / "pl", "prairielearn")
    pl = json.loads((tmp_path / "pl" / "results.json").read_text())
    assert pl["gradable"] is True and pl["score"] == 1.0
    assert [t["points"] for t in pl["tests"]] == [t.score for t in result.tests]
    assert any("images" in t for t in pl["tests"])


def test_visible_only_runs_the_visible_tests(solved, tmp_path):
    folder, _, full = solved["a02_cameras"]
    result = grade("a02", folder, None, visible_only=True, time_limit=LIMIT)
    assert [t.number for t in result.tests] == [t.number for t in full.tests if t.visibility == "visible"]


def test_submissions_as_a_zip_or_flat_files_are_found(solved, tmp_path):
    folder, _, _ = solved["a03_intersections"]
    archive = tmp_path / "upload.zip"
    with zipfile.ZipFile(archive, "w") as z:
        for path in folder.rglob("*.py"):
            z.write(path, "my-work/" + path.name)   # flattened, in a folder of the student's choosing
    assert grade("a03", archive, None, time_limit=LIMIT).score == 17
    partial = tmp_path / "partial"
    partial.mkdir()
    shutil.copy(folder / "shapes" / "sphere.py", partial / "sphere.py")
    result = grade("a03", partial, None, visible_only=True, time_limit=LIMIT)
    assert any("plane.py was not in your submission" in note for note in result.notes)
    assert _by_number(result)["3.2"].score == 2 and _by_number(result)["3.1"].score == 0


def test_grade_all_writes_one_gradebook_row_and_one_results_folder_per_submission(solved, tmp_path):
    klass = tmp_path / "class"
    shutil.copytree(solved["a04_diffuse"][0], klass / "alice")
    write_files(student_files("a04"), klass / "bob")
    make_submission("a04_missing_cosine", klass / "carol")
    from rtfgu.grading.gradebook import grade_all

    path = grade_all("a04", klass, tmp_path / "out", processes=2, time_limit=LIMIT)
    rows = list(csv.DictReader(open(path)))
    assert [r["student"] for r in rows] == ["alice", "bob", "carol"]
    scores = {r["student"]: float(r["score"]) for r in rows}
    assert scores["alice"] == 10 and scores["bob"] == 0 and 0 < scores["carol"] < 10
    for student in ("alice", "bob", "carol"):
        validate_gradescope(json.loads((tmp_path / "out" / student / "results.json").read_text()))


def test_gradescope_shows_a_visible_image_tests_diff_image_inline_with_the_students_output_escaped(tmp_path):
    # Gradescope shows only results.json: the diff image goes in as a data URI of an HTML
    # output, the message points to it, and what the student's code printed is text, not HTML.
    import base64
    import html

    files = dict(solution_files("a03"))
    head = "    def intersect_p(self, ray: Ray) -> bool:\n"
    assert head in files["shapes/sphere.py"]
    files["shapes/sphere.py"] = files["shapes/sphere.py"].replace(
        head, head + "        print('<img src=x onerror=alert(1)>')\n        return False\n", 1)
    write_files(files, tmp_path / "sub")
    slugs = ("07_image_lecture_01_scene_the_closest_hit_in_flat_c", "02_sphere_intersect_p_rays_that_hit")
    grade("a03", tmp_path / "sub", tmp_path / "out", only=slugs, time_limit=LIMIT)
    data = json.loads((tmp_path / "out" / "results.json").read_text())
    validate_gradescope(data)
    image_test, cases_test = sorted(data["tests"], key=lambda t: t["number"], reverse=True)
    assert image_test["status"] == "failed" and image_test["output_format"] == "html"
    diff = next((tmp_path / "out" / "diffs").glob("07_*.png")).read_bytes()
    assert 'src="data:image/png;base64,%s"' % base64.b64encode(diff).decode() in image_test["output"]
    assert "the diff image is below" in image_test["output"] and ".png" not in image_test["output"]
    # The pixel it names is one of the test image, and the message says how to render at its size.
    assert "of the 48x48 test image (`make render A=a03 W=48 H=48`" in image_test["output"]
    assert "<img src=x" not in image_test["output"]
    assert html.escape("<img src=x onerror=alert(1)>") in image_test["output"]
    assert "output_format" not in cases_test and "<img src=x onerror=alert(1)>" in cases_test["output"]
    # The local summary keeps the file's name, where the file is.
    assert "the diff image is 07_image" in (tmp_path / "out" / "summary.txt").read_text()


def _run_gradescope_bundle(assignment: str, submission: Path, root: Path, private: Path, **env) -> dict:
    """results.json of the Gradescope bundle of ``assignment`` run as Gradescope runs it: the
    zip (built into the folder ``private``) unpacked into ROOT/source, the upload copied to
    ROOT/submission, run_autograder with AUTOGRADER_ROOT=ROOT and ``env``. It must be a valid
    Gradescope result."""
    from rtfgu.grading.autograder import build_zip

    bundle = build_zip(get_assignment(assignment), private / ("autograder-%s.zip" % root.name))
    with zipfile.ZipFile(bundle) as z:
        assert {"setup.sh", "run_autograder"} <= set(z.namelist())
        z.extractall(root / "source")
    shutil.copytree(submission, root / "submission")
    env = {**os.environ, "AUTOGRADER_ROOT": str(root), "AUTOGRADER_PYTHON": sys.executable,
           "AUTOGRADER_TIME_LIMIT": "5", **env}
    subprocess.run(["bash", str(root / "source" / "run_autograder")], env=env, check=True, timeout=300,
                   capture_output=True)
    data = json.loads((root / "results" / "results.json").read_text())
    validate_gradescope(data)
    return data


def test_the_gradescope_bundle_runs_on_a_submission_in_a_grader_like_layout(solved, tmp_path):
    # 60 s a test: the honest solution must not lose a test to a machine the other pytest
    # worker loads (with 5 s a test it scored 0 of 16 in one clean-clone run).
    data = _run_gradescope_bundle("a05", solved["a05_shadows_phong_mirror_refraction"][0], tmp_path / "autograder",
                                  tmp_path, AUTOGRADER_TIME_LIMIT="60")
    assert data["score"] == 16, [(t.get("name"), t.get("output", "")[:120]) for t in data.get("tests", [])
                                 if t.get("score") != t.get("max_score")]


# Run at the import of shapes/sphere.py, in every test's interpreter, by a submission whose
# plane and triangle are solved and whose sphere is the stub (its honest part).
BUNDLE_ATTACKS = {
    "links": """
import os
for _name in set(os.listdir(".")) | {"output.txt", "stdout.txt", "stderr.txt"}:
    for _act in (os.unlink, lambda name: os.symlink(%(solved)r, name)):
        try:
            _act(_name)
        except OSError:
            pass
print("the output was replaced by links to the solved sphere")
""",
    "reads": """
for _path in (%(solved)r, %(references)r):
    try:
        _text = open(_path).read()
    except OSError as _error:
        print("reading %%s: %%s" %% (_path, type(_error).__name__))
    else:
        raise RuntimeError("LEAKED " + _text[:4000])
""",
}


def _strings(value) -> str:
    """Every string in a JSON value, one per line (results.json as a reader sees it)."""
    if isinstance(value, dict):
        return "\n".join(_strings(v) for v in value.values())
    if isinstance(value, list):
        return "\n".join(_strings(v) for v in value)
    return value if isinstance(value, str) else ""


def test_the_gradescope_bundle_as_root_without_bwrap_scores_the_honest_part_and_shows_no_solution(tmp_path):
    """Gradescope's case: run_autograder as root in a container where bubblewrap cannot make its
    namespaces, nor root its own (RTFGU_BWRAP=none, RTFGU_FALLBACK_NAMESPACES=0), the bundle's
    solved source world-readable in ROOT/source. A submission that replaces its output by links
    to the solved sphere, and one that reads the solved sphere and the references, score what
    the honest part scores, test by test, and results.json holds none of what they are after."""
    import tempfile

    if os.geteuid() != 0:
        pytest.skip("Gradescope runs the bundle as root; the grader's fallback (a sandbox user per grading) needs root")
    stub = student_files("a03")["shapes/sphere.py"]
    solved_only = [line.strip() for line in solution_files("a03")["shapes/sphere.py"].splitlines()
                   if len(line.strip()) > 12 and line not in stub.splitlines()]
    assert len(solved_only) >= 5
    shared = Path(tempfile.mkdtemp(prefix="rtfgu-gradescope-"))
    os.chmod(shared, 0o755)                       # /autograder: root's, open to every user
    try:
        results = {}
        for name in ("honest",) + tuple(BUNDLE_ATTACKS):
            root = shared / name
            paths = {"solved": str(root / "source" / "rtfgu" / "shapes" / "sphere.py"),
                     "references": str(root / "source" / "rtfgu" / "grading" / "reference" / "a03_intersections"
                                       / "observations.json")}
            files = dict(solution_files("a03"))
            files["shapes/sphere.py"] = stub + (BUNDLE_ATTACKS[name] % paths if name in BUNDLE_ATTACKS else "")
            write_files(files, tmp_path / name)
            results[name] = _run_gradescope_bundle("a03", tmp_path / name, root, tmp_path, RTFGU_BWRAP="none",
                                                   RTFGU_FALLBACK_NAMESPACES="0", RTFGU_ISOLATION="")
            assert os.stat(paths["solved"]).st_mode & 0o004        # readable to any user once grading is over
            needle = Path(paths["references"]).read_text()[40:120]
            text = _strings(results[name])
            assert results[name]["extra_data"]["isolation"] == "unprivileged user"
            assert "LEAKED" not in text and needle not in text
            assert [line for line in solved_only if line in text] == []
    finally:
        shutil.rmtree(shared)
    scores = {name: [(t["name"], t["score"]) for t in data["tests"]] for name, data in results.items()}
    assert 0 < results["honest"]["score"] < sum(t["max_score"] for t in results["honest"]["tests"])
    assert scores["links"] == scores["honest"] and scores["reads"] == scores["honest"]
    assert "replaced by links" in _strings(results["links"])
    assert _strings(results["reads"]).count("PermissionError") >= 2      # it tried, and was refused


def test_the_image_tolerance_forgives_a_one_pixel_silhouette_shift_but_not_a_colour_change():
    ref = np.zeros((16, 16, 3), np.uint8)
    ref[4:12, 4:12] = 200
    shifted = np.zeros_like(ref)
    shifted[5:13, 4:12] = 200
    assert neighbourhood_difference(shifted, ref).max() == 0
    darker = ref.copy()
    darker[4:12, 4:12] = 150
    assert (neighbourhood_difference(darker, ref) > 8).sum() >= 36   # the inside of the square


def test_a_thin_object_left_out_is_counted_missing_and_shown_in_blue(tmp_path):
    """One direction of the neighbourhood test excuses a one-pixel-wide line that is missing
    (each of its pixels has background next to it in the reference); the other does not."""
    ref = np.zeros((16, 16, 3), np.uint8)
    ref[2:14, 8] = 200                                   # a line one pixel wide
    mine = np.zeros_like(ref)
    assert neighbourhood_difference(mine, ref).max() == 0
    wrong, missing = image_differences(mine, ref)
    assert wrong.max() == 0 and (missing > 8).sum() == 12
    check = checks_for("a03")[7]
    assert check.kind == "image" and check.visibility == "visible"
    diff = tmp_path / "diff.png"
    fraction, lines, _ = judge_image(check, {"image": (mine / 255.0).tolist()}, ref, diff)
    assert fraction == 0.0 and "0 unlike every reference pixel near them, 12 more are details of the reference missing from yours" in lines[0]
    assert "make debug-pixel A=a03 T=3.8 X=8 Y=" in lines[-1]
    from PIL import Image
    strip = np.asarray(Image.open(diff).convert("RGB"))
    panel = strip[:, 2 * (16 * 4 + 2 * 4):]                # the third panel (4x enlarged, 2-pixel gaps)
    blue = (panel == (0, 96, 255)).all(axis=2)
    assert blue.sum() == 12 * 16 and not (panel == (255, 0, 0)).all(axis=2).any()


def test_cli_names_an_unknown_assignment(tmp_path):
    run = subprocess.run([sys.executable, "-m", "rtfgu.grading", "grade", "a99", str(tmp_path)],
                         capture_output=True, text=True, cwd=ROOT)
    assert run.returncode == 2 and "unknown assignment 'a99'" in run.stderr


def test_cli_solution_writes_the_solved_files(tmp_path):
    run = subprocess.run([sys.executable, "-m", "rtfgu.grading", "solution", "a03", str(tmp_path)],
                         capture_output=True, text=True, cwd=ROOT)
    assert run.returncode == 0
    assert sorted(p.relative_to(tmp_path).as_posix() for p in tmp_path.rglob("*.py")) == [
        "shapes/plane.py", "shapes/sphere.py", "shapes/triangle.py"]
    assert "NotImplementedError" not in (tmp_path / "shapes" / "sphere.py").read_text()


def _skip_without_a_webgpu_adapter():
    # The adapter is probed in a child process: the grader forks, and a GPU driver must not
    # be initialised in the process that forks.
    probe = subprocess.run([sys.executable, "-c", "import wgpu"], capture_output=True, text=True, cwd=ROOT)
    if probe.returncode != 0:
        pytest.skip("the WGSL assignment needs the Python package wgpu (pip install 'wgpu>=0.19'): "
                    + probe.stderr.strip().splitlines()[-1])
    probe = subprocess.run([sys.executable, "-c", "from rtfgu.wgsl.device import adapter_description as a; print(a())"],
                           capture_output=True, text=True, cwd=ROOT)
    if probe.returncode != 0:
        pytest.skip("no WebGPU adapter for the WGSL assignment (Mesa's llvmpipe: Debian packages libgl1-mesa-dri "
                    "libegl1 mesa-vulkan-drivers): " + probe.stderr.strip().splitlines()[-1])


def test_the_wgsl_assignment_gives_the_solution_full_marks_and_the_stubs_zero(tmp_path):
    _skip_without_a_webgpu_adapter()
    write_files(solution_files("a06"), tmp_path / "solution")
    solved = grade("a06", tmp_path / "solution", tmp_path / "out", time_limit=60)
    assert [t.output for t in solved.tests if t.status != "passed"] == []
    assert solved.score == solved.max_score > 0
    write_files(student_files("a06"), tmp_path / "stubs")
    stubs = grade("a06", tmp_path / "stubs", None, time_limit=60)
    assert stubs.score == 0
    assert all("TODO_a06_" in t.output for t in stubs.tests)


def test_a_wgsl_function_that_does_not_end_costs_only_the_tests_that_call_it(tmp_path):
    """intersect_sphere.wgsl running far past the time limit (a06_slow_loop), and starting with
    loop {} (a06_endless_loop): each grading ends, the plane and triangle tests keep their
    marks, and the sphere test and the image (which calls intersect_sphere) lose theirs. The
    slow one is stopped by the per-test limit (here 5 s instead of a06's 60). Mesa's software
    adapter ends every loop of a shader invocation after 65,535 steps in all, so loop {}
    returns there, with an undefined result (docs/grading_sandbox.md)."""
    import signal

    _skip_without_a_webgpu_adapter()

    def hung(signum, frame):
        raise TimeoutError("the grading of a06 did not end")
    previous = signal.signal(signal.SIGALRM, hung)
    signal.alarm(300)
    try:
        slow = _by_number(grade("a06", make_submission("a06_slow_loop", tmp_path / "slow"), None, time_limit=LIMIT))
        endless = _by_number(grade("a06", make_submission("a06_endless_loop", tmp_path / "endless"), None,
                                   time_limit=LIMIT))
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)
    for number in ("6.2", "6.4"):
        assert slow[number].score == 0
        assert "time limit of 5 s" in slow[number].output or "CPU time" in slow[number].output, slow[number].output
        assert endless[number].score < endless[number].max_score
    for tests in (slow, endless):
        for number in ("6.1", "6.3"):
            assert tests[number].score == tests[number].max_score, tests[number].output


def test_the_gradescope_setup_installs_bubblewrap_and_for_wgsl_mesas_software_adapter(tmp_path):
    from rtfgu.grading.autograder import MESA_PACKAGES, build_zip

    for name, wgsl in (("a03", False), ("a06", True)):
        with zipfile.ZipFile(build_zip(get_assignment(name), tmp_path / ("%s.zip" % name))) as z:
            setup = z.read("setup.sh").decode()
            run = z.read("run_autograder").decode()
        install = next(line for line in setup.splitlines() if line.startswith("apt-get install"))
        assert "bubblewrap" in install.split()
        assert all((package in install.split()) == wgsl for package in MESA_PACKAGES)
        assert "bubblewrap" in run


@pytest.mark.parametrize("forced, name", [("bwrap", "bwrap"), ("user", "unprivileged user"), ("rlimits", "rlimits only")])
def test_every_isolation_grades_the_solution_and_says_which_ran(forced, name, tmp_path, monkeypatch):
    from rtfgu.grading.sandbox import bwrap_works, find_bwrap

    if forced == "bwrap" and not bwrap_works(find_bwrap()):
        pytest.skip("bubblewrap is not installed or cannot run here (Debian package bubblewrap)")
    if forced == "user" and os.geteuid() != 0:
        pytest.skip("the unprivileged-user fallback needs the grader to run as root")
    monkeypatch.setenv("RTFGU_ISOLATION", forced)
    write_files(solution_files("a04"), tmp_path / "sub")
    checkout_mode = _checkout_mode_as_found()[0]
    result = grade("a04", tmp_path / "sub", tmp_path / "out", time_limit=LIMIT)
    assert result.score == result.max_score
    assert json.loads((tmp_path / "out" / "results.json").read_text())["extra_data"]["isolation"] == name
    assert "student code ran isolated by: %s" % name in (tmp_path / "out" / "summary.txt").read_text()
    # The fallback hides the checkout only while it grades: afterwards it has the mode it had,
    # or a grading of another test worker still holds it hidden and the state keeps that mode.
    mode, entry = _checkout_mode_as_found()
    assert mode == checkout_mode, entry
    assert entry is None or (entry["pids"] and os.getpid() not in entry["pids"]), entry


def _checkout_mode_as_found():
    """The checkout's own mode (the one recorded in the fallback's shared state while some
    grading holds it hidden), read under the state's lock so that no grading is between
    hiding and recording; with the state's entry, or None."""
    import fcntl
    from rtfgu.grading.sandbox import staff_folder, state_folder

    path = state_folder() / "hidden.json"
    if not path.parent.is_dir():
        return stat.S_IMODE(os.stat(ROOT).st_mode), None
    with os.fdopen(os.open(path, os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW, 0o600), "r+") as f:
        fcntl.flock(f, fcntl.LOCK_EX)
        f.seek(0)
        text = f.read()
        entry = json.loads(text or "{}").get(str(staff_folder()))
        if entry and entry["pids"]:
            return entry["mode"], entry
        return stat.S_IMODE(os.stat(ROOT).st_mode), None


def test_graders_that_run_at_once_under_the_user_fallback_do_not_kill_each_others_tests(tmp_path, monkeypatch):
    # Each grading process has a sandbox user of its own; the user's processes are killed
    # after every test, which must not reach a test another grader is running.
    from rtfgu.grading.gradebook import grade_all

    if os.geteuid() != 0:
        pytest.skip("the unprivileged-user fallback needs the grader to run as root")
    monkeypatch.setenv("RTFGU_ISOLATION", "user")
    for student in ("ann", "ben", "cat", "dan"):
        write_files(solution_files("a05"), tmp_path / "class" / student)
    path = grade_all("a05", tmp_path / "class", tmp_path / "out", processes=2, time_limit=LIMIT)
    rows = list(csv.DictReader(open(path)))
    assert [(r["student"], r["percent"]) for r in rows] == [(s, "100.0") for s in ("ann", "ben", "cat", "dan")]


def test_under_the_user_fallback_a_result_folder_is_closed_to_the_sandbox_users(tmp_path, monkeypatch):
    # Its diff images hold the reference images (hidden tests' too), written while another
    # student's code may run (grade-all); the folder is the grader's alone.
    import tempfile

    from rtfgu.grading.sandbox import sandbox_uid

    if os.geteuid() != 0:
        pytest.skip("the unprivileged-user fallback needs the grader to run as root")
    monkeypatch.setenv("RTFGU_ISOLATION", "user")
    shared = Path(tempfile.mkdtemp(prefix="rtfgu-results-"))
    try:
        os.chmod(shared, 0o755)                  # a results folder others may pass through
        write_files(solution_files("a03"), tmp_path / "sub")
        grade("a03", tmp_path / "sub", shared / "alice", only=("07_image_lecture_01_scene_the_closest_hit_in_flat_c",))
        diff = next((shared / "alice" / "diffs").glob("*.png"))
        read = "import sys\ntry:\n    open(sys.argv[1], 'rb').read()\n    print('read')\nexcept OSError:\n    print('denied')"

        # The sandbox user this process claimed, the one its students' code runs as: a grader
        # on another worker kills every process of its own user after each test, so a probe
        # as that user could be killed before it prints.
        uid = sandbox_uid()

        def as_sandbox_user():
            os.setgroups([])
            os.setgid(uid)
            os.setuid(uid)
        done = subprocess.run(["/usr/bin/python3", "-c", read, str(diff)], preexec_fn=as_sandbox_user,
                              capture_output=True, text=True, cwd="/")
        assert done.stdout.strip() == "denied", done.stdout + done.stderr
    finally:
        shutil.rmtree(shared)


def test_a_state_file_a_sandbox_user_planted_does_not_choose_the_mode_the_checkout_gets_back(tmp_path, monkeypatch):
    # The fallback records the staff folder's mode in its own root-only state folder; a file a
    # sandbox user plants in the temporary folder, where the state once lived, chooses nothing
    # and is left as it is.
    import stat
    import tempfile

    from rtfgu.grading import sandbox

    if os.geteuid() != 0:
        pytest.skip("the unprivileged-user fallback needs the grader to run as root")
    private = tmp_path / "tmp"
    private.mkdir(mode=0o1777)
    os.chmod(private, 0o1777)
    monkeypatch.setattr(tempfile, "tempdir", str(private))
    staff = tmp_path / "staff"
    staff.mkdir()
    os.chmod(staff, 0o755)
    monkeypatch.setattr(sandbox, "staff_folder", lambda: staff)
    planted = private / ("rtfgu-hidden-%d.json" % os.getuid())
    planted.write_text(json.dumps({str(staff): {"mode": 0o777, "pids": []}}))
    os.chown(planted, sandbox.SANDBOX_UID, sandbox.SANDBOX_UID)
    os.chmod(planted, 0o666)
    with sandbox.hidden_from_sandbox_user("unprivileged user"):
        assert stat.S_IMODE(os.stat(staff).st_mode) == 0o700
    assert stat.S_IMODE(os.stat(staff).st_mode) == 0o755
    assert planted.stat().st_uid == sandbox.SANDBOX_UID
    assert json.loads(planted.read_text()) == {str(staff): {"mode": 0o777, "pids": []}}


def test_bwrap_grades_while_the_fallback_has_the_checkout_closed(tmp_path, monkeypatch):
    # bwrap started as the sandbox user must not depend on the checkout (where `make venv`
    # unpacks bwrap), which an unprivileged-user grading beside it closes.
    from rtfgu.grading import sandbox

    if not sandbox.bwrap_as_user(sandbox.find_bwrap()):
        pytest.skip("bwrap does not run as a sandbox user here (not root, or no bubblewrap: Debian package bubblewrap)")
    monkeypatch.setenv("RTFGU_ISOLATION", "bwrap")
    write_files(solution_files("a04"), tmp_path / "sub")
    with sandbox.hidden_from_sandbox_user("unprivileged user"):
        result = grade("a04", tmp_path / "sub", None, time_limit=LIMIT)
    assert result.isolation == "bwrap"
    assert result.score == result.max_score, [t.output for t in result.tests if t.score < t.max_score]
