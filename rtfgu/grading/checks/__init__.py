"""The tests of every assignment: a probe that runs next to the student's code, and the
judging and hints that stay in the grader.

A check's ``probe`` = (module, function, kwargs) names a function of
``rtfgu.grading.probes`` (rtfgu/grading/probes/): it runs in the sandboxed child with the
student's copy of the package and returns plain JSON data, the inputs it tried and what the
student's code gave back. ``judge_cases`` (or the grader's image judge) runs here, compares
that with the reference observation (the same probe run on the solution, stored in
``rtfgu/grading/reference``) and says in words what differs; a hint compares numbers only
(the known mistakes of rtfgu.grading.mistakes arrive precomputed as ``inputs["known"]``).
Nothing the student's code does can reach the comparison: it only ever sees numbers.

A hidden test is registered between ``# ### BEGIN HIDDEN`` and ``# ### END HIDDEN`` lines,
after every visible test of its assignment, and its probe lives in ``probes/aNN_hidden.py``:
a student release leaves both out.
"""
from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from pathlib import Path

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
    probe: tuple                    # (module of rtfgu.grading.probes, function, kwargs): runs in the child
    visibility: str = "visible"     # "visible" or "hidden"
    kind: str = "cases"             # "cases", "image" or "statistic"
    hint: object = None             # hint(inputs, expected, got) -> str | None (grader side)
    rtol: float = 1e-6
    atol: float = 1e-9
    size: tuple = (48, 48)          # image tests
    number: str = ""
    slug: str = ""
    tags: tuple = field(default_factory=tuple)
    fresh: bool = False             # kept for old callers: every test runs in a new interpreter
    memory_mb: int | None = None    # overrides the grader's limit (0: none; llvmpipe reserves much address space)
    needs: tuple = ()               # the student files the test runs (relative to rtfgu/); () : all of them
    known: str = ""                 # a function of rtfgu.grading.mistakes: the known mistakes per case
    # judge(check, got, reference) -> (fraction, message lines): the check's own judge, for any
    # kind but images (judge_cases by default); with kind "statistic", reference() -> the
    # reference observation, computed on the grader's side (an exact truth or the staff
    # renderer's estimate) instead of by running the probe on the solution
    judge: object = None
    time_limit: float | None = None  # this test's own limit in seconds, over the grader's (a render in pure Python)
    reference: object = None
    # draw(rng) -> probe kwargs drawn when the test runs (inputs no submission can know in
    # advance, from the grader's random.Random or SystemRandom); the check's reference is then
    # reference(**drawn), computed by the grader for them (see drawn_inputs)
    draw: object = None
    assignment: str = ""

    def __post_init__(self):
        if len(self.probe) == 2:
            self.probe = (self.probe[0], self.probe[1], {})
        module, function, kwargs = self.probe
        self.probe = (module, function, dict(kwargs))

    def hint_function(self):
        return self.hint

    @property
    def probe_module(self) -> str:
        return self.probe[0]


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
    """The checks of an assignment (its id, "a03_intersections", or short id, "a03")."""
    from ..assignments import get_assignment

    _load()
    assignment_id = get_assignment(assignment_id).id
    if assignment_id not in CHECKS:
        raise ValueError("assignment %r has no checks" % (assignment_id,))
    return CHECKS[assignment_id]


def _load():
    from . import a01, a02, a03, a04, a05, a07, a08, a09, a10, a11, a12, a13  # noqa: F401  (each registers its checks)
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


REFERENCE_DIR = Path(__file__).resolve().parent.parent / "reference"


def known_mistakes(check, reference_dir: Path | None = None) -> list:
    """The known mistakes of every case of ``check`` (one dict per case, in the order of
    its reference cases), from ``reference/<assignment>/known.json``; [] if none."""
    path = Path(reference_dir or REFERENCE_DIR) / check.assignment / "known.json"
    if not check.known or not path.is_file():
        return []
    try:
        return json.loads(path.read_text()).get(check.slug, [])
    except ValueError:
        return []


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
    known = known_mistakes(check) if check.hint is not None else []
    right, lines = 0, []
    for i, (g, w) in enumerate(zip(cases_got, cases_want)):
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
                inputs = dict(w.get("in", {}), known=known[i] if i < len(known) else {})
                hint = hint_function(inputs, w["out"], g.get("out", {}))
            except Exception:  # a hint is a courtesy; a malformed observation must not stop grading
                hint = None
            if hint:
                line += "\n  Hint: " + hint
        lines.append(line)
    return right / len(cases_want), lines


def known_mistake_hint(hints, inputs, want, got, key: str, same):
    """The text of the first (mistake, text) of ``hints`` whose value of ``want[key]``, as
    ``inputs["known"]`` holds it, the student's ``got[key]`` equals (by ``same``) while the
    right value does not; None if there is none."""
    known = inputs.get("known") or {}
    for mistake, text in hints:
        if mistake in known and not same(known[mistake], want[key]) and same(got.get(key), known[mistake]):
            return text
    return None


def image_check(name: str, weight: float, scene: str, size=(48, 48), visibility: str = "visible",
                render: str | None = None, shaders=None, shadows=None, **options) -> Check:
    """An image test: probes.images.render_scene renders ``scene`` (a registered homework
    scene, or with ``shaders`` the 02562 default scene with those shader names) at ``size``
    with the student's code, by the lecture layer's pixel loop or by ``render``
    ("module.function" of the probes)."""
    width, height = size
    kwargs = {"scene": scene, "width": width, "height": height}
    if render is not None:
        kwargs["render"] = render
    if shaders is not None:
        kwargs["shaders"] = list(shaders)
        kwargs["shadows"] = bool(shadows)
    return Check(name, weight, ("images", "render_scene", kwargs), visibility=visibility, kind="image",
                 size=size, **options)


def traces_a_scene(check: Check) -> bool:
    """Whether ``check`` is an image test of a scene rendered by images.render_scene (made by
    image_check), whose pixels ``make debug-pixel`` can trace; an image test with a probe of
    its own (a11's glass sphere) is not."""
    return check.kind == "image" and tuple(check.probe[:2]) == ("images", "render_scene")


def drawn_inputs(check: Check, rng) -> tuple:
    """(probe, reference) of a check with ``draw``: its probe with the inputs drawn from
    ``rng`` added to its kwargs, and its reference computed for those inputs, which the judge
    finds as ``reference["drawn"]``. The grader draws afresh for every grading; the stored
    reference (and the student checker) holds one draw, from ``random.Random(0)``."""
    drawn = check.draw(rng)
    module, function, kwargs = check.probe
    return (module, function, dict(kwargs, **drawn)), dict(check.reference(**drawn), drawn=drawn)


def stored_probe(check: Check, reference) -> tuple:
    """The probe that a stored ``reference`` was computed for: with a check's drawn inputs."""
    if check.draw is None:
        return check.probe
    module, function, kwargs = check.probe
    return module, function, dict(kwargs, **reference["drawn"])


def probe_table() -> dict:
    """assignment id -> slug -> [module, function, kwargs] of every test (written beside the
    probes as tests.json, which boot.py reads for ``check ASSIGNMENT SLUG``)."""
    from ..assignments import ASSIGNMENTS

    _load()
    return {aid: {c.slug: list(c.probe) for c in CHECKS[aid]} for aid in ASSIGNMENTS if aid in CHECKS}
