"""Baselines for the 64-sphere figure: kernels that know only spheres in flat colours seen
by a pinhole camera, and nothing else (no planes, triangles, lights, shaders, path loop).

``brute_force``: the plain loop, every ray against every sphere with the lecture's
formulas (temp and c per ray). ``spheres_only``: the same algorithm as the numba path
(temp and c once per frame, per-tile culling), written for spheres alone; the general
kernel should run as fast as this one on a spheres-only scene.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from rtfgu.kernels.camera import gen_ray
from rtfgu.kernels.culling import cone_table, tile_candidates
from rtfgu.kernels.float3 import lit, row3
from rtfgu.kernels.intersect import intersect_sphere, sphere_eye_terms, sphere_roots
from rtfgu.layout import CAMERA_WIDTH, MAT_COLOR, PINHOLE, PINHOLE_EYE, SPHERE_RADIUS, SPHERE_ROW

TILE = 16


@njit(parallel=True, cache=True, error_model="numpy")
def brute_force(width, height, camera, spheres, colors, background, image):
    for iy in prange(height):
        for ix in range(width):
            one = lit(1, camera[0])
            sx = lit(2, one) * (lit(ix, one) + lit(0.5, one)) / lit(width, one) - one
            sy = lit(2, one) * (lit(iy, one) + lit(0.5, one)) / lit(height, one) - one
            origin, direction, tmin, tmax = gen_ray(PINHOLE, camera, sx, sy)
            best = -1
            for i in range(spheres.shape[0]):
                t = intersect_sphere(origin, direction, tmin, tmax, row3(spheres, i, 0),
                                     spheres[i, SPHERE_RADIUS])
                if t < tmax:
                    tmax = t
                    best = i
            out = image[height - 1 - iy, ix]
            for c in range(3):
                out[c] = background[c] if best < 0 else colors[best, MAT_COLOR + c]


@njit(parallel=True, cache=True, error_model="numpy")
def spheres_only(width, height, camera, camera64, spheres, sphere_eye, cones, colors,
                 background, tile_stride, image):
    tiles_x = (width + TILE - 1) // TILE
    n_tiles = tiles_x * ((height + TILE - 1) // TILE)
    for k in prange(n_tiles):
        tile = (k * tile_stride) % n_tiles
        x0 = (tile % tiles_x) * TILE
        y0 = (tile // tiles_x) * TILE
        x1 = min(x0 + TILE, width)
        y1 = min(y0 + TILE, height)
        candidates = np.empty(spheres.shape[0], dtype=np.int64)
        n = tile_candidates(camera64, cones, x0, x1, y0, y1, width, height, candidates)
        for iy in range(y0, y1):
            for ix in range(x0, x1):
                one = lit(1, camera[0])
                sx = lit(2, one) * (lit(ix, one) + lit(0.5, one)) / lit(width, one) - one
                sy = lit(2, one) * (lit(iy, one) + lit(0.5, one)) / lit(height, one) - one
                origin, direction, tmin, tmax = gen_ray(PINHOLE, camera, sx, sy)
                best = -1
                for j in range(n):
                    i = candidates[j]
                    t = sphere_roots(row3(sphere_eye, i, 0), sphere_eye[i, 3], direction, tmin,
                                     tmax)
                    if t < tmax:
                        tmax = t
                        best = i
                out = image[height - 1 - iy, ix]
                for c in range(3):
                    out[c] = background[c] if best < 0 else colors[best, MAT_COLOR + c]


def prepare(flat, width, height):
    """Arguments for both baselines from a FlatScene of spheres (scene order = row order)."""
    # A scene of many spheres holds them in its BVH too (rtfgu.layout.FlatMesh): rows of spheres only.
    only_spheres = flat.mesh is None or bool((flat.mesh.faces[:, 0] == SPHERE_ROW).all())
    if flat.camera_kind != PINHOLE or not only_spheres or any(
            flat.count(k) for k in flat.shapes if k not in ("sphere", "mesh")):
        raise ValueError("the spheres-only baselines need a pinhole camera and spheres only")
    camera = np.ascontiguousarray(flat.camera.reshape(CAMERA_WIDTH))
    camera64 = camera.astype(np.float64)
    sphere_eye = np.empty((len(flat.table("sphere")), 4), dtype=flat.dtype)
    sphere_eye_terms(camera[PINHOLE_EYE:PINHOLE_EYE + 3].copy(), flat.table("sphere"), sphere_eye)
    cones = cone_table(camera64, flat.table("sphere"))
    n_tiles = ((width + TILE - 1) // TILE) * ((height + TILE - 1) // TILE)
    stride = max(1, int(n_tiles * 0.6180339887))
    while math.gcd(stride, n_tiles) != 1:
        stride += 1
    return camera, camera64, sphere_eye, cones, stride


def run_brute_force(flat, width, height):
    camera = prepare(flat, width, height)[0]
    image = np.empty((height, width, 3), dtype=flat.dtype)
    brute_force(width, height, camera, flat.table("sphere"), flat.materials[flat.material_of], flat.background, image)
    return image.astype(np.float64)


def run_spheres_only(flat, width, height):
    camera, camera64, sphere_eye, cones, stride = prepare(flat, width, height)
    image = np.empty((height, width, 3), dtype=flat.dtype)
    spheres_only(width, height, camera, camera64, flat.table("sphere"), sphere_eye, cones,
                 flat.materials[flat.material_of], flat.background, stride, image)
    return image.astype(np.float64)
