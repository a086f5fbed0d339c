"""The pixel debugger (rtfgu/debug.py, ``python -m rtfgu debug-pixel``): where float32 and
float64 part, it names the bounce and the field; where they agree, it says so.

The scene where they part: an orthographic view of a mirror, which sends every ray up
to a sphere of radius 0.5 at distance 10^4. In float32 the lecture's quadratic loses
r^2 = 0.25 next to c = |o - center|^2 = 10^8 (float32 keeps 24 bits, steps of 8 there), so
the float32 slide formula hits the sphere where float64 sees the background; the robust
formula (Ray Tracing Gems ch. 7) keeps it.
"""
from __future__ import annotations

import pytest

from rtfgu import Float3, OrthographicCamera, Plane, Scene, Sphere
from rtfgu.__main__ import main
from rtfgu.debug import TOLERANCES, Bounce, first_difference, trace_pixel
from rtfgu.materials import Matte, Reflective
from rtfgu.scenes import get_scene
from wgsl_support import wgpu_device  # noqa: F401  (fixture)

SIZE = 8
BESIDE_THE_SPHERE = (0, 0)  # the mirrored ray passes the far sphere by 0.7 radii


def far_sphere_in_a_mirror():
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes = [Plane((0.0, 0.0, -1.0), (0.0, 0.0, 1.0), (1.0, 1.0, 1.0), Reflective()),
                    Sphere((0.0, 0.0, 1.0e4), 0.5, (1.0, 0.0, 0.0), Matte())]
    scene.background = Float3(0.1, 0.3, 0.6)
    return scene


far_sphere_in_a_mirror.size = (SIZE, SIZE)


def test_float32_slide_formula_differs_at_the_second_bounce_shape():
    scene = far_sphere_in_a_mirror()
    reference = trace_pixel(scene, *BESIDE_THE_SPHERE, SIZE, SIZE)
    f32 = trace_pixel(scene, *BESIDE_THE_SPHERE, SIZE, SIZE, "numba", "float32", "slide")
    assert [b.shader for b in reference] == ["mirror", "background"]
    difference = first_difference(reference, f32, TOLERANCES["float32"])
    assert difference is not None
    assert (difference.bounce, difference.field) == (1, "shape")
    assert (difference.first, difference.second) == (None, 1)


def test_float64_agrees_with_the_reference_bit_for_bit():
    scene = far_sphere_in_a_mirror()
    for x, y in (BESIDE_THE_SPHERE, (3, 3)):
        reference = trace_pixel(scene, x, y, SIZE, SIZE)
        assert first_difference(reference, trace_pixel(scene, x, y, SIZE, SIZE, "numba", "float64"), 0.0) is None


def test_float32_robust_formula_agrees():
    scene = far_sphere_in_a_mirror()
    reference = trace_pixel(scene, *BESIDE_THE_SPHERE, SIZE, SIZE)
    f32 = trace_pixel(scene, *BESIDE_THE_SPHERE, SIZE, SIZE, "numba", "float32", "robust")
    assert first_difference(reference, f32, TOLERANCES["float32"]) is None


def test_refraction_drifts_within_the_float32_tolerance():
    """Three bounces through the refractive sphere: the float32 path's directions drift
    from float64's, but stay within the tolerance, so nothing is reported."""
    scene = get_scene("default_refractive_sphere")()
    reference = trace_pixel(scene, 16, 18, 32, 32)
    f32 = trace_pixel(scene, 16, 18, 32, 32, "numba", "float32")
    assert [b.shader for b in reference] == ["transparent", "transparent", "background"]
    assert reference[1].direction != f32[1].direction
    assert first_difference(reference, f32, TOLERANCES["float32"]) is None


def test_wgpu_slide_formula_differs_where_numba_float32_does(wgpu_device):
    scene = far_sphere_in_a_mirror()
    reference = trace_pixel(scene, *BESIDE_THE_SPHERE, SIZE, SIZE)
    wgpu = trace_pixel(scene, *BESIDE_THE_SPHERE, SIZE, SIZE, "wgpu", formula="slide")
    difference = first_difference(reference, wgpu, TOLERANCES["float32"])
    assert difference is not None and (difference.bounce, difference.field) == (1, "shape")
    robust = trace_pixel(scene, *BESIDE_THE_SPHERE, SIZE, SIZE, "wgpu", formula="robust")
    assert first_difference(reference, robust, TOLERANCES["float32"]) is None


