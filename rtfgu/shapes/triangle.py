"""Triangle v0, v1, v2 with the 02562 barycentric intersection ("Ray-triangle intersection").

    e0 = v1 - v0,  e1 = v2 - v0,  n = e0 x e1
    t'    = ((v0 - o) . n) / (w . n)
    beta  =  ((v0 - o) x w) . e1 / (w . n)
    gamma = -((v0 - o) x w) . e0 / (w . n)
    hit when beta >= 0, gamma >= 0, beta + gamma <= 1 and t' in [tmin, tmax).
"""
from __future__ import annotations

import math

from ..float3 import Float3, as_float3, cross, dot, normalize
from ..ray import Ray
from .shape import Shape


class Triangle(Shape):
    def __init__(self, v0, v1, v2, color, material=None):
        super().__init__(color, material)
        self.v0 = as_float3(v0, "Triangle.v0")
        self.v1 = as_float3(v1, "Triangle.v1")
        self.v2 = as_float3(v2, "Triangle.v2")
        self.e0 = self.v1 - self.v0
        self.e1 = self.v2 - self.v0
        self.n = cross(self.e0, self.e1)
        if self.n.length_squared() == 0.0:
            raise ValueError("Triangle vertices v0, v1, v2 span zero area (collinear or repeated)")

    def intersect_p(self, ray: Ray) -> bool:
        ### BEGIN SOLUTION
        denom = dot(ray.direction, self.n)
        if denom == 0.0:
            return False  # the ray is parallel to the triangle's plane
        a = self.v0 - ray.origin
        t = dot(a, self.n) / denom
        if not (t >= ray.tmin and t < ray.tmax):
            return False
        c = cross(a, ray.direction)
        beta = dot(c, self.e1) / denom
        gamma = -dot(c, self.e0) / denom
        if beta >= 0.0 and gamma >= 0.0 and beta + gamma <= 1.0:
            ray.tmax = t
            return True
        return False
        ### END SOLUTION

    def normal_at(self, position: Float3) -> Float3:
        ### BEGIN SOLUTION
        return normalize(self.n)
        ### END SOLUTION

    def bounds(self):
        from ..accelerators.bbox import BBox
        return BBox.of_points((self.v0, self.v1, self.v2))

    def texcoord(self, position: Float3) -> tuple:
        """The barycentric (beta, gamma) of the point: p - v0 = beta e0 + gamma e1, so
        beta = ((p - v0) x e1) . n / (n . n) and gamma = (e0 x (p - v0)) . n / (n . n)."""
        d = position - self.v0
        nn = dot(self.n, self.n)
        return dot(cross(d, self.e1), self.n) / nn, dot(cross(self.e0, d), self.n) / nn

    # An area light's shape (Suffern ch. 18, "Area Lights"): sample, pdf and get_normal.
    @property
    def area(self) -> float:
        return 0.5 * self.n.length()

    def sample(self, u: float, v: float) -> Float3:
        """A point uniform by area for (u, v) uniform in [0, 1)^2: barycentric coordinates
        (1 - sqrt(u), v sqrt(u), (1 - v) sqrt(u)) (Shirley, "Graphics Gems III")."""
        ### BEGIN SOLUTION
        su = math.sqrt(u)
        return self.v0 + (self.e0 * v + self.e1 * (1.0 - v)) * su
        ### END SOLUTION

    def pdf(self, sr=None) -> float:
        return 1.0 / self.area

    def get_normal(self, point: Float3 = None) -> Float3:
        return self.normal_at(point)

