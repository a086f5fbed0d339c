"""The WGSL path renders every homework scene as the numba float32 path does, reports a broken
WGSL function by its line, reuses its pipeline when the camera or a light moves, and
assembles only what a scene uses.

Runs on whatever adapter rtfgu.wgsl.device finds (llvmpipe in CI); skips only where there
is none, naming the package to install.
"""
from __future__ import annotations

import numpy as np
import pytest

from rtfgu import renderer
from rtfgu.float3 import Float3
from rtfgu.image import to_8bit, write_png
from rtfgu.layout import compile_scene
from rtfgu.scenes import SCENES
from rtfgu.wgsl import WGSLCompileError, assemble, prepare, render_wgpu
from rtfgu.wgsl import device as wgsl_device
from rtfgu.wgsl import runner
from rtfgu.wgsl.assemble import read_piece

from wgsl_support import wgpu_device  # noqa: F401  (fixture)

SIZE = 32
# 02562 parity criterion: at least 99.9 % of 8-bit pixels within 1/255 of the comparison path.
MIN_AGREEING = 0.999
# A pixel is on a silhouette when a neighbour differs from it by more than this (8-bit steps):
# a jump that smooth shading between neighbouring pixels of a 32x32 image never makes.
SILHOUETTE_STEP = 24


def comparison_backend() -> tuple[str, str]:
    """numba float32 once that path exists, else the float64 reference."""
    if "numba" in renderer.BACKENDS:
        return "numba", "float32"
    return "reference", "float64"


def silhouette_mask(image8: np.ndarray) -> np.ndarray:
    padded = np.pad(image8.astype(int), ((1, 1), (1, 1), (0, 0)), mode="edge")
    h, w = image8.shape[:2]
    step = np.zeros((h, w), dtype=int)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            neighbour = padded[1 + dy:1 + dy + h, 1 + dx:1 + dx + w]
            step = np.maximum(step, np.abs(neighbour - image8).max(axis=2))
    return step > SILHOUETTE_STEP


@pytest.mark.parametrize("name", list(SCENES))
def test_homework_scene_matches_numba_float32(wgpu_device, name, output_dir):
    backend, precision = comparison_backend()
    spp = 4 if SCENES[name]().sampler is not None else None  # a sampled scene at 4 samples
    ours = to_8bit(renderer.render(SCENES[name](), SIZE, SIZE, backend="wgpu", spp=spp)).astype(int)
    theirs = to_8bit(renderer.render(SCENES[name](), SIZE, SIZE, backend=backend,
                                     precision=precision, spp=spp)).astype(int)
    differs = np.abs(ours - theirs).max(axis=2) > 1
    agreeing = 1.0 - differs.mean()
    off_silhouette = differs & ~silhouette_mask(theirs)
    if agreeing < MIN_AGREEING or off_silhouette.any():
        output_dir.mkdir(parents=True, exist_ok=True)
        write_png(ours / 255.0, output_dir / ("%s.wgsl.png" % name), gamma=1.0)
        write_png(theirs / 255.0, output_dir / ("%s.%s.png" % (name, backend)), gamma=1.0)
        diff = np.repeat(differs[:, :, None], 3, axis=2).astype(float)
        write_png(diff, output_dir / ("%s.wgsl-diff.png" % name), gamma=1.0)
    assert agreeing >= MIN_AGREEING, "%s: %.4f of pixels agree with %s %s" % (
        name, agreeing, backend, precision)
    assert not off_silhouette.any(), "%s: pixels %s differ away from silhouettes" % (
        name, list(zip(*np.nonzero(off_silhouette))))


def test_wgsl_is_not_blank_where_the_scene_is_lit(wgpu_device):
    image = render_wgpu(SCENES["default_lambertian_shadows"](), SIZE, SIZE)
    assert image.max() > 0.1
    assert len(np.unique(image.reshape(-1, 3), axis=0)) > 10


def test_broken_wgsl_function_is_reported_by_its_line(wgpu_device):
    text = read_piece("lambertian.wgsl")
    lines = text.splitlines()
    target = next(i for i, line in enumerate(lines) if "(*hit).kd" in line)   # f_r = kd cd / pi
    lines[target] = "    return (*hit).color * undefined_diffuse;"
    broken = "\n".join(lines) + "\n"
    with pytest.raises(WGSLCompileError) as caught:
        prepare(SCENES["default_lambertian"](), overrides={"lambertian.wgsl": broken})
    error = caught.value
    assert error.file == "rtfgu/wgsl/lambertian.wgsl"
    assert error.line == target + 1
    assert error.function == "brdf_lambertian"
    message = str(error)
    assert "lambertian.wgsl:%d" % (target + 1) in message
    assert "undefined_diffuse" in message


