"""Labelled contact sheets for the README and docs (``make montage``): every homework scene,
and Suffern's samplers side by side (one set of points each, and the star they render)."""
from __future__ import annotations

import numpy as np
from PIL import Image, ImageDraw

from .image import to_8bit
from .renderer import render
from .scenes import SCENES

TILE_HEIGHT = 160
LABEL_HEIGHT = 16
COLUMNS = 5


def montage(backend: str = "numba", tile_height: int = TILE_HEIGHT) -> Image.Image:
    tiles = []
    for name, fn in SCENES.items():
        w, h = fn.size
        width = max(1, round(tile_height * w / h))
        image = to_8bit(render(fn(), width, tile_height, backend=backend))
        tile = Image.new("RGB", (width, tile_height + LABEL_HEIGHT), (255, 255, 255))
        tile.paste(Image.fromarray(image), (0, 0))
        ImageDraw.Draw(tile).text((3, tile_height + 2), name, fill=(0, 0, 0))
        tiles.append(tile)
    rows = [tiles[i:i + COLUMNS] for i in range(0, len(tiles), COLUMNS)]
    sheet_w = max(sum(t.width for t in row) + 4 * (len(row) - 1) for row in rows)
    sheet_h = sum(max(t.height for t in row) for row in rows) + 4 * (len(rows) - 1)
    sheet = Image.new("RGB", (sheet_w, sheet_h), (255, 255, 255))
    y = 0
    for row in rows:
        x = 0
        for tile in row:
            sheet.paste(tile, (x, y))
            x += tile.width + 4
        y += max(t.height for t in row) + 4
    return sheet


def sampler_sheet(num_samples: int = 16, size: int = 160, backend: str = "numba") -> Image.Image:
    """Per sampler (Suffern ch. 5): the points of its first set on the pixel's n x n grid,
    and below it the centre of the star scene rendered with that sampler in big pixels."""
    from .sampling import Hammersley, Jittered, MultiJittered, NRooks, Regular
    from .scenes.sampling import star

    kinds = (Regular, Jittered, NRooks, MultiJittered, Hammersley)
    n = int(round(num_samples ** 0.5))
    sheet = Image.new("RGB", (len(kinds) * (size + 4) - 4, 2 * size + LABEL_HEIGHT), (255, 255, 255))
    for k, cls in enumerate(kinds):
        sampler = cls(num_samples)
        points = Image.new("RGB", (size, size), (255, 255, 255))
        draw = ImageDraw.Draw(points)
        for i in range(1, n):
            c = i * size // n
            draw.line([(c, 0), (c, size)], fill=(200, 200, 200))
            draw.line([(0, c), (size, c)], fill=(200, 200, 200))
        for x, y in sampler.samples[:num_samples]:
            px, py = x * (size - 1), (1 - y) * (size - 1)
            draw.ellipse([px - 3, py - 3, px + 3, py + 3], fill=(200, 30, 30))
        draw.rectangle([0, 0, size - 1, size - 1], outline=(0, 0, 0))
        scene = star(sampler)
        # The centre of the star in 40 x 40 big pixels, where the wedges alias.
        scene.camera.left, scene.camera.right = -0.4, 0.4
        scene.camera.bottom, scene.camera.top = -0.4, 0.4
        image = Image.fromarray(to_8bit(render(scene, 40, 40, backend=backend)))
        image = image.resize((size, size), Image.NEAREST)
        x0 = k * (size + 4)
        sheet.paste(points, (x0, 0))
        sheet.paste(image, (x0, size))
        ImageDraw.Draw(sheet).text((x0 + 3, 2 * size + 2), "%s(%d)" % (cls.__name__, num_samples),
                                   fill=(0, 0, 0))
    return sheet


if __name__ == "__main__":
    import sys

    out = sys.argv[1] if len(sys.argv) > 1 else "docs/homework_renders.png"
    montage().save(out)
    print(out)
    if len(sys.argv) > 2:
        sampler_sheet().save(sys.argv[2])
        print(sys.argv[2])
