"""An experiment, not the render's traversal: the wide BVH's bottom nodes as blocks of up to
eight triangles stored per coordinate and tested by one 8-wide watertight test (Embree's
``Triangle4``/``Triangle8`` leaves, Wald et al. 2014 section 4.2; the test of Woop, Benthin
and Wald 2013), measured against rtfgu.kernels.mesh.mesh_closest on the same rays. The
section "Leaf blocks: triangles tested eight at a time" of docs/bvh.md.

    python benchmarks/leaf_blocks.py [--meshes bunny icosphere] [--all-leaves] [--runs 7]

The blocks: a wide node whose every column is one face (the collapse's opened leaves,
rtfgu.accelerators.wide_bvh), those faces being the rows first .. first + count - 1 of
``faces``, becomes a block of ``count`` (1-8) faces. Its corners are stored per coordinate
in ``corners`` (float32), without padding: nine rows of ``count`` values each (v0.x of its
faces, then v0.y, v0.z, v1.x, ... v2.z), 36 bytes a face; ``table`` holds each block's
offset in ``corners``, first face and count (12 bytes). Its parent's code for it becomes
``N + block`` (N: the number of wide nodes), so the traversal tests the block's faces at
once instead of their boxes and then each face entered. With ``--all-leaves``, every other
leaf (a column of one to eight faces in a node that is not a block) becomes a block of its
faces too, which stores every face's corners: a measure of blocks everywhere.

``tri8`` is rtfgu.kernels.mesh.intersect_face lane by lane: the same operations in the same
order, on the ray frame's axes kx, ky, kz picked as rows, so a lane's t is the scalar test's
bit for bit. A lane whose edge function rounds to zero (the scalar test's recompute in
double) is left to the scalar test. Of the lanes hit in [tmin, next float above the best
t), the traversal keeps the nearest by mesh_closest's tie rule, in any order: the rule is
the lexicographic minimum of (t, scene index), so every ray gets mesh_closest's face and t,
which the script checks bit for bit before it times anything.

Timing: float32, both paths and Embree's fast mode (robust=False, benchmarks/meshes.py's
Embree) in one process, each round times every path once, each time the second of two
calls in a row, median of ``--runs``; on one thread and on numba's thread count. A
measurement to read, not a test.
"""
from __future__ import annotations

import argparse
import math
import statistics
import sys
import time
from pathlib import Path

import numpy as np
import numba
from llvmlite import ir
from numba import njit, prange, types
from numba.core import cgutils
from numba.extending import intrinsic

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
sys.path.insert(0, str(HERE))

from rtfgu.accelerators.wide_bvh import CODE_ROW, LEAF_BITS, WIDTH  # noqa: E402
from rtfgu.kernels import wide_bvh  # noqa: E402
from rtfgu.kernels.float3 import lit  # noqa: E402
from rtfgu.kernels.mesh import _wide_start, intersect_face  # noqa: E402

import meshes  # noqa: E402

CORNER_ROWS = 9
# A block's row in ``table``: where its corners start in ``corners``, its first face's row
# in ``faces``, its number of faces.
OFFSET, FIRST, COUNT = 0, 1, 2


