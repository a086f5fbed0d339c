# release: solves a08
"""Packets of rays through the wide BVH (rtfgu.accelerators.wide_bvh): up to PACKET rays that
start together (a pinhole's neighbouring primary rays) traverse the tree as one, so a node
is fetched and its bookkeeping done once for all the rays that enter it, and a child's box
is tested against all of them by one vector slab test, one lane a ray (``box_rays``; Wald,
Slusallek, Benthin and Wagner 2001, "Interactive Rendering with Coherent Ray Tracing";
Embree's hybrid traversal, Wald et al. 2014 section 4.3, which also switches a packet to
single rays when few of its rays remain, as SINGLE does here).

The traversal keeps one stack for the packet. An entry is a node's code (wide_bvh.CODE_ROW),
the bit mask of the packet's rays that enter its box, and the nearest t at which one of
them does. Popped, an entry keeps the rays whose nearest hit so far is not nearer than that
t (times the slab's widening, as mesh_closest drops a box), and:

- with at most SINGLE rays left, each finishes the subtree alone (mesh_closest from the
  entry's code, its nearest hit so far as its bound);
- at an inner node, box_frustum first tests the eight child boxes at once against the
  packet's frustum, and box_rays tests each child's box the frustum enters against the rays:
  a child is pushed with the mask of the rays that enter it and their nearest entry, the
  children sorted by it, the nearest on top;
- at a leaf, where every ray of the packet has the same frame axes (ray_frame's kx, ky, kz:
  the rays of a tile nearly always), each face is tested against all the entry's rays at
  once (face_rays, intersect_face lane by lane); a sphere, an instance, and a ray whose edge
  function rounds to zero are tested ray by ray (_leaf_closest); without a shared frame,
  each ray tests the leaf's primitives alone.

A ray tests a box only where it entered its parent's box within its own nearest hit so far,
with the very operations of box8 (so it enters the same boxes), and a primitive only where it
entered its box: it finds the face, t and tie of mesh_closest alone (tests/test_packet.py
compares every ray).

The frustum (Embree's coherent packets, BVHNIntersectorKHybrid::intersectCoherent in
kernels/bvh/bvh_intersector_hybrid.cpp, test a node's children against a Frustum of each
octant of the packet before the rays' own box tests; Reshetov, Soupikov and Hurley 2005,
"Multi-Level Ray Tracing Algorithm"): where every ray of
the packet has, on each axis, a finite 1 / direction of one sign, the packet's rays lie in
the intervals [omin, omax] of origins and [imin, imax] of inverses. A ray's near t of a box
is fl(fl(plane - o) * inv), and rounding is monotone, so the same operations on the ends of
the intervals (the smaller difference times each end of [imin, imax], the smaller product
kept) bound every ray's near t from below, and its far t from above: a box the frustum does
not enter, no ray of the packet enters, bit for bit (test_packet.py checks it against
box_rays). Primary rays of a tile (one origin) make a narrow frustum: most of a node's
children are then culled by one vector test instead of a box_rays each.
"""
from __future__ import annotations

import math

import numpy as np
from llvmlite import ir
from numba import njit, types
from numba.core import cgutils
from numba.cpython.unsafe.numbers import trailing_zeros
from numba.extending import intrinsic, overload

from ..accelerators.wide_bvh import BLOCK_HEADER, CODE_ROW, ROWS, WIDTH
from ..layout import INSTANCE_ROW, MESH, SPHERE_ROW
from . import wide_bvh
from .dispatch_support import as_python
from .float3 import lit, lit_per_precision
from .mesh import NO_REFCOUNT, WIDEN32, WIDEN64, _inverse, _leaf_closest, block_closest, mesh_closest, ray_frame

# Rays of a packet: its masks are bits of an int64, its lanes one vector.
PACKET = 16
# box_frustum's mask where a packet has no frustum: every column.
ALL_COLUMNS = (1 << WIDTH) - 1
# An entry left with at most this many rays is finished by each ray alone (docs/bvh.md,
# "Packets": measured with benchmarks/meshes.py; 1 since the leaves' faces go against the
# rays at once, face_rays).
SINGLE = 1

