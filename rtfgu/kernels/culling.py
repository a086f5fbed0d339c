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

The test is made on cosines, with no inverse cosine per sphere and tile: the angle a
between the cone's axis and a sphere's direction is within the limit L = half + R (R the
sphere's angular radius with its margin) where cos a >= cos L = cos(half) cos R -
sin(half) sin R, acos being decreasing on [-1, 1] and L below pi. cos R and sin R are
computed once per frame; the rounding of the cosines (about 1e-16, at most 2e-8 radians
where the angle is near 0 or pi) is far inside the margin.

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
    """Per sphere (a row of CONE_FIELDS): the unit direction from the eye to its centre, its
    angular radius R plus the margin (pi: always a candidate), cos R and sin R."""
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
        out[i, 4] = math.cos(out[i, 3])
        out[i, 5] = math.sin(out[i, 3])


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
    cos_half = min(min(min(dot(axis, c0), dot(axis, c1)), min(dot(axis, c2), dot(axis, c3))), 1.0)
    half = math.acos(cos_half)
    sin_half = math.sqrt(max(0.0, 1.0 - cos_half * cos_half))
    n = 0
    for i in range(cones.shape[0]):
        # Within the cone where the angle to the axis is at most L = half + R (L >= pi: any
        # angle), compared as cosines (the module docstring).
        if half + cones[i, 3] >= math.pi or axis[0] * cones[i, 0] + axis[1] * cones[i, 1] + \
                axis[2] * cones[i, 2] >= cos_half * cones[i, 4] - sin_half * cones[i, 5]:
            out[n] = i
            n += 1
    return n


# A row of the cone table (sphere_cones): direction (3), R, cos R, sin R.
CONE_FIELDS = 6


def cone_table(camera64: np.ndarray, spheres: np.ndarray) -> np.ndarray:
    """The culling cones of the sphere rows ``spheres`` seen from the pinhole ``camera64``
    (float64), (len(spheres), CONE_FIELDS) float64 (sphere_cones)."""
    cones = np.empty((len(spheres), CONE_FIELDS), dtype=np.float64)
    sphere_cones(camera64, spheres.astype(np.float64), cones)
    return cones
