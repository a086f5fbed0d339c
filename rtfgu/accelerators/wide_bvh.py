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
    corners = vertices.dtype == np.float32
    nodes = wide.nodes
    pure, leaf, firsts, counts = _choose_blocks(nodes, nodes.view(np.int32), np.asarray(wide.roots, dtype=np.int64),
                                                faces, corners)
    if len(counts) == 0:
        return wide
    if not corners and (faces.shape[1] != FACE_COLUMNS or not faces.flags.c_contiguous or faces.dtype != np.int32):
        raise ValueError("with_blocks: the faces of a float64 tree's blocks are read as C-ordered int32 rows of "
                         "%d, not %s %s" % (FACE_COLUMNS, faces.dtype, faces.shape))
    kept = len(nodes) - int(pure.sum())
    sizes = BLOCK_HEADER + CORNER_ROWS * counts * corners
    where = kept * ROWS * WIDTH + np.cumsum(sizes) - sizes
    total = int(where[-1] + sizes[-1])
    if total >= MAX_FIRST:
        return wide                               # beyond what a code holds: no blocks
    out = np.empty(-(-total // (ROWS * WIDTH)) * ROWS * WIDTH, dtype=np.float32)
    number = _fill_blocks(nodes, nodes.view(np.int32), pure, leaf, firsts, counts, where, out, out.view(np.int32))
    if corners:
        _copy_corners(vertices, faces, firsts, counts, where, out)
    out[total:] = 0
    return WideBVH(out.reshape(-1, ROWS, WIDTH), tuple(int(number[r]) for r in wide.roots), wide.build_seconds)


@njit(cache=True)
def _choose_blocks(nodes, links, roots, faces, corners):
    """with_blocks' blocks: (pure, leaf, firsts, counts). pure (N,): the nodes made blocks, a
    node not a root whose every column that is not empty (lo.x = +inf) is one triangle, those
    triangles consecutive rows of ``faces`` with no sphere or instance row (first column < 0)
    among them; with ``corners``, leaf (N, WIDTH): the leaf columns of LEAF_BLOCK_MIN or more
    triangles in the nodes kept, likewise with no other row. Each block's first face and count,
    the nodes' blocks in node order, then the leaves' in node and column order."""
    n = nodes.shape[0]
    others = np.empty(len(faces) + 1, dtype=np.int64)     # the sphere and instance rows before each
    others[0] = 0
    for f in range(len(faces)):
        others[f + 1] = others[f] + (faces[f, 0] < 0)
    is_root = np.zeros(n, dtype=np.bool_)
    for r in roots:
        is_root[r] = True
    pure = np.zeros(n, dtype=np.bool_)
    first_of = np.zeros(n, dtype=np.int64)
    count_of = np.zeros(n, dtype=np.int64)
    leaf = np.zeros((n, WIDTH), dtype=np.bool_)
    n_blocks = 0
    for w in range(n):
        count, lo, hi, single = 0, np.int64(0), np.int64(0), True
        for j in range(WIDTH):
            if nodes[w, 0, j] == np.inf:
                continue
            code = links[w, CODE_ROW, j]
            if code < 0 and (~code & (2 ** LEAF_BITS - 1)) == 0:
                f = np.int64(~code >> LEAF_BITS)
                lo, hi = (f, f) if count == 0 else (min(lo, f), max(hi, f))
                count += 1
            else:
                single = False
        if single and count > 0 and not is_root[w] and hi - lo == count - 1 and others[hi + 1] == others[lo]:
            pure[w] = True
            first_of[w], count_of[w] = lo, count
            n_blocks += 1
        elif corners:
            for j in range(WIDTH):
                code = links[w, CODE_ROW, j]
                if code < 0 and nodes[w, 0, j] != np.inf:
                    f = np.int64(~code >> LEAF_BITS)
                    c = (~code & (2 ** LEAF_BITS - 1)) + 1
                    if c >= LEAF_BLOCK_MIN and others[f + c] == others[f]:
                        leaf[w, j] = True
                        n_blocks += 1
    firsts = np.empty(n_blocks, dtype=np.int64)
    counts = np.empty(n_blocks, dtype=np.int64)
    k = 0
    for w in range(n):
        if pure[w]:
            firsts[k], counts[k] = first_of[w], count_of[w]
            k += 1
    for w in range(n):
        for j in range(WIDTH):
            if leaf[w, j]:
                code = links[w, CODE_ROW, j]
                firsts[k], counts[k] = ~code >> LEAF_BITS, (~code & (2 ** LEAF_BITS - 1)) + 1
                k += 1
    return pure, leaf, firsts, counts


@njit(cache=True)
def _fill_blocks(nodes, links, pure, leaf, firsts, counts, where, out, out_links):
    """with_blocks' table: the nodes kept, numbered again in their order, into ``out`` (flat
    float32, ``out_links`` its int32 view), each column's code made the new number of its
    node or the code of its block, and each block's header (its first face). Returns each
    node's new number."""
    n = nodes.shape[0]
    number = np.empty(n, dtype=np.int64)
    block = np.empty(n, dtype=np.int64)       # a pure node's block
    m, k = 0, 0
    for w in range(n):
        number[w] = m
        if pure[w]:
            block[w] = k
            k += 1
        else:
            m += 1
    stride = ROWS * WIDTH
    for b in range(len(counts)):
        out_links[where[b]] = firsts[b]
    for w in range(n):
        if pure[w]:
            continue
        at = number[w] * stride
        for r in range(CODE_ROW):
            for j in range(WIDTH):
                out[at + r * WIDTH + j] = nodes[w, r, j]
        for j in range(WIDTH):
            code = np.int64(links[w, CODE_ROW, j])
            b = -1
            if code >= 0:
                if pure[code]:
                    b = block[code]
                else:
                    code = number[code]
            elif leaf[w, j]:
                b = k
                k += 1
            if b >= 0:
                code = ~((1 << BLOCK_BIT) | where[b] << LEAF_BITS | (counts[b] - 1))
            out_links[at + CODE_ROW * WIDTH + j] = code
    return number


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
