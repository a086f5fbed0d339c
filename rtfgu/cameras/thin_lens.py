"""ThinLens: a camera with a lens of radius lens_radius focused at focal_distance, for depth
of field (Suffern ch. 10, "Thin-Lens Camera").

The image plane and its basis (b1, b2, v, camera constant d, aspect) are the pinhole's.
A ray starts at a point of the lens, eye + lens_radius (l_x b1 + l_y b2) for a point l of
the unit disk, and goes through the point where the pinhole's ray through (sx, sy) meets
the focal plane, focal_distance along v. That point is Suffern's "p = pixel point * f / d"
(ThinLens::ray_direction), found from the pinhole ray as PBRT's thin lens finds it.
Points on the focal plane are sharp, the rest blur with their distance from it;
lens_radius 0 is the pinhole camera.
"""
from __future__ import annotations

import math

from ..float3 import dot, normalize
from ..ray import Ray
from .pinhole import PinholeCamera


class ThinLens(PinholeCamera):
    # The render loop gives gen_ray a point of the unit disk for every sample.
    uses_lens = True

    def __init__(self, eye, lookat, up, d: float = 1.0, aspect: float = 1.0,
                 lens_radius: float = 0.0, focal_distance: float | None = None):
        super().__init__(eye, lookat, up, d, aspect)
        if not (math.isfinite(lens_radius) and lens_radius >= 0):
            raise ValueError("ThinLens.lens_radius must be finite and >= 0, got %r" % (lens_radius,))
        if focal_distance is None:      # focus on the look-at point
            focal_distance = (self.lookat - self.eye).length()
        if not (math.isfinite(focal_distance) and focal_distance > 0):
            raise ValueError("ThinLens.focal_distance must be finite and > 0, got %r" % (focal_distance,))
        self.lens_radius = float(lens_radius)
        self.focal_distance = float(focal_distance)

    def gen_ray(self, sx: float, sy: float, lens=(0.0, 0.0)) -> Ray:
        """The ray through (sx, sy) from the lens point ``lens`` of the unit disk."""
        pinhole = super().gen_ray(sx, sy)
        # The pinhole ray meets the focal plane at t = focal_distance / (d . v).
        focus = pinhole(self.focal_distance / dot(pinhole.direction, self.v))
        lx = lens[0] * self.lens_radius
        ly = lens[1] * self.lens_radius
        origin = self.eye + self.b1 * lx + self.b2 * ly
        return Ray(origin, normalize(focus - origin))
