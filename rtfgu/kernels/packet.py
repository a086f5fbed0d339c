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
- at an inner node, box_rays tests each child's box against the rays: a child is pushed with
  the mask of the rays that enter it and their nearest entry, the children sorted by it, the
  nearest on top;
- at a leaf, each ray tests its primitives (_leaf_closest).

A ray tests a box only where it entered its parent's box within its own nearest hit so far,
with the very operations of box8 (so it enters the same boxes), and a primitive only where it
entered its box: it finds the face, t and tie of mesh_closest alone (tests/test_packet.py
compares every ray).
"""
from __future__ import annotations

import math

import numpy as np
from llvmlite import ir
from numba import njit, types
from numba.core import cgutils
from numba.cpython.unsafe.numbers import trailing_zeros
from numba.extending import intrinsic

from ..accelerators.wide_bvh import CODE_ROW, ROWS, WIDTH
from . import wide_bvh
from .float3 import lit, lit_per_precision
from .mesh import NO_REFCOUNT, WIDEN32, WIDEN64, _inverse, _leaf_closest, mesh_closest, ray_frame

# Rays of a packet: its masks are bits of an int64, its lanes one vector.
PACKET = 16
# An entry left with at most this many rays is finished by each ray alone (docs/bvh.md,
# "Packets": measured with benchmarks/meshes.py).
SINGLE = 2

# The packet's rays as box_rays reads them: PACKET lanes of each of these rows.
OX, OY, OZ, IX, IY, IZ, REACH = range(7)
RAY_ROWS = 7

_rays_of = wide_bvh.on_the_stack(RAY_ROWS * PACKET, "A packet's rays, RAY_ROWS rows of PACKET lanes.")
_per_ray = wide_bvh.on_the_stack(3 * PACKET, "Three values per ray of a packet.")
lanes_of = wide_bvh.on_the_stack(PACKET, "A value per ray of a packet.")


@njit(cache=True, error_model="numpy", inline="always")
def nearer_hit(hit, other):
    """The nearer of two hits (t, scene index, kind, row) by the tie rule: the smaller t, of
    equal ts the smaller index (as mesh_closest keeps a face); ``other`` a miss (index -1)
    never wins."""
    if other[1] >= 0 and (other[0] < hit[0] or (other[0] == hit[0] and other[1] < hit[1])):
        return other
    return hit


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
    if not (isinstance(nodes, types.Array) and nodes.ndim == 3 and nodes.dtype == types.float32):
        return None
    if not isinstance(tmin, types.Float) or not isinstance(rays, types.CPointer):
        return None
    real = tmin

    def codegen(context, builder, signature, args):
        nodes_v, n_v, j_v, rays_v, live_v, tmin_v, widen_v = args
        nodes_t, n_t, j_t, _, live_t, tmin_t, widen_t = signature.args
        ft = context.get_value_type(real)
        vt = ir.VectorType(ft, PACKET)
        i64 = ir.IntType(64)
        i32 = ir.IntType(32)
        array = context.make_array(nodes_t)(context, builder, nodes_v)
        n64 = context.cast(builder, n_v, n_t, types.int64)
        j64 = context.cast(builder, j_v, j_t, types.int64)
        base = builder.gep(array.data, [builder.add(builder.mul(n64, ir.Constant(i64, ROWS * WIDTH)), j64)])

        def splat(x):
            v = builder.insert_element(ir.Constant(vt, ir.Undefined), x, ir.Constant(i32, 0))
            return builder.shuffle_vector(v, ir.Constant(vt, ir.Undefined),
                                          ir.Constant(ir.VectorType(i32, PACKET), [0] * PACKET))

        def plane(row):
            x = builder.load(builder.gep(base, [ir.Constant(i64, row * WIDTH)]))
            return splat(x if real.bitwidth == 32 else builder.fpext(x, ft))

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
            lo, hi = plane(a), plane(3 + a)
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
    return types.Tuple((types.int64, real))(nodes, n, j, rays, live, tmin, widen), codegen


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
    shear = _per_ray(tmin)
    o_k = _per_ray(tmin)
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
        shear[3 * i], shear[3 * i + 1], shear[3 * i + 2] = sx, sy, sz
        o_k[3 * i], o_k[3 * i + 1], o_k[3 * i + 2] = ox, oy, oz
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
        if n_live <= SINGLE or code < 0:
            while live != 0:
                i = trailing_zeros(live)
                live &= live - 1
                origin = (rays[OX * PACKET + i], rays[OY * PACKET + i], rays[OZ * PACKET + i])
                direction = (directions[3 * i], directions[3 * i + 1], directions[3 * i + 2])
                if code >= 0:
                    hit = mesh_closest(vertices, faces, nodes, links, spheres, origin, direction, tmin,
                                       (t[i], best[i], kind[i], row[i]), formula, code, instances)
                else:
                    start, size = wide_bvh.leaf_span(code)
                    frame = ((axes[3 * i], axes[3 * i + 1], axes[3 * i + 2],
                              shear[3 * i], shear[3 * i + 1], shear[3 * i + 2]),
                             (o_k[3 * i], o_k[3 * i + 1], o_k[3 * i + 2]))
                    hit = _leaf_closest(vertices, faces, spheres, instances, start, size, frame, origin, direction,
                                        tmin, (t[i], best[i], kind[i], row[i]), formula)
                t[i], best[i], kind[i], row[i] = hit
                rays[REACH * PACKET + i] = hit[0] * widen
            continue
        base = sp
        for j in range(WIDTH):
            child = links[code, CODE_ROW, j]
            if child == 0:      # an empty column: the columns after it are empty too
                break
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
