"""Suffern's Compound (ch. 19, "Compound objects"): the nearest child's hit, its normal,
material and colour recorded by Scene.intersect, set_material on every child, the union of
the boxes; and on every path (the ``path`` fixture) a compound numbered as its leaves, in
order, as rtfgu.layout lays them out."""
from __future__ import annotations

import math

import numpy as np
import pytest

import rtfgu
from rtfgu import Float3, Matte, OrthographicCamera, Phong, Ray, Scene, Sphere
from rtfgu.hit_info import HitInfo
from rtfgu.layout import compile_scene
from rtfgu.shapes.compound import Compound
from rtfgu.shapes.disk import Disk
from rtfgu.shapes.flat_rimmed_bowl import FlatRimmedBowl
from rtfgu.shapes.solid_cylinder import SolidCylinder
from rtfgu.shapes.thick_ring import ThickRing

RED, BLUE, GREEN = Float3(1.0, 0.0, 0.0), Float3(0.0, 0.0, 1.0), Float3(0.0, 1.0, 0.0)
DOWN = Float3(0.0, -1.0, 0.0)


def _scene(*shapes) -> Scene:
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes = list(shapes)
    return scene


def _intersect(scene, origin, direction):
    hit = HitInfo()
    found = scene.intersect(Ray(Float3(*origin), Float3(*direction)), hit)
    return hit if found else None


def test_scene_records_the_nearest_child():
    """The ray meets the far child first in the list: the hit is the near one's, with its
    normal, its material and its colour."""
    far, near = Matte(), Phong()
    compound = Compound()
    compound.add_object(Disk(Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), 1.0, RED, far))
    compound.add_object(Sphere(Float3(0.0, 2.0, 0.0), 0.5, BLUE, near))
    hit = _intersect(_scene(compound), (0.0, 5.0, 0.0), (0.0, -1.0, 0.0))
    assert hit.dist == 2.5 and hit.material is near and hit.color == BLUE
    assert hit.normal == Float3(0.0, 1.0, 0.0) and compound.hit_object is compound.objects[1]


def test_a_compound_in_a_compound_records_the_leaf():
    inner = SolidCylinder(0.0, 1.0, 1.0, GREEN, Matte())
    outer = Compound()
    outer.add_object(Sphere(Float3(0.0, 0.0, 5.0), 0.5, RED))
    outer.add_object(inner)
    hit = _intersect(_scene(outer), (0.25, 4.0, 0.0), (0.0, -1.0, 0.0))
    assert hit.dist == 3.0 and hit.normal == Float3(0.0, 1.0, 0.0)
    assert outer.hit_object is inner.objects[1]        # the top disk
    assert outer.leaves() == [outer.objects[0]] + inner.objects


def test_earlier_child_wins_a_tie():
    first, second = Matte(), Phong()
    compound = Compound()
    compound.add_object(Disk(Float3(0.0), Float3(0.0, 1.0, 0.0), 1.0, RED, first))
    compound.add_object(Disk(Float3(0.0), Float3(0.0, 1.0, 0.0), 2.0, BLUE, second))
    hit = _intersect(_scene(compound), (0.0, 1.0, 0.0), (0.0, -1.0, 0.0))
    assert hit.material is first and hit.color == RED


def test_a_miss_leaves_the_ray_and_hit_object():
    compound = SolidCylinder(0.0, 1.0, 1.0, GREEN)
    ray = Ray(Float3(3.0, 0.5, 0.0), Float3(0.0, 1.0, 0.0))
    assert not compound.intersect_p(ray) and ray.tmax == math.inf and compound.hit_object is None


def test_set_material_reaches_every_leaf():
    bowl = FlatRimmedBowl(Float3(0.0), 0.9, 1.0, RED)
    outer = Compound()
    outer.add_object(bowl)
    outer.add_object(Sphere(Float3(3.0, 0.0, 0.0), 1.0, RED))
    material = Phong()
    outer.set_material(material)
    assert len(outer.leaves()) == 4 and all(leaf.material is material for leaf in outer.leaves())


def test_bounds_are_the_union_of_the_children():
    compound = Compound()
    compound.add_object(Sphere(Float3(0.0), 1.0, RED))
    compound.add_object(Sphere(Float3(4.0, 0.0, 0.0), 1.0, RED))
    box = compound.bounds()
    spheres = [s.bounds() for s in compound.objects]
    for a in range(3):
        assert box.p0[a] == min(b.p0[a] for b in spheres) and box.p1[a] == max(b.p1[a] for b in spheres)
    assert box.p0.x < -1.0 and box.p1.x > 5.0
    assert Compound().bounds() is None


