"""Judging an image test (grader side and in the student checker): the student's render
against the reference image, with the tolerance of IMAGE_LEVELS and IMAGE_FRACTION, and a
diff image. It imports nothing of the renderer, so that judging never loads student code.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..assignments import get_assignment
from . import IMAGE_FRACTION, IMAGE_LEVELS, fmt, traces_a_scene

GAMMA = 2.2   # rtfgu.image.GAMMA: references are stored as the renderer writes its images


def to_8bit(image) -> np.ndarray:
    """rtfgu.image.to_8bit: gamma-correct, clamp to [0, 1] and round to uint8."""
    corrected = np.power(np.clip(np.asarray(image, dtype=np.float64), 0.0, 1.0), 1.0 / GAMMA)
    return np.floor(corrected * 255.0 + 0.5).astype(np.uint8)


def write_png(image, path) -> None:
    from PIL import Image

    Image.fromarray(to_8bit(image), mode="RGB").save(path)


def load_png(path) -> np.ndarray:
    from PIL import Image

    return np.asarray(Image.open(path).convert("RGB"))


# What the three panels of a diff image show, and what its colours mean (write_diff_image).
DIFF_LEGEND = ("yours | reference | differences (red: your pixel is unlike every reference pixel near it; "
               "blue: a detail of the reference, such as a thin edge or object, that yours lacks)")
WRONG, MISSING = (255, 0, 0), (0, 96, 255)


def neighbourhood_difference(mine: np.ndarray, reference: np.ndarray) -> np.ndarray:
    """Per pixel, the smallest (over the 3 x 3 neighbourhood of the reference pixel) of the
    largest channel difference, in 8-bit levels: a silhouette one pixel off costs nothing."""
    m = mine.astype(np.int32)
    r = np.pad(reference.astype(np.int32), ((1, 1), (1, 1), (0, 0)), mode="edge")
    h, w = reference.shape[:2]
    best = np.full((h, w), 1 << 30, dtype=np.int32)
    for dy in range(3):
        for dx in range(3):
            best = np.minimum(best, np.abs(m - r[dy:dy + h, dx:dx + w]).max(axis=2))
    return best


def image_differences(mine: np.ndarray, reference: np.ndarray) -> tuple:
    """(wrong, missing), per pixel in 8-bit levels: how far the student's pixel is from every
    reference pixel near it (something drawn that should not be there), and how far the
    reference pixel is from every student pixel near it (something the student's image lacks:
    a thin object left out is excused by the first, one pixel away from the background, but
    not by the second). Both forgive a one-pixel shift."""
    return neighbourhood_difference(mine, reference), neighbourhood_difference(reference, mine)


def write_diff_image(mine, reference, wrong, missing, path: Path, scale: int = 4) -> None:
    """yours | reference | differences (DIFF_LEGEND: grey, small; red, wrong; blue, missing
    from yours), enlarged."""
    from PIL import Image

    h, w = reference.shape[:2]
    heat = np.clip(np.maximum(wrong, missing) * 4, 0, 255).astype(np.uint8)
    diff = np.stack([heat, heat, heat], axis=2)
    diff[missing > IMAGE_LEVELS] = MISSING
    diff[wrong > IMAGE_LEVELS] = WRONG
    gap = np.full((h, 2, 3), 255, dtype=np.uint8)
    mine = mine if mine is not None else np.zeros_like(reference)
    strip = np.concatenate([mine, gap, reference, gap, diff], axis=1)
    strip = strip.repeat(scale, axis=0).repeat(scale, axis=1)
    path.parent.mkdir(parents=True, exist_ok=True)
    Image.fromarray(strip, mode="RGB").save(path)


def judge_image(check, data, reference: np.ndarray, diff_path: Path | None):
    """(fraction, message lines, diff image path or None)."""
    h, w = reference.shape[:2]
    if "error" in data:
        if diff_path is not None:
            everything = np.full((h, w), 255, np.int32)
            write_diff_image(None, reference, everything, everything, diff_path)
        return 0.0, ["rendering the image failed: " + data["error"]], diff_path
    image = np.asarray(data.get("image"), dtype=np.float64)
    if image.shape != (h, w, 3):
        return 0.0, ["the render has shape %s; expected (%d, %d, 3)" % (image.shape, h, w)], None
    if not np.all(np.isfinite(image)):
        row, col = np.argwhere(~np.isfinite(image).all(axis=2))[0]
        return 0.0, ["the pixel at column %d, row %d (row 0 at the top) is not a finite number (%s): "
                     "a NaN or infinity came out of your code there" % (col, row, image[row, col].tolist())], None
    mine = to_8bit(image)
    wrong, missing = image_differences(mine, reference)
    difference = np.maximum(wrong, missing)
    bad = difference > IMAGE_LEVELS
    allowed = max(1, int(IMAGE_FRACTION * h * w))
    if diff_path is not None:
        write_diff_image(mine, reference, wrong, missing, diff_path)
    n_bad = int(bad.sum())
    where = "; the diff image is %s (%s)" % (diff_path.name, DIFF_LEGEND) if diff_path else ""
    if n_bad <= allowed:
        return 1.0, ["%dx%d image matches the reference (%d pixels beyond the tolerance, %d allowed)%s"
                     % (w, h, n_bad, allowed, where)], diff_path
    row, col = np.unravel_index(np.argmax(difference), difference.shape)
    # The pixel is named in the test image, whose size the student's own renders differ from.
    short = get_assignment(check.assignment).short
    kinds = "%d unlike every reference pixel near them, %d more are details of the reference missing from yours" % (
        int((wrong > IMAGE_LEVELS).sum()), int(((missing > IMAGE_LEVELS) & (wrong <= IMAGE_LEVELS)).sum()))
    render = (" (`make render A=%s W=%d H=%d` renders the assignment's images at that size)" % (short, w, h)
              if traces_a_scene(check) else "")
    lines = ["%d of %d pixels (%.1f%%) differ from the reference by more than %d of 255 levels, even "
             "allowing a one-pixel shift (at most %d may): %s. The largest difference is at column %d, "
             "row %d (row 0 at the top) of the %dx%d test image%s: the reference pixel is %s, yours is %s%s"
             % (n_bad, h * w, 100.0 * n_bad / (h * w), IMAGE_LEVELS, allowed, kinds, col, row, w, h, render,
                fmt([int(v) for v in reference[row, col]]), fmt([int(v) for v in mine[row, col]]), where)]
    return 0.0, lines + debug_hint(check, col, row), diff_path


def debug_hint(check, x: int, y: int) -> list:
    """The command that traces pixel (x, y) of a visible image test through the student's code
    beside the expected values (rtfgu.grading.local.debug_pixel); none for a hidden test."""
    if check.visibility != "visible" or not traces_a_scene(check):
        return []
    return ["`make debug-pixel A=%s T=%s X=%d Y=%d` traces that pixel through your code beside what the "
            "solution computes there (the shape hit, t, the normal, the colour)"
            % (get_assignment(check.assignment).short, check.number, x, y)]
