# release: solves a03 a08
"""Triangle meshes on the numba path: the watertight test per face and the BVH traversal
(rtfgu.accelerators.flat_bvh's node table) that finds the nearest face.

The mesh arrives as (rtfgu.layout.compile_scene):

    vertices  (V, 3)  float    every mesh's vertices, once each
    faces     (F, 4)  int32    [i0, i1, i2, scene index], in the BVH's leaf order
    normals   (V, 3)  float    vertex normals (zero for a flat mesh's vertices), or None
    nodes     (N, 8)  float32  the BVH (flat_bvh), links its int32 view
    spheres   the sphere table: a row [SPHERE_ROW, sphere row, 0, scene index] of faces is
              that sphere, tested by the sphere formula of the render (``formula``: 1 robust)

A face is hit where rtfgu.robust.intersect_triangle_watertight hits it (Woop, Benthin and
Wald 2013): two faces that share an edge compute its edge function from the same two
vertices, so a ray through the edge hits one of them, in float32 too. The ray's shear
(the permutation kx, ky, kz and Sx, Sy, Sz) and the origin on its axes are computed once per
ray (ray_frame), not once per face.
Its normal and (u, v) are those of SmoothMeshTriangle / FlatMeshTriangle (rtfgu.shapes.mesh).

The traversal (rtfgu.accelerators.bvh.BVH.intersect): the nearer child first, a stack of the
farther ones with the distance at which the ray enters them, so that a node entered beyond
the nearest hit so far is dropped when it is popped. The stack lives in the caller's frame
(``_stack_pointer``, an array over it made where it is used: numba returns no such array): the render kernel allocates nothing per ray.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit, types
from numba.extending import overload

from ..accelerators.flat_bvh import MAX_DEPTH
from ..layout import INSTANCE_ROW, MESH, SPHERE, SPHERE_CENTER, SPHERE_RADIUS, SPHERE_ROW
from ..registry import SHAPE_IDS
from .instance import FACE_SHIFT

INSTANCE = SHAPE_IDS["instance"]
from .dispatch_support import as_python
from .intersect import intersect_sphere, intersect_sphere_robust
from .robust import _pick, ray_shear
from .next_float import next_up
from .float3 import add, cross, dot, lit, lit_per_precision, normalize, scale, sub
from . import wide_bvh
from ..accelerators.wide_bvh import BLOCK_HEADER, WIDTH

# 1 + 2 gamma_3 (PBRT-v4 section 6.1.2): the far end of a slab interval is widened by it, so
# that rounding never drops a box whose face the triangle test would hit (BBox.hit).
WIDEN64 = 1.0 + 2.0 * (3 * 2.0 ** -53) / (1 - 3 * 2.0 ** -53)
WIDEN32 = 1.0 + 2.0 * (3 * 2.0 ** -24) / (1 - 3 * 2.0 ** -24)


# A traversal's stack of MAX_DEPTH entries, in the caller's frame (rtfgu.kernels.wide_bvh.on_the_stack).
_stack_pointer = wide_bvh.on_the_stack(MAX_DEPTH, "The binary traversal's stack: MAX_DEPTH elements.")


@njit(cache=True, error_model="numpy", inline="always")
def ray_frame(origin, direction):
    """What every face test of a ray shares: its shear (ray_shear) and its origin's
    coordinates on the shear's axes kx, ky, kz (so a face reads only the vertex coordinates
    it uses: vertices[i, k] - origin[k] is A[k] of the watertight test, the same number)."""
    shear = ray_shear(direction)
    return shear, (_pick(origin, shear[0]), _pick(origin, shear[1]), _pick(origin, shear[2]))


@njit(cache=True, error_model="numpy", inline="always")
def intersect_face(vertices, faces, f, frame, tmin, tmax):
    """t of face ``f`` in [tmin, tmax), else inf: rtfgu.robust.intersect_triangle_watertight
    with the ray's ``frame`` (ray_frame). A mesh has no zero-area face (Mesh refuses one)."""
    (kx, ky, kz, Sx, Sy, Sz), (okx, oky, okz) = frame
    zero = lit(0, tmin)
    i0, i1, i2 = faces[f, 0], faces[f, 1], faces[f, 2]
    Az = vertices[i0, kz] - okz
    Bz = vertices[i1, kz] - okz
    Cz = vertices[i2, kz] - okz
    ax = (vertices[i0, kx] - okx) - Sx * Az
    ay = (vertices[i0, ky] - oky) - Sy * Az
    bx = (vertices[i1, kx] - okx) - Sx * Bz
    by = (vertices[i1, ky] - oky) - Sy * Bz
    cx = (vertices[i2, kx] - okx) - Sx * Cz
    cy = (vertices[i2, ky] - oky) - Sy * Cz
    U = cx * by - cy * bx
    V = ax * cy - ay * cx
    W = bx * ay - by * ax
    if U == zero or V == zero or W == zero:
        # Woop et al. section 3: an edge function that rounds to zero is recomputed in
        # double (a no-op in float64).
        U = lit(np.float64(cx) * np.float64(by) - np.float64(cy) * np.float64(bx), tmin)
        V = lit(np.float64(ax) * np.float64(cy) - np.float64(ay) * np.float64(cx), tmin)
        W = lit(np.float64(bx) * np.float64(ay) - np.float64(by) * np.float64(ax), tmin)
    if (U < zero or V < zero or W < zero) and (U > zero or V > zero or W > zero):
        return lit(math.inf, tmin)
    det = U + V + W
    if det == zero:
        return lit(math.inf, tmin)
    T = U * (Sz * Az) + V * (Sz * Bz) + W * (Sz * Cz)
    t = T / det
    if t >= tmin and t < tmax:
        return t
    return lit(math.inf, tmin)


