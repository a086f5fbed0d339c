"""Mesh triangles on every path (the registry's "mesh" kind: a BVH over the faces): no ray
leaks through a shared edge or vertex of a closed mesh, the nearest face, its normal and the
tie rule are the lecture layer's, shadow rays stop at faces, and the BVH and its layout hold
what they promise (every face in one leaf, boxes that hold their faces in float32 too, at most
64 bytes per triangle)."""
from __future__ import annotations

import math
import random

import numpy as np
import pytest
import trimesh

from rtfgu import Float3, OrthographicCamera, Plane, PointLight, Scene, Sphere, Triangle
from rtfgu.accelerators import flat_bvh
from rtfgu.layout import compile_scene
from rtfgu.materials import Material, Matte, Reflective
from rtfgu.shapes.mesh import Mesh

GREY = (0.5, 0.5, 0.5)
T_CLOSE = {"float64": 1e-12, "float32": 2e-5}


def icosphere(subdivisions: int, **kwargs) -> Mesh:
    sphere = trimesh.creation.icosphere(subdivisions=subdivisions)
    return Mesh(np.asarray(sphere.vertices), np.asarray(sphere.faces), GREY, **kwargs)


def scene_of(*shapes) -> Scene:
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    for shape in shapes:
        scene.shapes += shape.triangles() if isinstance(shape, Mesh) else [shape]
    return scene


# --- shared edges and vertices: a closed mesh holds every ray from inside ----------------

def edge_and_vertex_rays(mesh: Mesh, origin) -> list:
    """From ``origin`` (inside the mesh) through every vertex and every edge's midpoint."""
    o = np.asarray(origin, dtype=float)
    targets = list(mesh.vertices)
    edges = {tuple(sorted((int(f[a]), int(f[(a + 1) % 3])))) for f in mesh.faces for a in range(3)}
    targets += [(mesh.vertices[i] + mesh.vertices[j]) * 0.5 for i, j in sorted(edges)]
    return [(tuple(o), tuple(t - o), 0.0, math.inf) for t in targets]


@pytest.mark.parametrize("origin", [(0.0, 0.0, 0.0), (0.125, -0.0625, 0.25)])
def test_no_ray_from_inside_a_closed_mesh_leaks_through_an_edge_or_a_vertex(path, origin):
    mesh = icosphere(2)                    # 320 faces, 480 shared edges, 162 shared vertices
    rays = edge_and_vertex_rays(mesh, origin)
    leaks = [ray for ray, bounces in zip(rays, path.trace(scene_of(mesh), rays)) if bounces[0].shape is None]
    assert not leaks, "%s: %d of %d rays leak, e.g. %s" % (path, len(leaks), len(rays), leaks[:3])


# --- the nearest face, its normal, ties --------------------------------------------------

def random_rays(count: int, seed: int = 3):
    rng = random.Random(seed)
    rays = []
    for _ in range(count):
        o = [rng.uniform(-3.0, 3.0) for _ in range(3)]
        target = [rng.uniform(-1.0, 1.0) for _ in range(3)]
        rays.append((tuple(o), tuple(t - a for t, a in zip(target, o)), 0.0, math.inf))
    return rays


@pytest.mark.parametrize("smooth", [False, True], ids=["flat", "smooth"])
def test_the_nearest_face_and_its_normal_are_the_lecture_layers(path, smooth):
    sphere = trimesh.creation.icosphere(subdivisions=2)
    mesh = Mesh(np.asarray(sphere.vertices) * 0.75, np.asarray(sphere.faces), GREY,
                normals=np.asarray(sphere.vertex_normals) if smooth else None)
    scene = scene_of(Sphere(Float3(0.5, 0.0, 0.0), 0.5, GREY), mesh,
                     Triangle((-2, -2, -0.25), (2, -2, -0.25), (0, 2, -0.25), GREY))
    rays = random_rays(120)
    want = path.reference.trace(scene, rays)
    got = path.trace(scene, rays)
    hits = 0
    for ray, a, b in zip(rays, want, got):
        assert a[0].shape == b[0].shape, (path, ray)
        if a[0].shape is not None:
            hits += 1
            assert b[0].t == pytest.approx(a[0].t, rel=T_CLOSE[path.precision]), (path, ray)
            if a[0].normal is not None:
                assert b[0].normal == pytest.approx(a[0].normal, abs=1e-5 if path.precision == "float32" else 1e-12)
    assert hits > 60


