"""Scenes of texture mapping (02562 worksheet 3, Suffern ch. 29-30).

``default_texture_<filter>_<address>``: worksheet 3's textured plane, the 02562 default scene
(diffuse, with shadows) whose plane takes an image texture with the worksheet's plane
coordinates (tangent (-1, 0, 0), binormal (0, 0, 1)) and texture scale 0.2, filtered
nearest or bilinear and addressed repeat or clamp. The image is ``data/tiles16.png``, 16 x 16
sRGB texels (4 x 4 coloured tiles with dark borders, the top-left texel white), small so that
magnification shows each filter.

``suffern_checker``: Suffern ch. 30's procedural checker on a round floor (a disk: its plane
frame), a sphere (spherical map) and a triangle (barycentric coordinates).
"""
from __future__ import annotations

import math

from ..cameras import PinholeCamera
from ..float3 import Float3
from ..lights import PointLight
from ..materials import LAMBERTIAN, Matte
from ..scene import Scene
from ..shapes import Disk, Sphere, Triangle
from ..textures import Checker, ImageTexture
from .default_scene import default_scene
from .registry import homework

WORKSHEET3_TEXTURE_SCALE = 0.2


def texture_path(name: str):
    """The path of an image shipped in rtfgu/scenes/data."""
    from importlib import resources   # here: importing it costs a graded test's interpreter 5 ms

    return resources.files(__package__).joinpath("data", name)


def textured_plane(filter: str, address: str) -> Scene:
    scene = default_scene(LAMBERTIAN, LAMBERTIAN, shadows=True)
    texture = ImageTexture(texture_path("tiles16.png"), filter=filter, address=address,
                           scale=WORKSHEET3_TEXTURE_SCALE)
    scene.shapes[0].material = Matte(cd=texture)       # the book's SV_Matte
    return scene


for _filter in ("nearest", "bilinear"):
    for _address in ("repeat", "clamp"):
        def _scene(filter=_filter, address=_address) -> Scene:
            return textured_plane(filter, address)
        _scene.__name__ = _scene.__qualname__ = "default_texture_%s_%s" % (_filter, _address)
        _scene.__doc__ = "Worksheet 3: the plane textured, %s filtering, %s addressing." % (
            _filter, _address)
        homework(512, 512)(_scene)


@homework(512, 384)
def suffern_checker() -> Scene:
    """Suffern ch. 30: checkers on a floor, a sphere and a triangle."""
    camera = PinholeCamera(Float3(0.0, 2.0, 5.0), Float3(0.0, 0.6, 0.0), Float3(0.0, 1.0, 0.0),
                           d=1.5, aspect=512 / 384)
    scene = Scene(camera)
    scene.background = Float3(0.1, 0.3, 0.6)
    white, grey = Float3(0.85, 0.85, 0.85), Float3(0.15, 0.15, 0.15)
    # A round floor (Suffern's disk, ch. 19), not a plane: squares shrinking toward a
    # horizon would alias, and float32 would place their edges in other pixels.
    scene.shapes.append(Disk(Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), 4.0, Float3(1.0),
                             Matte(cd=Checker(white, grey, size=0.5))))
    scene.shapes.append(Sphere(Float3(-0.8, 0.7, 0.0), 0.7, Float3(1.0), Matte(
        cd=Checker(Float3(0.9, 0.2, 0.1), Float3(0.95, 0.9, 0.8), size=1 / 12))))
    scene.shapes.append(Triangle(Float3(0.4, 0.01, 0.8), Float3(1.8, 0.01, 0.6), Float3(1.0, 1.4, -0.2),
                                 Float3(1.0), Matte(cd=Checker(
                                     Float3(0.1, 0.4, 0.9), Float3(0.9, 0.8, 0.2), size=0.25))))
    scene.lights.append(PointLight(Float3(2.0, 4.0, 4.0), Float3(10 * math.pi)))
    return scene
