"""What a08's traversal test and a03's closest-hit test catch, graded under bwrap and under the
fallback as root without bwrap (RTFGU_BWRAP=none): the solution keeps full marks, the stubs
score 0, each planted traversal of tests/submissions/a08_traversal/ (right answers, the cost of
no BVH) loses exactly the traversal test's points, and a sphere that never hits no longer has
full marks in the closest hit among five shapes.

The planted traversals lie in a folder of their own: tests/test_grading.py lists the planted
submissions of tests/submissions/ one by one, with the tests each must lose.
"""
from __future__ import annotations

import json
import os

import pytest

from rtfgu.grading import sandbox
from rtfgu.grading.checks import checks_for
from rtfgu.grading.generate import solution_files, student_files, write_files
from rtfgu.grading.grader import REFERENCE_DIR, grade

from planted import SUBMISSIONS, describe, make_submission

LIMIT = 5.0
TRAVERSAL = next(c for c in checks_for("a08") if c.probe[1] == "observe_traversal")
CLOSEST = next(c for c in checks_for("a03") if c.probe[1] == "observe_closest")
PLANTED_TRAVERSALS = sorted("a08_traversal/" + p.stem for p in (SUBMISSIONS / "a08_traversal").glob("*.py"))


@pytest.fixture(params=["bwrap", "fallback"], scope="module")
def mode(request):
    if request.param == "bwrap":
        if not sandbox.bwrap_works(sandbox.find_bwrap()):
            pytest.skip("bubblewrap is not installed or cannot make its namespaces here (Debian package bubblewrap)")
        env = {"RTFGU_ISOLATION": "bwrap"}
    else:
        if os.geteuid() != 0:
            pytest.skip("the fallback runs student code as a sandbox user, which needs the grader to run as root")
        env = {"RTFGU_BWRAP": "none", "RTFGU_ISOLATION": ""}
    old = {k: os.environ.get(k) for k in env}
    os.environ.update(env)
    yield request.param
    for k, v in old.items():
        if v is None:
            os.environ.pop(k, None)
        else:
            os.environ[k] = v


def _by_number(result) -> dict:
    return {t.number: t for t in result.tests}


@pytest.fixture(scope="module")
def a08_solution(mode, tmp_path_factory):
    folder = tmp_path_factory.mktemp("a08_solution")
    write_files(solution_files("a08"), folder)
    return grade("a08", folder, None, time_limit=LIMIT)


def test_the_traversal_test_is_hidden_and_its_reference_was_computed_from_the_solution():
    stored = json.loads((REFERENCE_DIR / "a08_bvh" / "observations.json").read_text())[TRAVERSAL.slug]
    assert TRAVERSAL.visibility == "hidden" and TRAVERSAL.judge is not None and TRAVERSAL.weight == 2
    scenes = {case["in"]["scene"] for case in stored["cases"]}
    assert scenes == {"grid", "sheet", "random"}
    assert all(case["out"]["tested below a rejected box"] == [] and
               case["out"]["tested in a leaf whose box was not tested"] == [] for case in stored["cases"])
    assert sum(c.weight for c in checks_for("a08")) == 18


def test_the_solution_keeps_full_marks_and_the_stubs_score_zero(mode, a08_solution, tmp_path):
    assert a08_solution.score == a08_solution.max_score == 18
    assert "the random scene" in _by_number(a08_solution)[TRAVERSAL.number].output
    write_files(student_files("a08"), tmp_path / "stubs")
    assert grade("a08", tmp_path / "stubs", None, time_limit=LIMIT).score == 0


@pytest.mark.parametrize("name", PLANTED_TRAVERSALS)
def test_a_planted_traversal_loses_the_traversal_points_and_nothing_else(mode, a08_solution, tmp_path, name):
    assert describe(name)["ASSIGNMENT"] == "a08"
    result = grade("a08", make_submission(name, tmp_path / "sub"), None, time_limit=LIMIT)
    full = _by_number(a08_solution)
    for number, test in _by_number(result).items():
        if number == TRAVERSAL.number:
            assert test.score == 0, test.output
            assert "your traversal" in test.output
        else:
            assert test.score == full[number].score == test.max_score, (number, test.output)


def test_three_planted_traversals_brute_force_no_pruning_and_far_first_without_the_cut():
    assert [n.split("/")[1] for n in PLANTED_TRAVERSALS] == ["a08_brute_force", "a08_far_first_no_cut",
                                                             "a08_no_pruning"]


def test_a_sphere_that_never_hits_loses_points_in_the_closest_hit(mode, tmp_path):
    stored = json.loads((REFERENCE_DIR / "a03_intersections" / "observations.json").read_text())[CLOSEST.slug]
    kinds = {0: "sphere", 1: "plane", 2: "triangle", 3: "sphere", 4: "sphere"}
    second = [c for c in stored["cases"] if "among a sphere" in c["label"]]
    assert {kinds[c["out"]["closest shape"]] for c in second} == {"sphere", "plane", "triangle"}
    assert {c["out"]["closest shape"] for c in second} == {0, 1, 2, 3, 4}      # a sphere first, middle and last
    files = dict(solution_files("a03"))
    signature = "    def intersect_p(self, ray: Ray) -> bool:\n"
    assert files["shapes/sphere.py"].count(signature) == 1
    files["shapes/sphere.py"] = files["shapes/sphere.py"].replace(signature, signature + "        return False\n")
    write_files(files, tmp_path / "never")
    result = grade("a03", tmp_path / "never", None, time_limit=LIMIT, only=(CLOSEST.slug,))
    assert 0 < result.tests[0].score < result.tests[0].max_score
    assert "closest shape should be" in result.tests[0].output
    write_files(solution_files("a03"), tmp_path / "solved")
    solved = grade("a03", tmp_path / "solved", None, time_limit=LIMIT, only=(CLOSEST.slug,))
    assert solved.tests[0].score == solved.tests[0].max_score
