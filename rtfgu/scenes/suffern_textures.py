"""Suffern's texture chapters on every path.

``suffern_29_mappings``: Suffern ch. 29's mappings of an image texture: the 16 x 16 tiles of
``data/tiles16.png`` on a unit sphere about the origin through SphericalMap (latitude and
longitude), and on the floor through RectangularMap (x and z of the square -1..1, repeated).

``suffern_30_checker3d``: Suffern ch. 30's 3D checker: a sphere, a box and the floor cut out
of one block of cubes of side 0.4, so the squares run on across the shapes' edges.

``suffern_31_noise``: Suffern ch. 31's noise textures: fbm (cubic noise, six octaves), its
wrapped bands, marble (a ramp of colours through the perturbed height) and wood.
"""
from __future__ import annotations

import math

from ..cameras import PinholeCamera
from ..float3 import Float3
from ..lights import PointLight
from ..mappings import RectangularMap, SphericalMap
from ..materials import Matte, Phong
from ..noise import CubicNoise, LinearNoise
from ..scene import Scene
from ..shapes import Box, Plane, Sphere
from ..textures import Checker3D, FBmTexture, ImageTexture, RampFBmTexture, Wood, WrappedFBmTexture
from .registry import homework
from .textures import texture_path

# A marble ramp (the book reads one from an image): white and grey with a dark vein.
MARBLE_RAMP = ((0.85, 0.85, 0.82), (0.8, 0.8, 0.78), (0.7, 0.7, 0.68), (0.55, 0.55, 0.55),
               (0.25, 0.22, 0.2), (0.55, 0.55, 0.55), (0.7, 0.7, 0.68), (0.8, 0.8, 0.78))


def _stage(eye: Float3, look_at: Float3, aspect: float) -> Scene:
    scene = Scene(PinholeCamera(eye, look_at, Float3(0.0, 1.0, 0.0), d=1.5, aspect=aspect))
    scene.background = Float3(0.1, 0.3, 0.6)
    scene.lights.append(PointLight(Float3(3.0, 6.0, 6.0), Float3(60.0, 60.0, 60.0)))
    return scene


@homework(512, 384)
def suffern_29_mappings() -> Scene:
    scene = _stage(Float3(0.0, 1.6, 4.2), Float3(0.0, -0.1, 0.0), 512 / 384)
    tiles = texture_path("tiles16.png")
    floor = ImageTexture(tiles, filter="nearest", address="repeat", mapping=RectangularMap())
    scene.shapes.append(Plane(Float3(0.0, -1.0, 0.0), Float3(0.0, 1.0, 0.0), Float3(1.0), Matte(cd=floor)))
    globe = ImageTexture(tiles, filter="bilinear", address="repeat", mapping=SphericalMap())
    scene.shapes.append(Sphere(Float3(0.0, 0.0, 0.0), 1.0, Float3(1.0), Phong(cd=globe, cs=Float3(0.2), exp=40.0)))
    return scene


@homework(512, 384)
def suffern_30_checker3d() -> Scene:
    scene = _stage(Float3(0.5, 2.4, 5.0), Float3(0.0, 0.5, 0.0), 512 / 384)
    checker = Checker3D(Float3(0.9, 0.85, 0.75), Float3(0.15, 0.2, 0.35), size=0.4)
    scene.shapes.append(Plane(Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), Float3(1.0), Matte(cd=checker)))
    scene.shapes.append(Sphere(Float3(-0.9, 0.9, 0.0), 0.9, Float3(1.0), Matte(cd=checker)))
    scene.shapes.append(Box(Float3(0.5, 0.0, -0.3), Float3(1.7, 1.1, 0.9), Float3(1.0), Matte(cd=checker)))
    return scene


@homework(640, 320)
def suffern_31_noise() -> Scene:
    scene = _stage(Float3(0.0, 3.4, 5.6), Float3(0.0, 0.45, 0.0), 2.0)
    scene.shapes.append(Plane(Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), Float3(0.6, 0.6, 0.55), Matte()))
    fbm = FBmTexture(CubicNoise(num_octaves=6), Float3(1.0, 0.85, 0.5), scale=4.0)
    wrapped = WrappedFBmTexture(LinearNoise(num_octaves=4), Float3(0.6, 0.9, 0.7), expansion_number=6.0,
                                scale=3.0)
    marble = RampFBmTexture(CubicNoise(num_octaves=6), MARBLE_RAMP, perturbation=5.0, scale=5.0)
    wood = Wood(Float3(0.85, 0.6, 0.35), Float3(0.45, 0.25, 0.1), scale=1.0, ring_frequency=6.0)
    for x, texture in ((-2.55, fbm), (-0.85, wrapped), (0.85, marble)):
        scene.shapes.append(Sphere(Float3(x, 0.75, 0.0), 0.75, Float3(1.0), Matte(cd=texture)))
    scene.shapes.append(Box(Float3(1.85, 0.0, -0.7), Float3(3.25, 1.2, 0.7), Float3(1.0), Matte(cd=wood)))
    return scene