def sphere_prim(spheres, row, origin, direction, tmin, tmax, formula):
    """t of sphere ``row`` in [tmin, tmax], else inf; inf when ``spheres`` is None (typed by
    the overload below)."""
    return as_python(_typed_sphere_prim, spheres, row, origin, direction, tmin, tmax, formula)


@overload(sphere_prim, inline="always")
def _typed_sphere_prim(spheres, row, origin, direction, tmin, tmax, formula):
    if isinstance(spheres, types.NoneType):
        return lambda spheres, row, origin, direction, tmin, tmax, formula: lit(math.inf, tmin)

    def test(spheres, row, origin, direction, tmin, tmax, formula):
        center = (spheres[row, SPHERE_CENTER], spheres[row, SPHERE_CENTER + 1], spheres[row, SPHERE_CENTER + 2])
        if formula == 1:
            return intersect_sphere_robust(origin, direction, tmin, tmax, center, spheres[row, SPHERE_RADIUS])
        return intersect_sphere(origin, direction, tmin, tmax, center, spheres[row, SPHERE_RADIUS])
    return test


def instance_prim(instances, row, origin, direction, tmin, tmax, formula, best):
    """(t, place, face) of instance ``row`` for the tree that holds the instances (rows
    INSTANCE_ROW), as the instance's loop has them (rtfgu.kernels.dispatch, instanced_t;
    ``best``: the best index so far less the instance's first): ``instances`` is the
    instance kind's (table, index, objects); (inf, 0, -1) where the scene has none (its
    table None). A tree that does not hold the instances has no such row, so this is not
    called there (the instances' own loop, over their index, tests them)."""
    return as_python(_typed_instance_prim, instances, row, origin, direction, tmin, tmax, formula, best)


@overload(instance_prim, inline="always")
def _typed_instance_prim(instances, row, origin, direction, tmin, tmax, formula, best):
    if isinstance(instances.types[0], types.NoneType):
        return lambda instances, row, origin, direction, tmin, tmax, formula, best: (lit(math.inf, tmin), 0, -1)
    from .dispatch import instance_t    # generated from the registry: the instance's object switch

    def test(instances, row, origin, direction, tmin, tmax, formula, best):
        return instance_t(instances[0], instances[2], row, origin, direction, tmin, tmax, formula, best)
    return test


