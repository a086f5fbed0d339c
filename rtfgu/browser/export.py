"""A scene as one self-contained WebGPU page: the WGSL path (rtfgu/wgsl) in a browser.

The page holds the very program the wgpu runner compiles (``assemble_scene``, the same
assembler and the same text), the scene's buffers as ``Binding.pack`` writes them
(base64), the bytes of ``struct Uniforms`` of every dispatch in the runner's tiles and
sample batches (``runner.tiles``, ``runner.sample_batches``), and page.js, which binds them
as the runner does (group 0: the uniforms and the scene arrays, group 1: the image sums),
dispatches frame by frame, one batch of samples over every tile a frame, and draws the mean
so far into a canvas with gamma (display.wgsl; 02562's ``main_fs``). A GPU error (a shader
that does not compile, a lost device, a validation error) is shown on the page as text,
with the file and line of rtfgu/wgsl it points at, instead of a black image.

Opened with ``?report=URL``, the page posts its result there as JSON (rtfgu/browser/
headless.py): ``{"ok": true, "width", "height", "samples", "sums": base64 float32 RGBA
sums, "canvas": base64 RGBA8 of the canvas, "seconds"}`` or ``{"ok": false, "message"}``.
"""
from __future__ import annotations

import base64
import json
from importlib import resources

from .. import layout
from ..options import pixel_sampler
from ..wgsl import structs
from ..wgsl.assemble import GENERATED, PieceNotInRelease
from ..wgsl.runner import DEFAULT_SCENE_BUFFER, TILE, assemble_scene, sample_batches, tiles, workgroups
from ..image import GAMMA

# The camera constant d of each camera record that has one: the page's zoom.
ZOOM_FIELD = "d"


def _read(name: str) -> str:
    return resources.files(__package__).joinpath(name).read_text(encoding="utf-8")


def _b64(data: bytes) -> str:
    return base64.b64encode(data).decode("ascii")


def _origins(program) -> dict:
    """Per line of the program: the file it came from (as a compile error names it,
    rtfgu/wgsl/runner.py) and its line there."""
    files, index, lines = [], {}, []
    for file, line in program.line_origin:
        shown = file if file == GENERATED else "rtfgu/wgsl/%s" % file
        if shown not in index:
            index[shown] = len(files)
            files.append(shown)
        lines.append([index[shown], line])
    return {"files": files, "lines": lines}


def _zoom(flat, bindings):
    """Where the camera constant sits in the camera buffer (float index), or None for a
    camera without one (the orthographic camera)."""
    record = layout.CAMERA_RECORDS[flat.camera_kind]
    columns = {name: column for name, _, column in layout.RECORDS[record][1]}
    if ZOOM_FIELD not in columns:
        return None
    camera = next(b for b in bindings if b.name == "camera")
    return {"binding": camera.number, "index": columns[ZOOM_FIELD],
            "value": float(flat.camera.reshape(-1)[columns[ZOOM_FIELD]])}


def scene_data(scene, width: int, height: int, spp: int | None = None, seed: int = 0,
               name: str = "", overrides=None, tile: int = TILE, formula: str | None = None) -> dict:
    """Everything page.js needs to render ``scene`` at ``width`` x ``height`` as the wgpu
    path does (rtfgu.render(..., backend="wgpu", spp=spp, seed=seed, formula=formula)), as
    JSON-ready values. ``overrides``: WGSL pieces put in place of the package's
    (rtfgu.wgsl.assemble)."""
    scene.validate()
    sampler = pixel_sampler(scene, spp)
    total = 1 if sampler is None else sampler.num_samples
    flat, program = assemble_scene(scene, DEFAULT_SCENE_BUFFER, overrides, formula, sampler)
    background = flat.background[:3]
    frames = []
    for batch in sample_batches(program, (0, total)):
        frames.append({"end_sample": batch[1], "dispatches": [
            {"uniforms": _b64(structs.uniforms(background, seed, width, height, origin, size, batch)),
             "workgroups": list(workgroups(size))}
            for origin, size in tiles(width, height, tile)]})
    return {
        "name": name, "width": width, "height": height, "samples": total, "seed": seed,
        "wgsl": program.source,
        "origins": _origins(program),
        "uniforms_size": structs.UNIFORMS_SIZE,
        "bindings": [{"number": b.number, "name": b.name, "kind": b.kind, "data": _b64(b.pack(flat))}
                     for b in program.bindings],
        "frames": frames,
        "zoom": _zoom(flat, program.bindings),
    }


