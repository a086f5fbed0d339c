"""Benchmark scenes that are not homework images."""
from __future__ import annotations

import random

from rtfgu.cameras import PinholeCamera
from rtfgu.float3 import Float3
from rtfgu.scene import Scene
from rtfgu.shapes import Sphere


def random_spheres_64(seed: int = 2562, count: int = 64) -> Scene:
    """64 spheres in flat colours (no lights, no shading), seeded: a pure intersection load.
    The spheres fill a box in front of a pinhole camera; some overlap, most of the image is
    covered, and the rest shows the background."""
    rng = random.Random(seed)
    camera = PinholeCamera(Float3(0.0, 0.0, 6.0), Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), d=1.5)
    scene = Scene(camera)
    scene.background = Float3(0.1, 0.3, 0.6)
    for _ in range(count):
        center = Float3(rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0))
        colour = Float3(rng.random(), rng.random(), rng.random())
        scene.shapes.append(Sphere(center, rng.uniform(0.15, 0.45), colour))
    return scene