@njit(cache=True, error_model="numpy", inline="always")
def box_entry(nodes, n, origin, inv, tmin, tmax):
    """BBox.hit for node ``n``: the t at which the ray enters its box within [tmin, tmax],
    or inf. ``inv`` = (1 / direction (inf for a zero component), the column offsets of each
    axis's near and far plane: 0 and 4, or 4 and 0 where the component is negative, so the
    slab's near and far ends need no swap). A NaN from 0 * inf (the origin on a plane of a
    slab the ray runs in) fails every comparison, so it narrows nothing."""
    widen = lit_per_precision(WIDEN32, WIDEN64, tmin)
    inv, (near_at, far_at) = inv
    t0 = tmin
    t1 = tmax
    for a in range(3):
        near = (lit(nodes[n, a + near_at[a]], tmin) - origin[a]) * inv[a]
        far = (lit(nodes[n, a + far_at[a]], tmin) - origin[a]) * inv[a] * widen
        if near > t0:
            t0 = near
        if far < t1:
            t1 = far
    if t0 > t1:
        return lit(math.inf, tmin)
    return t0


@njit(cache=True, error_model="numpy", inline="always")
def _inverse(direction):
    """box_entry's ``inv``: 1 / direction and each axis's near and far plane columns."""
    one = lit(1, direction[0])
    inv = (one / direction[0], one / direction[1], one / direction[2])
    zero = lit(0, one)
    near_at = (4 if inv[0] < zero else 0, 4 if inv[1] < zero else 0, 4 if inv[2] < zero else 0)
    return inv, (near_at, (4 - near_at[0], 4 - near_at[1], 4 - near_at[2]))


@njit(cache=True, error_model="numpy", inline="always")
def _leaf_closest(vertices, faces, spheres, instances, first, count, frame, origin, direction, tmin, state, formula):
    """The nearest of the leaf's rows faces[first:first + count] and the best so far,
    ``state`` = (t, scene index, kind, row), by the tie rule (mesh_closest)."""
    tmax, best, best_kind, best_row = state
    for f in range(first, first + count):
        idx = faces[f, 3]
        limit = tmax if idx > best else next_up(tmax)
        if faces[f, 0] == SPHERE_ROW:
            t = sphere_prim(spheres, faces[f, 1], origin, direction, tmin, limit, formula)
            k, r = SPHERE, faces[f, 1]
        elif faces[f, 0] == INSTANCE_ROW:
            # An instance of a Mesh: its face's place and row (FACE_SHIFT).
            t, place, face = instance_prim(instances, faces[f, 1], origin, direction, tmin, limit, formula,
                                           best - idx)
            k, r = INSTANCE, faces[f, 1] + (face << FACE_SHIFT) if face >= 0 else faces[f, 1]
            idx += place
        else:
            t = intersect_face(vertices, faces, f, frame, tmin, limit)
            k, r = MESH, f
        if t < tmax or (t == tmax and idx < best):
            tmax = t
            best = idx
            best_kind = k
            best_row = r
    return tmax, best, best_kind, best_row


@njit(cache=True, error_model="numpy", inline="always")
def _leaf_any(vertices, faces, spheres, instances, first, count, frame, origin, direction, tmin, tmax, formula):
    """Whether a row of faces[first:first + count] is hit in [tmin, tmax) (mesh_any)."""
    for f in range(first, first + count):
        if faces[f, 0] == SPHERE_ROW:
            if sphere_prim(spheres, faces[f, 1], origin, direction, tmin, tmax, formula) < tmax:
                return True
        elif faces[f, 0] == INSTANCE_ROW:
            if instance_prim(instances, faces[f, 1], origin, direction, tmin, tmax, formula, -1)[0] < tmax:
                return True
        elif intersect_face(vertices, faces, f, frame, tmin, tmax) < tmax:
            return True
    return False


def _binary_closest(vertices, faces, nodes, links, spheres, origin, direction, tmin, bound, formula, root, instances):
    """mesh_closest on the binary table (N, 8): the nearer child first, the farther on the stack.
    ``bound``: the best hit so far (mesh_closest's ``hit``)."""
    state = bound
    inf = lit(math.inf, tmin)
    widen = lit_per_precision(WIDEN32, WIDEN64, tmin)
    frame = ray_frame(origin, direction)
    inv = _inverse(direction)
    node_stack = _stack_pointer(np.int32)
    entry_stack = _stack_pointer(tmin)
    sp = 0
    node = root
    if box_entry(nodes, root, origin, inv, tmin, state[0] * widen) == inf:
        return bound
    while True:
        count = links[node, 7]
        if count > 0:
            state = _leaf_closest(vertices, faces, spheres, instances, links[node, 3], count, frame, origin,
                                  direction, tmin, state, formula)
            node = -1
        else:
            left = links[node, 3]
            t_left = box_entry(nodes, left, origin, inv, tmin, state[0] * widen)
            t_right = box_entry(nodes, left + 1, origin, inv, tmin, state[0] * widen)
            if t_left <= t_right:
                near, far, t_far = left, left + 1, t_right
                node = near if t_left != inf else -1
            else:
                near, far, t_far = left + 1, left, t_left
                node = near
            if t_far != inf:
                if node < 0:
                    node = far
                else:
                    node_stack[sp] = far
                    entry_stack[sp] = t_far
                    sp += 1
        while node < 0 and sp > 0:
            sp -= 1
            if entry_stack[sp] <= state[0] * widen:
                node = node_stack[sp]
        if node < 0:
            break
    return state


