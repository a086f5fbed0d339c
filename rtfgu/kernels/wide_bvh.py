# release: solves a08
"""The traversal of the wide BVH (rtfgu.accelerators.wide_bvh) on the numba path: a node's
eight child boxes tested at once by one vector slab test (``box8``), the children entered
nearest first.

numba leaves LLVM's SLP vectoriser off, and a loop over eight boxes stays scalar; ``box8`` is
a numba intrinsic that writes the LLVM IR itself, on ``<8 x float>`` (``<8 x double>`` in a
float64 render, the float32 boxes widened exactly), which LLVM compiles to packed AVX
instructions where the CPU has them (rtfgu.kernels.mesh.WIDE chooses the tree by the CPU).
It is the scalar slab test of rtfgu.kernels.mesh.box_entry lane by lane, the same
operations in the same order, so a lane enters a box exactly where box_entry does.

The stack: a node's children that the ray enters are pushed sorted, the farthest deepest, so
the nearest is popped first (Embree's sorting network does the same for its hits); an entry
popped beyond the nearest hit so far is dropped. A child goes on the stack as its code, the
node's row CODE_ROW: an inner child's node, a leaf's ~(first << LEAF_BITS | count - 1).
"""
from __future__ import annotations

import math

import numpy as np
from llvmlite import ir
from numba import njit, types
from numba.core import cgutils
from numba.extending import intrinsic, overload

from ..accelerators.flat_bvh import MAX_DEPTH
from ..accelerators.wide_bvh import BLOCK_BIT, CODE_ROW, FACE_COLUMNS, LEAF_BITS, ROWS, WIDTH

# A traversal pushes at most WIDTH - 1 entries per level it descends.
STACK = MAX_DEPTH * WIDTH


def vector_cpu() -> bool:
    """Whether the CPU tests WIDTH float32 lanes in one instruction (AVX): the numba path then
    traverses the wide tree, else the binary one (rtfgu.kernels.render.mesh_arrays). Both give
    every ray the same face and t (tests/test_wide_bvh.py); the wide one is the faster where
    the box test is one instruction (docs/bvh.md, "The wide BVH")."""
    from llvmlite import binding
    return bool(binding.get_host_cpu_features().get("avx", False))


WIDE = vector_cpu()


def _element(dtype):
    if isinstance(dtype, types.NumberClass):
        return dtype.instance_type
    if isinstance(dtype, types.Number):
        return dtype
    return None


def on_the_stack(size: int, what: str):
    """A function giving ``size`` elements of a number type (or of the type of a value
    given): compiled, a pointer to an alloca in the entry block of the function it is inlined
    into (an intrinsic), so it costs nothing per call and needs no reference counting; as
    plain Python (NUMBA_DISABLE_JIT=1), a numpy array."""
    @intrinsic
    def allocate(typingctx, dtype):
        element = _element(dtype)
        if element is None:
            return None

        def codegen(context, builder, signature, args):
            return cgutils.alloca_once(builder, context.get_value_type(element), size=size)
        return types.CPointer(element)(dtype), codegen

    def elements(like):
        return np.empty(size, dtype=like if isinstance(like, type) else np.asarray(like).dtype)

    @overload(elements, inline="always")
    def _typed_elements(like):
        return lambda like: allocate(like)
    elements.__doc__ = what
    return elements


stack_of = on_the_stack(STACK, "A traversal's stack: STACK elements.")
lanes_of = on_the_stack(WIDTH, "box8's entry ts: WIDTH elements.")


def typed_for_nodes(nodes, tmin, *pointers) -> bool:
    """Whether an intrinsic on the wide nodes types for these arguments: ``nodes`` a (N,
    ROWS, WIDTH) float32 array, ``tmin`` a float (the test's precision), each of
    ``pointers`` a pointer."""
    return (isinstance(nodes, types.Array) and nodes.ndim == 3 and nodes.dtype == types.float32
            and isinstance(tmin, types.Float) and all(isinstance(p, types.CPointer) for p in pointers))


