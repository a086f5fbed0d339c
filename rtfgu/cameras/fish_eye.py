"""FishEye: a camera that sees up to psi_max degrees away from its view direction, the image
a disk (Suffern ch. 11.2, "Fish-Eye Camera"; FishEye::ray_direction).

The normalised image point (Suffern's pn) is (sx, sy) itself. Its polar coordinates
r = sqrt(sx^2 + sy^2) and alpha (cos alpha = sx / r, sin alpha = sy / r) give the ray:
psi = r psi_max is its angle from the view direction v, alpha its angle around v from b1,

    direction = b1 sin(psi) cos(alpha) + b2 sin(psi) sin(alpha) + v cos(psi),

which is the book's sin psi cos alpha u + sin psi sin alpha v - cos psi w with (u, v, w) =
(b1, b2, -v). psi_max = 90 sees a hemisphere, 180 the whole sphere. At r = 0 the ray is v
(alpha is undefined there: the book divides 0 by 0). A point outside the unit circle,
r^2 > 1, sees nothing: its ray is a blank ray (rtfgu.cameras.camera.blank_ray), so the
pixel shows Scene.background where the book leaves it black. On a non-square image the
circle is an ellipse touching the image's sides, as in the book (pn is normalised per axis).
"""
from __future__ import annotations

import math

from ..float3 import normalize
from ..ray import Ray
from .camera import Camera, blank_ray, check_angle, look_at_basis


class FishEye(Camera):
    def __init__(self, eye, lookat, up, psi_max: float = 120.0):
        self.eye, self.lookat, self.up, self.v, self.b1, self.b2 = look_at_basis(eye, lookat, up, "FishEye")
        self.psi_max = check_angle(psi_max, "FishEye", "psi_max", 180.0)
        # The book's psi_max * PI_ON_180, once.
        self.psi_max_radians = self.psi_max * (math.pi / 180.0)

    def gen_ray(self, sx: float, sy: float) -> Ray:
        r_squared = sx * sx + sy * sy
        if r_squared > 1.0:
            return blank_ray(self.eye, self.v)
        r = math.sqrt(r_squared)
        psi = r * self.psi_max_radians
        sin_psi = math.sin(psi)
        cos_psi = math.cos(psi)
        if r > 0.0:
            sin_alpha = sy / r
            cos_alpha = sx / r
        else:
            sin_alpha = 0.0
            cos_alpha = 1.0
        direction = self.b1 * (sin_psi * cos_alpha) + self.b2 * (sin_psi * sin_alpha) + self.v * cos_psi
        return Ray(self.eye.copy(), normalize(direction))
