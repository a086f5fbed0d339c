"""Checker3D: Suffern ch. 30's 3D checker, cubes of side ``size`` in space: the cube with
floor(x / size) + floor(y / size) + floor(z / size) even has ``color1``, the others
``color2``. The book adds a small number to each coordinate first (``EPSILON``), so that a
face of a box or a plane that lies on a cube boundary (y = 0, a floor) falls in one cube
and not, by rounding, in either."""
from __future__ import annotations

import math

from ..float3 import Float3
from ..validation import colour, positive
from .solid_texture import SolidTexture

# The book's Checker3D::get_color: "float eps = -0.000187453738; // small random number".
EPSILON = -0.000187453738


class Checker3D(SolidTexture):
    def __init__(self, color1=Float3(1.0), color2=Float3(0.5), size: float = 1.0, scale: float = 1.0):
        super().__init__(scale)
        self.color1 = colour(color1, "Checker3D.color1")
        self.color2 = colour(color2, "Checker3D.color2")
        self.size = positive(size, "Checker3D.size")

    def get_color(self, p: Float3) -> Float3:
        x = p.x + EPSILON
        y = p.y + EPSILON
        z = p.z + EPSILON
        if (math.floor(x / self.size) + math.floor(y / self.size) + math.floor(z / self.size)) % 2 == 0:
            return self.color1
        return self.color2