def test_first_difference_order_and_lengths():
    hit = Bounce((0.0, 0.0, 0.0), (0.0, 0.0, -1.0), 0, "plane", 1.0, (0.0, 0.0, 1.0), "lambertian",
                 (0.5, 0.5, 0.5))
    moved = Bounce((0.0, 0.0, 0.0), (0.0, 0.0, -1.0), 0, "plane", 1.0 + 1e-6, (0.0, 0.0, 1.0),
                   "lambertian", (0.25, 0.5, 0.5))
    assert first_difference([hit], [hit]) is None
    assert first_difference([hit], [moved], 1e-4).field == "color"   # t within, colour not
    assert first_difference([hit], [moved], 0.0).field == "t"        # t comes before colour
    assert first_difference([hit], [hit, hit]) == (1, "bounces", 1, 2)


def test_cli_prints_the_paths_and_marks_the_first_difference(monkeypatch, capsys):
    monkeypatch.setattr("rtfgu.__main__.get_scene", lambda name: far_sphere_in_a_mirror)
    assert main(["debug-pixel", "far_sphere", "0", "0", "--formula", "slide"]) == 0
    out = capsys.readouterr().out
    assert "reference" in out and "numba-float64" in out and "numba-float32" in out
    assert "1 shape" in out and "<< first" in out
    assert "numba-float64 agrees with reference (exact)" in out
    assert "numba-float32 first differs from reference at bounce 1, shape: 1 against None" in out


def test_cli_agreeing_pixel(capsys):
    assert main(["debug-pixel", "default_refractive_sphere", "16", "18", "--width", "32",
                 "--height", "32"]) == 0
    out = capsys.readouterr().out
    assert "0 shader" in out and "transparent" in out and "2 color" in out
    assert "numba-float32 agrees with reference" in out and "<< first" not in out


@pytest.mark.parametrize("argv,name", [
    (["default_lambertian", "32", "0", "--width", "32", "--height", "32"], "X"),
    (["default_lambertian", "0", "-1", "--width", "32", "--height", "32"], "Y"),
    (["default_lambertian", "0", "0", "--width", "0"], "width"),
])
def test_cli_bad_pixel_exits_2(argv, name, capsys):
    with pytest.raises(SystemExit) as exit_info:
        main(["debug-pixel"] + argv)
    assert exit_info.value.code == 2
    assert "%s must be" % name in capsys.readouterr().err


def test_cli_traces_the_paths_a_release_has(monkeypatch, capsys):
    """A student release has neither the numba kernels nor the WGSL pieces of the
    assignments it does not reveal (rtfgu.grading.release): the debugger still traces the
    lecture layer, the student's own code, and names each path it skips."""
    import importlib
    import importlib.util

    assemble = importlib.import_module("rtfgu.wgsl.assemble")  # the module, not its function
    find_spec = importlib.util.find_spec

    def read_piece(name):
        raise assemble.PieceNotInRelease("rtfgu/wgsl/%s is not part of this release of rtfgu" % name)

    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *rest: None if name == "rtfgu.kernels" else find_spec(name, *rest))
    monkeypatch.setattr(assemble, "read_piece", read_piece)
    assert main(["debug-pixel", "default_flat_colors", "100", "100"]) == 0
    out = capsys.readouterr().out
    assert "0 shape" in out and "plane" in out and "<< first" not in out
    skipped = [line for line in out.splitlines() if ": skipped, " in line]
    assert [line.split(":")[0] for line in skipped] == ["numba-float64", "numba-float32", "wgpu-float32"]
    assert all("not part of this release" in line or "adapter" in line for line in skipped), skipped


@pytest.mark.parametrize("name", ["default_lambertian_shadows", "default_glossy_sphere", "suffern_disks",
                                  "suffern_11_fisheye", "suffern_11_spherical", "suffern_12_stereo",
                                  "default_glossy_sphere under the sky", "default_texture_nearest_repeat",
                                  "suffern_29_uv_mesh"])
def test_the_bounces_add_up_to_the_rendered_pixel(path, name):
    """The debugger shows what the render computes: on every path the colours its bounces
    add, summed in the path's precision in bounce order as the path loop sums them, are the
    rendered pixel bit for bit (pixel (0, 0) sees the background or the sky). The last three
    scenes have what the debugger's numba kernel is given as an empty array where a scene
    lacks it (an environment, a texture, smooth normals and (u, v) on a mesh)."""
    import numpy as np

    import rtfgu
    from rtfgu.cameras import PinholeCamera
    from rtfgu.lights import EnvironmentLight
    from rtfgu.scenes.environment import SKY

    size = 16
    scene = get_scene(name.split()[0])()
    if name.endswith("under the sky"):
        scene.environment = EnvironmentLight(SKY)
    if isinstance(scene.camera, PinholeCamera):
        scene.camera.aspect = 1.0  # as render does for a square image of a wide scene
    image = rtfgu.render(scene, size, size, backend=path.backend, precision=path.precision)
    for x, y in ((0, 0), (2, 3), (8, 8), (13, 10)):
        total = np.zeros(3, dtype=path.precision)
        for bounce in trace_pixel(scene, x, y, size, size, path.backend, path.precision):
            total = total + np.asarray(bounce.color, dtype=path.precision)
        assert np.array_equal(total, image[y, x]), "%s %s pixel (%d, %d): bounces add up to %r, render %r" % (
            path.label, name, x, y, total, image[y, x])


