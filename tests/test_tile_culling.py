"""The per-tile culling of a pinhole's primary rays (rtfgu/kernels/culling.py), checked
against truths of its own: no sphere that a ray of the tile hits is left out, and the
cosine form of the cone test decides as the angles it stands for, computed at 50 digits."""
from __future__ import annotations

import math
import random

import mpmath
import numpy as np
import pytest

from rtfgu import Float3, PinholeCamera, Scene, Sphere
from rtfgu.kernels.culling import cone_table, tile_candidates
from rtfgu.layout import (CAMERA_WIDTH, PINHOLE_ASPECT, PINHOLE_B1, PINHOLE_B2, PINHOLE_D, PINHOLE_EYE,
                          PINHOLE_V, SPHERE_CENTER, SPHERE_RADIUS, compile_scene)

WIDTH, HEIGHT, SIDE = 64, 48, 16

mpmath.mp.dps = 50


def _world(seed):
    """A pinhole camera and spheres around its view: near the eye, behind it, huge, tiny."""
    rng = random.Random(seed)
    eye = Float3(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(4, 8))
    camera = PinholeCamera(eye, Float3(rng.uniform(-1, 1), rng.uniform(-1, 1), 0.0), Float3(0.0, 1.0, 0.0),
                           d=rng.uniform(0.5, 3.0), aspect=WIDTH / HEIGHT)
    scene = Scene(camera)
    for _ in range(40):
        scene.shapes.append(Sphere(Float3(rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-4, 10)),
                                   math.exp(rng.uniform(math.log(0.01), math.log(3.0))), Float3(0.5, 0.5, 0.5)))
    scene.shapes.append(Sphere(eye + Float3(0.0, 0.0, 0.001), 0.3, Float3(0.5, 0.5, 0.5)))  # the eye inside
    flat = compile_scene(scene, "float64")
    camera64 = np.ascontiguousarray(flat.camera.reshape(CAMERA_WIDTH), dtype=np.float64)
    return camera64, np.ascontiguousarray(flat.table("sphere"), dtype=np.float64)


def _direction(camera, sx, sy, number=float):
    """PinholeCamera.gen_ray's direction through (sx, sy), unnormalised, in ``number``."""
    u = number(sx) * number(camera[PINHOLE_ASPECT]) * number(0.5)
    w = number(sy) * number(0.5)
    return [number(camera[PINHOLE_B1 + a]) * u + number(camera[PINHOLE_B2 + a]) * w
            + number(camera[PINHOLE_V + a]) * number(camera[PINHOLE_D]) for a in range(3)]


def _tiles():
    for y0 in range(0, HEIGHT, SIDE):
        for x0 in range(0, WIDTH, SIDE):
            yield x0, min(x0 + SIDE, WIDTH), y0, min(y0 + SIDE, HEIGHT)


def _candidates(camera, cones, tile):
    out = np.empty(len(cones), dtype=np.int64)
    n = tile_candidates(camera, cones, *tile, WIDTH, HEIGHT, out)
    return set(out[:n].tolist())


def _hit_for_sure(eye, d, center, r):
    """Whether the ray from ``eye`` along ``d`` meets the sphere with a margin no rounding
    reaches: its line passes within 0.999 r of the centre, ahead of the eye, or the eye is
    inside."""
    p = center - eye
    if p @ p < (0.999 * r) ** 2:
        return True
    along = p @ d / math.sqrt(d @ d)
    return along > 0 and p @ p - along * along < (0.999 * r) ** 2


@pytest.mark.parametrize("seed", range(6))
def test_no_sphere_a_ray_of_the_tile_hits_is_left_out(seed):
    camera, spheres = _world(seed)
    cones = cone_table(camera, spheres)
    eye = camera[PINHOLE_EYE:PINHOLE_EYE + 3]
    hit = 0
    for tile in _tiles():
        kept = _candidates(camera, cones, tile)
        x0, x1, y0, y1 = tile
        # The pixels' outer edges and a grid inside: every sample point of a pixel is within.
        for fx in np.linspace(0.0, 1.0, 9):
            for fy in np.linspace(0.0, 1.0, 9):
                sx = 2.0 * (x0 + fx * (x1 - x0)) / WIDTH - 1.0
                sy = 2.0 * (y0 + fy * (y1 - y0)) / HEIGHT - 1.0
                d = np.array(_direction(camera, sx, sy))
                for i, s in enumerate(spheres):
                    if _hit_for_sure(eye, d, s[SPHERE_CENTER:SPHERE_CENTER + 3], s[SPHERE_RADIUS]):
                        hit += 1
                        assert i in kept, (tile, i)
    assert hit > 100  # the scenes show spheres


@pytest.mark.parametrize("seed", range(6))
def test_the_cone_test_decides_as_its_angles_do(seed):
    """The sphere is a candidate where the angle between the tile's cone axis and the
    sphere's direction is within half + R (culling.py), computed at 50 digits from the same
    camera and cone rows: both ways, away from the limit by more than the rounding."""
    camera, spheres = _world(seed)
    cones = cone_table(camera, spheres)
    inside = outside = 0
    for tile in _tiles():
        kept = _candidates(camera, cones, tile)
        x0, x1, y0, y1 = tile
        corners = []
        for x, y in ((x0, y0), (x1, y0), (x0, y1), (x1, y1)):
            c = _direction(camera, 2.0 * x / WIDTH - 1.0, 2.0 * y / HEIGHT - 1.0, mpmath.mpf)
            norm = mpmath.sqrt(sum(v * v for v in c))
            corners.append([v / norm for v in c])
        axis = [sum(c[a] for c in corners) for a in range(3)]
        norm = mpmath.sqrt(sum(v * v for v in axis))
        axis = [v / norm for v in axis]
        half = max(mpmath.acos(min(1, sum(axis[a] * c[a] for a in range(3)))) for c in corners)
        for i, cone in enumerate(cones):
            limit = half + mpmath.mpf(cone[3])
            if limit >= mpmath.pi:
                assert i in kept
                continue
            angle = mpmath.acos(max(-1, min(1, sum(axis[a] * mpmath.mpf(cone[a]) for a in range(3)))))
            if angle < limit - mpmath.mpf(1e-9):
                inside += 1
                assert i in kept, (tile, i, float(angle), float(limit))
            elif angle > limit + mpmath.mpf(1e-9):
                outside += 1
                assert i not in kept, (tile, i, float(angle), float(limit))
    assert inside > 10 and outside > inside  # both ways, most spheres culled