# The packet's rays as box_rays reads them: PACKET lanes of each of these rows.
OX, OY, OZ, IX, IY, IZ, REACH = range(7)
RAY_ROWS = 7

# The packet's frustum as box_frustum reads it, per axis a at FRUSTUM_AXIS * a: whether its
# inverses are negative (1) or positive (0), the origin bound for the near plane and for the
# far plane, and the smallest and largest inverse.
NEGATIVE, O_NEAR, O_FAR, I_MIN, I_MAX = range(5)
FRUSTUM_AXIS = 5

# The rays' frames (rtfgu.kernels.mesh.ray_frame) a lane a ray, as face_rays reads them:
# PACKET lanes of each of these rows.
SX, SY, SZ, OKX, OKY, OKZ = range(6)
FRAME_ROWS = 6

_rays_of = wide_bvh.on_the_stack(RAY_ROWS * PACKET, "A packet's rays, RAY_ROWS rows of PACKET lanes.")
_per_ray = wide_bvh.on_the_stack(3 * PACKET, "Three values per ray of a packet.")
lanes_of = wide_bvh.on_the_stack(PACKET, "A value per ray of a packet.")
_frustum_of = wide_bvh.on_the_stack(3 * FRUSTUM_AXIS, "A packet's frustum, FRUSTUM_AXIS values an axis.")
_frames_of = wide_bvh.on_the_stack(FRAME_ROWS * PACKET, "A packet's ray frames, FRAME_ROWS rows of PACKET lanes.")


@njit(cache=True, error_model="numpy", inline="always")
def nearer_hit(hit, other):
    """The nearer of two hits (t, scene index, kind, row) by the tie rule: the smaller t, of
    equal ts the smaller index (as mesh_closest keeps a face); ``other`` a miss (index -1)
    never wins."""
    if other[1] >= 0 and (other[0] < hit[0] or (other[0] == hit[0] and other[1] < hit[1])):
        return other
    return hit


def _slab_lanes(context, builder, signature, real, plane, rays_v, live_v, live_t, tmin_v, tmin_t, widen_v, widen_t):
    """The codegen of box_rays and box_rays_of: ``plane(row)`` gives the box's plane ``row``
    (0-2 lo, 3-5 hi) as a value of ``real``."""
    ft = context.get_value_type(real)
    vt = ir.VectorType(ft, PACKET)
    i64 = ir.IntType(64)
    i32 = ir.IntType(32)

    def splat(x):
        v = builder.insert_element(ir.Constant(vt, ir.Undefined), x, ir.Constant(i32, 0))
        return builder.shuffle_vector(v, ir.Constant(vt, ir.Undefined),
                                      ir.Constant(ir.VectorType(i32, PACKET), [0] * PACKET))

    def lanes(row):
        p = builder.gep(rays_v, [ir.Constant(i64, row * PACKET)])
        return builder.load(builder.bitcast(p, vt.as_pointer()), align=4)

    zero = ir.Constant(vt, [0.0] * PACKET)
    t0 = splat(context.cast(builder, tmin_v, tmin_t, real))
    t1 = lanes(REACH)
    w = splat(context.cast(builder, widen_v, widen_t, real))
    for a in range(3):
        o = lanes(OX + a)
        inv = lanes(IX + a)
        negative = builder.fcmp_ordered("<", inv, zero)
        lo, hi = splat(plane(a)), splat(plane(3 + a))
        near = builder.fmul(builder.fsub(builder.select(negative, hi, lo), o), inv)
        far = builder.fmul(builder.fmul(builder.fsub(builder.select(negative, lo, hi), o), inv), w)
        t0 = builder.select(builder.fcmp_ordered(">", near, t0), near, t0)
        t1 = builder.select(builder.fcmp_ordered("<", far, t1), far, t1)
    mask_t = ir.VectorType(ir.IntType(1), PACKET)
    live_bits = builder.bitcast(builder.trunc(context.cast(builder, live_v, live_t, types.int64),
                                              ir.IntType(PACKET)), mask_t)
    entered = builder.and_(builder.xor(builder.fcmp_ordered(">", t0, t1),
                                       ir.Constant(mask_t, [1] * PACKET)), live_bits)
    mask = builder.zext(builder.bitcast(entered, ir.IntType(PACKET)), i64)
    nearest = builder.select(entered, t0, ir.Constant(vt, [math.inf] * PACKET))
    reduce = cgutils.get_or_insert_function(
        builder.module, ir.FunctionType(ft, [vt]),
        "llvm.vector.reduce.fmin.v%df%d" % (PACKET, real.bitwidth))
    return context.make_tuple(builder, signature.return_type, [mask, builder.call(reduce, [nearest])])