@pytest.mark.parametrize("order", ["triangle first", "mesh first"])
def test_a_face_and_a_triangle_at_the_same_t_go_to_the_earlier_shape(path, order):
    square = Mesh(np.array([(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)], float),
                  np.array([(0, 1, 2), (1, 3, 2)]), GREY)
    triangle = Triangle((0, 0, 0), (1, 0, 0), (0, 1, 0), (1.0, 0.0, 0.0))
    scene = scene_of(triangle, square) if order == "triangle first" else scene_of(square, triangle)
    rays = [((x, y, 2.0), (0.0, 0.0, -1.0), 0.0, math.inf) for x, y in ((0.25, 0.25), (0.125, 0.5), (0.5, 0.25))]
    winner = 0
    for bounces in path.trace(scene, rays):
        assert bounces[0].t == 2.0
        assert bounces[0].shape == winner, (path, order, bounces[0])


def test_two_copies_of_a_mesh_at_the_same_place_show_the_earlier_one(path):
    mesh = icosphere(1)
    scene = scene_of(mesh, mesh)
    rays = random_rays(40, seed=5)
    for ray, bounces in zip(rays, path.trace(scene, rays)):
        if bounces[0].shape is not None:
            assert bounces[0].shape < len(mesh.faces), (path, ray, bounces[0].shape)


def test_a_mesh_casts_shadows_and_a_light_in_front_of_it_lights_the_floor(path):
    square = Mesh(np.array([(-1, 1, -1), (1, 1, -1), (-1, 1, 1), (1, 1, 1)], float),
                  np.array([(0, 2, 1), (1, 2, 3)]), GREY, material=Matte())
    floor = Plane(Float3(0, 0, 0), Float3(0, 1, 0), Float3(1.0), Matte())
    ray = [((0.0, 0.5, 0.0), (0.0, -1.0, 0.0), 0.0, math.inf)]
    above = scene_of(floor, square)
    above.lights.append(PointLight(Float3(0, 4, 0), Float3(16.0)))
    between = scene_of(floor, square)
    between.lights.append(PointLight(Float3(0, 0.75, 0), Float3(16.0)))
    shadowed = path.trace(above, ray)[0][0].color
    lit = path.trace(between, ray)[0][0].color
    assert lit[0] > shadowed[0] + 1.0, (path, lit, shadowed)
    assert shadowed == pytest.approx(path.reference.trace(above, ray)[0][0].color, rel=1e-5)


# --- the BVH and the layout ----------------------------------------------------------

def leaves(bvh):
    links = bvh.links
    return [(links[n, 3], links[n, 7]) for n in range(bvh.num_nodes) if links[n, 7] > 0]


@pytest.mark.parametrize("subdivisions", [0, 3])
def test_every_face_is_in_one_leaf_and_every_box_holds_its_faces(subdivisions):
    mesh = icosphere(subdivisions)
    lo, hi = flat_bvh.triangle_bounds(mesh.vertices, mesh.faces)
    bvh = flat_bvh.build(lo, hi)
    assert sorted(bvh.order) == list(range(len(lo)))
    assert sum(count for _, count in leaves(bvh)) == len(lo)
    assert bvh.num_nodes <= 2 * len(lo) - 1 and bvh.depth() <= flat_bvh.MAX_DEPTH
    links, nodes = bvh.links, bvh.nodes.astype(np.float64)
    for n in range(bvh.num_nodes):
        if links[n, 7] > 0:
            faces = bvh.order[links[n, 3]:links[n, 3] + links[n, 7]]
            assert (nodes[n, :3] <= lo[faces]).all() and (nodes[n, 4:7] >= hi[faces]).all()
            # float32 vertices (each rounded to nearest) stay inside the rounded-out box
            v32 = mesh.vertices[mesh.faces[faces]].astype(np.float32).astype(np.float64)
            assert (nodes[n, :3] <= v32.min(axis=1)).all() and (nodes[n, 4:7] >= v32.max(axis=1)).all()
        else:
            left = links[n, 3]
            for child in (left, left + 1):
                assert (nodes[n, :3] <= nodes[child, :3]).all() and (nodes[n, 4:7] >= nodes[child, 4:7]).all()


