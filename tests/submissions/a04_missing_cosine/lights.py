"""Point lights and the Light sample they return (02562, "Sampling light in the shader").

Kepler's inverse square law: a point light at p with intensity I gives the incident
radiance L_i = I / ||p - x||^2 at the surface point x.
"""
from __future__ import annotations

import math

from .float3 import Float3, as_float3


class Light:
    """A light sample as the slide's ``struct Light { L_i, w_i, dist }``: incident radiance,
    unit direction toward the light, and distance to it."""

    __slots__ = ("L_i", "w_i", "dist")

    def __init__(self, L_i: Float3, w_i: Float3, dist: float):
        self.L_i = L_i
        self.w_i = w_i
        self.dist = dist


class PointLight:
    def __init__(self, position, intensity):
        self.position = as_float3(position, "PointLight.position")
        self.intensity = as_float3(intensity, "PointLight.intensity")

    def sample(self, pos: Float3) -> Light:
        """``sample_point_light(pos)``: Kepler's law toward this light."""
        return sample_point_light(self, pos)


def sample_point_light(light: PointLight, pos: Float3) -> Light:
    to_light = light.position - pos
    dist_squared = to_light.length_squared()
    dist = math.sqrt(dist_squared)
    L_i = light.intensity / dist_squared
    return Light(L_i, to_light / dist, dist)
