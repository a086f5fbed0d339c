"""Probes of a08's visible tests: the slab test of a bounding box (``BBox.hit``) and the
traversal of a bounding volume hierarchy (``BVH.intersect``) (Suffern ch. 19 and 22;
PBRT-v4 sections 6.1.2 and 7.3).

Every coordinate of the box tests is a small multiple of a power of two, so that each
subtraction and division of the slab test is exact: the answers are those of exact
arithmetic. The BVH tests build the given ``BVH`` over scenes described as plain data
(``["sphere", center, radius]``, ``["triangle", v0, v1, v2]``) and ask it for the nearest
hit of each ray: the shape's number in the scene's list and ``ray.tmax``."""
from __future__ import annotations

import importlib
import math

from .support import Cases, StudentError, num

INF = math.inf

# The box of the visible box tests: x in [-1, 3], y in [0.5, 2], z in [-4, -2].
BOX = ([-1.0, 0.5, -4.0], [3.0, 2.0, -2.0])


def accelerators(rt):
    """The student's rtfgu.accelerators (BBox, BVH)."""
    return importlib.import_module(rt.__name__ + ".accelerators")


def _g(x) -> str:
    """A number as it is written in this file, so that a label can be typed back in."""
    x = float(x)
    if math.isinf(x):
        return "infinity" if x > 0 else "-infinity"
    if x == 0 and math.copysign(1.0, x) < 0:
        return "-0"
    return "%d" % x if x == int(x) and abs(x) < 1e15 else repr(x)


def _v(v) -> str:
    return "(%s)" % ", ".join(_g(x) for x in v)


def ray_label(o, d, tmin, tmax) -> str:
    return "the ray from %s along %s with tmin %s, tmax %s" % (_v(o), _v(d), _g(tmin), _g(tmax))


def box_cases(rt, rays, box=BOX):
    """BBox(p0, p1).hit(ray) for each (o, d, tmin, tmax, what) of ``rays``: the t it returns and
    the ray's tmin and tmax afterwards (the test changes nothing)."""
    p0, p1 = box
    cases = Cases()
    for o, d, tmin, tmax, what in rays:
        def run(o=o, d=d, tmin=tmin, tmax=tmax):
            F = rt.Float3
            ray = rt.Ray(F(*o), F(*d), tmin, tmax)
            t = num(accelerators(rt).BBox(F(*p0), F(*p1)).hit(ray), "BBox.hit's result")
            return {"t": t, "ray.tmin": num(ray.tmin, "ray.tmin"), "ray.tmax": num(ray.tmax, "ray.tmax")}
        cases.run("the box %s - %s, %s (%s)" % (_v(p0), _v(p1), ray_label(o, d, tmin, tmax), what), run,
                  p0=list(p0), p1=list(p1), o=list(o), d=list(d), tmin=tmin, tmax=tmax)
    return cases.result()


def observe_box_enter(rt):
    return box_cases(rt, [
        ((-3.0, 0.0, -5.5), (1.0, 0.5, 0.5), 0.0, INF, "enters through x = -1 at t = 3"),
        ((-2.5, 0.25, -6.0), (0.25, 0.125, 0.5), 0.0, INF, "a short direction: enters at t = 6"),
        ((-1.5, -1.0, -2.5), (2.0, 1.0, 0.25), 0.0, INF, "enters through y = 0.5"),
        ((-4.0, 0.0, -3.5), (8.0, 1.0, 0.5), 0.0, INF, "a long direction: enters at t = 0.5"),
        ((-1.25, 0.75, -3.0), (1.0, 0.125, 0.25), 0.0, INF, "starts just outside x = -1"),
    ])


def observe_box_negative(rt):
    return box_cases(rt, [
        ((5.0, 1.0, -3.5), (-1.0, 0.25, 0.125), 0.0, INF, "w.x < 0: enters through x = 3"),
        ((0.0, 4.0, -3.0), (0.5, -1.0, 0.25), 0.0, INF, "w.y < 0: enters through y = 2"),
        ((1.0, 1.0, 0.0), (0.25, 0.125, -2.0), 0.0, INF, "w.z < 0: enters through z = -2"),
        ((5.0, 3.0, 0.0), (-1.0, -0.5, -0.5), 0.0, INF, "every component < 0"),
        ((-3.0, 3.0, -5.0), (1.0, -0.5, 0.25), 0.0, INF, "mixed signs"),
        ((5.0, 3.0, 0.0), (-1.0, 0.5, -0.5), 0.0, INF, "mixed signs, rising away from the box: a miss"),
    ])


