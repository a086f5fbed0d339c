"""OpenCylinder: the side of the cylinder of ``radius`` about the y axis between the heights
``y0`` and ``y1``, without caps (Suffern ch. 19, "Open cylinders").

The book's ``OpenCylinder::hit``: the ray meets the infinite cylinder x^2 + z^2 = r^2 where

    a t^2 + b t + c = 0,  a = d_x^2 + d_z^2,  b = 2 (o_x d_x + o_z d_z),  c = o_x^2 + o_z^2 - r^2,

which is the sphere's quadratic (lecture 01) for the ray projected onto the xz plane,
(o_x, 0, o_z) + t (d_x, 0, d_z), and the sphere of radius r about the origin: the class asks
``Sphere.intersect_p`` for the near root, then (from just beyond it) for the far one, and a
root counts when its height o_y + t d_y lies within [y0, y1], so that a ray sees the inside
through an open end. The rims belong to the cylinder (the book's test is y0 < y < y1; rtfgu's
closed shapes keep their edges, as the disk its rim). A ray parallel to the axis (a = 0, where
the book divides by zero) misses it.

Both surfaces are seen, so the normal is (x, 0, z) / r turned toward the ray: the book flips
it when -d . n < 0, a hit from inside. That needs the ray, so the class gives it through
``hit_normal(position, direction)`` (rtfgu.shapes.shape.Shape.hit_normal); ``normal_at`` is
the outward normal.
"""
from __future__ import annotations

import math

from ..float3 import Float3, dot, normalize
from ..ray import Ray
from ..validation import finite
from .shape import Shape, positive
from .sphere import Sphere


class OpenCylinder(Shape):
    def __init__(self, y0: float, y1: float, radius: float, color, material=None):
        super().__init__(color, material)
        name = type(self).__name__
        self.y0 = finite(y0, name + ".y0")
        self.y1 = finite(y1, name + ".y1")
        if not self.y0 < self.y1:
            raise ValueError("%s.y0 must be below %s.y1, got y0 = %r, y1 = %r" % (name, name, self.y0, self.y1))
        self.radius = positive(radius, name + ".radius")
        self._circle = Sphere(Float3(0.0, 0.0, 0.0), self.radius, color)

    def intersect_p(self, ray: Ray) -> bool:
        o, d = ray.origin, ray.direction
        if d.x == 0.0 and d.z == 0.0:
            return False  # parallel to the axis
        flat = Ray(Float3(o.x, 0.0, o.z), Float3(d.x, 0.0, d.z), ray.tmin, ray.tmax)
        for _ in range(2):   # the near root, then the far one
            if not self._circle.intersect_p(flat):
                return False
            y_hit = o.y + flat.tmax * d.y
            if self.y0 <= y_hit <= self.y1:
                ray.tmax = flat.tmax
                return True
            flat = Ray(flat.origin, flat.direction, math.nextafter(flat.tmax, math.inf), ray.tmax)
        return False

    def normal_at(self, position: Float3) -> Float3:
        """The outward normal (x, 0, z) / r, normalised."""
        return normalize(Float3(position.x, 0.0, position.z))

    def hit_normal(self, position: Float3, direction: Float3) -> Float3:
        """The book's normal: outward, flipped when -d . n < 0 (the ray hits the inside)."""
        n = self.normal_at(position)
        if dot(direction, n) > 0.0:
            return -n
        return n

    def bounds(self):
        from ..accelerators.bbox import BBox
        return BBox(Float3(-self.radius, self.y0, -self.radius), Float3(self.radius, self.y1, self.radius))

    def texcoord(self, position: Float3) -> tuple:
        """Suffern's CylindricalMap (ch. 29): u = phi / (2 pi) about the axis, phi =
        atan2(x, z) in [0, 2 pi); v = (y - y0) / (y1 - y0)."""
        phi = math.atan2(position.x, position.z)
        if phi < 0.0:
            phi += 2.0 * math.pi
        return phi / (2.0 * math.pi), (position.y - self.y0) / (self.y1 - self.y0)

