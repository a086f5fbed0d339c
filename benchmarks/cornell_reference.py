"""The Mitsuba 3 reference image of the Cornell box, for comparing rtfgu's path tracer with
a peer per pixel.

    python benchmarks/cornell_reference.py [--spp N] [--passes P] [--size S] [--out PATH]
                                           [--png PATH] [--variant V]

The scene is the box of rtfgu.scenes.meshes.cornell_box_area_light() (cornell_box_blocks()
with path-traced surfaces: kd 1, the albedo each face's colour) lit by its emissive ceiling
quad only: every light but an AreaLight is removed (a point light standing in for the quad,
in rtfgu versions without area lights). The quad's two triangles face down (-y) and become
one Mitsuba ``area`` emitter (benchmarks/mitsuba_scene.py converts the scene). The
integrator is Mitsuba's ``path`` with max_depth -1 (unbounded, Russian roulette from depth
5), the film a box-filtered S x S hdrfilm.

Writes ``--out`` (default tests/data/cornell_mitsuba.npz):
  mean, stderr     float32 (S, S, 3), row 0 at the top, linear radiance; stderr is the
                   standard error of mean (render_mitsuba: std of the passes / sqrt(passes))
  spp, width, height, max_depth, passes   integers
  mitsuba_version, variant                strings
and a preview of mean (gamma 2.2, clipped to [0, 1], scaled up 4x) to ``--png`` (default
docs/cornell_mitsuba.png).

Defaults: 64 x 64, 65536 spp in 64 passes of 1024, scalar_rgb: about 4 minutes on a
2-core machine (16384 spp about 1 minute); stderr / mean is then 0.4 % at the median
pixel. Pixels that see only the light show its emission plus the light the quad reflects
(about 1 %: its material is Lambertian with Kd white, as every face of cornell_box.mtl).
"""
from __future__ import annotations

import argparse
import sys
import time
from importlib.metadata import version
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from mitsuba_scene import DEFAULT_VARIANT, render_mitsuba  # noqa: E402

MAX_DEPTH = -1


def cornell_scene():
    """The Cornell box with its blocks, every face a path-traced Matte (kd 1: its albedo is
    its colour), lit by its emissive quad only: cornell_box_area_light()'s box."""
    from rtfgu.scenes.meshes import cornell_box_area_light
    scene = cornell_box_area_light()
    scene.lights = [light for light in scene.lights if type(light).__name__ == "AreaLight"]
    scene.sampler = None            # an rtfgu render of it takes render's spp (rtfgu.options.pixel_sampler)
    return scene


def preview(mean: np.ndarray, path: Path, scale: int = 4) -> None:
    from PIL import Image
    pixels = (np.clip(mean, 0.0, 1.0) ** (1.0 / 2.2) * 255.0 + 0.5).astype(np.uint8)
    image = Image.fromarray(pixels)
    image = image.resize((image.width * scale, image.height * scale), Image.NEAREST)
    path.parent.mkdir(parents=True, exist_ok=True)
    image.save(path, optimize=True)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--spp", type=int, default=65536)
    parser.add_argument("--passes", type=int, default=64)
    parser.add_argument("--size", type=int, default=64)
    parser.add_argument("--out", type=Path, default=ROOT / "tests" / "data" / "cornell_mitsuba.npz")
    parser.add_argument("--png", type=Path, default=ROOT / "docs" / "cornell_mitsuba.png")
    parser.add_argument("--variant", default=DEFAULT_VARIANT)
    args = parser.parse_args(argv)

    start = time.perf_counter()

    def progress(done, total):
        print("pass %d/%d, %.0f s" % (done, total, time.perf_counter() - start), flush=True)

    mean, stderr = render_mitsuba(cornell_scene(), args.size, args.size, args.spp, passes=args.passes,
                                  max_depth=MAX_DEPTH, variant=args.variant, progress=progress)
    seconds = time.perf_counter() - start
    args.out.parent.mkdir(parents=True, exist_ok=True)
    np.savez_compressed(args.out, mean=mean.astype(np.float32), stderr=stderr.astype(np.float32),
                        spp=np.int64(args.spp), width=np.int64(args.size), height=np.int64(args.size),
                        max_depth=np.int64(MAX_DEPTH), passes=np.int64(args.passes),
                        mitsuba_version=np.str_(version("mitsuba")), variant=np.str_(args.variant))
    preview(mean, args.png)
    lit = mean > 1e-3                     # per pixel and channel
    rel = stderr[lit] / mean[lit]
    print("%s: %dx%d, %d spp in %d passes, %.0f s; stderr / mean where mean > 1e-3: median %.4f, max %.4f"
          % (args.out, args.size, args.size, args.spp, args.passes, seconds, np.median(rel), rel.max()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
