"""Triangle meshes (Suffern ch. 23) and OBJ loading: a mesh triangle is hit exactly where
``Triangle`` is, smooth normals interpolate, load_obj reads polygons, materials and normals
and names the file, line and statement of bad input, and the shipped meshes load."""
from __future__ import annotations

import itertools
import math
import random
import warnings

import numpy as np
import pytest

import rtfgu
from rtfgu import Float3, HitInfo, Material, Ray, Scene, Triangle, load_obj, normalize
from rtfgu.obj import mesh_path
from rtfgu.shapes.mesh import FlatMeshTriangle, Mesh, MeshTriangle, SmoothMeshTriangle

GREY = (0.5, 0.5, 0.5)


def components(v: Float3) -> tuple:
    return (v.x, v.y, v.z)


def write(folder, name: str, text: str):
    path = folder / name
    path.write_text(text)
    return path


# --- Mesh and its triangles ------------------------------------------------------------

# An octahedron with dyadic corners, slightly squashed, faces wound outwards.
OCTAHEDRON_VERTICES = [(1.5, 0, 0), (-1.25, 0, 0), (0, 0.75, 0), (0, -1, 0), (0, 0, 1.125), (0, 0, -0.5)]
OCTAHEDRON_FACES = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]


def octahedron(**kwargs) -> Mesh:
    return Mesh(np.array(OCTAHEDRON_VERTICES, dtype=float), np.array(OCTAHEDRON_FACES), GREY, **kwargs)


def random_rays(count: int, seed: int = 7):
    rng = random.Random(seed)
    for _ in range(count):
        origin = Float3(*(rng.uniform(-3, 3) for _ in range(3)))
        target = Float3(*(rng.uniform(-1.2, 1.2) for _ in range(3)))
        yield origin, target - origin


def test_a_mesh_triangle_is_the_watertight_test_with_the_normal_and_texcoord_of_triangle():
    from rtfgu.robust import intersect_triangle_watertight

    mesh = octahedron()
    hits = 0
    for shape, (origin, direction) in itertools.product(mesh.triangles(), random_rays(300)):
        v0, v1, v2 = (Float3(*mesh.vertices[i]) for i in (shape.index0, shape.index1, shape.index2))
        triangle = Triangle(v0, v1, v2, GREY)
        ours, watertight, slide = Ray(origin, direction), Ray(origin, direction), Ray(origin, direction)
        hit = shape.intersect_p(ours)
        assert hit == intersect_triangle_watertight(watertight, v0, v1, v2)
        assert ours.tmax == watertight.tmax                     # bit for bit, inf on a miss
        assert hit == triangle.intersect_p(slide)               # no ray of these passes an edge
        if hit:
            hits += 1
            assert ours.tmax == pytest.approx(slide.tmax, rel=1e-14)
            p = ours(ours.tmax)
            assert components(shape.normal_at(p)) == components(triangle.normal_at(p))
            assert shape.texcoord(p) == triangle.texcoord(p)
    assert hits > 100


def test_mesh_triangles_are_shapes_with_the_faces_colour_and_material():
    colors = np.array([(i / 8, 0.25, 0.5) for i in range(8)])
    materials = [rtfgu.Matte() for _ in range(8)]
    mesh = octahedron()
    mesh = Mesh(mesh.vertices, mesh.faces, colors, material=materials)
    triangles = mesh.triangles()
    assert [type(t) for t in triangles] == [FlatMeshTriangle] * 8
    for i, t in enumerate(triangles):
        assert isinstance(t, rtfgu.Shape) and t.mesh is mesh and t.face == i
        assert (t.index0, t.index1, t.index2) == OCTAHEDRON_FACES[i]
        assert components(t.color) == tuple(colors[i]) and t.material is materials[i]
    one = rtfgu.Phong(cs=(0.1, 0.1, 0.1), exp=10)
    assert all(t.material is one for t in octahedron(material=one).triangles())
    with pytest.raises(TypeError):
        MeshTriangle(mesh, 0)                                    # the normal is the subclass's


