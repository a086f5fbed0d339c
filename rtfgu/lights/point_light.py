"""PointLight: light from one point (Suffern ch. 14, "Point Lights"; 02562, "Kepler's inverse
square law").

The 02562 point light has an intensity I and obeys Kepler's inverse square law: at a point x
at distance d from it the incident radiance is L_i = I / d^2. Suffern's has a radiance
``ls cl`` that does not fall off (his exercise adds the falloff); ``inverse_square`` says
which: True (the 02562 light, every homework scene's) or False (the book's). Either way the
book's setters set it: ``set_ls`` and ``set_color`` make I = ls cl, ``set_location`` the point.
"""
from __future__ import annotations

import math

from ..float3 import Float3, as_float3
from ..validation import colour
from .light import Light


class PointLight(Light):
    def __init__(self, position=(0.0, 0.0, 0.0), intensity=(1.0, 1.0, 1.0), inverse_square: bool = True):
        self.set_location(position)
        self.color = self.intensity = colour(intensity, "PointLight.intensity")
        self.inverse_square = bool(inverse_square)

    def set_location(self, position) -> None:
        self.position = as_float3(position, "PointLight.position")

    def flat_limit(self):
        if not self.inverse_square:
            return ("numba and WGSL compute the 02562 point light (Kepler's inverse square law); the book's "
                    "(inverse_square = False) renders with backend='reference'")
        return super().flat_limit()

    def get_direction(self, sr) -> Float3:
        """The unit direction (p - x) / |p - x| toward the light."""
        ### BEGIN SOLUTION
        to_light = self.position - sr.position
        return to_light / math.sqrt(to_light.length_squared())
        ### END SOLUTION

    def L(self, sr) -> Float3:
        """Kepler: I / |p - x|^2 (the book's light: I, at every distance)."""
        if not self.inverse_square:
            return self.intensity
        ### BEGIN SOLUTION
        return self.intensity / (self.position - sr.position).length_squared()
        ### END SOLUTION

    # L G / pdf is L: a point has G = pdf = 1.
    incident = L

    def distance(self, sr) -> float:
        return math.sqrt((self.position - sr.position).length_squared())

    def __repr__(self) -> str:
        return "PointLight(%r, %r)" % (self.position, self.intensity)
