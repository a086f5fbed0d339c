"""The hard-case section of the bench report lists the slide formulas' measured failures."""
from __future__ import annotations

import importlib.util
from pathlib import Path

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