def test_the_intersection_shrinks_tmax_like_every_shape():
    shape = octahedron().triangles()[0]                          # (1.5, 0, 0), (0, 0.75, 0), (0, 0, 1.125)
    ray = Ray(Float3(0, 0, 0), Float3(1, 1, 1))
    assert shape.intersect_p(ray)
    t = ray.tmax
    assert 0 < t < math.inf
    assert not shape.intersect_p(Ray(Float3(0, 0, 0), Float3(1, 1, 1), 0.0, t))   # [tmin, tmax)


def test_smooth_normals_are_the_vertex_normals_at_the_vertices():
    given = np.array([(1, 0, 0), (-2, 0, 0), (0, 3, 0), (0, -1, 0), (0, 0, 1), (0.5, 0.5, -1)])
    mesh = octahedron(normals=given)
    assert np.allclose(np.linalg.norm(mesh.normals, axis=1), 1.0, rtol=0, atol=1e-15)
    for shape in mesh.triangles():
        assert isinstance(shape, SmoothMeshTriangle)
        for i in (shape.index0, shape.index1, shape.index2):
            at_vertex = shape.normal_at(Float3(*mesh.vertices[i]))
            assert components(at_vertex) == components(normalize(Float3(*mesh.normals[i])))
            assert np.allclose(components(at_vertex), given[i] / np.linalg.norm(given[i]),
                               rtol=0, atol=1e-15)


def test_smooth_normals_interpolate_with_the_barycentrics_and_are_unit():
    normals = np.array([(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)], float)
    mesh = octahedron(normals=normals)
    rng = random.Random(3)
    for shape in mesh.triangles():
        a, b, c = (np.array(mesh.vertices[i]) for i in (shape.index0, shape.index1, shape.index2))
        n0, n1, n2 = (mesh.normals[i] for i in (shape.index0, shape.index1, shape.index2))
        for _ in range(20):
            beta, gamma = rng.random() / 2, rng.random() / 2
            p = Float3(*((1 - beta - gamma) * a + beta * b + gamma * c))
            n = components(shape.normal_at(p))
            expected = (1 - beta - gamma) * n0 + beta * n1 + gamma * n2
            assert math.isclose(math.hypot(*n), 1.0, abs_tol=1e-15)
            assert np.allclose(n, expected / np.linalg.norm(expected), rtol=0, atol=1e-12)
        mid = Float3(*((a + b) / 2))                             # an edge's midpoint: n0 + n1
        assert np.allclose(components(shape.normal_at(mid)), (n0 + n1) / np.linalg.norm(n0 + n1),
                           rtol=0, atol=1e-15)


def test_smooth_normals_that_cancel_give_the_flat_normal():
    vertices = np.array([(0, 0, 0), (1, 0, 0), (0, 1, 0)], float)
    normals = np.array([(0, 0, 1), (0, 0, -1), (0, 0, 1)], float)
    shape = Mesh(vertices, [(0, 1, 2)], GREY, normals=normals).triangles()[0]
    n = shape.normal_at(Float3(0.5, 0, 0))                       # n0 / 2 + n1 / 2 = 0
    assert components(n) == (0.0, 0.0, 1.0)


