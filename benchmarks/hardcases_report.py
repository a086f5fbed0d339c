"""The hard-case section of docs/bench.md: what the slide and the robust formulas get wrong on
every family of rtfgu.hardcases, per path and precision, and what the robust ones cost.

    from benchmarks.hardcases_report import hardcases_markdown, speed_error_points
    text = hardcases_markdown()          # markdown, to paste into docs/bench.md
    points = speed_error_points()        # one dict per path x precision x formula, for the plot

Run as a script it prints the section; ``--families NAME ...`` prints only the table rows and
the descriptions of those families (no timing), for a family measured on its own.
"""
from __future__ import annotations

import math
import time
from functools import lru_cache

import numpy as np

from rtfgu.hardcases import FAMILIES, build, evaluate, runs
from rtfgu.hardcases.paths import NumbaPath, ReferencePath
from rtfgu.hardcases.wgsl_path import WgslPath, wgsl_unavailable_reason

SPEED_FAMILY = {"sphere": "sphere_far_small", "plane": "plane_nearly_parallel", "triangle": "tri_fan_edges"}


def _paths():
    paths = [ReferencePath("slide"), ReferencePath("robust")]
    paths += [NumbaPath(f, p) for p in ("float64", "float32") for f in ("slide", "robust")]
    if wgsl_unavailable_reason() is None:
        paths += [WgslPath("slide"), WgslPath("robust")]
    return paths


@lru_cache(maxsize=None)
def hardcase_results(families: tuple | None = None) -> tuple:
    """Every (family, path) Result of ``families`` (None: every family); a lecture-layer
    rejection is recorded as its message. A path without a formula for the family's kind
    (the disk's robust one) is left out."""
    rows = []
    for name in families or FAMILIES:
        for path in _paths():
            if not runs(build(name, path.precision), path):
                continue
            try:
                rows.append(evaluate(build(name, path.precision), path))
            except ValueError as error:
                rows.append((name, path.name, path.formula, path.precision, str(error)))
    return tuple(rows)


def _fmt(x: float) -> str:
    return "-" if x is None or math.isnan(x) else "%.1e" % x


def _rays_per_second(fn, *args, repeat: int = 3) -> float:
    fn(*args)  # compile or warm up
    best = math.inf
    for _ in range(repeat):
        start = time.perf_counter()
        fn(*args)
        best = min(best, time.perf_counter() - start)
    return args[-2].shape[0] / best  # rays: the rows of tmax


