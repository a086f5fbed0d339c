"""Scenes after Suffern's *Ray Tracing from the Ground Up* that the 02562 scene does not cover.

``suffern_disks``: Suffern ch. 19's disk (centre, normal, radius) as a floor and as two
tilted coins, with a Phong sphere that casts its shadow across a disk's rim and a mirror
disk that shows the others, lit by one point light.

``suffern_19_objects``: Suffern ch. 19's new objects together, as the chapter's renderings
show them: an open cylinder seen from above, so that its inside shows through the open top
(lit where the outside is in shadow, its normal turned toward the ray), two axis-aligned
boxes, a rectangular floor and a rectangular mirror standing behind them, lit by one point
light and traced by Whitted.

``suffern_19_torus``: Suffern ch. 19's torus, a quartic solved by Schwarze's closed form: a
Phong ring on the floor and a smaller Matte ring in its hole, lit by one point light.
``suffern_19_parts``: Suffern ch. 19's part objects in compounds: a FlatRimmedBowl holding a
ball, and a sphere shell with a quarter cut away (its inside a ConcavePartSphere).

``suffern_17_occlusion_regular`` and ``suffern_17_occlusion_multi_jittered``: Suffern ch.
17's comparison of samplers for an AmbientOccluder's directions (set_sampler): the same 16
directions at every point (Regular) band the shadow under the sphere; multi-jittered sets,
one picked per pixel, leave noise instead.

``suffern_11_fisheye``, ``suffern_11_spherical`` and ``suffern_12_stereo``: the cameras of
Suffern ch. 11 and 12 (a fish-eye and a spherical panoramic camera, a stereo pair) looking
at a ring of spheres on the checkered floor.

``suffern_21_instances``: Suffern ch. 21's instancing: one unit sphere, one box and one open
cylinder, each placed several times by an Instance (scaled, rotated, sheared, moved) with a
material of its own: three ellipsoids, two turned boxes and a leaning cylinder on the
checkered floor.

``suffern_24_reflective`` and ``suffern_27_transparent``: the book's Reflective (a Phong
surface that also mirrors, ch. 24) and Transparent (a Phong highlight, a reflected and a
refracted ray, ch. 27) traced by Whitted, with the coefficients of the book's listings.
"""
from __future__ import annotations

import math

from ..cameras import FishEye, PinholeCamera, Spherical, StereoCamera
from ..float3 import Float3
from ..lights import AmbientOccluder, PointLight
from ..materials import Matte, Phong, Reflective, Transparent
from ..shapes.plane import Plane
from ..textures.checker import Checker
from ..sampling.jittered import Jittered
from ..sampling.multi_jittered import MultiJittered
from ..sampling.regular import Regular
from ..sampling.sampler import sampler_of
from ..tracers import PathTrace, Whitted
from ..scene import Scene
from ..shapes.annulus import Annulus
from ..shapes.box import Box
from ..shapes.compound import Compound
from ..shapes.concave_part_sphere import ConcavePartSphere
from ..shapes.convex_part_sphere import ConvexPartSphere
from ..shapes.disk import Disk
from ..shapes.flat_rimmed_bowl import FlatRimmedBowl
from ..shapes.instance import Instance
from ..shapes.open_cylinder import OpenCylinder
from ..shapes.rectangle import Rectangle
from ..shapes.sphere import Sphere
from ..shapes.torus import Torus
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


@homework(512, 512)
def suffern_19_objects() -> Scene:
    camera = PinholeCamera(Float3(0.6, 3.6, 4.6), Float3(0.0, 0.4, -0.3), Float3(0.0, 1.0, 0.0), d=1.5)
    scene = Scene(camera)
    scene.background = Float3(0.1, 0.3, 0.6)
    # The floor: p0, a, b with a x b = +y.
    scene.shapes.append(Rectangle(Float3(-3.0, 0.0, -3.0), Float3(0.0, 0.0, 6.0), Float3(6.0, 0.0, 0.0),
                                  Float3(0.8, 0.8, 0.75), Matte()))
    # A mirror standing at the back, facing +z.
    scene.shapes.append(Rectangle(Float3(-2.2, 0.0, -2.4), Float3(4.4, 0.0, 0.0), Float3(0.0, 1.6, 0.0),
                                  Float3(0.0, 0.0, 0.0), Reflective()))
    # The open cylinder about the y axis: its inside shows through the open top.
    scene.shapes.append(OpenCylinder(0.0, 1.1, 0.6, Float3(0.9, 0.5, 0.1), Matte()))
    scene.shapes.append(Box(Float3(1.0, 0.0, -1.6), Float3(1.9, 0.9, -0.7), Float3(0.1, 0.3, 0.8),
                            Phong(cs=Float3(0.3, 0.3, 0.3), exp=30.0)))
    scene.shapes.append(Box(Float3(-2.0, 0.0, 0.3), Float3(-1.2, 0.45, 1.1), Float3(0.2, 0.6, 0.2), Matte()))
    scene.lights.append(PointLight(Float3(-2.0, 5.0, 3.0), Float3(10 * math.pi, 10 * math.pi, 10 * math.pi)))
    scene.tracer = Whitted()
    return scene