@pytest.mark.parametrize("make,field", [
    (lambda: Mesh([(0, 0, 0), (1, 0, 0)], [(0, 1, 2)], GREY), r"Mesh.faces\[0\] = \(0, 1, 2\) refers to a vertex"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, -1)], GREY), r"Mesh.faces\[0\]"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 1, 0)], [(0, 1, 3), (0, 1, 2)], GREY),
     r"Mesh.faces\[1\] = \(0, 1, 2\) spans zero area"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 1)], GREY), r"Mesh.faces\[0\].*zero area"),
    (lambda: Mesh([(0, 0, 0), (1, math.nan, 0), (0, 1, 0)], [(0, 1, 2)], GREY), r"Mesh.vertices\[1\] must be finite"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], np.zeros((0, 3), int), GREY), r"Mesh.faces is empty"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0.0, 1.0, 2.0)], GREY), r"Mesh.faces must hold integer"),
    (lambda: Mesh([(0, 0), (1, 0), (0, 1)], [(0, 1, 2)], GREY), r"Mesh.vertices must have shape"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)], GREY, normals=[(0, 0, 1)] * 2),
     r"Mesh.normals must have one row per vertex"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)], GREY, normals=[(0, 0, 1), (0, 0, 0), (0, 0, 1)]),
     r"Mesh.normals\[1\] is the zero vector"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)], GREY, uvs=[(0, 0)] * 2),
     r"Mesh.uvs must have one \(u, v\) row per vertex \(3, 2\)"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)], GREY, uvs=[(0, 0), (1, math.nan), (0, 1)]),
     r"Mesh.uvs\[1\] must be finite"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)], GREY, uvs="uv"), r"Mesh.uvs must be an \(n, 2\)"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)], [GREY, GREY]), r"Mesh.color must be one colour"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)], (math.inf, 0, 0)), r"Mesh.color\[0\] must be finite"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)], GREY, material=[Material()] * 2),
     r"Mesh.material must be one Material or one per face"),
    (lambda: Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)], GREY, material=["lambertian"]),
     r"Mesh.material\[0\] must be a Material"),
])
def test_bad_mesh_input_names_the_field(make, field):
    with pytest.raises(ValueError, match=field):
        make()


# --- a shared edge: the closest-hit loop reports it once, never zero times ----------------

# Two triangles of one mesh sharing the edge (1, 0, 0)-(0, 1, 0), both facing +z.
SQUARE = Mesh(np.array([(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)], float),
              np.array([(0, 1, 2), (1, 3, 2)]), GREY)
EDGE_POINTS = [(0.5, 0.5), (0.25, 0.75), (0.125, 0.875), (0.9375, 0.0625), (1.0, 0.0), (0.0, 1.0)]
# Dyadic directions: every product in the 02562 test is exact, so the ray meets the edge exactly.
DIRECTIONS = [(0, 0, -1), (0.25, 0.125, -1), (-0.5, 0.25, -0.5), (0.0625, -0.375, -2)]


@pytest.mark.parametrize("point", EDGE_POINTS)
@pytest.mark.parametrize("direction", DIRECTIONS)
def test_a_shared_edge_is_hit_by_exactly_one_triangle(point, direction):
    x, y = point
    d = Float3(*direction)
    origin = Float3(x, y, 0) - d * 2.0                           # reaches the edge at t = 2
    for order in (SQUARE.triangles(), SQUARE.triangles()[::-1]):
        for shape in order:                                      # each alone: no crack
            ray = Ray(origin, d)
            assert shape.intersect_p(ray) and ray.tmax == 2.0
        ray = Ray(origin, d)
        reported = [shape for shape in order if shape.intersect_p(ray)]
        assert reported == [order[0]] and ray.tmax == 2.0        # the earlier shape wins the tie
        scene = Scene()
        scene.shapes = list(order)
        hit = HitInfo()
        assert scene.intersect(Ray(origin, d), hit) and hit.dist == 2.0
        assert components(hit.normal) == (0.0, 0.0, 1.0)


