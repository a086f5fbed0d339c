"""One rule for ties on every path: of two shapes hit at exactly the same distance, the one
earlier in Scene.shapes wins (the lecture's loop over Scene.shapes keeps the first of two
equal distances, since a later shape needs t < tmax). Coincident shapes of different kinds,
in both orders, on the lecture layer, numba float64 and float32 and WGSL."""
from __future__ import annotations

import numpy as np
import pytest

import rtfgu
from rtfgu import Disk, Float3, OrthographicCamera, Plane, Scene, Sphere, Triangle
from wgsl_support import wgpu_device  # noqa: F401  (fixture)

RED, GREEN = Float3(1.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0)
PATHS = [("reference", None), ("numba", "float64"), ("numba", "float32"), ("wgpu", "float32")]


def _coincident(kind, color, z=-2.0):
    """A shape lying in the plane z (-2: where the pairs tie), covering the middle of the image."""
    if kind == "plane":
        return Plane((0.0, 0.0, z), (0.0, 0.0, 1.0), color)
    if kind == "disk":
        return Disk((0.0, 0.0, z), (0.0, 0.0, 1.0), 4.0, color)
    if kind == "triangle":
        return Triangle((-4.0, -4.0, z), (4.0, -4.0, z), (0.0, 4.0, z), color)
    return Sphere((0.0, 0.0, z - 1.0), 1.0, color)  # its near point (0, 0, z) lies in the plane


FLAT_KINDS = ("plane", "disk", "triangle")


def _scene(first, second):
    # An orthographic camera: every ray runs along -z, so both shapes are hit at exactly
    # the same t (the arithmetic of a plane at z = -2 from z = hither is exact).
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0, hither=0.0))
    scene.background = Float3(0.0, 0.0, 1.0)
    scene.shapes = [_coincident(first, RED), _coincident(second, GREEN)]
    # Behind the pair, hidden, the flat kind it lacks: every pair's scene then has the same
    # kinds, so each numba precision renders all of them with one kernel (docs/compile_time.md).
    scene.shapes += [_coincident(kind, Float3(0.0, 0.0, 0.5), z=-10.0) for kind in FLAT_KINDS
                     if first in FLAT_KINDS and second in FLAT_KINDS and kind not in (first, second)]
    return scene


PAIRS = [("plane", "disk"), ("disk", "plane"), ("plane", "triangle"), ("triangle", "disk"),
         ("triangle", "plane"), ("disk", "triangle")]


@pytest.mark.parametrize("backend,precision", PATHS, ids=["%s-%s" % p if p[1] else p[0] for p in PATHS])
@pytest.mark.parametrize("first,second", PAIRS, ids=["%s-then-%s" % p for p in PAIRS])
def test_the_earlier_shape_wins_a_tie_on_every_path(request, backend, precision, first, second):
    if backend == "wgpu":
        request.getfixturevalue("wgpu_device")
    image = rtfgu.render(_scene(first, second), 8, 8, backend=backend, precision=precision)
    # Every pixel sees both shapes at t = 2; the first in Scene.shapes is red.
    assert np.array_equal(image[:, :, 0], np.ones((8, 8))), "%s %s: %s" % (backend, precision, image[:, :, :2])
    assert not image[:, :, 1].any()


def test_the_sphere_touching_the_plane_ties_only_at_its_near_point():
    # The ray through the image centre meets the sphere's near point and the plane at t = 2:
    # the earlier shape (the sphere here) wins there; elsewhere the plane is nearer.
    scene = _scene("sphere", "plane")
    scene.camera = OrthographicCamera(-1.0, 1.0, -1.0, 1.0, hither=0.0)
    for backend, precision in PATHS[:3]:
        image = rtfgu.render(scene, 3, 3, backend=backend, precision=precision)
        assert image[1, 1, 0] == 1.0 and image[0, 0, 1] == 1.0, (backend, precision, image)