def test_faces_with_one_centroid_are_split_in_halves_down_to_leaves():
    v = np.array([(0, 0, 0), (1, 0, 0), (0, 1, 0)], float)
    lo, hi = flat_bvh.triangle_bounds(v, np.array([(0, 1, 2)] * 100))
    bvh = flat_bvh.build(lo, hi)
    assert max(count for _, count in leaves(bvh)) <= 4 and sorted(bvh.order) == list(range(100))


def test_the_build_without_numba_is_the_same_tree(monkeypatch):
    mesh = icosphere(1)
    lo, hi = flat_bvh.triangle_bounds(mesh.vertices, mesh.faces)
    jitted = flat_bvh.build(lo, hi)
    for name, value in list(vars(flat_bvh).items()):
        if hasattr(value, "py_func"):
            monkeypatch.setattr(flat_bvh, name, value.py_func)
    monkeypatch.setattr(flat_bvh, "TASK_MIN", 16)      # the parallel build's steps too
    plain = flat_bvh.build(lo, hi)
    assert not hasattr(flat_bvh._subtree, "py_func")
    assert np.array_equal(jitted.nodes.view(np.int32), plain.nodes.view(np.int32))
    assert np.array_equal(jitted.order, plain.order)


def _soups():
    """Boxes for the parallel build: a mesh, a soup half of whose centroids coincide (the
    median split), and faces that all share one centroid."""
    mesh = icosphere(4)
    rng = np.random.default_rng(7)
    centers = rng.random((3000, 3))
    centers[:1500] = 0.5
    one = flat_bvh.triangle_bounds(np.array([(0, 0, 0), (1, 0, 0), (0, 1, 0)], float),
                                   np.array([(0, 1, 2)] * 300))
    return [flat_bvh.triangle_bounds(mesh.vertices, mesh.faces), (centers, centers + 0.01), one]


@pytest.mark.parametrize("task_min", [8, 300])
def test_the_parallel_build_is_the_serial_tree_node_for_node(monkeypatch, task_min):
    """Split into subtrees built on all cores (TASK_MIN primitives or fewer each, the nodes
    above split with their bins made in parts), the table is the one-task build's (a
    TASK_MIN above the count), number for number."""
    for lo, hi in _soups():
        monkeypatch.setattr(flat_bvh, "TASK_MIN", 1 << 30)
        serial = flat_bvh.build(lo, hi)
        monkeypatch.setattr(flat_bvh, "TASK_MIN", task_min)
        parallel = flat_bvh.build(lo, hi)
        assert np.array_equal(serial.nodes.view(np.int32), parallel.nodes.view(np.int32))
        assert np.array_equal(serial.order, parallel.order)
        assert np.array_equal(serial.boxes, parallel.boxes)
        # each primitive's box, in leaf order, holds the primitive's own
        assert (parallel.boxes[:, :3] <= lo[parallel.order]).all() and (parallel.boxes[:, 3:] >= hi[parallel.order]).all()


