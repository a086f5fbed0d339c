"""A Mesh in Scene.shapes (its faces, in order) reaches the numba and WGSL paths as its arrays:
compile_scene packs it with numpy and never makes a MeshTriangle, every path sees the same
faces as a scene holding ``mesh.triangles()``, and the scene's BVH is built once for its
geometry: a second render, a camera move or another sample count reuse it, a moved vertex
builds it again."""
from __future__ import annotations

import copy
import math
import random

import numpy as np
import pytest
import trimesh

import rtfgu
from rtfgu import Float3, OrthographicCamera, PinholeCamera, PointLight, Scene, Sphere, Triangle
from rtfgu.accelerators import flat_bvh
from rtfgu.layout import compile_scene
from rtfgu.materials import Matte, Phong, Reflective
from rtfgu.shapes import mesh as mesh_module
from rtfgu.shapes.mesh import Mesh

GREY = (0.5, 0.5, 0.5)


def icosphere(subdivisions: int, scale: float = 1.0, **kwargs) -> Mesh:
    sphere = trimesh.creation.icosphere(subdivisions=subdivisions)
    return Mesh(np.asarray(sphere.vertices) * scale, np.asarray(sphere.faces), GREY, **kwargs)


def mixed_meshes():
    """A smooth mesh whose faces have colours and two materials of their own, and a flat one."""
    sphere = trimesh.creation.icosphere(subdivisions=2)
    m = len(sphere.faces)
    rng = np.random.default_rng(4)
    colors = rng.uniform(0.1, 0.9, (m, 3))
    colors[::3] = (0.2, 0.4, 0.6)            # repeated colours share a material row
    matte, mirror = Matte(), Reflective(cr=Float3(0.9), kr=0.5)
    materials = [mirror if k % 7 == 0 else matte for k in range(m)]
    smooth = Mesh(np.asarray(sphere.vertices) * 0.75, np.asarray(sphere.faces), colors,
                  normals=np.asarray(sphere.vertex_normals), material=materials)
    flat = icosphere(1, 0.4, material=Phong())
    flat.vertices += (0.0, 0.0, 1.0)
    return smooth, flat


def mixed_scene(hold_mesh: bool, smooth: Mesh, flat: Mesh) -> Scene:
    scene = Scene(PinholeCamera(Float3(0.5, 0.4, 3.0), Float3(0.0), Float3(0, 1, 0)))
    for shape in (Sphere(Float3(0.5, 0.0, 0.0), 0.5, GREY, Matte()), smooth,
                  Triangle((-2, -2, -0.25), (2, -2, -0.25), (0, 2, -0.25), GREY, Matte()), flat):
        if isinstance(shape, Mesh) and not hold_mesh:
            scene.shapes += shape.triangles()
        else:
            scene.shapes.append(shape)
    scene.lights.append(PointLight(Float3(2.0, 3.0, 4.0), Float3(20.0)))
    return scene


class Counted:
    """Counts the calls of a function a test wraps in place of it."""

    def __init__(self, function):
        self.function, self.calls = function, 0

    def __call__(self, *args, **kwargs):
        self.calls += 1
        return self.function(*args, **kwargs)


@pytest.fixture
def no_mesh_triangles(monkeypatch):
    """Fails the test if a MeshTriangle is made."""
    def refuse(self, mesh, face):
        raise AssertionError("a MeshTriangle was made (face %d)" % face)
    monkeypatch.setattr(mesh_module.MeshTriangle, "__init__", refuse)


@pytest.fixture
def builds(monkeypatch) -> Counted:
    """Counts the BVH builds: every one goes through build_rows (build's too)."""
    counted = Counted(flat_bvh.build_rows)
    monkeypatch.setattr(flat_bvh, "build_rows", counted)
    return counted


def test_a_scene_holding_a_20k_face_mesh_compiles_and_renders_without_a_mesh_triangle(no_mesh_triangles):
    mesh = icosphere(5, material=Matte())                            # 20480 faces
    scene = Scene(PinholeCamera(Float3(0, 0, 3.0), Float3(0.0), Float3(0, 1, 0)))
    scene.shapes.append(mesh)
    scene.lights.append(PointLight(Float3(2, 2, 3), Float3(10.0)))
    flat = compile_scene(scene)
    assert len(flat.mesh.faces) == 20480 and len(flat.material_of) == 20480
    assert len(flat.materials) == 1                                  # one material: one row
    assert sorted(flat.mesh.faces[:, 3]) == list(range(20480))      # each face's own index
    image = rtfgu.render(scene, 16, 16, backend="numba")
    assert image[8, 8].max() > 0.1 and image[0, 0].max() == 0.0      # the sphere in the middle
    assert mesh._triangles is None