@homework(512, 512)
def suffern_19_torus() -> Scene:
    """Suffern ch. 19's torus (the book's default Torus(2, 0.5) halved): a Phong ring
    resting on the floor with a smaller Matte ring floating in its hole, both about the y
    axis, seen from above so that the light shows through the holes onto the floor."""
    camera = PinholeCamera(Float3(0.0, 3.2, 4.2), Float3(0.0, -0.1, 0.0), Float3(0.0, 1.0, 0.0), d=1.6)
    scene = Scene(camera)
    scene.background = Float3(0.1, 0.3, 0.6)
    scene.shapes.append(Plane(Float3(0.0, -0.25, 0.0), Float3(0.0, 1.0, 0.0), Float3(0.8, 0.8, 0.75), Matte()))
    scene.shapes.append(Torus(1.0, 0.25, Float3(0.8, 0.2, 0.1), Phong(cs=Float3(0.4, 0.4, 0.4), exp=40.0)))
    scene.shapes.append(Torus(0.5, 0.125, Float3(0.1, 0.5, 0.2), Matte()))
    scene.lights.append(PointLight(Float3(-1.5, 5.0, 2.5), Float3(12 * math.pi, 12 * math.pi, 12 * math.pi)))
    return scene


@homework(512, 512)
def suffern_19_parts() -> Scene:
    """Suffern ch. 19's part objects in compounds: a FlatRimmedBowl (a ConvexPartSphere
    outside, a ConcavePartSphere inside, an Annulus rim) holding a ball, and a sphere with a
    quarter cut away, shown as a shell whose inside is a ConcavePartSphere, on a floor that
    is an Annulus without a hole, under one point light, traced by Whitted (the SolidCylinder
    is tests/test_compound.py's)."""
    camera = PinholeCamera(Float3(0.0, 3.4, 7.0), Float3(0.0, 0.5, 0.0), Float3(0.0, 1.0, 0.0), d=1.5)
    scene = Scene(camera)
    scene.background = Float3(0.1, 0.3, 0.6)
    scene.shapes.append(Annulus(Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), 0.0, 4.0, Float3(0.8, 0.8, 0.75),
                                Matte()))
    scene.shapes.append(FlatRimmedBowl(Float3(-1.3, 0.9, 0.3), 0.8, 0.9, Float3(0.9, 0.5, 0.1),
                                       Phong(cs=Float3(0.3, 0.3, 0.3), exp=30.0)))
    # A ball resting in the bowl: a part sphere of every angle.
    scene.shapes.append(ConvexPartSphere(Float3(-1.3, 0.45, 0.3), 0.35, 0.0, 360.0, 0.0, 180.0,
                                         Float3(0.8, 0.1, 0.1), Matte()))
    # The shell: every azimuth but 270..360 degrees (x < 0, z > 0, toward the camera).
    shell = Compound()
    shell.add_object(ConvexPartSphere(Float3(1.3, 0.8, 0.2), 0.8, 0.0, 270.0, 0.0, 180.0, Float3(0.1, 0.3, 0.8)))
    shell.add_object(ConcavePartSphere(Float3(1.3, 0.8, 0.2), 0.72, 0.0, 270.0, 0.0, 180.0, Float3(0.9, 0.85, 0.2)))
    shell.set_material(Matte())
    scene.shapes.append(shell)
    scene.lights.append(PointLight(Float3(-2.0, 5.0, 4.0), Float3(12 * math.pi, 12 * math.pi, 12 * math.pi)))
    scene.tracer = Whitted()
    return scene


def _book_stage(eye: Float3, look_at: Float3) -> Scene:
    """A checkered floor (Suffern's 3D checker seen as worksheet 3's plane texture) under a
    blue sky and one point light, Whitted as the tracer: what the book's chapter 24 and 27
    figures stand their spheres on."""
    scene = Scene(PinholeCamera(eye, look_at, Float3(0.0, 1.0, 0.0), d=1.3))
    scene.background = Float3(0.1, 0.3, 0.6)
    floor = Matte(ka=0.25, kd=0.75, cd=Checker(Float3(0.85, 0.85, 0.8), Float3(0.25, 0.25, 0.3), size=0.5))
    scene.shapes.append(Plane(Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), Float3(1.0), floor))
    scene.lights.append(PointLight(Float3(2.0, 7.0, 8.0), Float3(110.0, 110.0, 110.0)))
    scene.tracer = Whitted()
    return scene


