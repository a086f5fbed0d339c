"""a10: Suffern's multi-jittered sampler and Shirley and Chiu's concentric map (Suffern ch. 5,
"Multi-Jittered Sampling"; ch. 6, "Mapping Samples to a Unit Disk"). The probes are in
rtfgu/grading/probes/a10.py.

The sampler's tests hold its contract, not its numbers: a correct MultiJittered whose random
numbers are drawn in another order makes other points, equally good. Every set must have one
point in each cell of the n x n grid and one in each column and row of the n^2 x n^2 subgrid
(exact, counted); the sets must be shuffled (no set, and no two sets alike, in the canonical
arrangement's order); the seed must decide them (the sampler's own stream). The map is
checked at points whose images the solution gives (the centre, the middles of the edges, a
point in each region) and by the distribution of 8192 mapped points (chi-square: uniform on the
disk makes r^2 and phi uniform).
"""
from __future__ import annotations

import math

import numpy as np

from . import Check, fmt, known_mistake_hint, register
from ..probes.a10 import bin_disk
from .statistics import CHI_SQUARE_ALPHA, chi_square_p, worst_cell

SEED = 10
COUNT = 8192                # mapped points: 128 per bin of 8 x 8
SETS = 24                   # sets per sampler in the structure tests
SAMPLER = ("sampling/multi_jittered.py",)
MAPS = ("sampling/maps.py",)
SHOWN = 4                   # problems shown per test


def _cells(points, n: int):
    """(grid cells, subgrid columns, subgrid rows) of one set, as index arrays."""
    p = np.asarray(points, dtype=np.float64)
    column, row = np.floor(p[:, 0] * n).astype(int), np.floor(p[:, 1] * n).astype(int)
    return row * n + column, np.floor(p[:, 0] * n * n).astype(int), np.floor(p[:, 1] * n * n).astype(int)


def structure_problems(entry) -> list:
    """What is wrong with the sets of one MultiJittered (their structure), in words."""
    count, sets, points = entry["num_samples"], entry["num_sets"], entry["points"]
    n = math.isqrt(count)
    if len(points) != count * sets:
        return ["MultiJittered(%d, num_sets=%d) made %d points, not %d sets of %d" % (
            count, sets, len(points), sets, count)]
    problems = []
    for s in range(sets):
        chunk = points[s * count:(s + 1) * count]
        outside = [p for p in chunk if not (0.0 <= p[0] < 1.0 and 0.0 <= p[1] < 1.0)]
        if outside:
            problems.append("set %d of MultiJittered(%d): the point %s is outside [0, 1)^2" % (s, count, fmt(outside[0])))
            continue
        cells, columns, rows = _cells(chunk, n)
        for what, grid, index, size, hint in (
                ("cell", "the %d x %d grid" % (n, n), cells, count, "jittered: one point per grid cell"),
                ("column", "the %d x %d subgrid" % (count, count), columns, count,
                 "n-rooks: one point per subgrid column; shuffle x only among the points of one grid column"),
                ("row", "the %d x %d subgrid" % (count, count), rows, count,
                 "n-rooks: one point per subgrid row; shuffle y only among the points of one grid row")):
            held = np.bincount(index, minlength=size)
            if held.max() > 1:
                twice, empty = int(np.argmax(held)), int(np.argmin(held))
                name = (lambda k: "(row %d, column %d)" % divmod(k, n)) if what == "cell" else (lambda k: "%d" % k)
                problems.append("set %d of MultiJittered(%d): %s %s of %s holds %d points and %s %s none (%s)"
                                % (s, count, what, name(twice), grid, int(held[twice]), what, name(empty), hint))
                break
        if len(problems) >= SHOWN:
            break
    return problems


def asked_sets(check, got) -> list:
    """The answer's sets, checked against what the test asked for (its probe's counts and
    num_sets), not against what the answer says of itself: an answer written by other code
    than the probe (student code can reach the pipe) could claim sets of one point, which
    have every structure, or millions of them, which take the judge minutes."""
    asked = check.probe[2]
    sets = got["sets"]
    if len(sets) != len(asked["counts"]) or any(
            entry["num_samples"] != n or entry["num_sets"] != asked["num_sets"]
            or len(entry["points"]) != n * asked["num_sets"] for entry, n in zip(sets, asked["counts"])):
        raise ValueError("the sets are not those the test asked for")
    return sets


