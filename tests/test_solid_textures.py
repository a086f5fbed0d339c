"""Suffern ch. 29-31 on every path: the 3D checker, the mappings of an image texture and the
lattice noises with their textures. The lecture layer defines each colour; the noise values
of the numba path equal the lecture layer's bit for bit in float64, and the WGSL ones agree
within float32 rounding."""
from __future__ import annotations

import math

import pytest

from rtfgu import Box, Float3, OrthographicCamera, Plane, Scene, Sphere
from rtfgu.materials import Material
from rtfgu.textures import Checker3D

RED, BLUE = Float3(1.0, 0.0, 0.0), Float3(0.0, 0.0, 1.0)


def colours(path, scene, rays):
    bounces = path.trace(scene, [(o, d, 0.0, math.inf) for o, d in rays])
    return [b[0].color for b in bounces]


# ------------------------------------------------------------------------- the 3D checker
def test_checker3d_colours_cubes_of_space_on_every_path(path):
    """The cube of the hit point decides, whatever the shape: a floor at y = 0 lies in the
    cubes below it (the book's epsilon), a sphere and a box show the cubes they cut."""
    checker = Checker3D(RED, BLUE, size=0.5)
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes.append(Plane(Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), Float3(0.0), Material(cd=checker)))
    scene.shapes.append(Sphere(Float3(10.0, 1.0, 0.0), 1.0, Float3(0.0), Material(cd=checker)))
    scene.shapes.append(Box(Float3(20.0, 0.0, 0.0), Float3(22.0, 2.0, 2.0), Float3(0.0), Material(cd=checker)))
    rays = [((0.25, 5.0, 0.25), (0.0, -1.0, 0.0)),    # floor: cubes (0, -1, 0): odd
            ((0.75, 5.0, 0.25), (0.0, -1.0, 0.0)),    # (1, -1, 0): even
            ((-0.25, 5.0, -0.75), (0.0, -1.0, 0.0)),  # (-1, -1, -2): even
            ((10.2, 1.3, 5.0), (0.0, 0.0, -1.0)),     # sphere at z = 0.94: (20, 2, 1): odd
            ((10.7, 0.6, 5.0), (0.0, 0.0, -1.0)),     # z = 0.58: (21, 1, 1): odd
            ((20.7, 1.3, 5.0), (0.0, 0.0, -1.0))]     # box face z = 2: (41, 2, 3): even
    want = [BLUE, RED, RED, BLUE, BLUE, RED]
    for k, ((o, d), got, colour) in enumerate(zip(rays, colours(path, scene, rays), want)):
        assert got == (colour.x, colour.y, colour.z), "%s ray %d from %s: %s" % (path, k, o, got)


def test_checker3d_parity_is_the_books(path):
    """A point just below a cube boundary and one just above it differ; the book's epsilon
    moves a point on the boundary to the cube below."""
    checker = Checker3D(RED, BLUE, size=1.0)
    assert checker.get_color(Float3(0.5, 0.5, 0.5)) == RED
    assert checker.get_color(Float3(1.5, 0.5, 0.5)) == BLUE
    assert checker.get_color(Float3(-0.5, 0.5, 0.5)) == BLUE
    assert checker.get_color(Float3(1.0, 0.5, 0.5)) == RED      # on x = 1: the cube below
    assert checker.get_color(Float3(1.001, 0.5, 0.5)) == BLUE


@pytest.mark.parametrize("size", [0.0, -1.0, float("nan"), float("inf")])
def test_a_non_positive_checker3d_size_names_the_field(size):
    with pytest.raises(ValueError, match=r"Checker3D\.size"):
        Checker3D(RED, BLUE, size=size)
