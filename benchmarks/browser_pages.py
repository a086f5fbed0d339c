"""Every homework scene's WebGPU page in headless Chromium (SwiftShader) against the wgpu path:
the share of pixels within 1/255, the largest difference, and the seconds the page took
(compiling its WGSL and adding every sample); writes the table of docs/browser.md and a contact
sheet of the pages' canvases, docs/browser_pages.png.

    python benchmarks/browser_pages.py [--width 96 --height 72]
"""
from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from rtfgu import renderer  # noqa: E402
from rtfgu.__main__ import scene_at  # noqa: E402
from rtfgu.browser import headless, scene_page  # noqa: E402
from rtfgu.image import to_8bit  # noqa: E402
from rtfgu.scenes import SCENES  # noqa: E402
from rtfgu.wgsl.device import adapter_description  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--width", type=int, default=96)
    parser.add_argument("--height", type=int, default=72)
    parser.add_argument("--spp", type=int, default=4, help="samples per pixel of a sampled scene")
    args = parser.parse_args()
    pages, spp = {}, {}
    for name in SCENES:
        scene, width, height = scene_at(name, args.width, args.height)
        spp[name] = args.spp if scene.sampler is not None else None
        pages[name] = scene_page(scene, width, height, spp=spp[name], name=name)
    start = time.perf_counter()
    results = headless.render_pages(pages, timeout=900)
    total = time.perf_counter() - start
    rows, tiles = [], []
    for name in SCENES:
        page, canvas = headless.result_images(results[name])
        scene, width, height = scene_at(name, args.width, args.height)
        wgpu = renderer.render(scene, width, height, backend="wgpu", spp=spp[name])
        gap = np.abs(to_8bit(page).astype(int) - to_8bit(wgpu).astype(int)).max(axis=2)
        rows.append("| %s | %d | %.2f %% | %d | %.2f |" % (name, spp[name] or 1, 100.0 * (gap <= 1).mean(), gap.max(),
                                                           results[name]["seconds"]))
        tile = Image.fromarray(canvas).resize((args.width, args.height))
        labelled = Image.new("RGB", (args.width, args.height + 12), "white")
        labelled.paste(tile, (0, 12))
        ImageDraw.Draw(labelled).text((2, 0), name[:18], fill="black")
        tiles.append(labelled)
    columns = 8
    sheet = Image.new("RGB", (columns * (args.width + 4), ((len(tiles) + columns - 1) // columns) * (args.height + 16)),
                      "white")
    for i, tile in enumerate(tiles):
        sheet.paste(tile, ((i % columns) * (args.width + 4), (i // columns) * (args.height + 16)))
    sheet.save(ROOT / "docs" / "browser_pages.png")
    print("Chromium: %s; wgpu: %s; %d cores, load average %.2f; %d pages at %dx%d in one Chromium run, %.1f s"
          % (headless.find_chromium(), adapter_description(), os.cpu_count(), os.getloadavg()[0], len(pages),
             args.width, args.height, total))
    print("| scene | samples per pixel | pixels within 1/255 of wgpu | largest difference (of 255) | "
          "seconds in the page (compile and every sample) |")
    print("|---|---:|---:|---:|---:|")
    print("\n".join(rows))


if __name__ == "__main__":
    main()
