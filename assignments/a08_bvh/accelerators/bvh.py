"""BVH: a bounding volume hierarchy over shapes (Suffern ch. 22 builds a grid for the same
purpose; PBRT-v4 section 7.3, "Bounding Volume Hierarchies").

Build. Every node holds a box around its shapes. A node of more than ``LEAF_SIZE`` shapes
is split in two along one axis by the binned surface area heuristic (Wald 2007, "On fast
Construction of SAH-based Bounding Volume Hierarchies"): the shapes' box centroids are
sorted into ``BINS`` equal bins along each axis, and of the BINS - 1 planes between bins the
one with the least expected cost

    C = C_TRAVERSE + C_INTERSECT (A_left N_left + A_right N_right) / A_node

wins (A a box's surface area, N its number of shapes: the chance that a ray through the node
also passes through a child is the ratio of their areas). A node stays a leaf when no plane
costs less than intersecting all its shapes, C_INTERSECT N, and it is small enough. A node too
big for a leaf is split at its cheapest plane whatever it costs (PBRT-v4 section 7.3.4), so
that the shapes of one wall of a box stay together (a median split would cut them apart),
and at the median only where no plane parts its shapes.

Traversal. Nodes are visited nearest box first, and a node whose box the ray enters beyond
the nearest hit so far is skipped. The closest hit is the same as the scene's loop over all
shapes (Scene.intersect): the least t, and of equal ts the earlier shape (the tie rule of
every path). As shapes are met out of order, a shape earlier than the best so far is tested
up to and including the best t (its tmax is the next float above), a later one before it.

Shapes without a box (a Plane: unbounded) are not in a BVH; ``bounds()`` returns None for them.
"""
from __future__ import annotations

import math

from ..ray import Ray
from .bbox import BBox

LEAF_SIZE = 4
BINS = 16
C_TRAVERSE = 1.0
C_INTERSECT = 1.0


class BVHNode:
    """A box and either two children (``left``, ``right``) or, in a leaf, the shapes
    ``order[first:first + count]`` of its BVH."""

    __slots__ = ("bbox", "left", "right", "first", "count")

    def __init__(self, bbox: BBox, first: int, count: int):
        self.bbox = bbox
        self.left = None
        self.right = None
        self.first = first
        self.count = count

    @property
    def is_leaf(self) -> bool:
        return self.left is None


class BVH:
    def __init__(self, shapes):
        """A BVH over ``shapes`` (a list of Shape, every one with a box). A shape's number is
        its place in ``shapes``; ``intersect`` returns it."""
        self.shapes = list(shapes)
        self.boxes = []
        for i, shape in enumerate(self.shapes):
            box = shape.bounds()
            if box is None:
                raise ValueError("BVH: shapes[%d] (%s) has no bounding box" % (i, type(shape).__name__))
            self.boxes.append(box)
        self.centroids = [box.centroid() for box in self.boxes]
        self.order = list(range(len(self.shapes)))
        self.root = self._build(0, len(self.shapes)) if self.shapes else None

    def _box_of(self, first: int, count: int) -> BBox:
        box = self.boxes[self.order[first]]
        for k in range(first + 1, first + count):
            box = box.union(self.boxes[self.order[k]])
        return box

    def _build(self, first: int, count: int) -> BVHNode:
        node = BVHNode(self._box_of(first, count), first, count)
        if count <= 1:
            return node
        split = self._best_split(node)
        if split is None:
            if count <= LEAF_SIZE:
                return node
            split = self._median_split(node)
        axis, position = split
        members = self.order[first:first + count]
        left = [i for i in members if self.centroids[i][axis] < position]
        right = [i for i in members if self.centroids[i][axis] >= position]
        if not left or not right:   # every centroid on one side (equal centroids): halve
            left, right = members[:count // 2], members[count // 2:]
        self.order[first:first + count] = left + right
        node.left = self._build(first, len(left))
        node.right = self._build(first + len(left), len(right))
        return node

    def _best_split(self, node: BVHNode):
        """(axis, plane) of the binned SAH's cheapest split, or None if no split costs less
        than a leaf (for a node too big for a leaf, only if no plane parts its shapes)."""
        members = self.order[node.first:node.first + node.count]
        centroids = BBox.of_points(self.centroids[i] for i in members)
        best, best_cost = None, C_INTERSECT * node.count if node.count <= LEAF_SIZE else math.inf
        area = node.bbox.surface_area()
        for axis in range(3):
            lo, hi = centroids.p0[axis], centroids.p1[axis]
            if hi <= lo:
                continue
            boxes, counts = [None] * BINS, [0] * BINS
            for i in members:
                b = min(int(BINS * (self.centroids[i][axis] - lo) / (hi - lo)), BINS - 1)
                boxes[b] = self.boxes[i] if boxes[b] is None else boxes[b].union(self.boxes[i])
                counts[b] += 1
            for plane in range(1, BINS):
                n_left, n_right = sum(counts[:plane]), sum(counts[plane:])
                if n_left == 0 or n_right == 0:
                    continue
                left = _union([b for b in boxes[:plane] if b is not None])
                right = _union([b for b in boxes[plane:] if b is not None])
                cost = C_TRAVERSE + C_INTERSECT * (left.surface_area() * n_left
                                                   + right.surface_area() * n_right) / area if area > 0 else math.inf
                if cost < best_cost:
                    best, best_cost = (axis, lo + (hi - lo) * plane / BINS), cost
        return best

    def _median_split(self, node: BVHNode):
        members = self.order[node.first:node.first + node.count]
        centroids = BBox.of_points(self.centroids[i] for i in members)
        extent = centroids.p1 - centroids.p0
        axis = max(range(3), key=lambda a: extent[a])
        values = sorted(self.centroids[i][axis] for i in members)
        return axis, values[len(values) // 2]

    def intersect(self, ray: Ray) -> int:
        """The number of the nearest shape the ray hits in [tmin, tmax) (ties: the earlier
        shape), ray.tmax shrunk to its t; -1 and ray.tmax unchanged on a miss."""
        # TODO a08: BVH.intersect
        #   best = -1; an empty BVH (self.root is None) returns it. Keep a stack, starting with [self.root].
        #   Pop a node; skip it when the ray misses its box (node.bbox.hit(ray) is math.inf) or enters it
        #   beyond the nearest hit so far (> ray.tmax).
        #   Leaf: for k in node.first .. node.first + node.count - 1, shape i = self.order[k]: if best < 0
        #   or i > best, a hit of self.shapes[i].intersect_p(ray) makes best = i; if i < best (an earlier
        #   shape, which wins an equal t) raise ray.tmax to math.nextafter(ray.tmax, math.inf) first and
        #   put it back if the shape misses. Inner node: push the child whose box the ray enters later,
        #   then the nearer one (popped first). When the stack is empty, return best.
        raise NotImplementedError('a08: BVH.intersect')

    def depth(self) -> int:
        def depth(node):
            return 1 if node.is_leaf else 1 + max(depth(node.left), depth(node.right))
        return depth(self.root) if self.root else 0

    def leaves(self) -> list:
        out, stack = [], [self.root] if self.root else []
        while stack:
            node = stack.pop()
            if node.is_leaf:
                out.append(node)
            else:
                stack += [node.left, node.right]
        return out


def _union(boxes) -> BBox:
    box = boxes[0]
    for b in boxes[1:]:
        box = box.union(b)
    return box
