"""The wide BVH of the numba path (rtfgu.accelerators.wide_bvh, rtfgu.kernels.wide_bvh): the
collapse keeps every leaf and every box of the binary tree, the vector box test (an LLVM
intrinsic) is the scalar slab test lane by lane, and the wide traversal gives every ray the
binary traversal's face and t (the tie rule included) and its shadow answer, in both
precisions, with no leak from inside a closed mesh; through rtfgu.render the two trees give
the same image."""
from __future__ import annotations

import math

import numpy as np
import pytest
import trimesh
from numba import njit, prange

from rtfgu.accelerators import flat_bvh, wide_bvh
from rtfgu.kernels import render as render_kernels
from rtfgu.kernels.float3 import lit, lit_per_precision
from rtfgu.kernels.mesh import WIDEN32, WIDEN64, _inverse, box_entry, intersect_face, mesh_any, mesh_closest, ray_frame
from rtfgu.kernels.wide_bvh import box8, lanes_of

PRECISIONS = (np.float64, np.float32)


def tree_of(vertices, faces):
    """The binary tree, the wide one, and the (F, 4) faces in leaf order with their index."""
    bvh = flat_bvh.build(*flat_bvh.triangle_bounds(vertices, faces))
    rows = np.empty((len(faces), 4), dtype=np.int32)
    rows[:, :3] = faces[bvh.order]
    rows[:, 3] = bvh.order
    return bvh, bvh.wide(), rows


def leaves_of_binary(bvh, root=0):
    links = bvh.links
    out, stack = [], [root]
    while stack:
        n = stack.pop()
        if links[n, 7] > 0:
            out.append((int(links[n, 3]), int(links[n, 7]), tuple(bvh.nodes[n, [0, 1, 2, 4, 5, 6]])))
        else:
            stack += [links[n, 3], links[n, 3] + 1]
    return sorted(out)


def leaves_of_wide(wide, root=0):
    links = wide.links
    out, stack, nodes = [], [root], 0
    while stack:
        n = stack.pop()
        nodes += 1
        for j in range(wide_bvh.WIDTH):
            box = tuple(wide.nodes[n, :6, j])
            code = int(links[n, wide_bvh.CODE_ROW, j])
            if not np.isfinite(box).all():     # an empty column: the empty box, which no ray enters
                assert box == (math.inf,) * 3 + (-math.inf,) * 3
            elif code < 0:
                leaf = ~code
                first, count = leaf >> wide_bvh.LEAF_BITS, (leaf & (2 ** wide_bvh.LEAF_BITS - 1)) + 1
                assert wide_bvh.leaf_code(first, count) == code
                out.append((first, count, box))
            else:
                stack.append(code)
    return sorted(out), nodes


def opened_leaves_closed(wide_leaves, bvh, root=0):
    """The wide tree's leaves with the leaves the collapse opened (a column per primitive)
    put back together, each checked: a primitive's column holds its own box (FlatBVH.boxes),
    inside its leaf's, and a leaf is opened whole or not at all."""
    binary = {first: (count, box) for first, count, box in leaves_of_binary(bvh, root)}
    out, singles = [], {}
    for first, count, box in wide_leaves:
        if first in binary and binary[first] == (count, box):
            out.append((first, count, box))
            continue
        assert count == 1, "a wide leaf of several primitives is a binary leaf"
        assert box == tuple(bvh.boxes[first])
        leaf = max(f for f in binary if f <= first)
        assert first < leaf + binary[leaf][0]
        lo, hi = np.array(binary[leaf][1][:3]), np.array(binary[leaf][1][3:])
        assert (np.array(box[:3]) >= lo).all() and (np.array(box[3:]) <= hi).all()
        singles.setdefault(leaf, []).append(first)
    for leaf, primitives in singles.items():
        assert sorted(primitives) == list(range(leaf, leaf + binary[leaf][0]))
        out.append((leaf,) + binary[leaf])
    return sorted(out), len(singles)


def soup(count, seed, spread=1.0, size=0.3):
    rng = np.random.default_rng(seed)
    centers = rng.uniform(-spread, spread, (count, 1, 3))
    vertices = (centers + rng.uniform(-size, size, (count, 3, 3))).reshape(-1, 3)
    return vertices, np.arange(3 * count).reshape(count, 3)