# Enters the box at t = 2 through x = -1 and leaves it at t = 6 through x = 3.
_O, _D = (-3.0, 1.0, -3.0), (1.0, 0.125, 0.125)


def observe_box_interval(rt):
    return box_cases(rt, [
        ((5.0, 1.0, -3.0), (1.0, 0.25, 0.25), 0.0, INF, "pointing away from the box"),
        ((-3.0, 2.5, -3.0), (1.0, 0.25, 0.125), 0.0, INF, "rising past the box"),
        ((-3.0, -9.0, -3.0), (1.0, 1.0, 0.25), 0.0, INF,
         "in the x slab for 2 <= t <= 6, in the y slab for 9.5 <= t <= 11"),
        (_O, _D, 0.0, 1.5, "tmax before the box"),
        (_O, _D, 0.0, 2.0, "tmax exactly where the ray enters: [tmin, tmax] is closed"),
        (_O, _D, 0.0, 4.0, "tmax inside the box"),
        (_O, _D, 3.0, INF, "tmin inside the box: the ray starts there"),
        (_O, _D, 7.0, INF, "tmin past the box"),
        ((1.0, 1.0, -3.0), _D, 0.0, INF, "the origin inside the box"),
        ((1.0, 1.0, -3.0), _D, 0.25, INF, "the origin inside the box, tmin 0.25"),
        ((5.0, 1.0, -3.0), (-1.0, 0.125, 0.125), 0.0, 1.5, "w.x < 0 and tmax before the box"),
        ((5.0, 1.0, -3.0), (-1.0, 0.125, 0.125), 0.0, 3.0, "w.x < 0 and tmax inside the box"),
    ])


def observe_box_zero(rt):
    return box_cases(rt, [
        ((-3.0, 1.0, -3.0), (1.0, 0.0, 0.0), 0.0, INF, "along x, inside the y and z slabs"),
        ((1.0, -3.0, -3.0), (0.0, 1.0, 0.0), 0.0, INF, "along y"),
        ((1.0, 1.0, 3.0), (0.0, 0.0, -0.5), 0.0, INF, "along -z"),
        ((-3.0, 3.0, -3.0), (1.0, 0.0, 0.0), 0.0, INF, "along x, above the y slab"),
        ((-3.0, 1.0, -5.0), (1.0, 0.0, 0.0), 0.0, INF, "along x, in front of the z slab"),
        ((-3.0, 0.25, -3.0), (1.0, 0.0, 0.5), 0.0, INF, "w.y = 0 below the y slab"),
        ((-3.0, 0.5, -3.0), (1.0, 0.0, 0.0), 0.0, INF, "along the face y = 0.5"),
        ((5.0, 2.0, -3.0), (-1.0, 0.0, 0.0), 0.0, INF, "along the face y = 2"),
        ((1.0, 1.0, -3.0), (0.0, 1.0, 0.0), 0.0, INF, "from inside"),
        ((-3.0, 1.0, -3.0), (1.0, -0.0, -0.0), 0.0, INF, "components of -0"),
    ])


# --- the BVH ------------------------------------------------------------------------------

def grid_scene():
    """Spheres and triangles on a 4 x 4 grid, two layers deep, and a floor of two triangles."""
    shapes = []
    for layer in range(2):
        for i in range(4):
            for j in range(4):
                x, y, z = 2.0 * i - 3.0, 2.0 * j - 3.0, -4.0 - 3.0 * layer - 0.5 * i
                if (i + j + layer) % 2 == 0:
                    shapes.append(["sphere", [x, y, z], 0.75])
                else:
                    shapes.append(["triangle", [x - 1.0, y - 0.75, z + 0.5], [x + 1.0, y - 0.75, z],
                                   [x, y + 1.0, z - 0.5]])
    shapes.append(["triangle", [-6.0, -4.5, 2.0], [6.0, -4.5, 2.0], [6.0, -4.5, -14.0]])
    shapes.append(["triangle", [-6.0, -4.5, 2.0], [6.0, -4.5, -14.0], [-6.0, -4.5, -14.0]])
    return shapes


