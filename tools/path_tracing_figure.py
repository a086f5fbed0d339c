"""docs/path_tracing.png: the path-traced homework scenes and rtfgu against Mitsuba 3.

    python tools/path_tracing_figure.py

Top: worksheet 5's Cornell box under its area light and worksheet 7's progressive Cornell
box (rtfgu numba float32, the scenes' own sample counts, 256 x 256). Bottom: the Cornell box
with its blocks at 64 x 64, rtfgu (16 renders of 256 samples per pixel) beside Mitsuba 3
(tests/data/cornell_mitsuba.npz, 65,536 samples) and z = (rtfgu - Mitsuba) / combined
standard error of the red channel, blue -3 to red +3 (as tests/test_cornell_mitsuba.py).
"""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from PIL import Image

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from rtfgu import PathTrace, render  # noqa: E402
from rtfgu.image import to_8bit  # noqa: E402
from rtfgu.scenes import SCENES  # noqa: E402
from rtfgu.scenes.meshes import cornell_box_area_light  # noqa: E402


def big(image, side=256):
    return np.asarray(Image.fromarray(image).resize((side, side), Image.NEAREST))


def main():
    top = [to_8bit(render(SCENES[name](), 256, 256, backend="numba", precision="float32"))
           for name in ("cornell_box_area_light", "cornell_box_progressive")]
    peer = np.load(ROOT / "tests" / "data" / "cornell_mitsuba.npz")
    size = int(peer["width"])
    runs = []
    for seed in range(16):
        scene = cornell_box_area_light()     # the box with its blocks, kd 1 (the albedo is the colour)
        scene.tracer = PathTrace()
        scene.sampler = None
        runs.append(render(scene, size, size, backend="numba", precision="float32", spp=256, seed=1000 + seed))
    runs = np.array(runs)
    mean, stderr = runs.mean(axis=0), runs.std(axis=0, ddof=1) / 4
    with np.errstate(invalid="ignore", divide="ignore"):
        z = np.nan_to_num((mean - peer["mean"]) / np.sqrt(stderr ** 2 + peer["stderr"] ** 2))[..., 0]
    t = np.clip((z + 3) / 6, 0, 1)
    zmap = (np.stack([t, 1 - np.abs(2 * t - 1), 1 - t], axis=-1) * 255).astype(np.uint8)
    bottom = [big(to_8bit(mean), 170), big(to_8bit(peer["mean"].astype(float)), 170), big(zmap, 170)]
    row1 = np.concatenate(top, axis=1)
    row2 = np.concatenate(bottom + [np.zeros((170, 512 - 510, 3), np.uint8)], axis=1)
    Image.fromarray(np.concatenate([row1, row2], axis=0)).save(ROOT / "docs" / "path_tracing.png")


if __name__ == "__main__":
    main()
