"""The 02562 default scene (weeks 1-3) and one function per homework image of it.

Camera: eye (2, 1.5, 2), look-at (0, 0.5, 0), up (0, 1, 0), camera constant 1.
Plane through the origin with normal (0, 1, 0), colour (0.1, 0.7, 0).
Triangle (-0.2, 0.1, 0.9), (0.2, 0.1, 0.9), (-0.2, 0.1, -0.1), colour (0.4, 0.3, 0.2).
Sphere at (0, 0.5, 0), radius 0.3, index of refraction 1.5, shininess 42, specular 0.1;
its colour is black, as in the course, so that only its specular and refraction show.
Point light at (0, 1, 0) with intensity (pi, pi, pi). Background (0.1, 0.3, 0.6).

The course names its shaders by the cases of the slide's ``shade`` switch; each is a book
material (rtfgu/materials) with the course's numbers: lambertian a Matte (ka 0.1, kd 0.9
under the scene's white Ambient), phong a Phong with ks cs = 0.1 and exp 42, mirror a
Reflective (kr cr = 1 and nothing else), transparent a Transparent (kt = 1, ior 1.5), glossy
a Transparent with the Phong part, and base_color the plain Material, the shape's colour.
"""
from __future__ import annotations

import math

from ..cameras import PinholeCamera
from ..float3 import Float3
from ..lights import PointLight
from ..materials import (BASE_COLOR, GLOSSY, LAMBERTIAN, MIRROR, PHONG, SHADER_NAMES, TRANSPARENT, Material, Matte,
                         Phong, Reflective, Transparent)
from ..scene import Scene
from ..shapes import Plane, Sphere, Triangle
from .registry import homework

SPHERE_SPECULAR = Float3(0.1, 0.1, 0.1)
SPHERE_SHININESS = 42.0
SPHERE_IOR = 1.5


def course_material(shader: int) -> Material:
    """The book material of a 02562 shader, with the default sphere's numbers."""
    if shader == LAMBERTIAN:
        return Matte()
    if shader == PHONG:
        return Phong(cs=SPHERE_SPECULAR, exp=SPHERE_SHININESS)
    if shader == MIRROR:
        return Reflective()
    if shader == TRANSPARENT:
        return Transparent(ior=SPHERE_IOR)
    if shader == GLOSSY:
        return Transparent(ior=SPHERE_IOR, ka=0.1, kd=0.9, ks=1.0, cs=SPHERE_SPECULAR, exp=SPHERE_SHININESS)
    if shader == BASE_COLOR:
        return Material()
    raise ValueError("default_scene: no 02562 shader %r" % (shader,))


def default_scene(sphere_shader: int = LAMBERTIAN, other_shader: int = LAMBERTIAN,
                  shadows: bool = True, aspect: float = 1.0) -> Scene:
    """The 02562 default scene with the given shaders (the switch's ids); the sphere keeps
    its full material. ``shadows``: whether the light casts them (02562 week 2)."""
    camera = PinholeCamera(Float3(2.0, 1.5, 2.0), Float3(0.0, 0.5, 0.0), Float3(0.0, 1.0, 0.0),
                           d=1.0, aspect=aspect)
    scene = Scene(camera)
    scene.background = Float3(0.1, 0.3, 0.6)
    other = course_material(other_shader)
    scene.shapes.append(Plane(Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0),
                              Float3(0.1, 0.7, 0.0), other))
    scene.shapes.append(Triangle(Float3(-0.2, 0.1, 0.9), Float3(0.2, 0.1, 0.9),
                                 Float3(-0.2, 0.1, -0.1), Float3(0.4, 0.3, 0.2), other))
    scene.shapes.append(Sphere(Float3(0.0, 0.5, 0.0), 0.3, Float3(0.0, 0.0, 0.0), course_material(sphere_shader)))
    if other_shader != BASE_COLOR or sphere_shader != BASE_COLOR:
        light = PointLight(Float3(0.0, 1.0, 0.0), Float3(math.pi, math.pi, math.pi))
        light.set_shadows(shadows)
        scene.lights.append(light)
    return scene


@homework(512, 512)
def default_ray_directions() -> Scene:
    """Week 1: each pixel shows its eye ray's direction as a colour, d * 0.5 + 0.5."""
    scene = default_scene(BASE_COLOR, BASE_COLOR)
    scene.show_ray_direction = True
    scene.shapes.clear()
    return scene


@homework(512, 512)
def default_flat_colors() -> Scene:
    """Week 2: hidden-surface removal only; each pixel has the colour of the nearest shape."""
    return default_scene(BASE_COLOR, BASE_COLOR)


@homework(512, 512)
def default_lambertian() -> Scene:
    """Week 2: diffuse shading by the point light (Kepler, Lambert) and ambient, no shadows."""
    return default_scene(LAMBERTIAN, LAMBERTIAN, shadows=False)


@homework(512, 512)
def default_lambertian_shadows() -> Scene:
    """Week 2: as above with a shadow ray toward the light."""
    return default_scene(LAMBERTIAN, LAMBERTIAN, shadows=True)


def sphere_scene(name: str, shader: int):
    """Week 3's scene function ``default_<name>_sphere``: the sphere with the course's shader
    ``shader`` on the Lambertian floor and triangle, with shadows."""
    def scene() -> Scene:
        return default_scene(shader, LAMBERTIAN)
    scene.__name__ = scene.__qualname__ = "default_%s_sphere" % name
    scene.__doc__ = "Week 3: the sphere as the course's %s shader." % SHADER_NAMES[shader]
    return scene


for _name, _shader in (("mirror", MIRROR), ("refractive", TRANSPARENT), ("phong", PHONG), ("glossy", GLOSSY)):
    homework(512, 512)(sphere_scene(_name, _shader))


@homework(800, 450)
def default_widescreen_800x450() -> Scene:
    """The Lambertian scene with shadows at 16:9: the camera's aspect ratio follows the image."""
    return default_scene(LAMBERTIAN, LAMBERTIAN, shadows=True, aspect=800 / 450)


# The worksheets' shader menu (02562 weeks 2-3): the homework scenes of the default scene
# that differ only in the sphere's shader (flat colours: every shape's base colour), in the
# order the weeks add them; a web page of one of them offers the others (rtfgu/browser).
SHADER_MENU = ("default_flat_colors", "default_lambertian_shadows", "default_phong_sphere",
               "default_mirror_sphere", "default_refractive_sphere", "default_glossy_sphere")
