"""Progressive rendering in a Jupyter notebook: the image shows inline and is redrawn as
each pass of samples arrives.

    import rtfgu
    from rtfgu.scenes import SCENES
    image = rtfgu.show(SCENES["suffern_depth_of_field"](), 512, 384, spp=256, backend="numba")

IPython (which every notebook has) is imported only when ``show`` is called; rtfgu does not
depend on it.
"""
from __future__ import annotations

from PIL import Image

from .image import to_8bit
from .renderer import render_passes

# Passes of a render shown in a notebook: each redraws the image.
SHOW_PASSES = 16


def show(scene, width: int, height: int, backend: str = "numba", spp: int | None = None,
         passes: int = SHOW_PASSES, **options):
    """Render ``scene`` progressively, displaying the image (gamma applied, as written to a
    PNG) after the first pass and updating it in place after every other one; returns the
    final linear image, as ``rtfgu.render`` does. ``options``: precision, formula, seed."""
    from IPython.display import display

    handle = None
    image = None
    for done, image in render_passes(scene, width, height, backend, spp=spp, passes=passes,
                                     **options):
        picture = Image.fromarray(to_8bit(image), mode="RGB")
        if handle is None:
            handle = display(picture, display_id=True)
        else:
            handle.update(picture)
    return image