@intrinsic
def box_rays(typingctx, nodes, n, j, rays, live, tmin, widen):
    """The slab test of child ``j``'s box of node ``n`` (nodes (N, ROWS, WIDTH) float32)
    against the packet's rays (``rays``: a pointer to RAY_ROWS x PACKET values of tmin's
    type: origin, 1 / direction and the reach, each ray's nearest hit so far times the
    widening), one lane a ray: (the bit mask of the rays of ``live`` that enter it within
    [tmin, reach], the nearest t at which one does, inf for none). A lane does what box8
    does for that column: the near plane of an axis is hi where the ray's inv < 0, near =
    (plane - o) * inv, far the same times ``widen``; t0 the largest of tmin and the nears,
    t1 the smallest of the reach and the fars, a NaN narrowing neither; entered where not
    t0 > t1."""
    if not wide_bvh.typed_for_nodes(nodes, tmin, rays):
        return None
    real = tmin

    def codegen(context, builder, signature, args):
        nodes_v, n_v, j_v, rays_v, live_v, tmin_v, widen_v = args
        nodes_t, n_t, j_t, _, live_t, tmin_t, widen_t = signature.args
        i64 = ir.IntType(64)
        array = context.make_array(nodes_t)(context, builder, nodes_v)
        n64 = context.cast(builder, n_v, n_t, types.int64)
        j64 = context.cast(builder, j_v, j_t, types.int64)
        base = builder.gep(array.data, [builder.add(builder.mul(n64, ir.Constant(i64, ROWS * WIDTH)), j64)])

        def plane(row):
            x = builder.load(builder.gep(base, [ir.Constant(i64, row * WIDTH)]))
            return x if real.bitwidth == 32 else builder.fpext(x, context.get_value_type(real))
        return _slab_lanes(context, builder, signature, real, plane, rays_v, live_v, live_t, tmin_v, tmin_t,
                           widen_v, widen_t)
    return types.Tuple((types.int64, real))(nodes, n, j, rays, live, tmin, widen), codegen


@intrinsic
def box_rays_of(typingctx, boxes, j, rays, live, tmin, widen):
    """box_rays for box ``j`` of ``boxes`` (a pointer to six rows of WIDTH values of tmin's
    type: lo.x, lo.y, lo.z, hi.x, hi.y, hi.z of each box, _block_boxes)."""
    if not (isinstance(boxes, types.CPointer) and boxes.dtype == tmin and isinstance(rays, types.CPointer)
            and isinstance(tmin, types.Float) and isinstance(j, types.Integer)):
        return None
    real = tmin

    def codegen(context, builder, signature, args):
        boxes_v, j_v, rays_v, live_v, tmin_v, widen_v = args
        _, j_t, _, live_t, tmin_t, widen_t = signature.args
        i64 = ir.IntType(64)
        base = builder.gep(boxes_v, [context.cast(builder, j_v, j_t, types.int64)])

        def plane(row):
            return builder.load(builder.gep(base, [ir.Constant(i64, row * WIDTH)]))
        return _slab_lanes(context, builder, signature, real, plane, rays_v, live_v, live_t, tmin_v, tmin_t,
                           widen_v, widen_t)
    return types.Tuple((types.int64, real))(boxes, j, rays, live, tmin, widen), codegen