@homework(512, 512)
def suffern_24_reflective() -> Scene:
    """Suffern ch. 24: a yellow Reflective sphere (ka 0.25, kd 0.5, ks 0.15, exp 100, kr 0.75:
    the book's listing) with its Phong highlight, mirroring a red Matte and a blue Phong sphere
    and the checkered floor."""
    scene = _book_stage(Float3(0.0, 2.4, 8.0), Float3(0.0, 0.7, 0.0))
    mirror = Reflective(kr=0.75, ka=0.25, kd=0.5, cd=Float3(0.75, 0.75, 0.0), ks=0.15, exp=100.0)
    scene.shapes.append(Sphere(Float3(0.0, 1.0, 0.0), 1.0, Float3(1.0), mirror))
    scene.shapes.append(Sphere(Float3(-2.0, 0.6, 1.0), 0.6, Float3(0.8, 0.15, 0.1), Matte()))
    scene.shapes.append(Sphere(Float3(1.9, 0.7, 1.2), 0.7, Float3(0.1, 0.3, 0.8),
                               Phong(cs=Float3(0.3, 0.3, 0.3), exp=30.0)))
    return scene


@homework(512, 512)
def suffern_27_transparent() -> Scene:
    """Suffern ch. 27: a glass sphere (ior 1.5, kr 0.1, kt 0.9, ks 0.2, exp 2000: the book's
    listing) in front of three Matte spheres; Whitted traces its reflected and its refracted
    ray at every hit, total internal reflection inside the glass included."""
    scene = _book_stage(Float3(0.0, 1.8, 7.5), Float3(0.0, 0.8, 0.0))
    glass = Transparent(ior=1.5, kt=0.9, kr=0.1, ka=0.0, kd=0.0, ks=0.2, exp=2000.0)
    scene.shapes.append(Sphere(Float3(0.0, 1.0, 1.5), 1.0, Float3(1.0), glass))
    for x, color in ((-1.6, Float3(0.8, 0.15, 0.1)), (0.0, Float3(0.1, 0.6, 0.15)), (1.6, Float3(0.1, 0.3, 0.8))):
        scene.shapes.append(Sphere(Float3(x, 0.7, -1.5), 0.7, color, Matte()))
    return scene


@homework(512, 512)
def suffern_21_instances() -> Scene:
    """Suffern ch. 21: instances of one unit sphere (ellipsoids: scaled, turned, moved), of one
    unit box (turned about y, then about x) and of one open cylinder (sheared so that it leans,
    its inside lit through its top), each instance with its own material, on the checkered
    floor; the transformations compose in the order they are called (ch. 21.2)."""
    scene = _book_stage(Float3(0.0, 4.2, 8.0), Float3(0.0, 0.6, 0.0))
    sphere = Sphere(Float3(0.0, 0.0, 0.0), 1.0, Float3(1.0))
    box = Box(Float3(-0.5, -0.5, -0.5), Float3(0.5, 0.5, 0.5), Float3(1.0))
    cylinder = OpenCylinder(0.0, 1.0, 0.5, Float3(1.0))
    shiny = Phong(cs=Float3(0.3, 0.3, 0.3), exp=30.0)
    scene.shapes += [
        Instance(sphere, Phong(cd=Float3(0.8, 0.15, 0.1), cs=Float3(0.3, 0.3, 0.3), exp=40.0))
        .scale(1.2, 0.45, 0.6).rotate_z(25.0).translate(-2.2, 1.0, 0.4),
        Instance(sphere, Matte(cd=Float3(0.9, 0.75, 0.1))).scale(0.35, 1.1, 0.35).translate(-0.9, 1.1, -2.0),
        Instance(sphere, Matte(cd=Float3(0.1, 0.6, 0.2))).scale(0.8, 0.25, 0.8).rotate_x(-20.0)
        .translate(2.1, 0.5, 1.3),
        Instance(box, Matte(cd=Float3(0.1, 0.3, 0.8))).scale(1.0, 0.6, 1.0).rotate_y(35.0).translate(1.6, 0.3, -1.0),
        Instance(box, shiny).scale(0.6).rotate_y(-30.0).rotate_x(20.0).translate(-0.9, 0.45, 1.6),
        Instance(cylinder, Matte(cd=Float3(0.9, 0.5, 0.1))).shear(hyx=0.5).scale(1.1, 1.2, 1.1)
        .translate(0.1, 0.0, -0.3),
    ]
    return scene


# The samples per pixel of the ambient-occlusion figures, and of their occluder's sampler.
OCCLUSION_SPP = 16