@intrinsic
def tri8(typingctx, corners, offset, count, frame, tmin, limit, out):
    """The watertight test of a block's ``count`` (1-8) faces, whose corners lie in
    ``corners`` (float32, float32 rays) from ``offset`` on, row by row (module docstring):
    each lane's t at ``out`` (WIDTH floats); returns a bit mask, bits 0-7 the lanes hit in
    [tmin, limit), bits 8-15 the lanes whose U, V or W rounds to zero (for the scalar test,
    which recomputes them in double). A row is read by a masked load of its ``count`` lanes,
    so nothing past the block is read."""
    if not (isinstance(corners, types.Array) and corners.dtype == types.float32 and tmin == types.float32):
        return None

    def codegen(context, builder, signature, args):
        corners_v, offset_v, count_v, frame_v, tmin_v, limit_v, out_v = args
        ft = ir.FloatType()
        vt = ir.VectorType(ft, WIDTH)
        i64, i32 = ir.IntType(64), ir.IntType(32)
        lanes = ir.VectorType(ir.IntType(1), WIDTH)
        array = context.make_array(signature.args[0])(context, builder, corners_v)
        offset64 = context.cast(builder, offset_v, signature.args[1], types.int64)
        count64 = context.cast(builder, count_v, signature.args[2], types.int64)
        base = builder.gep(array.data, [offset64])
        shear, origin = builder.extract_value(frame_v, 0), builder.extract_value(frame_v, 1)
        kx, ky, kz = (builder.extract_value(shear, a) for a in range(3))

        def splat(x, typ=vt):
            v = builder.insert_element(ir.Constant(typ, ir.Undefined), x, ir.Constant(i32, 0))
            return builder.shuffle_vector(v, ir.Constant(typ, ir.Undefined), ir.Constant(ir.VectorType(i32, WIDTH), [0] * WIDTH))

        valid = builder.icmp_signed("<", ir.Constant(ir.VectorType(i64, WIDTH), list(range(WIDTH))),
                                    splat(count64, ir.VectorType(i64, WIDTH)))
        load = cgutils.get_or_insert_function(
            builder.module, ir.FunctionType(vt, [vt.as_pointer(), i32, lanes, vt]), "llvm.masked.load.v8f32.p0")
        nan = ir.Constant(vt, [math.nan] * WIDTH)

        def corner(vertex, k):
            row = builder.add(k, ir.Constant(i64, 3 * vertex))
            p = builder.gep(base, [builder.mul(row, count64)])
            return builder.call(load, [builder.bitcast(p, vt.as_pointer()), ir.Constant(i32, 4), valid, nan])

        Sx, Sy, Sz = (splat(builder.extract_value(shear, 3 + a)) for a in range(3))
        okx, oky, okz = (splat(builder.extract_value(origin, a)) for a in range(3))
        sub, mul, add = builder.fsub, builder.fmul, builder.fadd
        Az, Bz, Cz = (sub(corner(v, kz), okz) for v in range(3))
        ax, ay = sub(sub(corner(0, kx), okx), mul(Sx, Az)), sub(sub(corner(0, ky), oky), mul(Sy, Az))
        bx, by = sub(sub(corner(1, kx), okx), mul(Sx, Bz)), sub(sub(corner(1, ky), oky), mul(Sy, Bz))
        cx, cy = sub(sub(corner(2, kx), okx), mul(Sx, Cz)), sub(sub(corner(2, ky), oky), mul(Sy, Cz))
        U = sub(mul(cx, by), mul(cy, bx))
        V = sub(mul(ax, cy), mul(ay, cx))
        W = sub(mul(bx, ay), mul(by, ax))
        zero = ir.Constant(vt, [0.0] * WIDTH)

        def cmp(op, a, b=zero):
            return builder.fcmp_ordered(op, a, b)

        any3 = lambda op: builder.or_(builder.or_(cmp(op, U), cmp(op, V)), cmp(op, W))
        zeroed = builder.and_(any3("=="), valid)
        det = add(add(U, V), W)
        missed = builder.or_(builder.and_(any3("<"), any3(">")), cmp("==", det))
        t = builder.fdiv(add(add(mul(U, mul(Sz, Az)), mul(V, mul(Sz, Bz))), mul(W, mul(Sz, Cz))), det)
        within = builder.and_(cmp(">=", t, splat(tmin_v)), cmp("<", t, splat(limit_v)))
        hit = builder.and_(builder.and_(builder.xor(builder.or_(missed, zeroed), ir.Constant(lanes, [1] * WIDTH)),
                                        within), valid)
        builder.store(t, builder.bitcast(out_v, vt.as_pointer()), align=4)
        bits = lambda m: builder.zext(builder.bitcast(m, ir.IntType(WIDTH)), i64)
        return builder.or_(bits(hit), builder.shl(bits(zeroed), ir.Constant(i64, WIDTH)))
    return types.int64(corners, offset, count, frame, tmin, limit, out), codegen


@njit(error_model="numpy", inline="always")
def _take(state, t, idx, f):
    """mesh_closest's tie rule: (t, idx) replaces the best where it is lexicographically less."""
    tmax, best, kind, row = state
    if t < tmax or (t == tmax and idx < best):
        return t, idx, kind, f
    return state


