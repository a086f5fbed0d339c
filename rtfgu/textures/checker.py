"""Checker: a procedural checkerboard of two colours in texture space (Suffern ch. 30,
"Checker3D" and its 2D "PlaneChecker"): squares of side ``size`` in (u, v); the square
with floor(u / size) + floor(v / size) even has ``color1``."""
from __future__ import annotations

import math

from ..float3 import Float3, as_float3
from .texture import Texture


class Checker(Texture):
    def __init__(self, color1, color2, size: float = 0.1, scale: float = 1.0):
        super().__init__(scale)
        self.color1 = as_float3(color1, "Checker.color1")
        self.color2 = as_float3(color2, "Checker.color2")
        if isinstance(size, bool) or not isinstance(size, (int, float)) or not (
                math.isfinite(size) and size > 0):
            raise ValueError("Checker.size must be finite and > 0, got %r" % (size,))
        self.size = float(size)

    def get_color(self, u: float, v: float) -> Float3:
        if (math.floor(u / self.size) + math.floor(v / self.size)) % 2 == 0:
            return self.color1
        return self.color2
