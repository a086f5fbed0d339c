"""tests/data/rgbe/: Radiance pictures written by another program than rtfgu, for
tests/test_rgbe.py to read with rtfgu.lights.read_hdr.

    pip install imagecodecs && python tools/make_rgbe_test_files.py

The writer is imagecodecs' ``rgbe_encode`` (Christoph Gohlke's imagecodecs, version 2026.3.6
wrote the files kept; it wraps Bruce Walter's rgbe.c, after Greg Ward's Radiance code):
new-style run-length encoded scanlines for widths 8 to 32767, flat ones otherwise. Written
once and kept, so that the tests need no imagecodecs (26 MB, for one test). ``expected.npz``
holds, for each file, the floats it was written from (``NAME_written``) and imagecodecs'
``rgbe_decode`` of it (``NAME_decoded``).
"""
from __future__ import annotations

from pathlib import Path

import imagecodecs
import numpy as np

OUT = Path(__file__).resolve().parent.parent / "tests" / "data" / "rgbe"


def rle_image() -> np.ndarray:
    """300 x 6: runs longer than the longest run (127), noise (literals of 128), black, and
    values from 1e-6 to 1e6."""
    rng = np.random.default_rng(2562)
    image = np.empty((6, 300, 3), dtype=np.float32)
    image[0] = (0.75, 1.5, 3.0)                                      # one value: runs only
    image[1] = rng.random((300, 3))                                  # noise: literals only
    image[2] = 0.0                                                   # black (e = 0) ...
    image[2, 150:] = np.linspace(0.0, 2.0, 150)[:, None] * (1.0, 0.5, 0.25)   # ... then a ramp
    image[3] = 10.0 ** np.linspace(-6, 6, 300)[:, None] * (1.0, 0.3, 0.01)
    image[4] = np.repeat(rng.random((30, 3)) * 40, 10, axis=0)       # runs of 10 and literals
    image[5] = rng.random((300, 3)) * rng.choice([0.01, 1.0, 100.0], (300, 1))
    return image


def flat_image() -> np.ndarray:
    """5 x 3: too narrow for run-length encoding."""
    rng = np.random.default_rng(9)
    return (rng.random((3, 5, 3)) * 8).astype(np.float32)


def main() -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    expected = {}
    for name, image in (("rle_300x6", rle_image()), ("flat_5x3", flat_image())):
        data = imagecodecs.rgbe_encode(image, header=True)
        (OUT / ("imagecodecs_%s.hdr" % name)).write_bytes(data)
        expected[name + "_written"] = image
        expected[name + "_decoded"] = imagecodecs.rgbe_decode(data)
    np.savez_compressed(OUT / "expected.npz", **expected)


if __name__ == "__main__":
    main()
