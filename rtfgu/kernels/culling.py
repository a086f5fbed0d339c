# release: solves a03
"""Per-tile sphere culling for a pinhole camera's primary rays.

All primary rays of a tile leave the eye inside one circular cone: around the mean of the
directions through the tile's corners, as wide as the widest of them (q is affine in
(sx, sy), so every ray of the tile lies in the cone of its corners). The corners are the
pixels' outer edges, so rays through any sample point of a pixel are inside. A sphere seen from the
eye under the angular radius asin(r / D) can only be hit by a ray of the tile if its centre
direction is within the cone's half angle plus that radius. Spheres outside are left out of
the tile's candidate list; the test is conservative by a margin far above the rounding of
the float32 intersection (about 2 eps D / r near a grazing ray), so no hit is ever lost and
the image is the same bit for bit.

The cones are computed in float64 whatever the render precision: they only choose which
spheres to test, never a result.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..layout import (PINHOLE_ASPECT, PINHOLE_B1, PINHOLE_B2, PINHOLE_D, PINHOLE_EYE,
                      PINHOLE_V, SPHERE_CENTER, SPHERE_RADIUS)
from .float3 import add, dot, load3, normalize, row3, scale, sub

# Spheres this close to the eye (D < NEAR_FACTOR r) are always candidates: their silhouette
# seen from the eye is too close to a tangent plane for an angular bound.
NEAR_FACTOR = 1.01
# Angular margin in radians: ABSOLUTE + RELATIVE * D / r, with RELATIVE >= 16 float32 eps.
MARGIN_ABSOLUTE = 1e-5
MARGIN_RELATIVE = 1e-6


@njit(cache=True, error_model="numpy")
def sphere_cones(camera, spheres, out):
    """Per sphere: the unit direction from the eye to its centre and its angular radius
    plus the margin (pi: always a candidate)."""
    eye = load3(camera, PINHOLE_EYE)
    for i in range(spheres.shape[0]):
        p = sub(row3(spheres, i, SPHERE_CENTER), eye)
        D = math.sqrt(dot(p, p))
        r = spheres[i, SPHERE_RADIUS]
        if D < NEAR_FACTOR * r:
            out[i, 0] = 0.0
            out[i, 1] = 0.0
            out[i, 2] = 1.0
            out[i, 3] = math.pi
        else:
            out[i, 0] = p[0] / D
            out[i, 1] = p[1] / D
            out[i, 2] = p[2] / D
            out[i, 3] = math.asin(r / D) + MARGIN_ABSOLUTE + MARGIN_RELATIVE * D / r


@njit(cache=True, error_model="numpy")
def _direction(camera, sx, sy):
    u = sx * camera[PINHOLE_ASPECT] * 0.5
    w = sy * 0.5
    q = add(add(scale(load3(camera, PINHOLE_B1), u), scale(load3(camera, PINHOLE_B2), w)),
            scale(load3(camera, PINHOLE_V), camera[PINHOLE_D]))
    return normalize(q)


@njit(cache=True, error_model="numpy")
def tile_candidates(camera, cones, x0, x1, y0, y1, width, height, out):
    """Write the rows of the spheres that a primary ray of pixels [x0, x1) x [y0, y1) can
    hit into ``out`` (in increasing order) and return how many there are. ``camera`` is
    the pinhole camera block in float64."""
    sx0 = 2.0 * x0 / width - 1.0
    sx1 = 2.0 * x1 / width - 1.0
    sy0 = 2.0 * y0 / height - 1.0
    sy1 = 2.0 * y1 / height - 1.0
    c0 = _direction(camera, sx0, sy0)
    c1 = _direction(camera, sx1, sy0)
    c2 = _direction(camera, sx0, sy1)
    c3 = _direction(camera, sx1, sy1)
    axis = normalize(add(add(c0, c1), add(c2, c3)))
    cos_half = min(min(dot(axis, c0), dot(axis, c1)), min(dot(axis, c2), dot(axis, c3)))
    half = math.acos(min(cos_half, 1.0))
    n = 0
    for i in range(cones.shape[0]):
        limit = half + cones[i, 3]
        if limit >= math.pi:
            out[n] = i
            n += 1
            continue
        cos_a = axis[0] * cones[i, 0] + axis[1] * cones[i, 1] + axis[2] * cones[i, 2]
        if math.acos(max(-1.0, min(cos_a, 1.0))) <= limit:
            out[n] = i
            n += 1
    return n


def cone_table(camera64: np.ndarray, spheres: np.ndarray) -> np.ndarray:
    cones = np.empty((len(spheres), 4), dtype=np.float64)
    sphere_cones(camera64, spheres.astype(np.float64), cones)
    return cones
