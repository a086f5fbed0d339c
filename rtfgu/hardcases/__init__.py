# release: solves a03
"""Hard cases for ray/shape intersection: seeded families with exact truth, the
paths they run through, and the evaluator that counts what each path gets wrong.

    from rtfgu.hardcases import FAMILIES, build, evaluate, available_paths
    family = build("sphere_far_small", "float32")
    result = evaluate(family, NumbaPath("slide", "float32"))   # result.wrong, .leaks, ...
"""
from .evaluate import Result, evaluate
from .families import FAMILIES, Family, build
from .kinds import KINDS
from .paths import FORMULAS, NumbaPath, ReferencePath, available_paths, runs

__all__ = ["FAMILIES", "FORMULAS", "Family", "KINDS", "NumbaPath", "ReferencePath", "Result",
           "available_paths", "build", "evaluate", "runs"]
