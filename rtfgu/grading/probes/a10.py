"""Probes of a10's visible tests: Suffern's multi-jittered sampler
(``MultiJittered.generate_samples``, ch. 5) and Shirley and Chiu's concentric map
(``concentric_map``, ch. 6).

A probe returns what the student's code made, never a verdict: every set's points (the judge
checks the structure), the points of samplers made twice with one seed and once with another,
the map at chosen points, and many uniformly drawn points of the square mapped (the grader
bins them on the disk by r^2 and phi, bin_disk: uniform on the disk makes both uniform; the
judge applies a chi-square test)."""
from __future__ import annotations

import importlib
import math
import random

from .support import Cases, StudentError, num

R_BINS = 8          # bins of r^2 on the disk
PHI_BINS = 8        # bins of the angle
SHOWN = 5           # the points off the disk shown in a message


def _sampler(rt, num_samples: int, num_sets: int, seed: int):
    cls = importlib.import_module(rt.__name__ + ".sampling.multi_jittered").MultiJittered
    return cls(num_samples, num_sets=num_sets, seed=seed)


def _points(sampler, what: str) -> list:
    points = []
    for k, p in enumerate(sampler.samples):
        if not isinstance(p, (tuple, list)) or len(p) != 2:
            raise StudentError("%s: sample %d is %r, not a point (x, y)" % (what, k, p))
        points.append([num(p[0], "%s: x of sample %d" % (what, k)), num(p[1], "%s: y of sample %d" % (what, k))])
    return points


def observe_sets(rt, counts, num_sets: int, seed: int):
    """The points of MultiJittered(n, num_sets, seed) for each n of ``counts``."""
    out = []
    for n in counts:
        sampler = _sampler(rt, n, num_sets, seed)
        out.append({"num_samples": n, "num_sets": num_sets,
                    "points": _points(sampler, "MultiJittered(%d, num_sets=%d)" % (n, num_sets))})
    return {"sets": out}


def observe_seeds(rt, num_samples: int, num_sets: int, seeds):
    """The points of MultiJittered(num_samples, num_sets, seed) for each seed, in order (a seed
    may come twice)."""
    return {"runs": [{"seed": s, "points": _points(_sampler(rt, num_samples, num_sets, s),
                                                   "MultiJittered(seed=%d)" % s)} for s in seeds]}


def _maps(rt):
    return importlib.import_module(rt.__name__ + ".sampling.maps")


def _disk_point(got, what: str) -> dict:
    if not isinstance(got, (tuple, list)) or len(got) != 2:
        raise StudentError("%s should return a point (x, y) of the disk, but it returned %r" % (what, got))
    return {"x": num(got[0], what + "'s x"), "y": num(got[1], what + "'s y")}


def observe_concentric(rt, points):
    """concentric_map at every point (x, y): cases whose inputs are the points."""
    cases = Cases()
    for x, y in points:
        what = "concentric_map(%r, %r)" % (x, y)
        cases.run(what, lambda x=x, y=y, what=what: _disk_point(_maps(rt).concentric_map(x, y), what), x=x, y=y)
    return cases.result()


def observe_concentric_binned(rt, count: int, seed: int):
    """concentric_map of ``count`` uniform points of the square (stream ``seed``): every point
    it gave (bin_disk bins them on the grader's side: a histogram, whose truth is flat, is
    easily forged by code that replaces this probe; the points are not)."""
    stream = random.Random(seed)
    out = []
    for _ in range(count):
        x, y = stream.random(), stream.random()
        p = _disk_point(_maps(rt).concentric_map(x, y), "concentric_map(%r, %r)" % (x, y))
        out.append([p["x"], p["y"]])
    return {"points": out}


def bin_disk(points, count: int, seed: int) -> dict:
    """The grader's side of observe_concentric_binned: the ``count`` mapped points binned by r^2
    and phi; the points off the unit disk counted (and the first few kept with the points of
    the square they came from)."""
    if not isinstance(points, list) or len(points) != count:
        raise ValueError("concentric_map: not the %d points the test drew" % count)
    stream = random.Random(seed)
    counts = [[0] * PHI_BINS for _ in range(R_BINS)]
    bad, n_bad = [], 0
    for point in points:
        x, y = stream.random(), stream.random()
        px, py = float(point[0]), float(point[1])
        r2 = px * px + py * py
        if not (math.isfinite(r2) and r2 <= 1.0 + 1e-12):
            n_bad += 1
            if len(bad) < SHOWN:
                bad.append([[x, y], [px, py]])
            continue
        phi = math.atan2(py, px) % (2.0 * math.pi)
        counts[min(int(r2 * R_BINS), R_BINS - 1)][min(int(phi / (2.0 * math.pi) * PHI_BINS), PHI_BINS - 1)] += 1
    return {"counts": counts, "bad": bad, "n_bad": n_bad, "count": count}