def _script_text(text: str) -> str:
    """``text`` safe inside a <script> element: no "</" can end it early."""
    return text.replace("</", "<\\/")


def page_html(scenes: list, selected: int = 0, menu: str = "shader") -> str:
    """The page of ``scene_data`` results of one size: page.html with them, display.wgsl and
    page.js put in; it renders ``scenes[selected]`` and offers the others in a menu labelled
    ``menu``."""
    first = scenes[selected]
    for data in scenes:
        if (data["width"], data["height"]) != (first["width"], first["height"]):
            raise ValueError("page_html: scene %r is %dx%d, scene %r %dx%d: a page has one size"
                             % (data["name"], data["width"], data["height"], first["name"],
                                first["width"], first["height"]))
    page = {"width": first["width"], "height": first["height"], "gamma": GAMMA,
            "scenes": scenes, "selected": selected, "menu": menu}
    title = first["name"] or "rtfgu scene"
    scene_json = json.dumps(page, separators=(",", ":")).replace("<", "\\u003c")
    html = _read("page.html")
    for marker, text in (("{{TITLE}}", title.replace("&", "&amp;").replace("<", "&lt;")),
                         ("{{SCENE_JSON}}", scene_json),
                         ("{{DISPLAY_WGSL}}", _script_text(_read("display.wgsl"))),
                         ("{{PAGE_JS}}", _script_text(_read("page.js")))):
        if marker not in html:
            raise ValueError("rtfgu/browser/page.html: the marker %s is missing" % marker)
        html = html.replace(marker, text)
    return html


def scene_page(scene, width: int, height: int, spp: int | None = None, seed: int = 0,
               name: str = "", overrides=None, formula: str | None = None) -> str:
    """The self-contained HTML page that renders ``scene`` with WebGPU."""
    return page_html([scene_data(scene, width, height, spp, seed, name, overrides, formula=formula)])


def menu_page(scenes: dict, selected: str, width: int, height: int, spp: int | None = None,
              seed: int = 0, formula: str | None = None, menu: str = "shader") -> str:
    """One page for the scenes {name: Scene}, showing ``selected`` first and the others in a
    menu labelled ``menu``: the worksheets' shader menu (rtfgu.scenes.default_scene.SHADER_MENU)
    or subdivision level (rtfgu.scenes.sampling.SUBDIVISION_MENU). A scene whose WGSL pieces
    this copy leaves out (a student release) is left out of the menu."""
    if selected not in scenes:
        raise ValueError("menu_page: %r is not among %s" % (selected, ", ".join(scenes)))
    data = []
    for name, scene in scenes.items():
        try:
            data.append(scene_data(scene, width, height, spp, seed, name, formula=formula))
        except PieceNotInRelease:
            if name == selected:
                raise
    return page_html(data, [d["name"] for d in data].index(selected), menu)


def index_html(names) -> str:
    """A page of links to the scene pages NAME.html beside it (make html's html/index.html)."""
    links = "\n".join('<li><a href="%s.html">%s</a></li>' % (name, name) for name in names)
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head><meta charset=\"utf-8\"><title>rtfgu scenes</title></head>\n"
            "<body>\n<h1>The homework scenes, rendered with WebGPU</h1>\n<ul>\n%s\n</ul>\n</body>\n</html>\n" % links)
