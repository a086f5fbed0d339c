"""The expected path of every pixel of an image test: what ``make debug-pixel`` in a student
release compares the student's code with (rtfgu.grading.local.debug_pixel).

``expected_pixels(check)`` traces each pixel of the test's image through the solution
(rtfgu.debug.trace_pixel on the lecture layer, the path whose image the test's reference
is) and packs the bounces as a .npz file: the release writes it beside the test's reference
image, so that a student's checker holds the expected shape, t, normal, shader and colour
of every pixel without holding the code that computes them. This module runs on the staff
side only: it imports the solved renderer.
"""
from __future__ import annotations

import io

import numpy as np

SUFFIX = ".pixels.npz"
# numbers[..., k]: the float fields of a Bounce, NaN where the field is None
NUMBERS = (("origin", 3), ("direction", 3), ("shape", 1), ("t", 1), ("normal", 3), ("color", 3))


def expected_pixels(check) -> bytes:
    """The bounces of every pixel of image test ``check``'s image, as .npz bytes."""
    import rtfgu
    import rtfgu.scenes.default_scene  # noqa: F401  (build_scene reaches it as rt.scenes.default_scene)
    from rtfgu.debug import trace_pixel

    from .probes.images import build_scene

    kwargs = check.probe[2]
    width, height = kwargs["width"], kwargs["height"]
    scene = build_scene(rtfgu, kwargs["scene"], kwargs.get("shaders"), kwargs.get("shadows"))
    paths = [[trace_pixel(scene, x, y, width, height) for x in range(width)] for y in range(height)]
    depth = max(len(p) for row in paths for p in row)
    numbers = np.full((height, width, depth, sum(n for _, n in NUMBERS)), np.nan)
    names = np.full((height, width, depth, 2), -1, dtype=np.int16)
    count = np.zeros((height, width), dtype=np.int16)
    kinds, shaders = [], []
    for y, row in enumerate(paths):
        for x, path in enumerate(row):
            count[y, x] = len(path)
            for k, bounce in enumerate(path):
                values = []
                for field, n in NUMBERS:
                    v = getattr(bounce, field)
                    values += [np.nan] * n if v is None else list(v) if n == 3 else [v]
                numbers[y, x, k] = values
                for j, (name, table) in enumerate(((bounce.kind, kinds), (bounce.shader, shaders))):
                    if name is not None:
                        if name not in table:
                            table.append(name)
                        names[y, x, k, j] = table.index(name)
    out = io.BytesIO()
    np.savez_compressed(out, numbers=numbers, names=names, count=count,
                        kinds=np.array(kinds or [""]), shaders=np.array(shaders or [""]))
    return out.getvalue()


def pixel_bounces(data, x: int, y: int) -> list:
    """The bounces of pixel (x, y) in an expected_pixels file (a path or its loaded arrays), as
    dicts of rtfgu.debug.Bounce's fields (JSON-ready)."""
    arrays = np.load(data) if not isinstance(data, dict) else data
    out = []
    for k in range(int(arrays["count"][y, x])):
        row, i, bounce = arrays["numbers"][y, x, k], 0, {}
        for field, n in NUMBERS:
            v = row[i:i + n]
            i += n
            if np.isnan(v).all() and field in ("shape", "t", "normal"):
                bounce[field] = None
            elif field == "shape":
                bounce[field] = int(v[0])
            else:
                bounce[field] = float(v[0]) if n == 1 else [float(c) for c in v]
        kind, shader = arrays["names"][y, x, k]
        bounce["kind"] = str(arrays["kinds"][kind]) if kind >= 0 else None
        bounce["shader"] = str(arrays["shaders"][shader])
        out.append(bounce)
    return out
