"""The wide BVH of the numba path: flat_bvh's binary tree collapsed into nodes of WIDTH (8)
children whose boxes are stored per coordinate, so that one vector instruction tests a
coordinate's plane of all eight (Embree's BVH8, Wald et al. 2014, "Embree: A Kernel
Framework for Efficient CPU Ray Tracing", section 4.1; the collapse of Wald, Benthin and
Boulos 2008, "Getting Rid of Packets").

A node is a (ROWS, WIDTH) = (7, 8) float32 block, 224 bytes, one row per field and one
column per child:

    rows 0-2  lo.x, lo.y, lo.z  of each child's box
    rows 3-5  hi.x, hi.y, hi.z
    row 6     int32 bits: the child's code, what the traversal pushes: an inner child's node
              (>= 0), or a leaf child's ~(first << LEAF_BITS | count - 1) (< 0), its first
              primitive and its count (leaf_code), or in a render's tree a block's code
              (with_blocks: a node of single triangles, or a float32 leaf of three or
              more, made one vector test)

A column no child fills has the empty box (lo = +inf, hi = -inf), which no ray enters. The
boxes are the binary tree's own or its primitives' (FlatBVH.boxes), rounded outward to
float32, so a ray enters a wide child wherever it enters that binary node or hits that
primitive; the wide tree tests fewer boxes on the way down, never other ones, and finds the
same face and t with the one tie rule (docs/bvh.md).

The collapse: a node starts with the two children of a binary node and opens the inner child
of the largest surface area into its two children until it has WIDTH children or only
leaves. Columns still free then take the primitives of its leaves, one a column with its own
box, the leaf of the largest area first, where all of a leaf's primitives fit: the box test
tests the eight columns at once, so a free column costs as much as a full one, and a ray then
tests only the primitives whose boxes it enters (the Cornell box's two triangles of a wall,
each boxing half of it). The primitives stay in the binary tree's leaf order.
"""
from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from .flat_bvh import FlatBVH, njit

WIDTH = 8
# A leaf's code is ~(first << LEAF_BITS | count - 1): LEAF_SIZE <= 2^LEAF_BITS.
LEAF_BITS = 3
# A block's code is ~(1 << BLOCK_BIT | where << LEAF_BITS | count - 1) (with_blocks), so a
# leaf's first and a block's place stay below 2^(BLOCK_BIT - LEAF_BITS).
BLOCK_BIT = 30
MAX_FIRST = 2 ** (BLOCK_BIT - LEAF_BITS)
# A block: a header, its first face (int32), then its corners.
BLOCK_HEADER = 1
# A face's row in the faces table: its three vertices' rows and its place in Scene.shapes
# (a float64 block's test loads its faces' rows at once).
FACE_COLUMNS = 4
CORNER_ROWS = 9
# A node's rows: six of box planes and the children's codes (CODE_ROW).
ROWS = 7
CODE_ROW = 6
# A float32 tree's leaf columns of this many triangles or more are blocks too (with_blocks):
# with those of two, the 1.31 M icosphere's table would pass 64 bytes a triangle
# (docs/bvh.md, "Leaf columns made blocks").
LEAF_BLOCK_MIN = 3


def leaf_code(first: int, count: int) -> int:
    """The code of a leaf of ``count`` primitives from ``first`` (module docstring)."""
    return ~(first << LEAF_BITS | (count - 1))


@dataclass
class WideBVH:
    nodes: np.ndarray          # (N, ROWS, WIDTH) float32 (module docstring)
    roots: tuple               # the wide node of each root of the binary table, in order
    build_seconds: float

    @property
    def links(self) -> np.ndarray:
        return self.nodes.view(np.int32)

    @property
    def nbytes(self) -> int:
        return self.nodes.nbytes


@njit(cache=True)
def _place(nodes, boxes, c, kids, kbox, k):
    """Make ``c`` child k: a binary node c >= 0, or the primitive ~c of ``boxes``
    (FlatBVH.boxes); kbox[k] = its box [lo, hi] and kbox[k, 6] its surface area / 2."""
    kids[k] = c
    for a in range(3):
        kbox[k, a] = nodes[c, a] if c >= 0 else boxes[~c, a]
        kbox[k, 3 + a] = nodes[c, 4 + a] if c >= 0 else boxes[~c, 3 + a]
    dx = np.float64(kbox[k, 3]) - kbox[k, 0]
    dy = np.float64(kbox[k, 4]) - kbox[k, 1]
    dz = np.float64(kbox[k, 5]) - kbox[k, 2]
    kbox[k, 6] = dx * dy + dy * dz + dz * dx


