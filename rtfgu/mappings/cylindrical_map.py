"""CylindricalMap: Suffern ch. 29's mapping of a cylinder of radius 1 about the y axis from
y = -1 to 1: phi = atan2(x, z) in [0, 2 pi); u = phi / 2 pi, v = (y + 1) / 2."""
from __future__ import annotations

import math

from ..float3 import Float3
from .mapping import Mapping


class CylindricalMap(Mapping):
    name = "cylindrical_map"

    def get_texel_coordinates(self, p: Float3) -> tuple:
        phi = math.atan2(p.x, p.z)
        if phi < 0.0:
            phi += 2.0 * math.pi
        return phi / (2.0 * math.pi), (p.y + 1.0) / 2.0
