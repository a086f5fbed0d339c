"""Every homework scene's WebGPU page (rtfgu/browser) renders in headless Chromium the image
the wgpu path renders, shows a GPU error as text naming the WGSL file and line, and a page
that reports nothing fails with a message, not a black image.

One Chromium process renders every page (rtfgu/browser/headless.py); the tests skip where
Chromium is not installed, naming its Debian package.
"""
from __future__ import annotations

import json
import re

import numpy as np
import pytest

from rtfgu import renderer
from rtfgu.__main__ import main, scene_at
from rtfgu.browser import menu_page, scene_page
from rtfgu.browser import headless
from rtfgu.image import to_8bit, write_png
from rtfgu.options import pixel_sampler
from rtfgu.scenes import SCENES
from rtfgu.scenes.default_scene import SHADER_MENU
from rtfgu.scenes.sampling import SUBDIVISION_MENU
from rtfgu.wgsl.assemble import read_piece
from rtfgu.wgsl.runner import assemble_scene

from wgsl_support import wgpu_device  # noqa: F401  (fixture)

WIDTH, HEIGHT = 64, 48
# 02562 parity criterion, as tests/test_wgsl_render.py: at least 99.9 % of 8-bit pixels
# within 1/255 of the wgpu path's.
MIN_AGREEING = 0.999
# A path-traced scene: a path's Russian roulette decides on its float32 throughput, which two
# adapters (SwiftShader in Chromium, Mesa under wgpu) may round to either side of the random
# number: a few pixels then follow other paths, as a few samples of 4.
MIN_AGREEING_PATHS = 0.995
# Chromium's whole run, every page together.
TIMEOUT = 300
BROKEN = "broken_lambertian"
# The shader menu's page with its controls set by the query string.
CONTROLS = "shader_menu"
CONTROLLED_SCENE, ZOOM, CONTROLLED_GAMMA = "default_mirror_sphere", 1.5, 1.0
# Worksheet 3's subdivision level: the page of level 1, set to level 4 by the query string.
SUBDIVISION = "subdivision_menu"


def spp_of(name):
    """As tests/test_wgsl_render.py: a sampled scene at 4 samples, else one through the centre."""
    return 4 if SCENES[name]().sampler is not None else None


def broken_lambertian():
    """default_lambertian with an undefined name in brdf_lambertian, and where it is."""
    lines = read_piece("lambertian.wgsl").splitlines()
    target = next(i for i, line in enumerate(lines) if "(*hit).kd" in line)
    lines[target] = "    return (*hit).color * undefined_diffuse;"
    return {"lambertian.wgsl": "\n".join(lines) + "\n"}, target + 1


@pytest.fixture(scope="module")
def chromium():
    try:
        return headless.find_chromium()
    except headless.BrowserNotFound as error:
        pytest.skip(str(error))


@pytest.fixture(scope="module")
def page_results(chromium, tmp_path_factory):
    """{name: the page's result} of every homework scene at WIDTH x HEIGHT, of BROKEN, of the
    shader menu's page (CONTROLS) and of the subdivision level's (SUBDIVISION, written by
    the command line), from one Chromium run."""
    pages = {}
    for name in SCENES:
        scene, width, height = scene_at(name, WIDTH, HEIGHT)
        pages[name] = scene_page(scene, width, height, spp=spp_of(name), name=name)
    overrides, _ = broken_lambertian()
    scene, width, height = scene_at("default_lambertian", WIDTH, HEIGHT)
    pages[BROKEN] = scene_page(scene, width, height, name=BROKEN, overrides=overrides)
    menu = {name: scene_at(name, WIDTH, HEIGHT)[0] for name in SHADER_MENU}
    pages[CONTROLS] = menu_page(menu, SHADER_MENU[0], WIDTH, HEIGHT)
    out = tmp_path_factory.mktemp("pages") / "subdivision.html"
    assert main(["export-html", SUBDIVISION_MENU[0], "-o", str(out), "--width", str(WIDTH),
                 "--height", str(HEIGHT)]) in (0, None)
    pages[SUBDIVISION] = out.read_text()
    results = headless.render_pages(pages, timeout=TIMEOUT, queries={
        CONTROLS: "scene=%s&zoom=%r&gamma=%r" % (CONTROLLED_SCENE, ZOOM, CONTROLLED_GAMMA),
        SUBDIVISION: "scene=%s" % SUBDIVISION_MENU[2]})
    results["pages"] = pages
    return results


