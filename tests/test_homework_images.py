"""Every homework scene rendered small with the reference backend and compared with a
committed PNG in tests/reference_images/.

Size: the longer side is SIDE pixels and the shorter keeps the aspect of ``fn.size``
(512x512 -> 32x32, 800x450 -> 32x18).

Tolerance: at most 1 level in 255 per channel of the 8-bit image after gamma. The
references come from this same float64 code, so on another machine, Python or numpy the
only legitimate difference is the last bit of a libm result (sqrt, pow) that tips a value
lying on a quantisation boundary to the neighbouring level. A real change (a moved edge, a
wrong shading term, a flipped image) moves whole pixels by far more than one level.

On a mismatch the rendered image, the reference and a diff image are written to
tests/output/ (git-ignored). The references are rewritten only by
``pytest --update-reference-images``.
"""
from __future__ import annotations

import numpy as np
import pytest
from PIL import Image

import rtfgu
from rtfgu.image import read_png, to_8bit
from rtfgu.scenes import SCENES

SIDE = 32
TOLERANCE = 1  # levels of 255, per channel, after gamma


def small_size(size, side=SIDE):
    w, h = size
    if w >= h:
        return side, max(1, round(side * h / w))
    return max(1, round(side * w / h)), side


def test_small_size_keeps_the_aspect():
    assert small_size((512, 512)) == (32, 32)
    assert small_size((800, 450)) == (32, 18)
    assert small_size((256, 256)) == (32, 32)
    assert small_size((450, 800)) == (18, 32)


def diff_image(got: np.ndarray, ref: np.ndarray) -> np.ndarray:
    """Black where equal; the absolute difference amplified 16 times elsewhere, and pure
    magenta where it exceeds the tolerance, so a single bad pixel is visible."""
    diff = np.abs(got.astype(np.int16) - ref.astype(np.int16))
    out = np.clip(diff * 16, 0, 255).astype(np.uint8)
    out[np.any(diff > TOLERANCE, axis=2)] = (255, 0, 255)
    return out


@pytest.mark.parametrize("name", list(SCENES))
def test_homework_image_matches_reference(name, reference_images_dir, output_dir,
                                          update_reference_images):
    fn = SCENES[name]
    width, height = small_size(fn.size, min(SIDE, fn.test_side or SIDE))
    linear = rtfgu.render(fn(), width, height, backend="reference", spp=fn.test_spp)
    got = to_8bit(linear)
    assert got.shape == (height, width, 3)
    # a render that shows something: at least two colours
    assert len({tuple(p) for p in got.reshape(-1, 3)}) >= 2, "%s rendered a blank image" % name

    ref_path = reference_images_dir / (name + ".png")
    if update_reference_images:
        reference_images_dir.mkdir(exist_ok=True)
        Image.fromarray(got, mode="RGB").save(ref_path)
        return
    assert ref_path.exists(), (
        "no reference image %s; create it with "
        "`pytest tests/test_homework_images.py --update-reference-images`" % ref_path)
    ref = read_png(ref_path)
    assert ref.shape == got.shape, "%s: rendered %s, reference %s" % (name, got.shape, ref.shape)

    worst = int(np.max(np.abs(got.astype(np.int16) - ref.astype(np.int16))))
    if worst > TOLERANCE:
        output_dir.mkdir(exist_ok=True)
        got_path = output_dir / (name + ".png")
        ref_copy = output_dir / (name + ".reference.png")
        diff_path = output_dir / (name + ".diff.png")
        Image.fromarray(got, mode="RGB").save(got_path)
        Image.fromarray(ref, mode="RGB").save(ref_copy)
        Image.fromarray(diff_image(got, ref), mode="RGB").save(diff_path)
        bad = int(np.count_nonzero(np.any(np.abs(got.astype(np.int16) - ref.astype(np.int16))
                                          > TOLERANCE, axis=2)))
        pytest.fail("%s differs from %s by up to %d/255 (tolerance %d/255) in %d of %d pixels; "
                    "rendered: %s, diff: %s"
                    % (name, ref_path, worst, TOLERANCE, bad, width * height, got_path, diff_path))


def test_widescreen_sphere_is_round():
    # The sphere sits at the look-at point, so its image is a circle when the camera's aspect
    # matches the image's; it is black (its colour is (0, 0, 0) and nothing else is exactly
    # black), so its bounding box in a 96x54 render must be as wide as it is high.
    image = rtfgu.render(SCENES["default_widescreen_800x450"](), 96, 54)
    rows, cols = np.nonzero(np.all(image == 0.0, axis=2))
    assert rows.size > 50
    height = rows.max() - rows.min() + 1
    width = cols.max() - cols.min() + 1
    assert abs(int(width) - int(height)) <= 1, "sphere is %d wide and %d high" % (width, height)


# Last in the file, so that under --update-reference-images it runs after the images are written.
def test_every_scene_has_a_reference_and_no_reference_is_stale(reference_images_dir,
                                                                update_reference_images):
    if update_reference_images:
        for stale in set(p.stem for p in reference_images_dir.glob("*.png")) - set(SCENES):
            (reference_images_dir / (stale + ".png")).unlink()
    on_disk = {p.stem for p in reference_images_dir.glob("*.png")}
    assert on_disk == set(SCENES), (
        "reference images and SCENES differ: missing %s, stale %s; run "
        "`pytest tests/test_homework_images.py --update-reference-images`"
        % (sorted(set(SCENES) - on_disk), sorted(on_disk - set(SCENES))))
