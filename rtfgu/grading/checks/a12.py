"""a12: area lights, points drawn uniformly by area, Suffern's AreaLight and the AreaLighting
tracer (Suffern ch. 18, "Area Lights"; 02562 worksheets 5 and 7). The probes are in
rtfgu/grading/probes/a12.py.

The points are checked exactly at chosen (u, v) (the TODO names the map, which the numba and
WGSL paths share) and by their distribution: many points from uniform (u, v) must fall
evenly into 16 parts of equal area of the shape (chi-square), which catches a map that is
not uniform whatever its numbers. The light's methods are checked each on its own at chosen
points against their values, the hints naming the classic slips of rtfgu.grading.mistakes
(no square root, G without its square or its cosine, pdf = A); the tracer by the method it
calls; and Suffern's chapter-18 figure rendered by the lecture layer with AreaLighting.
"""
from __future__ import annotations

import numpy as np

from . import Check, close, fmt, known_mistake_hint, register
from .statistics import CHI_SQUARE_ALPHA, chi_square_p

SAMPLES = ("shapes/triangle.py", "shapes/rectangle.py")
LIGHT = ("lights/area_light.py",)
TRACER = ("tracers/area_lighting.py",)
COUNT = 4096                     # points per distribution test: 256 per part
SEED = 12


def _same(a, b) -> bool:
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(_same(u, v) for u, v in zip(a, b))
    return isinstance(a, float) and isinstance(b, float) and close(a, b, 1e-6, 1e-9)


SAMPLE_SLIPS = (
    ("no_sqrt", "your point is v0 + (e0 v + e1 (1 - v)) u, without the square root of u: such points crowd "
                "toward v0; uniform by area is v0 + (e0 v + e1 (1 - v)) sqrt(u)"),
    ("direct", "your point is v0 + u e0 + v e1, (u, v) taken as barycentric coordinates: it leaves the triangle "
               "where u + v > 1; the TODO's map is v0 + (e0 v + e1 (1 - v)) sqrt(u)"),
)


def hint_sample(inputs, want, got):
    return known_mistake_hint(SAMPLE_SLIPS, inputs, want, got, "point", _same)


TERM_SLIPS = {
    "G": (("G_unsquared", "your G is cos(theta_l) / d: the geometry factor divides by the distance squared, "
                          "cos(theta_l) / d^2"),
          ("G_no_cosine", "your G is 1 / d^2: it needs the cosine at the light too, cos(theta_l) = -n_l . w_i")),
    "pdf": (("pdf_area", "your pdf is the area A: a point uniform by area has the density 1 / A"),),
}


def hint_terms(inputs, want, got):
    for key, slips in TERM_SLIPS.items():
        hint = known_mistake_hint(slips, inputs, want, got, key, _same)
        if hint:
            return hint
    G = got.get("G")
    if isinstance(G, float) and G < 0.0:
        return "G is never negative: where the light is seen from behind (cos(theta_l) <= 0) it is 0"
    return None


def judge_uniform(check, got, reference):
    """COUNT points from uniform (u, v): all on the shape, evenly in its 16 parts (chi-square)."""
    if "error" in got:
        return 0.0, [got["error"]]
    if got["n_bad"]:
        return 0.0, ["%d of %d points are not on the %s, for example %s" % (
            got["n_bad"], got["count"], got["kind"],
            "; ".join("sample(%s, %s) = %s" % (fmt(a[0]), fmt(a[1]), fmt(b)) for a, b in got["bad"]))]
    counts = np.asarray(got["counts"], dtype=np.float64)
    p = chi_square_p(counts)
    if p >= CHI_SQUARE_ALPHA:
        return 1.0, []
    most, least = int(np.argmax(counts)), int(np.argmin(counts))
    return 0.0, ["the %d points are not uniform by area on the %s (chi-square p = %.2g, below %g): of its 16 parts "
                 "of equal area, about %d points each, one holds %d and another %d%s"
                 % (got["count"], got["kind"], p, CHI_SQUARE_ALPHA, got["count"] // 16, counts[most], counts[least],
                    " (the part at v0 holds %d)" % counts[0] if got["kind"] == "triangle" else "")]