@njit(cache=True)
def _collapse(nodes, links, boxes, roots, out, out_links, wide_roots, width, leaf_bits):
    """Fill out (M, ROWS, width) from the binary table; returns M. A work list of (binary node,
    wide node) pairs; each wide node's children are chosen as the module docstring says: a
    child is a binary node (>= 0) or, once a leaf is opened, one primitive p (~p)."""
    work = np.empty((len(nodes) + len(roots), 2), dtype=np.int64)
    kids = np.empty(width, dtype=np.int64)
    kbox = np.empty((width, 7))
    done = 0
    for r in range(len(roots)):
        wide_roots[r] = done
        work[0, 0], work[0, 1] = roots[r], done
        top = 1
        done += 1
        while top > 0:
            top -= 1
            b, w = work[top, 0], work[top, 1]
            if links[b, 7] > 0:        # a tree that is a single leaf
                _place(nodes, boxes, b, kids, kbox, 0)
                count = 1
            else:
                _place(nodes, boxes, links[b, 3], kids, kbox, 0)
                _place(nodes, boxes, links[b, 3] + 1, kids, kbox, 1)
                count = 2
                while count < width:
                    widest = -1
                    for k in range(count):
                        if links[kids[k], 7] == 0 and (widest < 0 or kbox[k, 6] > kbox[widest, 6]):
                            widest = k
                    if widest < 0:
                        break
                    left = links[kids[widest], 3]
                    _place(nodes, boxes, left, kids, kbox, widest)
                    _place(nodes, boxes, left + 1, kids, kbox, count)
                    count += 1
            # Columns left over: the widest leaf whose primitives all fit opened into one
            # child per primitive, each with its own box, until none fits.
            while count < width:
                widest = -1
                for k in range(count):
                    c = kids[k]
                    if c >= 0 and links[c, 7] > 1 and count + links[c, 7] - 1 <= width \
                            and (widest < 0 or kbox[k, 6] > kbox[widest, 6]):
                        widest = k
                if widest < 0:
                    break
                first, n = links[kids[widest], 3], links[kids[widest], 7]
                _place(nodes, boxes, ~first, kids, kbox, widest)
                for i in range(1, n):
                    _place(nodes, boxes, ~(first + i), kids, kbox, count)
                    count += 1
            for j in range(width):
                if j >= count:
                    for a in range(3):
                        out[w, a, j] = np.inf
                        out[w, 3 + a, j] = -np.inf
                    out_links[w, 6, j] = 0
                    continue
                c = kids[j]
                for a in range(6):
                    out[w, a, j] = kbox[j, a]
                if c < 0:
                    out_links[w, 6, j] = ~(~c << leaf_bits)
                elif links[c, 7] > 0:
                    out_links[w, 6, j] = ~(links[c, 3] << leaf_bits | (links[c, 7] - 1))
                else:
                    out_links[w, 6, j] = done
                    work[top, 0], work[top, 1] = c, done
                    top += 1
                    done += 1
    return done


