"""Sphere: the points p with (p - c) . (p - c) = r^2 (lecture 01, "Ray-Sphere Intersection")."""
from __future__ import annotations

import math

from ..float3 import Float3, as_float3, dot, normalize
from ..ray import Ray
from .shape import Shape, positive


class Sphere(Shape):
    def __init__(self, center, radius: float, color, material=None):
        super().__init__(color, material)
        self.center = as_float3(center, "Sphere.center")
        self.radius = positive(radius, "Sphere.radius")

    def intersect_p(self, ray: Ray) -> bool:
        # TODO a03: Sphere.intersect_p
        #   a = d . d, b = 2 (o - c) . d, c = (o - c) . (o - c) - r^2, disc = b^2 - 4ac.
        #   No hit if disc < 0. Otherwise try t = (-b - sqrt(disc)) / 2a, then (-b + sqrt(disc)) / 2a:
        #   the first with tmin <= t < tmax is the hit (set ray.tmax = t, return True).
        raise NotImplementedError('a03: Sphere.intersect_p')

    def normal_at(self, position: Float3) -> Float3:
        # TODO a03: Sphere.normal_at
        #   Return the unit outward normal at a point on the sphere: (position - center) / radius.
        raise NotImplementedError('a03: Sphere.normal_at')

    def bounds(self):
        from ..accelerators.bbox import padded
        return padded(self.center, Float3(self.radius))

    def texcoord(self, position: Float3) -> tuple:
        """Suffern's SphericalMap (ch. 29): u = phi / 2 pi with phi = atan2(x, z) in [0, 2 pi),
        v = 1 - theta / pi with theta = acos(y), for (x, y, z) = (p - c) / r."""
        d = position - self.center
        y = min(max(d.y / self.radius, -1.0), 1.0)
        theta = math.acos(y)
        phi = math.atan2(d.x / self.radius, d.z / self.radius)
        if phi < 0.0:
            phi += 2.0 * math.pi
        return phi / (2.0 * math.pi), 1.0 - theta / math.pi

    # An area light's shape (Suffern ch. 18, "Area Lights"): sample, pdf and get_normal.
    @property
    def area(self) -> float:
        return 4.0 * math.pi * self.radius * self.radius

    def sample(self, u: float, v: float) -> Float3:
        """A point uniform by area for (u, v) uniform in [0, 1)^2: the direction with
        z = 1 - 2u and phi = 2 pi v (Archimedes: uniform in z)."""
        return self.sample_with_normal(u, v)[0]

    def sample_with_normal(self, u: float, v: float) -> tuple:
        """(sample(u, v), its unit normal), the normal without a division by the radius."""
        normal = self.unit_direction(u, v)
        return self.center + normal * self.radius, normal

    @staticmethod
    def unit_direction(u: float, v: float) -> Float3:
        z = 1.0 - 2.0 * u
        s = math.sqrt(max(0.0, 1.0 - z * z))
        phi = 2.0 * math.pi * v
        return Float3(s * math.cos(phi), s * math.sin(phi), z)

    def pdf(self, sr=None) -> float:
        """The density of ``sample`` per unit area: 1 / area."""
        return 1.0 / self.area

    def get_normal(self, point: Float3) -> Float3:
        return (point - self.center) / self.radius