@intrinsic
def rays_within(typingctx, rays, mask, near):
    """(the rays of ``mask`` whose reach is not below ``near``, how many): one vector
    comparison of the reach lanes (``rays`` as box_rays has them)."""
    if not isinstance(near, types.Float) or not isinstance(rays, types.CPointer):
        return None
    real = near

    def codegen(context, builder, signature, args):
        rays_v, mask_v, near_v = args
        _, mask_t, near_t = signature.args
        ft = context.get_value_type(real)
        vt = ir.VectorType(ft, PACKET)
        i32 = ir.IntType(32)
        i64 = ir.IntType(64)
        p = builder.gep(rays_v, [ir.Constant(i64, REACH * PACKET)])
        reach = builder.load(builder.bitcast(p, vt.as_pointer()), align=4)
        x = builder.insert_element(ir.Constant(vt, ir.Undefined), context.cast(builder, near_v, near_t, real),
                                   ir.Constant(i32, 0))
        x = builder.shuffle_vector(x, ir.Constant(vt, ir.Undefined),
                                   ir.Constant(ir.VectorType(i32, PACKET), [0] * PACKET))
        within = builder.bitcast(builder.fcmp_ordered("<=", x, reach), ir.IntType(PACKET))
        kept = builder.and_(builder.zext(within, i64), context.cast(builder, mask_v, mask_t, types.int64))
        ctpop = cgutils.get_or_insert_function(builder.module, ir.FunctionType(i64, [i64]), "llvm.ctpop.i64")
        return context.make_tuple(builder, signature.return_type, [kept, builder.call(ctpop, [kept])])
    return types.UniTuple(types.int64, 2)(rays, mask, near), codegen


@intrinsic
def box_frustum(typingctx, nodes, n, frustum, tmin, widen):
    """The bit mask of node ``n``'s WIDTH child boxes (nodes (N, ROWS, WIDTH) float32) that
    the packet's frustum enters at or beyond ``tmin`` (``frustum``: a pointer to 3 x
    FRUSTUM_AXIS values of tmin's type, frustum_of_packet's): box8's slab test with, on each
    axis, the near plane's t the smaller of (plane - o_near) * imin and (plane - o_near) *
    imax, the far plane's the larger of (plane - o_far) * imin and ... * imax, times
    ``widen``. A superset of the boxes any ray of the packet enters (the module docstring)."""
    if not wide_bvh.typed_for_nodes(nodes, tmin, frustum):
        return None
    real = tmin

    def codegen(context, builder, signature, args):
        nodes_v, n_v, frustum_v, tmin_v, widen_v = args
        nodes_t, n_t, _, tmin_t, widen_t = signature.args
        ft = context.get_value_type(real)
        i64 = ir.IntType(64)
        vt, splat, row = wide_bvh.node_lanes(context, builder, nodes_t, nodes_v, n_t, n_v, real)

        def value(a, field):
            return builder.load(builder.gep(frustum_v, [ir.Constant(i64, a * FRUSTUM_AXIS + field)]))

        def smaller(x, y):
            return builder.select(builder.fcmp_ordered("<", y, x), y, x)

        def larger(x, y):
            return builder.select(builder.fcmp_ordered(">", y, x), y, x)

        t0 = splat(context.cast(builder, tmin_v, tmin_t, real))
        t1 = ir.Constant(vt, [math.inf] * WIDTH)
        w = splat(context.cast(builder, widen_v, widen_t, real))
        for a in range(3):
            negative = builder.fcmp_ordered(">", value(a, NEGATIVE), ir.Constant(ft, 0.0))
            near_row = builder.select(negative, ir.Constant(i64, 3 + a), ir.Constant(i64, a))
            far_row = builder.select(negative, ir.Constant(i64, a), ir.Constant(i64, 3 + a))
            i_min, i_max = splat(value(a, I_MIN)), splat(value(a, I_MAX))
            d = builder.fsub(row(near_row), splat(value(a, O_NEAR)))
            near = smaller(builder.fmul(d, i_min), builder.fmul(d, i_max))
            e = builder.fsub(row(far_row), splat(value(a, O_FAR)))
            far = builder.fmul(larger(builder.fmul(e, i_min), builder.fmul(e, i_max)), w)
            t0 = builder.select(builder.fcmp_ordered(">", near, t0), near, t0)
            t1 = builder.select(builder.fcmp_ordered("<", far, t1), far, t1)
        entered = builder.xor(builder.fcmp_ordered(">", t0, t1), ir.Constant(ir.VectorType(ir.IntType(1), WIDTH),
                                                                              [1] * WIDTH))
        return builder.zext(builder.bitcast(entered, ir.IntType(WIDTH)), i64)
    return types.int64(nodes, n, frustum, tmin, widen), codegen