# As mesh_closest (NO_REFCOUNT), but not cached: a test loads this script under a name no
# import finds, and numba's cache of it could not be loaded again.
@njit(error_model="numpy", _nrt=False)
def closest_blocks(vertices, faces, nodes, links, corners, table, first_block, origin, direction, tmin):
    """mesh_closest's wide traversal (no spheres, no instances, root 0) where a code
    >= ``first_block`` is the block code - first_block, tested by tri8."""
    state = (lit(math.inf, tmin), -1, 0, -1)
    frame, inv, widen, stack, entry_stack, entry = _wide_start(origin, direction, tmin)
    inf = lit(math.inf, tmin)
    sp = 0
    code = 0
    while True:
        if code >= first_block:
            b = code - first_block
            first = table[b, FIRST]
            mask = tri8(corners, table[b, OFFSET], table[b, COUNT], frame, tmin, np.nextafter(state[0], inf), entry)
            zeroed = mask >> WIDTH
            mask = (mask | zeroed) & (2 ** WIDTH - 1)
            for j in range(WIDTH):
                if mask >> j & 1:
                    f = first + j
                    idx = faces[f, 3]
                    t = entry[j]
                    if zeroed >> j & 1:
                        limit = state[0] if idx > state[1] else np.nextafter(state[0], inf)
                        t = intersect_face(vertices, faces, f, frame, tmin, limit)
                    state = _take(state, t, idx, f)
        elif code >= 0:
            sp = wide_bvh.enter_node(nodes, links, code, origin, inv, tmin, state[0] * widen, widen, entry, stack,
                                     entry_stack, sp)
        else:
            first, count = wide_bvh.leaf_span(code)
            for f in range(first, first + count):
                idx = faces[f, 3]
                limit = state[0] if idx > state[1] else np.nextafter(state[0], inf)
                state = _take(state, intersect_face(vertices, faces, f, frame, tmin, limit), idx, f)
        code, found, sp = wide_bvh.pop_within(stack, entry_stack, sp, state[0] * widen)
        if not found:
            break
    return state


@njit(parallel=True, error_model="numpy")
def closest_hits_blocks(vertices, faces, nodes, links, corners, table, first_block, origins, directions,
                        t_out, face_out):
    """benchmarks/meshes.py's closest_hits through closest_blocks."""
    for i in prange(origins.shape[0]):
        origin = (origins[i, 0], origins[i, 1], origins[i, 2])
        direction = (directions[i, 0], directions[i, 1], directions[i, 2])
        hit = closest_blocks(vertices, faces, nodes, links, corners, table, first_block, origin, direction,
                             lit(0, origins[i, 0]))
        t_out[i] = hit[0]
        face_out[i] = hit[1]


