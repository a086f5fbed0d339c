"""Directional: light from infinitely far away, arriving along one direction with the same
radiance everywhere (Suffern ch. 14, "Directional Lights"; 02562 worksheet 5's teapot is lit
by one, intensity pi).

``direction`` is the book's: the direction toward the light, which ``get_direction`` returns
normalised (the light travels along its opposite). L is the intensity (no inverse square law:
there is no distance to fall off over), and the distance is infinite, so a shadow ray is
cut by nothing but shapes (02562: a shadow ray toward a directional light has no tmax).
"""
from __future__ import annotations

from ..float3 import Float3, normalize
from ..validation import colour, nonzero_vector
from .light import Light

class Directional(Light):
    def __init__(self, direction=(0.0, 1.0, 0.0), intensity=(1.0, 1.0, 1.0)):
        self.set_direction(direction)
        self.color = self.intensity = colour(intensity, "Directional.intensity")

    def set_direction(self, direction) -> None:
        self.direction = nonzero_vector(direction, "Directional.direction")

    def get_direction(self, sr) -> Float3:
        return normalize(self.direction)

    def L(self, sr) -> Float3:
        return self.intensity

    incident = L

    def __repr__(self) -> str:
        return "Directional(%r, %r)" % (self.direction, self.intensity)