def test_the_flat_layout_holds_each_mesh_once_with_its_faces_in_bvh_order():
    from rtfgu.layout import compile_scene

    scene = Scene(rtfgu.PinholeCamera(Float3(0, 0, 3), Float3(0, 0, 0), Float3(0, 1, 0), 1.0, 1.0))
    scene.shapes = [rtfgu.Sphere(Float3(0, 0, -5), 1.0, GREY)] + SQUARE.triangles() + octahedron().triangles()
    flat = compile_scene(scene, "float32")
    assert "mesh" in flat.features and flat.mesh.vertices.dtype == np.float32
    assert len(flat.mesh.vertices) == 4 + 6 and flat.mesh.normals is None
    rows = flat.mesh.faces
    assert sorted(rows[:, 3]) == list(range(0, 11))              # every face and the sphere
    assert rows[rows[:, 3] == 0].tolist() == [[-1, 0, 0, 0]] and flat.mesh.spheres  # with a mesh, in the BVH
    faces = rows[rows[:, 0] >= 0]
    for row in faces:                                            # each face names its own vertices
        shape = scene.shapes[row[3]]
        first = 0 if shape.mesh is SQUARE else 4
        assert tuple(row[:3] - first) == (shape.index0, shape.index1, shape.index2)
    assert flat.mesh.build_seconds > 0
    again = compile_scene(scene, "float32")                      # the scene's BVH is cached
    assert again.mesh.bvh is flat.mesh.bvh and again.mesh.build_seconds == 0.0
    assert compile_scene(scene, "float64").mesh.build_seconds > 0  # per precision


# --- load_obj -----------------------------------------------------------------------------

def test_load_obj_triangulates_polygons_as_fans_keeping_their_winding(tmp_path):
    path = write(tmp_path, "polygons.obj", """\
# a unit square, a pentagon and a triangle, all facing +z
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 3 0 0
v 4 0 0
v 4.5 1 0
v 3.5 2 0
v 2.5 1 0
v 6 0 0
v 7 0 0
v 6 1 0
f 1 2 3 4
f 5 6 7 8 9
f 10 11 12
""")
    mesh = load_obj(path)
    assert mesh.num_triangles == 2 + 3 + 1 and mesh.normals is None
    v, f = mesh.vertices, mesh.faces
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    assert (n[:, 2] > 0).all() and (n[:, :2] == 0).all()        # wound as the polygons
    assert n[:, 2].sum() / 2 == 1 + 2.5 + 0.5                   # the areas of the polygons
    pentagon = [tuple(v[i]) for t in f for i in t if v[i][0] >= 2.5 and v[i][0] < 5]
    assert set(pentagon) == {(3, 0, 0), (4, 0, 0), (4.5, 1, 0), (3.5, 2, 0), (2.5, 1, 0)}
    assert all(type(t) is FlatMeshTriangle for t in mesh.triangles())


def test_load_obj_reads_a_quads_only_file(tmp_path):
    path = write(tmp_path, "quads.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
                                        "f 1 2 3 4\nf 2 5 6 3\n")
    mesh = load_obj(path)
    assert mesh.num_triangles == 4
    corners = sorted(tuple(sorted(tuple(mesh.vertices[i]) for i in t)) for t in mesh.faces)
    # the fans around each quad's first corner: (1, 2, 3), (1, 3, 4) and (2, 5, 6), (2, 6, 3)
    assert corners == sorted([((0, 0, 0), (1, 0, 0), (1, 1, 0)), ((0, 0, 0), (0, 1, 0), (1, 1, 0)),
                              ((1, 0, 0), (2, 0, 0), (2, 1, 0)), ((1, 0, 0), (1, 1, 0), (2, 1, 0))])


MATERIALS_OBJ = """\
mtllib box.mtl
v 0 0 0
v 1 0 0
v 0 1 0
v 2 0 0
v 3 0 0
v 2 1 0
v 4 0 0
v 5 0 0
v 4 1 0
v 6 0 0
v 7 0 0
v 6 1 0
f 1 2 3
usemtl red
f 4 5 6
usemtl lamp
f 7 8 9
usemtl red
f 10 11 12
"""
MATERIALS_MTL = """\
# Kd is the colour, Ke the emission
newmtl red
Ka 0 0 0
Kd 0.75 0.125 0.0625
illum 1
newmtl lamp
Kd 1 1 1
Ke 4 2 1
newmtl unused
Kd 0.5
"""


