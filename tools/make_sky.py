"""rtfgu/scenes/data/sky.exr: the lat-long sky of the environment-lit homework scene.

    python tools/make_sky.py

A procedural sky, 256 x 128 texels of linear radiance (rtfgu/lights/environment_light.py's
mapping: -z in the middle, +y the top row): blue overhead, paler toward the horizon, a
warm glow of about 12 degrees radius around a sun 35 degrees above the horizon, a grey-brown
ground below. Broad on purpose: PathTrace finds the environment only by its bounces (it
samples area lights, not the environment), so a small bright sun would be fireflies.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import OpenEXR

OUT = Path(__file__).resolve().parent.parent / "rtfgu" / "scenes" / "data" / "sky.exr"
WIDTH, HEIGHT = 256, 128


def sky() -> np.ndarray:
    v = (np.arange(HEIGHT) + 0.5) / HEIGHT
    u = (np.arange(WIDTH) + 0.5) / WIDTH
    theta = (v * np.pi)[:, None]                      # from +y
    phi = ((u - 0.5) * 2 * np.pi)[None, :]            # atan2(x, -z)
    d = np.stack(np.broadcast_arrays(np.sin(theta) * np.sin(phi), np.cos(theta),
                                     -np.sin(theta) * np.cos(phi)), axis=-1)
    up = d[..., 1:2]
    zenith, horizon, ground = np.array([0.25, 0.45, 1.0]), np.array([0.9, 0.95, 1.0]), np.array([0.35, 0.3, 0.25])
    t = np.clip(up, 0, 1) ** 0.5
    image = np.where(up > 0, horizon * (1 - t) + zenith * t, ground)
    sun = np.array([np.cos(np.radians(35)) * np.sin(np.radians(40)), np.sin(np.radians(35)),
                    -np.cos(np.radians(35)) * np.cos(np.radians(40))])
    cos_sun = d @ sun
    glow = np.exp((cos_sun - 1) / (1 - np.cos(np.radians(12))))[..., None]
    image = image + glow * np.array([12.0, 10.0, 7.0])
    return image.astype(np.float32)


def main():
    header = {"compression": OpenEXR.ZIP_COMPRESSION, "type": OpenEXR.scanlineimage}
    with OpenEXR.File(header, {"RGB": sky()}) as f:
        f.write(str(OUT))


if __name__ == "__main__":
    main()