def _occlusion(sampler_class) -> Scene:
    """A sphere on a floor lit by an AmbientOccluder only (PathTrace with one vertex: the
    book's image), whose directions come from a ``sampler_class`` sampler of OCCLUSION_SPP
    samples; the pixels jittered."""
    scene = Scene(PinholeCamera(Float3(0.0, 2.5, 6.0), Float3(0.0, 0.6, 0.0), Float3(0.0, 1.0, 0.0), d=1.6))
    scene.background = Float3(0.0)
    white = Matte(ka=0.0, kd=1.0)
    scene.shapes.append(Plane(Float3(0.0), Float3(0.0, 1.0, 0.0), Float3(0.8), white))
    scene.shapes.append(Sphere(Float3(0.0, 1.0, 0.0), 1.0, Float3(0.8), white))
    occluder = AmbientOccluder(1.0)
    occluder.set_sampler(sampler_of(sampler_class, OCCLUSION_SPP))
    scene.lights.append(occluder)
    scene.tracer = PathTrace(max_depth=1)
    scene.sampler = sampler_of(Jittered, OCCLUSION_SPP)
    return scene


@homework(512, 512, test_side=24)
def suffern_17_occlusion_regular() -> Scene:
    """Suffern ch. 17, the occluder's directions from a Regular sampler: 16 fixed directions
    at every point, so the shadow under the sphere comes in bands."""
    return _occlusion(Regular)


@homework(512, 512, test_side=24)
def suffern_17_occlusion_multi_jittered() -> Scene:
    """Suffern ch. 17, the occluder's directions from a MultiJittered sampler: each pixel
    draws one of its sets, so the bands of the Regular image become noise."""
    return _occlusion(MultiJittered)


# The spheres of the ch. 11-12 camera figures: a ring of radius 3 around the origin, each
# 0.6 in radius and coloured by its place, and a larger white one at the centre.
_RING = ((0.8, 0.15, 0.1), (0.85, 0.6, 0.1), (0.2, 0.6, 0.15), (0.1, 0.5, 0.7), (0.1, 0.3, 0.8),
         (0.5, 0.2, 0.7))


def _ring_of_spheres(eye: Float3, look_at: Float3) -> Scene:
    scene = _book_stage(eye, look_at)
    scene.shapes.append(Sphere(Float3(0.0, 1.0, 0.0), 1.0, Float3(0.85), Phong(cs=Float3(0.3), exp=30.0)))
    for k, color in enumerate(_RING):
        angle = 2 * math.pi * k / len(_RING)
        scene.shapes.append(Sphere(Float3(3.0 * math.sin(angle), 0.6, 3.0 * math.cos(angle)), 0.6,
                                   Float3(*color), Matte()))
    return scene


@homework(400, 400)
def suffern_11_fisheye() -> Scene:
    """Suffern ch. 11.2 (the fish-eye figures): a FishEye of psi_max 120 (a 240 degree field
    of view) standing inside the ring of spheres, looking at the white one: the ring bends
    into a circle, and the corners outside the image's circle show the background."""
    scene = _ring_of_spheres(Float3(0.0, 1.2, 2.2), Float3(0.0, 0.8, 0.0))
    scene.camera = FishEye(Float3(0.0, 1.2, 2.2), Float3(0.0, 0.8, 0.0), Float3(0.0, 1.0, 0.0), psi_max=120.0)
    return scene


@homework(512, 256)
def suffern_11_spherical() -> Scene:
    """Suffern ch. 11.3 (the panoramic figures): a Spherical camera with lambda_max 180 and
    psi_max 90 in the middle of the ring: every direction at once, longitude across and
    latitude up, so the floor fills the lower half and each sphere of the ring appears once."""
    scene = _ring_of_spheres(Float3(0.0, 1.2, 1.6), Float3(0.0, 1.0, 0.0))
    scene.camera = Spherical(Float3(0.0, 1.2, 1.6), Float3(0.0, 1.0, 0.0), Float3(0.0, 1.0, 0.0),
                             lambda_max=180.0, psi_max=90.0)
    return scene


@homework(410, 200)
def suffern_12_stereo() -> Scene:
    """Suffern ch. 12 (the stereo pairs): a StereoCamera, two views of 200 x 200 pixels with a
    10 pixel gap, beta 5 degrees, parallel viewing (the left eye's view on the left), looking
    at the ring of spheres from outside it."""
    eye, look_at = Float3(0.0, 2.6, 8.0), Float3(0.0, 0.8, 0.0)
    scene = _ring_of_spheres(eye, look_at)
    scene.camera = StereoCamera(eye, look_at, Float3(0.0, 1.0, 0.0), d=1.4, hres=200, vres=200, pixel_gap=10,
                                beta=5.0, viewing="parallel")
    return scene
