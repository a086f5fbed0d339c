"""Probes of a02's hidden tests."""
from __future__ import annotations

from .a02 import _ortho_cases, _pinhole_cases


def observe_ortho_hidden(rt):
    return _ortho_cases(rt, [(0.0, 4.0, -3.0, 3.0, 0.5, 10.0), (-1.0, 1.0, -1.0, 1.0, 1e-5, 100.0)])


def observe_pinhole_hidden(rt):
    return _pinhole_cases(rt, [((0.0, 0.0, 5.0), (0.0, 0.0, 0.0), (0.0, 1.0, 0.0), 2.0, 16 / 9),
                               ((-1.0, 3.0, 1.0), (1.0, 0.0, -2.0), (0.0, 1.0, 0.0), 1.5, 0.75)])