def test_type_error_in_a_shader_names_its_function(wgpu_device):
    text = read_piece("mirror.wgsl").replace("return (*hit).emission;", "return 1.0;")
    with pytest.raises(WGSLCompileError) as caught:
        prepare(SCENES["default_mirror_sphere"](), overrides={"mirror.wgsl": text})
    assert caught.value.file == "rtfgu/wgsl/mirror.wgsl"
    assert caught.value.function == "mirror"


def test_moving_camera_and_light_reuses_the_pipeline(wgpu_device):
    scene = SCENES["default_phong_sphere"]()
    first = prepare(scene)
    image1 = first.render(SIZE, SIZE).copy()
    compiles = runner.COMPILES

    scene.lights[0].position = Float3(0.5, 1.2, 0.3)
    moved_light = prepare(scene)
    image2 = moved_light.render(SIZE, SIZE).copy()

    scene.camera = type(scene.camera)(Float3(-2.0, 1.0, 2.0), Float3(0.0, 0.5, 0.0),
                                      Float3(0.0, 1.0, 0.0))
    moved_camera = prepare(scene)
    image3 = moved_camera.render(SIZE, SIZE).copy()

    assert moved_light is first and moved_camera is first
    assert moved_light.pipeline is first.pipeline
    assert runner.COMPILES == compiles
    assert np.abs(image2 - image1).max() > 0.05
    assert np.abs(image3 - image2).max() > 0.05
    # and the new data renders what the new scene shows
    reference = renderer.render(scene, SIZE, SIZE, backend="reference")
    assert (np.abs(to_8bit(image3).astype(int) - to_8bit(reference).astype(int)).max(axis=2) <= 1).mean() \
        >= MIN_AGREEING


def test_tiles_do_not_show(wgpu_device):
    compiled = prepare(SCENES["default_glossy_sphere"]())
    whole = compiled.render(37, 29, tile=64).copy()
    tiled = compiled.render(37, 29, tile=8)
    np.testing.assert_array_equal(whole, tiled)


def test_storage_buffers_render_the_same(wgpu_device):
    scene = SCENES["default_refractive_sphere"]()
    uniform = render_wgpu(scene, SIZE, SIZE, scene_buffer="uniform")
    storage = render_wgpu(scene, SIZE, SIZE, scene_buffer="storage")
    np.testing.assert_array_equal(uniform, storage)


def test_wgpu_refuses_float64():
    with pytest.raises(ValueError, match="precision"):
        renderer.render(SCENES["default_flat_colors"](), 4, 4, backend="wgpu", precision="float64")


def test_no_adapter_names_the_package_to_install(monkeypatch):
    import wgpu

    monkeypatch.setattr(wgsl_device, "_DEVICE", None)
    monkeypatch.setattr(wgpu.gpu, "enumerate_adapters_sync", lambda: [])
    with pytest.raises(wgsl_device.NoAdapterError) as caught:
        wgsl_device.get_device()
    assert "libgl1-mesa-dri" in str(caught.value)
    assert "mesa-vulkan-drivers" in str(caught.value)


def _program(name):
    return assemble(compile_scene(SCENES[name](), "float32"))


def test_shade_switch_holds_only_the_cases_the_scene_uses():
    mirror = _program("default_mirror_sphere").source
    assert "case MIRROR" in mirror and "case LAMBERTIAN" in mirror
    assert "case PHONG" not in mirror and "fn brdf_phong" not in mirror
    assert "fn transparent" not in mirror
    flat = _program("default_flat_colors").source
    assert "fn brdf_lambertian" not in flat and "fn sample_point_light" not in flat
    assert "case default" in flat
    no_shadows = _program("default_lambertian").source
    assert "fn in_shadow" not in no_shadows and "in_shadow(" not in no_shadows
    assert "fn in_shadow" in _program("default_lambertian_shadows").source
    ortho = _program("lecture01_flat_colors").source
    assert "struct OrthographicCamera" in ortho and "PinholeCamera" not in ortho
    assert "fn intersect_triangle" not in ortho and "fn intersect_sphere" in ortho
    directions = _program("default_ray_directions").source
    assert "fn intersect_scene" not in directions and "fn shade" not in directions


