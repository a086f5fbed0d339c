"""A directional light (Suffern ch. 14, ``Directional``; 02562 worksheet 5's teapot is lit by
one, direction normalize(-1, -1, -1), intensity pi): light from infinitely far away, arriving
along one direction with the same radiance everywhere.

``direction`` is the way the light travels (toward the scene); the sample's w_i, toward the
light, is -normalize(direction), L_i is the intensity (no inverse square law: there is no
distance to fall off over), and dist is infinite, so a shadow ray is cut by nothing but
shapes (02562: a shadow ray toward a directional light has no tmax).
"""
from __future__ import annotations

import math

from .float3 import as_float3, normalize
from .lights import Light
from .shapes.shape import nonzero_vector


class Directional:
    def __init__(self, direction, intensity):
        self.direction = nonzero_vector(direction, "Directional.direction")
        self.intensity = as_float3(intensity, "Directional.intensity")

    def sample(self, pos) -> Light:
        """The slide's Light struct for this light, the same at every ``pos``."""
        return Light(self.intensity, -normalize(self.direction), math.inf)