def colour_at(mesh: Mesh, x: float) -> tuple:
    """The colour of the one triangle whose centroid is left of x and within 1 of it."""
    centroids = mesh.vertices[mesh.faces].mean(axis=1)
    (i,) = np.flatnonzero((centroids[:, 0] < x) & (centroids[:, 0] > x - 1))
    return tuple(mesh.colors[i]), mesh.materials[i]


def test_load_obj_gives_each_face_its_mtl_material(tmp_path):
    write(tmp_path, "box.mtl", MATERIALS_MTL)
    base = rtfgu.Matte()
    mesh = load_obj(write(tmp_path, "box.obj", MATERIALS_OBJ), material=base, default_color=(0.25, 0.5, 1))
    assert mesh.num_triangles == 4
    assert colour_at(mesh, 1) == ((0.25, 0.5, 1), base)         # before any usemtl: the default
    assert colour_at(mesh, 3) == ((0.75, 0.125, 0.0625), base)
    assert colour_at(mesh, 7) == ((0.75, 0.125, 0.0625), base)   # red again, after the lamp
    lamp_color, lamp = colour_at(mesh, 5)
    assert lamp_color == (1, 1, 1) and lamp is not base
    assert lamp.shader == rtfgu.LAMBERTIAN and components(lamp.emission) == (4, 2, 1)
    assert components(base.emission) == (0, 0, 0)
    shapes = mesh.triangles()
    assert [components(s.color) for s in shapes] == [tuple(c) for c in mesh.colors]


def test_load_obj_keeps_the_indices_of_objects_that_define_their_vertices_as_they_go(tmp_path):
    write(tmp_path, "box.mtl", MATERIALS_MTL)
    path = write(tmp_path, "two.obj", """\
mtllib box.mtl
o first
v 0 0 0
v 1 0 0
v 0 1 0
usemtl red
f 1 2 3
o second
v 5 0 0
v 6 0 0
v 5 1 0
usemtl lamp
f 4 5 6
o third
v 9 0 0
v 10 0 0
v 9 1 0
usemtl red
f 7 8 9
""")
    mesh = load_obj(path)
    red, lamp = (0.75, 0.125, 0.0625), (1.0, 1.0, 1.0)
    found = sorted((tuple(map(tuple, mesh.vertices[f])), tuple(c)) for f, c in zip(mesh.faces, mesh.colors))
    assert found == [(((0, 0, 0), (1, 0, 0), (0, 1, 0)), red), (((5, 0, 0), (6, 0, 0), (5, 1, 0)), lamp),
                     (((9, 0, 0), (10, 0, 0), (9, 1, 0)), red)]


def test_load_obj_reads_vertex_normals_for_smooth_shading(tmp_path):
    path = write(tmp_path, "normals.obj", """\
v 0 0 0
v 1 0 0
v 0 1 0
v 1 1 0
vt 0 0
vt 1 0
vt 0 1
vn 0 0 2
vn 0.6 0 0.8
vn 0 -0.6 0.8
f 1/1/1 2/2/2 3/3/3
f 2/2/2 4/1/1 3/3/3
""")
    mesh = load_obj(path)
    assert mesh.normals is not None and mesh.num_triangles == 2
    expected = {(0, 0, 0): (0, 0, 1), (1, 0, 0): (0.6, 0, 0.8), (0, 1, 0): (0, -0.6, 0.8), (1, 1, 0): (0, 0, 1)}
    for shape in mesh.triangles():
        assert isinstance(shape, SmoothMeshTriangle)
        for i in (shape.index0, shape.index1, shape.index2):
            p = tuple(mesh.vertices[i])
            assert np.allclose(components(shape.normal_at(Float3(*p))), expected[p], rtol=0, atol=1e-15)