@njit(cache=True, error_model="numpy", inline="always")
def _wide_start(origin, direction, tmin):
    """What a wide traversal sets up once per ray: the faces' ray frame, 1 / direction, the
    slab's widening, its stack of codes and of entry ts, and box8's lanes (allocas in the frame
    of the function this is inlined into)."""
    return (ray_frame(origin, direction), _inverse(direction)[0], lit_per_precision(WIDEN32, WIDEN64, tmin),
            wide_bvh.stack_of(np.int32), wide_bvh.stack_of(tmin), wide_bvh.lanes_of(tmin))


def block_closest(vertices, faces, nodes, at, first, count, frame, tmin, state, lanes):
    """The nearest of a block's faces faces[first:first + count] and the best so far
    ``state``, by the tie rule (mesh_closest); ``lanes``: WIDTH values of tmin's type for the
    test's ts. In float32 the block's corners are at float ``at`` of ``nodes``
    (rtfgu.accelerators.wide_bvh.with_blocks; block_test), in float64 they are gathered
    through ``faces`` (block_test_gathered)."""
    return as_python(_typed_block_closest, vertices, faces, nodes, at, first, count, frame, tmin, state, lanes)


@overload(block_closest, inline="always")
def _typed_block_closest(vertices, faces, nodes, at, first, count, frame, tmin, state, lanes):
    def vector(vertices, faces, nodes, at, first, count, frame, tmin, state, lanes):
        tmax, best, best_kind, best_row = state
        # Every lane hit in [tmin, the float above the best t), then the tie rule lane by lane:
        # the lexicographic least (t, scene index), whatever the lanes' order.
        mask = _block_lanes(vertices, faces, nodes, at, first, count, frame, tmin, next_up(tmax), lanes)
        zeroed = mask >> WIDTH
        mask = (mask | zeroed) & ((1 << WIDTH) - 1)
        for j in range(WIDTH):
            if mask >> j & 1:
                f = first + j
                idx = faces[f, 3]
                t = lanes[j]
                if zeroed >> j & 1:
                    t = intersect_face(vertices, faces, f, frame, tmin, tmax if idx > best else next_up(tmax))
                if t < tmax or (t == tmax and idx < best):
                    tmax, best, best_kind, best_row = t, idx, MESH, f
        return tmax, best, best_kind, best_row
    return vector


def _block_lanes(vertices, faces, nodes, at, first, count, frame, tmin, limit, lanes):
    """The block's vector test in tmin's precision: its copied corners (float32) or its
    corners gathered (float64)."""
    return as_python(_typed_block_lanes, vertices, faces, nodes, at, first, count, frame, tmin, limit, lanes)


@overload(_block_lanes, inline="always")
def _typed_block_lanes(vertices, faces, nodes, at, first, count, frame, tmin, limit, lanes):
    if tmin == types.float32:
        return lambda vertices, faces, nodes, at, first, count, frame, tmin, limit, lanes: wide_bvh.block_test(
            nodes, at + BLOCK_HEADER, count, frame, tmin, limit, lanes)
    return lambda vertices, faces, nodes, at, first, count, frame, tmin, limit, lanes: wide_bvh.block_test_gathered(
        vertices, faces, first, count, frame, tmin, limit, lanes)


@njit(cache=True, error_model="numpy", inline="always")
def block_any(vertices, faces, nodes, at, first, count, frame, tmin, tmax, lanes):
    """Whether a face of a block (block_closest's arguments) is hit in [tmin, tmax)
    (mesh_any): its vector test, and the scalar test for a lane whose edge function rounded
    to zero."""
    mask = _block_lanes(vertices, faces, nodes, at, first, count, frame, tmin, tmax, lanes)
    if mask & ((1 << WIDTH) - 1):
        return True
    zeroed = mask >> WIDTH
    for j in range(WIDTH):
        if zeroed >> j & 1 and intersect_face(vertices, faces, first + j, frame, tmin, tmax) < tmax:
            return True
    return False


