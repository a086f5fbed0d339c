"""RectangularMap: Suffern ch. 29's mapping of the square -1 <= x, z <= 1 of the plane
y = 0: u = (z + 1) / 2, v = (x + 1) / 2 (the book's RectangularMap.cpp)."""
from __future__ import annotations

from ..float3 import Float3
from .mapping import Mapping


class RectangularMap(Mapping):
    name = "rectangular_map"

    def get_texel_coordinates(self, p: Float3) -> tuple:
        return (p.z + 1.0) / 2.0, (p.x + 1.0) / 2.0
