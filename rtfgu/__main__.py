"""The command line: ``python -m rtfgu list | render | render-all | info | export-wgsl | export-html | export-html-all | debug-pixel``.

Errors in what the user typed (unknown scene, bad size, bad backend) exit with code 2 and a
message naming the parameter, as argparse does for its own errors.
"""
from __future__ import annotations

import argparse
import os
import sys
import time

from . import renderer as render_module
from .cameras import PinholeCamera
from .image import write_png
from .progress import TimeLeft
from .scenes import SCENES, get_scene
from .wgsl import NoAdapterError, WGSLCompileError


BAR = 30


def _progress_printer(label: str, stream=None):
    """progress(done, total) drawing a bar on one line of standard error, at most twice a
    second, with the time so far and the time left (rtfgu.progress.TimeLeft: the pace since
    the first report, which also holds compiling the kernels)."""
    clock = TimeLeft()
    shown = [0.0]

    def progress(done: int, total: int) -> None:
        clock.update(done, total)
        if done < total and clock.elapsed - shown[0] < 0.5:
            return  # a line every half second is enough to show it is alive
        shown[0] = clock.elapsed
        filled = BAR * done // total
        end = "\n" if done == total else ""
        print("\r%s [%s%s] %3d%%  %.1f s, %s" % (
            label, "#" * filled, "." * (BAR - filled), 100 * done // total, clock.elapsed, clock.describe()),
            end=end, file=stream or sys.stderr, flush=True)
    return progress


# What the first render on a backend in a process waits for, said before it starts.
COMPILING = {
    "numba": "numba: compiling the kernels this scene needs, or loading them from numba's cache "
             "(about 20 s the first time)",
    "wgpu": "wgpu: compiling the scene's WGSL program on the adapter (a few seconds per scene)",
}
_announced = set()


def _announce_compiling(backend: str, stream=None) -> None:
    if backend in COMPILING and backend not in _announced:
        _announced.add(backend)
        print(COMPILING[backend], file=stream or sys.stderr, flush=True)


# Passes of a long render: the progress bar moves (and a notebook refreshes) once per pass.
PROGRESS_PASSES = 16


def scene_at(name, width=None, height=None):
    """(the scene ``name``, width, height): its homework size unless given; at another size
    a pinhole camera follows the aspect ratio, so that pixels stay square."""
    fn = get_scene(name)
    w, h = fn.size
    width = w if width is None else width
    height = h if height is None else height
    render_module.check_size(width, height)
    scene = fn()
    if isinstance(scene.camera, PinholeCamera) and (width, height) != (w, h):
        scene.camera.aspect = width / height
    return scene, width, height


def _render_one(name, width, height, backend, precision, out, show_progress, spp=None, seed=0):
    scene, width, height = scene_at(name, width, height)
    if show_progress:
        _announce_compiling(backend or render_module.DEFAULT_BACKEND)
    progress = _progress_printer(name) if show_progress else None
    start = time.perf_counter()
    samples = spp or (scene.sampler.num_samples if scene.sampler is not None else 1)
    passes = PROGRESS_PASSES if show_progress and samples > 1 else 1
    image = render_module.render(scene, width, height, backend=backend, precision=precision,
                                 progress=progress, spp=spp, seed=seed, passes=passes)
    write_png(image, out)
    return time.perf_counter() - start, width, height, samples


def _debug_pixel(args) -> None:
    """Trace one pixel on every path and print them side by side (rtfgu/debug.py)."""
    from .debug import PATHS, TOLERANCES, PathNotInRelease, report, trace_pixel

    scene, width, height = scene_at(args.name, args.width, args.height)
    traces, tolerances, notes = {}, {}, []
    for label, backend, precision in PATHS:
        formula = None if backend == "reference" else args.formula
        try:
            traces[label] = trace_pixel(scene, args.x, args.y, width, height, backend, precision, formula)
        except (NoAdapterError, PathNotInRelease) as error:
            notes.append("%s: skipped, %s" % (label, error))
            continue
        tolerances[label] = TOLERANCES[precision]
    formulas = ", ".join("%s %s" % (label, "slide" if backend == "reference" else
                                    args.formula or render_module.DEFAULT_FORMULAS[backend])
                         for label, backend, _ in PATHS if label in traces)
    print(report("%s: pixel (%d, %d) of %dx%d; sphere formula: %s"
                 % (args.name, args.x, args.y, width, height, formulas), traces, tolerances))
    for note in notes:
        print(note)


def _export_html(name, out, width=None, height=None, spp=None, seed=0, formula=None) -> str:
    """Write the WebGPU page of scene ``name`` (rtfgu/browser/export.py) to ``out``; a scene
    of a worksheet's menu (the shaders, the subdivision levels) offers the others of it."""
    from .browser import menu_page, scene_page
    from .scenes.default_scene import SHADER_MENU
    from .scenes.sampling import SUBDIVISION_MENU

    scene, width, height = scene_at(name, width, height)
    menus = {"shader": SHADER_MENU, "subdivision level": SUBDIVISION_MENU}
    label = next((label for label, names in menus.items() if name in names), None)
    if label is not None:
        menu = {other: scene_at(other, width, height)[0] for other in menus[label]}
        html = menu_page(menu, name, width, height, spp, seed, formula, label)
    else:
        html = scene_page(scene, width, height, spp, seed, name, formula=formula)
    with open(out, "w", encoding="utf-8") as f:
        f.write(html)
    return "%s  %dx%d  WebGPU page" % (out, width, height)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m rtfgu", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)

    sub.add_parser("list", help="print the homework scene names")

    def add_render_options(p):
        p.add_argument("--backend", default=render_module.DEFAULT_BACKEND,
                       choices=render_module.BACKENDS)
        p.add_argument("--precision", default=None, choices=render_module.PRECISIONS,
                       help="default float64; float32 for --backend wgpu")
        p.add_argument("--spp", type=int, default=None,
                       help="samples per pixel (default: the scene's sampler, else 1)")
        p.add_argument("--seed", type=int, default=0, help="the random stream's seed")

    p = sub.add_parser("render", help="render one scene to a PNG")
    p.add_argument("name")
    p.add_argument("-o", "--output", default=None, help="PNG path (default NAME.png)")
    p.add_argument("--width", type=int, default=None)
    p.add_argument("--height", type=int, default=None)
    add_render_options(p)

    p = sub.add_parser("render-all", help="render every homework scene into a folder")
    p.add_argument("--out", default="renders")
    add_render_options(p)

    sub.add_parser("info", help="print the WebGPU adapter the wgpu backend uses")

    p = sub.add_parser("export-wgsl", help="write the assembled WGSL program of a scene")
    p.add_argument("name")
    p.add_argument("-o", "--output", default=None, help="file path (default: standard output)")

    p = sub.add_parser("export-html", help="write a scene as a self-contained WebGPU page")
    p.add_argument("name")
    p.add_argument("-o", "--output", default=None, help="HTML path (default NAME.html)")
    p.add_argument("--width", type=int, default=None)
    p.add_argument("--height", type=int, default=None)
    p.add_argument("--spp", type=int, default=None,
                   help="samples per pixel (default: the scene's sampler, else 1)")
    p.add_argument("--seed", type=int, default=0, help="the random stream's seed")
    p.add_argument("--formula", default=None, choices=render_module.FORMULAS,
                   help="the sphere test (default: the wgpu backend's own)")

    p = sub.add_parser("export-html-all", help="write every homework scene as a WebGPU page, and index.html")
    p.add_argument("--out", default="html")

    p = sub.add_parser("debug-pixel", help="trace one pixel through every path, bounce by bounce")
    p.add_argument("name")
    p.add_argument("x", metavar="X", type=int, help="column, 0 at the left")
    p.add_argument("y", metavar="Y", type=int, help="row, 0 at the top")
    p.add_argument("--width", type=int, default=None)
    p.add_argument("--height", type=int, default=None)
    p.add_argument("--formula", default=None, choices=render_module.FORMULAS,
                   help="the numba and wgpu sphere test (default: each backend's own)")

    args = parser.parse_args(argv)
    try:
        if args.command == "list":
            for name in SCENES:
                print(name)
        elif args.command == "render":
            out = args.output or args.name + ".png"
            seconds, w, h, spp = _render_one(args.name, args.width, args.height, args.backend,
                                             args.precision, out, True, args.spp, args.seed)
            print("%s  %dx%d  %s  %d spp  %.2f s" % (out, w, h, args.backend, spp, seconds))
        elif args.command == "render-all":
            os.makedirs(args.out, exist_ok=True)
            for name in SCENES:
                out = os.path.join(args.out, name + ".png")
                seconds, w, h, spp = _render_one(name, None, None, args.backend, args.precision,
                                                 out, True, args.spp, args.seed)
                print("%s  %dx%d  %s  %d spp  %.2f s" % (out, w, h, args.backend, spp, seconds), flush=True)
        elif args.command == "info":
            from .wgsl import adapter_description
            print("wgpu adapter: %s" % adapter_description())
            print("backends: %s" % ", ".join(render_module.BACKENDS))
        elif args.command == "export-html":
            print(_export_html(args.name, args.output or args.name + ".html", args.width, args.height,
                               args.spp, args.seed, args.formula))
        elif args.command == "export-html-all":
            os.makedirs(args.out, exist_ok=True)
            for name in SCENES:
                print(_export_html(name, os.path.join(args.out, name + ".html")), flush=True)
            from .browser import index_html
            with open(os.path.join(args.out, "index.html"), "w", encoding="utf-8") as f:
                f.write(index_html(SCENES))
            print(os.path.join(args.out, "index.html"))
        elif args.command == "debug-pixel":
            _debug_pixel(args)
        elif args.command == "export-wgsl":
            from .layout import compile_scene
            from .wgsl import assemble
            source = assemble(compile_scene(get_scene(args.name)(), "float32")).source
            if args.output:
                with open(args.output, "w", encoding="utf-8") as f:
                    f.write(source)
            else:
                sys.stdout.write(source)
    except ValueError as error:
        parser.exit(2, "error: %s\n" % error)
    except (NoAdapterError, WGSLCompileError) as error:
        parser.exit(1, "error: %s\n" % error)
    return 0


if __name__ == "__main__":
    sys.exit(main())