def traversal_mesh(name):
    """The traversal tests' meshes: "soup", "icosphere" (closed), or "coincident": each face
    twice at the same place, so every hit is a tie that the earlier copy wins."""
    if name == "soup":
        return soup(3000, seed=4)
    if name == "icosphere":
        return closed_mesh(4)
    vertices, faces = soup(500, seed=8)
    return vertices, np.concatenate([faces, faces])[np.random.default_rng(0).permutation(1000)]


def closed_mesh(subdivisions=3):
    sphere = trimesh.creation.icosphere(subdivisions=subdivisions)
    return np.asarray(sphere.vertices, dtype=np.float64), np.asarray(sphere.faces, dtype=np.int64)


def rays_from_inside(subdivisions=3):
    """A closed icosphere's tree, and rays from two points inside it through each of its
    vertices and edge midpoints, where a leak between faces would be: (vertices, rows, wide,
    [(origins, directions) per inside point])."""
    vertices, faces = closed_mesh(subdivisions)
    _, wide, rows = tree_of(vertices, faces)
    edges = {tuple(sorted((int(f[a]), int(f[(a + 1) % 3])))) for f in faces for a in range(3)}
    targets = np.concatenate([vertices, [(vertices[i] + vertices[j]) * 0.5 for i, j in sorted(edges)]])
    rays = []
    for origin in ((0.0, 0.0, 0.0), (0.125, -0.0625, 0.25)):
        origins = np.tile(origin, (len(targets), 1))
        rays.append((origins, targets - origins))
    return vertices, rows, wide, rays


