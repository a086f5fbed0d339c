"""Image probes: a scene rendered with the student's code."""
from __future__ import annotations

import importlib

from .support import image


def build_scene(rt, scene: str, shaders=None, shadows=None):
    """The registered homework scene ``scene`` (rtfgu.scenes), or with ``shaders`` (names of
    rtfgu's shader ids, e.g. ["PHONG", "LAMBERTIAN"]) the 02562 default scene built with
    them and ``shadows``."""
    if shaders is not None:
        ids = [getattr(rt, name) for name in shaders]
        return rt.scenes.default_scene.default_scene(*ids, shadows=bool(shadows))
    return rt.scenes.get_scene(scene)()


def render_scene(rt, scene: str, width: int, height: int, render=None, shaders=None, shadows=None):
    """The scene (build_scene) rendered at width x height: by the lecture layer's pixel loop,
    or by ``render`` = "module.function" of this package, called as function(rt, scene,
    width, height) and returning a (height, width, 3) array."""
    built = build_scene(rt, scene, shaders, shadows)
    if render is None:
        return image(rt.renderer.render_reference(built, width, height))
    module, function = render.split(".")
    package = __name__.rsplit(".", 1)[0]
    return image(getattr(importlib.import_module("%s.%s" % (package, module)), function)(rt, built, width, height))


def render_homework(rt, scene: str, width: int = 0, height: int = 0):
    """A homework image at its registered size (0: the scene's own), by the lecture layer."""
    fn = rt.scenes.get_scene(scene)
    w, h = fn.size
    return image(rt.renderer.render_reference(fn(), width or w, height or h))


# The path on which a test's image is made, when it is not the lecture layer's pixel loop:
# (backend, formula) for rtfgu.debug.trace_pixel.
DEBUG_PATHS = {"a06.render_wgsl": ("wgpu", "slide")}


def debug_pixel(rt, scene: str, width: int, height: int, x: int, y: int, expected: list, rtol: float,
                title: str, render=None, shaders=None, shadows=None):
    """Pixel (x, y) of the test image traced through the student's code (rtfgu.debug), side
    by side with the ``expected`` bounces (dicts of rtfgu.debug.Bounce's fields, from the
    solution): {"report": text, "differs": bool}. Numbers agree within ``rtol`` (relative
    above 1, absolute below); a float32 path within rtfgu.debug's float32 tolerance."""
    import importlib

    debug = importlib.import_module("rtfgu.debug")
    built = build_scene(rt, scene, shaders, shadows)
    backend, formula = DEBUG_PATHS.get(render, ("reference", None))
    yours = debug.trace_pixel(built, x, y, width, height, backend, None, formula)
    wanted = [debug.Bounce(**{k: tuple(v) if isinstance(v, list) else v for k, v in b.items()}) for b in expected]
    tolerance = max(rtol, debug.TOLERANCES["float32"]) if backend == "wgpu" else rtol
    label = "yours (%s)" % ("your WGSL" if backend == "wgpu" else "your code")
    report = debug.report(title, {"expected": wanted, label: yours}, {label: tolerance})
    return {"report": report, "differs": debug.first_difference(wanted, yours, tolerance) is not None}
