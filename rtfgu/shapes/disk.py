"""Disk: the points of the plane through ``center`` with normal ``normal`` that lie within
``radius`` of the centre (Suffern ch. 19, "Disks").

A disk is a plane clipped to a radius, and it is intersected that way: the plane's test
(``Plane.intersect_p``, lecture 01) gives t, and the hit counts when the point
p = o + t d has (p - c) . (p - c) <= r^2 (the rim belongs to the disk, as the triangle's
edges belong to the triangle).
"""
from __future__ import annotations

import math

from ..float3 import Float3, as_float3, normalize
from .planar_shape import PlanarShape
from .shape import nonzero_vector, plane_texcoord, positive


class Disk(PlanarShape):
    def __init__(self, center, normal, radius: float, color, material=None):
        super().__init__(color, material)
        self.center = as_float3(center, "Disk.center")
        self.normal = nonzero_vector(normal, "Disk.normal")
        self.radius = positive(radius, "Disk.radius")
        self.set_plane(self.center, self.normal)

    def contains(self, position: Float3) -> bool:
        return (position - self.center).length_squared() <= self.radius * self.radius

    def bounds(self):
        """The disk's exact box: along axis a it reaches radius sqrt(1 - n_a^2) from the centre."""
        from ..accelerators.bbox import padded
        n = normalize(self.normal)
        return padded(self.center, Float3(*(self.radius * math.sqrt(max(0.0, 1.0 - n[a] * n[a]))
                                            for a in range(3))))

    def texcoord(self, position: Float3) -> tuple:
        """The plane's coordinates about the centre (rtfgu.shapes.shape.plane_texcoord)."""
        return plane_texcoord(position, self.center, self.normal)
