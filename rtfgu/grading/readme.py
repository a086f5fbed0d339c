"""The README of every assignment, generated from its spec and its tests."""
from __future__ import annotations

from .assignments import ASSIGNMENTS
from .checks import IMAGE_FRACTION, IMAGE_LEVELS, checks_for
from .checks.images import DIFF_LEGEND
from .checks.statistics import CHI_SQUARE_ALPHA, PIXEL_FRACTION, Z_LIMIT, Z_PIXEL


def later(absent: dict, f: str) -> str:
    """" (...)" after a student file a release leaves out until other assignments are revealed
    (``absent``: file -> those assignments' short ids, rtfgu.grading.release), else ""."""
    if f not in absent:
        return ""
    return " (not in this copy yet: it comes with the release that reveals %s)" % ", ".join(absent[f])


def assignment_readme(a, release: bool = False, absent=None) -> str:
    """The README of assignment ``a``: for the course's tree, whose assignments/<id>/ holds the
    student files, or (``release``) for a student repository, where they are edited in place
    in rtfgu/ and assignments/<id>/ holds only this README; ``absent``: the student files that
    release leaves out, and the assignments that bring them (later)."""
    absent = absent or {}
    checks = checks_for(a.id)
    visible = [c for c in checks if c.visibility == "visible"]
    hidden = [c for c in checks if c.visibility != "visible"]
    total = sum(c.weight for c in checks)
    lines = ["# %s: %s" % (a.short, a.title), "", "## Task", "", a.task, "",
             "## Files to edit", ""]
    for f in a.files:
        names = ", ".join("`%s`" % b.qualname for b in a.blocks if b.file == f)
        lines.append("- `rtfgu/%s`%s: %s" % (f, later(absent, f), names) if release else
                     "- `%s` (in the package: `rtfgu/%s`): %s" % (f, f, names))
    lines += ["", "Each place to fill in raises `NotImplementedError(\"%s: ...\")` and says above it what to "
              "write. Replace the `raise` and the TODO comment with your code; change nothing else." % a.short,
              "", "## Formulas", "", a.formulas, "", "## Slides", ""]
    lines += ["- %s" % s for s in a.slides]
    lines += ["", "## Check your work", "",
              "From the top of the repository:", "",
              "    make check A=%s     # the visible tests below, on your files in %s" % (
                  a.short, "rtfgu/ (the files above)" if release else "assignments/%s/" % a.id)]
    if a.images:
        lines.append("    make render A=%s    # this assignment's images, rendered with your code, into renders/%s/"
                     % (a.short, a.short))
    lines += ["", "A failing test says what was expected, what your code gave, and for which ray, point or pixel."]
    if any(c.kind == "image" for c in checks):
        lines += ["Image tests compare your render with the reference: a pixel counts as different only if it differs",
                  "by more than %d of 255 levels from every pixel in the 3 x 3 neighbourhood of the reference pixel,"
                  % IMAGE_LEVELS,
                  "and up to %.1f%% of the pixels may differ. Every image test writes a diff image" % (100 * IMAGE_FRACTION),
                  "(%s). A failing one names a pixel of its test image" % DIFF_LEGEND,
                  "(%s)%s." % (" or ".join(sorted({"%d x %d" % c.size for c in checks if c.kind == "image"})),
                               " and the `make render A=%s W=.. H=..` that renders the images at that size" % a.short
                               if a.images else "")]
    if any(c.kind == "statistic" for c in checks):
        lines += ["Statistical tests judge random samples: a chi-square test of where your directions fall (it",
                  "fails a correct sampler once in %d gradings), and means of many samples against the truth or" % round(1 / CHI_SQUARE_ALPHA),
                  "the reference estimate, which pass within %g standard errors of the Monte Carlo noise of both;" % Z_LIMIT,
                  "an image also fails when more than %g%% of its pixel channels are beyond %g standard errors."
                  % (100 * PIXEL_FRACTION, Z_PIXEL),
                  "The probes draw from a fixed stream of random numbers, so a test gives the same answer every run."]
        if any(c.draw is not None for c in checks):
            lines += ["The tests that say \"drawn for each grading\" are the exception: the grader draws their inputs",
                      "(points, normals) afresh every time, and `make check` runs them on one stored draw."]
    lines += ["", "## Hand in", "", "The file%s" % ("s" if len(a.files) > 1 else ""), ""]
    lines += ["- `%s%s`%s" % ("rtfgu/" if release else "", f, later(absent, f) if release else "") for f in a.files]
    if a.images:
        lines += ["", "and these images, rendered with `make render A=%s` (PNG, the size the scene registers):" % a.short, ""]
        lines += ["- `%s.png`" % name for name in a.images]
    lines += ["", "## Grading (%g points)" % total, "", "| test | points | |", "|---|---|---|"]
    for c in visible:
        lines.append("| %s %s | %g | visible |" % (c.number, c.name, c.weight))
    if hidden:
        lines.append("| %d hidden test%s | %g | hidden until grades are published |"
                     % (len(hidden), "s" if len(hidden) > 1 else "", sum(c.weight for c in hidden)))
    lines += ["", "Each test runs in its own process with a time limit; an exception, an endless loop or a",
              "wrong return type costs that test's points only.", ""]
    if a.extra:
        lines += [a.extra, ""]
    return "\n".join(lines)


def index_readme(release: bool = False, absent=None) -> str:
    """The index of the assignments (``release``: as a student repository has them, see
    assignment_readme; ``absent`` as there)."""
    absent = absent or {}
    if release:
        lines = ["# Assignments", "",
                 "Each folder holds an assignment's README. You edit its files where they are, in `rtfgu/`",
                 "(the table names them); `make check A=a03` runs the visible tests on them and",
                 "`make render A=a03` renders the assignment's images with them.", "",
                 "| id | title | files |", "|---|---|---|"]
        for a in ASSIGNMENTS.values():
            lines.append("| [%s](%s/README.md) | %s | %s |" % (a.id, a.id, a.title, ", ".join(
                "`rtfgu/%s`%s" % (f, later(absent, f)) for f in a.files)))
        return "\n".join(lines + [""])
    lines = ["# Assignments", "",
             "Generated by `make assignments` from the solutions marked `### BEGIN SOLUTION` /",
             "`### END SOLUTION` in `rtfgu/`; do not edit by hand (a test checks that this folder is",
             "exactly what the generator writes).", "",
             "Each folder holds the assignment's README and its student files, under their paths in the",
             "package (`shapes/sphere.py` is `rtfgu/shapes/sphere.py`). A student edits them in place;",
             "`make check A=a03` runs the visible tests on them and `make render A=a03` renders the",
             "assignment's images with them. Everything else comes from the course's copy of the package.", "",
             "| id | title | files |", "|---|---|---|"]
    for a in ASSIGNMENTS.values():
        lines.append("| [%s](%s/README.md) | %s | %s |" % (a.id, a.id, a.title, ", ".join("`%s`" % f for f in a.files)))
    lines += ["", "Staff: `python -m rtfgu.grading solution a03 DIR` writes the solved files (a known-good",
              "submission); `make grade A=a03 SUBMISSION=path` grades one submission,",
              "`make grade-all A=a03 SUBMISSIONS=dir/` a class, and `make autograder-zip A=a03` builds the",
              "Gradescope bundle.", ""]
    return "\n".join(lines)