def test_the_layout_holds_the_leaves_in_the_compounds_place():
    """A compound lays out as its leaves in order, the same tables and indices as the
    leaves listed one by one."""
    cylinder = SolidCylinder(0.0, 1.0, 1.0, GREEN, Matte())
    sphere = Sphere(Float3(0.0, 3.0, 0.0), 0.5, RED, Matte())
    flat = compile_scene(_scene(sphere, cylinder))
    listed = compile_scene(_scene(sphere, *cylinder.objects))
    for kind in ("sphere", "disk", "open_cylinder"):
        assert np.array_equal(flat.table(kind), listed.table(kind))
        assert np.array_equal(flat.index(kind), listed.index(kind))
    assert list(flat.index("disk")) == [1, 2] and list(flat.index("open_cylinder")) == [3]


# Rays at a solid cylinder (leaves 1-3) behind a sphere (shape 0), each with the leaf it hits
# first and where: the top disk from above, the side from the side, the bottom disk from below.
CYLINDER_RAYS = [
    (((0.75, 4.0, 0.0), (0.0, -1.0, 0.0), 0.0, math.inf), 2, "disk", 3.0, (0.0, 1.0, 0.0)),
    (((3.0, 0.5, 0.0), (-1.0, 0.0, 0.0), 0.0, math.inf), 3, "open_cylinder", 2.0, (1.0, 0.0, 0.0)),
    (((0.5, -2.0, 0.0), (0.0, 1.0, 0.0), 0.0, math.inf), 1, "disk", 2.0, (0.0, -1.0, 0.0)),
    (((0.0, 9.0, 0.0), (0.0, -1.0, 0.0), 0.0, math.inf), 0, "sphere", 5.5, (0.0, 1.0, 0.0)),
]


def test_compound_on_every_path(path):
    scene = _scene(Sphere(Float3(0.0, 3.0, 0.0), 0.5, RED, Matte()), SolidCylinder(0.0, 1.0, 1.0, GREEN, Matte()))
    bounces = path.trace(scene, [ray for ray, *_ in CYLINDER_RAYS])
    for (ray, shape, kind, t, normal), bounce in zip(CYLINDER_RAYS, bounces):
        first = bounce[0]
        assert (first.shape, first.kind) == (shape, kind), "%s: ray %s hit %r" % (path.label, ray, first)
        assert first.t == pytest.approx(t, rel=1e-6) and first.normal == pytest.approx(normal, abs=1e-6)


def test_path_trace_renders_a_compound_on_every_path(path):
    """PathTrace checks a compound's leaves' materials, and a compound path traces as its leaves."""
    from rtfgu import PathTrace, PinholeCamera, PointLight
    scene = Scene(PinholeCamera(Float3(0.0, 2.0, 4.0), Float3(0.0, 0.5, 0.0), Float3(0.0, 1.0, 0.0), d=1.5))
    scene.shapes = [SolidCylinder(0.0, 1.0, 0.5, GREEN, Matte(ka=0.0, kd=1.0))]
    scene.lights = [PointLight(Float3(1.0, 3.0, 2.0), Float3(20.0))]
    scene.tracer = PathTrace(max_depth=2)
    flat = _scene(*scene.shapes[0].objects)
    flat.camera, flat.lights, flat.tracer = scene.camera, scene.lights, scene.tracer
    a, b = (rtfgu.render(s, 8, 8, backend=path.backend, precision=path.precision, spp=2) for s in (scene, flat))
    assert np.array_equal(a, b) and a.max() > 0.0


# Rays at a ThickRing (y 0..1, radii 1 and 2; leaves: the inner wall, the outer wall, the
# bottom and the top annulus), each with the leaf it hits first: the top from above, nothing
# through the hole, the inner wall from the hole (its normal toward the ray), the outer wall.
RING_RAYS = [
    (((1.5, 3.0, 0.0), (0.0, -1.0, 0.0), 0.0, math.inf), 3, "annulus", 2.0, (0.0, 1.0, 0.0)),
    (((0.5, 3.0, 0.0), (0.0, -1.0, 0.0), 0.0, math.inf), None, None, None, None),
    (((0.0, 0.5, 0.0), (1.0, 0.0, 0.0), 0.0, math.inf), 0, "open_cylinder", 1.0, (-1.0, 0.0, 0.0)),
    (((5.0, 0.5, 0.0), (-1.0, 0.0, 0.0), 0.0, math.inf), 1, "open_cylinder", 3.0, (1.0, 0.0, 0.0)),
    (((1.5, -2.0, 0.0), (0.0, 1.0, 0.0), 0.0, math.inf), 2, "annulus", 2.0, (0.0, -1.0, 0.0)),
]


def test_thick_ring_on_every_path(path):
    scene = _scene(ThickRing(0.0, 1.0, 1.0, 2.0, GREEN, Matte()))
    bounces = path.trace(scene, [ray for ray, *_ in RING_RAYS])
    for (ray, shape, kind, t, normal), bounce in zip(RING_RAYS, bounces):
        first = bounce[0]
        assert (first.shape, first.kind) == (shape, kind), "%s: ray %s hit %r" % (path.label, ray, first)
        if shape is not None:
            assert first.t == pytest.approx(t, rel=1e-6) and first.normal == pytest.approx(normal, abs=1e-6)
