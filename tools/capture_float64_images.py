"""Render every homework scene small on the two float64 paths (the lecture layer and numba
float64) and store the images, so that a later change can be checked bit for bit against
them (tests/test_images_unchanged.py).

    python tools/capture_float64_images.py tests/data/float64_images.npz

The size and samples are those of tests/test_homework_images.py: the longer side 32 pixels
(a scene's ``test_side`` where smaller) at the scene's ``test_spp``.
"""
from __future__ import annotations

import sys

import numpy as np

import rtfgu
from rtfgu.scenes import SCENES

SIDE = 32


def small_size(size, side=SIDE):
    w, h = size
    if w >= h:
        return side, max(1, round(side * h / w))
    return max(1, round(side * w / h)), side


def render_all(backend: str) -> dict:
    images = {}
    for name, fn in SCENES.items():
        width, height = small_size(fn.size, min(SIDE, fn.test_side or SIDE))
        images["%s/%s" % (backend, name)] = rtfgu.render(fn(), width, height, backend=backend,
                                                         precision="float64", spp=fn.test_spp)
    return images


if __name__ == "__main__":
    images = render_all("reference")
    images.update(render_all("numba"))
    np.savez_compressed(sys.argv[1], **images)
    print("wrote %d images to %s" % (len(images), sys.argv[1]))