@pytest.mark.parametrize("name, x, y", [("suffern_11_fisheye", 0, 0), ("suffern_11_fisheye", 399, 399),
                                        ("suffern_12_stereo", 204, 100)])
def test_a_pixel_the_camera_sees_nothing_through_is_one_miss(path, name, x, y):
    """Outside a fish-eye's circle and in a stereo pair's gap the camera's ray is blank
    (rtfgu.cameras.camera.blank_ray): on every path the debugger shows one ray that left
    the scene, its colour the background, along the camera's view direction."""
    import numpy as np

    scene = get_scene(name)()
    width, height = get_scene(name).size
    bounces = trace_pixel(scene, x, y, width, height, path.backend, path.precision)
    assert [b.shader for b in bounces] == ["background"], path
    v = scene.camera.v
    assert np.allclose(bounces[0].direction, (v.x, v.y, v.z), atol=1e-7), path
    assert np.allclose(bounces[0].color, (0.1, 0.3, 0.6), atol=1e-7), path


def _bvh_families():
    """Scenes whose BVH holds each combination of what it may hold, beside the homework
    scenes (the camera looks along -z at a triangle at z = -2, lit from the front): spheres
    with a mesh, instances with their boxes, a Mesh held only by an instance (no tree of the
    scene's own), and an instance without a box (a backdrop plane's: its own loop) beside a
    mesh."""
    from rtfgu import Float3, Instance, Matte, OrthographicCamera, Plane, Scene, Sphere
    from rtfgu.lights import PointLight
    from rtfgu.shapes.mesh import Mesh

    def mesh(z=-2.0):
        return Mesh([(-0.8, -0.8, z), (0.8, -0.8, z), (0.0, 0.8, z)], [(0, 1, 2)], (0.5, 0.5, 0.5),
                    material=Matte())

    def sphere(center=(0.3, 0.2, -1.5)):
        return Sphere(center, 0.4, (1.0, 0.0, 0.0), Matte())

    def scene(*shapes):
        out = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
        out.shapes = list(shapes)
        out.lights = [PointLight(Float3(-0.5, 1.5, 1.0), Float3(1.0))]   # shadow rays through the BVH too
        return out

    backdrop = Plane((0.0, 0.0, -4.0), (0.0, 0.0, 1.0), (0.2, 0.2, 0.6), Matte())
    return {"spheres and a mesh": scene(sphere(), mesh()),
            "instances of a sphere and a mesh": scene(Instance(sphere((0.0, 0.0, 0.0))).translate(0.3, 0.2, -1.5),
                                                      mesh()),
            "a mesh held by an instance only": scene(Instance(mesh(0.0)).translate(0.1, 0.1, -2.0), sphere()),
            "an unbounded instance beside a mesh": scene(Instance(backdrop).translate(0.0, 0.0, -0.5), mesh(),
                                                         sphere())}


@pytest.mark.parametrize("precision", ["float32", "float64"])
def test_one_debugger_kernel_serves_every_scene(precision):
    """The numba debugger's arguments (rtfgu.kernels.debug.scene_arguments) have one numba
    type for every homework scene of a precision, with or without a mesh, whatever its BVH
    holds (a tree of its own, spheres, instances): it compiles once, not once per scene's
    features (textures, an environment, samplers of their own, smooth normals, (u, v), a
    mesh), each compile some 40-60 s."""
    import numba

    from rtfgu.kernels.debug import scene_arguments
    from rtfgu.layout import compile_scene
    from rtfgu.scenes import SCENES

    types, families = {}, set()
    scenes = {name: make() for name, make in SCENES.items()}
    scenes.update(_bvh_families())
    for name, scene in scenes.items():
        flat = compile_scene(scene, precision)
        mesh = flat.mesh
        held = [kind for kind, held in (("a tree", mesh.scene_tree), ("spheres", mesh.spheres),
                                        ("instances", mesh.instances)) if held] if mesh is not None else []
        families.add("no mesh" if mesh is None else "BVH of " + ", ".join(held) if held
                     else "instanced meshes' trees only")
        types.setdefault(numba.typeof(scene_arguments(flat)), []).append(name)
    assert {"no mesh", "BVH of a tree", "BVH of a tree, spheres", "BVH of a tree, instances",
            "instanced meshes' trees only"} <= families, sorted(families)
    assert len(types) == 1, "%s: %d kernels: %s" % (precision, len(types), [names[:3] for names in types.values()])


