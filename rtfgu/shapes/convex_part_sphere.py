"""ConvexPartSphere: the part of the sphere about ``center`` of ``radius`` between the
azimuths phi_min and phi_max and the polar angles theta_min and theta_max, in degrees (Suffern
ch. 19, "Part objects", and rtfgu.shapes.part for the angles).

The book's ``ConvexPartSphere::hit`` is the sphere's quadratic with an angle test on each
root: the near root counts when its point p - c has

    r cos(theta_max) <= y <= r cos(theta_min)  and  phi_min <= atan2(x, z) <= phi_max,

else the far root under the same test, so that a ray through a gap sees the inside of the
far side. Here the sphere is asked for the near root (``Sphere.intersect_p``, lecture 01),
then from just beyond it for the far one, as the OpenCylinder asks it: the part holds no
formula of its own. The rims belong to the part (the book's tests are <= and >=).

The normal is the sphere's, pointing out: a part seen from inside (a bowl) shows its back
face, which is what the ConcavePartSphere is for.
"""
from __future__ import annotations

import math

from ..float3 import Float3, as_float3
from ..ray import Ray
from .part import angle_range, azimuth
from .shape import Shape, positive
from .sphere import Sphere


class ConvexPartSphere(Shape):
    def __init__(self, center, radius: float, phi_min: float, phi_max: float, theta_min: float,
                 theta_max: float, color, material=None):
        super().__init__(color, material)
        name = type(self).__name__
        self.center = as_float3(center, name + ".center")
        self.radius = positive(radius, name + ".radius")
        # In radians, as the book keeps them; the polar range as its cosines.
        self.phi_min, self.phi_max = angle_range(phi_min, phi_max, 360.0, name + ".phi_min", name + ".phi_max")
        self.theta_min, self.theta_max = angle_range(theta_min, theta_max, 180.0, name + ".theta_min",
                                                     name + ".theta_max")
        self.cos_theta_min = math.cos(self.theta_min)
        self.cos_theta_max = math.cos(self.theta_max)
        self._sphere = Sphere(self.center, self.radius, color)

    def intersect_p(self, ray: Ray) -> bool:
        probe = Ray(ray.origin, ray.direction, ray.tmin, ray.tmax)
        for _ in range(2):   # the near root, then the far one
            if not self._sphere.intersect_p(probe):
                return False
            if self.holds(ray(probe.tmax) - self.center):
                ray.tmax = probe.tmax
                return True
            probe = Ray(ray.origin, ray.direction, math.nextafter(probe.tmax, math.inf), ray.tmax)
        return False

    def holds(self, hit: Float3) -> bool:
        """The book's angle test of a point of the sphere, hit = p - center."""
        return (self.radius * self.cos_theta_max <= hit.y <= self.radius * self.cos_theta_min
                and self.phi_min <= azimuth(hit) <= self.phi_max)

    def normal_at(self, position: Float3) -> Float3:
        """The sphere's outward normal."""
        return self._sphere.normal_at(position)

    def bounds(self):
        """The whole sphere's box (the book's ConvexPartSphere keeps it too)."""
        return self._sphere.bounds()

    def texcoord(self, position: Float3) -> tuple:
        """The whole sphere's SphericalMap (Sphere.texcoord)."""
        return self._sphere.texcoord(position)
