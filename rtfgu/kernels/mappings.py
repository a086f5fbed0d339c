"""Suffern ch. 29's mappings for the kernels, operation for operation as rtfgu/mappings/:
``mapped_coordinates(mapping, p)`` is the (u, v) of the point p under the mapping with that
id (rtfgu.registry.MAPPING_IDS)."""
from __future__ import annotations

import math

from numba import njit

from ..registry import MAPPING_IDS
from .float3 import lit

SPHERICAL = MAPPING_IDS["spherical_map"]
CYLINDRICAL = MAPPING_IDS["cylindrical_map"]
RECTANGULAR = MAPPING_IDS["rectangular_map"]
PANORAMIC = MAPPING_IDS["panoramic"]


@njit(cache=True, error_model="numpy")
def spherical_map(p):
    """SphericalMap.get_texel_coordinates."""
    one = lit(1.0, p[0])
    two_pi = lit(2.0 * math.pi, one)
    theta = math.acos(min(max(p[1], -one), one))
    phi = math.atan2(p[0], p[2])
    if phi < lit(0.0, one):
        phi += two_pi
    return phi / two_pi, one - theta / lit(math.pi, one)


@njit(cache=True, error_model="numpy")
def cylindrical_map(p):
    """CylindricalMap.get_texel_coordinates."""
    one = lit(1.0, p[0])
    two_pi = lit(2.0 * math.pi, one)
    phi = math.atan2(p[0], p[2])
    if phi < lit(0.0, one):
        phi += two_pi
    return phi / two_pi, (p[1] + one) / lit(2.0, one)


@njit(cache=True, error_model="numpy")
def light_probe(p, panoramic):
    """LightProbe.get_texel_coordinates, regular or panoramic."""
    zero = lit(0.0, p[0])
    one = lit(1.0, p[0])
    half = lit(0.5, p[0])
    d = math.sqrt(p[0] * p[0] + p[1] * p[1])
    sin_beta = zero
    cos_beta = one
    if d > zero:
        sin_beta = p[1] / d
        cos_beta = p[0] / d
    z = -p[2] if panoramic else p[2]
    r = math.acos(min(max(z, -one), one)) / lit(math.pi, one)
    return (one + r * cos_beta) * half, (one + r * sin_beta) * half


@njit(cache=True, error_model="numpy")
def mapped_coordinates(mapping, p):
    one = lit(1.0, p[0])
    if mapping == SPHERICAL:
        return spherical_map(p)
    if mapping == CYLINDRICAL:
        return cylindrical_map(p)
    if mapping == RECTANGULAR:
        return (p[2] + one) / lit(2.0, one), (p[0] + one) / lit(2.0, one)
    return light_probe(p, mapping == PANORAMIC)
