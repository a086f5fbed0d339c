# release: solves a03
"""Run a family through a path and count what it gets wrong against the exact truth.

A path is a callable ``path(kind, origins, directions, tmin, tmax, shapes) -> t`` over
arrays of rays and one shape per ray (t is inf on a miss), with the attributes ``name``,
``formula`` ("slide" or "robust") and ``precision``; a path that evaluates secondary-ray
families also has ``spawn(kind, positions, normals, directions, shapes) -> (origins, tmin)``.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..layout import DTYPES
from .families import Family


@dataclass
class Result:
    family: str
    path: str
    formula: str
    precision: str
    rays: int
    wrong: int           # wrong hit/miss decisions (for secondary rays also self-hits and skips)
    leaks: int           # rays that hit in truth and miss in the path (light leaks through)
    false_hits: int      # rays that miss in truth and hit in the path
    self_hits: int       # secondary rays that hit the surface they leave
    skips: int           # secondary rays that miss, or pass, the real hit just beyond
    rel_err_median: float
    rel_err_max: float
    nan: int             # NaN returned instead of inf or a distance
    t: np.ndarray | None = None

    def row(self) -> dict:
        return {k: v for k, v in self.__dict__.items() if k != "t"}


def closest(path, family: Family, origins, tmin) -> np.ndarray:
    """The least t over the family's K shapes per ray (the slide's loop over the shapes)."""
    dtype = DTYPES[family.precision]
    t = np.full(family.size, np.inf)
    for k in range(family.shapes.shape[0]):
        tk = np.asarray(path(family.kind, np.ascontiguousarray(origins, dtype),
                             np.ascontiguousarray(family.directions, dtype),
                             np.ascontiguousarray(tmin, dtype),
                             np.ascontiguousarray(family.tmax, dtype),
                             np.ascontiguousarray(family.shapes[k], dtype)), dtype=np.float64)
        nan = np.isnan(tk)
        t = np.where(nan | np.isnan(t), np.nan, np.fmin(t, tk))
    return t


def evaluate(family: Family, path) -> Result:
    if path.precision != family.precision:
        raise ValueError("path precision %s does not match family precision %s"
                         % (path.precision, family.precision))
    if family.spawn is not None:
        origins, tmin = path.spawn(family.kind, family.spawn["positions"], family.spawn["normals"],
                                   family.spawn["directions"], family.shapes[0])
    else:
        origins, tmin = family.origins, family.tmin
    t = closest(path, family, origins, tmin)
    nan = np.isnan(t)
    hit = np.isfinite(t)
    truth_hit = family.truth_hit
    leaks = truth_hit & ~hit
    false_hits = hit & ~truth_hit
    wrong = leaks | false_hits | nan
    self_hits = np.zeros(family.size, bool)
    skips = np.zeros(family.size, bool)
    if family.spawn is not None:
        with np.errstate(invalid="ignore"):
            self_hits = hit & (t < family.self_threshold)
            skips = truth_hit & (~hit | (t > 1.5 * family.truth_t))
        wrong = wrong | self_hits | skips
    both = hit & truth_hit
    if np.any(both):
        # (t - hi) - lo: exact truth as a double-double, so float64 errors are measured finely
        tt, hi, lo = t[both], family.truth_t[both], family.truth_lo[both]
        scale = np.abs(hi)
        scale[scale == 0] = 1.0
        rel = np.abs((tt - hi) - lo) / scale
        med, mx = float(np.median(rel)), float(np.max(rel))
    else:
        med = mx = float("nan")
    return Result(family=family.name, path=path.name, formula=path.formula,
                  precision=family.precision, rays=family.size, wrong=int(wrong.sum()),
                  leaks=int(leaks.sum()), false_hits=int(false_hits.sum()),
                  self_hits=int(self_hits.sum()), skips=int(skips.sum()),
                  rel_err_median=med, rel_err_max=mx, nan=int(nan.sum()), t=t)
