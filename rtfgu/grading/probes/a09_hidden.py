"""Probes of a09's hidden tests: a sharp Phong lobe and the corners of the unit square for
hemisphere_map, and Lambertian.sample_f about more normals with coloured albedos."""
from __future__ import annotations

from .a09 import observe_hemisphere, observe_hemisphere_points, observe_sample_f

CORNER = 1.0 - 2.0 ** -53       # the largest uniform number below 1


def observe_lobe_and_corners(rt, count: int, seed: int):
    points = [[x, y, e] for e in (0.0, 1.0, 1000.0) for x in (0.0, CORNER) for y in (0.0, CORNER)]
    return dict(observe_hemisphere(rt, [100], count, seed), **observe_hemisphere_points(rt, points))


def observe_sample_f_more(rt, count: int, seed: int):
    normals = [[0.0, 1.0, 0.0], [0.26726124191242440, -0.53452248382484879, 0.80178372573727319]]
    rhos = [[0.25, 0.5, 0.75], [0.9, 0.6, 0.3]]
    return observe_sample_f(rt, normals, rhos, count, seed)
