"""OpenCylinder: the side of the cylinder of ``radius`` about the y axis between the heights
``y0`` and ``y1``, without caps (Suffern ch. 19, "Open cylinders").

The book's ``OpenCylinder::hit``: the ray meets the infinite cylinder x^2 + z^2 = r^2 where

    a t^2 + b t + c = 0,  a = d_x^2 + d_z^2,  b = 2 (o_x d_x + o_z d_z),  c = o_x^2 + o_z^2 - r^2,

written as the sphere's quadratic (lecture 01), and a root counts when its height o_y + t d_y
lies within [y0, y1]: the near root first, then the far one, so that a ray sees the inside
through the open end. The rims belong to the cylinder (the book's test is y0 < y < y1; rtfgu's
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
from .shape import Shape, positive


class OpenCylinder(Shape):
    def __init__(self, y0: float, y1: float, radius: float, color, material=None):
        super().__init__(color, material)
        self.y0 = _height(y0, "OpenCylinder.y0")
        self.y1 = _height(y1, "OpenCylinder.y1")
        if not self.y0 < self.y1:
            raise ValueError("OpenCylinder.y0 must be below OpenCylinder.y1, got y0 = %r, y1 = %r"
                             % (self.y0, self.y1))
        self.radius = positive(radius, "OpenCylinder.radius")

    def intersect_p(self, ray: Ray) -> bool:
        o, d = ray.origin, ray.direction
        a = d.x * d.x + d.z * d.z
        if a == 0.0:
            return False  # parallel to the axis
        b = 2.0 * (o.x * d.x + o.z * d.z)
        c = o.x * o.x + o.z * o.z - self.radius * self.radius
        disc = b * b - 4.0 * a * c
        if disc < 0.0:
            return False
        e = math.sqrt(disc)
        denom = 2.0 * a
        # The near root, then the far one (the inside, seen through an open end).
        for t in ((-b - e) / denom, (-b + e) / denom):
            if t >= ray.tmin and t < ray.tmax:
                y_hit = o.y + t * d.y
                if y_hit >= self.y0 and y_hit <= self.y1:
                    ray.tmax = t
                    return True
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


def _height(value, name: str) -> float:
    """A finite height (of either sign)."""
    try:
        ok = not isinstance(value, bool) and math.isfinite(value)
    except TypeError:
        ok = False
    if not ok:
        raise ValueError("%s must be a finite number, got %r" % (name, value))
    return float(value)
