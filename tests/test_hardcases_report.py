"""The hard-case section of the bench report lists the slide formulas' measured failures."""
from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

from rtfgu.hardcases import NumbaPath, build, evaluate

REPORT = Path(__file__).resolve().parent.parent / "benchmarks" / "hardcases_report.py"


def _load():
    spec = importlib.util.spec_from_file_location("hardcases_report", REPORT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_report_lists_slide_failures():
    report = _load()
    text = report.hardcases_markdown(rays=2000)
    wrong = evaluate(build("sphere_far_small", "float32"), NumbaPath("slide", "float32")).wrong
    assert wrong > 0
    row = "| sphere_far_small | numba | float32 | slide | %d |" % wrong
    assert row in text, row
    leaks = evaluate(build("tri_fan_edges", "float64"), NumbaPath("slide", "float64")).leaks
    assert leaks > 0 and "| tri_fan_edges | numba | float64 | slide | %d | %d |" % (leaks, leaks) in text
    assert "Speed cost of the robust formulas" in text and "| sphere | numba | float32 |" in text
    points = report.speed_error_points(rays=2000)
    assert {(p["path"], p["precision"], p["formula"]) for p in points} >= {
        ("numba", "float32", "slide"), ("numba", "float32", "robust")}


def test_families_option_prints_only_those_rows_and_descriptions(capsys):
    report = _load()
    report.main(["--families", "instance_inside"])
    out = capsys.readouterr().out
    rows = [line for line in out.split("\n") if line.startswith("| ")]
    assert rows and all(line.startswith("| instance_inside | ") for line in rows), out
    wrong = evaluate(build("instance_inside", "float32"), NumbaPath("slide", "float32")).wrong
    assert "| instance_inside | numba | float32 | slide | %d |" % wrong in out
    assert "- `instance_inside` (instance): rays that start inside an ellipsoid" in out
    assert "Speed cost" not in out and "sphere_tangent" not in out


def test_families_option_names_an_unknown_family(capsys):
    report = _load()
    with pytest.raises(SystemExit) as stop:
        report.main(["--families", "instance_inside", "no_such_family"])
    assert stop.value.code == 2
    assert "no hard-case family no_such_family" in capsys.readouterr().err