def test_uv_mesh_triangles_interpolate_their_corners_uvs_exactly():
    """Suffern's UV mesh triangles: (u, v) = (1 - beta - gamma) uv0 + beta uv1 + gamma uv2,
    checked against fractions at dyadic points (every product exact in binary)."""
    from fractions import Fraction as F
    corners = [(0, 0, 0), (2, 0, 0), (0, 4, 0)]
    uvs = [(0.25, 0.5), (0.75, 0.5), (0.25, 1.5)]
    mesh = Mesh(np.array(corners, float), np.array([(0, 1, 2)]), GREY, uvs=uvs)
    face = mesh.triangles()[0]
    for x, y in [(0.5, 1.0), (0.25, 0.5), (1.0, 0.0), (0.0, 4.0), (1.0, 2.0)]:
        beta, gamma = F(x) / 2, F(y) / 4
        alpha = 1 - beta - gamma
        exact = tuple(alpha * F(uvs[0][k]) + beta * F(uvs[1][k]) + gamma * F(uvs[2][k]) for k in range(2))
        assert face.texcoord(Float3(x, y, 0.0)) == exact
        assert face.barycentric(Float3(x, y, 0.0)) == (beta, gamma)
    assert Mesh(np.array(corners, float), np.array([(0, 1, 2)]), GREY).triangles()[0].texcoord(
        Float3(0.5, 1.0, 0.0)) == (0.25, 0.25)            # without uvs: the barycentrics


def test_load_obj_reads_texture_coordinates_per_corner(tmp_path):
    """A position with two vt is two vertices at one place (the faces still share the edge);
    v/vt and v/vt/vn give uvs, v and v//vn none."""
    path = write(tmp_path, "quad.obj", """\
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vt 0.5 0.5 0.0
f 1/1 2/2 3/3
f 1/5 3/3 4/4
""")
    mesh = load_obj(path)
    assert mesh.num_vertices == 5 and mesh.normals is None
    at = {(tuple(mesh.vertices[i]), tuple(mesh.uvs[i])) for i in range(5)}
    assert at == {((0, 0, 0), (0, 0)), ((1, 0, 0), (1, 0)), ((1, 1, 0), (1, 1)), ((0, 1, 0), (0, 1)),
                  ((0, 0, 0), (0.5, 0.5))}
    first, second = mesh.triangles()
    assert first.texcoord(Float3(0.75, 0.25, 0.0)) == (0.75, 0.25)
    # (0.25, 0.75) on the second face is beta 0.25 toward (1, 1) and gamma 0.5 toward (0, 1):
    # 0.25 (0.5, 0.5) + 0.25 (1, 1) + 0.5 (0, 1).
    assert second.texcoord(Float3(0.25, 0.75, 0.0)) == (0.375, 0.875)
    plain = write(tmp_path, "plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n")
    assert load_obj(plain).uvs is None