@njit(cache=True, error_model="numpy", inline="always")
def frustum_of_packet(rays, count, frustum):
    """Fill ``frustum`` (box_frustum's) from the rays 0 <= i < count of ``rays`` (box_rays'
    rows); False where a packet has none: on some axis an inverse that is not finite (a
    direction's zero component) or inverses of both signs."""
    for a in range(3):
        o_min = o_max = rays[(OX + a) * PACKET]
        i_min = i_max = rays[(IX + a) * PACKET]
        for i in range(1, count):
            o = rays[(OX + a) * PACKET + i]
            v = rays[(IX + a) * PACKET + i]
            o_min = min(o_min, o)
            o_max = max(o_max, o)
            i_min = min(i_min, v)
            i_max = max(i_max, v)
        if not (math.isfinite(i_min) and math.isfinite(i_max) and (i_min > 0 or i_max < 0)):
            return False
        negative = i_max < 0
        frustum[a * FRUSTUM_AXIS + NEGATIVE] = 1 if negative else 0
        # inv > 0: near = (lo - o) * inv grows with lo - o, smallest at o_max; far at o_min.
        # inv < 0: near = (hi - o) * inv shrinks as hi - o grows, smallest at o_min.
        frustum[a * FRUSTUM_AXIS + O_NEAR] = o_min if negative else o_max
        frustum[a * FRUSTUM_AXIS + O_FAR] = o_max if negative else o_min
        frustum[a * FRUSTUM_AXIS + I_MIN] = i_min
        frustum[a * FRUSTUM_AXIS + I_MAX] = i_max
    return True


def _block_boxes(vertices, faces, nodes, at, first, count, boxes):
    """The boxes of a block's faces faces[first:first + count] into ``boxes`` (six rows of
    WIDTH values): from its corners at float ``at`` of ``nodes`` in a float32 tree
    (block_boxes), from its faces' vertices in a float64 one (block_boxes_gathered)."""
    return as_python(_typed_block_boxes, vertices, faces, nodes, at, first, count, boxes)


@overload(_block_boxes, inline="always")
def _typed_block_boxes(vertices, faces, nodes, at, first, count, boxes):
    if vertices.dtype == types.float32:
        return lambda vertices, faces, nodes, at, first, count, boxes: wide_bvh.block_boxes(
            nodes, at + BLOCK_HEADER, count, boxes)
    return lambda vertices, faces, nodes, at, first, count, boxes: wide_bvh.block_boxes_gathered(
        vertices, faces, first, count, boxes)


@njit(cache=True, error_model="numpy", inline="always")
def _frame(axes, frames, i):
    """Ray i's frame (ray_frame) from the packet's rows."""
    return ((axes[3 * i], axes[3 * i + 1], axes[3 * i + 2],
             frames[SX * PACKET + i], frames[SY * PACKET + i], frames[SZ * PACKET + i]),
            (frames[OKX * PACKET + i], frames[OKY * PACKET + i], frames[OKZ * PACKET + i]))


