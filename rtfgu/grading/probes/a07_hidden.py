"""Probes of a07's hidden tests."""
from __future__ import annotations

from .a07 import WIDE, lookup_cases, lookups_with

# 2 texels wide, 5 high (row 0 at the top), and a single texel.
TALL = [
    [[0.125, 0.875, 0.5], [1.0, 0.25, 0.0]],
    [[0.5, 0.0, 0.75], [0.25, 0.625, 1.0]],
    [[0.875, 0.375, 0.125], [0.0, 0.5, 0.25]],
    [[0.375, 1.0, 0.625], [0.75, 0.125, 0.875]],
    [[0.625, 0.25, 0.0], [0.5, 0.75, 0.375]],
]
ONE = [[[0.25, 0.5, 0.875]]]


def observe_seam(rt):
    return lookup_cases(rt, WIDE, lookups_with(
        "bilinear", "repeat",
        (0.0, 0.5, "u = 0: halfway between the right column and the left one"),
        (0.03125, 0.5, "just right of u = 0: mostly the left column, some of the right one"),
        (0.96875, 0.5, "just left of u = 1: mostly the right column, some of the left one"),
        (0.375, 1.0, "v = 1: halfway between the top row and the bottom one"),
        (0.375, 0.0625, "near v = 0: the bottom row and some of the top one"),
        (0.0, 0.0, "the corner: the mean of the four corner texels"),
        (-1.0, 2.0, "a corner of another period: the same mean"),
    ) + lookups_with("nearest", "repeat", (1.0, 0.5, "u = 1 under repeat is u = 0: the left column")))


def observe_one_texel_and_tall(rt):
    out = lookup_cases(rt, ONE, [(f, a, u, v, "a single texel: its colour everywhere")
                                 for f in ("nearest", "bilinear") for a in ("repeat", "clamp")
                                 for u, v in ((0.5, 0.5), (0.1, 0.9), (1.0, 0.0), (-0.3, 1.7))])
    tall = lookup_cases(rt, TALL, [
        ("nearest", "repeat", 0.25, 0.9, "the centre of texel (0, 0)"),
        ("nearest", "repeat", 0.75, 0.1, "the centre of texel (1, 4)"),
        ("nearest", "clamp", 0.6, 0.45, "inside texel (1, 2)"),
        ("nearest", "clamp", 1.5, 0.35, "u above 1: the right column, row 3"),
        ("bilinear", "repeat", 0.5, 0.6, "halfway between the columns, rows 1 and 2"),
        ("bilinear", "repeat", 0.375, 0.25, "between four texel centres"),
        ("bilinear", "clamp", 0.875, 0.95, "near the top-right corner"),
        ("bilinear", "repeat", 0.0, 0.95, "across the seam at u = 0 near the top"),
    ])
    out["cases"] += tall["cases"]
    return out