def test_a_builds_task_size_is_a_threads_share_within_its_bounds(monkeypatch):
    """task_size: one task up to TASK_FLOOR primitives, a thread's share above it, at most
    TASK_MIN, and on one thread (or without numba) one task up to TASK_MIN."""
    floor, most = flat_bvh.TASK_FLOOR, flat_bvh.TASK_MIN
    for count, n, want in [(2, 3674, floor), (2, floor, floor), (2, 4 * floor, 2 * floor), (4, 4 * floor, floor),
                           (2, 100 * most, most), (8, 20 * floor, 5 * floor // 2), (1, 5 * floor, 5 * floor),
                           (1, most, most), (1, 3 * most, most)]:
        monkeypatch.setattr(flat_bvh, "threads", lambda: count)
        assert flat_bvh.task_size(n) == want, (count, n)


def test_a_mesh_of_a_few_tasks_builds_the_one_task_tree(monkeypatch):
    """A mesh past TASK_FLOOR (20480 faces: two tasks or more on two threads) against the
    tree one task builds over all of it: the same table, number for number."""
    mesh = icosphere(5)
    lo, hi = flat_bvh.triangle_bounds(mesh.vertices, mesh.faces)
    assert flat_bvh.task_size(len(lo)) < len(lo) or flat_bvh.threads() < 2
    split = flat_bvh.build(lo, hi)
    monkeypatch.setattr(flat_bvh, "task_size", lambda n_prims: n_prims)
    whole = flat_bvh.build(lo, hi)
    assert np.array_equal(split.nodes.view(np.int32), whole.nodes.view(np.int32))
    assert np.array_equal(split.order, whole.order) and np.array_equal(split.boxes, whole.boxes)


def test_a_node_of_few_primitives_picks_the_plane_its_bins_pick():
    """_best_plane_few (a node of at most FEW primitives, sorted by bin) against the bins
    (_bin and _best_plane) on random nodes: spread, clustered (empty bins between runs),
    centroids shared (one bin holds all), flat on an axis (no extent), and a node of no
    area; every count from 1 to FEW, both sides of LEAF_SIZE."""
    rng = np.random.default_rng(5)
    bins, chosen = flat_bvh.BINS, set()
    for trial in range(3000):
        count = 1 + trial % flat_bvh.FEW
        kind = trial % 5
        centers = rng.random((count, 3))
        if kind == 1:
            centers = np.round(centers * 3) / 3                  # few distinct bins
        elif kind == 2:
            centers[:] = centers[0]                              # one bin
        elif kind == 3:
            centers[:, trial % 3] = 0.25                         # no extent on an axis
        half = 0.0 if kind == 4 else rng.random((count, 3)) * 0.2
        lo, hi = centers - half, centers + half
        refs = flat_bvh._references(lo, hi)
        bounds = np.empty(12)
        flat_bvh._node_bounds(refs, 0, count, bounds)
        scale = np.zeros(3)
        flat_bvh._bin_scale(bounds, bins, scale)
        bin_count, bin_box = np.zeros((3, bins), dtype=np.int64), np.empty((3, bins, 6))
        flat_bvh._empty_bins(bin_count, bin_box)
        flat_bvh._bin(refs, 0, count, bounds, scale, bin_count, bin_box)
        binned = flat_bvh._best_plane(bin_count, bin_box, bounds, scale, count, flat_bvh.LEAF_SIZE,
                                      flat_bvh.C_TRAVERSE, flat_bvh.C_INTERSECT, np.empty(bins),
                                      np.empty(bins, dtype=np.int64))
        few = flat_bvh._best_plane_few(refs, 0, count, bounds, scale, bins, flat_bvh.LEAF_SIZE,
                                       flat_bvh.C_TRAVERSE, flat_bvh.C_INTERSECT,
                                       np.empty((flat_bvh.FEW, 2), dtype=np.int64), np.empty(flat_bvh.FEW))
        assert few == binned, (trial, count, kind)
        chosen.add(binned[0])
    assert chosen == {-1, 0, 1, 2}       # leaves and each axis were chosen


def test_boxes_round_out_to_float32_as_nextafter_does():
    """The build's rounding (a step on the float32's bits) against np.nextafter, over
    magnitudes from subnormal to overflow, both zeros and exact float32 values."""
    rng = np.random.default_rng(3)
    values = np.concatenate([rng.normal(size=20000) * 10.0 ** rng.integers(-47, 40, 20000),
                             [0.0, -0.0, 1e-300, -1e-300, 1e-46, -1e-46, 3.5e38, -3.5e38, 1.0, -1.0,
                              2.0 ** -149, -2.0 ** -149, 2.0 ** -150, -2.0 ** -150, 1 + 2.0 ** -30]])
    out = np.zeros((len(values), 8), np.float32)
    flat_bvh._round_out(np.stack([values] * 6, axis=1), out, out.view(np.int32), 4)
    for column, toward in ((0, -np.inf), (4, np.inf)):
        with np.errstate(over="ignore"):     # beyond float32: inf, stepped back to its largest
            expected = values.astype(np.float32)
        wrong_side = (expected.astype(np.float64) > values) if toward < 0 else (expected.astype(np.float64) < values)
        expected[wrong_side] = np.nextafter(expected[wrong_side], np.float32(toward))
        assert np.array_equal(out[:, column].view(np.int32), expected.view(np.int32))
    assert (out[:, 0] <= values).all() and (out[:, 4] >= values).all()


def test_bad_boxes_are_refused():
    with pytest.raises(ValueError, match="not finite"):
        flat_bvh.build(np.array([[0.0, np.nan, 0.0]]), np.array([[1.0, 1.0, 1.0]]))
    with pytest.raises(ValueError, match=r"\(P, 3\)"):
        flat_bvh.build(np.zeros((0, 3)), np.zeros((0, 3)))
    with pytest.raises(ValueError, match=r"\(P, 6\) float64"):
        flat_bvh.build_rows(np.zeros((4, 3)))
    with pytest.raises(ValueError, match="not finite"):
        flat_bvh.build_rows(np.array([[0.0, 0.0, 0.0, 1.0, np.inf, 1.0]]))


def test_a_meshs_rows_are_its_triangles_boxes_then_the_others():
    """triangle_rows, what compile_scene builds from: each face's box, then the boxes given
    (spheres, instances), and the tree over them is build's over the same boxes."""
    mesh = icosphere(2)
    corners = mesh.vertices[mesh.faces]
    lo, hi = corners.min(axis=1), corners.max(axis=1)
    extra_lo, extra_hi = np.array([[5.0, 5.0, 5.0]]), np.array([[6.0, 7.0, 8.0]])
    rows = flat_bvh.triangle_rows(mesh.vertices, mesh.faces, extra_lo, extra_hi)
    assert np.array_equal(rows, np.concatenate([np.hstack([lo, hi]), np.hstack([extra_lo, extra_hi])]))
    tree = flat_bvh.build_rows(rows)
    same = flat_bvh.build(np.concatenate([lo, extra_lo]), np.concatenate([hi, extra_hi]))
    assert np.array_equal(tree.nodes.view(np.int32), same.nodes.view(np.int32))
    assert np.array_equal(tree.order, same.order) and tree.order.max() == len(mesh.faces)


def test_a_mesh_takes_at_most_64_bytes_per_triangle_with_its_bvh_in_float32():
    mesh = icosphere(5)                                          # 20480 faces
    flat = compile_scene(scene_of(mesh), "float32")
    per_triangle = flat.mesh.nbytes / len(mesh.faces)
    assert per_triangle <= 64, per_triangle


# --- spheres in the BVH ----------------------------------------------------------------

def many_spheres(count: int, seed: int = 11) -> Scene:
    """``count`` spheres, some mirrors, over a floor, under a point light: shadow and
    secondary rays meet spheres through the BVH when count >= BVH_MIN_SPHERES."""
    rng = random.Random(seed)
    scene = scene_of(Plane(Float3(0, -1, 0), Float3(0, 1, 0), Float3(0.8), Matte()))
    for i in range(count):
        center = Float3(rng.uniform(-1, 1), rng.uniform(-0.8, 0.8), rng.uniform(-1, 1))
        scene.shapes.append(Sphere(center, rng.uniform(0.05, 0.2), Float3(0.2, 0.5, 0.9),
                                   Reflective() if i % 3 == 0 else Matte()))
    scene.lights.append(PointLight(Float3(0.5, 3, 0.5), Float3(10.0)))
    return scene


def test_a_scene_of_many_spheres_finds_them_through_the_bvh_and_a_few_in_a_loop():
    from rtfgu.layout import BVH_MIN_SPHERES

    many = compile_scene(many_spheres(BVH_MIN_SPHERES))
    assert many.mesh is not None and many.mesh.spheres and "bvh_spheres" in many.features
    assert len(many.mesh.faces) == BVH_MIN_SPHERES and (many.mesh.faces[:, 0] == -1).all()
    few = compile_scene(many_spheres(BVH_MIN_SPHERES - 1))
    assert few.mesh is None and "bvh_spheres" not in few.features


def test_spheres_seen_only_by_primary_rays_from_a_pinhole_stay_in_the_culled_loop():
    """Without shadow rays, mirrors or path tracing, a pinhole's per-tile culling finds the
    spheres: no BVH. The same spheres under another camera, or casting shadows, are in it."""
    from rtfgu import PinholeCamera
    from rtfgu.layout import BVH_MIN_SPHERES

    def spheres(camera, shadows):
        scene = Scene(camera)
        rng = random.Random(5)
        for _ in range(BVH_MIN_SPHERES * 2):
            center = Float3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))
            scene.shapes.append(Sphere(center, 0.1, Float3(0.5), Material()))
        if shadows:
            scene.shapes[0].material = Matte()
            scene.lights.append(PointLight(Float3(0, 3, 0), Float3(1.0)))
        return scene

    pinhole = PinholeCamera(Float3(0, 0, 5), Float3(0, 0, 0), Float3(0, 1, 0), 1.0)
    flat = compile_scene(spheres(pinhole, shadows=False))
    assert flat.mesh is None and "bvh_spheres" not in flat.features
    lit = compile_scene(spheres(pinhole, shadows=True))
    assert lit.mesh is not None and lit.mesh.spheres
    orthographic = OrthographicCamera(-1.0, 1.0, -1.0, 1.0)
    assert compile_scene(spheres(orthographic, shadows=False)).mesh.spheres


