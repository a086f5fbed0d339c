"""Shared by the tests that use a benchmark's scene: benchmarks/ is a folder of scripts, not
a package, so a script is loaded from its file, once per test process."""
from __future__ import annotations

import functools
import importlib.util
from pathlib import Path

BENCHMARKS = Path(__file__).resolve().parent.parent / "benchmarks"


@functools.lru_cache(maxsize=None)
def benchmark_script(name: str):
    """The module of benchmarks/<name>.py."""
    spec = importlib.util.spec_from_file_location("rtfgu_benchmark_" + name, BENCHMARKS / (name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