def sheet_scene():
    """A sheet of two triangles slanting away from the camera (from z = 2 at y = -4 to z = -14 at
    y = 4) with a flap at either end, a column of eight small spheres, some in front of the sheet
    and some behind it, and two spheres behind it all: the box of the sheet's node is entered
    first and its hit is often the farthest."""
    shapes = [
        ["triangle", [-4.0, -4.0, 2.0], [4.0, -4.0, 2.0], [4.0, 4.0, -14.0]],
        ["triangle", [-4.0, -4.0, 2.0], [4.0, 4.0, -14.0], [-4.0, 4.0, -14.0]],
        ["triangle", [-4.0, 4.0, -14.0], [4.0, 4.0, -14.0], [4.0, 5.0, -16.0]],
        ["triangle", [-4.0, -4.0, 2.0], [4.0, -4.0, 2.0], [0.0, -5.0, 4.0]],
    ]
    for k in range(8):
        shapes.append(["sphere", [-1.5 + 0.5 * (k % 2), 2.0 - 0.5 * k, -6.0 - 0.25 * k], 0.375])
    shapes.append(["sphere", [0.0, 0.0, -20.0], 2.0])
    shapes.append(["sphere", [3.0, -3.0, -18.0], 1.0])
    return shapes


def overlap_scene():
    """Two triangles in the plane z = 0 that overlap around (0.25, 0.25), and a cluster of
    spheres elsewhere so that the two land in different nodes."""
    shapes = [["triangle", [-6.0, -1.0, 0.0], [3.0, -1.0, 0.0], [-6.0, 5.0, 0.0]]]
    shapes += [["sphere", [8.0 + k, 8.0, -2.0 * k], 0.5] for k in range(6)]
    shapes.append(["triangle", [-0.5, 0.0, 0.0], [6.0, 0.0, 0.0], [-0.5, 2.0, 0.0]])
    return shapes


SCENES = {"grid": grid_scene, "sheet": sheet_scene, "overlap": overlap_scene, "empty": lambda: [],
          "one sphere": lambda: [["sphere", [0.0, 0.0, 0.0], 1.0]]}


def build_shapes(rt, scene):
    """The student's Sphere and Triangle objects of a scene's plain data."""
    F = rt.Float3
    white = F(1.0, 1.0, 1.0)
    shapes = []
    for spec in scene:
        if spec[0] == "sphere":
            shapes.append(rt.Sphere(F(*spec[1]), spec[2], white))
        else:
            shapes.append(rt.Triangle(F(*spec[1]), F(*spec[2]), F(*spec[3]), white))
    return shapes


VARIANTS = ("as built", "every node's children swapped", "every leaf's shapes reversed")


def reorder(bvh, variant: str):
    """The same tree in another order: a node's children, or a leaf's shapes, are the build's
    choice, and the closest hit must not depend on it."""
    if variant == "as built" or bvh.root is None:
        return bvh
    stack = [bvh.root]
    while stack:
        node = stack.pop()
        if node.is_leaf:
            if variant == "every leaf's shapes reversed":
                part = bvh.order[node.first:node.first + node.count]
                bvh.order[node.first:node.first + node.count] = part[::-1]
        else:
            if variant == "every node's children swapped":
                node.left, node.right = node.right, node.left
            stack += [node.left, node.right]
    return bvh


def shape_number(value, count: int) -> int:
    if isinstance(value, bool) or not isinstance(value, int) and type(value).__name__ not in ("int64", "int32"):
        raise StudentError("BVH.intersect's result should be a shape's number (an int), but it is %r (of type %s)"
                           % (value, type(value).__name__))
    value = int(value)
    if not -1 <= value < count:
        raise StudentError("BVH.intersect returned %d: a shape's number is 0 .. %d, or -1 for a miss"
                           % (value, count - 1))
    return value


