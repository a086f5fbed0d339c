"""The BVH of the numba and WGSL paths: the binned SAH build of rtfgu.accelerators.bvh over
arrays, into a flat node table that both paths traverse.

The build is the lecture BVH's (BINS bins, LEAF_SIZE, C_INTERSECT) over the primitives'
boxes as arrays, with numba on all cores when it is installed (task_size says how; the
1.3-million-triangle mesh of `make bench` builds in about 1 s on 2 cores, docs/bvh.md) and as
plain Python otherwise, the same table either way. It has one
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

import contextlib

import time
from dataclasses import dataclass, field

import numpy as np

from .bvh import BINS, C_INTERSECT, LEAF_SIZE

from ..jit import chunks_of_one, njit, one_thread, prange, threads

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
    _blocked: tuple = field(default=None, repr=False, compare=False)

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

    def wide_with_blocks(self, roots, vertices, faces):
        """The wide tree with its bottom nodes made blocks of faces
        (rtfgu.accelerators.wide_bvh.with_blocks; their corners copied where ``vertices`` are
        float32): ``vertices`` and ``faces`` those this table was built over (a FlatMesh's),
        made at the first call for their precision and kept with the table."""
        from .wide_bvh import with_blocks
        key = (tuple(int(r) for r in roots), np.dtype(vertices.dtype))
        if self._blocked is None or self._blocked[0] != key[0]:
            self._blocked = (key[0], {})
        if key[1] not in self._blocked[1]:
            self._blocked[1][key[1]] = with_blocks(self.wide(key[0]), vertices, faces)
        return self._blocked[1][key[1]]

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


@njit(cache=True, parallel=True)
def _references(lo, hi):
    """The primitives as the build moves them (Embree's PrimRef): a row each, [lo (3), hi (3)],
    kept in the order of ``order`` as the build reorders it, so that a node's primitives are
    read one row after another. Their centroids are computed where they are read
    (_centroid), not stored: 48 bytes a primitive to move, not 72."""
    refs = np.empty((lo.shape[0], 6))
    for p in prange(lo.shape[0]):
        for axis in range(3):
            refs[p, axis] = lo[p, axis]
            refs[p, 3 + axis] = hi[p, axis]
    return refs


@njit(cache=True, inline="always")
def _centroid(r, axis):
    """The centroid of a primitive's box ``r`` (a row of refs) on ``axis``."""
    return 0.5 * (r[axis] + r[3 + axis])


# The build's helpers below are inlined where they are called (a call counted a reference per
# array it was given): docs/bvh.md, "The blocks and the build's helpers, compiled".
@njit(cache=True, inline="always")
def _node_bounds(refs, first, count, out):
    """out[0:6] = the box of primitives first..first + count - 1 (rows of ``refs``), out[6:12]
    the box of their centroids, each [lo, hi]."""
    b0 = np.inf; b1 = np.inf; b2 = np.inf; b3 = -np.inf; b4 = -np.inf; b5 = -np.inf
    c0 = np.inf; c1 = np.inf; c2 = np.inf; c3 = -np.inf; c4 = -np.inf; c5 = -np.inf
    for k in range(first, first + count):
        r = refs[k]
        b0 = min(b0, r[0]); b1 = min(b1, r[1]); b2 = min(b2, r[2])
        b3 = max(b3, r[3]); b4 = max(b4, r[4]); b5 = max(b5, r[5])
        x = _centroid(r, 0); y = _centroid(r, 1); z = _centroid(r, 2)
        c0 = min(c0, x); c1 = min(c1, y); c2 = min(c2, z)
        c3 = max(c3, x); c4 = max(c4, y); c5 = max(c5, z)
    out[0], out[1], out[2], out[3], out[4], out[5] = b0, b1, b2, b3, b4, b5
    out[6], out[7], out[8], out[9], out[10], out[11] = c0, c1, c2, c3, c4, c5


@njit(cache=True, inline="always")
def _bin(refs, first, count, bounds, scale, bin_count, bin_box):
    """Add primitives first..first + count - 1 to the bins of all three axes at once
    (bin_count (3, bins), bin_box (3, bins, 6)), by their centroids over the centroid box
    bounds[6:12]; an axis whose ``scale`` is 0 (no extent) is skipped."""
    bins = bin_count.shape[1]
    for k in range(first, first + count):
        r = refs[k]
        l0, l1, l2, h0, h1, h2 = r[0], r[1], r[2], r[3], r[4], r[5]
        for axis in range(3):
            if scale[axis] == 0.0:
                continue
            j = min(int(scale[axis] * (_centroid(r, axis) - bounds[6 + axis])), bins - 1)
            bin_count[axis, j] += 1
            box_j = bin_box[axis, j]
            box_j[0] = min(box_j[0], l0); box_j[1] = min(box_j[1], l1); box_j[2] = min(box_j[2], l2)
            box_j[3] = max(box_j[3], h0); box_j[4] = max(box_j[4], h1); box_j[5] = max(box_j[5], h2)


@njit(cache=True, inline="always")
def _bin_scale(bounds, bins, scale):
    for axis in range(3):
        extent = bounds[9 + axis] - bounds[6 + axis]
        scale[axis] = bins / extent if extent > 0.0 else 0.0


@njit(cache=True, inline="always")
def _empty_bins(bin_count, bin_box):
    bin_count[:, :] = 0
    bin_box[:, :, 0:3] = np.inf
    bin_box[:, :, 3:6] = -np.inf


@njit(cache=True, inline="always")
def _as_a_leaf(bounds, count, leaf_size, c_intersect):
    """What a plane must beat: (the area of the node's box, the cost of leaving the node a
    leaf, inf where it has more than leaf_size primitives, axis -1, plane 0.0)."""
    area = _surface_area(bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5])
    return area, (c_intersect * count if count <= leaf_size else np.inf), -1, 0.0


@njit(cache=True, inline="always")
def _best_plane(bin_count, bin_box, bounds, scale, count, leaf_size, c_traverse, c_intersect,
                right_area, right_count):
    """The binned SAH (rtfgu.accelerators.bvh.BVH._best_split) over the filled bins: (axis,
    plane) of the cheapest plane, axis -1 where none is cheaper than a leaf of a node small
    enough to be one. A node bigger than that is split at its cheapest plane, whatever it
    costs (PBRT-v4 section 7.3.4)."""
    bins = bin_count.shape[1]
    area, best_cost, best_axis, best_plane = _as_a_leaf(bounds, count, leaf_size, c_intersect)
    for axis in range(3):
        if scale[axis] == 0.0:
            continue
        clo = bounds[6 + axis]
        extent = bounds[9 + axis] - clo
        # Sweep from the right: area and count of bins j..bins-1.
        r0 = np.inf; r1 = np.inf; r2 = np.inf; r3 = -np.inf; r4 = -np.inf; r5 = -np.inf
        n_right = 0
        # An empty bin changes neither side: the plane past it costs what the plane before
        # it cost (and is no cheaper), so it is skipped, as are its min and max.
        area_right = 0.0
        for j in range(bins - 1, 0, -1):
            if bin_count[axis, j] > 0:
                r0 = min(r0, bin_box[axis, j, 0]); r1 = min(r1, bin_box[axis, j, 1]); r2 = min(r2, bin_box[axis, j, 2])
                r3 = max(r3, bin_box[axis, j, 3]); r4 = max(r4, bin_box[axis, j, 4]); r5 = max(r5, bin_box[axis, j, 5])
                n_right += bin_count[axis, j]
                area_right = _surface_area(r0, r1, r2, r3, r4, r5)
            right_count[j] = n_right
            right_area[j] = area_right
        l0 = np.inf; l1 = np.inf; l2 = np.inf; l3 = -np.inf; l4 = -np.inf; l5 = -np.inf
        n_left = 0
        for plane in range(1, bins):
            j = plane - 1
            if bin_count[axis, j] == 0:
                continue
            l0 = min(l0, bin_box[axis, j, 0]); l1 = min(l1, bin_box[axis, j, 1]); l2 = min(l2, bin_box[axis, j, 2])
            l3 = max(l3, bin_box[axis, j, 3]); l4 = max(l4, bin_box[axis, j, 4]); l5 = max(l5, bin_box[axis, j, 5])
            n_left += bin_count[axis, j]
            if right_count[plane] == 0 or not area > 0.0:
                continue
            cost = c_traverse + c_intersect * (_surface_area(l0, l1, l2, l3, l4, l5) * n_left
                                               + right_area[plane] * right_count[plane]) / area
            if cost < best_cost:
                best_cost = cost
                best_axis = axis
                best_plane = clo + extent * plane / bins
    return best_axis, best_plane


# A node of at most FEW primitives chooses its plane without the bins (_best_plane_few);
# docs/bvh.md, "The blocks and the build's helpers, compiled".
FEW = 8


@njit(cache=True, inline="always")
def _best_plane_few(refs, first, count, bounds, scale, bins, leaf_size, c_traverse, c_intersect, by_bin,
                    right_area):
    """_best_plane of a node of few primitives (count <= FEW) without filling the bins: on
    each axis its primitives sorted by the bin their centroid falls in (_bin's formula),
    then swept from the left, a plane costed after each run of one bin that has primitives
    after it. Those are the planes _best_plane costs (it skips the empty bins), with the
    same two boxes (min and max are exact in any order), counts and expression, in the same
    order: the same (axis, plane), at the cost of the primitives rather than of the bins.
    ``by_bin`` (FEW, 2) int64 and ``right_area`` (FEW,) are scratch."""
    area, best_cost, best_axis, best_plane = _as_a_leaf(bounds, count, leaf_size, c_intersect)
    for axis in range(3):
        if scale[axis] == 0.0:
            continue
        clo = bounds[6 + axis]
        for k in range(count):
            j = min(int(scale[axis] * (_centroid(refs[first + k], axis) - clo)), bins - 1)
            m = k
            while m > 0 and by_bin[m - 1, 0] > j:
                by_bin[m, 0] = by_bin[m - 1, 0]
                by_bin[m, 1] = by_bin[m - 1, 1]
                m -= 1
            by_bin[m, 0] = j
            by_bin[m, 1] = first + k
        # right_area[m]: the area of the box of the sorted primitives m..count-1.
        r0 = np.inf; r1 = np.inf; r2 = np.inf; r3 = -np.inf; r4 = -np.inf; r5 = -np.inf
        for m in range(count - 1, 0, -1):
            r = refs[by_bin[m, 1]]
            r0 = min(r0, r[0]); r1 = min(r1, r[1]); r2 = min(r2, r[2])
            r3 = max(r3, r[3]); r4 = max(r4, r[4]); r5 = max(r5, r[5])
            right_area[m] = _surface_area(r0, r1, r2, r3, r4, r5)
        l0 = np.inf; l1 = np.inf; l2 = np.inf; l3 = -np.inf; l4 = -np.inf; l5 = -np.inf
        for m in range(count - 1):
            r = refs[by_bin[m, 1]]
            l0 = min(l0, r[0]); l1 = min(l1, r[1]); l2 = min(l2, r[2])
            l3 = max(l3, r[3]); l4 = max(l4, r[4]); l5 = max(l5, r[5])
            if by_bin[m + 1, 0] == by_bin[m, 0] or not area > 0.0:
                continue
            n_left = m + 1
            n_right = count - n_left
            cost = c_traverse + c_intersect * (_surface_area(l0, l1, l2, l3, l4, l5) * n_left
                                               + right_area[n_left] * n_right) / area
            if cost < best_cost:
                best_cost = cost
                best_axis = axis
                best_plane = clo + (bounds[9 + axis] - clo) * (by_bin[m, 0] + 1) / bins    # _best_plane's
    return best_axis, best_plane


@njit(cache=True)
def _split_at(refs, order, first, count, bounds, axis, plane, left_bounds, right_bounds):
    """Reorder primitives first..first + count - 1 (``refs`` and ``order`` alike) into the
    two children and return where the right one starts: centroids below ``plane`` on
    ``axis`` first; with axis -1 (no plane pays), the median of the widest axis of the
    centroid box (by lo + hi, a stable sort). Fills each child's bounds as _node_bounds
    would (min and max are exact in any order): the partition gathers them as it sees each
    primitive, so no pass over the children is needed to start them."""
    if axis < 0:
        axis = 0
        if bounds[10] - bounds[7] > bounds[9] - bounds[6]:
            axis = 1
        if bounds[11] - bounds[8] > max(bounds[9] - bounds[6], bounds[10] - bounds[7]):
            axis = 2
        keys = np.empty(count)
        for k in range(count):
            keys[k] = refs[first + k, axis] + refs[first + k, 3 + axis]
        permutation = np.argsort(keys, kind="mergesort") + first
        order[first:first + count] = order[permutation]
        refs[first:first + count] = refs[permutation]
        mid = first + count // 2
        _node_bounds(refs, first, mid - first, left_bounds)
        _node_bounds(refs, mid, first + count - mid, right_bounds)
        return mid
    # Partition: centroids below the plane first. Each primitive is seen once, on its side.
    a0 = np.inf; a1 = np.inf; a2 = np.inf; a3 = -np.inf; a4 = -np.inf; a5 = -np.inf
    a6 = np.inf; a7 = np.inf; a8 = np.inf; a9 = -np.inf; a10 = -np.inf; a11 = -np.inf
    b0 = np.inf; b1 = np.inf; b2 = np.inf; b3 = -np.inf; b4 = -np.inf; b5 = -np.inf
    b6 = np.inf; b7 = np.inf; b8 = np.inf; b9 = -np.inf; b10 = -np.inf; b11 = -np.inf
    i = first
    j = first + count - 1
    while i <= j:
        r = refs[i]
        x = _centroid(r, 0); y = _centroid(r, 1); z = _centroid(r, 2)
        if (x if axis == 0 else y if axis == 1 else z) < plane:
            a0 = min(a0, r[0]); a1 = min(a1, r[1]); a2 = min(a2, r[2])
            a3 = max(a3, r[3]); a4 = max(a4, r[4]); a5 = max(a5, r[5])
            a6 = min(a6, x); a7 = min(a7, y); a8 = min(a8, z)
            a9 = max(a9, x); a10 = max(a10, y); a11 = max(a11, z)
            i += 1
        else:
            b0 = min(b0, r[0]); b1 = min(b1, r[1]); b2 = min(b2, r[2])
            b3 = max(b3, r[3]); b4 = max(b4, r[4]); b5 = max(b5, r[5])
            b6 = min(b6, x); b7 = min(b7, y); b8 = min(b8, z)
            b9 = max(b9, x); b10 = max(b10, y); b11 = max(b11, z)
            p = order[i]
            order[i] = order[j]
            order[j] = p
            for c in range(6):
                refs[i, c], refs[j, c] = refs[j, c], refs[i, c]
            j -= 1
    if i == first or i == first + count:
        # Rounding put every centroid on one side of a plane the bins had between them.
        mid = first + count // 2
        _node_bounds(refs, first, mid - first, left_bounds)
        _node_bounds(refs, mid, first + count - mid, right_bounds)
        return mid
    left_bounds[0], left_bounds[1], left_bounds[2], left_bounds[3] = a0, a1, a2, a3
    left_bounds[4], left_bounds[5], left_bounds[6], left_bounds[7] = a4, a5, a6, a7
    left_bounds[8], left_bounds[9], left_bounds[10], left_bounds[11] = a8, a9, a10, a11
    right_bounds[0], right_bounds[1], right_bounds[2], right_bounds[3] = b0, b1, b2, b3
    right_bounds[4], right_bounds[5], right_bounds[6], right_bounds[7] = b4, b5, b6, b7
    right_bounds[8], right_bounds[9], right_bounds[10], right_bounds[11] = b8, b9, b10, b11
    return i


@njit(cache=True)
def _subtree(refs, order, table, links, root, first, count, depth, root_bounds, next_node, leaf_size, bins,
             c_traverse, c_intersect, max_depth):
    """Build the subtree of primitives first..first + count - 1 at node ``root`` (at
    ``depth``; ``root_bounds`` its _node_bounds), its children placed from node
    ``next_node`` on, next to each other: fill the rows of ``table`` (N, 8) float32, the
    node table of the module docstring, its box rounded out (_put_box) and its links in
    ``links``, the same array as int32 (a leaf: first primitive, count; an inner node: left
    child, 0). Returns the first
    node it left free, or -1 where the tree would be deeper than ``max_depth``. Nodes are
    taken from a stack of (node, first, count, depth) and their bounds, the left child
    first."""
    stack = np.empty((4 * max_depth, 4), dtype=np.int64)
    stack_bounds = np.empty((4 * max_depth + 4, 12))
    stack[0, 0], stack[0, 1], stack[0, 2], stack[0, 3] = root, first, count, depth
    stack_bounds[0, :] = root_bounds
    sp = 1
    n_nodes = next_node
    bin_count = np.zeros((3, bins), dtype=np.int64)
    bin_box = np.empty((3, bins, 6))
    right_area = np.empty(bins)
    right_count = np.empty(bins, dtype=np.int64)
    scale = np.zeros(3)
    by_bin = np.empty((FEW, 2), dtype=np.int64)
    few_area = np.empty(FEW)
    while sp > 0:
        sp -= 1
        node, first, count, depth = stack[sp, 0], stack[sp, 1], stack[sp, 2], stack[sp, 3]
        if depth > max_depth:
            return -1
        bounds = stack_bounds[sp]
        _put_box(bounds, table, links, node, 4)
        if count <= 1:
            links[node, 3], links[node, 7] = first, count
            continue
        _bin_scale(bounds, bins, scale)
        if count <= FEW:
            axis, plane = _best_plane_few(refs, first, count, bounds, scale, bins, leaf_size, c_traverse,
                                          c_intersect, by_bin, few_area)
        else:
            _empty_bins(bin_count, bin_box)
            _bin(refs, first, count, bounds, scale, bin_count, bin_box)
            axis, plane = _best_plane(bin_count, bin_box, bounds, scale, count, leaf_size, c_traverse,
                                      c_intersect, right_area, right_count)
        if axis < 0 and count <= leaf_size:
            links[node, 3], links[node, 7] = first, count
            continue
        # The right child's bounds go below the left's, over this node's (read: done).
        mid = _split_at(refs, order, first, count, bounds, axis, plane, stack_bounds[sp + 2], stack_bounds[sp + 3])
        stack_bounds[sp + 1, :] = stack_bounds[sp + 2]
        stack_bounds[sp, :] = stack_bounds[sp + 3]
        left = n_nodes
        n_nodes += 2
        links[node, 3], links[node, 7] = left, 0
        stack[sp, 0], stack[sp, 1], stack[sp, 2], stack[sp, 3] = left + 1, mid, first + count - mid, depth + 1
        stack[sp + 1, 0], stack[sp + 1, 1], stack[sp + 1, 2], stack[sp + 1, 3] = left, first, mid - first, depth + 1
        sp += 2
    return n_nodes


# The parallel build (_build): a node of more than task_size(P) primitives is split with its
# bounds and bins made by all cores (PARTS parts of its primitives each, merged: min, max and
# counts are exact in any order), and each node of at most task_size(P) below them is a
# subtree that one core builds (_subtree), the biggest first, handed out one at a time. A
# node's split depends only on its primitives and their order, so the tree is the one
# _subtree builds over all primitives at once, and the nodes are numbered again as that build
# numbers them: the table is the same, node for node, whatever the task size and the number
# of cores (tests/test_mesh_paths.py builds it both ways).
TASK_MIN = 1 << 17
TASK_FLOOR = 1 << 14
PARTS = 16


def task_size(n_prims: int) -> int:
    """The most primitives a subtree task of a build over ``n_prims`` holds: a thread's share,
    within [TASK_FLOOR, TASK_MIN] (the splits are uneven, so a thread gets one to a few
    tasks). A mesh of at most TASK_FLOOR primitives is one task (splitting its top on all
    cores costs more than it saves); one of a few tens of thousands is split a few times so
    that both cores build (docs/bvh.md, "A mesh's size and the build's tasks"). On one thread
    (or without numba) a mesh of at most TASK_MIN is one task, as before."""
    return min(TASK_MIN, max(TASK_FLOOR, n_prims // threads()))


@njit(cache=True, parallel=True)
def _node_bounds_parallel(refs, first, count, out):
    """_node_bounds with all cores: PARTS parts, merged."""
    parts = np.empty((PARTS, 12))
    for q in prange(PARTS):
        start = first + count * q // PARTS
        _node_bounds(refs, start, first + count * (q + 1) // PARTS - start, parts[q])
    for i in range(6):
        out[i] = parts[:, i].min()
        out[6 + i] = parts[:, 6 + i].min()
    for i in range(3):
        out[3 + i] = parts[:, 3 + i].max()
        out[9 + i] = parts[:, 9 + i].max()


@njit(cache=True, parallel=True)
def _split_node(refs, order, first, count, bounds, bins, leaf_size, c_traverse, c_intersect, left_bounds,
                right_bounds):
    """Split a node of the top of the tree as _subtree splits one (a node this big is never
    a leaf), its bins made by all cores: each of PARTS parts of its primitives into bins of
    its own, merged. Returns where the right child starts (_split_at)."""
    scale = np.zeros(3)
    _bin_scale(bounds, bins, scale)
    counts = np.zeros((PARTS, 3, bins), dtype=np.int64)
    boxes = np.empty((PARTS, 3, bins, 6))
    for q in prange(PARTS):
        _empty_bins(counts[q], boxes[q])
        start = first + count * q // PARTS
        _bin(refs, start, first + count * (q + 1) // PARTS - start, bounds, scale, counts[q], boxes[q])
    bin_count = np.zeros((3, bins), dtype=np.int64)
    bin_box = np.empty((3, bins, 6))
    for axis in range(3):
        for j in range(bins):
            bin_count[axis, j] = counts[:, axis, j].sum()
            for i in range(3):
                bin_box[axis, j, i] = boxes[:, axis, j, i].min()
                bin_box[axis, j, 3 + i] = boxes[:, axis, j, 3 + i].max()
    axis, plane = _best_plane(bin_count, bin_box, bounds, scale, count, leaf_size, c_traverse, c_intersect,
                              np.empty(bins), np.empty(bins, dtype=np.int64))
    return _split_at(refs, order, first, count, bounds, axis, plane, left_bounds, right_bounds)


@njit(cache=True, parallel=True)
def _subtrees(refs, order, table, links, tasks, task_bounds, leaf_size, bins, c_traverse, c_intersect,
              max_depth, ends):
    """_subtree of each row (node, first, count, depth, next node) of ``tasks`` with its
    bounds ``task_bounds``, all cores; ends[i] = what task i returned."""
    for i in prange(tasks.shape[0]):
        ends[i] = _subtree(refs, order, table, links, tasks[i, 0], tasks[i, 1], tasks[i, 2], tasks[i, 3],
                           task_bounds[i], tasks[i, 4], leaf_size, bins, c_traverse, c_intersect, max_depth)


@njit(cache=True, parallel=True)
def _place_blocks(links_in, blocks, links):
    """Copy each block (start, end, new start) of rows of the node table links_in (as int32)
    to its new start in links, its inner nodes' left children moved with it."""
    for i in prange(blocks.shape[0]):
        start, end, to = blocks[i, 0], blocks[i, 1], blocks[i, 2]
        shift = to - start
        for k in range(end - start):
            for c in range(NODE_WIDTH):
                links[to + k, c] = links_in[start + k, c]
            if links_in[start + k, 7] == 0:
                links[to + k, 3] += shift


def _build(refs, order):
    """The node table (N, 8) float32 of the tree over all primitives, root node 0, as the
    parallel build makes it (task_size), or None where it would be deeper than MAX_DEPTH."""
    n_prims = len(order)
    task_min = task_size(n_prims)
    root_bounds = np.empty(12)
    # The top of the tree, each node split by all cores; its nodes numbered as they come.
    # (A tree of at most task_min primitives is one task, its root.)
    _node_bounds_parallel(refs, 0, n_prims, root_bounds)
    top, tasks = [], []
    stack = [(0, 0, n_prims, 1, root_bounds)]
    n_top = 1
    while stack:
        node, first, count, depth, bounds = stack.pop()
        if count <= task_min:
            tasks.append((node, first, count, depth, bounds))
            continue
        if depth > MAX_DEPTH:
            return None
        left_bounds, right_bounds = np.empty(12), np.empty(12)
        mid = _split_node(refs, order, first, count, bounds, BINS, LEAF_SIZE, C_TRAVERSE, C_INTERSECT,
                          left_bounds, right_bounds)
        top.append((node, bounds[:6], n_top))
        stack.append((n_top + 1, mid, first + count - mid, depth + 1, right_bounds))
        stack.append((n_top, first, mid - first, depth + 1, left_bounds))
        n_top += 2
    # Below it, the subtrees: task i's children from node n_top + 2 first on (a subtree of
    # c primitives has at most 2 c - 1 nodes).
    table_in = np.empty((n_top + 2 * n_prims, NODE_WIDTH), dtype=np.float32)
    links_in = table_in.view(np.int32)
    for node, node_box, left in top:
        _put_box(node_box, table_in, links_in, node, 4)
        links_in[node, 3], links_in[node, 7] = left, 0
    tasks.sort(key=lambda task: -task[2])    # the biggest first
    rows = np.array([(node, first, count, depth, n_top + 2 * first) for node, first, count, depth, _ in tasks],
                    dtype=np.int64)
    task_bounds = np.array([task[4] for task in tasks])
    ends = np.empty(len(rows), dtype=np.int64)
    with chunks_of_one():
        _subtrees(refs, order, table_in, links_in, rows, task_bounds, LEAF_SIZE, BINS, C_TRAVERSE, C_INTERSECT,
                  MAX_DEPTH, ends)
    if (ends < 0).any():
        return None
    # Number the nodes as the serial build does: a node's children get the next two numbers
    # when it is taken from the stack, the left one taken next, so the nodes below a task's
    # root take the next (end - start) numbers in the order its own build gave them.
    below = {int(r[0]): (int(r[4]), int(e)) for r, e in zip(rows, ends)}
    blocks = []
    placed = []    # (node, its row in table_in, its left child's number or -1: the row's own)
    stack = [(0, 0)]
    n_nodes = 1
    while stack:
        source, node = stack.pop()
        if source in below:
            start, end = below[source]
            placed.append((node, source, n_nodes - start + links_in[source, 3] if links_in[source, 7] == 0 else -1))
            blocks.append((start, end, n_nodes))
            n_nodes += end - start
            continue
        left = int(links_in[source, 3])
        placed.append((node, source, n_nodes))
        stack.append((left + 1, n_nodes + 1))
        stack.append((left, n_nodes))
        n_nodes += 2
    table = np.empty((n_nodes, NODE_WIDTH), dtype=np.float32)
    links = table.view(np.int32)
    for node, source, left in placed:
        links[node] = links_in[source]
        if left >= 0:
            links[node, 3] = left
    _place_blocks(links_in, np.array(blocks, dtype=np.int64), links)
    return table


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


@njit(cache=True, parallel=True)
def _round_out(box, out, bits, high):
    """_put_box for every row of ``box`` (N, >= 6), into the same rows of ``out``."""
    for i in prange(box.shape[0]):
        _put_box(box[i], out, bits, i, high)


@njit(cache=True, inline="always")
def _put_box(box, out, bits, i, high):
    """Write the float64 box ``box`` [lo, hi] (its first 6 values) into the float32 row ``i``
    of ``out`` (``bits``: the same array as int32), lo at columns 0-2 and hi at ``high``..``high``
    + 2, lo rounded down and hi up to a float32: the nearest float32, moved one step where it
    lies on the wrong side (np.nextafter's step, done on the bits: one float32 further from
    zero is the next integer, ±0 steps to the smallest subnormal)."""
    for axis in range(3):
        lo = np.float32(box[axis])
        out[i, axis] = lo
        if np.float64(lo) > box[axis]:
            if lo == 0:
                bits[i, axis] = -2147483647    # 0x80000001: the subnormal below -0
            else:
                bits[i, axis] += -1 if lo > 0 else 1
        hi = np.float32(box[3 + axis])
        out[i, high + axis] = hi
        if np.float64(hi) < box[3 + axis]:
            if hi == 0:
                bits[i, high + axis] = 1
            else:
                bits[i, high + axis] += 1 if hi > 0 else -1


def build(lo, hi) -> FlatBVH:
    """The BVH over primitives with boxes lo (P, 3), hi (P, 3) (float64, finite, lo <= hi)."""
    lo = np.ascontiguousarray(lo, dtype=np.float64)
    hi = np.ascontiguousarray(hi, dtype=np.float64)
    if lo.shape != hi.shape or lo.ndim != 2 or lo.shape[1] != 3 or len(lo) == 0:
        raise ValueError("BVH: lo and hi must be (P, 3) arrays with P >= 1, got %s and %s" % (lo.shape, hi.shape))
    with _threads_for(len(lo)):
        refs = _references(lo, hi)
    return build_rows(refs)


def _threads_for(n_prims: int):
    """The threads a pass or a build over ``n_prims`` primitives runs on: all of numba's, or
    where it is one task (at most TASK_FLOOR), the calling thread alone (rtfgu.jit.one_thread:
    on a busy machine each parallel loop would wait milliseconds for a second core; docs/bvh.md,
    "A small mesh's build on a busy machine"). The tree is the same either way."""
    return one_thread() if n_prims <= TASK_FLOOR else contextlib.nullcontext()


def build_rows(refs) -> FlatBVH:
    """The BVH over primitives with boxes ``refs`` (P, 6) float64 [lo, hi] (finite, lo <= hi),
    which the build reorders: made for it (_references, triangle_rows), so a mesh's boxes
    are written once."""
    if refs.dtype != np.float64 or refs.ndim != 2 or refs.shape[1] != 6 or len(refs) == 0:
        raise ValueError("BVH: the boxes must be a (P, 6) float64 array with P >= 1, got %s %s"
                         % (refs.shape, refs.dtype))
    if not np.isfinite(refs).all():
        raise ValueError("BVH: a primitive's box is not finite")
    start = time.perf_counter()
    order = np.arange(len(refs), dtype=np.int32)
    with _threads_for(len(refs)):
        nodes = _build(refs, order)
        if nodes is None:
            raise ValueError("BVH: the tree would be deeper than %d levels (degenerate boxes)" % MAX_DEPTH)
        boxes = np.empty((len(order), 6), dtype=np.float32)    # refs are in leaf order now
        _round_out(refs, boxes, boxes.view(np.int32), 3)
    return FlatBVH(nodes, order, time.perf_counter() - start, boxes)


def offset(bvh: FlatBVH, first_node: int, first_primitive: int) -> FlatBVH:
    """``bvh`` as it reads placed after ``first_node`` nodes and ``first_primitive``
    primitives of other trees in one table (the trees of instanced meshes, rtfgu.layout)."""
    nodes = bvh.nodes.copy()
    links = nodes.view(np.int32)
    leaf = links[:, 7] > 0
    links[:, 3] += np.where(leaf, first_primitive, first_node).astype(np.int32)
    return FlatBVH(nodes, bvh.order + np.int32(first_primitive), bvh.build_seconds, bvh.boxes)


def triangle_rows(vertices: np.ndarray, faces: np.ndarray, lo=None, hi=None) -> np.ndarray:
    """build_rows' boxes (F + E, 6) float64 [lo, hi] of the triangles faces (F, >=3) of
    vertices (V, 3), followed by the boxes lo, hi (E, 3) where given (spheres, instances)."""
    faces = np.ascontiguousarray(faces)
    extra = 0 if lo is None else len(lo)
    rows = np.empty((len(faces) + extra, 6))
    with _threads_for(len(faces)):
        _triangle_bounds(np.ascontiguousarray(vertices, dtype=np.float64), faces, rows[:, :3], rows[:, 3:])
    if extra:
        rows[len(faces):, :3] = lo
        rows[len(faces):, 3:] = hi
    return rows


def triangle_bounds(vertices: np.ndarray, faces: np.ndarray):
    """lo, hi (F, 3) float64 of the triangles faces (F, >=3) of vertices (V, 3): the two
    halves of triangle_rows."""
    rows = triangle_rows(vertices, faces)
    return rows[:, :3], rows[:, 3:]


@njit(cache=True, parallel=True)
def _triangle_bounds(vertices, faces, lo, hi):
    for f in prange(faces.shape[0]):
        a, b, c = faces[f, 0], faces[f, 1], faces[f, 2]
        for axis in range(3):
            x, y, z = vertices[a, axis], vertices[b, axis], vertices[c, axis]
            lo[f, axis] = min(x, min(y, z))
            hi[f, axis] = max(x, max(y, z))