@pytest.mark.parametrize("name", sorted(_bvh_families()))
def test_the_debugger_traces_what_each_bvh_holds_as_the_render_does(name):
    """Every pixel of a small render of each of _bvh_families' scenes, float64: the
    debugger's bounces end on the shape the reference's do, and add up to the numba
    render's pixel bit for bit (an empty index or tree where the render has none must
    hide nothing the BVH holds, nor add anything)."""
    import numpy as np

    from rtfgu import render

    scene = _bvh_families()[name]
    size = 8
    image = render(scene, size, size, backend="numba", precision="float64")
    seen = set()
    for y in range(size):
        for x in range(size):
            reference = trace_pixel(scene, x, y, size, size)
            numba_path = trace_pixel(scene, x, y, size, size, "numba", "float64")
            assert [b.shape for b in numba_path] == [b.shape for b in reference], (x, y)
            seen.add(reference[0].shape)
            total = np.zeros(3)
            for bounce in numba_path:   # in bounce order, as the path loop sums them
                total = total + np.asarray(bounce.color)
            assert np.array_equal(total, image[y, x]), (x, y, total, image[y, x])
    assert len(seen - {None}) == len(scene.shapes), seen   # every shape is seen somewhere


@pytest.mark.parametrize("name, kind", [("spheres and a mesh", "sphere"),
                                        ("instances of a sphere and a mesh", "instance")])
def test_a_kinds_loops_run_over_its_index(name, kind):
    """What the BVH holds reaches the debugger as its table and an empty index: the kind's
    own loops (the generated scan_ and any_hit_, run as plain Python) test no row then, and
    every row with the scene's index. A loop over the table would test the rows twice, with
    scene indices read past the empty index."""
    import math

    from rtfgu.kernels import dispatch
    from rtfgu.kernels.render import shape_arrays
    from rtfgu.layout import compile_scene
    from rtfgu.registry import INSTANCED

    generated = dispatch.load()
    flat = compile_scene(_bvh_families()[name], "float64")
    shapes = shape_arrays(flat, empty=True)
    at = dispatch.slot_offsets()[kind]
    table, empty = shapes[at], shapes[at + 1]
    assert len(table) == 1 and len(empty) == 0
    extra = (None, None, -1) if kind == "sphere" else (shapes[at + 2:at + 2 + len(INSTANCED) + len(dispatch.MESH_SLOTS)],)
    shadow_extra = () if kind == "sphere" else extra
    scan, any_hit = getattr(generated, "scan_" + kind), getattr(generated, "any_hit_" + kind)
    ray = ((0.3, 0.2, 1.0), (0.0, 0.0, -1.0), 0.0)     # straight at the sphere, instanced or not
    none = (math.inf, -1, -1, -1)
    assert scan(table, empty, *extra, *ray, none, 0) == none
    assert not any_hit(table, empty, *shadow_extra, *ray, math.inf, 0)
    t, index, _, row = scan(table, flat.index(kind), *extra, *ray, none, 0)
    assert (index, row) == (0, 0) and t == pytest.approx(2.1)
    assert any_hit(table, flat.index(kind), *shadow_extra, *ray, math.inf, 0)


@pytest.mark.parametrize("wide", [True, False])
def test_the_empty_tree_is_entered_by_no_ray(monkeypatch, wide):
    """empty_tree, what the debugger is given for a scene without a tree of its own, in the
    wide layout and the binary one (a CPU without AVX): every traversal returns the hit it
    was given, and no shadow ray is stopped, for rays along the axes and off them, from
    the origin and far from it."""
    import math

    import numpy as np

    from rtfgu.kernels import render
    from rtfgu.kernels.mesh import mesh_any, mesh_closest

    if wide and not render.WIDE:
        pytest.skip("this CPU has no AVX: the numba path has no wide tree")
    monkeypatch.setattr(render, "WIDE", wide)
    vertices, faces, _, nodes, links, _ = render.empty_tree(np.float64)
    assert nodes.ndim == (3 if wide else 2)
    given = (5.0, 3, 1, 7)
    for origin in ((0.0, 0.0, 0.0), (1.0, -2.0, 0.5), (-1e30, 3.0, 1e-30)):
        for direction in ((1.0, 0.0, 0.0), (0.0, -1.0, 0.0), (0.0, 0.0, 1.0), (0.6, 0.0, -0.8)):
            assert mesh_closest(vertices, faces, nodes, links, None, origin, direction, 0.0, given, 0) == given
            assert not mesh_any(vertices, faces, nodes, links, None, origin, direction, 0.0, math.inf, 0)