def judge_structure(check, got, reference):
    if "error" in got:
        return 0.0, [got["error"]]
    right, lines = 0, []
    for entry in asked_sets(check, got):
        problems = structure_problems(entry)
        if problems:
            lines += ["- " + p for p in problems]
        else:
            right += 1
    return right / len(got["sets"]), lines


def _order(points, n: int) -> tuple:
    """The set's subcell of x and of y in the order of the grid cells (row by row): the same
    tuple for two sets shuffled alike."""
    cells, columns, rows = _cells(points, n)
    order = np.argsort(cells)
    return tuple(columns[order] % n) + tuple(rows[order] % n)


def judge_shuffled(check, got, reference):
    """No set in the canonical arrangement's order, and the sets not all shuffled alike."""
    if "error" in got:
        return 0.0, [got["error"]]
    entry = asked_sets(check, got)[0]
    if structure_problems(entry):
        return 0.0, ["the sets are not multi-jittered (the test of their structure says how), so their "
                     "shuffling cannot be judged"]
    count, sets, points = entry["num_samples"], entry["num_sets"], entry["points"]
    n = math.isqrt(count)
    orders = [_order(points[s * count:(s + 1) * count], n) for s in range(sets)]
    # Canonical: the point of grid cell (row r, column c) in x subcell c n + r, y subcell r n + c.
    canonical = tuple(r for r in range(n) for c in range(n)) + tuple(c for r in range(n) for c in range(n))
    lines = []
    unshuffled = sum(o == canonical for o in orders)
    if unshuffled > 1:
        lines.append("%d of your %d sets of MultiJittered(%d) are in the canonical arrangement's order: shuffle "
                     "x among the points of each grid column and y among those of each grid row (k = "
                     "rand_int(j, n - 1), then swap)" % (unshuffled, sets, count))
    elif len(set(orders)) < sets // 2:
        lines.append("your %d sets of MultiJittered(%d) are shuffled in only %d different ways: each set needs "
                     "its own shuffle, from new random numbers" % (sets, count, len(set(orders))))
    return (0.0, lines) if lines else (1.0, [])


def judge_seeded(check, got, reference):
    """The same seed twice gives the same points; another seed other points."""
    if "error" in got:
        return 0.0, [got["error"]]
    asked = check.probe[2]
    runs = got["runs"]
    if [run["seed"] for run in runs] != list(asked["seeds"]) or any(
            len(run["points"]) != asked["num_samples"] * asked["num_sets"] for run in runs):
        raise ValueError("the runs are not those the test asked for")
    first, again, other = runs[0]["points"], runs[1]["points"], runs[2]["points"]
    if first != again:
        return 0.0, ["MultiJittered(seed=%d) made other points the second time: draw every random number from "
                     "the sampler's own stream, self.rand_float() and self.rand_int(), which the seed starts"
                     % runs[0]["seed"]]
    if first == other:
        return 0.0, ["MultiJittered made the same points with seed %d and seed %d: the points must come from the "
                     "sampler's random stream (self.rand_float(), self.rand_int())" % (runs[0]["seed"], runs[2]["seed"])]
    return 1.0, []


SLIPS = (("polar", "this is the polar map (r = sqrt(x), phi = 2 pi y), uniform on the disk too, but not Shirley "
                   "and Chiu's concentric map, which keeps squares about the centre together"),
         ("unshifted", "map (x, y) to (sx, sy) = (2x - 1, 2y - 1) in [-1, 1]^2 first"),
         ("no_pi_over_4", "phi counts eighths of a turn (0 to 8 around the square): multiply it by pi / 4 "
                          "before the cosine and sine"))


def hint_concentric(inputs, want, got):
    def same(a, b):
        return isinstance(a, list) and isinstance(b, list) and all(
            isinstance(u, float) and abs(u - v) <= 1e-9 for u, v in zip(a, b))
    point = {"xy": [got.get("x"), got.get("y")]}
    return known_mistake_hint(SLIPS, inputs, {"xy": [want["x"], want["y"]]}, point, "xy", same)