def with_blocks(wide: WideBVH, vertices: np.ndarray, faces: np.ndarray) -> WideBVH:
    """The tree ``wide`` with its bottom nodes made blocks: a node whose every column is one
    triangle, those triangles being the rows first .. first + count - 1 of ``faces``, becomes
    a **block** of ``count`` faces that one vector test tests at once
    (rtfgu.kernels.wide_bvh.block_test, block_test_gathered) instead of their eight boxes and
    then each face entered.

    The blocks follow the nodes in the same float32 table, without padding. At float
    ``where`` (counted from the table's start), each block's first face (int32 bits); then,
    for float32 ``vertices``, nine rows of ``count`` values, v0.x of its faces, v0.y, v0.z,
    v1.x, ... v2.z, their corners' copies stored per coordinate as Embree's ``Triangle4``
    leaves are (Wald et al. 2014, section 4.2): 4 + 36 * count bytes, where the node was 224.
    For float64 ``vertices`` a block is its first face alone (4 bytes): its test gathers the
    corners through ``faces`` ((F, 4) rows), since corners copied in float64 (72 bytes a face)
    would take the table past 64 bytes a triangle. Its parent's column holds the code
    ~(1 << BLOCK_BIT | where << LEAF_BITS | count - 1): the test needs nothing from the block
    before its corners. A root stays a node; a node whose columns hold a sphere or an
    instance, or whose faces are not consecutive rows, stays a node. The nodes left are
    numbered again in their order.

    In float32, a leaf column of a node kept that holds LEAF_BLOCK_MIN or more triangles (a
    leaf's rows are consecutive) becomes a block as well, after the nodes' blocks: its column
    keeps the leaf's box and takes the block's code. (In float64, whose blocks gather their
    corners, the packets measured slower with them.) A table past MAX_FIRST floats gets no
    blocks."""
    nodes = wide.nodes
    links = nodes.view(np.int32)
    n = len(nodes)
    codes = links[:, CODE_ROW, :]
    empty = np.isposinf(nodes[:, 0, :])
    one = (codes < 0) & ((~codes & (2 ** LEAF_BITS - 1)) == 0) & ~empty
    first_of = np.where(one, ~codes >> LEAF_BITS, 0).astype(np.int64)
    count = one.sum(axis=1)
    pure = np.all(one | empty, axis=1) & (count > 0)
    pure[list(wide.roots)] = False
    big = np.iinfo(np.int64).max
    lo = np.where(one, first_of, big).min(axis=1)
    hi = np.where(one, first_of, -1).max(axis=1)
    pure &= hi - lo == count - 1                 # consecutive rows (each once: a leaf's rows are its own)
    # no sphere or instance row among first .. last: the count of such rows up to each
    others = np.concatenate([[0], np.cumsum(faces[:, 0] < 0)])
    pure[pure] = others[hi[pure] + 1] == others[lo[pure]]
    kept = ~pure
    corners = vertices.dtype == np.float32
    # In float32, the leaf columns of LEAF_BLOCK_MIN or more triangles in the nodes kept.
    leaf = (codes < 0) & ~empty & kept[:, None] & corners
    leaf_count = np.where(leaf, (~codes & (2 ** LEAF_BITS - 1)) + 1, 0)
    leaf_first = np.where(leaf, ~codes >> LEAF_BITS, 0).astype(np.int64)
    leaf &= leaf_count >= LEAF_BLOCK_MIN
    leaf[leaf] = others[leaf_first[leaf] + leaf_count[leaf]] == others[leaf_first[leaf]]
    if not pure.any() and not leaf.any():
        return wide
    number = np.cumsum(kept) - 1                 # a kept node's new number
    firsts = np.concatenate([lo[pure], leaf_first[leaf]])
    counts = np.concatenate([count[pure], leaf_count[leaf]])
    if not corners and (faces.shape[1] != FACE_COLUMNS or not faces.flags.c_contiguous or faces.dtype != np.int32):
        raise ValueError("with_blocks: the faces of a float64 tree's blocks are read as C-ordered int32 rows of "
                         "%d, not %s %s" % (FACE_COLUMNS, faces.dtype, faces.shape))
    sizes = BLOCK_HEADER + CORNER_ROWS * counts * corners
    where = len(number[kept]) * ROWS * WIDTH + np.cumsum(sizes) - sizes
    total = int(where[-1] + sizes[-1])
    if total >= MAX_FIRST:
        return wide                               # beyond what a code holds: no blocks
    out = np.empty(-(-total // (ROWS * WIDTH)) * ROWS * WIDTH, dtype=np.float32)
    m = int(kept.sum())
    table = out[:m * ROWS * WIDTH].reshape(m, ROWS, WIDTH)
    table[:] = nodes[kept]
    new_codes = table.view(np.int32)[:, CODE_ROW, :]
    inner = new_codes >= 0
    codes_of = ~((1 << BLOCK_BIT) | where << LEAF_BITS | (counts - 1))
    n_pure = int(pure.sum())                     # the nodes' blocks come first, then the leaves'
    block_code = np.full(n, 0, dtype=np.int64)
    block_code[pure] = codes_of[:n_pure]
    to_block = inner & pure[np.where(inner, new_codes, 0)]
    new_codes[to_block] = block_code[new_codes[to_block]]
    renumber = inner & ~to_block
    new_codes[renumber] = number[new_codes[renumber]]
    new_codes[leaf[kept]] = codes_of[n_pure:]
    flat = out.view(np.int32)
    flat[where] = firsts
    if corners:
        _copy_corners(vertices, faces, firsts, counts, where, out)
    out[int(total):] = 0
    blocked = out.reshape(-1, ROWS, WIDTH)
    return WideBVH(blocked, tuple(int(number[r]) for r in wide.roots), wide.build_seconds)


@njit(cache=True)
def _copy_corners(vertices, faces, firsts, counts, where, out):
    """Each block's corners into ``out`` (with_blocks): block b's faces firsts[b] ..
    firsts[b] + counts[b] - 1, corner row r (v0.x, v0.y, v0.z, v1.x, ... v2.z: r = 3 v + a)
    of its lane j at where[b] + BLOCK_HEADER + r * counts[b] + j."""
    for b in range(len(counts)):
        count = counts[b]
        base = where[b] + BLOCK_HEADER
        for j in range(count):
            f = firsts[b] + j
            for v in range(3):
                corner = faces[f, v]
                for a in range(3):
                    out[base + (3 * v + a) * count + j] = vertices[corner, a]


def collapse(bvh: FlatBVH, roots=(0,)) -> WideBVH:
    """The wide tree of ``bvh`` (each of ``roots`` the first node of a tree in its table)."""
    start = time.perf_counter()
    links = bvh.links
    leaves = links[:, 7] > 0
    if leaves.any() and (links[leaves, 7].max() > 2 ** LEAF_BITS or links[leaves, 3].max() >= MAX_FIRST):
        raise ValueError("wide BVH: a leaf holds more than %d primitives or starts past %d"
                         % (2 ** LEAF_BITS, MAX_FIRST))
    # Room for a wide node per binary one (only the pages written are ever touched), cut
    # down to the nodes made in place: realloc, no copy of the table.
    out = np.empty((len(bvh.nodes) + len(roots), ROWS, WIDTH), dtype=np.float32)
    out_links = out.view(np.int32)
    wide_roots = np.zeros(len(roots), dtype=np.int64)
    n = _collapse(bvh.nodes, links, bvh.boxes, np.asarray(roots, dtype=np.int64), out, out_links,
                  wide_roots, WIDTH, LEAF_BITS)
    del out_links
    out.resize((n, ROWS, WIDTH), refcheck=False)    # no view of ``out`` is left
    return WideBVH(out, tuple(int(r) for r in wide_roots), time.perf_counter() - start)
