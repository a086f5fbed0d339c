"""Scenes of pixel sampling and depth of field (02562 worksheet 3, Suffern ch. 4-5 and 10).

``default_antialiasing_<s>``: worksheet 3's anti-aliasing, the 02562 default scene (diffuse,
with shadows) with stratified jitter at subdivision level s, i.e. Jittered(s * s) samples
per pixel, s = 1, 2, 4, 8.

``suffern_samplers_<name>``: Suffern ch. 5's comparison of samplers on a pattern that
aliases, a fan of 48 thin triangles meeting at one point, 16 samples per pixel with each
of Regular, Jittered, NRooks, MultiJittered and Hammersley.

``suffern_depth_of_field``: Suffern ch. 10's thin-lens camera focused on the middle one of
five spheres in a row on a floor; the nearer and farther ones blur.
"""
from __future__ import annotations

import math

from ..cameras import OrthographicCamera, ThinLens
from ..float3 import Float3
from ..lights import PointLight
from ..materials import LAMBERTIAN, Matte, Phong
from ..sampling import Hammersley, Jittered, MultiJittered, NRooks, Regular
from ..scene import Scene
from ..shapes import Plane, Sphere, Triangle
from .default_scene import default_scene
from .registry import homework


def _antialiasing(level: int) -> Scene:
    scene = default_scene(LAMBERTIAN, LAMBERTIAN, shadows=True)
    scene.sampler = Jittered(level * level)
    return scene


for _level in (1, 2, 4, 8):
    def _scene(level=_level) -> Scene:
        return _antialiasing(level)
    _scene.__name__ = _scene.__qualname__ = "default_antialiasing_%d" % _level
    _scene.__doc__ = "Worksheet 3: stratified jitter, subdivision level %d (%d samples per pixel)." % (
        _level, _level * _level)
    homework(512, 512)(_scene)


# Worksheet 3's subdivision level, offered as a menu on these scenes' web pages (rtfgu/browser).
SUBDIVISION_MENU = tuple("default_antialiasing_%d" % level for level in (1, 2, 4, 8))


def star(sampler) -> Scene:
    """48 alternating black and white wedges meeting near the centre, seen head on: near the
    centre they are thinner than a pixel. The star is turned by 0.1 rad and its centre moved
    off the pixel grid, so no edge runs exactly through a sample point of a symmetric
    sampler (there float32 and float64 would rightly disagree)."""
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.background = Float3(0.5, 0.5, 0.5)
    n = 48
    cx, cy = 0.0131, 0.0077
    for k in range(n):
        a0 = 2 * math.pi * k / n + 0.1
        a1 = 2 * math.pi * (k + 1) / n + 0.1
        colour = Float3(1.0) if k % 2 == 0 else Float3(0.0)
        scene.shapes.append(Triangle(Float3(cx, cy, -1.0),
                                     Float3(cx + 1.6 * math.cos(a0), cy + 1.6 * math.sin(a0), -1.0),
                                     Float3(cx + 1.6 * math.cos(a1), cy + 1.6 * math.sin(a1), -1.0),
                                     colour))
    scene.sampler = sampler
    return scene


for _name, _cls in (("regular", Regular), ("jittered", Jittered), ("n_rooks", NRooks),
                    ("multi_jittered", MultiJittered), ("hammersley", Hammersley)):
    def _scene(cls=_cls) -> Scene:
        return star(cls(16))
    _scene.__name__ = _scene.__qualname__ = "suffern_samplers_%s" % _name
    _scene.__doc__ = "Suffern ch. 5: the star with %s(16)." % _cls.__name__
    homework(256, 256)(_scene)


@homework(512, 384)
def suffern_depth_of_field() -> Scene:
    """Suffern ch. 10: five spheres in a row, focused on the middle one."""
    camera = ThinLens(Float3(0.0, 1.2, 6.0), Float3(0.0, 0.6, 0.0), Float3(0.0, 1.0, 0.0),
                      d=1.5, aspect=512 / 384, lens_radius=0.12)
    camera.focal_distance = (Float3(0.0, 0.5, 0.0) - camera.eye).length()
    scene = Scene(camera)
    scene.background = Float3(0.1, 0.3, 0.6)
    scene.sampler = MultiJittered(64)
    scene.shapes.append(Plane(Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), Float3(0.8, 0.8, 0.75),
                              Matte()))
    colours = (Float3(0.9, 0.2, 0.1), Float3(0.9, 0.7, 0.1), Float3(0.2, 0.7, 0.2),
               Float3(0.1, 0.4, 0.9), Float3(0.6, 0.2, 0.8))
    for k, colour in enumerate(colours):
        z = 3.0 - 1.8 * k
        x = -1.2 + 0.6 * k
        scene.shapes.append(Sphere(Float3(x, 0.5, z), 0.5, colour,
                                   Phong(cs=Float3(0.3), exp=40.0)))
    scene.lights.append(PointLight(Float3(3.0, 5.0, 5.0), Float3(12 * math.pi)))
    return scene