# The centre, the middles of the four edges, a corner and a point inside each region.
POINTS = [[0.5, 0.5], [1.0, 0.5], [0.5, 1.0], [0.0, 0.5], [0.5, 0.0], [0.75, 0.5], [0.5, 0.75],
          [0.9, 0.6], [0.6, 0.9], [0.1, 0.4], [0.4, 0.1], [0.2, 0.85], [0.85, 0.2]]


def judge_disk(check, got, reference):
    """8192 uniform points mapped: all on the disk, uniform by r^2 and phi (chi-square)."""
    if "error" in got:
        return 0.0, [got["error"]]
    got = bin_disk(got["points"], check.probe[2]["count"], check.probe[2]["seed"])
    if got["n_bad"]:
        return 0.0, ["%d of %d mapped points are not on the unit disk, for example %s" % (
            got["n_bad"], got["count"], "; ".join("(%s, %s) to %s" % (fmt(a[0]), fmt(a[1]), fmt(b))
                                                  for a, b in got["bad"]))]
    counts = np.asarray(got["counts"], dtype=np.float64)
    p = chi_square_p(counts)
    if p >= CHI_SQUARE_ALPHA:
        return 1.0, []
    (i, j), seen, expected = worst_cell(counts)
    return 0.0, ["the %d mapped points are not uniform on the disk (chi-square p = %.2g, below %g): binned by r^2 "
                 "(which uniform points make uniform) the 8 rings hold %s of about %d each, by the angle %s; the cell "
                 "r^2 in [%g, %g), angle bin %d holds %d, about %d expected"
                 % (got["count"], p, CHI_SQUARE_ALPHA, [int(c) for c in counts.sum(axis=1)], got["count"] // 8,
                    [int(c) for c in counts.sum(axis=0)], i / 8, (i + 1) / 8, j, seen, round(expected))]


register("a10_samplers", [
    Check("MultiJittered.generate_samples: one point per grid cell and per subgrid column and row, in every set", 3,
          ("a10", "observe_sets", dict(counts=[4, 9, 16, 25], num_sets=SETS, seed=SEED)), kind="statistic",
          judge=judge_structure, reference=lambda: {}, needs=SAMPLER),
    Check("MultiJittered.generate_samples: every set is shuffled, and each its own way", 1,
          ("a10", "observe_sets", dict(counts=[16], num_sets=SETS, seed=SEED + 1)), kind="statistic",
          judge=judge_shuffled, reference=lambda: {}, needs=SAMPLER),
    Check("MultiJittered.generate_samples: the seed decides the points (the sampler's own random stream)", 1,
          ("a10", "observe_seeds", dict(num_samples=9, num_sets=4, seeds=[SEED, SEED, SEED + 7])), kind="statistic",
          judge=judge_seeded, reference=lambda: {}, needs=SAMPLER),
    Check("concentric_map: the centre, the middles of the edges and a point in each region", 3,
          ("a10", "observe_concentric", dict(points=POINTS)), hint=hint_concentric, known="concentric", needs=MAPS),
    Check("concentric_map: uniform points of the square are uniform on the disk (chi-square)", 2,
          ("a10", "observe_concentric_binned", dict(count=COUNT, seed=SEED)), kind="statistic", judge=judge_disk,
          reference=lambda: {"count": COUNT}, needs=MAPS),
    # ### BEGIN HIDDEN
    Check("MultiJittered.generate_samples with 1, 64 and 100 samples per set", 1,
          ("a10", "observe_sets", dict(counts=[1, 64, 100], num_sets=6, seed=SEED + 2)), kind="statistic",
          judge=judge_structure, reference=lambda: {}, visibility="hidden", needs=SAMPLER),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    Check("concentric_map on the diagonals and the axes, where the regions meet", 1,
          ("a10", "observe_concentric", dict(points=[[0.25, 0.25], [0.75, 0.75], [0.25, 0.75], [0.75, 0.25],
                                                      [0.5, 0.25], [0.25, 0.5], [1.0, 1.0], [0.0, 0.0]])),
          hint=hint_concentric, known="concentric", visibility="hidden", needs=MAPS),
    # ### END HIDDEN
])