def test_the_globe_is_closed_outward_and_textured():
    mesh = load_obj(mesh_path("globe.obj"))
    v, f = mesh.vertices, mesh.faces
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    assert (np.einsum("ij,ij->i", n, v[f].mean(axis=1)) > 0).all()
    assert mesh.uvs is not None and mesh.normals is not None
    assert mesh.uvs.min() == 0.0 and mesh.uvs.max() == 1.0
    # Closed: every edge, by position, is shared by exactly two faces.
    key = {tuple(p): k for k, p in enumerate(np.unique(v, axis=0).tolist())}
    ids = np.array([[key[tuple(v[i])] for i in face] for face in f.tolist()])
    edges = np.sort(np.concatenate([ids[:, [0, 1]], ids[:, [1, 2]], ids[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    assert (counts == 2).all()


def test_load_obj_reads_negative_indices_comments_tabs_and_crlf(tmp_path):
    path = tmp_path / "messy.obj"
    path.write_bytes(b"# made by hand\r\n  v\t0 0 0\r\nv 1 0 0 # x\r\nv 0 1 0\r\n"
                     b"vn 0 0 1\r\ng tri\r\ns off\r\no thing\r\nf -3//1 -2//1\t-1//1\r\n")
    mesh = load_obj(path)
    assert mesh.num_triangles == 1 and mesh.normals is not None
    assert sorted(map(tuple, mesh.vertices[mesh.faces[0]])) == [(0, 0, 0), (0, 1, 0), (1, 0, 0)]


def test_load_obj_may_drop_zero_area_triangles_with_a_warning(tmp_path):
    path = write(tmp_path, "flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 4\nf 1 2 3\n")
    with pytest.warns(UserWarning, match="dropped 1 triangles of zero area"):
        mesh = load_obj(path, drop_degenerate=True)
    assert mesh.num_triangles == 1


# Each bad input: the file's text, the line and the statement the message names, and a word of it.
BAD_OBJ = [
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", 4, "'f'", "v index 4 is out of range"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 -2 -1\n", 4, "'f'", "v index -4 is out of range"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n", 5, "'f'", "vn index 2 is out of range"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/9\n", 5, "'f'", "vt index 9 is out of range"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", 4, "'f'", "0 is no index"),
    ("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 4\nf 1 2 3\n", 6, "'f'", "zero area"),
    ("v 0 0 0\nv 1 0 0\nv 1 0 0\nf 1 2 3\n", 4, "'f'", "zero area"),
    ("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", 2, "'v'", "not finite"),
    ("v 0 0 0\nv 1 0 0\nv 0 1e999 0\nf 1 2 3\n", 3, "'v'", "not finite"),
    ("v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", 2, "'v'", "3, 4 or 6 numbers expected, got 2"),
    ("v 0 0 0\nv 1 0 x\nv 0 1 0\nf 1 2 3\n", 2, "'v'", "'x', is not a number"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0\nf 1 2 3\n", 4, "'vn'", "3 numbers expected"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n", 4, "'vn'", "zero vector"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", 4, "'f'", "at least 3 corners"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", 4, "'f'", "corner 3, 'x'"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1 2 3\nf 1//1 2//1 3//1\n", 6, "'f'", "one corner format"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\ncstype bspline\nf 1 2 3\n", 4, "'cstype'", "not a statement"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n", 4, "'usemtl'", "no mtllib"),
    ("mtllib nowhere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", 1, "'mtllib'", "no such material library"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nv 1 1 0\nf -1 -2 -3\n", 6, "'f'", "negative (relative) indices"),
    ("v 0 0 0\nv 1 0 0\n\\\nv 0 1 0\nf 1 2 3\n", 3, "text", "continued"),
]


@pytest.mark.parametrize("text,line,field,words", BAD_OBJ, ids=[b[3] for b in BAD_OBJ])
def test_bad_obj_input_names_the_file_line_and_statement(tmp_path, text, line, field, words):
    path = write(tmp_path, "bad.obj", text)
    with pytest.raises(ValueError) as error:
        load_obj(path)
    message = str(error.value)
    assert str(path) in message
    assert "line %d, %s" % (line, field) in message, message
    assert words in message, message


def test_bad_mtl_input_names_the_mtl_file_and_line(tmp_path):
    obj = write(tmp_path, "m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n")
    for mtl, line, words in [("newmtl a\nKd 1 x 0\n", 2, "r g b numbers expected"),
                             ("newmtl a\nKd 1 nan 0\n", 2, "three finite numbers >= 0"),
                             ("Kd 1 1 1\nnewmtl a\n", 1, "before any newmtl"),
                             ("newmtl a\nnewmtl a\n", 2, "defined twice"),
                             ("newmtl b\nKd 1 1 1\n", None, "material 'a' is not in the material library")]:
        write(tmp_path, "m.mtl", mtl)
        with pytest.raises(ValueError) as error:
            load_obj(obj)
        message = str(error.value)
        assert words in message, message
        if line is not None:
            assert "%s, line %d" % (tmp_path / "m.mtl", line) in message, message
        else:
            assert "%s, line 5, 'usemtl'" % obj in message, message


@pytest.mark.parametrize("text,words", [
    ("# nothing but a comment\n", "no faces"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\n", "no faces"),
    ("", "no faces"),
])
def test_a_file_without_faces_is_an_empty_mesh(tmp_path, text, words):
    path = write(tmp_path, "empty.obj", text)
    with pytest.raises(ValueError, match=words) as error:
        load_obj(path)
    assert str(path) in str(error.value)


def test_a_missing_file_is_named(tmp_path):
    with pytest.raises(ValueError, match="no such file .*missing.obj"):
        load_obj(tmp_path / "missing.obj")


# --- the shipped meshes -------------------------------------------------------------------

@pytest.mark.parametrize("name,triangles", [("bunny.obj", 3674), ("teapot.obj", 992), ("cornell_box.obj", 46)])
def test_the_shipped_meshes_load_with_finite_non_degenerate_triangles(name, triangles):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        mesh = load_obj(mesh_path(name))
    assert mesh.num_triangles == triangles
    v = mesh.vertices[mesh.faces]
    assert np.isfinite(v).all()
    area = np.linalg.norm(np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0]), axis=1) / 2
    assert area.min() > 0
    shapes = mesh.triangles()                                    # Triangle refuses none of them
    assert len(shapes) == triangles and all(type(s) is FlatMeshTriangle for s in shapes)


def test_the_closed_bunny_faces_outwards():
    mesh = load_obj(mesh_path("bunny.obj"))
    a, b, c = (mesh.vertices[mesh.faces[:, k]] for k in range(3))
    assert np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6 > 0   # positive signed volume
    edges = np.sort(np.concatenate([mesh.faces[:, [0, 1]], mesh.faces[:, [1, 2]], mesh.faces[:, [2, 0]]]), axis=1)
    assert (np.unique(edges, axis=0, return_counts=True)[1] == 2).all()   # closed: two faces per edge


def test_the_cornell_box_has_its_walls_blocks_and_light():
    mesh = load_obj(mesh_path("cornell_box.obj"))
    white, red, green = (0.885809, 0.698859, 0.666422), (0.570068, 0.0430135, 0.0443706), (0.105421, 0.37798, 0.076425)
    colours = [tuple(c) for c in mesh.colors]
    assert colours.count(red) == 2 and colours.count(green) == 2
    assert colours.count(white) == 2 + 16 + 2 + 10 + 10 + 2       # floor, ceiling, back, blocks, light
    v = mesh.vertices[mesh.faces]
    lit = [i for i, m in enumerate(mesh.materials) if components(m.emission) != (0, 0, 0)]
    assert len(lit) == 2 and all(components(mesh.materials[i].emission) == (18.387, 13.9873, 6.75357) for i in lit)
    light = v[lit].reshape(-1, 3)
    assert (light[:, 1] == 548.8).all()
    assert {tuple(p) for p in light[:, [0, 2]]} == {(213, 227), (343, 227), (343, 332), (213, 332)}
    # the ceiling and the light cover 556 x 559.2 at y = 548.8 once, facing down
    top = np.flatnonzero((v[:, :, 1] == 548.8).all(axis=1))
    n = np.cross(v[top, 1] - v[top, 0], v[top, 2] - v[top, 0])
    assert (n[:, 1] < 0).all() and -n[:, 1].sum() / 2 == pytest.approx(556 * 559.2)
    # looking up from the middle of the floor: the light; along +z at mid-height: the back wall
    scene = Scene()
    scene.shapes = mesh.triangles()
    hit = HitInfo()
    assert scene.intersect(Ray(Float3(278, 1, 279.6), Float3(0, 1, 0)), hit)
    assert hit.dist == pytest.approx(547.8) and components(hit.emission) == (18.387, 13.9873, 6.75357)
    hit = HitInfo()
    assert scene.intersect(Ray(Float3(278, 500, 1), Float3(0, 0, 1)), hit)
    assert hit.dist == pytest.approx(558.2) and hit.normal.z == pytest.approx(-1)


def test_load_obj_and_mesh_are_exported():
    assert rtfgu.load_obj is load_obj and rtfgu.Mesh is Mesh
    assert "Mesh" in rtfgu.__all__ and "load_obj" in rtfgu.__all__