def bvh_cases(rt, scene: str, rays, variants=("as built",), scene_data=None):
    """BVH(shapes).intersect(ray) for each (o, d, tmin, tmax, what) of ``rays`` on the scene
    ``SCENES[scene]`` (or ``scene_data``), the tree built once per variant (see ``reorder``)."""
    data = scene_data if scene_data is not None else SCENES[scene]()
    cases = Cases()
    for variant in variants:
        built = []

        def bvh(variant=variant):
            if not built:
                built.append(reorder(accelerators(rt).BVH(build_shapes(rt, data)), variant))
            return built[0]
        for o, d, tmin, tmax, what in rays:
            def run(o=o, d=d, tmin=tmin, tmax=tmax):
                F = rt.Float3
                ray = rt.Ray(F(*o), F(*d), tmin, tmax)
                shape = shape_number(bvh().intersect(ray), len(data))
                return {"shape": shape, "ray.tmax": num(ray.tmax, "ray.tmax")}
            where = "the %s scene (%d shapes)" % (scene, len(data))
            if variant != "as built":
                where += ", BVH with %s" % variant
            cases.run("%s, %s (%s)" % (where, ray_label(o, d, tmin, tmax), what), run,
                      scene=scene, variant=variant, o=list(o), d=list(d), tmin=tmin, tmax=tmax)
    return cases.result()


def nearest_rays():
    """The rays of observe_bvh_nearest, on the grid scene."""
    eye = (0.25, 0.5, 6.0)
    rays = []
    for target in ((-3.0, -3.0, -4.0), (-1.0, -1.0, -4.5), (1.0, 1.0, -5.0), (3.0, 3.0, -5.5), (-3.0, 3.0, -4.0),
                   (3.0, -3.0, -5.5), (0.0, 0.0, -12.0), (-1.0, 3.0, -8.5), (2.5, -2.0, -9.0), (0.0, -4.0, -9.0)):
        rays.append((eye, tuple(t - e for t, e in zip(target, eye)), 0.0, INF, "from the eye"))
    rays += [
        ((9.0, -1.0, -5.0), (-1.0, 0.0, 0.0), 0.0, INF, "from the side, along -x"),
        ((-9.0, 1.0, -6.0), (1.0, 0.0, -0.125), 0.0, INF, "from the other side"),
        ((1.0, 9.0, -5.5), (0.0, -1.0, 0.0), 0.0, INF, "from above, down a column"),
        ((-3.0, -3.0, -20.0), (0.0, 0.0, 1.0), 0.0, INF, "from behind, along +z"),
        ((1.0, -1.0, -6.0), (-0.5, 0.25, 1.0), 0.0, INF, "from between the shapes"),
        ((0.5, 0.5, 6.0), (0.0, -0.5, -1.0), 0.0, INF, "down to the floor"),
    ]
    return rays


def observe_bvh_nearest(rt):
    return bvh_cases(rt, "grid", nearest_rays())


def observe_bvh_misses_and_interval(rt):
    eye = (0.25, 0.5, 6.0)
    out = bvh_cases(rt, "grid", [
        (eye, (0.0, 0.0, 1.0), 0.0, INF, "away from every shape"),
        (eye, (1.0, 1.0, 0.0), 0.0, INF, "above the floor, past every shape"),
        ((-3.0, -3.0, 6.0), (0.0, 0.0, -1.0), 0.0, 9.0, "tmax before the first shape"),
        ((-3.0, -3.0, 6.0), (0.0, 0.0, -1.0), 0.0, 11.0, "tmax inside the first sphere: its near side"),
        ((-3.0, -3.0, 6.0), (0.0, 0.0, -1.0), 10.5, INF, "tmin past the first sphere's near side"),
        ((-3.0, -3.0, -4.0), (0.0, 0.0, -1.0), 0.0, INF, "from a sphere's centre: its far side"),
        ((1.0, 1.0, -5.0), (0.0, 0.0, -1.0), 0.0, 0.5, "from a sphere's centre, tmax inside it"),
        ((9.0, 9.0, 9.0), (1.0, 1.0, 1.0), 0.0, INF, "far outside, pointing away"),
    ])
    for scene, rays in (("empty", [((0.0, 0.0, 6.0), (0.0, 0.0, -1.0), 0.0, INF, "no shape to hit")]),
                        ("one sphere", [((0.0, 0.0, 6.0), (0.0, 0.0, -1.0), 0.0, INF, "the one shape"),
                                        ((0.0, 0.0, 6.0), (0.0, 0.0, -1.0), 0.0, 5.0, "tmax before it")])):
        out["cases"] += bvh_cases(rt, scene, rays)["cases"]
    return out


