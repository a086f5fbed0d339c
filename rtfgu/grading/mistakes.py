"""Known mistakes, computed on the staff side from a test's inputs: the numbers a student's
code gives when it errs in a way the hints name (the sphere's t with b^2 + 4ac, with a = 1,
the far root; Lambert's law without its cosine). They are solution maths, so this module is
never shipped: ``write_known`` stores the numbers per case in
``reference/<assignment>/known.json`` and a hint only compares numbers with them (it gets
them as ``inputs["known"]``).

A check names its function here with ``Check(known="sphere")``.
"""
from __future__ import annotations

import json
import math
from pathlib import Path

REFERENCE_DIR = Path(__file__).resolve().parent / "reference"


def _quadratic(a, b, c):
    disc = float(b * b - 4 * a * c)
    if disc < 0:
        return disc, []
    e = math.sqrt(disc)
    return disc, [(-b - e) / (2 * a), (-b + e) / (2 * a)]


def sphere(inputs: dict) -> dict:
    """The slide's quadratic for the ray o + t d and the sphere (center, radius): a, the
    discriminant b^2 - 4ac, its roots; the roots with b^2 + 4ac and with a taken as 1."""
    o, d, c, r = inputs["o"], inputs["d"], inputs["center"], inputs["radius"]
    oc = [o[i] - c[i] for i in range(3)]
    a = float(sum(x * x for x in d))
    b = 2.0 * sum(oc[i] * d[i] for i in range(3))
    cc = float(sum(x * x for x in oc) - r * r)
    disc, roots = _quadratic(a, b, cc)
    plus = b * b + 4 * a * cc
    roots_plus = [] if plus < 0 else [(-b - math.sqrt(plus)) / (2 * a), (-b + math.sqrt(plus)) / (2 * a)]
    _, roots_a_is_one = _quadratic(1.0, b, cc)
    return {"a": a, "disc": disc, "roots": roots, "roots_plus_4ac": roots_plus, "roots_a_is_one": roots_a_is_one}


def lambert(inputs: dict) -> dict:
    """n . w_i for every light of a lambertian case (n the unit normal, w_i toward the light)."""
    normal, position = inputs["normal"], inputs["position"]
    length = math.sqrt(sum(v * v for v in normal))
    n = [v / length for v in normal]
    cos = []
    for light in inputs["lights"]:
        w = [light[i] - position[i] for i in range(3)]
        dist = math.sqrt(sum(v * v for v in w))
        cos.append(sum(n[i] * w[i] / dist for i in range(3)))
    return {"cos": [float(c) for c in cos]}


def kepler(inputs: dict) -> dict:
    """The distance from the sampled point to the light."""
    return {"dist": float(math.dist(inputs["p"], inputs["x"]))}


def known_for(check, observation: dict):
    """The known mistakes of every case of ``observation`` (a reference observation of
    ``check``), or None if the check names none."""
    if not check.known:
        return None
    function = globals()[check.known]
    return [function(case.get("in", {})) for case in observation.get("cases", [])]


def write_known(assignment, reference_dir: Path = REFERENCE_DIR):
    """Write ``known.json`` (slug -> one dict per case) beside the assignment's reference
    observations, from their inputs; returns its path (None, and no file, if no test of the
    assignment names known mistakes)."""
    from .checks import checks_for

    folder = Path(reference_dir) / assignment.id
    observations = json.loads((folder / "observations.json").read_text())
    known = {}
    for check in checks_for(assignment.id):
        if check.kind == "cases" and check.slug in observations:
            cases = known_for(check, observations[check.slug])
            if cases is not None:
                known[check.slug] = cases
    path = folder / "known.json"
    if not known:
        if path.exists():
            path.unlink()
        return None
    path.write_text(json.dumps(known, indent=1, sort_keys=True) + "\n")
    return path
