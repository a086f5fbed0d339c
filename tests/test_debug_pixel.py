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


@pytest.mark.parametrize("precision", ["float32", "float64"])
def test_one_debugger_kernel_serves_every_scene_of_a_kind(precision):
    """The numba debugger's arguments (rtfgu.kernels.debug.scene_arguments) have one numba
    type for every homework scene of a precision without a mesh, and one for the scenes
    whose BVH holds the same kinds (a tree of their own, spheres, instances): it compiles
    once for each, not once per scene's features (textures, an environment, samplers of
    their own, smooth normals, (u, v)), each compile some 40 s."""
    import numba

    from rtfgu.kernels.debug import scene_arguments
    from rtfgu.layout import compile_scene
    from rtfgu.scenes import SCENES

    types = {}
    for name, make in SCENES.items():
        flat = compile_scene(make(), precision)
        mesh = flat.mesh
        family = "no mesh" if mesh is None else "BVH of %s" % ", ".join(
            kind for kind, held in (("a tree", mesh.scene_tree), ("spheres", mesh.spheres),
                                    ("instances", mesh.instances)) if held)
        types.setdefault(family, {}).setdefault(numba.typeof(scene_arguments(flat)), []).append(name)
    assert {"no mesh", "BVH of a tree"} <= set(types), sorted(types)
    for family, kinds in types.items():
        assert len(kinds) == 1, "%s, %s: %d kernels: %s" % (
            precision, family, len(kinds), [names[:3] for names in kinds.values()])
