"""Packets of rays through the wide BVH (rtfgu.kernels.packet): box_rays is box8 ray by ray
(the same lanes entered, the same nearest entry), and a packet gives every ray the face, t
and tie of mesh_closest alone, and of the loop over all faces, in both precisions: on a
camera's tiles (coherent, the packet path down to the leaves) and on scattered rays (the
packet drops to single rays), with a bound given on entry, for partial packets, and with no
leak from inside a closed mesh."""
from __future__ import annotations

import math

import numpy as np
import pytest
from numba import njit, prange

from rtfgu.accelerators import wide_bvh
from rtfgu.kernels.float3 import lit, lit_per_precision
from rtfgu.kernels.mesh import WIDEN32, WIDEN64, _inverse, mesh_closest
from rtfgu.kernels.packet import (OX, PACKET, REACH, RAY_ROWS, box_frustum, box_rays, frustum_of_packet,
                                  mesh_closest_packet, _frustum_of, _rays_of)
from rtfgu.kernels.wide_bvh import box8, lanes_of

from test_wide_bvh import PRECISIONS, hard_rays, looped, rays_from_inside, soup, traversal_mesh, tree_of


@njit(error_model="numpy", inline="always")
def _fill_rays(rays, origins, directions, count, reach):
    """The packet's rows as mesh_closest_packet lays them out, ray i's reach reach[i]."""
    for i in range(count):
        inv = _inverse((directions[i, 0], directions[i, 1], directions[i, 2]))[0]
        for a in range(3):
            rays[(OX + a) * PACKET + i] = origins[i, a]
            rays[(OX + 3 + a) * PACKET + i] = inv[a]
        rays[REACH * PACKET + i] = reach[i]


@njit(error_model="numpy")
def _both(nodes, n, origins, directions, count, reach, masks, nears, single):
    tmin = lit(0, origins[0, 0])
    widen = lit_per_precision(WIDEN32, WIDEN64, tmin)
    rays = _rays_of(tmin)
    entry = lanes_of(tmin)
    _fill_rays(rays, origins, directions, count, reach)
    for i in range(count):
        inv = _inverse((directions[i, 0], directions[i, 1], directions[i, 2]))[0]
        single[i] = box8(nodes, n, (origins[i, 0], origins[i, 1], origins[i, 2]), inv, tmin, reach[i], widen, entry)
        for j in range(8):
            nears[j, 1 + i] = entry[j]
    live = (np.int64(1) << count) - 1
    for j in range(8):
        masks[j], nears[j, 0] = box_rays(nodes, n, j, rays, live, tmin, widen)


@pytest.mark.parametrize("dtype", PRECISIONS, ids=lambda d: d.__name__)
def test_box_rays_is_box8_ray_by_ray(dtype):
    vertices, faces = soup(400, seed=2)
    _, wide, _ = tree_of(vertices, faces)
    rng = np.random.default_rng(5)
    assert RAY_ROWS == 7
    mismatches, entered = [], 0
    for trial in range(300):
        count = int(rng.integers(1, PACKET + 1))
        origins, directions = hard_rays(vertices, count, seed=trial)
        reach = rng.choice([math.inf, 0.5, 2.0], count).astype(dtype)
        n = int(rng.integers(0, len(wide.nodes)))
        masks = np.empty(8, dtype=np.int64)
        nears = np.empty((8, 1 + count), dtype=dtype)
        single = np.empty(count, dtype=np.int64)
        _both(wide.nodes, n, origins.astype(dtype), directions.astype(dtype), count, reach, masks, nears, single)
        for j in range(8):
            expected = sum(1 << i for i in range(count) if single[i] >> j & 1)
            lanes = [nears[j, 1 + i] for i in range(count) if single[i] >> j & 1]
            nearest = dtype(min(lanes)) if lanes else dtype(math.inf)
            entered += bool(expected)
            if masks[j] != expected or nears[j, 0].tobytes() != nearest.tobytes():
                mismatches.append((trial, j, masks[j], expected, nears[j, 0], nearest))
    assert entered > 100                      # the rays do enter boxes
    assert not mismatches, mismatches[:3]


