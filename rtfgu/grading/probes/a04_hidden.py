"""Probes of a04's hidden tests."""
from __future__ import annotations

from .a04 import PI3, _lambert_cases


def observe_lambert_more(rt):
    return _lambert_cases(rt, [
        ([((0, 1, 0), PI3), ((2, 1, 0), (1, 2, 3))], (0.5, 0, 0), (0, 1, 0), (0.8, 0.6, 0.4), (0, 0, 0)),
        ([((0, 1, 0), PI3)], (0, 0, 0), (0, 1, 0), (0.2, 0.2, 0.2), (0.5, 0.25, 0)),
        ([((1, 1, 1), (2, 2, 2)), ((-1, 1, 1), (2, 0, 2)), ((0, -1, 0), (9, 9, 9))], (0, 0, 0),
         (0, 1, 1), (0.3, 0.6, 0.9), (0, 0, 0)),
    ])