def node_lanes(context, builder, nodes_t, nodes_v, n_t, n_v, real):
    """For the codegen of a test of node ``n``'s WIDTH columns (nodes (N, ROWS, WIDTH)
    float32): (vt, splat, row), the vector type of WIDTH values of ``real``, a value of
    ``real`` splatted across it, and row(index) the node's row ``index`` (an i64 value) as
    such a vector (float32 widened exactly in a float64 test)."""
    vt = ir.VectorType(context.get_value_type(real), WIDTH)
    vf32 = ir.VectorType(ir.FloatType(), WIDTH)
    i64 = ir.IntType(64)
    i32 = ir.IntType(32)
    array = context.make_array(nodes_t)(context, builder, nodes_v)
    n64 = context.cast(builder, n_v, n_t, types.int64)
    base = builder.gep(array.data, [builder.mul(n64, ir.Constant(i64, ROWS * WIDTH))])

    def splat(x):
        v = builder.insert_element(ir.Constant(vt, ir.Undefined), x, ir.Constant(i32, 0))
        return builder.shuffle_vector(v, ir.Constant(vt, ir.Undefined), ir.Constant(ir.VectorType(i32, WIDTH), [0] * WIDTH))

    def row(index):
        p = builder.gep(base, [builder.mul(index, ir.Constant(i64, WIDTH))])
        v = builder.load(builder.bitcast(p, vf32.as_pointer()), align=4)
        return v if real.bitwidth == 32 else builder.fpext(v, vt)
    return vt, splat, row


@intrinsic
def box8(typingctx, nodes, n, origin, inv, tmin, tmax, widen, entry):
    """The slab test of node ``n``'s WIDTH child boxes (nodes (N, ROWS, WIDTH) float32): a bit
    mask of the children the ray enters within [tmin, tmax], and at ``entry`` (a pointer to
    WIDTH floats of tmin's type) the t at which it enters each (inf where it does not).
    ``inv`` = 1 / direction (inf for a zero component): the near plane of an axis is hi
    where its inv < 0, lo otherwise. As box_entry: near = (plane - o) * inv, far the same
    times ``widen``; t0 the largest of tmin and the nears, t1 the smallest of tmax and the
    fars, a NaN (0 * inf) narrowing neither; entered where not t0 > t1."""
    if not typed_for_nodes(nodes, tmin):
        return None
    real = tmin

    def codegen(context, builder, signature, args):
        nodes_v, n_v, origin_v, inv_v, tmin_v, tmax_v, widen_v, entry_v = args
        nodes_t, n_t, origin_t, inv_t, tmin_t, tmax_t, widen_t, _ = signature.args
        ft = context.get_value_type(real)
        i64 = ir.IntType(64)
        vt, splat, row = node_lanes(context, builder, nodes_t, nodes_v, n_t, n_v, real)

        def scalar(value, typ):
            return context.cast(builder, value, typ, real)

        zero = ir.Constant(ft, 0.0)
        t0 = splat(scalar(tmin_v, tmin_t))
        t1 = splat(scalar(tmax_v, tmax_t))
        w = splat(scalar(widen_v, widen_t))
        for a in range(3):
            o = splat(scalar(builder.extract_value(origin_v, a), origin_t.types[a]))
            inv_a = scalar(builder.extract_value(inv_v, a), inv_t.types[a])
            i = splat(inv_a)
            negative = builder.fcmp_ordered("<", inv_a, zero)
            near_row = builder.select(negative, ir.Constant(i64, 3 + a), ir.Constant(i64, a))
            far_row = builder.select(negative, ir.Constant(i64, a), ir.Constant(i64, 3 + a))
            near = builder.fmul(builder.fsub(row(near_row), o), i)
            far = builder.fmul(builder.fmul(builder.fsub(row(far_row), o), i), w)
            t0 = builder.select(builder.fcmp_ordered(">", near, t0), near, t0)
            t1 = builder.select(builder.fcmp_ordered("<", far, t1), far, t1)
        missed = builder.fcmp_ordered(">", t0, t1)
        inf = ir.Constant(vt, [math.inf] * WIDTH)
        builder.store(builder.select(missed, inf, t0), builder.bitcast(entry_v, vt.as_pointer()), align=4)
        entered = builder.xor(missed, ir.Constant(ir.VectorType(ir.IntType(1), WIDTH), [1] * WIDTH))
        mask = builder.bitcast(entered, ir.IntType(WIDTH))
        return builder.zext(mask, i64)
    return types.int64(nodes, n, origin, inv, tmin, tmax, widen, types.CPointer(real)), codegen


