"""The lecture layer's Matrix and Instance (Suffern ch. 20-21): the matrices each call
composes, the inverse against the forward matrix, the hit, normal, (u, v) and box of an
instance, instances of a Mesh and of an Instance. The contract cases of the instance kind
on every path are in test_contract.py."""
from __future__ import annotations

import math

import numpy as np
import pytest

from rtfgu import (Box, Float3, HitInfo, Instance, Material, Matrix, Matte, Mesh, OrthographicCamera, Ray,
                   Rectangle, Scene, Sphere)

GREY = (0.5, 0.25, 1.0)


def as_array(matrix: Matrix) -> np.ndarray:
    return np.array(matrix.m)


def test_matrix_is_the_identity_and_multiplies_as_the_book():
    a = Matrix([[1, 2, 3, 4], [5, 6, 7, 8], [9, 10, 11, 12], [0, 0, 0, 1]])
    b = Matrix([[2, 0, 1, -1], [0, 3, 0, 2], [1, 1, 1, 0], [0, 0, 0, 1]])
    assert as_array(Matrix()).tolist() == np.eye(4).tolist()
    assert as_array(a * b).tolist() == (as_array(a) @ as_array(b)).tolist()
    assert as_array(b * a).tolist() == (as_array(b) @ as_array(a)).tolist()
    p = Float3(1.0, -2.0, 0.5)
    assert a * p == Float3(*(as_array(a) @ [1.0, -2.0, 0.5, 1.0])[:3])
    assert a.transform_vector(p) == Float3(*(as_array(a) @ [1.0, -2.0, 0.5, 0.0])[:3])
    assert a.transform_normal(p) == Float3(*(as_array(a)[:3, :3].T @ [1.0, -2.0, 0.5]))
    a.set_identity()
    assert a == Matrix()