def test_spheres_in_the_bvh_give_the_lecture_layers_hits_shadows_and_reflections(path):
    from rtfgu.layout import BVH_MIN_SPHERES

    scene = many_spheres(BVH_MIN_SPHERES + 8)
    rng = random.Random(17)
    rays = []
    for i in range(150):                  # from above, toward a sphere (and past it) or the floor
        o = (rng.uniform(-2, 2), 2.5, rng.uniform(-2, 2))
        target = scene.shapes[1 + i % (len(scene.shapes) - 1)].center
        d = (target.x + rng.uniform(-0.2, 0.2) - o[0], target.y - o[1], target.z + rng.uniform(-0.2, 0.2) - o[2])
        rays.append((o, d, 0.0, math.inf))
    want = path.reference.trace(scene, rays)
    got = path.trace(scene, rays)
    sphere_hits = 0
    for ray, a, b in zip(rays, want, got):
        assert [x.shape for x in a] == [y.shape for y in b], (path, ray)
        for x, y in zip(a, b):
            assert y.color == pytest.approx(x.color, rel=2e-3 if path.precision == "float32" else 1e-12, abs=1e-5)
        sphere_hits += sum(1 for x in a if x.shape not in (None, 0))
    assert sphere_hits > 60


def test_a_textured_mesh_takes_its_colour_at_the_faces_barycentrics(path):
    from rtfgu.textures import Checker

    sphere = trimesh.creation.icosphere(subdivisions=1)
    checker = Checker(Float3(1.0, 0.25, 0.0), Float3(0.0, 0.5, 1.0), 0.25)
    mesh = Mesh(np.asarray(sphere.vertices), np.asarray(sphere.faces), GREY,
                normals=np.asarray(sphere.vertex_normals), material=Matte(cd=checker))
    scene = scene_of(mesh)
    scene.lights.append(PointLight(Float3(2, 3, 4), Float3(20.0)))
    rays = random_rays(60, seed=23)
    want = path.reference.trace(scene, rays)
    colours = set()
    for ray, a, b in zip(rays, want, path.trace(scene, rays)):
        assert a[0].shape == b[0].shape, (path, ray)
        if a[0].shape is not None:
            colours.add(tuple(round(c, 3) for c in a[0].color))
            assert b[0].color == pytest.approx(a[0].color, rel=2e-3 if path.precision == "float32" else 1e-12, abs=1e-5)
    assert len(colours) > 5
