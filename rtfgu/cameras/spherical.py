"""Spherical: a panoramic camera whose image is a rectangle of longitude and latitude
(Suffern ch. 11.3, "Spherical Panoramic Camera"; Spherical::ray_direction).

The normalised image point (Suffern's pn) is (sx, sy) itself: its longitude is
lambda = sx lambda_max (degrees to the right of the view direction v, at most 180) and
its latitude psi = sy psi_max (degrees above the b1-v plane, at most 90). The book takes
the polar angles phi = pi - lambda, theta = pi / 2 - psi and forms
sin theta sin phi u + cos theta v + sin theta cos phi w with (u, v, w) = (b1, b2, -v);
with sin(pi - lambda) = sin lambda, cos(pi - lambda) = -cos lambda, sin(pi / 2 - psi) =
cos psi and cos(pi / 2 - psi) = sin psi that is

    direction = b1 cos(psi) sin(lambda) + b2 sin(psi) + v cos(psi) cos(lambda),

written so, so that the centre's ray is v exactly. lambda_max = 180 and psi_max = 90 see
every direction (an equirectangular image, twice as wide as high).
"""
from __future__ import annotations

import math

from ..float3 import normalize
from ..ray import Ray
from .camera import Camera, check_angle, look_at_basis


class Spherical(Camera):
    def __init__(self, eye, lookat, up, lambda_max: float = 180.0, psi_max: float = 90.0):
        self.eye, self.lookat, self.up, self.v, self.b1, self.b2 = look_at_basis(eye, lookat, up, "Spherical")
        self.lambda_max = check_angle(lambda_max, "Spherical", "lambda_max", 180.0)
        self.psi_max = check_angle(psi_max, "Spherical", "psi_max", 90.0)
        # The book's degreeToRadian(lambda_max) and degreeToRadian(psi_max), once.
        self.lambda_max_radians = self.lambda_max * (math.pi / 180.0)
        self.psi_max_radians = self.psi_max * (math.pi / 180.0)

    def gen_ray(self, sx: float, sy: float) -> Ray:
        lam = sx * self.lambda_max_radians
        psi = sy * self.psi_max_radians
        cos_psi = math.cos(psi)
        direction = (self.b1 * (cos_psi * math.sin(lam)) + self.b2 * math.sin(psi)
                     + self.v * (cos_psi * math.cos(lam)))
        return Ray(self.eye.copy(), normalize(direction))