def test_matrix_refuses_bad_rows():
    with pytest.raises(ValueError, match="Matrix"):
        Matrix([[1, 2, 3]])
    with pytest.raises(ValueError, match="finite"):
        Matrix([[math.nan, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])


def _instance():
    return Instance(Sphere((0.0, 0.0, 0.0), 1.0, GREY))


@pytest.mark.parametrize("steps", [
    [("translate", (1.0, -2.0, 3.0))],
    [("scale", (2.0, 0.5, 4.0))],
    [("scale", (3.0,))],
    [("rotate_x", (30.0,))],
    [("rotate_y", (-45.0,))],
    [("rotate_z", (120.0,))],
    [("shear", (0.5, 0.25, -1.0, 0.0, 2.0, 0.125))],
    [("scale", (2.0, 1.0, 1.0)), ("rotate_z", (60.0,)), ("shear", (0.0, 0.0, 0.5)), ("translate", (1.0, 2.0, 3.0))],
], ids=["translate", "scale", "uniform_scale", "rotate_x", "rotate_y", "rotate_z", "shear", "composed"])
def test_the_inverse_is_the_inverse(steps):
    """inv_matrix forward_matrix = I, and forward_matrix is the product of the steps' matrices,
    the later on the left (the book: forward_matrix = T forward_matrix)."""
    instance = _instance()
    for name, args in steps:
        assert getattr(instance, name)(*args) is instance
    product = as_array(instance.inv_matrix) @ as_array(instance.forward_matrix)
    assert np.allclose(product, np.eye(4), atol=1e-12)
    assert as_array(instance.forward_matrix)[3].tolist() == [0.0, 0.0, 0.0, 1.0]


def test_transformations_are_the_books_matrices():
    """Each call's forward matrix, applied to a point: a rotation turns y toward z (x), z
    toward x (y), x toward y (z); a shear's h_ab adds a times h_ab to b."""
    p = Float3(1.0, 2.0, 3.0)
    assert _instance().translate(1.0, 2.0, 3.0).forward_matrix * p == Float3(2.0, 4.0, 6.0)
    assert _instance().scale(2.0, 3.0, 4.0).forward_matrix * p == Float3(2.0, 6.0, 12.0)
    assert _instance().rotate_x(90.0).forward_matrix.transform_vector(Float3(0.0, 1.0, 0.0)).z == 1.0
    assert _instance().rotate_y(90.0).forward_matrix.transform_vector(Float3(0.0, 0.0, 1.0)).x == 1.0
    assert _instance().rotate_z(90.0).forward_matrix.transform_vector(Float3(1.0, 0.0, 0.0)).y == 1.0
    sheared = _instance().shear(hxy=0.5, hzx=0.25).forward_matrix * p
    assert sheared == Float3(1.0 + 0.25 * 3.0, 2.0 + 0.5 * 1.0, 3.0)
    # Composition: scale, then translate; translate, then scale.
    assert _instance().scale(2.0).translate(1.0, 0.0, 0.0).forward_matrix * p == Float3(3.0, 4.0, 6.0)
    assert _instance().translate(1.0, 0.0, 0.0).scale(2.0).forward_matrix * p == Float3(4.0, 4.0, 6.0)


def _hit(shapes, origin, direction):
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes = list(shapes)
    hit = HitInfo()
    ray = Ray(Float3(*origin), Float3(*direction))
    return hit if scene.with_faces().intersect(ray, hit) else None


def test_an_ellipsoid_from_a_scaled_sphere():
    """The unit sphere scaled by (2, 1, 1) and moved by (1, 0, 0): the ellipsoid
    (x - 1)^2 / 4 + y^2 + z^2 = 1, hit from -x at x = -1 (t = 4), and by a ray along -z
    through (2, 0, .) at z = sqrt(3) / 2, where the normal is (x - 1) / 4, y, z normalised."""
    ellipsoid = Instance(Sphere((0.0, 0.0, 0.0), 1.0, GREY)).scale(2.0, 1.0, 1.0).translate(1.0, 0.0, 0.0)
    hit = _hit([ellipsoid], (-5.0, 0.0, 0.0), (1.0, 0.0, 0.0))
    assert hit.dist == 4.0 and hit.normal == Float3(-1.0, 0.0, 0.0)
    hit = _hit([ellipsoid], (2.0, 0.0, 5.0), (0.0, 0.0, -1.0))
    z = math.sqrt(3.0) / 2.0
    assert hit.dist == pytest.approx(5.0 - z, abs=1e-15)
    n = np.array([0.25, 0.0, z])
    assert np.allclose([hit.normal.x, hit.normal.y, hit.normal.z], n / np.linalg.norm(n), atol=1e-15)
    # t is the same in both spaces: the object ray's direction is not normalised.
    assert _hit([ellipsoid], (-5.0, 0.0, 0.0), (2.0, 0.0, 0.0)).dist == 2.0


def test_a_rotated_box_and_a_sheared_rectangle():
    box = Instance(Box((0.0, 0.0, 0.0), (2.0, 1.0, 1.0), GREY)).rotate_z(90.0)   # now x in [-1, 0], y in [0, 2]
    hit = _hit([box], (-0.5, 5.0, 0.5), (0.0, -1.0, 0.0))
    assert hit.dist == pytest.approx(3.0, abs=1e-15)
    assert np.allclose([hit.normal.x, hit.normal.y, hit.normal.z], [0.0, 1.0, 0.0], atol=1e-15)
    assert _hit([box], (0.5, 5.0, 0.5), (0.0, -1.0, 0.0)) is None
    # The unit square in z = 0 (normal +z) turned into y = 0 (normal -y), then sheared by
    # hzy = 1 (y' = y + z): the square y = z, x and z in [0, 1], whose normal is the inverse
    # transpose's image of -y: (0, -1, 1) / sqrt(2).
    square = Instance(Rectangle((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), GREY)).rotate_x(90.0)
    square.shear(hzy=1.0)
    hit = _hit([square], (0.5, 5.0, 0.5), (0.0, -1.0, 0.0))
    assert hit.dist == pytest.approx(4.5, abs=1e-15)
    assert np.allclose([hit.normal.x, hit.normal.y, hit.normal.z], np.array([0.0, -1.0, 1.0]) / math.sqrt(2.0),
                       atol=1e-15)


def test_texcoord_material_and_colour_come_from_the_object():
    sphere = Sphere((0.0, 0.0, 0.0), 1.0, GREY, Matte())
    moved = Instance(sphere).translate(0.0, 3.0, 0.0)
    point = Float3(0.0, 3.0, 1.0)
    assert moved.texcoord(point) == sphere.texcoord(Float3(0.0, 0.0, 1.0))
    assert moved.material is sphere.material and moved.color == sphere.color
    own = Material()
    assert Instance(sphere, own).material is own


def test_instances_of_a_mesh_share_it_and_nest():
    """Two instances of one mesh: the scene's faces are an Instance per face of each, with
    the instance's matrices; an Instance of an Instance composes both."""
    mesh = Mesh(np.array([(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]), np.array([(0, 1, 2)]), GREY)
    left = Instance(mesh).translate(-2.0, 0.0, 0.0)
    right = Instance(Instance(mesh).scale(2.0)).translate(2.0, 0.0, 0.0)
    hit = _hit([left, right], (-1.75, 0.25, 5.0), (0.0, 0.0, -1.0))
    assert hit.dist == 5.0 and hit.normal == Float3(0.0, 0.0, 1.0)
    hit = _hit([left, right], (3.5, 0.25, 5.0), (0.0, 0.0, -1.0))  # inside only the scaled face
    assert hit.dist == 5.0
    assert _hit([left, right], (-0.5, 0.75, 5.0), (0.0, 0.0, -1.0)) is None
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes = [left, right]
    faces = scene.with_faces().shapes
    assert len(faces) == 2 and faces[0].object.mesh is mesh and faces[1].object.object.mesh is mesh


def test_bounds_hold_the_transformed_object():
    box = Instance(Box((0.0, 0.0, 0.0), (1.0, 2.0, 3.0), GREY)).rotate_y(30.0).shear(hxz=0.5).translate(1.0, 1.0, 1.0)
    bounds = box.bounds()
    for x in (0.0, 1.0):
        for y in (0.0, 2.0):
            for z in (0.0, 3.0):
                p = box.forward_matrix * Float3(x, y, z)
                assert all(bounds.p0[a] < p[a] < bounds.p1[a] for a in range(3))
    exact = Instance(Box((0.0, 0.0, 0.0), (1.0, 1.0, 1.0), GREY)).scale(2.0).translate(1.0, 0.0, 0.0).bounds()
    assert exact.p0.x == pytest.approx(1.0) and exact.p1.x == pytest.approx(3.0)
    from rtfgu import Plane
    assert Instance(Plane((0.0, 0.0, 0.0), (0.0, 1.0, 0.0), GREY)).rotate_x(10.0).bounds() is None



def test_an_instance_carries_its_objects_texture_on_every_path(path):
    """A checkered sphere moved and scaled: every path colours the hit with the object's
    (u, v) at the object-space point, and reports the normal through the inverse transpose."""
    from rtfgu import Checker

    texture = Checker(Float3(0.9, 0.1, 0.1), Float3(0.1, 0.1, 0.9), size=0.25)
    ball = Instance(Sphere((0.0, 0.0, 0.0), 1.0, GREY), Matte(cd=texture)).scale(2.0, 1.0, 1.0).translate(1.0, 0.0, 0.0)
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes = [ball]
    rays = [((x, y, 5.0), (0.0, 0.0, -1.0), 0.0, math.inf) for x, y in ((0.3, 0.2), (1.7, -0.4), (2.5, 0.1))]
    got = [bounces[0] for bounces in path.trace(scene, rays)]
    for (origin, direction, _, _), bounce in zip(rays, got):
        ray = Ray(Float3(*origin), Float3(*direction))
        hit = HitInfo()
        assert scene.intersect(ray, hit) and bounce.kind == "instance"
        want = 0.1 * hit.color   # the Matte's ambient part: no light
        tolerance = 1e-12 if path.precision == "float64" else 1e-5
        assert np.allclose(bounce.color, (want.x, want.y, want.z), atol=tolerance), (path.label, bounce, want)
        assert np.allclose(bounce.normal, (hit.normal.x, hit.normal.y, hit.normal.z), atol=tolerance * 10)
    assert len({tuple(round(c, 3) for c in b.color) for b in got}) > 1, "the cases should see both colours"


def test_the_flat_layout_shares_an_objects_row_and_names_what_it_refuses():
    """Instances of one sphere share its row in the instanced sphere table; an instance of an
    Instance is refused by the numba and WGSL layout, naming the shape."""
    from rtfgu.layout import compile_scene

    sphere = Sphere((0.0, 0.0, 0.0), 1.0, GREY)
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes = [Instance(sphere).translate(1.0, 0.0, 0.0), Instance(sphere).scale(2.0)]
    flat = compile_scene(scene)
    assert len(flat.instanced["sphere"]) == 1 and flat.count("instance") == 2
    assert "instanced_sphere" in flat.features and "sphere" not in flat.features
    scene.shapes = [sphere, Instance(Instance(sphere))]
    with pytest.raises(ValueError, match=r"Scene.shapes\[1\].*an Instance of a Instance"):
        compile_scene(scene)


def _octahedron(**kwargs) -> Mesh:
    v = np.array([(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)], dtype=float)
    f = np.array([(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)])
    return Mesh(v, f, [(0.9, 0.2, 0.1 + 0.1 * k) for k in range(8)], **kwargs)


def _agree(path, scene, rays, float32=2e-4):
    """Each ray's bounces on ``path`` against the lecture layer's: exactly in float64 (the
    shape hit, its kind and shader always exactly), within ``float32`` (relative) otherwise."""
    from rtfgu.debug import first_difference

    want = path.reference.trace(scene, rays)
    got = path.trace(scene, rays)
    tolerance = 0.0 if path.precision == "float64" else float32
    for ray, a, b in zip(rays, want, got):
        assert first_difference(a, b, tolerance) is None, (path.label, ray, a, b)
    return want


def test_instances_of_a_mesh_share_its_tree_on_every_path(path):
    """One smooth, textured mesh drawn as itself and through two instances (one with a
    material of its own), lit by a point light whose shadow rays cross the instances: every
    path hits the face the lecture layer hits (each instance's faces are shapes of their own,
    Instance.parts), with its normal through the inverse transpose, its (u, v) and the face's
    or the instance's material; the mesh's vertices and its tree are laid out once."""
    from rtfgu import Checker, PointLight
    from rtfgu.layout import compile_scene

    v = np.array([(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)], dtype=float)
    mesh = _octahedron(normals=v, uvs=(v[:, :2] + 1.0) * 0.5, material=Matte())
    checker = Matte(cd=Checker(Float3(0.9, 0.9, 0.1), Float3(0.1, 0.4, 0.9), size=0.2))
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes = [mesh, Instance(mesh, checker).scale(1.5, 1.0, 1.0).rotate_z(30.0).translate(-2.2, 0.0, 0.0),
                    Instance(mesh).rotate_y(20.0).translate(2.2, 0.3, 0.5),
                    Rectangle((-5.0, -1.5, -5.0), (0.0, 0.0, 10.0), (10.0, 0.0, 0.0), GREY, Matte())]
    scene.lights = [PointLight(Float3(0.0, 6.0, 0.5), Float3(1.0, 1.0, 1.0), 30.0)]
    scene.shadows = True
    rays = [((x, y, 5.0), (0.0, 0.0, -1.0), 0.0, math.inf)
            for x in np.linspace(-3.37, 3.41, 18) for y in np.linspace(-1.33, 1.39, 7)]
    rays += [((x, 4.0, z), (0.0, -1.0, 0.0), 0.0, math.inf) for x in np.linspace(-4.5, 4.5, 19) for z in (-0.5, 0.5)]
    want = _agree(path, scene, rays)
    hit = {(b[0].kind, b[0].shape) for b in want if b and b[0].kind is not None}
    assert {"mesh", "instance", "rectangle"} <= {kind for kind, _ in hit}
    assert {shape // 8 for kind, shape in hit if kind == "instance"} == {1, 2}, "both instances are hit"
    floor = {b[0].color for b in want if b and b[0].kind == "rectangle"}
    assert len(floor) > 2, "the floor sees light and the instances' shadows"
    flat = compile_scene(scene)
    assert len(flat.mesh.vertices) == len(v) and len(flat.mesh.roots) == 1
    rows = flat.table("instance")[:, 13]
    assert rows.tolist() == [flat.mesh.roots[0]] * 2


def test_a_tie_inside_an_instanced_mesh_goes_to_the_earlier_face_on_every_path(path):
    """A quad of two faces of their own colours, instanced with exact steps: a ray through its
    diagonal hits both faces at the same t, and every path takes the earlier face, as the
    lecture layer's loop over each face's Instance does; so does a ray at an instance that
    another instance of the quad, earlier in Scene.shapes, meets at the same t.

    The quad has normals and (u, v), the third instance a checker of its own and the quad is
    also drawn as itself, after the instances and away from the rays: the scene has the kinds
    of the test above, so the numba paths trace it with the kernel that test compiled
    (docs/compile_time.md)."""
    from rtfgu import Checker

    quad = Mesh(np.array([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], dtype=float), np.array([(0, 1, 2), (0, 2, 3)]),
                [(0.9, 0.1, 0.1), (0.1, 0.1, 0.9)], material=Material(), normals=np.array([(0.0, 0.0, 1.0)] * 4),
                uvs=np.array([(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]))
    checker = Matte(cd=Checker(Float3(0.9, 0.9, 0.1), Float3(0.1, 0.4, 0.9), size=0.2))
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes = [Instance(quad).translate(2.0, 0.0, 0.0), Instance(quad).scale(2.0).translate(1.0, -1.0, 0.0),
                    Instance(quad, checker).translate(-2.0, 0.0, 0.0), quad]
    rays = [((2.5, 0.5, 3.0), (0.0, 0.0, -1.0), 0.0, math.inf),      # the diagonal of the first
            ((2.25, 0.5, 3.0), (0.0, 0.0, -1.0), 0.0, math.inf),     # the first and the second
            ((-1.5, 0.5, 3.0), (0.0, 0.0, -1.0), 0.0, math.inf)]     # the third's diagonal
    want = _agree(path, scene, rays)
    assert [b[0].shape for b in want] == [0, 1, 4]


def _instances(count: int) -> list:
    """``count`` instances of one unit sphere and one unit box, each scaled, turned and moved
    along a row, and a floor under them."""
    sphere, box = Sphere((0.0, 0.0, 0.0), 1.0, GREY), Box((0.0, 0.0, 0.0), (1.0, 1.0, 1.0), GREY)
    shapes = [Instance(sphere if k % 2 else box, Matte(cd=Float3(0.2 + 0.03 * k, 0.5, 0.3)))
              .scale(0.3 + 0.02 * k, 0.4, 0.35).rotate_y(17.0 * k).translate(-4.0 + 0.4 * k, 0.3 * math.sin(k), -0.5 * k)
              for k in range(count)]
    return shapes + [Rectangle((-6.0, -1.5, -12.0), (0.0, 0.0, 14.0), (12.0, 0.0, 0.0), GREY, Matte())]


def test_the_bvh_holds_the_instances_on_every_path(path):
    """Twenty instances (BVH_MIN_SPHERES or more) go into the scene's BVH by their boxes
    (Instance.bounds), as the spheres do, and a triangle's mesh takes them in with it, and so
    do instances of a smooth Mesh, whose test enters the mesh's own tree (two levels): every
    path hits what the lecture layer hits, each instanced face at its place, and the shadow
    rays find the instances there too."""
    from rtfgu import PointLight
    from rtfgu.layout import BVH_MIN_SPHERES, INSTANCE_ROW, compile_scene

    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.lights = [PointLight(Float3(0.0, 6.0, 0.5), Float3(1.0, 1.0, 1.0), 30.0)]
    scene.shadows = True
    rays = [((x, y, 5.0), (0.0, 0.0, -1.0), 0.0, math.inf)
            for x in np.linspace(-4.3, 4.1, 24) for y in np.linspace(-1.4, 1.3, 8)]
    rays += [((x, 4.0, z), (0.0, -1.0, 0.0), 0.0, math.inf) for x in np.linspace(-4.3, 4.1, 16) for z in (-7.0, -2.5, 0.5)]
    triangle = Mesh(np.array([(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]), np.array([(0, 1, 2)]), GREY)
    octahedron = _octahedron(normals=np.array([(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]))
    meshes = [Instance(octahedron).scale(0.5).rotate_x(10.0 * k).translate(-3.0 + 0.9 * k, 1.0, -1.0 * k)
              for k in range(8)]
    for shapes in (_instances(BVH_MIN_SPHERES + 4), _instances(3) + [triangle], _instances(12) + meshes):
        scene.shapes = shapes
        flat = compile_scene(scene)
        assert "bvh_instances" in flat.features
        assert (flat.mesh.faces[:, 0] == INSTANCE_ROW).sum() == flat.count("instance")
        want = _agree(path, scene, rays, float32=1e-3)
        assert len({b[0].shape for b in want if b and b[0].kind == "instance"}) >= 3
        floor = [b[0].color for b in want if b and b[0].kind == "rectangle"]
        assert min(floor) < max(floor), "some of the floor lies in an instance's shadow"


def test_instances_stay_in_their_loop_where_the_bvh_cannot_hold_them():
    """Fewer than BVH_MIN_SPHERES instances without a mesh, or an instance of a plane (no
    box): the instances keep their loop."""
    from rtfgu import Plane
    from rtfgu.layout import compile_scene

    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    plane = Instance(Plane((0.0, 0.0, 0.0), (0.0, 1.0, 0.0), GREY)).translate(0.0, -2.0, 0.0)
    for shapes in (_instances(3), _instances(20) + [plane], _instances(3) + [Instance(_octahedron())]):
        scene.shapes = shapes
        flat = compile_scene(scene)
        assert "bvh_instances" not in flat.features
        assert flat.mesh is None or not flat.mesh.instances
    scene.shapes = _instances(20)
    assert "bvh_instances" in compile_scene(scene).features


def test_instances_of_a_compound_share_its_leaves_on_every_path(path):
    """A solid cylinder (a Compound of a tube and two disks) placed twice, once with a
    material of its own: every path hits the leaf the lecture layer hits, numbered as the
    compound's leaves in its place, and the leaves' rows are laid out once for both."""
    from rtfgu import Phong, SolidCylinder
    from rtfgu.layout import compile_scene

    can = SolidCylinder(-0.5, 0.5, 0.6, (0.8, 0.3, 0.1), Matte())
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes = [Instance(can).rotate_x(60.0).translate(-1.2, 0.0, 0.0),
                    Instance(can, Phong(cd=Float3(0.2, 0.6, 0.9), cs=Float3(0.3, 0.3, 0.3), exp=20.0))
                    .scale(1.0, 1.5, 1.0).rotate_z(40.0).translate(1.2, 0.0, 0.0)]
    rays = [((x, y, 5.0), (0.0, 0.0, -1.0), 0.0, math.inf)
            for x in np.linspace(-2.13, 2.19, 22) for y in np.linspace(-1.21, 1.17, 9)]
    want = _agree(path, scene, rays, float32=1e-3)
    leaves = {b[0].shape for b in want if b and b[0].kind is not None}
    assert {0, 1, 2} & leaves and {3, 4, 5} & leaves and len(leaves) >= 3, leaves
    flat = compile_scene(scene)
    assert flat.count("instance") == 6 and len(flat.instanced["open_cylinder"]) == 1
    assert len(flat.instanced["disk"]) == 2
