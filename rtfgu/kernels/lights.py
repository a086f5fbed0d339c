# release: solves a04
"""sample_point_light (02562 "Sampling light in the shader", Kepler's inverse square law),
operation for operation as rtfgu.lights.sample_point_light, and sample_directional as
rtfgu.directional_light.Directional.sample."""
from __future__ import annotations

import math

from numba import njit

from ..layout import LIGHT_INTENSITY, LIGHT_POSITION, offset
from .float3 import div, lit, neg, normalize, row3, sub

DIRECTIONAL_DIRECTION = offset("Directional", "direction")
DIRECTIONAL_INTENSITY = offset("Directional", "intensity")


@njit(cache=True, error_model="numpy")
def sample_point_light(lights, j, pos):
    """The slide's Light struct (L_i, w_i, dist) for light j of the layout seen from pos:
    L_i = I / ||p - x||^2."""
    to_light = sub(row3(lights, j, LIGHT_POSITION), pos)
    dist_squared = to_light[0] * to_light[0] + to_light[1] * to_light[1] + to_light[2] * to_light[2]
    dist = math.sqrt(dist_squared)
    L_i = div(row3(lights, j, LIGHT_INTENSITY), dist_squared)
    return L_i, div(to_light, dist), dist


@njit(cache=True, error_model="numpy")
def sample_directional(lights, j, pos):
    """(L_i, w_i, dist) of directional light j: its intensity, -normalize(direction), inf."""
    w_i = neg(normalize(row3(lights, j, DIRECTIONAL_DIRECTION)))
    return row3(lights, j, DIRECTIONAL_INTENSITY), w_i, lit(math.inf, pos[0])