@njit(cache=True, error_model="numpy", inline="always")
def enter_node(nodes, links, node, origin, inv, tmin, reach, widen, entry, stack, entry_stack, sp):
    """box8 on ``node`` within [tmin, reach], and the children the ray enters pushed sorted
    by their entry t, the nearest on top (``entry``: box8's lanes); returns the new stack
    size. Each goes on as its code (rtfgu.accelerators.wide_bvh)."""
    mask = box8(nodes, node, origin, inv, tmin, reach, widen, entry)
    base = sp
    for j in range(WIDTH):
        if mask >> j & 1:
            t = entry[j]
            child = links[node, CODE_ROW, j]
            k = sp
            while k > base and entry_stack[k - 1] < t:
                stack[k] = stack[k - 1]
                entry_stack[k] = entry_stack[k - 1]
                k -= 1
            stack[k] = child
            entry_stack[k] = t
            sp += 1
    return sp


@njit(cache=True, error_model="numpy", inline="always")
def enter_node_any(nodes, links, node, origin, inv, tmin, reach, widen, entry, stack, sp):
    """enter_node for a shadow ray, which stops at any hit: the children it enters pushed in
    column order, unsorted (Embree's any-hit traversal does not sort either)."""
    mask = box8(nodes, node, origin, inv, tmin, reach, widen, entry)
    for j in range(WIDTH):
        if mask >> j & 1:
            stack[sp] = links[node, CODE_ROW, j]
            sp += 1
    return sp