def make_blocks(wide_nodes, vertices, faces, all_leaves=False):
    """(nodes, corners, table, reachable nodes, faces in blocks): a copy of the wide nodes
    whose codes name the blocks (module docstring), the blocks' corners and their table; a
    node made a block is no longer reached. A node becomes a block where every column is one
    face (or empty) and its faces are the rows first .. first + count - 1 of ``faces``."""
    nodes = wide_nodes.copy()
    codes = nodes.view(np.int32)[:, CODE_ROW, :]
    n = len(nodes)
    empty = np.isposinf(wide_nodes[:, 0, :])
    one_face = (codes < 0) & ((~codes & (2 ** LEAF_BITS - 1)) == 0)
    pure = np.all(one_face | empty, axis=1)
    pure[0] = False                         # the root stays a node
    spans = []                              # (node or -1, column, first, count)
    for node in np.nonzero(pure)[0]:
        fs = np.sort(~codes[node][one_face[node] & ~empty[node]] >> LEAF_BITS)
        if len(fs) and fs[-1] - fs[0] == len(fs) - 1:
            spans.append((node, -1, int(fs[0]), len(fs)))
        else:
            pure[node] = False
    reached = ~pure
    if all_leaves:
        for node, j in zip(*np.nonzero((codes < 0) & ~empty & reached[:, None])):
            leaf = ~int(codes[node, j])
            spans.append((-1, (node, j), leaf >> LEAF_BITS, (leaf & (2 ** LEAF_BITS - 1)) + 1))
    table = np.zeros((len(spans), 3), dtype=np.int32)
    counts = np.array([s[3] for s in spans], dtype=np.int64)
    table[:, OFFSET] = CORNER_ROWS * (np.cumsum(counts) - counts)
    table[:, FIRST] = [s[2] for s in spans]
    table[:, COUNT] = counts
    corners = np.empty(CORNER_ROWS * int(counts.sum()), dtype=np.float32)
    block_of = np.full(n, -1, dtype=np.int64)
    for b, (node, column, first, count) in enumerate(spans):
        # rows v0.x, v0.y, v0.z, v1.x, ... of the faces first .. first + count - 1
        rows = vertices[faces[first:first + count, :3]].reshape(count, CORNER_ROWS).T
        corners[table[b, OFFSET]:table[b, OFFSET] + CORNER_ROWS * count] = rows.reshape(-1)
        if node >= 0:
            block_of[node] = b
        else:
            codes[column] = n + b
    named = (codes >= 0) & (codes < n) & (block_of[np.clip(codes, 0, n - 1)] >= 0)
    codes[named] = n + block_of[codes[named]]
    return nodes, corners, table, reached, int(counts.sum())


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--meshes", nargs="+", default=["bunny", "icosphere"])
    parser.add_argument("--all-leaves", action="store_true")
    parser.add_argument("--runs", type=int, default=7)
    args = parser.parse_args(argv)
    threads = numba.get_num_threads()
    embree = None
    try:
        embree = meshes.Embree(threads, robust=False)
    except ImportError as exc:
        print("Embree fast not measured: %s (make bench installs embreex)" % exc)
    rows = []
    for name in args.meshes:
        mesh = meshes.bunny() if name == "bunny" else meshes.displaced_icosphere(meshes.ICOSPHERE_SUBDIVISIONS)
        rtfgu = meshes.Rtfgu(threads)
        rtfgu.build(mesh)
        if embree is not None:
            embree.build(mesh)
        vertices, faces, wide = rtfgu.vertices["float32"], rtfgu.faces4, rtfgu.wide.nodes
        nodes, corners, table, reached, in_blocks = make_blocks(wide, vertices, faces, args.all_leaves)
        size = (reached.sum() * wide[0].nbytes + corners.nbytes + table.nbytes + faces.nbytes + vertices.nbytes
                ) / len(faces)
        now_size = (wide.nbytes + faces.nbytes + vertices.nbytes) / len(faces)
        for kind in ("primary", "incoherent"):
            rays = (meshes.primary_rays(mesh.vertices, meshes.PRIMARY) if kind == "primary"
                    else meshes.incoherent_rays(mesh.vertices, meshes.INCOHERENT))
            origins, directions = rays.of("float32")
            t0, f0 = np.empty(len(origins), np.float32), np.empty(len(origins), np.int64)
            t1, f1 = np.empty_like(t0), np.empty_like(f0)
            paths = {
                "mesh_closest": lambda: meshes.closest_hits(vertices, faces, wide, wide.view(np.int32), origins,
                                                            directions, t0, f0),
                "blocks": lambda: closest_hits_blocks(vertices, faces, nodes, nodes.view(np.int32), corners, table,
                                                      len(nodes), origins, directions, t1, f1)}
            if embree is not None:
                paths["Embree fast"] = lambda: embree.trace(rays, numba.get_num_threads())
            for path in paths.values():
                path()
            if not (np.array_equal(t0.view(np.int32), t1.view(np.int32)) and np.array_equal(f0, f1)):
                raise SystemExit("%s %s: the blocks' faces or ts differ from mesh_closest's" % (name, kind))
            for count in sorted({1, threads}):
                numba.set_num_threads(count)
                rates = {path: [] for path in paths}
                for _ in range(args.runs):
                    for path, run in paths.items():
                        run()
                        start = time.perf_counter()
                        run()
                        rates[path].append(len(origins) / (time.perf_counter() - start) / 1e6)
                med = {path: statistics.median(r) for path, r in rates.items()}
                rows.append((name, kind, count, med, len(table), in_blocks / max(len(table), 1), now_size, size))
                print(rows[-1], flush=True)
            numba.set_num_threads(threads)
    print("\n| mesh | rays | threads | mesh_closest | blocks | blocks / mesh_closest | Embree fast | blocks / "
          "Embree fast | blocks (faces a block) | bytes per triangle, now / with blocks |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name, kind, count, med, nblocks, lanes, now_size, size in rows:
        e = med.get("Embree fast")
        print("| %s | %s | %d | %.2f M/s | %.2f M/s | %.2f | %s | %s | %d (%.1f) | %.1f / %.1f |" % (
            name, kind, count, med["mesh_closest"], med["blocks"], med["blocks"] / med["mesh_closest"],
            "%.2f M/s" % e if e else "-", "%.2f" % (med["blocks"] / e) if e else "-", nblocks, lanes, now_size, size))


if __name__ == "__main__":
    main()