@pytest.mark.parametrize("name", list(SCENES))
def test_page_renders_the_wgpu_image(page_results, wgpu_device, name, output_dir):
    result = page_results[name]
    assert result.get("ok"), "%s: the page failed: %s" % (name, result.get("message"))
    page, canvas = headless.result_images(result)
    scene, width, height = scene_at(name, WIDTH, HEIGHT)
    wgpu = renderer.render(scene, width, height, backend="wgpu", spp=spp_of(name))
    ours, theirs = to_8bit(page).astype(int), to_8bit(wgpu).astype(int)
    differs = np.abs(ours - theirs).max(axis=2) > 1
    agreeing = 1.0 - differs.mean()
    from rtfgu.tracers import PathTrace
    least = MIN_AGREEING_PATHS if isinstance(scene.tracer, PathTrace) else MIN_AGREEING
    if agreeing < least:
        output_dir.mkdir(parents=True, exist_ok=True)
        write_png(page, output_dir / ("%s.browser.png" % name))
        write_png(wgpu, output_dir / ("%s.wgpu.png" % name))
    assert agreeing >= least, "%s: %.4f of the page's pixels agree with the wgpu path's" % (
        name, agreeing)
    # The canvas shows the same mean with gamma (display.wgsl as rtfgu.image.to_8bit).
    shown = np.abs(canvas.astype(int) - ours).max(axis=2)
    assert shown.max() <= 1, "%s: the canvas differs from the page's image by %d/255 at %s" % (
        name, shown.max(), np.unravel_index(shown.argmax(), shown.shape))


def test_the_shader_menu_zoom_and_gamma_render_what_they_say(page_results, wgpu_device):
    """The menu's page, set to the mirror sphere, camera constant 1.5 and gamma 1, renders
    that scene with that camera as the wgpu path does, and shows it with that gamma."""
    result = page_results[CONTROLS]
    assert result.get("ok"), result.get("message")
    assert result["name"] == CONTROLLED_SCENE and result["gamma"] == CONTROLLED_GAMMA
    page, canvas = headless.result_images(result)
    scene, width, height = scene_at(CONTROLLED_SCENE, WIDTH, HEIGHT)
    unzoomed = renderer.render(scene, width, height, backend="wgpu")
    scene.camera.d = ZOOM
    wgpu = renderer.render(scene, width, height, backend="wgpu")
    ours = to_8bit(page).astype(int)
    assert (np.abs(ours - to_8bit(wgpu).astype(int)).max(axis=2) <= 1).mean() >= MIN_AGREEING
    assert (np.abs(ours - to_8bit(unzoomed).astype(int)).max(axis=2) > 1).mean() > 0.1
    shown = np.abs(canvas.astype(int) - to_8bit(page, gamma=CONTROLLED_GAMMA).astype(int))
    assert shown.max() <= 1, "the canvas is not the image with gamma %r" % CONTROLLED_GAMMA


def test_the_subdivision_level_menu_renders_the_level_chosen(page_results, wgpu_device):
    """The page export-html writes for worksheet 3's anti-aliasing offers its subdivision levels;
    set to level 4 (16 jittered samples per pixel) it renders what the wgpu path renders."""
    result = page_results[SUBDIVISION]
    assert result.get("ok"), result.get("message")
    assert result["name"] == SUBDIVISION_MENU[2] and result["samples"] == 16
    assert '"menu":"subdivision level"' in page_results["pages"][SUBDIVISION]
    page, _ = headless.result_images(result)
    scene, width, height = scene_at(SUBDIVISION_MENU[2], WIDTH, HEIGHT)
    wgpu = renderer.render(scene, width, height, backend="wgpu")
    level_1 = renderer.render(scene_at(SUBDIVISION_MENU[0], WIDTH, HEIGHT)[0], width, height, backend="wgpu")
    ours = to_8bit(page).astype(int)
    assert (np.abs(ours - to_8bit(wgpu).astype(int)).max(axis=2) <= 1).mean() >= MIN_AGREEING
    assert (np.abs(ours - to_8bit(level_1).astype(int)).max(axis=2) > 1).mean() > 0.005