@pytest.mark.parametrize("precision", ["float64", "float32"])
def test_a_mesh_packs_to_the_arrays_of_its_triangles(precision):
    smooth, flat = mixed_meshes()
    a = compile_scene(mixed_scene(True, smooth, flat), precision)
    b = compile_scene(mixed_scene(False, smooth, flat), precision)
    for name in ("vertices", "faces", "normals"):
        assert np.array_equal(getattr(a.mesh, name), getattr(b.mesh, name)), name
    assert np.array_equal(a.mesh.bvh.nodes.view(np.int32), b.mesh.bvh.nodes.view(np.int32))
    assert np.array_equal(a.materials, b.materials) and np.array_equal(a.shaders, b.shaders)
    assert np.array_equal(a.material_of, b.material_of)
    assert len(np.unique(a.materials, axis=0)) > 100                 # the faces' colours are there
    for kind in a.shapes:
        assert np.array_equal(a.table(kind), b.table(kind)) and np.array_equal(a.index(kind), b.index(kind))
    assert a.features == b.features


def random_rays(count: int, seed: int = 3):
    rng = random.Random(seed)
    rays = []
    for _ in range(count):
        o = [rng.uniform(-3.0, 3.0) for _ in range(3)]
        target = [rng.uniform(-1.0, 1.0) for _ in range(3)]
        rays.append((tuple(o), tuple(t - a for t, a in zip(target, o)), 0.0, math.inf))
    return rays


def test_every_path_sees_a_mesh_as_its_triangles(path):
    smooth, flat = mixed_meshes()
    rays = random_rays(60)
    held = path.trace(mixed_scene(True, smooth, flat), rays)
    assert held == path.trace(mixed_scene(False, smooth, flat), rays)
    assert sum(bounces[0].kind == "mesh" for bounces in held) > 20
    assert max(bounces[0].shape or 0 for bounces in held) > len(smooth.faces)   # the faces count in the numbering


@pytest.mark.parametrize("backend", ["reference", "numba"])
def test_an_image_of_a_scene_holding_meshes_is_that_of_their_triangles(backend):
    smooth, flat = mixed_meshes()
    held = rtfgu.render(mixed_scene(True, smooth, flat), 12, 12, backend=backend)
    assert np.array_equal(held, rtfgu.render(mixed_scene(False, smooth, flat), 12, 12, backend=backend))
    assert held.max() > 0.1


def test_a_second_render_a_camera_move_and_another_sample_count_reuse_the_bvh(builds, no_mesh_triangles):
    mesh = icosphere(3, material=Matte())
    scene = Scene(PinholeCamera(Float3(0, 0, 3.0), Float3(0.0), Float3(0, 1, 0)))
    scene.shapes.append(mesh)
    scene.lights.append(PointLight(Float3(2, 2, 3), Float3(10.0)))
    first = rtfgu.render(scene, 16, 16, backend="numba")
    assert builds.calls == 1
    assert np.array_equal(rtfgu.render(scene, 16, 16, backend="numba"), first)
    again, once_more = compile_scene(scene), compile_scene(scene)
    assert again.mesh.build_seconds == 0.0 and builds.calls == 1
    assert once_more.mesh.faces is again.mesh.faces and once_more.mesh.vertices is again.mesh.vertices
    assert len(once_more.materials) == 1 and len(once_more.material_of) == mesh.num_triangles   # a row per material
    scene.camera = PinholeCamera(Float3(0.5, 0, 3.0), Float3(0.0), Float3(0, 1, 0))
    moved = rtfgu.render(scene, 16, 16, backend="numba", spp=4)
    assert builds.calls == 1 and not np.array_equal(moved, first)
    rtfgu.render(scene, 16, 16, backend="numba", precision="float32")
    assert builds.calls == 2                                          # a tree per precision