@njit(error_model="numpy")
def _frustum_and_rays(nodes, n, origins, directions, count, masks):
    """box_rays' mask of each of node n's columns for the packet (reach infinite), and
    box_frustum's mask; -1 where the packet has no frustum."""
    tmin = lit(0, origins[0, 0])
    widen = lit_per_precision(WIDEN32, WIDEN64, tmin)
    rays = _rays_of(tmin)
    _fill_rays(rays, origins, directions, count, np.full(count, math.inf, dtype=origins.dtype))
    live = (np.int64(1) << count) - 1
    for j in range(8):
        masks[j] = box_rays(nodes, n, j, rays, live, tmin, widen)[0]
    frustum = _frustum_of(tmin)
    if not frustum_of_packet(rays, count, frustum):
        return -1
    return box_frustum(nodes, n, frustum, tmin, widen)


def grazing_packet(nodes, rng, dtype):
    """(node, origins, directions) of a packet aimed at points on the boundary of one of the
    node's child boxes (coordinates snapped to its planes), from one eye or from origins
    spread around it, some on the box's planes themselves."""
    while True:
        n = int(rng.integers(0, len(nodes)))
        j = int(rng.integers(0, 8))
        lo, hi = nodes[n, 0:3, j].astype(np.float64), nodes[n, 3:6, j].astype(np.float64)
        if np.all(np.isfinite(lo)) and np.all(np.isfinite(hi)) and np.all(lo <= hi):
            break
    count = int(rng.integers(1, PACKET + 1))
    targets = rng.uniform(lo, hi, (count, 3))
    for i in range(count):
        for a in rng.choice(3, int(rng.integers(1, 3)), replace=False):
            targets[i, a] = (lo if rng.random() < 0.5 else hi)[a]
    size = np.maximum(hi - lo, 1e-3)
    eye = np.where(rng.random(3) < 0.5, lo - size * rng.uniform(0.5, 3.0, 3), hi + size * rng.uniform(0.5, 3.0, 3))
    origins = np.tile(eye, (count, 1))
    if rng.random() < 0.5:
        origins += rng.normal(0.0, 0.05, (count, 3)) * size
    if rng.random() < 0.3:
        a = int(rng.integers(0, 3))
        origins[:, a] = (lo if rng.random() < 0.5 else hi)[a]      # on a plane of the box
    return n, origins.astype(dtype), (targets - origins).astype(dtype)


@pytest.mark.parametrize("dtype", PRECISIONS, ids=lambda d: d.__name__)
def test_the_frustum_enters_every_box_a_ray_of_its_packet_enters(dtype):
    # box_frustum culls a column only where box_rays, ray by ray, enters it with none: on
    # packets aimed at a box's faces, edges and corners (the rounding of the bounds decides),
    # and on a camera's tiles against every node of the tree.
    vertices, faces = traversal_mesh("icosphere")
    _, wide, _ = tree_of(vertices, faces)
    nodes = wide.nodes
    rng = np.random.default_rng(11)
    masks = np.empty(8, dtype=np.int64)
    missed, with_frustum, culled, entered = [], 0, 0, 0

    def check(n, origins, directions, count):
        nonlocal with_frustum, culled, entered
        frustum = _frustum_and_rays(nodes, n, origins, directions, count, masks)
        if frustum < 0:
            return
        with_frustum += 1
        for j in range(8):
            entered += masks[j] != 0
            culled += masks[j] == 0 and not frustum >> j & 1
            if masks[j] != 0 and not frustum >> j & 1:
                missed.append((n, j, masks[j], origins[:count].tolist(), directions[:count].tolist()))

    for _ in range(3000):
        n, origins, directions = grazing_packet(nodes, rng, dtype)
        check(n, origins, directions, len(origins))
    origins, directions = camera_tiles(vertices, 32)
    origins, directions = origins.astype(dtype), directions.astype(dtype)
    for first in range(0, len(origins), PACKET):
        for n in range(len(nodes)):
            check(n, origins[first:first + PACKET], directions[first:first + PACKET], PACKET)
    assert with_frustum > 2000 and entered > 2000 and culled > 2000     # it culls, and is checked
    assert not missed, missed[:2]