TRIANGLE = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
TILTED = [[1.0, 2.0, -1.0], [3.0, 2.5, -1.0], [1.0, 3.0, 1.0]]
LAMP = [[-0.5, 2.0, -0.5], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]      # a rectangle facing down (a x b = -y)
SAMPLE_CASES = [("triangle", TRIANGLE, 0.25, 0.5), ("triangle", TRIANGLE, 1.0, 0.0), ("triangle", TILTED, 0.64, 0.25),
                ("triangle", TILTED, 0.0, 0.7), ("rectangle", LAMP, 0.25, 0.75), ("rectangle", LAMP, 0.5, 0.5)]
DOWN = [[-0.5, 2.0, 0.5], [-0.5, 2.0, -0.5], [0.5, 2.0, 0.5]]     # a triangle facing down
DIRECTION_CASES = [("triangle", DOWN, (0.0, 0.0, 0.0), 0.25, 0.5), ("rectangle", LAMP, (0.2, 0.0, -0.1), 0.25, 0.75),
                   ("rectangle", LAMP, (1.0, 0.5, 1.0), 0.5, 0.5)]
TERM_CASES = [("rectangle", LAMP, (1.0, 1.0, 1.0), (0.0, 2.0, 0.0), (0.0, 0.0, 0.0)),
              ("rectangle", LAMP, (2.0, 1.0, 0.5), (0.25, 2.0, 0.25), (1.0, 0.5, -0.5)),
              ("triangle", DOWN, (3.0, 3.0, 3.0), (0.0, 2.0, 0.0), (0.6, 0.0, 0.8)),
              ("rectangle", LAMP, (1.0, 1.0, 1.0), (0.0, 2.0, 0.0), (0.0, 3.0, 0.0))]     # from behind

register("a12_area_lights", [
    Check("Triangle.sample and Rectangle.sample: the points at chosen (u, v)", 2,
          ("a12", "observe_sample", dict(cases=SAMPLE_CASES)), hint=hint_sample, known="area_sample", needs=SAMPLES),
    Check("Triangle.sample: points from uniform (u, v) are uniform by area (chi-square)", 2,
          ("a12", "observe_sample_binned", dict(kind="triangle", corners=TILTED, count=COUNT, seed=SEED)),
          kind="statistic", judge=judge_uniform, reference=lambda: {"count": COUNT}, needs=SAMPLES),
    Check("AreaLight.get_direction: the point drawn, its normal and the direction toward it", 2,
          ("a12", "observe_direction", dict(cases=DIRECTION_CASES)), needs=SAMPLES + LIGHT),
    Check("AreaLight.G, pdf and incident: cos(theta_l) / d^2, 1 / A and L G / pdf, 0 from behind", 3,
          ("a12", "observe_light_terms", dict(cases=TERM_CASES)), hint=hint_terms, known="light_terms", needs=LIGHT),
    Check("AreaLighting.shade: the material's area_light_shade", 1, ("a12", "observe_tracer"), needs=TRACER),
    Check("image: Suffern's chapter-18 Cornell box under its lamp, AreaLighting (one point of the lamp per pixel)", 2,
          ("a12", "render_area_lighting", dict(width=24, height=24)), kind="image", size=(24, 24)),
    # ### BEGIN HIDDEN
    Check("Rectangle.sample: points from uniform (u, v) are uniform by area (chi-square)", 1,
          ("a12", "observe_sample_binned", dict(kind="rectangle", corners=LAMP, count=COUNT, seed=SEED + 1)),
          kind="statistic", judge=judge_uniform, reference=lambda: {"count": COUNT}, visibility="hidden",
          needs=SAMPLES),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    Check("AreaLight of a sphere: G, pdf and L G / pdf at points facing toward and away", 1,
          ("a12", "observe_light_terms", dict(cases=[
              ("sphere", [[0.0, 3.0, 0.0], [0.5]], (2.0, 2.0, 2.0), (0.0, 2.5, 0.0), (0.0, 0.0, 0.0)),
              ("sphere", [[0.0, 3.0, 0.0], [0.5]], (2.0, 2.0, 2.0), (0.3, 2.6, 0.0), (1.0, 0.0, 0.5)),
              ("sphere", [[0.0, 3.0, 0.0], [0.5]], (2.0, 2.0, 2.0), (0.0, 3.5, 0.0), (0.0, 0.0, 0.0))])),
          hint=hint_terms, known="light_terms", visibility="hidden", needs=LIGHT),
    # ### END HIDDEN
])
