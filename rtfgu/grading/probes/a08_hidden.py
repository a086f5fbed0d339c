"""Probes of a08's hidden tests: the slab test on a box's faces, edges and corners, on boxes
of zero thickness, from the box's boundary and where rounding decides; the BVH's tie rule
in any visiting order and a random scene."""
from __future__ import annotations

import math
import random

from .a08 import INF, VARIANTS, box_cases, bvh_cases

def _join(*results):
    out = {"cases": []}
    for result in results:
        out["cases"] += result["cases"]
    return out


def observe_box_edges_and_flat(rt):
    box = ([-1.0, 0.5, -4.0], [3.0, 2.0, -2.0])
    flat = ([0.0, 0.0, 1.0], [2.0, 2.0, 1.0])      # zero thickness along z
    point = ([1.0, 1.0, 1.0], [1.0, 1.0, 1.0])
    return _join(box_cases(rt, [
        ((-3.0, -1.5, -3.0), (1.0, 1.0, 0.0), 0.0, INF, "enters through the edge x = -1, y = 0.5"),
        ((-3.0, 0.0, -3.0), (1.0, 1.0, 0.0), 0.0, INF, "touches the edge x = -1, y = 2 and nothing else"),
        ((-3.0, 0.0, -6.0), (1.0, 1.0, 1.0), 0.0, INF, "touches the corner (-1, 2, -4) and nothing else"),
        ((-3.0, 0.25, -6.0), (1.0, 1.0, 1.0), 0.0, INF, "passes the corner (-1, 2, -4) a quarter above it"),
        ((-1.0, -1.0, -3.0), (0.0, 1.0, 0.125), 0.0, INF, "in the plane of the face x = -1"),
        ((-1.0, -1.0, -2.0), (0.0, 1.0, 0.0), 0.0, INF, "along the edge x = -1, z = -2"),
        ((3.0, 3.0, -4.0), (0.0, -0.5, 0.0), 0.0, INF, "along the edge x = 3, z = -4, downward"),
    ]), box_cases(rt, [
        ((1.0, 1.0, 3.0), (0.0, 0.0, -1.0), 0.0, INF, "straight through the flat box"),
        ((-1.0, -1.0, 3.0), (1.0, 1.0, -1.0), 0.0, INF, "obliquely through the flat box"),
        ((-1.0, -1.0, 3.0), (1.0, 1.0, -0.5), 0.0, INF, "crosses z = 1 outside the flat box"),
        ((-1.0, 1.0, 1.0), (1.0, 0.0, 0.0), 0.0, INF, "in the flat box's plane"),
        ((-1.0, 1.0, 1.5), (1.0, 0.0, 0.0), 0.0, INF, "parallel to the flat box, above it"),
        ((1.0, 1.0, -1.0), (0.0, 0.0, 1.0), 0.0, 2.0, "up to tmax exactly at the flat box"),
    ], flat), box_cases(rt, [
        ((0.0, 0.0, 0.0), (1.0, 1.0, 1.0), 0.0, INF, "through a box that is one point"),
        ((0.0, 0.0, 0.0), (1.0, 1.0, 0.5), 0.0, INF, "past a box that is one point"),
        ((1.0, 1.0, 1.0), (-1.0, 0.5, 0.25), 0.0, INF, "from a box that is one point"),
    ], point))


