"""The Mitsuba 3 reference image of the Cornell box, for comparing rtfgu's path tracer with
a peer per pixel.

    python benchmarks/cornell_reference.py [--spp N] [--passes P] [--size S] [--out PATH]
                                           [--png PATH] [--variant V]

The scene is the box of rtfgu.scenes.meshes.cornell_box_area_light() (cornell_box_blocks()
with path-traced surfaces: kd 1, the albedo each face's colour) lit by its emissive ceiling
quad only: every light but an AreaLight is removed (a point light standing in for the quad,
in rtfgu versions without area lights). The quad's two triangles face down (-y); they are
one Rectangle and its AreaLight (ceiling_lamp: the same surface), and one Mitsuba ``area``
emitter (benchmarks/mitsuba_scene.py converts the scene). The
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
    its colour), lit by its emissive quad only: cornell_box_area_light()'s box, its lamp one
    Rectangle (ceiling_lamp)."""
    from rtfgu.scenes.meshes import cornell_box_area_light
    scene = cornell_box_area_light()
    scene.lights = [light for light in scene.lights if type(light).__name__ == "AreaLight"]
    scene.sampler = None            # an rtfgu render of it takes render's spp (rtfgu.options.pixel_sampler)
    return ceiling_lamp(scene)


def ceiling_lamp(scene):
    """``scene`` with the two emitting triangles of its ceiling quad (each an AreaLight) made
    one Rectangle and its one AreaLight: the same surface, emission and material, as the book
    builds its Cornell box's lamp (Suffern ch. 18.6, "Rectangular lights"). A light is sampled
    once at every vertex, so the quad then costs one shadow ray a vertex instead of two, as
    Mitsuba's one emitter of the quad's faces does (benchmarks/mitsuba_scene.py). Refused
    unless the two triangles tile an axis-aligned rectangle."""
    from rtfgu.float3 import Float3, cross
    from rtfgu.lights import AreaLight
    from rtfgu.shapes import Rectangle

    lamps = [light.shape for light in scene.lights if isinstance(light, AreaLight)]
    if len(lamps) != 2 or len(scene.lights) != 2:
        raise ValueError("ceiling_lamp: the scene's lights must be the two AreaLights of the quad, got %r"
                         % (scene.lights,))
    corners = {}
    for shape in lamps:
        t = shape.triangle
        for v in (t.v0, t.v0 + t.e0, t.v0 + t.e1):
            corners[(v.x, v.y, v.z)] = v
    xs, ys, zs = (sorted({c[k] for c in corners}) for k in range(3))
    area = sum(shape.triangle.area for shape in lamps)
    if len(corners) != 4 or len(ys) != 1 or len(xs) != 2 or len(zs) != 2 or \
            abs(area - (xs[1] - xs[0]) * (zs[1] - zs[0])) > 1e-12 * area:
        raise ValueError("ceiling_lamp: the AreaLights' triangles do not tile one axis-aligned horizontal "
                         "rectangle: corners %s" % sorted(corners))
    a, b = Float3(xs[1] - xs[0], 0.0, 0.0), Float3(0.0, 0.0, zs[1] - zs[0])
    if cross(a, b).y * lamps[0].triangle.get_normal().y < 0.0:      # face where the triangles face
        a, b = b, a
    lamp = Rectangle(Float3(xs[0], ys[0], zs[0]), a, b, lamps[0].color, lamps[0].material)
    scene.shapes = [shape for shape in scene.shapes if shape not in lamps] + [lamp]
    scene.lights = [AreaLight(lamp)]
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
