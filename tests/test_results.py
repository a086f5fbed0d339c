"""What a student sees of a result: hidden tests stay hidden until the grades are published."""
from __future__ import annotations

from rtfgu.grading.results import Result, TestResult, validate_gradescope


def _result():
    r = Result("a03_intersections", "sub", isolation="bwrap")
    r.tests = [TestResult("3.1", "visible one", 2.0, 1.0, "visible", "half right"),
               TestResult("3.9", "hidden one", 3.0, 3.0, "hidden", "the closest hit: all 7 cases right")]
    return r


def test_gradescope_hidden_tests_are_after_published_and_the_visible_output_omits_their_points():
    data = _result().to_gradescope()
    validate_gradescope(data)
    by_number = {t["number"]: t for t in data["tests"]}
    assert by_number["3.9"]["visibility"] == "after_published"
    assert by_number["3.1"]["visibility"] == "visible"
    assert "1 / 2 points in the visible tests" in data["output"]
    assert "4" not in data["output"].split("\n")[0]          # the total, 1 + 3, is not shown
    assert "1 hidden test" in data["output"]
    assert data["extra_data"]["isolation"] == "bwrap"


def test_prairielearn_shows_no_message_of_a_hidden_test():
    data = _result().to_prairielearn()
    hidden = next(t for t in data["tests"] if t["name"] == "hidden one")
    assert "closest hit" not in hidden["message"]
    assert "closest hit" not in data["message"]
    visible = next(t for t in data["tests"] if t["name"] == "visible one")
    assert visible["message"] == "half right"


def test_the_summary_says_which_isolation_ran(tmp_path):
    r = _result()
    r.write(tmp_path)
    assert "student code ran isolated by: bwrap" in (tmp_path / "summary.txt").read_text()
