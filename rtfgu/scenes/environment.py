"""An environment-lit scene (02562 worksheet 9, "Environment mapping"; Suffern ch. 18): three
spheres, glossy (a GlossyReflector), mirror and absorbing glass, on a grey disk under a lat-long sky
(rtfgu/scenes/data/sky.exr, made by tools/make_sky.py), path traced: the sky lights the
diffuse surfaces through their bounces and is seen in the mirror and through the glass."""
from __future__ import annotations

from pathlib import Path

from ..cameras import PinholeCamera
from ..float3 import Float3
from ..lights import EnvironmentLight
from ..materials import GlossyReflector, Reflective, dielectric
from ..sampling import Jittered
from ..sampling.sampler import sampler_of
from ..scene import Scene
from ..shapes import Disk, Sphere
from ..tracers import PathTrace
from .meshes import TEST_SPP, path_matte
from .registry import homework

SKY = Path(__file__).resolve().parent / "data" / "sky.exr"
ENVIRONMENT_SPP = 256


@homework(512, 512, test_side=16, test_spp=TEST_SPP)
def environment_spheres() -> Scene:
    """Worksheet 9: a glossy, a mirror and a glass sphere on a disk under an HDR sky."""
    camera = PinholeCamera(Float3(0.0, 1.6, 6.5), Float3(0.0, 0.5, 0.0), Float3(0.0, 1.0, 0.0), d=1.7)
    scene = Scene(camera)
    scene.environment = EnvironmentLight(SKY)
    scene.shapes.append(Disk(Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), 3.0, Float3(0.6),
                             path_matte()))
    scene.shapes.append(Sphere(Float3(-1.1, 0.5, 0.0), 0.5, Float3(0.5, 0.15, 0.1),
                               GlossyReflector(ka=0.0, kd=1.0, cs=(0.4, 0.4, 0.4), exp=60.0)))
    scene.shapes.append(Sphere(Float3(0.0, 0.5, -0.6), 0.5, Float3(0.0), Reflective()))
    scene.shapes.append(Sphere(Float3(1.1, 0.5, 0.0), 0.5, Float3(0.0), dielectric(1.5, (0.3, 0.1, 0.2))))
    scene.tracer = PathTrace()
    scene.sampler = sampler_of(Jittered, ENVIRONMENT_SPP)
    return scene