def test_assembled_order_defines_before_use():
    source = _program("default_glossy_sphere").source
    order = ["struct Ray", "struct HitInfo", "fn get_camera_ray", "fn intersect_plane",
             "fn intersect_triangle", "fn intersect_sphere", "fn sample_point_light",
             "fn in_shadow", "fn brdf_phong", "fn direct_light", "fn mirror" if "fn mirror" in source else "",
             "fn transparent", "fn glossy", "fn shade", "fn intersect_scene", "fn main"]
    positions = [source.index(item) for item in order if item]
    assert positions == sorted(positions)


def test_camera_and_light_values_are_not_in_the_program_text():
    scene = SCENES["default_lambertian_shadows"]()
    before = assemble(compile_scene(scene, "float32")).source
    scene.lights[0].position = Float3(0.25, 2.0, -0.5)
    scene.camera = type(scene.camera)(Float3(3.0, 2.0, 1.0), Float3(0.0, 0.5, 0.0),
                                      Float3(0.0, 1.0, 0.0))
    assert assemble(compile_scene(scene, "float32")).source == before


def test_export_wgsl_and_info_commands(tmp_path, wgpu_device, capsys):
    from rtfgu.__main__ import main

    out = tmp_path / "mirror.wgsl"
    assert main(["export-wgsl", "default_mirror_sphere", "-o", str(out)]) == 0
    assert out.read_text() == _program("default_mirror_sphere").source
    assert main(["info"]) == 0
    printed = capsys.readouterr().out
    assert wgsl_device.adapter_description() in printed


def test_scene_without_shapes_shows_its_background(wgpu_device):
    from rtfgu.scene import Scene

    scene = Scene(SCENES["default_flat_colors"]().camera)
    scene.background = Float3(0.2, 0.3, 0.4)
    image = render_wgpu(scene, 8, 8)
    np.testing.assert_allclose(image, np.broadcast_to([0.2, 0.3, 0.4], image.shape), rtol=1e-6)


def test_arrays_too_large_for_a_uniform_binding_go_to_storage():
    from rtfgu.shapes import Sphere

    scene = SCENES["default_lambertian"]()
    for k in range(1400):  # 1403 materials x 48 bytes > 64 KiB
        scene.shapes.append(Sphere(Float3(0.01 * k, 0.0, -5.0), 0.01, Float3(0.5, 0.5, 0.5)))
    kinds = {b.name: b.kind for b in assemble(compile_scene(scene, "float32")).bindings}
    assert kinds["materials"] == "storage"
    assert kinds["spheres"] == "uniform" and kinds["camera"] == "uniform"


def test_a_process_without_a_runtime_dir_gets_a_private_one_and_mesa_stays_quiet(wgpu_device, tmp_path, monkeypatch):
    """Mesa's Vulkan driver (lavapipe) prints "error: XDG_RUNTIME_DIR is invalid or not set"
    through libwayland once per probe where the variable is missing (a container, CI, ssh);
    the device gives the process a private, empty one first. A folder others can write to is
    not kept either (the XDG Base Directory specification requires mode 0700)."""
    import os
    import stat
    import subprocess
    import sys

    monkeypatch.delenv("XDG_RUNTIME_DIR", raising=False)
    wgsl_device._runtime_dir()
    made = os.environ["XDG_RUNTIME_DIR"]
    info = os.stat(made)
    assert stat.S_ISDIR(info.st_mode) and info.st_uid == os.getuid() and stat.S_IMODE(info.st_mode) == 0o700
    open_folder = tmp_path / "open"
    open_folder.mkdir()
    open_folder.chmod(0o777)
    monkeypatch.setenv("XDG_RUNTIME_DIR", str(open_folder))
    wgsl_device._runtime_dir()
    assert os.environ["XDG_RUNTIME_DIR"] not in (str(open_folder), made)
    kept = os.environ["XDG_RUNTIME_DIR"]
    wgsl_device._runtime_dir()
    assert os.environ["XDG_RUNTIME_DIR"] == kept
    # As a user runs it: a wgpu render in a process without the variable prints no such error.
    env = {k: v for k, v in os.environ.items() if k != "XDG_RUNTIME_DIR"}
    done = subprocess.run([sys.executable, "-m", "rtfgu", "render", "default_flat_colors", "--backend", "wgpu",
                           "--width", "8", "--height", "8", "--out", str(tmp_path / "x.png")],
                          env=env, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert "XDG_RUNTIME_DIR" not in done.stdout + done.stderr