@lru_cache(maxsize=None)
def speed_rows(rays: int = 200_000) -> tuple:
    """Rays/s of the numba batch evaluators (and the WGSL program) per shape kind, slide and
    robust, on a family tiled to ``rays`` rays."""
    from rtfgu.kernels import robust as kernels
    rows = []
    for kind_name, family_name in SPEED_FAMILY.items():
        for precision in ("float64", "float32"):
            fam = build(family_name, precision)
            reps = -(-rays // fam.size)
            o = np.ascontiguousarray(np.tile(fam.origins, (reps, 1))[:rays])
            d = np.ascontiguousarray(np.tile(fam.directions, (reps, 1))[:rays])
            lo = np.ascontiguousarray(np.tile(fam.tmin, reps)[:rays])
            hi = np.ascontiguousarray(np.tile(fam.tmax, reps)[:rays])
            s = np.ascontiguousarray(np.tile(fam.shapes[0], (reps, 1))[:rays])
            speeds = {}
            for formula in ("slide", "robust"):
                adapter, finite = kernels.ADAPTERS[kind_name, formula]
                speeds[formula] = _rays_per_second(kernels.batch, adapter, finite, o, d, lo, hi, s)
            rows.append(dict(kind=kind_name, path="numba", precision=precision, **speeds))
            if precision == "float32" and wgsl_unavailable_reason() is None:
                speeds = {}
                for formula in ("slide", "robust"):
                    path = WgslPath(formula)
                    speeds[formula] = _rays_per_second(
                        path, kind_name, o, d, lo, hi, s, repeat=2)
                rows.append(dict(kind=kind_name, path="wgsl", precision=precision, **speeds))
    return tuple(rows)


def speed_error_points(rays: int = 200_000) -> list:
    """One point per path x precision x formula: total wrong decisions over all families
    (invalid input excluded), median relative error of t, and mean rays/s over the kinds."""
    results = [r for r in hardcase_results() if not isinstance(r, tuple)]
    speed = {}
    for row in speed_rows(rays):
        for formula in ("slide", "robust"):
            speed.setdefault((row["path"], row["precision"], formula), []).append(row[formula])
    points = []
    for (path, precision, formula), values in sorted(speed.items()):
        mine = [r for r in results if (r.path, r.precision, r.formula) == (path, precision, formula)
                and FAMILIES[r.family][0] != "invalid"]
        med = [r.rel_err_median for r in mine if not math.isnan(r.rel_err_median)]
        points.append(dict(path=path, precision=precision, formula=formula,
                           rays_per_second=float(np.mean(values)),
                           wrong=int(sum(r.wrong for r in mine)),
                           rel_err_median=float(np.median(med)) if med else float("nan")))
    return points


def table_rows(results) -> list:
    """The rows of the hard-case table for ``results`` (hardcase_results)."""
    out = []
    for r in results:
        if isinstance(r, tuple):
            name, path, formula, precision, message = r
            out.append("| %s | %s | %s | %s | ValueError: %s | | | | |"
                       % (name, path, precision, formula, message.split(",")[0]))
            continue
        spawn = "%d/%d" % (r.self_hits, r.skips) if FAMILIES[r.family][0] == "secondary" else "-"
        out.append("| %s | %s | %s | %s | %d | %d | %s | %s | %s |"
                   % (r.family, r.path, r.precision, r.formula, r.wrong, r.leaks, spawn,
                      _fmt(r.rel_err_median), _fmt(r.rel_err_max)))
    return out


def family_lines(names) -> list:
    """The list entries of the families ``names`` under "### Families"."""
    return ["- `%s` (%s): %s" % (name, FAMILIES[name][0], FAMILIES[name][3]) for name in names]


def hardcases_markdown(rays: int = 200_000) -> str:
    """The hard-case section of docs/bench.md, measured now."""
    out = ["## Hard cases", "",
           "Seeded families from `rtfgu.hardcases`, %d rays each, with exact truth (rationals, "
           "50-digit square roots; a torus's root isolated by Sturm's theorem in rationals, then at "
           "50 digits). *wrong*: wrong hit/miss decisions (for secondary rays also "
           "self-hits and skipped real hits); *leaks*: true hits the path missed; *self/skip*: "
           "secondary rays that re-hit their own surface / passed the real hit just beyond; "
           "*rel. err.*: median and maximum |t - t_exact| / t_exact over rays both hit. "
           "`reference` is the lecture layer (Python, float64)." % build("sphere_tangent", "float64").size,
           ""]
    missing = wgsl_unavailable_reason()
    if missing is not None:
        out += ["WGSL float32 path not measured: %s" % missing, ""]
    out += ["| family | path | precision | formula | wrong | leaks | self/skip | rel. err. median | rel. err. max |",
            "|---|---|---|---|---:|---:|---:|---:|---:|"]
    out += table_rows(hardcase_results())
    out += ["", "### Families", ""]
    out += family_lines(FAMILIES)
    out += ["", "### Speed cost of the robust formulas", "",
            "Rays per second of the batch evaluators (one shape per ray, %d rays, best of 3; "
            "WGSL includes upload and read-back)." % rays, "",
            "| shape | path | precision | slide rays/s | robust rays/s | robust / slide |",
            "|---|---|---|---:|---:|---:|"]
    for row in speed_rows(rays):
        out.append("| %s | %s | %s | %.3g | %.3g | %.2f |"
                   % (row["kind"], row["path"], row["precision"], row["slide"], row["robust"],
                      row["robust"] / row["slide"]))
    out += ["", "### Speed against error (data of the plot)", "",
            "| path | precision | formula | rays/s | wrong decisions (all families) | median rel. err. |",
            "|---|---|---|---:|---:|---:|"]
    for p in speed_error_points(rays):
        out.append("| %s | %s | %s | %.3g | %d | %s |" % (p["path"], p["precision"], p["formula"],
                                                          p["rays_per_second"], p["wrong"],
                                                          _fmt(p["rel_err_median"])))
    return "\n".join(out) + "\n"


def main(argv=None) -> None:
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--families", nargs="+", metavar="NAME",
                        help="print only these families' table rows and descriptions, untimed")
    args = parser.parse_args(argv)
    if not args.families:
        print(hardcases_markdown())
        return
    unknown = [name for name in args.families if name not in FAMILIES]
    if unknown:
        parser.error("no hard-case family %s (rtfgu.hardcases.FAMILIES)" % ", ".join(unknown))
    missing = wgsl_unavailable_reason()
    if missing is not None:
        print("WGSL float32 path not measured: %s" % missing)
    print("\n".join(table_rows(hardcase_results(tuple(args.families)))))
    print()
    print("\n".join(family_lines(args.families)))


if __name__ == "__main__":
    main()