def _wide_closest(vertices, faces, nodes, links, spheres, origin, direction, tmin, bound, formula, root, instances):
    """mesh_closest on the wide table (N, ROWS, WIDTH): rtfgu.kernels.wide_bvh's box8 and stack.
    ``bound``: the best hit so far (mesh_closest's ``hit``)."""
    state = bound
    frame, inv, widen, stack, entry_stack, entry = _wide_start(origin, direction, tmin)
    sp = 0
    code = root
    while True:
        if code >= 0:
            sp = wide_bvh.enter_node(nodes, links, code, origin, inv, tmin, state[0] * widen, widen, entry, stack,
                                     entry_stack, sp)
        else:
            first, count = wide_bvh.leaf_span(code, links)
            if wide_bvh.is_block(code):
                state = block_closest(vertices, faces, nodes, wide_bvh.block_at(code), first, count, frame, tmin,
                                      state, entry)
            else:
                state = _leaf_closest(vertices, faces, spheres, instances, first, count, frame, origin, direction,
                                      tmin, state, formula)
        code, found, sp = wide_bvh.pop_within(stack, entry_stack, sp, state[0] * widen)
        if not found:
            break
    return state


def _by_tree(binary, wide):
    """A traversal that runs ``wide`` on a wide table ((N, ROWS, WIDTH) nodes) and ``binary`` on
    a binary one ((N, 8)): numba picks one by the nodes' dimensions when it compiles the
    caller, and inlines it there."""
    def traverse(vertices, faces, nodes, links, spheres, origin, direction, tmin, bound, formula, root, instances):
        return (wide if nodes.ndim == 3 else binary)(
            vertices, faces, nodes, links, spheres, origin, direction, tmin, bound, formula, root, instances)

    @overload(traverse, inline="always")
    def typed(vertices, faces, nodes, links, spheres, origin, direction, tmin, bound, formula, root, instances):
        return wide if nodes.ndim == 3 else binary
    return traverse


_traverse_closest = _by_tree(_binary_closest, _wide_closest)


# mesh_closest and mesh_any are called, not inlined: compiled once per precision and tree kind
# and cached, they are shared by every render kernel (each scene's kinds compile a kernel of
# their own). ``nodes`` is the binary table (flat_bvh, (N, 8)) or the wide one (wide_bvh,
# (N, ROWS, WIDTH)): its number of dimensions picks the traversal when numba compiles it.
# NO_REFCOUNT: they allocate nothing (their stacks are allocas) and keep no array they are
# given, so they are compiled without numba's reference counting, which otherwise
# increments and decrements each array argument atomically at every call, once a ray, from
# whichever caller (docs/bvh.md, "Where a single ray's time goes").
NO_REFCOUNT = dict(cache=True, error_model="numpy", _nrt=False)


@njit(**NO_REFCOUNT)
def mesh_closest(vertices, faces, nodes, links, spheres, origin, direction, tmin, hit, formula, root=0,
                 instances=(None, None, None)):
    """The nearest face, sphere or instance hit, given the nearest hit so far ``hit`` = (t,
    scene index, kind, row): of equal ts the one earlier in Scene.shapes wins (an earlier
    one is tested up to the next float above the best t). A face is (MESH, its row in
    faces), a sphere (SPHERE, its row in the sphere table), an instance (INSTANCE, its row:
    instance_prim). ``root``: the tree's first node (the scene's, 0; an instanced mesh's,
    whose rows' indices are places in the mesh).

    A box is dropped where the ray enters it beyond the best t times 1 + 2 gamma_3, not
    beyond the best t: the entry's rounding (up to gamma_3) must not drop a box whose face
    ties the best t and is earlier in Scene.shapes, so that the tie rule holds on every tree
    (tests/test_wide_bvh.py: the nearest face of a loop over all faces)."""
    return _traverse_closest(vertices, faces, nodes, links, spheres, origin, direction, tmin, hit, formula, root,
                             instances)


