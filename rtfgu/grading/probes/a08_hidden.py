"""Probes of a08's hidden tests: the slab test on a box's faces, edges and corners, on boxes
of zero thickness, from the box's boundary and where rounding decides; the BVH's tie rule
in any visiting order and a random scene; and what the traversal costs: the shape and box
tests it makes per ray, and whether it tests a shape below a node its own box test
rejected."""
from __future__ import annotations

import math
import random

from .a08 import (INF, SCENES as VISIBLE_SCENES, VARIANTS, accelerators, box_cases, build_shapes, bvh_cases,
                  nearest_rays, not_first_rays, ray_label, shape_number)
from .support import Cases, num

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


# --- the traversal's cost -------------------------------------------------------------------

class Counter:
    """The tests one ray's traversal makes, seen through counting wrappers of BBox.hit and of
    every shape class's intersect_p (a test made inside another counted test is not counted
    again). A box test *rejects* its node when the t it returns is beyond ray.tmax at that
    moment (math.inf among them once tmax is finite). A shape test is *unguarded* when the
    box of the leaf that holds it was not tested for this ray, and *below a rejected box*
    when a node above it (its leaf included) stands rejected by its latest box test: either
    way the traversal tested a shape its box tests did not lead it to."""

    EXAMPLES = 5

    def __init__(self):
        self.active = False
        self.depth = 0
        self.tree = None

    def start(self, tree) -> None:
        self.tree = tree
        self.shapes = self.boxes = 0
        self.tested, self.rejected = set(), set()
        self.skipped, self.unguarded = [], []
        self.active = True

    def stop(self) -> dict:
        self.active = False
        return {"shape tests": self.shapes, "box tests": self.boxes, "tested below a rejected box": self.skipped,
                "tested in a leaf whose box was not tested": self.unguarded}

    def box(self, box, ray, t) -> None:
        self.boxes += 1
        if self.tree is None:
            return
        node = self.tree["box"].get(id(box))
        if node is None:
            return
        self.tested.add(node)
        try:
            rejected = float(t) > float(ray.tmax)
        except (TypeError, ValueError):
            rejected = False
        if rejected:
            self.rejected.add(node)
        else:
            self.rejected.discard(node)

    def shape(self, shape) -> None:
        self.shapes += 1
        if self.tree is None:
            return
        number = self.tree["number"].get(id(shape))
        paths = self.tree["paths"].get(number, [])
        if not paths:
            return
        if all(path[-1] not in self.tested for path in paths):
            if len(self.unguarded) < self.EXAMPLES:
                self.unguarded.append(number)
        elif all(self.rejected.intersection(path) for path in paths):
            if len(self.skipped) < self.EXAMPLES:
                self.skipped.append(number)


def _counting(counter, method, kind: str):
    """``method`` (BBox.hit when ``kind`` is "box", else a shape's intersect_p), counted."""
    def counted(self, ray, *args, **kwargs):
        if not counter.active or counter.depth:
            return method(self, ray, *args, **kwargs)
        counter.depth += 1
        try:
            result = method(self, ray, *args, **kwargs)
        finally:
            counter.depth -= 1
        if kind == "box":
            counter.box(self, ray, result)
        else:
            counter.shape(self)
        return result
    counted.__name__ = method.__name__
    return counted


def _tree(bvh, shapes) -> dict | None:
    """The BVH's nodes as the grader's traversal sees them: which node a box belongs to, and
    for each shape number the nodes from the root down to each leaf that holds it."""
    try:
        number = {id(shape): i for i, shape in enumerate(shapes)}
        box, paths = {}, {}
        stack = [(bvh.root, ())] if bvh.root is not None else []
        while stack:
            node, above = stack.pop()
            index = len(box)
            box[id(node.bbox)] = index
            path = above + (index,)
            if node.left is None:
                for i in bvh.order[node.first:node.first + node.count]:
                    paths.setdefault(int(i), []).append(path)
            else:
                stack += [(node.left, path), (node.right, path)]
        return {"box": box, "number": number, "paths": paths}
    except Exception:  # a tree not built as the given build builds it: counts only
        return None


def traversal_cases(rt, acc, counter, scene: str, rays, scene_data):
    """For each ray of ``rays`` on ``scene_data``: BVH.intersect's answer and what it cost
    (``counter``, whose wrappers observe_traversal has put in place), the tree built once by
    the student's BVH."""
    shapes = build_shapes(rt, scene_data)
    cases = Cases()
    built = []
    for o, d, tmin, tmax, what in rays:
        def run(o=o, d=d, tmin=tmin, tmax=tmax):
            if not built:
                bvh = acc.BVH(shapes)
                built.append((bvh, _tree(bvh, shapes)))
            bvh, tree = built[0]
            F = rt.Float3
            ray = rt.Ray(F(*o), F(*d), tmin, tmax)
            counter.start(tree)
            try:
                shape = bvh.intersect(ray)
            finally:
                cost = counter.stop()
            out = {"shape": shape_number(shape, len(scene_data)), "ray.tmax": num(ray.tmax, "ray.tmax")}
            out.update(cost)
            return out
        cases.run("the %s scene (%d shapes), %s (%s)" % (scene, len(scene_data), ray_label(o, d, tmin, tmax), what),
                  run, scene=scene, o=list(o), d=list(d), tmin=tmin, tmax=tmax)
    return cases.result()


def observe_traversal(rt):
    """traversal_cases on three scenes. The shapes' intersect_p are wrapped before the
    student's accelerators are imported (nothing imports them before this probe), so that a
    reference to a shape's test taken when the student's module is imported is the counted
    one: a BVH that called the originals through such references, ignoring its tree, once
    passed this test with its shape tests uncounted. BBox, the student's own, is wrapped once
    imported. One counter and one set of wrappers serve all three scenes, and the originals
    are put back at the end."""
    counter = Counter()
    patched = [(cls, "intersect_p", cls.intersect_p, "shape") for cls in (rt.Sphere, rt.Triangle)]
    try:
        for cls, name, method, kind in patched:
            setattr(cls, name, _counting(counter, method, kind))
        acc = accelerators(rt)
        patched.append((acc.BBox, "hit", acc.BBox.hit, "box"))
        setattr(acc.BBox, "hit", _counting(counter, acc.BBox.hit, "box"))
        return _join(traversal_cases(rt, acc, counter, "grid", nearest_rays(), VISIBLE_SCENES["grid"]()),
                     traversal_cases(rt, acc, counter, "sheet", not_first_rays(), VISIBLE_SCENES["sheet"]()),
                     traversal_cases(rt, acc, counter, "random", random_rays(2, 150), SCENES["random"]()))
    finally:
        for cls, name, method, _ in reversed(patched):
            setattr(cls, name, method)