@njit(cache=True, error_model="numpy", inline="always")
def face_rays(vertices, faces, f, axes, frames, count, live, tmin, hits, rays, widen):
    """Face ``f`` (a mesh's) against the rays of ``live`` (a bit a ray, 0 <= r < count)
    that all have the frame axes ``axes`` = (kx, ky, kz): rtfgu.kernels.mesh.intersect_face
    lane by lane, the same operations in the same order, and each ray's nearest hit (``hits``
    = (t, best, kind, row)) and reach kept by mesh_closest's tie rule. The loop over the rays
    has no branch, so LLVM's loop vectoriser tests several rays an instruction. Returns the
    bits of the rays whose edge function rounded to zero: the scalar test, which recomputes
    it in double, decides those."""
    kx, ky, kz = axes
    t_best, best, kind, row = hits
    zero = lit(0, tmin)
    i0, i1, i2 = faces[f, 0], faces[f, 1], faces[f, 2]
    idx = faces[f, 3]
    a_x, a_y, a_z = vertices[i0, kx], vertices[i0, ky], vertices[i0, kz]
    b_x, b_y, b_z = vertices[i1, kx], vertices[i1, ky], vertices[i1, kz]
    c_x, c_y, c_z = vertices[i2, kx], vertices[i2, ky], vertices[i2, kz]
    redo = 0
    for r in range(count):
        Sx, Sy, Sz = frames[SX * PACKET + r], frames[SY * PACKET + r], frames[SZ * PACKET + r]
        okx, oky, okz = frames[OKX * PACKET + r], frames[OKY * PACKET + r], frames[OKZ * PACKET + r]
        Az = a_z - okz
        Bz = b_z - okz
        Cz = c_z - okz
        ax = (a_x - okx) - Sx * Az
        ay = (a_y - oky) - Sy * Az
        bx = (b_x - okx) - Sx * Bz
        by = (b_y - oky) - Sy * Bz
        cx = (c_x - okx) - Sx * Cz
        cy = (c_y - oky) - Sy * Cz
        U = cx * by - cy * bx
        V = ax * cy - ay * cx
        W = bx * ay - by * ax
        flat = (U == zero) | (V == zero) | (W == zero)
        outside = ((U < zero) | (V < zero) | (W < zero)) & ((U > zero) | (V > zero) | (W > zero))
        det = U + V + W
        T = U * (Sz * Az) + V * (Sz * Bz) + W * (Sz * Cz)
        t = T / det
        tmax = t_best[r]
        on = ((live >> r) & 1) == 1
        # intersect_face's t in [tmin, limit) and mesh_closest's keep, as one rule: t < tmax,
        # or t == tmax for a face earlier in Scene.shapes.
        keep = on & (flat ^ True) & (outside ^ True) & (det != zero) & (t >= tmin) \
            & ((t < tmax) | ((t == tmax) & (idx < best[r])))
        t_best[r] = t if keep else tmax
        best[r] = idx if keep else best[r]
        kind[r] = MESH if keep else kind[r]
        row[r] = f if keep else row[r]
        rays[REACH * PACKET + r] = t * widen if keep else rays[REACH * PACKET + r]
        redo |= (1 << r) if on & flat else 0
    return redo