@njit(parallel=True, error_model="numpy")
def _packets(vertices, faces, nodes, links, origins, directions, bound, hits):
    """Every PACKET consecutive rays as one packet (the last one partial), each starting
    from its ``bound`` (t, index)."""
    n = origins.shape[0]
    for g in prange((n + PACKET - 1) // PACKET):
        first = g * PACKET
        count = min(PACKET, n - first)
        o = origins[first:first + count].ravel()
        d = directions[first:first + count].ravel()
        t = bound[first:first + count, 0].astype(origins.dtype)
        best = bound[first:first + count, 1].astype(np.int64)
        kind = np.full(count, -1, dtype=np.int64)
        row = np.full(count, -1, dtype=np.int64)
        mesh_closest_packet(vertices, faces, nodes, links, None, (o, d, count, lit(0, origins[0, 0])),
                            (t, best, kind, row), 0)
        for i in range(count):
            hits[first + i, 0] = t[i]
            hits[first + i, 1] = best[i]
            hits[first + i, 2] = row[i]


@njit(parallel=True, error_model="numpy")
def _singles(vertices, faces, nodes, links, origins, directions, bound, hits):
    for i in prange(origins.shape[0]):
        tmin = lit(0, origins[i, 0])
        t, best, _, row = mesh_closest(vertices, faces, nodes, links, None,
                                       (origins[i, 0], origins[i, 1], origins[i, 2]),
                                       (directions[i, 0], directions[i, 1], directions[i, 2]), tmin,
                                       (lit(bound[i, 0], tmin), np.int64(bound[i, 1]), -1, -1), 0)
        hits[i, 0] = t
        hits[i, 1] = best
        hits[i, 2] = row


def run(kernel, vertices, rows, wide, origins, directions, dtype, bound=None):
    if bound is None:
        bound = np.tile([math.inf, -1.0], (len(origins), 1))
    hits = np.empty((len(origins), 3), dtype=np.float64)
    kernel(vertices.astype(dtype), rows, wide.nodes, wide.links, origins.astype(dtype), directions.astype(dtype),
           bound, hits)
    return hits


def render_tree(wide, vertices, rows, dtype):
    """The wide tree a render of ``dtype`` traverses: with its blocks
    (rtfgu.kernels.render.numba_tree; their corners copied in float32, gathered in float64),
    which the packets test face by face against their rays or ray by ray."""
    blocked = wide_bvh.with_blocks(wide, vertices.astype(dtype), rows)
    assert len(blocked.nodes) != len(wide.nodes) or blocked.nodes.tobytes() != wide.nodes.tobytes()
    return blocked


def camera_tiles(vertices, size):
    """A pinhole's size x size rays at the mesh, ordered a 4 x 4 tile after another (each
    tile one packet), from a corner so that rays graze it."""
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    eye = hi + (hi - lo) * 1.5
    w = (lo + hi) / 2 - eye
    w /= np.linalg.norm(w)
    u = np.cross(w, (0.0, 1.0, 0.0))
    u /= np.linalg.norm(u)
    v = np.cross(u, w)
    s = (2 * (np.arange(size) + 0.5) / size - 1) * 0.25
    sx, sy = np.meshgrid(s, -s)
    directions = (sx[..., None] * u + sy[..., None] * v + w).reshape(size // 4, 4, size // 4, 4, 3)
    directions = directions.transpose(0, 2, 1, 3, 4).reshape(-1, 3)
    return np.broadcast_to(eye, directions.shape).copy(), directions


@pytest.mark.parametrize("dtype", PRECISIONS, ids=lambda d: d.__name__)
@pytest.mark.parametrize("mesh", ["soup", "icosphere", "coincident"])
@pytest.mark.parametrize("rays", ["tiles", "scattered"])
def test_a_packet_finds_every_rays_face_and_t_of_mesh_closest(rays, mesh, dtype):
    vertices, faces = traversal_mesh(mesh)
    _, wide, rows = tree_of(vertices, faces)
    wide = render_tree(wide, vertices, rows, dtype)
    if rays == "tiles":
        origins, directions = camera_tiles(vertices, 64)
    else:
        origins, directions = hard_rays(vertices, 20003, seed=9)     # the last packet partial
    packed = run(_packets, vertices, rows, wide, origins, directions, dtype)
    single = run(_singles, vertices, rows, wide, origins, directions, dtype)
    truth = looped(vertices, rows, origins, directions, dtype)
    assert (truth[:, 1] >= 0).mean() > 0.2 and (truth[:, 1] < 0).any()     # rays hit, and miss
    assert single.tobytes() == truth.tobytes()
    assert packed.tobytes() == truth.tobytes()


@pytest.mark.parametrize("dtype", PRECISIONS, ids=lambda d: d.__name__)
def test_a_packet_keeps_each_rays_bound_and_tie_rule(dtype):
    # The bound on entry is the nearest hit so far of shapes outside the tree (their scene
    # index): a face beyond it is not taken, one at its t is taken only if its index is lower.
    vertices, faces = soup(2000, seed=3)
    _, wide, rows = tree_of(vertices, faces)
    wide = render_tree(wide, vertices, rows, dtype)
    origins, directions = camera_tiles(vertices, 48)
    free = run(_singles, vertices, rows, wide, origins, directions, dtype)
    hit = free[:, 1] >= 0
    rng = np.random.default_rng(1)
    bound = np.tile([math.inf, -1.0], (len(origins), 1))
    pick = rng.integers(0, 4, len(origins))
    bound[pick == 0, 0] = 0.5 * np.where(hit, free[:, 0], 1.0)[pick == 0]       # a nearer hit outside
    bound[pick == 1, 0] = np.where(hit, free[:, 0], 1.0)[pick == 1]             # a tie at the face's t
    bound[pick == 1, 1] = rng.integers(0, len(faces), (pick == 1).sum())
    bound[pick == 2, 0] = 2.0 * np.where(hit, free[:, 0], 1.0)[pick == 2]       # a farther one
    bound[pick == 2, 1] = len(faces) + 1
    packed = run(_packets, vertices, rows, wide, origins, directions, dtype, bound)
    single = run(_singles, vertices, rows, wide, origins, directions, dtype, bound)
    assert packed.tobytes() == single.tobytes()
    # the bound held: no ray of pick 0 took a face, and some of pick 1 kept the outside index
    assert (packed[(pick == 0) & hit, 2] == -1).all()
    tie = (pick == 1) & hit
    assert ((packed[tie, 1] == bound[tie, 1]) & (packed[tie, 2] == -1)).any()
    assert (packed[(pick == 3) & hit, 2] >= 0).all()


@pytest.mark.parametrize("dtype", PRECISIONS, ids=lambda d: d.__name__)
def test_no_ray_of_a_packet_from_inside_a_closed_mesh_leaks(dtype):
    vertices, rows, wide, rays = rays_from_inside()
    wide = render_tree(wide, vertices, rows, dtype)
    for origins, directions in rays:
        hits = run(_packets, vertices, rows, wide, origins, directions, dtype)
        assert (hits[:, 1] >= 0).all(), "%d of %d rays leak" % ((hits[:, 1] < 0).sum(), len(origins))


@njit(error_model="numpy")
def _one_packet(vertices, faces, nodes, origins, directions, count):
    t = np.full(PACKET + 1, math.inf)
    best = np.full(PACKET + 1, -1, dtype=np.int64)
    mesh_closest_packet(vertices, faces, nodes, nodes.view(np.int32), None,
                        (origins.ravel(), directions.ravel(), count, 0.0), (t, best, best.copy(), best.copy()), 0)


@pytest.mark.parametrize("count", [0, PACKET + 1])
def test_a_packet_of_no_rays_or_too_many_is_refused(count):
    vertices, faces = soup(10, seed=1)
    _, wide, rows = tree_of(vertices, faces)
    rays = np.ones((PACKET + 1, 3))
    with pytest.raises(ValueError, match="1 to PACKET rays"):
        _one_packet(vertices, rows, wide.nodes, rays, rays, count)


# --- through the render -------------------------------------------------------------------

def _both_renders(scene, width, height, sampler=None, precision="float32"):
    """The kernel's sums and ray counts with the pinhole's primary rays in packets and
    without (the same arguments, only ``packets`` changed)."""
    from rtfgu.kernels import hit_phases, kernel_arguments, render_tiles, sums_dtype
    from rtfgu.kernels.render import COUNTS
    from rtfgu.layout import compile_sampler, compile_scene

    flat = compile_scene(scene, precision)
    args, tiles = kernel_arguments(flat, width, height, sampler=compile_sampler(sampler, precision),
                                   samples=(0, 1 if sampler is None else sampler.num_samples))
    out = {}
    for packets in (None, 1):
        run = list(args)
        run[7] = args[7][:2] + (packets, hit_phases(args[7][0], packets))
        sums = np.full((height, width, 3), np.nan, dtype=sums_dtype(flat, sampler))   # as NumbaAccumulator's
        counts = np.zeros((tiles, COUNTS), dtype=np.int64)
        render_tiles(tuple(run), tiles, sums, counts)
        out[packets] = (sums, counts.sum(axis=0))
    return args[7][2], out[None], out[1]


def _vector_cpu() -> bool:
    from rtfgu.kernels.wide_bvh import vector_cpu
    return vector_cpu()


@pytest.mark.parametrize("precision", ["float64", "float32"])
@pytest.mark.parametrize("name", ["cornell_box_spheres", "suffern_18_area_lighting"])
def test_the_render_gives_the_same_image_with_packets_as_without(name, precision):
    # Spheres the tree holds, with a mirror and a Transparent (a tile's stack of second
    # rays); area lights sampled, several samples a pixel: the pixels are traced in another
    # order, the sums must be the same bits.
    from rtfgu.options import pixel_sampler
    from rtfgu.scenes import SCENES

    scene = SCENES[name]()
    chosen, single, packed = _both_renders(scene, 37, 29, pixel_sampler(scene, None), precision)  # blocks cut by edges
    assert chosen == (1 if _vector_cpu() else None)     # packets where the numba path has the wide tree
    if not _vector_cpu():
        pytest.skip("this CPU has no AVX: the numba path traverses the binary tree, which has no packets")
    assert np.isfinite(single[0]).all() and single[0].std() > 0
    assert single[0].tobytes() == packed[0].tobytes()
    assert np.array_equal(single[1], packed[1])


@pytest.mark.parametrize("precision", ["float64", "float32"])
def test_a_render_compiles_one_traversal_per_kind_of_tree(precision):
    """A render with packets compiles the packet traversal once, for an int64 count (a
    literal 0 had numba compile it once more, for a count no call passes), and one
    mesh_closest for the scan of the tree and the packets' single rays (both pass the root
    as an int64): no two compiled signatures differ in the count or the root alone."""
    if not _vector_cpu():
        pytest.skip("this CPU has no AVX: the numba path traverses the binary tree, which has no packets")
    import rtfgu
    from numba import types

    from rtfgu.kernels.mesh import mesh_closest
    from rtfgu.kernels.packet import mesh_closest_packet
    from rtfgu.scenes import SCENES

    rtfgu.render(SCENES["cornell_box_spheres"](), 16, 16, backend="numba", precision=precision)

    def compiled(dispatcher) -> list:
        """The signatures compiled in this process and those numba's cache holds (a kernel
        loaded from the cache compiles nothing it calls)."""
        held = [key[0] for key in dispatcher._cache._cache_file._load_index()]
        return list(dict.fromkeys(list(dispatcher.signatures) + held))

    def others(signatures, at, at_in_tuple=None):
        """Each signature's arguments with argument ``at`` (or element ``at_in_tuple`` of
        that tuple) left out."""
        out = []
        for sig in signatures:
            args = list(sig)
            if at_in_tuple is None:
                del args[at]
            else:
                args[at] = tuple(t for i, t in enumerate(args[at].types) if i != at_in_tuple)
            out.append(tuple(args))
        return out

    packets = compiled(mesh_closest_packet)
    rendered = [sig for sig in packets if isinstance(sig[5].types[0], types.CPointer)]
    assert rendered and not any(isinstance(sig[5].types[2], types.Literal) for sig in rendered)
    assert len(set(others(packets, 5, 2))) == len(packets)
    roots = [sig for sig in compiled(mesh_closest) if len(sig) > 10]
    assert len(set(others(roots, 10))) == len(roots), [str(sig[10]) for sig in roots]


def test_a_packets_hit_is_weighed_against_a_plane_outside_the_tree_as_the_traversal_is():
    # A mesh square lying in a plane: at every pixel the plane (outside the BVH) and a face
    # of the tree meet at ts a rounding apart, or equal, where the shape earlier in
    # Scene.shapes wins: the pixels mix the two colours, and packets must mix them alike.
    import rtfgu
    from rtfgu.float3 import Float3

    square = rtfgu.Mesh(np.array([[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0]]),
                        np.array([[0, 1, 2], [0, 2, 3]]), (1.0, 0.0, 0.0))
    plane = rtfgu.Plane(Float3(0.0, 0.0, 0.0), Float3(0.0, 0.0, 1.0), (0.0, 0.0, 1.0))
    for first in (square, plane):
        scene = rtfgu.Scene(rtfgu.PinholeCamera(Float3(0.3, 0.2, 3.0), Float3(0.0), Float3(0, 1, 0), 1.0))
        scene.shapes += [first, plane if first is square else square]
        chosen, single, packed = _both_renders(scene, 24, 24)
        if chosen is None:
            pytest.skip("this CPU has no AVX: no wide tree, no packets")
        assert single[0].tobytes() == packed[0].tobytes()
        centre = packed[0][8:16, 8:16].reshape(-1, 3)
        assert (centre[:, 0] > 0).any() and (centre[:, 2] > 0).any()      # both shapes won pixels
