"""Suffern's ch. 19 part objects carry textures: their texture coordinates are their whole
shape's (the sphere's SphericalMap, the cylinder's CylindricalMap, the annulus's plane frame),
and every path picks the same square of a checker on them as the lecture layer."""
from __future__ import annotations

import math

import pytest

from rtfgu import Float3, Material, OrthographicCamera, Ray, Scene
from rtfgu.hit_info import HitInfo
from rtfgu.shapes.annulus import Annulus
from rtfgu.shapes.concave_part_sphere import ConcavePartSphere
from rtfgu.shapes.convex_part_sphere import ConvexPartSphere
from rtfgu.shapes.open_part_cylinder import OpenPartCylinder
from rtfgu.shapes.open_cylinder import OpenCylinder
from rtfgu.shapes.sphere import Sphere
from rtfgu.textures.checker import Checker

RED, BLUE = Float3(1.0, 0.0, 0.0), Float3(0.0, 0.0, 1.0)
SIZE = 0.125


def _checkered(cls, *args):
    return cls(*args, Float3(0.0), Material(cd=Checker(RED, BLUE, size=SIZE)))


# Two scenes of two kinds each (a WGSL scene binds two buffers per kind), with rays from
# outside and, through the parts' gaps, to their far side.
SCENES = {
    "part spheres": ([lambda: _checkered(ConvexPartSphere, (0.0, 0.0, 0.0), 1.0, 0.0, 270.0, 20.0, 160.0),
                      lambda: _checkered(ConcavePartSphere, (10.0, 0.0, 0.0), 1.0, 0.0, 270.0, 20.0, 160.0)],
                     [((0.2, 0.1, 5.0), (0.0, 0.0, -1.0)), ((0.6, -0.3, 5.0), (0.0, 0.0, -1.0)),
                      ((-0.5, 0.2, 5.0), (0.0, 0.0, -1.0)), ((10.3, 0.4, 5.0), (0.0, 0.0, -1.0)),
                      ((9.4, -0.2, 5.0), (0.0, 0.0, -1.0)), ((10.75, 0.1, -5.0), (0.0, 0.0, 1.0))]),
    "part cylinder and annulus": ([lambda: _checkered(OpenPartCylinder, -1.0, 1.0, 1.0, 0.0, 270.0),
                                   lambda: _checkered(Annulus, (10.0, 0.0, 0.0), (0.0, 1.0, 0.0), 0.5, 2.0)],
                                  [((0.3, 0.6, 5.0), (0.0, 0.0, -1.0)), ((0.8, -0.3, 5.0), (0.0, 0.0, -1.0)),
                                   ((-0.4, 0.2, 5.0), (0.0, 0.0, -1.0)), ((10.7, 5.0, 0.3), (0.0, -1.0, 0.0)),
                                   ((9.1, 5.0, -0.9), (0.0, -1.0, 0.0)), ((11.45, 5.0, 1.2), (0.0, -1.0, 0.0))]),
}


def _scene(name) -> Scene:
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes = [make() for make in SCENES[name][0]]
    return scene


@pytest.mark.parametrize("name", list(SCENES))
def test_part_objects_texcoords_are_their_whole_shapes(name):
    """Where the lecture layer's ray hits, the part's (u, v) is its whole shape's there."""
    scene = _scene(name)
    for origin, direction in SCENES[name][1]:
        hit = HitInfo()
        assert scene.intersect(Ray(Float3(*origin), Float3(*direction)), hit), origin
        shape = next(s for s in scene.shapes if s.material is hit.material)
        whole = (Sphere(shape.center, shape.radius, RED) if isinstance(shape, ConvexPartSphere)
                 else OpenCylinder(shape.y0, shape.y1, shape.radius, RED) if isinstance(shape, OpenPartCylinder)
                 else None)
        if whole is not None:
            assert shape.texcoord(hit.position) == whole.texcoord(hit.position)


@pytest.mark.parametrize("name", list(SCENES))
def test_checker_on_part_objects_on_every_path(path, name):
    scene = _scene(name)
    rays = [(o, d, 0.0, math.inf) for o, d in SCENES[name][1]]
    want = []
    for origin, direction in SCENES[name][1]:   # the lecture layer's square, far from its edges
        hit = HitInfo()
        scene.intersect(Ray(Float3(*origin), Float3(*direction)), hit)
        shape = next(s for s in scene.shapes if s.material is hit.material)
        cells = [c / SIZE for c in shape.texcoord(hit.position)]
        assert all(0.02 < c - math.floor(c) < 0.98 for c in cells), (origin, cells)
        want.append((hit.color.x, hit.color.y, hit.color.z))
    assert (1.0, 0.0, 0.0) in want and (0.0, 0.0, 1.0) in want
    bounces = path.trace(scene, rays)
    for k, (ray_bounces, colour) in enumerate(zip(bounces, want)):
        assert ray_bounces[0].color == colour, "%s %s ray %d: %s" % (path, name, k, ray_bounces[0].color)
