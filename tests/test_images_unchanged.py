"""The homework images on the two float64 paths, bit for bit as they were before the lecture
layer was restated in the book's classes (materials built from BRDFs, lights with the book's
methods, tracers): the 02562 radiometry expressed in those classes gives the same numbers.

tests/data/float64_images_before_book_classes.npz holds every homework scene rendered by the
lecture layer and by numba float64 before that change, at the size and samples of
tests/test_homework_images.py (tools/capture_float64_images.py wrote it). A scene added
since has no stored image and is not compared here (its images are in test_homework_images).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import rtfgu
from rtfgu.scenes import SCENES

BEFORE = Path(__file__).resolve().parent / "data" / "float64_images_before_book_classes.npz"
SIDE = 32


def small_size(size, side=SIDE):
    w, h = size
    if w >= h:
        return side, max(1, round(side * h / w))
    return max(1, round(side * w / h)), side


with np.load(BEFORE) as _stored:
    STORED = {key: _stored[key] for key in _stored.files}
# Scenes whose images changed on purpose since, and why; their images are compared in
# tests/test_homework_images.py, their expectations in tests/test_path_trace.py.
CHANGED_SINCE = {
    name: "PathTrace's Russian roulette now ends paths on their throughput from the second vertex "
          "(rtfgu/tracers/path_trace.py): the same expectation, other samples"
    for name in ("cornell_box_progressive", "cornell_box_fresnel", "environment_spheres")}
NAMES = sorted({key.split("/", 1)[1] for key in STORED} - set(CHANGED_SINCE))


@pytest.mark.parametrize("backend", ["reference", "numba"])
@pytest.mark.parametrize("name", NAMES)
def test_image_is_bit_for_bit_as_before(name, backend):
    fn = SCENES[name]
    width, height = small_size(fn.size, min(SIDE, fn.test_side or SIDE))
    image = rtfgu.render(fn(), width, height, backend=backend, precision="float64", spp=fn.test_spp)
    before = STORED["%s/%s" % (backend, name)]
    assert image.shape == before.shape
    differ = image != before
    assert not differ.any(), (
        "%s on %s float64: %d of %d channels differ from the image before the change, by up to %.3g"
        % (name, backend, int(differ.sum()), differ.size, float(np.max(np.abs(image - before)))))


def test_every_stored_scene_still_exists():
    missing = [name for name in NAMES if name not in SCENES]
    assert not missing, "stored scenes no longer registered: %s" % ", ".join(missing)
