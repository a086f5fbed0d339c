"""SphericalMap: Suffern ch. 29's mapping of a unit sphere about the origin (latitude and
longitude): phi = atan2(x, z) in [0, 2 pi), theta = acos(y); u = phi / 2 pi, v = 1 - theta / pi.
(y is clamped to [-1, 1], so a point rounded off the sphere still maps.)"""
from __future__ import annotations

import math

from ..float3 import Float3
from .mapping import Mapping


class SphericalMap(Mapping):
    name = "spherical_map"

    def get_texel_coordinates(self, p: Float3) -> tuple:
        theta = math.acos(min(max(p.y, -1.0), 1.0))
        phi = math.atan2(p.x, p.z)
        if phi < 0.0:
            phi += 2.0 * math.pi
        return phi / (2.0 * math.pi), 1.0 - theta / math.pi
