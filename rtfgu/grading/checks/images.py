"""Judging an image test (grader side and in the student checker): the student's render
against the reference image, with the tolerance of IMAGE_LEVELS and IMAGE_FRACTION, and a
diff image. It imports nothing of the renderer, so that judging never loads student code.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..assignments import get_assignment
from . import IMAGE_FRACTION, IMAGE_LEVELS, fmt

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


def write_diff_image(mine, reference, difference, bad, path: Path, scale: int = 4) -> None:
    """yours | reference | difference (grey: small, red: beyond the tolerance), enlarged."""
    from PIL import Image

    h, w = reference.shape[:2]
    heat = np.clip(difference * 4, 0, 255).astype(np.uint8)
    diff = np.stack([heat, heat, heat], axis=2)
    diff[bad] = [255, 0, 0]
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
            write_diff_image(None, reference, np.zeros((h, w), np.int32), np.ones((h, w), bool), diff_path)
        return 0.0, ["rendering the image failed: " + data["error"]], diff_path
    image = np.asarray(data.get("image"), dtype=np.float64)
    if image.shape != (h, w, 3):
        return 0.0, ["the render has shape %s; expected (%d, %d, 3)" % (image.shape, h, w)], None
    if not np.all(np.isfinite(image)):
        row, col = np.argwhere(~np.isfinite(image).all(axis=2))[0]
        return 0.0, ["the pixel at column %d, row %d (row 0 at the top) is not a finite number (%s): "
                     "a NaN or infinity came out of your code there" % (col, row, image[row, col].tolist())], None
    mine = to_8bit(image)
    difference = neighbourhood_difference(mine, reference)
    bad = difference > IMAGE_LEVELS
    allowed = max(1, int(IMAGE_FRACTION * h * w))
    if diff_path is not None:
        write_diff_image(mine, reference, difference, bad, diff_path)
    n_bad = int(bad.sum())
    where = "; the diff image is %s (yours | reference | differences in red)" % diff_path.name if diff_path else ""
    if n_bad <= allowed:
        return 1.0, ["%dx%d image matches the reference (%d pixels beyond the tolerance, %d allowed)%s"
                     % (w, h, n_bad, allowed, where)], diff_path
    row, col = np.unravel_index(np.argmax(difference), difference.shape)
    # The pixel is named in the test image, whose size the student's own renders differ from.
    short = get_assignment(check.assignment).short
    return 0.0, ["%d of %d pixels (%.1f%%) differ from the reference by more than %d of 255 levels, even "
                 "allowing a one-pixel shift (at most %d may). The largest difference is at column %d, "
                 "row %d (row 0 at the top) of the %dx%d test image (`make render A=%s W=%d H=%d` renders "
                 "the assignment's images at that size): the reference pixel is %s, yours is %s%s"
                 % (n_bad, h * w, 100.0 * n_bad / (h * w), IMAGE_LEVELS, allowed, col, row, w, h, short, w, h,
                    fmt([int(v) for v in reference[row, col]]), fmt([int(v) for v in mine[row, col]]), where)], diff_path