def hard_rays(vertices, count, seed):
    """Rays from around the mesh at random points of it, and rays along the axes (zero
    direction components, negative zeros) and through vertices: the slab test's NaN and
    infinite cases and the faces' shared edges."""
    rng = np.random.default_rng(seed)
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    origins = rng.uniform(lo - 1.0, hi + 1.0, (count, 3))
    targets = vertices[rng.integers(0, len(vertices), count)] + rng.normal(0.0, 0.05, (count, 3))
    directions = targets - origins
    k = count // 4
    axis = rng.integers(0, 3, k)
    directions[:k] = 0.0
    directions[np.arange(k), axis] = rng.choice([-1.0, 1.0], k)
    directions[:k // 2][directions[:k // 2] == 0.0] = -0.0
    origins[k:2 * k] = np.round(origins[k:2 * k] * 4) / 4     # origins on box planes, often
    directions[2 * k:3 * k] = vertices[rng.integers(0, len(vertices), k)] - origins[2 * k:3 * k]
    return origins, directions


@njit(parallel=True, error_model="numpy")
def trace_all(vertices, faces, nodes, links, origins, directions, hits, shadows):
    for i in prange(origins.shape[0]):
        origin = (origins[i, 0], origins[i, 1], origins[i, 2])
        direction = (directions[i, 0], directions[i, 1], directions[i, 2])
        tmin = lit(0, origins[i, 0])
        t, index, kind, row = mesh_closest(vertices, faces, nodes, links, None, origin, direction, tmin,
                                           (lit(math.inf, tmin), -1, -1, -1), 0)
        hits[i, 0] = t
        hits[i, 1] = index
        hits[i, 2] = row
        # a shadow ray to a point just short of the nearest face, and one past it
        reach = lit(4, tmin) if t == lit(math.inf, tmin) else t
        shadows[i, 0] = mesh_any(vertices, faces, nodes, links, None, origin, direction, tmin,
                                 reach * lit(0.5, tmin), 0)
        shadows[i, 1] = mesh_any(vertices, faces, nodes, links, None, origin, direction, tmin,
                                 reach * lit(1.5, tmin), 0)


@njit(error_model="numpy")
def loop_one(vertices, faces, origin, direction):
    """The truth of the tie rule: every face tested, the nearest kept, of equal ts the one of
    the lower index (tested up to the next float above the best t)."""
    tmin = lit(0, origin[0])
    inf = lit(math.inf, tmin)
    frame = ray_frame(origin, direction)
    tmax, best, row = inf, -1, -1
    for f in range(faces.shape[0]):
        idx = faces[f, 3]
        limit = tmax if idx > best else np.nextafter(tmax, inf)
        t = intersect_face(vertices, faces, f, frame, tmin, limit)
        if t < tmax or (t == tmax and idx < best):
            tmax, best, row = t, idx, f
    return tmax, best, row


@njit(parallel=True, error_model="numpy")
def loop_all(vertices, faces, origins, directions, hits):
    for i in prange(origins.shape[0]):
        t, best, row = loop_one(vertices, faces, (origins[i, 0], origins[i, 1], origins[i, 2]),
                                (directions[i, 0], directions[i, 1], directions[i, 2]))
        hits[i, 0] = t
        hits[i, 1] = best
        hits[i, 2] = row


def looped(vertices, faces, origins, directions, dtype):
    hits = np.empty((len(origins), 3), dtype=np.float64)
    loop_all(vertices.astype(dtype), faces, origins.astype(dtype), directions.astype(dtype), hits)
    return hits


def traced(vertices, faces, nodes, origins, directions, dtype):
    hits = np.empty((len(origins), 3), dtype=np.float64)
    shadows = np.empty((len(origins), 2), dtype=np.bool_)
    trace_all(vertices.astype(dtype), faces, nodes, nodes.view(np.int32), origins.astype(dtype),
              directions.astype(dtype), hits, shadows)
    return hits, shadows


# --- the build ----------------------------------------------------------------------------

def open_box():
    """The five walls of a unit box open at the front, two triangles a wall (as the Cornell
    box's), with the quads' diagonals alternating."""
    corners = np.array([[x, y, z] for x in (0.0, 1.0) for y in (0.0, 1.0) for z in (0.0, 1.0)])
    at = {tuple(c): i for i, c in enumerate(corners)}
    quads = [((0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)), ((0, 1, 0), (0, 1, 1), (1, 1, 1), (1, 1, 0)),
             ((0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0)), ((1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1)),
             ((0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1))]
    faces = []
    for k, q in enumerate(quads):
        a, b, c, d = (at[p] for p in q)
        faces += [(a, b, c), (a, c, d)] if k % 2 else [(a, b, d), (b, c, d)]
    return corners, np.array(faces, dtype=np.int32)


def test_a_node_too_big_for_a_leaf_splits_at_its_cheapest_plane():
    # Ten faces on five walls: no plane splits them for less than a leaf of all ten costs,
    # but ten is too many for a leaf. Split at the cheapest plane (PBRT-v4), every wall
    # ends in a leaf of its own; split at the median of the widest axis, leaves mixed walls,
    # boxes as big as the box, which every ray inside enters.
    vertices, faces = open_box()
    bvh = flat_bvh.build(*flat_bvh.triangle_bounds(vertices, faces))
    for first, count, box in leaves_of_binary(bvh):
        extent = np.array(box[3:]) - np.array(box[:3])
        assert extent.min() == 0.0, "a leaf's faces lie on one wall"


# --- the collapse -------------------------------------------------------------------------

@pytest.mark.parametrize("count", [1, 2, 7, 9, 300, 5000])
def test_the_collapse_keeps_every_leaf_and_box_of_the_binary_tree(count):
    bvh, wide, _ = tree_of(*soup(count, seed=count))
    binary_leaves = leaves_of_binary(bvh)
    wide_leaves, reached = leaves_of_wide(wide)
    closed, opened = opened_leaves_closed(wide_leaves, bvh)
    assert closed == binary_leaves
    assert reached == len(wide.nodes)                      # no node is unreachable
    assert sum(c for _, c, _ in wide_leaves) == count       # every primitive once
    if count >= 300:
        assert opened > 0          # nodes with columns left over open their leaves
    if count >= 300:
        # fewer levels: the depth of a leaf is about log8 rather than log2 of the count
        assert len(wide.nodes) * 4 < bvh.num_nodes


def test_a_node_opens_its_largest_child_first():
    # Two far clusters of unequal extent: the root's two children are the clusters, and the
    # wide root opens the larger one down to its leaves before the smaller.
    big, faces = soup(64, seed=1, spread=8.0, size=1.0)
    small, small_faces = soup(64, seed=2, spread=0.1, size=0.01)
    vertices = np.concatenate([big, small + 100.0])
    bvh, wide, _ = tree_of(vertices, np.concatenate([faces, small_faces + len(big)]))
    root_boxes = wide.nodes[0, :6, :].T
    in_small = (root_boxes[:, 0] > 50.0).sum()
    assert in_small == 1 and np.isfinite(root_boxes).all()


def test_the_roots_of_several_trees_in_one_table_are_collapsed_each():
    a_vertices, a_faces = soup(40, seed=5)
    b_vertices, b_faces = soup(90, seed=6)
    a = flat_bvh.build(*flat_bvh.triangle_bounds(a_vertices, a_faces))
    b = flat_bvh.offset(flat_bvh.build(*flat_bvh.triangle_bounds(b_vertices, b_faces)), a.num_nodes, len(a_faces))
    table = flat_bvh.FlatBVH(np.concatenate([a.nodes, b.nodes]), np.concatenate([a.order, b.order]), 0.0,
                             np.concatenate([a.boxes, b.boxes]))
    wide = table.wide((0, a.num_nodes))
    assert wide.roots[0] == 0
    for root, binary_root in zip(wide.roots, (0, a.num_nodes)):
        leaves = opened_leaves_closed(leaves_of_wide(wide, root)[0], table, binary_root)[0]
        assert leaves == leaves_of_binary(table, binary_root)
    assert table.wide((0, a.num_nodes)) is wide                # kept with the table


def test_a_leaf_too_big_for_the_stack_code_is_refused():
    bvh, _, _ = tree_of(*soup(3, seed=1))
    links = bvh.nodes.view(np.int32)
    links[0, 3], links[0, 7] = 0, 2 ** wide_bvh.LEAF_BITS + 1
    with pytest.raises(ValueError, match="leaf holds more than"):
        wide_bvh.collapse(flat_bvh.FlatBVH(bvh.nodes[:1].copy(), bvh.order, 0.0, bvh.boxes))


# --- the vector box test ------------------------------------------------------------------

@njit(error_model="numpy")
def both_box_tests(nodes8, wide_nodes, origin, direction, tmin, tmax, out_scalar, out_vector):
    inv = _inverse(direction)
    entry = lanes_of(tmin)
    mask = box8(wide_nodes, 0, origin, inv[0], tmin, tmax, lit_per_precision(WIDEN32, WIDEN64, tmin), entry)
    for j in range(8):
        out_scalar[j] = box_entry(nodes8, j, origin, inv, tmin, tmax)
        out_vector[j] = entry[j]
    return mask


@pytest.mark.parametrize("dtype", PRECISIONS, ids=lambda d: d.__name__)
def test_the_vector_box_test_is_the_scalar_one_lane_by_lane(dtype):
    rng = np.random.default_rng(7)
    mismatches = []
    for trial in range(400):
        lo = rng.uniform(-1, 1, (8, 3)).astype(np.float32)
        hi = lo + rng.uniform(0, 1, (8, 3)).astype(np.float32)
        if trial % 4 == 0:
            hi[3] = lo[3]                                          # flat boxes
        nodes8 = np.zeros((8, 8), dtype=np.float32)
        nodes8[:, 0:3], nodes8[:, 4:7] = lo, hi
        wide = np.zeros((1, wide_bvh.ROWS, 8), dtype=np.float32)
        wide[0, 0:3, :], wide[0, 3:6, :] = lo.T, hi.T
        origin = rng.uniform(-2, 2, 3)
        if trial % 3 == 0:
            origin[trial % 3] = lo[trial % 8, trial % 3]           # on a box's plane
        direction = rng.normal(size=3)
        if trial % 5 == 0:
            direction[trial % 3] = 0.0 if trial % 2 else -0.0      # in a slab's planes: 0 * inf
        tmin = dtype(rng.uniform(0, 0.5))
        tmax = dtype(math.inf if trial % 2 else rng.uniform(0.5, 3))
        scalar, vector = np.empty(8, dtype), np.empty(8, dtype)
        mask = both_box_tests(nodes8, wide, tuple(origin.astype(dtype)), tuple(direction.astype(dtype)), tmin, tmax,
                              scalar, vector)
        expected = sum(1 << j for j in range(8) if scalar[j] != math.inf)
        if mask != expected or scalar.tobytes() != vector.tobytes():
            mismatches.append((trial, mask, expected, scalar, vector))
    assert not mismatches, mismatches[:2]


# --- the traversal ------------------------------------------------------------------------

@pytest.mark.parametrize("dtype", PRECISIONS, ids=lambda d: d.__name__)
@pytest.mark.parametrize("mesh", ["soup", "icosphere", "coincident"])
def test_the_wide_traversal_finds_the_binary_ones_face_and_t_and_shadow(mesh, dtype):
    vertices, faces = traversal_mesh(mesh)
    bvh, wide, rows = tree_of(vertices, faces)
    origins, directions = hard_rays(vertices, 20000, seed=9)
    binary = traced(vertices, rows, bvh.nodes, origins, directions, dtype)
    wider = traced(vertices, rows, wide.nodes, origins, directions, dtype)
    truth = looped(vertices, rows, origins, directions, dtype)
    assert (truth[:, 1] >= 0).mean() > 0.3                        # the rays do hit
    # t, face index and row, bit for bit: the loop's, on both trees
    assert binary[0].tobytes() == truth.tobytes()
    assert wider[0].tobytes() == truth.tobytes()
    assert np.array_equal(binary[1], wider[1])
    # the render's tree: its bottom nodes made blocks (corners copied in float32, gathered in float64)
    blocked = wide_bvh.with_blocks(wide, vertices.astype(dtype), rows)
    assert len(block_codes(blocked)) > 0
    with_blocks = traced(vertices, rows, blocked.nodes, origins, directions, dtype)
    assert with_blocks[0].tobytes() == truth.tobytes()
    assert np.array_equal(binary[1], with_blocks[1])
    if mesh == "coincident":
        first = {}
        for k, f in enumerate(faces.tolist()):
            first.setdefault(tuple(f), k)
        hit = wider[0][:, 1] >= 0
        won = wider[0][hit, 1].astype(int)
        assert all(first[tuple(faces[k].tolist())] == k for k in won)


@pytest.mark.parametrize("dtype", PRECISIONS, ids=lambda d: d.__name__)
def test_no_ray_from_inside_a_closed_mesh_leaks_through_the_wide_tree(dtype):
    vertices, rows, wide, rays = rays_from_inside()
    for nodes in (wide.nodes, wide_bvh.with_blocks(wide, vertices.astype(dtype), rows).nodes):
        for origins, directions in rays:
            hits, _ = traced(vertices, rows, nodes, origins, directions, dtype)
            assert (hits[:, 1] >= 0).all(), "%d of %d rays leak" % ((hits[:, 1] < 0).sum(), len(origins))


def reached_columns(wide, roots=None):
    """(node, code) of each column that is not empty of the nodes reached from ``roots`` (the
    tree's own where None), each node's columns in order."""
    links, stack = wide.links, list(wide.roots if roots is None else roots)
    while stack:
        n = stack.pop()
        for j in range(wide_bvh.WIDTH):
            code = int(links[n, wide_bvh.CODE_ROW, j])
            if np.isfinite(wide.nodes[n, 0, j]):
                if code >= 0:
                    stack.append(code)
                yield n, code


def is_block_code(code):
    return code < 0 and (~code) >> wide_bvh.BLOCK_BIT != 0


def block_codes(wide):
    """The block codes of the tree's nodes (those reached from its roots)."""
    return [code for _, code in reached_columns(wide) if is_block_code(code)]


def block_span(flat, code):
    """(where, first face, count) of the block ``code`` in the flat table ``flat``."""
    at = ((~code) & ((1 << wide_bvh.BLOCK_BIT) - 1)) >> wide_bvh.LEAF_BITS
    return at, int(flat[at:at + 1].view(np.int32)[0]), ((~code) & 7) + 1


@pytest.mark.parametrize("dtype", PRECISIONS, ids=lambda d: d.__name__)
def test_the_blocks_hold_each_face_of_the_nodes_they_replace_once(dtype):
    """with_blocks: every face of the wide tree is in one leaf or one block, as before; a
    block's header names consecutive faces; in float32 its rows are their corners, copied,
    in float64 it is the header alone; the roots stay nodes; the table is the nodes then the
    blocks, no larger than the nodes it had and 40 bytes a face in a block in float32, and
    smaller in float64. In float32 a leaf column of LEAF_BLOCK_MIN or more faces is a block
    too, in float64 it stays a leaf."""
    vertices, faces = traversal_mesh("soup")
    _, wide, rows = tree_of(vertices, faces)
    corners = vertices.astype(dtype)
    blocked = wide_bvh.with_blocks(wide, corners, rows)
    assert blocked.nodes.dtype == np.float32
    in_blocks = sum(((~c) & 7) + 1 for c in block_codes(blocked))
    if dtype == np.float32:
        assert blocked.nodes.nbytes <= wide.nodes.nbytes + 40 * in_blocks
    else:
        assert blocked.nodes.nbytes < 0.8 * wide.nodes.nbytes
    flat = blocked.nodes.reshape(-1)
    seen, ends, leaves = [], [], []
    for code in block_codes(blocked):
        at, first, count = block_span(flat, code)
        if dtype == np.float32:
            stored = flat[at + 1:at + 1 + 9 * count].reshape(9, count)
            assert stored.T.tobytes() == corners[rows[first:first + count, :3]].reshape(count, 9).tobytes()
        ends.append((at, at + wide_bvh.BLOCK_HEADER + (9 * count if dtype == np.float32 else 0)))
        seen += range(first, first + count)
    ends.sort()
    assert all(b[0] >= a[1] for a, b in zip(ends, ends[1:]))     # the blocks do not overlap
    for n, code in reached_columns(blocked):
        assert (n + 1) * wide_bvh.ROWS * wide_bvh.WIDTH <= ends[0][0]     # the nodes before the blocks
        if code < 0 and not is_block_code(code):
            leaf = ~code
            first, count = leaf >> wide_bvh.LEAF_BITS, (leaf & 7) + 1
            seen += range(first, first + count)
            leaves.append(count)
    assert sorted(seen) == list(range(len(rows)))
    assert len(block_codes(blocked)) > 0
    assert blocked.roots == (0,)
    # the leaves left are the small ones in float32; in float64 the larger stay leaves too
    if dtype == np.float32:
        assert max(leaves) < wide_bvh.LEAF_BLOCK_MIN
    else:
        assert max(leaves) >= wide_bvh.LEAF_BLOCK_MIN


def _rows_reached(wide, root):
    """(rows of the leaves, rows of the blocks) reached from ``root`` of a blocked tree."""
    flat, leaves, blocks = wide.nodes.reshape(-1), [], []
    for _, code in reached_columns(wide, [root]):
        if is_block_code(code):
            _, first, count = block_span(flat, code)
            blocks += range(first, first + count)
        elif code < 0:
            first, count = (~code) >> wide_bvh.LEAF_BITS, ((~code) & 7) + 1
            leaves += range(first, first + count)
    return leaves, blocks


@pytest.mark.parametrize("dtype", PRECISIONS, ids=lambda d: d.__name__)
def test_no_block_holds_a_sphere_or_an_instance_row_and_every_root_stays_a_node(dtype):
    """A tree over faces and spheres (rows [-1, ...], as rtfgu.layout writes them), spheres
    among the faces, and a second tree after it in the same table (an instanced mesh's, of
    six faces: its root's columns are its six faces, which a node not a root would make a
    block): the blocks hold faces only, every sphere row stays in a leaf, every row is
    reached once from the root of its own tree, and both roots are nodes of the new table."""
    vertices, faces = traversal_mesh("icosphere")
    rng = np.random.default_rng(7)
    centres = vertices[rng.choice(len(vertices), 40, replace=False)] * 1.01
    rows = flat_bvh.triangle_rows(vertices, faces, centres - 0.02, centres + 0.02)
    first = flat_bvh.build_rows(rows)
    small = faces[:6]
    second = flat_bvh.build(*flat_bvh.triangle_bounds(vertices, small))
    n1, f1 = len(first.nodes), len(first.order)
    moved = flat_bvh.offset(second, n1, f1)
    both = flat_bvh.FlatBVH(np.concatenate([first.nodes, moved.nodes]), np.concatenate([first.order, moved.order]),
                            0.0, np.concatenate([first.boxes, moved.boxes]))
    table = np.empty((len(both.order), 4), dtype=np.int32)
    for at, p in enumerate(first.order):
        table[at] = (*faces[p], p) if p < len(faces) else (-1, p - len(faces), 0, p)
    table[f1:, :3] = small[second.order]
    table[f1:, 3] = len(rows) + second.order
    wide = both.wide((0, n1))
    blocked = wide_bvh.with_blocks(wide, vertices.astype(dtype), table)
    spheres = set(np.nonzero(table[:, 0] < 0)[0].tolist())
    assert len(spheres) == 40
    flat_end = min(block_span(blocked.nodes.reshape(-1), c)[0] for c in block_codes(blocked))
    assert len(blocked.roots) == 2
    for root, rows_of_tree in zip(blocked.roots, (range(f1), range(f1, len(table)))):
        assert (root + 1) * wide_bvh.ROWS * wide_bvh.WIDTH <= flat_end
        leaves, blocks = _rows_reached(blocked, root)
        assert not spheres & set(blocks)
        assert sorted(leaves + blocks) == list(rows_of_tree)
        if root == blocked.roots[0]:
            assert blocks and spheres <= set(leaves)
        else:
            assert len(leaves) == 6 and not blocks


def test_the_float64_blocks_refuse_faces_they_cannot_read_as_rows():
    vertices, faces = traversal_mesh("soup")
    _, wide, rows = tree_of(vertices, faces)
    with pytest.raises(ValueError, match="int32 rows of 4"):
        wide_bvh.with_blocks(wide, vertices, rows[:, :3].copy())
    with pytest.raises(ValueError, match="int32 rows of 4"):
        wide_bvh.with_blocks(wide, vertices, rows.astype(np.int64))


def test_a_block_test_reads_only_its_own_lanes():
    """A block of fewer than eight faces is followed by other values (no padding): its masked
    rows must not take them as faces. The block's faces are hit at t = 1 and what follows it
    holds faces at t = 0.5 that the ray would hit, in every lane."""
    from rtfgu.kernels.wide_bvh import block_test

    near = [-1.0, -1.0, 0.5, 3.0, -1.0, 0.5, -1.0, 3.0, 0.5]     # v0, v1, v2: hit at t = 0.5
    far = [-1.0, -1.0, 1.0, 3.0, -1.0, 1.0, -1.0, 3.0, 1.0]      # hit at t = 1

    @njit
    def test(nodes, at, count, origin, direction):
        lanes = lanes_of(np.float32)
        mask = block_test(nodes, at, count, ray_frame(origin, direction), np.float32(0), np.float32(np.inf), lanes)
        out = np.empty(8, dtype=np.float32)
        for j in range(8):
            out[j] = lanes[j]
        return mask, out

    origin = (np.float32(0.25), np.float32(0.25), np.float32(0))
    direction = (np.float32(0), np.float32(0), np.float32(1))
    for count in range(1, 9):
        for at in (0, 5):
            values = np.zeros(wide_bvh.ROWS * wide_bvh.WIDTH * 4, dtype=np.float32)
            values[at:at + 9 * count] = np.repeat(np.array(far, dtype=np.float32), count)
            values[at + 9 * count:at + 9 * count + 9 * 8] = np.repeat(np.array(near, dtype=np.float32), 8)
            mask, out = test(values.reshape(-1, wide_bvh.ROWS, wide_bvh.WIDTH), at, count, origin, direction)
            assert mask & 0xFF == (1 << count) - 1 and mask >> 8 == 0, (count, at, bin(mask))
            assert (out[:count] == 1).all(), (count, at, out)


def test_a_gathered_block_test_reads_only_its_own_faces():
    """A float64 block's faces are rows of the faces table followed by other rows: the
    block's rows must not take them as faces. Its faces are hit at t = 1 and the rows after
    them are faces at t = 0.5 that the ray would hit, in every lane; each lane's t is the
    scalar test's."""
    from rtfgu.kernels.wide_bvh import block_test_gathered

    @njit
    def test(vertices, faces, first, count, origin, direction):
        lanes = lanes_of(np.float64)
        mask = block_test_gathered(vertices, faces, first, count, ray_frame(origin, direction), 0.0, np.inf, lanes)
        out = np.empty(8, dtype=np.float64)
        for j in range(8):
            out[j] = lanes[j]
        return mask, out

    # vertices 0-2: a triangle at z = 1, 3-5 one at z = 0.5, both under the ray
    corners = np.array([[-1.0, -1.0, 1.0], [3.0, -1.0, 1.0], [-1.0, 3.0, 1.0],
                        [-1.0, -1.0, 0.5], [3.0, -1.0, 0.5], [-1.0, 3.0, 0.5]])
    origin, direction = (0.25, 0.25, 0.0), (0.0, 0.0, 1.0)
    for count in range(1, 9):
        for first in (0, 3):
            rows = np.array([[3, 4, 5, 0]] * 24, dtype=np.int32)
            rows[first:first + count] = [0, 1, 2, 0]
            mask, out = test(corners, rows, first, count, origin, direction)
            assert mask == (1 << count) - 1, (count, first, bin(mask))
            assert (out[:count] == 1).all(), (count, first, out)


@pytest.mark.parametrize("mesh", ["soup", "icosphere"])
def test_a_float64_blocks_face_boxes_are_the_boxes_its_node_held(mesh):
    """A packet boxes a float64 block's faces from their gathered corners
    (block_boxes_gathered): each box must be the one the node the block replaced held for
    that face (the float64 box rounded outward to float32), so the packet's rays enter the
    same boxes as before."""
    from rtfgu.kernels.packet import _boxes_of
    from rtfgu.kernels.wide_bvh import block_boxes_gathered

    @njit
    def box_rows(vertices, faces, first, count):
        boxes = _boxes_of(np.float64)
        block_boxes_gathered(vertices, faces, first, count, boxes)
        out = np.empty((6, wide_bvh.WIDTH))
        for r in range(6):
            for j in range(wide_bvh.WIDTH):
                out[r, j] = boxes[r * wide_bvh.WIDTH + j]
        return out

    vertices, faces = traversal_mesh(mesh)
    _, wide, rows = tree_of(vertices, faces)
    held = {}
    for n in range(len(wide.nodes)):
        for j in range(wide_bvh.WIDTH):
            code = int(wide.links[n, wide_bvh.CODE_ROW, j])
            if code < 0 and (~code) & 7 == 0:
                held[(~code) >> wide_bvh.LEAF_BITS] = wide.nodes[n, :6, j].astype(np.float64)
    blocked = wide_bvh.with_blocks(wide, vertices, rows)
    flat = blocked.nodes.reshape(-1)
    checked = 0
    for code in block_codes(blocked):
        at, first, count = block_span(flat, code)
        out = box_rows(vertices, rows, first, count)
        for lane in range(count):
            assert out[:, lane].tobytes() == held[first + lane].tobytes(), (first + lane, out[:, lane], held[first + lane])
            checked += 1
    assert checked > 20


def test_a_scene_traverses_blocks_in_both_precisions_with_corners_in_float32_only():
    from rtfgu.layout import compile_scene
    from rtfgu.scenes import SCENES

    scene = SCENES["suffern_29_uv_mesh"]()
    trees = {p: render_kernels.numba_tree(compile_scene(scene, p).mesh) for p in ("float32", "float64")}
    for tree in trees.values():
        assert len(block_codes(tree)) > 0
    blocks = {p: [block_span(tree.nodes.reshape(-1), c)[1:] for c in block_codes(tree)] for p, tree in trees.items()}
    # float64's blocks are float32's too (the nodes of single triangles); float32 has the leaf
    # columns of three or more as well, and holds 36 bytes of corners a face
    assert set(blocks["float64"]) < set(blocks["float32"])
    assert min(count for _, count in set(blocks["float32"]) - set(blocks["float64"])) >= wide_bvh.LEAF_BLOCK_MIN
    faces = sum(count for _, count in blocks["float32"])
    assert trees["float32"].nodes.nbytes - trees["float64"].nodes.nbytes >= 36 * faces - wide_bvh.ROWS * wide_bvh.WIDTH * 4


def test_the_traversals_called_once_a_ray_count_no_references():
    """mesh_closest, mesh_any, the instances' copy and the packets' traversal are called, not
    inlined, once a ray: compiled with numba's reference counting, each call would increment
    and decrement every array argument atomically (docs/bvh.md, "Where a single ray's time
    goes"). They allocate nothing, so they are compiled without it."""
    from rtfgu.kernels.mesh import object_mesh_closest
    from rtfgu.kernels.packet import mesh_closest_packet
    for traversal in (mesh_closest, mesh_any, object_mesh_closest, mesh_closest_packet):
        assert traversal.targetoptions.get("_nrt") is False, traversal.py_func.__name__


# --- through rtfgu.render -----------------------------------------------------------------

def test_the_render_traverses_the_wide_tree_where_the_cpu_has_vector_units_and_both_give_one_image(monkeypatch):
    from rtfgu.layout import compile_scene
    from rtfgu.renderer import render
    from rtfgu.scenes import SCENES

    scene = SCENES["suffern_29_uv_mesh"]()
    flat = compile_scene(scene, "float32")
    arrays = render_kernels.mesh_arrays(flat)
    assert arrays[3].ndim == (3 if wide_bvh_cpu() else 2)
    images = {}
    for wide in (False, True):
        monkeypatch.setattr(render_kernels, "WIDE", wide)
        images[wide] = render(SCENES["suffern_29_uv_mesh"](), 40, 30, backend="numba", precision="float32")
    assert np.isfinite(images[True]).all() and images[True].std() > 0
    assert images[False].tobytes() == images[True].tobytes()


def wide_bvh_cpu() -> bool:
    from rtfgu.kernels.wide_bvh import vector_cpu
    return vector_cpu()
