"""a09's contract tests: hemisphere_map is Suffern's map, a function of its sample, and the pdf
Lambertian.sample_f returns is the density of its directions. Their inputs (points, normals,
the probe's stream) are drawn when the test runs; a correct sampler passes at every draw
(the calibration: docs/grading_sandbox.md), and the two planted cheats that pass every other
a09 test fail them."""
from __future__ import annotations

import json
import math
import random
from pathlib import Path

import numpy as np
import pytest

import rtfgu
from rtfgu.grading import probes
from rtfgu.grading.checks import Check, checks_for, drawn_inputs, stored_probe
from rtfgu.grading.checks import a09 as judges
from rtfgu.grading.checks.statistics import Z_LIMIT
from rtfgu.grading.generate import solution_files, write_files
from rtfgu.grading.grader import grade
from rtfgu.sampling.maps import hemisphere_map

from planted import make_submission

CHECKS = {c.number: c for c in checks_for("a09")}
MAP, DENSITY = CHECKS["9.6"], CHECKS["9.7"]
CONTRACT = (MAP.slug, DENSITY.slug)
SEEDS = 30


def _run_in_process(check: Check, rng):
    """(fraction, lines, answer, reference) of ``check`` with inputs drawn from ``rng``, its
    probe run here on the solution (the staff package), its answer through JSON as the
    grader receives it."""
    (module, function, kwargs), reference = drawn_inputs(check, rng)
    answer = json.loads(json.dumps(probes.run(module, function, kwargs, rtfgu)))
    fraction, lines = check.judge(check, answer, reference)
    return fraction, lines, answer, reference


def test_the_solution_passes_the_contract_tests_at_every_one_of_30_draws():
    worst_z, normals = 0.0, set()
    for seed in range(SEEDS):
        fraction, lines, _, _ = _run_in_process(MAP, random.Random("calibration/%d" % seed))
        assert fraction == 1.0, (seed, lines)
        fraction, lines, answer, reference = _run_in_process(DENSITY, random.Random("calibration/%d" % seed))
        assert fraction == 1.0, (seed, lines)
        for got, n in zip(answer["sets"], reference["drawn"]["normals"]):
            stats = judges.density_stats(n, got["samples"])
            worst_z = max(worst_z, float(np.abs(stats["z"]).max()))
            assert stats["n_off"] == 0
            normals.add(tuple(n))
    assert len(normals) == 2 * SEEDS             # every draw is a new frame
    assert 1.0 < worst_z < Z_LIMIT               # the cells' errors are noise of the size the test expects


@pytest.fixture(scope="module")
def contract_scores(tmp_path_factory):
    """name -> {test number: score} of the contract tests, graded in the sandbox."""
    out = {}
    for name in ("solution", "a09_own_rng", "a09_tuned_pdf"):
        folder = tmp_path_factory.mktemp(name)
        if name == "solution":
            write_files(solution_files("a09"), folder)
        else:
            make_submission(name, folder)
        result = grade("a09", folder, None, only=CONTRACT)
        out[name] = {t.number: (t.score, t.max_score, t.output) for t in result.tests}
    return out


def test_the_two_cheats_fail_the_contract_test_they_break_and_the_solution_passes_both(contract_scores):
    assert {n: s[:2] for n, s in contract_scores["solution"].items()} == {"9.6": (1.0, 1.0), "9.7": (2.0, 2.0)}
    own_rng, tuned = contract_scores["a09_own_rng"], contract_scores["a09_tuned_pdf"]
    assert own_rng["9.6"][0] == 0 and own_rng["9.7"][:2] == (2.0, 2.0)      # its directions are still right
    assert tuned["9.7"][0] == 0 and tuned["9.6"][:2] == (1.0, 1.0)
    assert "10 times" in tuned["9.7"][2] and "standard errors off" in tuned["9.7"][2]


def test_each_grading_draws_new_inputs_and_a_seed_draws_them_again(tmp_path):
    write_files(solution_files("a09"), tmp_path / "sub")

    def message(seed):
        return grade("a09", tmp_path / "sub", None, only=(DENSITY.slug,), seed=seed).tests[0].output
    fresh = [message(None) for _ in range(2)]
    assert fresh[0] != fresh[1] and "drawn for this grading" in fresh[0]
    assert message(7) == message(7)
    first, again = (drawn_inputs(DENSITY, random.Random(s))[1]["drawn"] for s in (1, 1))
    assert first == again and first != drawn_inputs(DENSITY, random.SystemRandom())[1]["drawn"]


def test_the_student_checker_runs_the_contract_tests_on_the_stored_draw():
    from rtfgu.grading.local import check, load_reference

    stored = load_reference(DENSITY)
    assert stored_probe(DENSITY, stored)[2]["normals"] == stored["drawn"]["normals"]
    result = check("a09", Path(rtfgu.__file__).resolve().parent.parent, only=CONTRACT)
    assert [(t.number, t.score) for t in result.tests] == [("9.6", 1.0), ("9.7", 2.0)]
    assert judges.fmt(stored["drawn"]["normals"][0]) in result.tests[1].output


