"""The lecture-01 scene: an orthographic camera, spheres and a plane in flat colours.

Built exactly as the slides build a scene (a camera and coloured shapes, nothing else), so
the render shows each pixel in the colour of the nearest shape and the background elsewhere.
"""
from __future__ import annotations

from ..cameras import OrthographicCamera
from ..float3 import Float3
from ..scene import Scene
from ..shapes import Plane, Sphere
from .registry import homework


@homework(256, 256)
def lecture01_flat_colors() -> Scene:
    scene = Scene(OrthographicCamera(-2.0, 2.0, -2.0, 2.0))
    # A backdrop plane leaning back from the camera (the rays run along -z, so a floor with
    # normal +y would be seen edge-on), and three spheres in front of it.
    scene.shapes.append(Plane(Float3(0, 0, -6), Float3(0, 0.5, 1), Float3(0.8, 0.8, 0.8)))
    scene.shapes.append(Sphere(Float3(-1.0, -0.2, -3), 0.8, Float3(1, 0, 0)))
    scene.shapes.append(Sphere(Float3(0.6, 0.3, -4), 1.0, Float3(0, 1, 0)))
    scene.shapes.append(Sphere(Float3(1.2, -0.6, -2), 0.45, Float3(0, 0, 1)))
    scene.background = Float3(0.0, 0.0, 0.0)
    return scene
