"""Scenes after Suffern's *Ray Tracing from the Ground Up* that the 02562 scene does not cover.

``suffern_disks``: Suffern ch. 19's disk (centre, normal, radius) as a floor and as two
tilted coins, with a Phong sphere that casts its shadow across a disk's rim and a mirror
disk that shows the others, lit by one point light.
"""
from __future__ import annotations

import math

from ..cameras import PinholeCamera
from ..float3 import Float3
from ..lights import PointLight
from ..materials import Matte, Phong, Reflective
from ..scene import Scene
from ..shapes.disk import Disk
from ..shapes.sphere import Sphere
from .registry import homework


@homework(512, 512)
def suffern_disks() -> Scene:
    camera = PinholeCamera(Float3(0.0, 2.2, 5.0), Float3(0.0, 0.4, 0.0), Float3(0.0, 1.0, 0.0), d=1.6)
    scene = Scene(camera)
    scene.background = Float3(0.1, 0.3, 0.6)
    diffuse = Matte()
    scene.shapes.append(Disk(Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), 1.9,
                             Float3(0.8, 0.8, 0.75), diffuse))
    scene.shapes.append(Disk(Float3(1.1, 0.7, -0.4), Float3(-1.0, 0.5, 0.5), 0.65,
                             Float3(0.9, 0.3, 0.1), diffuse))
    scene.shapes.append(Disk(Float3(-1.2, 0.9, -0.9), Float3(0.5, 0.1, 1.0), 0.8,
                             Float3(0.0, 0.0, 0.0), Reflective()))
    scene.shapes.append(Sphere(Float3(-0.2, 0.45, 0.6), 0.45, Float3(0.1, 0.3, 0.8),
                               Phong(cs=Float3(0.3, 0.3, 0.3), exp=30.0)))
    scene.lights.append(PointLight(Float3(2.0, 4.0, 3.0), Float3(8 * math.pi, 8 * math.pi, 8 * math.pi)))
    return scene