@njit(cache=True, error_model="numpy", inline="always")
def _alone(each, f, scene, packet, tmin, hits, formula, widen):
    """Row ``f`` of ``faces`` tested by each ray of the bits ``each`` alone (_leaf_closest),
    its hit and reach kept: ``scene`` = (vertices, faces, spheres, instances), ``packet`` =
    (axes, frames, rays, directions) as mesh_closest_packet has them."""
    vertices, faces, spheres, instances = scene
    axes, frames, rays, directions = packet
    t, best, kind, row = hits
    while each != 0:
        i = trailing_zeros(each)
        each &= each - 1
        origin = (rays[OX * PACKET + i], rays[OY * PACKET + i], rays[OZ * PACKET + i])
        direction = (directions[3 * i], directions[3 * i + 1], directions[3 * i + 2])
        hit = _leaf_closest(vertices, faces, spheres, instances, f, 1, _frame(axes, frames, i), origin, direction,
                            tmin, (t[i], best[i], kind[i], row[i]), formula)
        t[i], best[i], kind[i], row[i] = hit
        rays[REACH * PACKET + i] = hit[0] * widen


_boxes_of = wide_bvh.on_the_stack(6 * WIDTH, "A block's faces' boxes: rows lo.x, lo.y, lo.z, hi.x, hi.y, hi.z.")


