"""PlanarShape: a shape that is a part of a plane, intersected as Suffern's ch. 19 disk and
rectangle are: the plane's own test (``Plane.intersect_p``, lecture 01) gives t, and the hit
counts when the point o + t d lies in the part (``contains``). Its normal is the plane's.
"""
from __future__ import annotations

from ..float3 import Float3
from ..ray import Ray
from .plane import Plane
from .shape import Shape, meets_plane


class PlanarShape(Shape):
    """A subclass sets ``self._plane`` (through ``set_plane``) and defines ``contains``."""

    def set_plane(self, point: Float3, normal: Float3) -> None:
        self._plane = Plane(point, normal, self.color)

    def contains(self, position: Float3) -> bool:
        """Whether a point of the plane lies in the shape (its rim or edges included)."""
        raise NotImplementedError

    def intersect_p(self, ray: Ray) -> bool:
        t = meets_plane(self._plane, ray)
        if t is None or not self.contains(ray(t)):
            return False
        ray.tmax = t
        return True

    def normal_at(self, position: Float3) -> Float3:
        return self._plane.normal_at(position)