def _samples(normal, count, seed, sample):
    """[x, y, z, pdf] of ``count`` directions about ``normal`` from sample(u, v) -> (local
    direction about +z, pdf), turned into the judge's own frame."""
    n = np.asarray(normal, dtype=np.float64)
    t, b = judges._frame(n)
    stream = np.random.default_rng(seed)
    out = []
    for u, v in stream.random((count, 2)):
        (x, y, z), pdf = sample(u, v)
        out.append(list(x * t + y * b + z * n) + [pdf])
    return out


def _cosine(u, v):
    c = math.sqrt(1.0 - v)
    s = math.sqrt(v)
    return (s * math.cos(2 * math.pi * u), s * math.sin(2 * math.pi * u), c), c / math.pi


def _uniform(u, v):
    c = 1.0 - v
    s = math.sqrt(1.0 - c * c)
    return (s * math.cos(2 * math.pi * u), s * math.sin(2 * math.pi * u), c), 1.0 / (2.0 * math.pi)


def _judge_density(sample, normal=(0.0, 0.6, 0.8)):
    # as many samples as the test draws: the judge takes no other count
    answer = {"sets": [{"normal": list(normal), "samples": _samples(normal, DENSITY.probe[2]["count"], 3, sample)}]}
    return judges.judge_pdf_density(DENSITY, answer, {"drawn": {"normals": [list(normal)]}})


def test_the_density_judge_passes_any_sampler_with_its_own_pdf_and_names_a_wrong_one():
    assert _judge_density(_cosine)[0] == 1.0
    fraction, lines = _judge_density(_uniform)
    assert fraction == 1.0 and "at every direction" not in lines[0]    # not cosine-weighted: the histogram only
    # cosine-weighted directions whose pdf is off by a factor that averages out over phi
    fraction, lines = _judge_density(lambda u, v: (_cosine(u, v)[0], _cosine(u, v)[1] * (0.5 if u < 0.5 else 1.5)))
    assert fraction == 0.0 and "standard errors off" in lines[0] and "(n . w_i) / pi at each" in lines[0]
    # a direction that is no direction
    fraction, lines = _judge_density(lambda u, v: ((math.nan, 0.0, 1.0) if u < 0.01 else _cosine(u, v)[0],
                                                   _cosine(u, v)[1]))
    assert fraction == 0.0 and "not a unit direction" in lines[0]


def test_the_cells_exact_values_are_their_integrals():
    """Each cell's solid angle (projected in the horizon band) and the second moment of its
    weight for cosine-weighted directions, against a midpoint rule in cos(theta)."""
    truth, squares = judges.cell_moments()
    mu = (np.arange(200000) + 0.5) / 200000
    dphi = 2 * math.pi / judges.PHI_BINS
    for i in range(judges.COS_BINS):
        inside = (mu >= i / judges.COS_BINS) & (mu < (i + 1) / judges.COS_BINS)
        weight = mu if i == 0 else np.ones_like(mu)
        assert truth[i, 0] == pytest.approx((weight * inside).sum() / len(mu) * dphi, rel=1e-6)
        assert squares[i, 0] == pytest.approx((weight ** 2 * math.pi / mu * inside).sum() / len(mu) * dphi, rel=1e-3)
    assert truth.sum() == pytest.approx(2 * math.pi * (1 - 1 / judges.COS_BINS) + math.pi / judges.COS_BINS ** 2)


def test_the_map_judge_names_a_map_that_is_not_suffern_s():
    points = judges.draw_map_points(random.Random(4))["points"]
    reference = dict(judges.map_reference(points), drawn={"points": points})
    right = [{"in": p, "out": d} for p, d in zip(points, reference["out"])]
    assert judges.judge_map_contract(MAP, {"first": right, "second": right}, reference)[0] == 1.0
    swapped = [{"in": [x, y, e], "out": list(hemisphere_map(y, x, e))} for x, y, e in points]
    fraction, lines = judges.judge_map_contract(MAP, {"first": swapped, "second": swapped}, reference)
    assert fraction == 0.0 and "not where Suffern's map puts them" in lines[0]
    fraction, lines = judges.judge_map_contract(MAP, {"first": right, "second": swapped}, reference)
    assert fraction == 0.0 and "another direction the second time" in lines[0]
    # a map that is a function of its arguments but not a direction: wrong, not "changed"
    nan = [{"in": p, "out": [math.nan, 0.0, 1.0]} for p in points]
    fraction, lines = judges.judge_map_contract(MAP, {"first": nan, "second": nan}, reference)
    assert fraction == 0.0 and "not where Suffern's map puts them" in lines[0]