# mesh_closest again, for the tree of a mesh an instance holds: the scene's tree may hold that
# instance (rtfgu.layout: bvh_instances), and numba compiles no function that calls itself.
object_mesh_closest = njit(**NO_REFCOUNT)(getattr(mesh_closest, "py_func", mesh_closest))


def _binary_any(vertices, faces, nodes, links, spheres, origin, direction, tmin, bound, formula, root, instances):
    """mesh_any on the binary table: both children entered, one kept on the stack. ``bound``:
    mesh_any's ``tmax``."""
    tmax = bound
    inf = lit(math.inf, tmin)
    frame = ray_frame(origin, direction)
    inv = _inverse(direction)
    node_stack = _stack_pointer(np.int32)
    sp = 0
    node = root if box_entry(nodes, root, origin, inv, tmin, tmax) != inf else -1
    while node >= 0:
        count = links[node, 7]
        if count > 0:
            if _leaf_any(vertices, faces, spheres, instances, links[node, 3], count, frame, origin, direction, tmin,
                         tmax, formula):
                return True
            node = -1
        else:
            left = links[node, 3]
            hit_left = box_entry(nodes, left, origin, inv, tmin, tmax) != inf
            hit_right = box_entry(nodes, left + 1, origin, inv, tmin, tmax) != inf
            if hit_left and hit_right:
                node_stack[sp] = left + 1
                sp += 1
                node = left
            elif hit_left:
                node = left
            elif hit_right:
                node = left + 1
            else:
                node = -1
        if node < 0 and sp > 0:
            sp -= 1
            node = node_stack[sp]
    return False


def _wide_any(vertices, faces, nodes, links, spheres, origin, direction, tmin, bound, formula, root, instances):
    """mesh_any on the wide table: every child the ray enters on the stack, in any order.
    ``bound``: mesh_any's ``tmax``."""
    frame, inv, widen, stack, _, entry = _wide_start(origin, direction, tmin)
    sp = 0
    code = root
    while True:
        if code >= 0:
            sp = wide_bvh.enter_node_any(nodes, links, code, origin, inv, tmin, bound, widen, entry, stack, sp)
        else:
            first, count = wide_bvh.leaf_span(code, links)
            if wide_bvh.is_block(code):
                if block_any(vertices, faces, nodes, wide_bvh.block_at(code), first, count, frame, tmin, bound, entry):
                    return True
            elif _leaf_any(vertices, faces, spheres, instances, first, count, frame, origin, direction, tmin, bound,
                           formula):
                return True
        if sp == 0:
            return False
        sp -= 1
        code = stack[sp]


_traverse_any = _by_tree(_binary_any, _wide_any)


@njit(**NO_REFCOUNT)
def mesh_any(vertices, faces, nodes, links, spheres, origin, direction, tmin, tmax, formula, root=0,
             instances=(None, None, None)):
    """A shadow ray: is any face or sphere hit in [tmin, tmax)? ``root`` as in mesh_closest."""
    return _traverse_any(vertices, faces, nodes, links, spheres, origin, direction, tmin, tmax, formula, root,
                         instances)


def instanced_mesh_t(vertices, faces, nodes, links, root, origin, direction, tmin, tmax, best):
    """An instanced mesh (Suffern ch. 21, one mesh, many instances) along the object-space
    ray: (t, place, face) of its nearest face in [tmin, tmax), ``place`` the face's place in
    the mesh and ``face`` its row in ``faces``; of equal ts the face of the lower place wins,
    and a face whose place is below ``best`` (the scene's best index less the instance's
    first) wins at t = tmax too, as mesh_closest does with scene indices. (inf, 0, -1) for
    none, and where the scene holds no instanced mesh (``vertices`` None)."""
    return as_python(_typed_instanced_mesh_t, vertices, faces, nodes, links, root, origin, direction, tmin, tmax, best)


@overload(instanced_mesh_t, inline="always")
def _typed_instanced_mesh_t(vertices, faces, nodes, links, root, origin, direction, tmin, tmax, best):
    if isinstance(vertices, types.NoneType):
        return lambda vertices, faces, nodes, links, root, origin, direction, tmin, tmax, best: \
            (lit(math.inf, tmin), 0, -1)

    def present(vertices, faces, nodes, links, root, origin, direction, tmin, tmax, best):
        t, place, _, face = object_mesh_closest(vertices, faces, nodes, links, None, origin, direction, tmin,
                                                (tmax, best, 0, -1), 0, root)
        if face < 0:
            return lit(math.inf, tmin), 0, -1
        return t, place, face
    return present


