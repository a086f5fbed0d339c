"""The result model of one grading, and its writers: Gradescope's results.json,
PrairieLearn's results format, and a summary a person reads."""
from __future__ import annotations

import base64
import html
import json
from dataclasses import dataclass, field
from pathlib import Path

from .checks.images import DIFF_LEGEND

OUTPUT_LIMIT = 8000   # characters of message per test
IMAGE_LIMIT = 256 * 1024   # bytes of a diff image shown inside a result (a 48 x 48 test's: about 2 KB)


def _shown_image(t) -> bytes | None:
    """The PNG bytes of a visible test's diff image, to show inside the result (Gradescope and
    PrairieLearn show only results.json, not the files beside it); None for a hidden test (its
    image holds the hidden reference), for none, or one above IMAGE_LIMIT."""
    if t.visibility != "visible" or not t.image or not Path(t.image).is_file():
        return None
    data = Path(t.image).read_bytes()
    return data if len(data) <= IMAGE_LIMIT else None


def gradescope_test_output(t) -> dict:
    """A test's output for Gradescope: text, or where it has a diff image to show, HTML with
    the text escaped (what the student's code printed is in it) and the image inline as a data
    URI, which the message then points to instead of a file the student cannot see."""
    text = t.output[:OUTPUT_LIMIT]
    image = _shown_image(t)
    if image is None:
        return {"output": text}
    text = text.replace("the diff image is %s" % Path(t.image).name, "the diff image is below")
    return {"output_format": "html",
            "output": "<pre>%s</pre>\n<p>%s</p>\n"
                      "<img alt=\"diff image: %s\" "
                      "src=\"data:image/png;base64,%s\" style=\"image-rendering: pixelated\">"
                      % (html.escape(text), html.escape(DIFF_LEGEND), html.escape(DIFF_LEGEND),
                         base64.b64encode(image).decode())}


@dataclass
class TestResult:
    __test__ = False  # not a pytest test class
    number: str
    name: str
    max_score: float
    score: float
    visibility: str
    output: str
    image: str | None = None   # the diff image of an image test (path)
    # Why the test could not judge the code ("" where it ran and judged): a syntax error at
    # file and line, the time limit, the memory limit, a crash (the gradebook's error column).
    cause: str = ""

    @property
    def status(self) -> str:
        return "passed" if self.score >= self.max_score - 1e-9 else "failed"