def not_first_rays():
    """The rays of observe_bvh_nearest_not_first, on the sheet scene."""
    eye = (0.0, 0.0, 6.0)
    rays = []
    for k in range(8):
        target = (-1.5 + 0.5 * (k % 2), 2.0 - 0.5 * k, -6.0 - 0.25 * k)
        rays.append((eye, tuple(t - e for t, e in zip(target, eye)), 0.0, INF,
                     "toward sphere %d" % (4 + k)))
    rays += [
        (eye, (0.0, 0.0, -1.0), 0.0, INF, "at the middle of the sheet"),
        (eye, (0.125, -0.125, -1.0), 0.0, INF, "at the sheet near the sphere behind it"),
        ((0.0, 0.0, -30.0), (0.0, 0.0, 1.0), 0.0, INF, "from behind: the big sphere first"),
        ((3.0, -3.0, -30.0), (0.0, 0.0, 1.0), 0.0, INF, "from behind: the small sphere first"),
        ((-1.5, 6.0, -6.0), (0.0, -1.0, 0.0), 0.0, INF, "from above, down the column of spheres"),
    ]
    return rays


def observe_bvh_nearest_not_first(rt):
    return bvh_cases(rt, "sheet", not_first_rays())


def observe_bvh_tie(rt):
    return bvh_cases(rt, "overlap", [
        ((0.25, 0.25, 5.0), (0.0, 0.0, -1.0), 0.0, INF, "down onto both triangles"),
        ((0.25, 0.25, -5.0), (0.0, 0.0, 1.0), 0.0, INF, "up onto both triangles"),
        ((1.0, 1.0, 3.0), (0.0, 0.0, -0.5), 0.0, INF, "down onto both triangles elsewhere"),
        ((-2.0, 1.0, 3.0), (0.0, 0.0, -1.0), 0.0, INF, "down onto the first triangle only"),
        ((4.0, 0.5, 3.0), (0.0, 0.0, -1.0), 0.0, INF, "down onto the second triangle only"),
    ], VARIANTS)


def observe_box(rt):
    """Box.intersect_p (Suffern's box, ch. 19.5) on the rays of a03's shape tests: hits from
    outside on each axis, from inside, misses, a ray parallel to a slab, and the interval."""
    from .a03 import _hit_case

    cases = Cases()
    F = rt.Float3
    p0, p1 = (-1.0, -0.5, -2.0), (1.0, 0.5, -1.0)

    def make():
        return importlib.import_module(rt.__name__ + ".shapes.box").Box(F(*p0), F(*p1), F(1, 1, 1))
    label = "the box from %s to %s" % (p0, p1)
    _hit_case(rt, cases, label, make, (0, 0, 0), (0, 0, -1))                    # the +z face at t = 1
    _hit_case(rt, cases, label, make, (3, 0, -1.5), (-1, 0, 0))                 # the +x face at t = 2
    _hit_case(rt, cases, label, make, (0.5, -2, -1.25), (0, 1, 0))               # the -y face at t = 1.5
    _hit_case(rt, cases, label, make, (0, 0, 0), (0.25, 0.125, -1))             # oblique, through +z
    _hit_case(rt, cases, label, make, (0, 0, -1.5), (0, 0, -1))                 # from inside: leaves at t = 0.5
    _hit_case(rt, cases, label, make, (0, 0, -1.5), (1, 1, 1))                  # from inside, obliquely
    _hit_case(rt, cases, label, make, (0, 2, 0), (0, 0, -1))                    # parallel to the y slab, outside
    _hit_case(rt, cases, label, make, (0, 0, 0), (0, 1, 0))                     # misses
    _hit_case(rt, cases, label, make, (0, 0, 0), (0, 0, 1))                     # points away
    _hit_case(rt, cases, label, make, (0, 0, 0), (0, 0, -1), 1e-5, 0.5)         # beyond tmax
    return cases.result()