@njit(**NO_REFCOUNT)
def mesh_closest_packet(vertices, faces, nodes, links, spheres, packet, hits, formula, root=0,
                        instances=(None, None, None)):
    """mesh_closest for the rays 0 <= r < count (count <= PACKET) of ``packet`` = (origins,
    directions, count, tmin) in one traversal of the wide tree ``nodes``, in [tmin, ...): ray
    r starts at origins[3r:3r + 3] in direction directions[3r:3r + 3] (flat arrays, or
    pointers into a caller's frame: render_tile's packets); with ``hits`` = (t, best, kind,
    row), its nearest hit so far is (t[r], best[r], kind[r], row[r]) on entry (mesh_closest's
    ``hit``) and its nearest hit on return."""
    origins, directions, count, tmin = packet
    t, best, kind, row = hits
    if count < 1 or count > PACKET:
        raise ValueError("mesh_closest_packet: a packet holds 1 to PACKET rays")
    widen = lit_per_precision(WIDEN32, WIDEN64, tmin)
    inf = lit(math.inf, tmin)
    rays = _rays_of(tmin)
    axes = _per_ray(np.int64)
    frames = _frames_of(tmin)
    for i in range(count):
        origin = (origins[3 * i], origins[3 * i + 1], origins[3 * i + 2])
        direction = (directions[3 * i], directions[3 * i + 1], directions[3 * i + 2])
        (kx, ky, kz, sx, sy, sz), (ox, oy, oz) = ray_frame(origin, direction)
        inv = _inverse(direction)[0]
        for a in range(3):
            rays[(OX + a) * PACKET + i] = origin[a]
            rays[(IX + a) * PACKET + i] = inv[a]
        rays[REACH * PACKET + i] = t[i] * widen
        axes[3 * i], axes[3 * i + 1], axes[3 * i + 2] = kx, ky, kz
        frames[SX * PACKET + i], frames[SY * PACKET + i], frames[SZ * PACKET + i] = sx, sy, sz
        frames[OKX * PACKET + i], frames[OKY * PACKET + i], frames[OKZ * PACKET + i] = ox, oy, oz
    frustum = _frustum_of(tmin)
    cull = frustum_of_packet(rays, count, frustum)
    # Whether every ray has the first one's frame axes: its leaves' faces then go against
    # all the rays at once (face_rays).
    shared = True
    for i in range(1, count):
        for a in range(3):
            shared = shared and axes[3 * i + a] == axes[a]
    kxyz = (axes[0], axes[1], axes[2])
    lanes = wide_bvh.lanes_of(tmin)
    boxes = _boxes_of(tmin)
    codes = wide_bvh.stack_of(np.int32)
    masks = wide_bvh.stack_of(np.int64)
    nears = wide_bvh.stack_of(tmin)
    codes[0] = root
    masks[0] = (np.int64(1) << count) - 1
    nears[0] = -inf
    sp = 1
    while sp > 0:
        sp -= 1
        code = codes[sp]
        near = nears[sp]
        live, n_live = rays_within(rays, masks[sp], near)
        if n_live == 0:
            continue
        if code < 0 and wide_bvh.is_block(code) and shared and n_live > SINGLE:
            # A block (a float32 tree's node of single triangles) entered by several rays: each
            # face's box, made from its corners, against the rays, and the face against those
            # that enter it, as the node it replaces had its faces' boxes.
            start, size = wide_bvh.leaf_span(code, links)
            _block_boxes(vertices, faces, nodes, wide_bvh.block_at(code), start, size, boxes)
            for j in range(size):
                entered, _ = box_rays_of(boxes, j, rays, live, tmin, widen)
                if entered == 0:
                    continue
                f = start + j
                each = face_rays(vertices, faces, f, kxyz, frames, count, entered, tmin, hits, rays, widen)
                _alone(each, f, (vertices, faces, spheres, instances), (axes, frames, rays, directions), tmin, hits,
                       formula, widen)     # a face whose edge rounded to zero
            continue
        if code < 0 and wide_bvh.is_block(code):
            # A block entered by few rays, or by rays of other frame axes: its faces tested at
            # once for each ray, as a single ray does (block_closest).
            start, size = wide_bvh.leaf_span(code, links)
            while live != 0:
                i = trailing_zeros(live)
                live &= live - 1
                hit = block_closest(vertices, faces, nodes, wide_bvh.block_at(code), start, size,
                                    _frame(axes, frames, i), tmin, (t[i], best[i], kind[i], row[i]), lanes)
                t[i], best[i], kind[i], row[i] = hit
                rays[REACH * PACKET + i] = hit[0] * widen
            continue
        if code < 0 and shared and n_live > SINGLE:
            start, size = wide_bvh.leaf_span(code, links)
            for f in range(start, start + size):
                mesh_face = faces[f, 0] != SPHERE_ROW and faces[f, 0] != INSTANCE_ROW
                each = live if not mesh_face else face_rays(vertices, faces, f, kxyz, frames, count, live, tmin,
                                                            hits, rays, widen)
                # a sphere or an instance, or a face whose edge rounded to zero
                _alone(each, f, (vertices, faces, spheres, instances), (axes, frames, rays, directions), tmin, hits,
                       formula, widen)
            continue
        if n_live <= SINGLE or code < 0:
            while live != 0:
                i = trailing_zeros(live)
                live &= live - 1
                origin = (rays[OX * PACKET + i], rays[OY * PACKET + i], rays[OZ * PACKET + i])
                direction = (directions[3 * i], directions[3 * i + 1], directions[3 * i + 2])
                if code >= 0:
                    # The root as an int64, as the generated scan_ of a mesh kind passes it: one
                    # compiled mesh_closest for both.
                    hit = mesh_closest(vertices, faces, nodes, links, spheres, origin, direction, tmin,
                                       (t[i], best[i], kind[i], row[i]), formula, np.int64(code), instances)
                else:
                    start, size = wide_bvh.leaf_span(code, links)
                    hit = _leaf_closest(vertices, faces, spheres, instances, start, size, _frame(axes, frames, i),
                                        origin, direction,
                                        tmin, (t[i], best[i], kind[i], row[i]), formula)
                t[i], best[i], kind[i], row[i] = hit
                rays[REACH * PACKET + i] = hit[0] * widen
            continue
        base = sp
        candidates = box_frustum(nodes, code, frustum, tmin, widen) if cull else ALL_COLUMNS
        for j in range(WIDTH):
            child = links[code, CODE_ROW, j]
            if child == 0:      # an empty column: the columns after it are empty too
                break
            if not candidates >> j & 1:
                continue
            entered, tj = box_rays(nodes, code, j, rays, live, tmin, widen)
            if entered != 0:
                k = sp
                while k > base and nears[k - 1] < tj:
                    codes[k] = codes[k - 1]
                    masks[k] = masks[k - 1]
                    nears[k] = nears[k - 1]
                    k -= 1
                codes[k] = child
                masks[k] = entered
                nears[k] = tj
                sp += 1
