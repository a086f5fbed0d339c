"""The tests of every assignment, as observe / judge pairs.

A check's ``observe(rt)`` runs in the sandboxed child with ``rt`` the student's copy of the
package (the submission overlaid on a clean copy); it returns plain JSON data: the inputs
it tried and what the student's code gave back. ``judge`` runs in the grader, compares
that with the reference observation (the same ``observe`` run on the solution, stored in
``rtfgu/grading/reference``) and says in words what differs. Nothing the student's code
does can reach the comparison: it only ever sees numbers.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

CHECKS = {}

# Image tests: a pixel fails if, even after trying the 3 x 3 neighbourhood of the
# reference pixel, every colour differs by more than IMAGE_LEVELS of 255 in some channel;
# the test fails if more than IMAGE_FRACTION of the pixels fail (at least one).
IMAGE_LEVELS = 8
IMAGE_FRACTION = 0.005


@dataclass
class Check:
    name: str
    weight: float
    observe: object                 # observe(rt) -> JSON data (runs in the child)
    visibility: str = "visible"     # "visible" or "hidden"
    kind: str = "cases"             # "cases" or "image"
    hint: object = None             # hint(inputs, expected, got) -> str | None
    rtol: float = 1e-6
    atol: float = 1e-9
    size: tuple = (48, 48)          # image tests
    number: str = ""
    slug: str = ""
    tags: tuple = field(default_factory=tuple)
    fresh: bool = False             # kept for old callers: every test runs in a new interpreter
    memory_mb: int | None = None    # overrides the grader's limit (0: none; llvmpipe reserves much address space)
    needs: tuple = ()               # the student files the test runs (relative to rtfgu/); () : all of them
    assignment: str = ""

    def hint_function(self):
        """The hint: a function, or the name of one in the check's module (a hint that
        computes a solution lives in a STAFF region, which a release leaves out: then none)."""
        if not isinstance(self.hint, str):
            return self.hint
        import importlib

        module = importlib.import_module("%s.%s" % (__name__, self.assignment.split("_", 1)[0]))
        return getattr(module, self.hint, None)


def register(assignment_id: str, checks) -> None:
    for i, check in enumerate(checks, start=1):
        check.assignment = assignment_id
        check.number = "%s.%d" % (assignment_id.split("_", 1)[0][1:].lstrip("0") or "0", i)
        check.slug = "%02d_%s" % (i, _slug(check.name))
    CHECKS[assignment_id] = list(checks)


def _slug(name: str) -> str:
    out = "".join(c.lower() if c.isalnum() else "_" for c in name)
    while "__" in out:
        out = out.replace("__", "_")
    return out.strip("_")[:48]


def checks_for(assignment_id: str):
    _load()
    if assignment_id not in CHECKS:
        raise ValueError("assignment %r has no checks" % (assignment_id,))
    return CHECKS[assignment_id]


def _load():
    from . import a01, a02, a03, a04, a05  # noqa: F401  (each registers its checks)
    try:
        from . import a06  # noqa: F401
    except ImportError:
        pass


# --- formatting and comparing (grader side) -----------------------------------------------

def fmt(value) -> str:
    if isinstance(value, bool):
        return "True" if value else "False"
    if isinstance(value, float):
        if math.isinf(value):
            return "infinity" if value > 0 else "-infinity"
        return "%.6g" % value
    if isinstance(value, list) and len(value) == 3 and all(isinstance(v, (int, float)) for v in value):
        return "(%s)" % ", ".join(fmt(float(v)) for v in value)
    if value is None:
        return "nothing"
    return str(value)


def close(got, want, rtol: float, atol: float) -> bool:
    if isinstance(want, bool) or isinstance(got, bool) or isinstance(want, str):
        return type(got) is type(want) and got == want
    if isinstance(want, (int, float)):
        if not isinstance(got, (int, float)):
            return False
        if math.isinf(want) or math.isnan(want):
            return got == want or (math.isnan(want) and math.isnan(got))
        if math.isnan(got) or math.isinf(got):
            return False
        return abs(got - want) <= atol + rtol * abs(want)
    if isinstance(want, list):
        return isinstance(got, list) and len(got) == len(want) and all(
            close(g, w, rtol, atol) for g, w in zip(got, want))
    if isinstance(want, dict):
        return isinstance(got, dict) and all(k in got and close(got[k], want[k], rtol, atol) for k in want)
    return got == want


def judge_cases(check: Check, got, want):
    """(fraction of cases right, message lines) for a cases check."""
    if "error" in got:
        return 0.0, [got["error"]]
    cases_got, cases_want = got.get("cases"), want["cases"]
    if not isinstance(cases_got, list) or len(cases_got) != len(cases_want):
        return 0.0, ["the test stopped before it tried every case (%s)" % got.get("stopped", "no reason given")]
    errors = {g.get("error") for g in cases_got}
    if len(errors) == 1 and None not in errors:
        return 0.0, ["every one of the %d cases raised %s" % (len(cases_want), errors.pop()),
                     "the first case: " + cases_want[0]["label"]]
    right, lines = 0, []
    for g, w in zip(cases_got, cases_want):
        label = w["label"]
        if "error" in g:
            lines.append("- %s: your code raised %s" % (label, g["error"]))
            continue
        wrong = [key for key in w["out"] if not close(g.get("out", {}).get(key), w["out"][key], check.rtol, check.atol)]
        if not wrong:
            right += 1
            continue
        parts = ["%s should be %s, yours is %s" % (key, fmt(w["out"][key]), fmt(g.get("out", {}).get(key)))
                 for key in wrong]
        line = "- %s: %s." % (label, "; ".join(parts))
        hint_function = check.hint_function()
        if hint_function is not None:
            try:
                hint = hint_function(w.get("in", {}), w["out"], g.get("out", {}))
            except Exception:  # a hint is a courtesy; a malformed observation must not stop grading
                hint = None
            if hint:
                line += "\n  Hint: " + hint
        lines.append(line)
    return right / len(cases_want), lines


def image_check(name: str, weight: float, build, size=(48, 48), visibility: str = "visible", render=None,
                **options) -> Check:
    """An image test: ``build(rt)`` returns the scene (or a registered scene name), rendered by
    the lecture layer's pixel loop with the student's code at ``size``."""
    width, height = size

    def observe(rt):
        from .child import image

        scene = build(rt) if callable(build) else rt.scenes.get_scene(build)()
        if render is not None:
            return image(render(rt, scene, width, height))
        return image(rt.renderer.render_reference(scene, width, height))

    return Check(name, weight, observe, visibility=visibility, kind="image", size=size, **options)
