"""Probes of a07's visible tests: texture lookup (02562 worksheet 3; Suffern ch. 29, "Image
Textures"): ImageTexture.texel's addressing and get_color's nearest and bilinear filters.

Every texture here is built from its texels (``ImageTexture(texels=...)``, height x width x 3,
row 0 at the top), in eighths, every texel a colour of its own."""
from __future__ import annotations

from .support import Cases, vec

# 4 texels wide, 3 high; row 0 is the top row (v = 1).
WIDE = [
    [[0.125, 0.5, 1.0], [0.25, 0.0, 0.5], [1.0, 0.875, 0.0], [0.375, 0.625, 0.25]],
    [[0.0, 0.25, 0.75], [0.5, 0.5, 0.5], [0.75, 0.125, 0.375], [0.875, 1.0, 0.125]],
    [[0.625, 0.75, 0.0], [0.25, 0.375, 0.875], [0.0, 1.0, 0.625], [0.5, 0.125, 0.25]],
]


def _size(texels) -> str:
    return "%d x %d" % (len(texels[0]), len(texels))


def texture(rt, texels, filter="nearest", address="repeat"):
    """The student's ImageTexture of these texels (a list of rows, each a list of [r, g, b])."""
    import numpy as np

    return rt.textures.ImageTexture(texels=np.array(texels, dtype=np.float64), filter=filter, address=address)


def texel_cases(rt, texels, address, indices):
    """texel(i, j) for each (i, j, what) of ``indices``."""
    cases = Cases()
    for i, j, what in indices:
        def run(i=i, j=j):
            return {"color": vec(texture(rt, texels, "nearest", address).texel(i, j), "texel's result")}
        cases.run("%s texture, %s: texel(%d, %d) (%s)" % (_size(texels), address, i, j, what), run,
                  texels=texels, address=address, i=i, j=j)
    return cases.result()


def lookup_cases(rt, texels, lookups):
    """get_color(u, v) for each (filter, address, u, v, what) of ``lookups``."""
    cases = Cases()
    for filter, address, u, v, what in lookups:
        def run(filter=filter, address=address, u=u, v=v):
            return {"color": vec(texture(rt, texels, filter, address).get_color(u, v), "get_color's result")}
        cases.run("%s texture, %s, %s: get_color(%.6g, %.6g) (%s)" % (_size(texels), filter, address, u, v, what),
                  run, texels=texels, filter=filter, address=address, u=u, v=v)
    return cases.result()


def lookups_with(filter, address, *points):
    """(filter, address, u, v, what) for each (u, v, what) of ``points``: lookup_cases' lookups
    that share a filter and an addressing."""
    return [(filter, address, u, v, what) for u, v, what in points]


def centre(i, j, width=4, height=3):
    """(u, v) of the centre of texel (i, j) (column i, row j from the top)."""
    return (i + 0.5) / width, 1.0 - (j + 0.5) / height


def _wide_texel_indices(row, column):
    """(i, j, what) for texel(i, j) on WIDE: two corners and a texel inside, one past each edge
    (in row ``row`` beside the left and right edges, in column ``column`` above and below),
    and far outside."""
    return [
        (0, 0, "the top-left texel"), (3, 2, "the bottom-right texel"), (2, 1, "inside"),
        (4, row, "one column past the right edge"), (-1, row, "one column left of the left edge"),
        (column, 3, "one row below the bottom"), (column, -1, "one row above the top"),
        (-5, -4, "far up and to the left"), (9, 7, "far down and to the right"),
    ]


def observe_texel_repeat(rt):
    return texel_cases(rt, WIDE, "repeat", _wide_texel_indices(row=0, column=1))


def observe_texel_clamp(rt):
    return texel_cases(rt, WIDE, "clamp", _wide_texel_indices(row=1, column=2))


def observe_nearest(rt):
    lookups = []
    for i, j in [(0, 0), (3, 0), (1, 1), (2, 1), (0, 2), (3, 2)]:
        u, v = centre(i, j)
        lookups.append(("nearest", "repeat", u, v, "the centre of texel (%d, %d)" % (i, j)))
    lookups += [
        ("nearest", "repeat", 0.01, 0.99, "near the top-left corner: v = 1 is the top row"),
        ("nearest", "repeat", 0.99, 0.01, "near the bottom-right corner"),
        ("nearest", "repeat", 0.3, 0.7, "off-centre inside texel (1, 0)"),
        ("nearest", "clamp", 0.7, 0.3, "off-centre inside texel (2, 2)"),
        ("nearest", "clamp", 0.45, 0.55, "off-centre inside texel (1, 1)"),
    ]
    return lookup_cases(rt, WIDE, lookups)


def observe_bilinear(rt):
    lookups = []
    for address, i, j in [("repeat", 1, 1), ("repeat", 2, 1), ("clamp", 1, 0)]:
        u, v = centre(i, j)
        lookups.append(("bilinear", address, u, v, "the centre of texel (%d, %d): that texel alone" % (i, j)))
    lookups += [
        ("bilinear", "repeat", 0.5, centre(0, 1)[1], "halfway between the centres of texels (1, 1) and (2, 1)"),
        ("bilinear", "clamp", centre(2, 0)[0], 2.0 / 3.0, "halfway between the centres of texels (2, 0) and (2, 1)"),
        ("bilinear", "repeat", 0.25, 2.0 / 3.0, "halfway between the centres of texels (0, 0), (1, 0), (0, 1), (1, 1)"),
        ("bilinear", "clamp", 0.75, 1.0 / 3.0, "halfway between the centres of texels (2, 1), (3, 1), (2, 2), (3, 2)"),
        ("bilinear", "repeat", 0.3, 0.6, "between texel centres, unequal weights"),
        ("bilinear", "clamp", 0.5625, 0.3125, "between texel centres, unequal weights"),
    ]
    return lookup_cases(rt, WIDE, lookups)


def observe_repeat(rt):
    return lookup_cases(rt, WIDE, lookups_with(
        "nearest", "repeat",
        (1.3, 0.7, "u above 1"),
        (-0.7, 0.7, "u below 0"),
        (0.45, 1.8, "v above 1"),
        (0.45, -1.2, "v below 0"),
        (-2.6, 3.1, "several periods away"),
    ) + lookups_with(
        "bilinear", "repeat",
        (1.3, 0.6, "u above 1"),
        (-0.7, -0.4, "u and v below 0"),
        (2.5625, 1.3125, "several periods away"),
    ))


def observe_clamp(rt):
    return lookup_cases(rt, WIDE, lookups_with(
        "nearest", "clamp",
        (1.3, 0.7, "u above 1: the right column"),
        (1.0, 0.5, "u = 1 exactly: the right column"),
        (-0.7, 0.5, "u below 0: the left column"),
        (0.3, 1.8, "v above 1: the top row"),
        (0.8, -1.2, "v below 0: the bottom row"),
        (2.0, -3.0, "beyond the bottom-right corner"),
    ) + lookups_with(
        "bilinear", "clamp",
        (1.3, 0.5, "u above 1: the right column"),
        (-0.5, 1.5, "beyond the top-left corner: the corner texel"),
        (0.05, 0.6, "inside, less than half a texel from the left edge"),
        (0.7, 0.02, "inside, less than half a texel from the bottom edge"),
    ))
