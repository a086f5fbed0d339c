"""The BVH of the numba and WGSL paths: the binned SAH build of rtfgu.accelerators.bvh over
arrays, into a flat node table that both paths traverse.

The build is the lecture BVH's (BINS bins, LEAF_SIZE, C_INTERSECT) over the primitives'
boxes as arrays, with numba when it is installed (the build of a 1.3-million-triangle mesh
takes under a second; docs/bvh.md has the figures) and as plain Python otherwise. It has one
constant of its own: a step down the tree costs C_TRAVERSE = 2 shape tests, where the
lecture's costs 1. Leaves then hold two shapes or more where they can (the lecture's tree
splits down to single shapes, so a student sees every step and ties meet across leaves):
0.7 nodes per triangle instead of 1.16, at the same speed on the numba path (docs/bvh.md,
"Cost constants"). The tree it returns is a table of 32-byte nodes, children of a node next
to each other:

    nodes  (N, 8) float32   [lo.x, lo.y, lo.z, a, hi.x, hi.y, hi.z, b]
                            a, b are int32 bit patterns (nodes.view(np.int32)[:, 3], [:, 7]):
                            a leaf: a = its first primitive, b = its count (>= 1);
                            an inner node: a = its left child (the right one is a + 1), b = 0
    order  (P,) int32       the primitives in leaf order: leaf primitives are order[a:a + b]

The boxes are rounded outward to float32 (every bound down or up to the next float32), so a
float32 box holds every point of the float64 box it came from: one table serves both
precisions, and a float32 vertex (the nearest float32 to a float64 one) is inside it too.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from .bvh import BINS, C_INTERSECT, LEAF_SIZE

from ..jit import njit

NODE_WIDTH = 8
# Deepest stack a traversal needs: the build splits until LEAF_SIZE, and a tree of 2^31
# primitives split evenly is 31 deep; an uneven SAH tree is deeper, so the build refuses a
# tree deeper than this (it never happens on a mesh whose boxes are not degenerate).
MAX_DEPTH = 64
# The cost of a step down the tree, in shape tests (module docstring).
C_TRAVERSE = 2.0


@dataclass
class FlatBVH:
    nodes: np.ndarray          # (N, 8) float32 (module docstring)
    order: np.ndarray          # (P,) int32
    build_seconds: float
    boxes: np.ndarray          # (P, 6) float32: each primitive's box in leaf order, rounded out
    _wide: tuple = field(default=None, repr=False, compare=False)

    @property
    def links(self) -> np.ndarray:
        return self.nodes.view(np.int32)

    def wide(self, roots=(0,)):
        """The wide tree of the numba path (rtfgu.accelerators.wide_bvh) over this table's trees
        from ``roots``: collapsed at the first call and kept with the table."""
        from .wide_bvh import collapse
        roots = tuple(int(r) for r in roots)
        if self._wide is None or self._wide[0] != roots:
            self._wide = (roots, collapse(self, roots))
        return self._wide[1]

    @property
    def num_nodes(self) -> int:
        return len(self.nodes)

    @property
    def nbytes(self) -> int:
        return self.nodes.nbytes

    def depth(self) -> int:
        return _depth(self.links)


@njit(cache=True)
def _surface_area(lo0, lo1, lo2, hi0, hi1, hi2):
    dx, dy, dz = hi0 - lo0, hi1 - lo1, hi2 - lo2
    return 2.0 * (dx * dy + dy * dz + dz * dx)


@njit(cache=True)
def _build(lo, hi, order, box, links, leaf_size, bins, c_traverse, c_intersect, max_depth):
    """Fill box (N, 6) float64 and links (N, 2) int32; returns the number of nodes. The nodes
    are built from a stack of (node, first, count, depth); children are placed next to each
    other at the end of the table."""
    n_prims = order.shape[0]
    stack = np.empty((4 * max_depth, 4), dtype=np.int64)
    stack[0, 0], stack[0, 1], stack[0, 2], stack[0, 3] = 0, 0, n_prims, 1
    sp = 1
    n_nodes = 1
    bin_count = np.zeros((3, bins), dtype=np.int64)
    bin_box = np.empty((3, bins, 6))
    right_area = np.empty(bins)
    right_count = np.empty(bins, dtype=np.int64)
    cent = np.empty((n_prims, 3))
    for p in range(n_prims):
        for axis in range(3):
            cent[p, axis] = 0.5 * (lo[p, axis] + hi[p, axis])
    while sp > 0:
        sp -= 1
        node, first, count, depth = stack[sp, 0], stack[sp, 1], stack[sp, 2], stack[sp, 3]
        if depth > max_depth:
            return -1
        # The node's box and the box of its primitives' centroids.
        b0 = np.inf; b1 = np.inf; b2 = np.inf; b3 = -np.inf; b4 = -np.inf; b5 = -np.inf
        c0 = np.inf; c1 = np.inf; c2 = np.inf; c3 = -np.inf; c4 = -np.inf; c5 = -np.inf
        for k in range(first, first + count):
            p = order[k]
            b0 = min(b0, lo[p, 0]); b1 = min(b1, lo[p, 1]); b2 = min(b2, lo[p, 2])
            b3 = max(b3, hi[p, 0]); b4 = max(b4, hi[p, 1]); b5 = max(b5, hi[p, 2])
            x = cent[p, 0]; y = cent[p, 1]; z = cent[p, 2]
            c0 = min(c0, x); c1 = min(c1, y); c2 = min(c2, z)
            c3 = max(c3, x); c4 = max(c4, y); c5 = max(c5, z)
        box[node, 0], box[node, 1], box[node, 2] = b0, b1, b2
        box[node, 3], box[node, 4], box[node, 5] = b3, b4, b5
        if count <= 1:
            links[node, 0], links[node, 1] = first, count
            continue
        # The binned SAH (rtfgu.accelerators.bvh.BVH._best_split): the cheapest plane. One
        # pass over the primitives bins them along all three axes at once.
        area = _surface_area(b0, b1, b2, b3, b4, b5)
        # A node small enough to be a leaf is split only where a plane costs less than the
        # leaf; a bigger one at its cheapest plane, whatever it costs (PBRT-v4 section 7.3.4).
        best_cost = c_intersect * count if count <= leaf_size else np.inf
        best_axis = -1
        best_plane = 0.0
        clo = (c0, c1, c2)
        extent = (c3 - c0, c4 - c1, c5 - c2)
        scale = np.zeros(3)
        for axis in range(3):
            if extent[axis] > 0.0:
                scale[axis] = bins / extent[axis]
        bin_count[:, :] = 0
        bin_box[:, :, 0:3] = np.inf
        bin_box[:, :, 3:6] = -np.inf
        for k in range(first, first + count):
            p = order[k]
            l0, l1, l2, h0, h1, h2 = lo[p, 0], lo[p, 1], lo[p, 2], hi[p, 0], hi[p, 1], hi[p, 2]
            for axis in range(3):
                if scale[axis] == 0.0:
                    continue
                j = min(int(scale[axis] * (cent[p, axis] - clo[axis])), bins - 1)
                bin_count[axis, j] += 1
                box_j = bin_box[axis, j]
                box_j[0] = min(box_j[0], l0); box_j[1] = min(box_j[1], l1); box_j[2] = min(box_j[2], l2)
                box_j[3] = max(box_j[3], h0); box_j[4] = max(box_j[4], h1); box_j[5] = max(box_j[5], h2)
        for axis in range(3):
            if scale[axis] == 0.0:
                continue
            # Sweep from the right: area and count of bins j..bins-1.
            r0 = np.inf; r1 = np.inf; r2 = np.inf; r3 = -np.inf; r4 = -np.inf; r5 = -np.inf
            n_right = 0
            for j in range(bins - 1, 0, -1):
                r0 = min(r0, bin_box[axis, j, 0]); r1 = min(r1, bin_box[axis, j, 1]); r2 = min(r2, bin_box[axis, j, 2])
                r3 = max(r3, bin_box[axis, j, 3]); r4 = max(r4, bin_box[axis, j, 4]); r5 = max(r5, bin_box[axis, j, 5])
                n_right += bin_count[axis, j]
                right_count[j] = n_right
                right_area[j] = _surface_area(r0, r1, r2, r3, r4, r5) if n_right > 0 else 0.0
            l0 = np.inf; l1 = np.inf; l2 = np.inf; l3 = -np.inf; l4 = -np.inf; l5 = -np.inf
            n_left = 0
            for plane in range(1, bins):
                j = plane - 1
                l0 = min(l0, bin_box[axis, j, 0]); l1 = min(l1, bin_box[axis, j, 1]); l2 = min(l2, bin_box[axis, j, 2])
                l3 = max(l3, bin_box[axis, j, 3]); l4 = max(l4, bin_box[axis, j, 4]); l5 = max(l5, bin_box[axis, j, 5])
                n_left += bin_count[axis, j]
                if n_left == 0 or right_count[plane] == 0 or not area > 0.0:
                    continue
                cost = c_traverse + c_intersect * (_surface_area(l0, l1, l2, l3, l4, l5) * n_left
                                                   + right_area[plane] * right_count[plane]) / area
                if cost < best_cost:
                    best_cost = cost
                    best_axis = axis
                    best_plane = clo[axis] + extent[axis] * plane / bins
        if best_axis < 0:
            if count <= leaf_size:
                links[node, 0], links[node, 1] = first, count
                continue
            # No plane pays, but the node is too big for a leaf: the median of the widest axis.
            best_axis = 0
            if c4 - c1 > c3 - c0:
                best_axis = 1
            if c5 - c2 > max(c3 - c0, c4 - c1):
                best_axis = 2
            keys = np.empty(count)
            for k in range(count):
                p = order[first + k]
                keys[k] = lo[p, best_axis] + hi[p, best_axis]
            sorted_part = order[first:first + count][np.argsort(keys, kind="mergesort")]
            order[first:first + count] = sorted_part
            mid = first + count // 2
        else:
            # Partition order[first:first + count]: centroids below the plane first.
            i = first
            j = first + count - 1
            while i <= j:
                p = order[i]
                if cent[p, best_axis] < best_plane:
                    i += 1
                else:
                    order[i] = order[j]
                    order[j] = p
                    j -= 1
            mid = i
            if mid == first or mid == first + count:
                mid = first + count // 2
        left = n_nodes
        n_nodes += 2
        links[node, 0], links[node, 1] = left, 0
        stack[sp, 0], stack[sp, 1], stack[sp, 2], stack[sp, 3] = left + 1, mid, first + count - mid, depth + 1
        stack[sp + 1, 0], stack[sp + 1, 1], stack[sp + 1, 2], stack[sp + 1, 3] = left, first, mid - first, depth + 1
        sp += 2
    return n_nodes


@njit(cache=True)
def _depth(links):
    deepest = 0
    stack = np.empty((MAX_DEPTH * 2 + 2, 2), dtype=np.int64)
    stack[0, 0], stack[0, 1] = 0, 1
    sp = 1
    while sp > 0:
        sp -= 1
        node, depth = stack[sp, 0], stack[sp, 1]
        deepest = max(deepest, depth)
        if links[node, 7] == 0:
            left = links[node, 3]
            stack[sp, 0], stack[sp, 1] = left, depth + 1
            stack[sp + 1, 0], stack[sp + 1, 1] = left + 1, depth + 1
            sp += 2
    return deepest


@njit(cache=True)
def _round_out(box, nodes):
    """Write the float64 boxes ``box`` (N, 6) [lo, hi] into the float32 ``nodes`` (N, 8)
    columns 0-2 and 4-6, each lo rounded down and each hi up to a float32."""
    for i in range(box.shape[0]):
        for axis in range(3):
            lo = np.float32(box[i, axis])
            if np.float64(lo) > box[i, axis]:
                lo = np.nextafter(lo, np.float32(-np.inf))
            hi = np.float32(box[i, 3 + axis])
            if np.float64(hi) < box[i, 3 + axis]:
                hi = np.nextafter(hi, np.float32(np.inf))
            nodes[i, axis] = lo
            nodes[i, 4 + axis] = hi


@njit(cache=True)
def _primitive_boxes(lo, hi, order, boxes):
    """boxes[k] = the box of primitive order[k], [lo, hi] rounded outward to float32."""
    for k in range(order.shape[0]):
        p = order[k]
        for axis in range(3):
            low = np.float32(lo[p, axis])
            if np.float64(low) > lo[p, axis]:
                low = np.nextafter(low, np.float32(-np.inf))
            high = np.float32(hi[p, axis])
            if np.float64(high) < hi[p, axis]:
                high = np.nextafter(high, np.float32(np.inf))
            boxes[k, axis] = low
            boxes[k, 3 + axis] = high


def build(lo, hi) -> FlatBVH:
    """The BVH over primitives with boxes lo (P, 3), hi (P, 3) (float64, finite, lo <= hi)."""
    lo = np.ascontiguousarray(lo, dtype=np.float64)
    hi = np.ascontiguousarray(hi, dtype=np.float64)
    if lo.shape != hi.shape or lo.ndim != 2 or lo.shape[1] != 3 or len(lo) == 0:
        raise ValueError("BVH: lo and hi must be (P, 3) arrays with P >= 1, got %s and %s" % (lo.shape, hi.shape))
    if not (np.isfinite(lo).all() and np.isfinite(hi).all()):
        raise ValueError("BVH: a primitive's box is not finite")
    start = time.perf_counter()
    order = np.arange(len(lo), dtype=np.int32)
    capacity = 2 * len(lo)
    box = np.empty((capacity, 6))
    links = np.zeros((capacity, 2), dtype=np.int32)
    n = _build(lo, hi, order, box, links, LEAF_SIZE, BINS, C_TRAVERSE, C_INTERSECT, MAX_DEPTH)
    if n < 0:
        raise ValueError("BVH: the tree would be deeper than %d levels (degenerate boxes)" % MAX_DEPTH)
    nodes = np.zeros((n, NODE_WIDTH), dtype=np.float32)
    _round_out(box[:n], nodes)
    ints = nodes.view(np.int32)
    ints[:, 3] = links[:n, 0]
    ints[:, 7] = links[:n, 1]
    boxes = np.empty((len(order), 6), dtype=np.float32)
    _primitive_boxes(lo, hi, order, boxes)
    return FlatBVH(nodes, order, time.perf_counter() - start, boxes)


def offset(bvh: FlatBVH, first_node: int, first_primitive: int) -> FlatBVH:
    """``bvh`` as it reads placed after ``first_node`` nodes and ``first_primitive``
    primitives of other trees in one table (the trees of instanced meshes, rtfgu.layout)."""
    nodes = bvh.nodes.copy()
    links = nodes.view(np.int32)
    leaf = links[:, 7] > 0
    links[:, 3] += np.where(leaf, first_primitive, first_node).astype(np.int32)
    return FlatBVH(nodes, bvh.order + np.int32(first_primitive), bvh.build_seconds, bvh.boxes)


def triangle_bounds(vertices: np.ndarray, faces: np.ndarray):
    """lo, hi (F, 3) float64 of the triangles faces (F, >=3) of vertices (V, 3)."""
    faces = np.ascontiguousarray(faces)
    lo = np.empty((len(faces), 3))
    hi = np.empty((len(faces), 3))
    _triangle_bounds(np.ascontiguousarray(vertices, dtype=np.float64), faces, lo, hi)
    return lo, hi


@njit(cache=True)
def _triangle_bounds(vertices, faces, lo, hi):
    for f in range(faces.shape[0]):
        a, b, c = faces[f, 0], faces[f, 1], faces[f, 2]
        for axis in range(3):
            x, y, z = vertices[a, axis], vertices[b, axis], vertices[c, axis]
            lo[f, axis] = min(x, min(y, z))
            hi[f, axis] = max(x, max(y, z))