def test_a_shader_that_does_not_compile_is_shown_by_its_file_and_line(page_results):
    result = page_results[BROKEN]
    _, line = broken_lambertian()
    assert not result.get("ok"), "the page with undefined_diffuse rendered"
    message = result["message"]
    assert "did not compile" in message
    assert re.search(r"rtfgu/wgsl/lambertian\.wgsl:%d:\d+" % line, message), message
    assert "undefined_diffuse" in message


def test_a_page_that_reports_nothing_fails_with_a_message(chromium):
    silent = "<!DOCTYPE html><html><body><p>no WebGPU here</p></body></html>"
    result = headless.render_pages({"silent": silent}, timeout=2)["silent"]
    assert not result["ok"]
    assert "silent: the page reported no result within 2 s" in result["message"]
    with pytest.raises(RuntimeError, match="no result"):
        headless.result_images(result)


def test_a_browser_that_exits_at_once_is_named_with_its_output(tmp_path, monkeypatch):
    fake = tmp_path / "chromium"
    fake.write_text("#!/bin/sh\necho cannot open display >&2\nexit 3\n")
    fake.chmod(0o755)
    monkeypatch.setenv("PATH", str(tmp_path))
    result = headless.render_pages({"scene": "<html></html>"}, timeout=60)["scene"]
    assert not result["ok"]
    assert "Chromium exited (code 3) before the page reported a result" in result["message"]
    assert "cannot open display" in result["message"]


def test_export_html_holds_the_program_the_wgpu_path_runs(tmp_path):
    """The command line's page carries the very WGSL text and buffers the runner compiles."""
    out = tmp_path / "page.html"
    assert main(["export-html", "suffern_disks", "-o", str(out), "--width", "40", "--height", "30"]) == 0
    text = out.read_text(encoding="utf-8")
    page = json.loads(re.search(r'<script type="application/json" id="rtfgu-scene">(.*?)</script>',
                                text, re.S).group(1))
    assert len(page["scenes"]) == 1
    data = page["scenes"][page["selected"]]
    scene, width, height = scene_at("suffern_disks", 40, 30)
    flat, program = assemble_scene(scene, sampler=pixel_sampler(scene, None))
    assert data["wgsl"] == program.source
    assert [b["number"] for b in data["bindings"]] == [b.number for b in program.bindings]
    assert (data["width"], data["height"]) == (40, 30)
    samples = 1 if scene.sampler is None else scene.sampler.num_samples
    assert data["frames"][-1]["end_sample"] == samples
    assert "</script" not in data["wgsl"] and text.count("</script>") == 3


def test_a_page_of_the_shader_menu_offers_the_menu(tmp_path):
    out = tmp_path / "page.html"
    assert main(["export-html", "default_phong_sphere", "-o", str(out)]) == 0
    page = json.loads(re.search(r'<script type="application/json" id="rtfgu-scene">(.*?)</script>',
                                out.read_text(encoding="utf-8"), re.S).group(1))
    assert [s["name"] for s in page["scenes"]] == list(SHADER_MENU)
    assert page["scenes"][page["selected"]]["name"] == "default_phong_sphere"
    assert len({s["wgsl"] for s in page["scenes"]}) == len(SHADER_MENU)   # each its own program


def test_export_html_all_writes_a_page_per_scene_and_an_index(tmp_path, capsys):
    assert main(["export-html-all", "--out", str(tmp_path)]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([n + ".html" for n in SCENES] + ["index.html"])
    index = (tmp_path / "index.html").read_text(encoding="utf-8")
    assert re.findall(r'href="(\w+)\.html"', index) == list(SCENES)


def test_export_html_refuses_an_unknown_scene(tmp_path, capsys):
    with pytest.raises(SystemExit) as caught:
        main(["export-html", "no_such_scene", "-o", str(tmp_path / "x.html")])
    assert caught.value.code == 2
    assert "unknown scene name 'no_such_scene'" in capsys.readouterr().err