@njit(cache=True, error_model="numpy", inline="always")
def _face_frame(vertices, faces, f, like):
    v0 = (lit(vertices[faces[f, 0], 0], like), lit(vertices[faces[f, 0], 1], like), lit(vertices[faces[f, 0], 2], like))
    v1 = (lit(vertices[faces[f, 1], 0], like), lit(vertices[faces[f, 1], 1], like), lit(vertices[faces[f, 1], 2], like))
    v2 = (lit(vertices[faces[f, 2], 0], like), lit(vertices[faces[f, 2], 1], like), lit(vertices[faces[f, 2], 2], like))
    e0 = sub(v1, v0)
    e1 = sub(v2, v0)
    return v0, e0, e1, cross(e0, e1)


@njit(cache=True, error_model="numpy", inline="always")
def barycentric_mesh(vertices, faces, f, position):
    """MeshTriangle.barycentric: the (beta, gamma) of the point (Triangle.texcoord)."""
    v0, e0, e1, n = _face_frame(vertices, faces, f, position[0])
    d = sub(position, v0)
    nn = dot(n, n)
    return dot(cross(d, e1), n) / nn, dot(cross(e0, d), n) / nn


def texcoord_mesh(vertices, faces, uvs, f, position):
    """MeshTriangle.texcoord: the barycentric (beta, gamma) without uvs (``uvs`` None), else
    the corners' (u, v) interpolated with them (FlatMesh.uvs; a vertex whose third column is
    0 belongs to a mesh without uvs, whose faces keep their barycentrics)."""
    return as_python(_typed_texcoord_mesh, vertices, faces, uvs, f, position)


@overload(texcoord_mesh, inline="always")
def _typed_texcoord_mesh(vertices, faces, uvs, f, position):
    if isinstance(uvs, types.NoneType):
        def barycentric(vertices, faces, uvs, f, position):
            return barycentric_mesh(vertices, faces, f, position)
        return barycentric

    def interpolated(vertices, faces, uvs, f, position):
        beta, gamma = barycentric_mesh(vertices, faces, f, position)
        i0, i1, i2 = faces[f, 0], faces[f, 1], faces[f, 2]
        if uvs[i0, 2] == 0:
            return beta, gamma
        alpha = lit(1, beta) - beta - gamma
        return (alpha * lit(uvs[i0, 0], beta) + beta * lit(uvs[i1, 0], beta) + gamma * lit(uvs[i2, 0], beta),
                alpha * lit(uvs[i0, 1], beta) + beta * lit(uvs[i1, 1], beta) + gamma * lit(uvs[i2, 1], beta))
    return interpolated


def normal_mesh(vertices, faces, normals, f, position):
    """The unit normal of face ``f`` at ``position``: FlatMeshTriangle's without vertex
    normals (``normals`` None), else SmoothMeshTriangle's (typed by the overload below)."""
    return as_python(_typed_normal_mesh, vertices, faces, normals, f, position)


@overload(normal_mesh, inline="always")
def _typed_normal_mesh(vertices, faces, normals, f, position):
    if isinstance(normals, types.NoneType):
        def flat(vertices, faces, normals, f, position):
            return normalize(_face_frame(vertices, faces, f, position[0])[3])
        return flat

    def smooth(vertices, faces, normals, f, position):
        n = _face_frame(vertices, faces, f, position[0])[3]
        beta, gamma = barycentric_mesh(vertices, faces, f, position)
        one = lit(1, beta)
        i0, i1, i2 = faces[f, 0], faces[f, 1], faces[f, 2]
        n0 = (lit(normals[i0, 0], one), lit(normals[i0, 1], one), lit(normals[i0, 2], one))
        n1 = (lit(normals[i1, 0], one), lit(normals[i1, 1], one), lit(normals[i1, 2], one))
        n2 = (lit(normals[i2, 0], one), lit(normals[i2, 1], one), lit(normals[i2, 2], one))
        m = add(add(scale(n0, one - beta - gamma), scale(n1, beta)), scale(n2, gamma))
        if dot(m, m) == lit(0, one):
            return normalize(n)
        return normalize(m)
    return smooth
