"""Annulus: a disk with a hole, the points of the plane through ``center`` with normal
``normal`` whose distance from the centre is between ``inner_radius`` and ``outer_radius``
(Suffern ch. 19, "Part objects": the flat rim of the FlatRimmedBowl).

It is intersected as the Disk is: the plane's test (``Plane.intersect_p``, lecture 01)
gives t, and the hit counts when p = o + t d has r_i^2 <= (p - c) . (p - c) <= r_o^2; both
rims belong to the annulus, as the disk's rim to the disk.
"""
from __future__ import annotations

from ..float3 import Float3, as_float3
from ..ray import Ray
from ..validation import number
from .disk import Disk
from .plane import Plane
from .shape import Shape, meets_plane, nonzero_vector, plane_texcoord, positive


class Annulus(Shape):
    def __init__(self, center, normal, inner_radius: float, outer_radius: float, color, material=None):
        super().__init__(color, material)
        self.center = as_float3(center, "Annulus.center")
        self.normal = nonzero_vector(normal, "Annulus.normal")
        self.inner_radius = number(inner_radius, "Annulus.inner_radius")
        self.outer_radius = positive(outer_radius, "Annulus.outer_radius")
        if not self.inner_radius < self.outer_radius:
            raise ValueError("Annulus.inner_radius must be below Annulus.outer_radius, got %r and %r"
                             % (inner_radius, outer_radius))
        self._plane = Plane(self.center, self.normal, color)

    def intersect_p(self, ray: Ray) -> bool:
        t = meets_plane(self._plane, ray)
        if t is None:
            return False
        to_hit = ray(t) - self.center
        d2 = to_hit.length_squared()
        if self.inner_radius * self.inner_radius <= d2 <= self.outer_radius * self.outer_radius:
            ray.tmax = t
            return True
        return False

    def normal_at(self, position: Float3) -> Float3:
        return self._plane.normal_at(position)

    def bounds(self):
        """The outer disk's box."""
        return Disk(self.center, self.normal, self.outer_radius, self.color).bounds()

    def texcoord(self, position: Float3) -> tuple:
        """The plane's coordinates about the centre, as the disk's (plane_texcoord)."""
        return plane_texcoord(position, self.center, self.normal)