def observe_box_boundary_and_rounding(rt):
    box = ([-1.0, 0.5, -4.0], [3.0, 2.0, -2.0])
    return _join(box_cases(rt, [
        ((3.0, 1.0, -3.0), (1.0, 0.125, 0.125), 0.0, INF, "from the face x = 3, leaving: it touches at t = 0"),
        ((3.0, 1.0, -3.0), (1.0, 0.125, 0.125), 1e-05, INF, "from the face x = 3, leaving, tmin 1e-5"),
        ((-1.0, 1.0, -3.0), (1.0, 0.125, 0.125), 0.0, INF, "from the face x = -1, entering"),
        ((-1.0, 0.5, -4.0), (1.0, 1.0, 1.0), 0.0, INF, "from the corner p0, entering"),
        ((3.0, 2.0, -2.0), (1.0, 1.0, 1.0), 0.0, INF, "from the corner p1, leaving"),
        ((3.0, 2.0, -2.0), (1.0, 1.0, 1.0), 0.5, INF, "from the corner p1, leaving, tmin 0.5"),
        ((1.0, 1.0, -3.0), (0.0, 0.0, 1.0), 1.0, INF, "from inside, tmin exactly at the face z = -2"),
    ], box),
        # Decimal numbers: the ray meets the edge exactly (in the floats' own values) where it
        # enters one slab and leaves the other, and rounding puts t_near after t_far.
        box_cases(rt, [((-0.2, 0.3, 0.0), (0.2, -0.3, 0.0), 0.0, INF,
                        "touches the edge x = 0.4, y = -0.6 at t = 3, where rounding decides")],
                  ([0.4, -0.6, -1.0], [1.4, 0.4, 1.0])),
        box_cases(rt, [((-1.0, 3.0, 0.0), (0.5, -1.5, 0.0), 0.0, INF,
                        "grazes the edge x = -0.2, y = 0.6 near t = 1.6, where rounding decides")],
                  ([-0.2, 0.6, -1.0], [0.8, 1.6, 1.0])),
        box_cases(rt, [((-0.6, 2.9, 0.5), (1.0, -1.4, 0.0), 0.0, INF,
                        "touches the edge x = 0.9, y = 0.8 at t = 1.5, where rounding decides")],
                  ([0.9, 0.8, 0.0], [1.9, 1.8, 1.0])))


# --- the BVH ------------------------------------------------------------------------------

def _q(rng, lo, hi, step=0.125):
    """A random multiple of ``step`` in [lo, hi]."""
    return step * rng.randint(math.ceil(lo / step), math.floor(hi / step))


def random_scene(seed: int, n: int):
    """``n`` spheres and triangles at random, every number a multiple of 1/8."""
    rng = random.Random(seed)
    shapes = []
    while len(shapes) < n:
        c = [_q(rng, -5, 5) for _ in range(3)]
        if rng.random() < 0.4:
            shapes.append(["sphere", c, _q(rng, 0.125, 0.75)])
            continue
        d = [[_q(rng, -1, 1) for _ in range(3)] for _ in range(2)]
        n_ = [d[0][1] * d[1][2] - d[0][2] * d[1][1], d[0][2] * d[1][0] - d[0][0] * d[1][2],
              d[0][0] * d[1][1] - d[0][1] * d[1][0]]
        if n_ != [0.0, 0.0, 0.0]:
            shapes.append(["triangle", c, [c[i] + d[0][i] for i in range(3)], [c[i] + d[1][i] for i in range(3)]])
    return shapes


def random_rays(seed: int, n: int):
    rng = random.Random(seed)
    rays = []
    while len(rays) < n:
        o = [_q(rng, -8, 8) for _ in range(3)]
        d = [_q(rng, -5, 5) - x for x in o]
        if d == [0.0, 0.0, 0.0]:
            continue
        tmin, tmax = rng.choice([(0.0, INF), (0.0, INF), (0.0, 0.75), (0.25, INF)])
        rays.append((tuple(o), tuple(d), tmin, tmax, "random ray %d" % len(rays)))
    return rays


TRI = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]


def tie_scene(place: int):
    """A random scene with three copies of one triangle, the first at ``place``, the others at
    the end, and two copies of one sphere after them."""
    shapes = random_scene(20 + place, 40)
    shapes.insert(place, ["triangle"] + TRI)
    shapes += [["triangle"] + TRI, ["triangle"] + TRI]
    shapes += [["sphere", [0.25, 0.25, 0.0], 0.5], ["sphere", [0.25, 0.25, 0.0], 0.5]]
    return shapes


SCENES = {"random": lambda: random_scene(1, 120)}
SCENES.update({"ties %d" % place: (lambda place=place: tie_scene(place)) for place in (0, 17, 40)})


def observe_bvh_ties(rt):
    rays = [((0.25, 0.25, 5.0), (0.0, 0.0, -1.0), 0.0, INF, "down onto the copies"),
            ((0.25, 0.25, -5.0), (0.0, 0.0, 1.0), 0.0, INF, "up onto the copies"),
            ((0.125, 0.5, 4.0), (0.0, 0.0, -1.0), 0.0, INF, "down onto the copies, off-centre"),
            ((0.25, 0.25, 0.0), (1.0, 0.0, 0.0), 0.0, INF, "from inside the two spheres")]
    return _join(*(bvh_cases(rt, name, rays, VARIANTS, scene_data=SCENES[name]())
                   for name in ("ties 0", "ties 17", "ties 40")))


def observe_bvh_random(rt):
    return bvh_cases(rt, "random", random_rays(2, 150), scene_data=SCENES["random"]())