@njit(cache=True, error_model="numpy", inline="always")
def flat_value(table, at):
    """The value at ``at`` of the (N, ROWS, WIDTH) table, counted from its start (a block's
    header and corners: rtfgu.accelerators.wide_bvh.with_blocks)."""
    node = at // (ROWS * WIDTH)
    k = at - node * (ROWS * WIDTH)
    return table[node, k // WIDTH, k % WIDTH]


@njit(cache=True, error_model="numpy", inline="always")
def is_block(code):
    """Whether a leaf's stack entry names a block (rtfgu.accelerators.wide_bvh.with_blocks)."""
    return (~code) >> BLOCK_BIT != 0


@njit(cache=True, error_model="numpy", inline="always")
def block_at(code):
    """Where a block's header lies in the table (a float's index from its start)."""
    return ((~code) & ((1 << BLOCK_BIT) - 1)) >> LEAF_BITS


@njit(cache=True, error_model="numpy", inline="always")
def leaf_span(code, links):
    """(first, count) of a leaf's stack entry, a block's first read from its header."""
    leaf = ~code
    count = (leaf & ((1 << LEAF_BITS) - 1)) + 1
    if leaf >> BLOCK_BIT:
        return np.int64(flat_value(links, block_at(code))), count
    return leaf >> LEAF_BITS, count


def _block_rows(context, builder, signature, nodes_v, at_v, count_v):
    """For the codegen of a block's test: (corner(k), valid, vt): corner(k) the block's
    corners' row k (0-8: v0.x, v0.y, v0.z, v1.x, ...; an i64 value) as WIDTH float32 lanes,
    each a masked load of its ``count`` lanes (NaN in the others), valid the mask of the
    lanes below ``count``."""
    ft = ir.FloatType()
    vt = ir.VectorType(ft, WIDTH)
    i64, i32 = ir.IntType(64), ir.IntType(32)
    lanes = ir.VectorType(ir.IntType(1), WIDTH)
    array = context.make_array(signature.args[0])(context, builder, nodes_v)
    count64 = context.cast(builder, count_v, signature.args[2], types.int64)
    base = builder.gep(array.data, [context.cast(builder, at_v, signature.args[1], types.int64)])
    i64v = ir.VectorType(i64, WIDTH)
    splat = builder.shuffle_vector(builder.insert_element(ir.Constant(i64v, ir.Undefined), count64, ir.Constant(i32, 0)),
                                   ir.Constant(i64v, ir.Undefined), ir.Constant(ir.VectorType(i32, WIDTH), [0] * WIDTH))
    valid = builder.icmp_signed("<", ir.Constant(i64v, list(range(WIDTH))), splat)
    load = cgutils.get_or_insert_function(
        builder.module, ir.FunctionType(vt, [vt.as_pointer(), i32, lanes, vt]), "llvm.masked.load.v8f32.p0")
    nan = ir.Constant(vt, [math.nan] * WIDTH)

    def corner(k):
        p = builder.gep(base, [builder.mul(k, count64)])
        return builder.call(load, [builder.bitcast(p, vt.as_pointer()), ir.Constant(i32, 4), valid, nan])
    return corner, valid, vt


def _outward_to_float32(builder, x, down):
    """x (a vector of doubles) rounded to float32 down (``down``) or up, and widened back:
    the nearest float32, one step further where it lies on the wrong side, as
    rtfgu.accelerators.flat_bvh._put_box rounds a box (±0 steps to the smallest subnormal)."""
    f32v = ir.VectorType(ir.FloatType(), WIDTH)
    i32v = ir.VectorType(ir.IntType(32), WIDTH)
    near = builder.fptrunc(x, f32v)
    wrong = builder.fcmp_ordered(">" if down else "<", builder.fpext(near, x.type), x)
    bits = builder.bitcast(near, i32v)
    zero = ir.Constant(f32v, [0.0] * WIDTH)
    toward_zero = builder.fcmp_ordered(">" if down else "<", near, zero)     # the step is towards zero
    step = builder.select(toward_zero, ir.Constant(i32v, [-1] * WIDTH), ir.Constant(i32v, [1] * WIDTH))
    stepped = builder.select(builder.fcmp_ordered("==", near, zero),
                             ir.Constant(i32v, [-2147483647 if down else 1] * WIDTH), builder.add(bits, step))
    return builder.fpext(builder.select(wrong, builder.bitcast(stepped, f32v), near), x.type)


def _corner_boxes(builder, corner, vt, out_v):
    """For the codegen of a block's faces' boxes: the smallest and largest of each coordinate
    of their three corners (corner(vertex, k) as in _watertight_lanes), stored at ``out_v``
    as six rows of WIDTH values, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z: exact in float32; in
    float64 rounded outward to float32, so that each is the box the tree held for that face
    (flat_bvh's boxes) and a packet's rays enter the same boxes as at the node the block
    replaced."""
    i64 = ir.IntType(64)
    for a in range(3):
        c = [corner(v, ir.Constant(i64, a)) for v in range(3)]
        lo = builder.select(builder.fcmp_ordered("<", c[1], c[0]), c[1], c[0])
        lo = builder.select(builder.fcmp_ordered("<", c[2], lo), c[2], lo)
        hi = builder.select(builder.fcmp_ordered(">", c[1], c[0]), c[1], c[0])
        hi = builder.select(builder.fcmp_ordered(">", c[2], hi), c[2], hi)
        if isinstance(vt.element, ir.DoubleType):
            lo, hi = _outward_to_float32(builder, lo, True), _outward_to_float32(builder, hi, False)
        for row, value in ((a, lo), (3 + a, hi)):
            p = builder.gep(out_v, [ir.Constant(i64, row * WIDTH)])
            builder.store(value, builder.bitcast(p, vt.as_pointer()), align=4)


@intrinsic
def block_boxes(typingctx, nodes, at, count, out):
    """The boxes of a block's ``count`` faces (their corners' nine rows from float ``at`` of
    ``nodes``) into ``out`` (a pointer to six rows of WIDTH float32: lo.x, lo.y, lo.z, hi.x,
    hi.y, hi.z of each face): the smallest and largest of each coordinate of its three
    corners, exact (a face's points lie in it)."""
    if not (typed_for_nodes(nodes, types.float32, out) and isinstance(at, types.Integer)
            and isinstance(count, types.Integer)):
        return None

    def codegen(context, builder, signature, args):
        nodes_v, at_v, count_v, out_v = args
        rows, _, vt = _block_rows(context, builder, signature, nodes_v, at_v, count_v)
        i64 = ir.IntType(64)
        _corner_boxes(builder, lambda vertex, k: rows(builder.add(k, ir.Constant(i64, 3 * vertex))), vt, out_v)
        return context.get_dummy_value()
    return types.none(nodes, at, count, out), codegen


def _watertight_lanes(context, builder, frame_t, corner, valid, vt, frame_v, tmin_v, limit_v, out_v, zeroed_redone):
    """For the codegen of a block's test: rtfgu.kernels.mesh.intersect_face on WIDTH faces,
    lane by lane, the same operations in the same order, so a lane's t is the scalar test's
    bit for bit. corner(vertex, k): the faces' corner ``vertex`` (0-2), coordinate ``k`` (an
    i64 value), as a vector of vt; ``valid``: the mask of the lanes that hold a face;
    ``frame_v`` the ray frame (ray_frame), of type ``frame_t``. Stores each lane's t at
    ``out_v`` and returns the i64 mask: bits 0-7 the lanes hit in [tmin, limit), and, where
    ``zeroed_redone`` (a float32 test), bits 8-15 the lanes whose U, V or W rounds to zero,
    which the scalar test recomputes in double (left out of bits 0-7). In float64 that
    recomputation is a no-op, so such lanes are decided here."""
    i64, i32 = ir.IntType(64), ir.IntType(32)
    lanes = ir.VectorType(ir.IntType(1), WIDTH)
    shear, origin = builder.extract_value(frame_v, 0), builder.extract_value(frame_v, 1)
    kx, ky, kz = (context.cast(builder, builder.extract_value(shear, a), frame_t.types[0].types[a], types.int64)
                  for a in range(3))

    def splat(x):
        v = builder.insert_element(ir.Constant(vt, ir.Undefined), x, ir.Constant(i32, 0))
        return builder.shuffle_vector(v, ir.Constant(vt, ir.Undefined),
                                      ir.Constant(ir.VectorType(i32, WIDTH), [0] * WIDTH))

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
    zeroed = builder.and_(any3("=="), valid) if zeroed_redone else ir.Constant(lanes, [0] * WIDTH)
    det = add(add(U, V), W)
    missed = builder.or_(builder.and_(any3("<"), any3(">")), cmp("==", det))
    t = builder.fdiv(add(add(mul(U, mul(Sz, Az)), mul(V, mul(Sz, Bz))), mul(W, mul(Sz, Cz))), det)
    within = builder.and_(cmp(">=", t, splat(tmin_v)), cmp("<", t, splat(limit_v)))
    hit = builder.and_(builder.and_(builder.xor(builder.or_(missed, zeroed), ir.Constant(lanes, [1] * WIDTH)),
                                    within), valid)
    builder.store(t, builder.bitcast(out_v, vt.as_pointer()), align=4)
    bits = lambda m: builder.zext(builder.bitcast(m, ir.IntType(WIDTH)), i64)
    return builder.or_(bits(hit), builder.shl(bits(zeroed), ir.Constant(i64, WIDTH)))


@intrinsic
def block_test(typingctx, nodes, at, count, frame, tmin, limit, out):
    """The watertight test of a block's ``count`` (1-8) faces (with_blocks), their corners'
    nine rows from float ``at`` of the table ``nodes`` on, in a float32 test: each lane's t
    at ``out`` (a pointer to WIDTH floats); returns a bit mask, bits 0-7 the lanes hit in
    [tmin, limit), bits 8-15 the lanes whose U, V or W rounds to zero (the scalar test
    recomputes those in double). It is rtfgu.kernels.mesh.intersect_face lane by lane
    (_watertight_lanes), on the ray frame's axes kx, ky, kz picked as rows. A row is read by
    a masked load of its ``count`` lanes, so nothing past the block is read."""
    if not (typed_for_nodes(nodes, tmin, out) and tmin == types.float32 and isinstance(at, types.Integer)
            and isinstance(count, types.Integer)):
        return None

    def codegen(context, builder, signature, args):
        nodes_v, at_v, count_v, frame_v, tmin_v, limit_v, out_v = args
        rows, valid, vt = _block_rows(context, builder, signature, nodes_v, at_v, count_v)
        i64 = ir.IntType(64)

        def corner(vertex, k):
            return rows(builder.add(k, ir.Constant(i64, 3 * vertex)))
        return _watertight_lanes(context, builder, signature.args[3], corner, valid, vt, frame_v, tmin_v, limit_v,
                                 out_v, True)
    return types.int64(nodes, at, count, frame, tmin, limit, out), codegen


def typed_for_gathers(vertices, faces, first, count, real) -> bool:
    """Whether a block's corners can be gathered for these arguments: ``vertices`` (V, 3) of
    ``real``, ``faces`` (F, FACE_COLUMNS) int32 in C order, ``first`` and ``count`` ints."""
    return (isinstance(vertices, types.Array) and vertices.ndim == 2 and vertices.dtype == real
            and isinstance(faces, types.Array) and faces.ndim == 2 and faces.layout == "C"
            and faces.dtype == types.int32 and isinstance(first, types.Integer) and isinstance(count, types.Integer))


def _gathered_corners(context, builder, signature, vertices_v, faces_v, first_v, count_v, real):
    """For the codegen of a test of a block that holds no corners (a float64 tree's,
    with_blocks): (corner, valid, vt) as _block_rows gives them, for the faces
    faces[first:first + count] (arguments 0-3 of ``signature``: vertices, faces, first,
    count). The block's rows are one masked load of count * FACE_COLUMNS int32, each
    vertex's column of them a shuffle; a corner's coordinate is one masked gather of its
    ``count`` lanes from ``vertices`` (NaN in the others)."""
    ft = context.get_value_type(real)
    vt = ir.VectorType(ft, WIDTH)
    i64, i32 = ir.IntType(64), ir.IntType(32)
    i64v = ir.VectorType(i64, WIDTH)
    wide = FACE_COLUMNS * WIDTH
    i32w, i64w = ir.VectorType(i32, wide), ir.VectorType(i64, wide)

    def splat(t, x, n=WIDTH):
        v = builder.insert_element(ir.Constant(t, ir.Undefined), x, ir.Constant(i32, 0))
        return builder.shuffle_vector(v, ir.Constant(t, ir.Undefined), ir.Constant(ir.VectorType(i32, n), [0] * n))

    first64 = context.cast(builder, first_v, signature.args[2], types.int64)
    count64 = context.cast(builder, count_v, signature.args[3], types.int64)
    valid = builder.icmp_signed("<", ir.Constant(i64v, list(range(WIDTH))), splat(i64v, count64))
    face_rows = context.make_array(signature.args[1])(context, builder, faces_v)
    points = context.make_array(signature.args[0])(context, builder, vertices_v)
    load = cgutils.get_or_insert_function(builder.module, ir.FunctionType(
        i32w, [i32w.as_pointer(), i32, ir.VectorType(ir.IntType(1), wide), i32w]), "llvm.masked.load.v%di32.p0" % wide)
    in_block = builder.icmp_signed("<", ir.Constant(i64w, list(range(wide))),
                                   splat(i64w, builder.mul(count64, ir.Constant(i64, FACE_COLUMNS)), wide))
    start = builder.gep(face_rows.data, [builder.mul(first64, ir.Constant(i64, FACE_COLUMNS))])
    rows = builder.call(load, [builder.bitcast(start, i32w.as_pointer()), ir.Constant(i32, 4), in_block,
                               ir.Constant(i32w, [0] * wide)])
    # Corner v's coordinates start at vertices.data + its row * the row stride (bytes).
    row_stride, column_stride = (builder.extract_value(points.strides, a) for a in range(2))
    base = splat(i64v, builder.ptrtoint(points.data, i64))
    starts = [builder.add(base, builder.mul(builder.sext(builder.shuffle_vector(
        rows, ir.Constant(i32w, ir.Undefined),
        ir.Constant(ir.VectorType(i32, WIDTH), [FACE_COLUMNS * j + v for j in range(WIDTH)])), i64v),
        splat(i64v, row_stride))) for v in range(3)]
    pointers = ir.VectorType(ft.as_pointer(), WIDTH)
    gather = cgutils.get_or_insert_function(builder.module, ir.FunctionType(
        vt, [pointers, i32, ir.VectorType(ir.IntType(1), WIDTH), vt]), "llvm.masked.gather.v8f%d.v8p0" % real.bitwidth)
    nan = ir.Constant(vt, [math.nan] * WIDTH)

    def corner(vertex, k):
        p = builder.inttoptr(builder.add(starts[vertex], splat(i64v, builder.mul(k, column_stride))), pointers)
        return builder.call(gather, [p, ir.Constant(i32, real.bitwidth // 8), valid, nan])
    return corner, valid, vt


@intrinsic
def block_test_gathered(typingctx, vertices, faces, first, count, frame, tmin, limit, out):
    """block_test for a block that holds no corners (a float64 tree's, with_blocks): the
    faces faces[first:first + count], their corners gathered from ``vertices``
    (_gathered_corners), in a test of tmin's precision. Each lane's t at ``out``; returns
    the mask of the lanes hit in [tmin, limit) (bits 0-7; in float64 no lane is left to the
    scalar test, whose recomputation in double changes nothing)."""
    if not (typed_for_gathers(vertices, faces, first, count, tmin) and isinstance(out, types.CPointer)):
        return None

    def codegen(context, builder, signature, args):
        vertices_v, faces_v, first_v, count_v, frame_v, tmin_v, limit_v, out_v = args
        corner, valid, vt = _gathered_corners(context, builder, signature, vertices_v, faces_v, first_v, count_v, tmin)
        return _watertight_lanes(context, builder, signature.args[4], corner, valid, vt, frame_v, tmin_v, limit_v,
                                 out_v, tmin == types.float32)
    return types.int64(vertices, faces, first, count, frame, tmin, limit, out), codegen


@intrinsic
def block_boxes_gathered(typingctx, vertices, faces, first, count, out):
    """block_boxes for a block that holds no corners: the boxes of faces[first:first +
    count], from their corners gathered from ``vertices`` (_gathered_corners), into ``out``
    (six rows of WIDTH values of the vertices' type): in float64 the boxes the tree held for
    those faces (_corner_boxes)."""
    if not (isinstance(vertices, types.Array) and typed_for_gathers(vertices, faces, first, count, vertices.dtype)
            and isinstance(out, types.CPointer) and out.dtype == vertices.dtype):
        return None

    def codegen(context, builder, signature, args):
        vertices_v, faces_v, first_v, count_v, out_v = args
        corner, _, vt = _gathered_corners(context, builder, signature, vertices_v, faces_v, first_v, count_v,
                                          signature.args[0].dtype)
        _corner_boxes(builder, corner, vt, out_v)
        return context.get_dummy_value()
    return types.none(vertices, faces, first, count, out), codegen


@njit(cache=True, error_model="numpy", inline="always")
def pop_within(stack, entry_stack, sp, reach):
    """The next stack entry the ray enters within ``reach`` (the best t so far, widened):
    (its code, True, the stack size below it); the entries popped beyond ``reach`` are
    dropped. (0, False, 0) when none is left."""
    while sp > 0:
        sp -= 1
        if entry_stack[sp] <= reach:
            return stack[sp], True, sp
    return 0, False, 0
