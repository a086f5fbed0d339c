"""Progressive rendering in a Jupyter notebook: the image shows inline and is redrawn as
each pass of samples arrives, under a line with the samples done, the time so far and the
time left (rtfgu.progress.TimeLeft).

    import rtfgu
    from rtfgu.scenes import SCENES
    image = rtfgu.show(SCENES["suffern_depth_of_field"](), 512, 384, spp=256)

The backend is the fastest this installation has (``best_backend``): numba in the course
tree, the lecture layer in a student release, which carries no numba kernels. Outside a
notebook (plain Python, a script) ``show`` writes the image to a PNG and says where.
IPython is imported only inside a notebook; ``pip install -e '.[notebook]'`` installs what
Jupyter needs.
"""
from __future__ import annotations

import importlib.util
from pathlib import Path

from .image import to_8bit, write_png
from .progress import TimeLeft
from .renderer import render_passes

# Passes of a render shown in a notebook: each redraws the image.
SHOW_PASSES = 16
OUT = "rtfgu_show.png"      # where show writes its image outside a notebook, unless told


def best_backend() -> str:
    """"numba" where this installation has numba and rtfgu's kernels (the course tree), else
    "reference" (the lecture layer: a student release leaves the kernels out)."""
    if importlib.util.find_spec("numba") is not None and importlib.util.find_spec(__package__ + ".kernels"):
        return "numba"
    return "reference"


def in_notebook() -> bool:
    """Whether this runs in a Jupyter kernel (not a script, not the terminal IPython)."""
    try:
        from IPython import get_ipython
    except ImportError:
        return False
    shell = get_ipython()
    return shell is not None and "IPKernelApp" in getattr(shell, "config", {})


def show(scene, width: int, height: int, backend: str | None = None, spp: int | None = None,
         passes: int = SHOW_PASSES, out=None, **options):
    """Render ``scene`` progressively and show it: in a notebook, the image (gamma applied, as
    written to a PNG) after the first pass, updated in place after every other one, under a
    line "48 of 256 samples, 1.2 s, 3.4 s left (numba)"; elsewhere the final image written to
    ``out`` (default rtfgu_show.png) and its path printed. With ``out`` a notebook writes it
    too. Returns the final linear image, as ``rtfgu.render`` does. ``backend`` defaults to
    best_backend(); ``options``: precision, formula, seed."""
    backend = backend or best_backend()
    total = spp or (scene.sampler.num_samples if getattr(scene, "sampler", None) is not None else 1)
    notebook = in_notebook()
    clock = TimeLeft()
    picture_handle = caption_handle = None
    image = None
    for done, image in render_passes(scene, width, height, backend, spp=spp, passes=passes, **options):
        clock.update(done, total)
        caption = "%d of %d samples, %.1f s, %s (%s)" % (done, total, clock.elapsed, clock.describe(), backend)
        if notebook:
            from IPython.display import Pretty, display
            from PIL import Image

            picture = Image.fromarray(to_8bit(image), mode="RGB")
            if picture_handle is None:
                picture_handle = display(picture, display_id=True)
                caption_handle = display(Pretty(caption), display_id=True)
            else:
                picture_handle.update(picture)
                caption_handle.update(Pretty(caption))
    if out is not None or not notebook:
        path = Path(OUT if out is None else out)
        write_png(image, path)
        if not notebook:
            print("rtfgu.show: wrote %s (%dx%d, %d sample%s, %s backend, %.1f s); open it to see the image"
                  % (path, width, height, total, "" if total == 1 else "s", backend, clock.elapsed))
    return image
