"""LightProbe: Suffern ch. 29's mapping of a light probe image (Debevec's angular map: the
circle inscribed in the square image shows every direction) onto a unit sphere. For the
point (x, y, z): d = sqrt(x^2 + y^2), cos beta = x / d, sin beta = y / d, alpha = acos(z)
(``panoramic``: acos(-z), the view from inside the sphere, as the book's map type
Panoramic), r = alpha / pi; u = (1 + r cos beta) / 2, v = (1 + r sin beta) / 2.
On the z axis (d = 0) beta is taken as 0: there r is 0 or 1 and the point is the image's
centre or its rim, where beta has no other meaning."""
from __future__ import annotations

import math

from ..float3 import Float3
from .mapping import Mapping


class LightProbe(Mapping):
    def __init__(self, panoramic: bool = False):
        if not isinstance(panoramic, bool):
            raise ValueError("LightProbe.panoramic must be True or False, got %r" % (panoramic,))
        self.panoramic = panoramic

    @property
    def name(self) -> str:
        return "panoramic" if self.panoramic else "light_probe"

    def get_texel_coordinates(self, p: Float3) -> tuple:
        d = math.sqrt(p.x * p.x + p.y * p.y)
        if d > 0.0:
            sin_beta = p.y / d
            cos_beta = p.x / d
        else:
            sin_beta = 0.0
            cos_beta = 1.0
        z = min(max(-p.z if self.panoramic else p.z, -1.0), 1.0)
        r = math.acos(z) / math.pi
        return (1.0 + r * cos_beta) * 0.5, (1.0 + r * sin_beta) * 0.5