@dataclass
class Result:
    assignment: str
    submission: str
    tests: list = field(default_factory=list)
    execution_time: float = 0.0
    notes: list = field(default_factory=list)
    isolation: str = ""          # how student code was isolated (rtfgu.grading.sandbox.ISOLATIONS)

    @property
    def score(self) -> float:
        return round(sum(t.score for t in self.tests), 4)

    @property
    def max_score(self) -> float:
        return round(sum(t.max_score for t in self.tests), 4)

    @property
    def cause(self) -> str:
        """The causes of the tests that could not judge the code, each once with the tests it
        cost ("" where every test ran and was judged): what staff sort a class by."""
        counts = {}
        for t in self.tests:
            if t.cause:
                counts[t.cause] = counts.get(t.cause, 0) + 1
        return "; ".join("%s (%d test%s)" % (c, n, "" if n == 1 else "s") for c, n in counts.items())

    def output(self) -> str:
        lines = ["%s: %g / %g points" % (self.assignment, self.score, self.max_score)]
        lines += self.notes
        return "\n".join(lines)

    def isolation_line(self) -> str:
        return "student code ran isolated by: %s" % (self.isolation or "unknown")

    def visible_output(self) -> str:
        """The result as a student may see it before grades are published: the visible tests'
        points only, and that hidden tests exist (not what they scored)."""
        visible = [t for t in self.tests if t.visibility == "visible"]
        lines = ["%s: %g / %g points in the visible tests" % (
            self.assignment, round(sum(t.score for t in visible), 4), round(sum(t.max_score for t in visible), 4))]
        hidden = len(self.tests) - len(visible)
        if hidden:
            lines.append("%d hidden test(s) are shown when the grades are published" % hidden)
        return "\n".join(lines + self.notes)

    def to_gradescope(self) -> dict:
        # Gradescope's results.json (gradescope-autograders.readthedocs.io, "Autograder
        # Specifications"): a test's "visibility" is visible, hidden, after_due_date or
        # after_published. Hidden tests are after_published, shown with their scores once the
        # staff publish the grades; "hidden" would hide them from the students for good. The
        # top-level output a student sees at once names only the visible tests' points.
        return {
            "score": self.score,
            "execution_time": round(self.execution_time, 3),
            "output": self.visible_output(),
            "visibility": "visible",
            "stdout_visibility": "hidden",
            "extra_data": {"isolation": self.isolation},
            "tests": [dict({"name": t.name, "number": t.number, "score": round(t.score, 4),
                            "max_score": t.max_score, "status": t.status,
                            "visibility": "visible" if t.visibility == "visible" else "after_published"},
                           **gradescope_test_output(t))
                      for t in self.tests],
        }

    def to_prairielearn(self) -> dict:
        tests = []
        for t in self.tests:
            hidden = t.visibility != "visible"
            # PrairieLearn shows every test's message to the student: a hidden test's says
            # only that it is hidden.
            entry = {"name": t.name, "description": "test %s" % t.number, "points": round(t.score, 4),
                     "max_points": t.max_score,
                     "message": "a hidden test" if hidden else t.output[:OUTPUT_LIMIT], "output": ""}
            image = _shown_image(t)
            if image is not None:
                entry["images"] = [{"label": "yours | reference | difference",
                                    "url": "data:image/png;base64," + base64.b64encode(image).decode()}]
            tests.append(entry)
        return {"gradable": True, "score": self.score / self.max_score if self.max_score else 0.0,
                "message": self.visible_output(), "output": "", "tests": tests,
                "isolation": self.isolation}

    def summary(self) -> str:
        width = max([len(t.name) for t in self.tests] + [10])
        lines = [self.output(), ""]
        for t in self.tests:
            lines.append("%-5s %-*s %5.2f / %-4g %s%s" % (t.number, width, t.name, t.score, t.max_score,
                                                        t.status.upper(), "" if t.visibility == "visible" else " (hidden)"))
        for t in self.tests:
            if t.status != "passed":
                lines += ["", "--- %s %s" % (t.number, t.name), t.output]
        lines += ["", "total %g / %g   (%.1f s)" % (self.score, self.max_score, self.execution_time),
                  self.isolation_line()]
        return "\n".join(lines) + "\n"

    def write(self, out_dir, fmt: str = "gradescope") -> Path:
        out_dir = Path(out_dir)
        out_dir.mkdir(parents=True, exist_ok=True)
        if fmt == "gradescope":
            path = out_dir / "results.json"
            data = self.to_gradescope()
        elif fmt == "prairielearn":
            path = out_dir / "results.json"
            data = self.to_prairielearn()
        else:
            raise ValueError("format must be gradescope or prairielearn, got %r" % (fmt,))
        path.write_text(json.dumps(data, indent=2) + "\n")
        (out_dir / "summary.txt").write_text(self.summary(), encoding="utf-8", errors="replace")
        return path


GRADESCOPE_TEST_FIELDS = {"name": str, "number": str, "score": (int, float), "max_score": (int, float),
                          "status": str, "output": str, "visibility": str}


def validate_gradescope(data: dict) -> None:
    """Raise a ValueError naming the field if ``data`` is not a Gradescope results.json."""
    for key, kind in (("score", (int, float)), ("execution_time", (int, float)), ("output", str),
                      ("tests", list)):
        if not isinstance(data.get(key), kind) or isinstance(data.get(key), bool):
            raise ValueError("results.json: %s missing or of the wrong type" % key)
    for i, test in enumerate(data["tests"]):
        for key, kind in GRADESCOPE_TEST_FIELDS.items():
            if not isinstance(test.get(key), kind) or isinstance(test.get(key), bool):
                raise ValueError("results.json: tests[%d].%s missing or of the wrong type" % (i, key))
        if test["status"] not in ("passed", "failed"):
            raise ValueError("results.json: tests[%d].status must be passed or failed" % i)
        if test.get("output_format", "text") not in ("text", "html", "simple_format", "md", "ansi"):
            raise ValueError("results.json: tests[%d].output_format is %r" % (i, test["output_format"]))
        if test["visibility"] not in ("visible", "hidden", "after_due_date", "after_published"):
            raise ValueError("results.json: tests[%d].visibility is %r" % (i, test["visibility"]))
        if not 0 <= test["score"] <= test["max_score"] + 1e-9:
            raise ValueError("results.json: tests[%d].score is outside [0, max_score]" % i)
    if abs(sum(t["score"] for t in data["tests"]) - data["score"]) > 1e-3:
        raise ValueError("results.json: score is not the sum of the tests' scores")
