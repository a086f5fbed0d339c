"""OpenPartCylinder: the part of an OpenCylinder (y0, y1, radius) between the azimuths
phi_min and phi_max, in degrees (Suffern ch. 19, "Part objects"; rtfgu.shapes.part).

The book's part cylinder is the open cylinder's quadratic with the azimuth test
phi_min <= atan2(x, z) <= phi_max on each root. Here the OpenCylinder is asked for its
nearest hit, then from just beyond it for the next one (it has two at most), and a hit
counts when its azimuth is in range: the part holds no formula of its own. Like rtfgu's
OpenCylinder (and unlike the book's convex part, whose normal always points out) both sides
are seen: the normal turns toward the ray.
"""
from __future__ import annotations

import math

from ..ray import Ray
from .open_cylinder import OpenCylinder
from .part import angle_range, azimuth


class OpenPartCylinder(OpenCylinder):
    def __init__(self, y0: float, y1: float, radius: float, phi_min: float, phi_max: float, color,
                 material=None):
        super().__init__(y0, y1, radius, color, material)
        self.phi_min, self.phi_max = angle_range(phi_min, phi_max, 360.0, "OpenPartCylinder.phi_min",
                                                 "OpenPartCylinder.phi_max")

    def intersect_p(self, ray: Ray) -> bool:
        probe = Ray(ray.origin, ray.direction, ray.tmin, ray.tmax)
        for _ in range(2):   # the nearest hit of the whole cylinder, then the next one
            if not super().intersect_p(probe):
                return False
            if self.phi_min <= azimuth(ray(probe.tmax)) <= self.phi_max:
                ray.tmax = probe.tmax
                return True
            probe = Ray(ray.origin, ray.direction, math.nextafter(probe.tmax, math.inf), ray.tmax)
        return False
