"""A labelled contact sheet of every homework scene, for the README (``make montage``)."""
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


if __name__ == "__main__":
    import sys

    out = sys.argv[1] if len(sys.argv) > 1 else "docs/homework_renders.png"
    montage().save(out)
    print(out)
