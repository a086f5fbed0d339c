"""AreaLighting: Whitted with area lights sampled (Suffern ch. 18, "AreaLighting").

It calls the materials' ``area_light_shade``: the light loop asks each light for a
direction, which an AreaLight draws as a point of its shape (from its sampler, or the
random stream), and weighs the light by L G / pdf; the pixel's samples average the points,
so its shadows are soft. Under RayCast and Whitted an area light is worksheet 5's point
light at its shape's centre (rtfgu/lights/area_light.py).
"""
from __future__ import annotations

from ..float3 import Float3
from .whitted import Whitted


class AreaLighting(Whitted):
    samples_area_lights = True

    def shade(self, sr) -> Float3:
        """The book's AreaLighting::trace_ray at a hit: the material's area_light_shade."""
        # TODO a12: AreaLighting.shade
        #   Suffern's AreaLighting::trace_ray calls the material's area_light_shade at a hit (where Whitted
        #   calls shade): return it.
        raise NotImplementedError('a12: AreaLighting.shade')