def test_a_moved_vertex_builds_the_bvh_again_and_the_image_shows_it(builds):
    mesh = icosphere(3, material=Matte())
    scene = Scene(OrthographicCamera(-1.5, 1.5, -1.5, 1.5))
    scene.shapes.append(mesh)
    first = rtfgu.render(scene, 24, 24, backend="numba")
    key = mesh.geometry_key()
    top = int(np.argmax(mesh.vertices[:, 0]))                        # the vertex at +x, moved out
    mesh.vertices[top] *= 1.4
    assert mesh.geometry_key() != key
    moved = rtfgu.render(scene, 24, 24, backend="numba")
    assert builds.calls == 2
    assert np.array_equal(compile_scene(scene).mesh.vertices[top], mesh.vertices[top])
    fresh = Scene(OrthographicCamera(-1.5, 1.5, -1.5, 1.5))
    fresh.shapes += Mesh(mesh.vertices.copy(), mesh.faces, GREY, material=mesh.materials[0]).triangles()
    assert not np.array_equal(moved, first)
    assert np.array_equal(moved, rtfgu.render(fresh, 24, 24, backend="numba"))   # the new tree finds the new faces


def test_the_lecture_layers_faces_are_made_once_and_again_after_a_change():
    mesh = icosphere(1)
    faces = mesh.triangles()
    assert all(a is b for a, b in zip(faces, mesh.triangles()))
    k = int(np.flatnonzero(mesh.faces[:, 0] == 0)[0])                  # a face whose v0 is vertex 0
    mesh.vertices[0] *= 1.25
    again = mesh.triangles()
    assert again[k] is not faces[k]
    assert again[k].triangle.v0 == Float3(*mesh.vertices[0]) != faces[k].triangle.v0


def test_a_bad_material_of_a_face_is_named_by_the_mesh_and_the_face():
    mesh = icosphere(1, material=[Matte()] * 45 + [rtfgu.GlossyReflector()] + [Matte()] * 34)
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes += [Sphere(Float3(3, 0, 0), 0.5, GREY), mesh]
    scene.tracer = rtfgu.PathTrace(max_depth=2)
    compile_scene(scene)
    mesh.colors[45] = (2.0, 2.0, 2.0)                                 # kd cd above 1
    with pytest.raises(ValueError, match=r"Scene\.shapes\[1\]\.materials\[45\] \(GlossyReflector\)"):
        compile_scene(scene)


def test_area_lights_on_the_faces_of_a_held_mesh_light_it_as_they_light_its_triangles():
    from rtfgu.scenes.meshes import cornell_box_area_light

    of_faces = cornell_box_area_light()                               # holds mesh.triangles()
    mesh = of_faces.shapes[0].mesh
    held = copy.copy(of_faces)
    held.shapes = [mesh]                                              # its lights: AreaLights of those faces
    a, b = compile_scene(held), compile_scene(of_faces)
    assert np.array_equal(a.mesh.faces, b.mesh.faces) and np.array_equal(a.materials, b.materials)
    assert all(np.array_equal(a.lights[k], b.lights[k]) for k in a.lights) and a.light_count == 2
    assert np.array_equal(rtfgu.render(held, 8, 8, backend="numba", spp=4),
                          rtfgu.render(of_faces, 8, 8, backend="numba", spp=4))
    held.lights = held.lights[:1]
    with pytest.raises(ValueError, match=r"Scene\.shapes\[0\] \(a Mesh\): face \d+ emits .* add "
                                         r"AreaLight\(mesh\.triangles\(\)\[\d+\]\)"):
        compile_scene(held)


def test_the_lecture_layer_traces_a_held_mesh_through_the_scenes_view_of_its_faces():
    mesh = icosphere(1)
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes += [Sphere(Float3(3, 0, 0), 0.5, GREY), mesh]
    view = scene.with_faces()
    assert len(view.shapes) == 1 + len(mesh.faces) and view.shapes[1:] == mesh.triangles()
    assert scene.shapes[1] is mesh and view.lights is scene.lights and scene.with_faces().shapes == view.shapes
    hit = rtfgu.HitInfo()
    assert view.intersect(rtfgu.Ray(Float3(0, 0, 5), Float3(0, 0, -1)), hit) and hit.dist == pytest.approx(4.0, rel=0.1)
    with pytest.raises(TypeError, match=r"scene\.with_faces\(\)"):
        scene.intersect(rtfgu.Ray(Float3(0, 0, 5), Float3(0, 0, -1)), rtfgu.HitInfo())
