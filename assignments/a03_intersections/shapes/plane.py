"""Plane: the points p with (p - a) . n = 0 (lecture 01, "Plane" and "Ray-Plane Intersection")."""
from __future__ import annotations

from ..float3 import Float3, as_float3, dot, normalize
from ..ray import Ray
from .shape import Shape, nonzero_vector, plane_texcoord


class Plane(Shape):
    def __init__(self, point, normal, color, material=None):
        super().__init__(color, material)
        self.point = as_float3(point, "Plane.point")
        self.normal = nonzero_vector(normal, "Plane.normal")

    def intersect_p(self, ray: Ray) -> bool:
        # TODO a03: Plane.intersect_p
        #   t = ((a - o) . n) / (d . n), written as on the slide with A = o . n, B = d . n,
        #   C = a . n. A ray parallel to the plane (B == 0) misses. Accept t only if
        #   tmin <= t < tmax; then set ray.tmax = t and return True, else return False.
        raise NotImplementedError('a03: Plane.intersect_p')

    def normal_at(self, position: Float3) -> Float3:
        # TODO a03: Plane.normal_at
        #   Return the plane's normal as a unit vector.
        raise NotImplementedError('a03: Plane.normal_at')

    def texcoord(self, position: Float3) -> tuple:
        """Worksheet 3's plane coordinates (rtfgu.shapes.shape.plane_texcoord)."""
        return plane_texcoord(position, self.point, self.normal)
