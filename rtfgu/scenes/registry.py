"""The registry of homework scenes: name -> function returning a Scene.

Each scene function is registered with the image size its homework asks for, so that
``make render`` and ``python -m rtfgu render NAME`` use it unless told otherwise.
"""
from __future__ import annotations

SCENES = {}


def homework(width: int, height: int, test_side: int | None = None, test_spp: int | None = None):
    """Register a scene function with its homework image size. ``test_side``: the longer
    side of the small images the tests render of it, where the lecture layer would take too
    long at the tests' usual size (a mesh of thousands of faces, each tested by every ray);
    None: the tests' default. ``test_spp``: the samples per pixel the tests render it with,
    for a scene whose own sampler (a path-traced scene's hundreds of samples) would take the
    lecture layer minutes; None: the tests' default."""
    def register(fn):
        fn.size = (width, height)
        fn.test_side = test_side
        fn.test_spp = test_spp
        SCENES[fn.__name__] = fn
        return fn
    return register


def get_scene(name: str):
    """The scene function called ``name``; a ValueError listing the names if there is none."""
    try:
        return SCENES[name]
    except KeyError:
        raise ValueError("unknown scene name %r; known scenes: %s" % (name, ", ".join(SCENES))) from None
