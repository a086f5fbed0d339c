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
        ### BEGIN SOLUTION
        # t = ((a - o) . n) / (d . n), written as on the slide with A, B, C.
        A = dot(ray.origin, self.normal)
        B = dot(ray.direction, self.normal)
        C = dot(self.point, self.normal)
        if B == 0.0:
            # A ray parallel to the plane never meets it. C++ divides by zero and the
            # comparisons below fail on inf/NaN; Python would raise, so we say it here.
            return False
        t = (C - A) / B

        if t >= ray.tmin and t < ray.tmax:
            ray.tmax = t
            return True
        else:
            return False
        ### END SOLUTION

    def normal_at(self, position: Float3) -> Float3:
        ### BEGIN SOLUTION
        return normalize(self.normal)
        ### END SOLUTION

    def texcoord(self, position: Float3) -> tuple:
        """Worksheet 3's plane coordinates (rtfgu.shapes.shape.plane_texcoord)."""
        return plane_texcoord(position, self.point, self.normal)
