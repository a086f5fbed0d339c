"""AreaLight: a shape that emits light (Suffern ch. 18, "Area Lights"; 02562 worksheets 5 and 7).

An area light is one emitting shape, a triangle (``Triangle`` or a mesh's ``MeshTriangle``)
or a ``Sphere``, whose material's emission L_e is its radiance; the shape stays in
``Scene.shapes``, where rays see it. It emits from its front: for a triangle the side
(v1 - v0) x (v2 - v0) points to, for a sphere the outside.

Two ways to sample it, one per tracer:

* ``sample(pos)``, the ray-cast light loop (02562 worksheet 5): the light as a point light
  at the shape's centre. A triangle of area A sends I = L_e A cos(theta_l) toward pos,
  theta_l the angle between its normal and the way to pos; a sphere of radius r sends
  L_e pi r^2 in every direction, and the shadow ray stops at its surface
  (dist = ||c - pos|| - r).
* ``sample_area(pos, normal, u, v)``, ``PathTrace``'s direct light (Suffern's
  ``AreaLight::get_direction`` and ``G / pdf``): a point p' of the shape, uniform by area
  (pdf 1 / A), turned from area to solid angle by the geometry term:

      L_i = L_e cos(theta_l) / ||p' - pos||^2 / pdf = L_e A cos(theta_l) / ||p' - pos||^2,

  zero where p' is seen from behind (cos(theta_l) <= 0).

The layout row (rtfgu.registry): [v0, radius], [e0, 0], [e1, 0], [emission, 0]; a sphere's
v0 is its centre and its radius > 0, a triangle's radius is 0.
"""
from __future__ import annotations

import math

from .float3 import Float3, cross, dot, normalize
from .lights import Light, PointLight, sample_point_light


class AreaLight:
    def __init__(self, shape):
        from .shapes.mesh import MeshTriangle
        from .shapes.sphere import Sphere
        from .shapes.triangle import Triangle

        if isinstance(shape, Sphere):
            self.v0, self.radius = shape.center, shape.radius
            self.e0 = self.e1 = Float3(0.0)
            self.area = 4.0 * math.pi * shape.radius * shape.radius
        elif isinstance(shape, (Triangle, MeshTriangle)):
            triangle = shape if isinstance(shape, Triangle) else shape.triangle
            self.v0, self.e0, self.e1, self.radius = triangle.v0, triangle.e0, triangle.e1, 0.0
            self.area = 0.5 * cross(self.e0, self.e1).length()
        else:
            raise ValueError("AreaLight.shape must be a Triangle, a mesh triangle or a Sphere, got %s"
                             % type(shape).__name__)
        emission = shape.material.emission
        if max(emission.x, emission.y, emission.z) <= 0.0:
            raise ValueError("AreaLight.shape: its material emits nothing (material.emission is %r); "
                             "give it Emissive(ls, ce) or an emission > 0" % (emission,))
        self.shape = shape
        self.emission = emission

    @property
    def is_sphere(self) -> bool:
        return self.radius > 0.0

    def sample(self, pos: Float3) -> Light:
        """The ray-cast light loop's sample: the light as a point light at the shape's centre
        (Kepler's law, sample_point_light) with the intensity it sends toward ``pos``."""
        if self.is_sphere:
            light = sample_point_light(PointLight(self.v0, self.emission * (math.pi * self.radius * self.radius)), pos)
            return Light(light.L_i, light.w_i, light.dist - self.radius)
        center = self.v0 + (self.e0 + self.e1) / 3.0
        light = sample_point_light(PointLight(center, self.emission * self.area), pos)
        cos_l = max(-dot(normalize(cross(self.e0, self.e1)), light.w_i), 0.0)
        return Light(light.L_i * cos_l, light.w_i, light.dist)

    def sample_point(self, u: float, v: float) -> tuple:
        """(p', n'): a point of the shape, uniform by area for (u, v) uniform in [0, 1)^2, and
        the shape's unit normal there. A triangle's point has the barycentric coordinates
        (1 - sqrt(u), v sqrt(u), (1 - v) sqrt(u)) (Shirley, "Graphics Gems III"); a sphere's
        is the direction with z = 1 - 2u and phi = 2 pi v (Archimedes: uniform in z)."""
        if self.is_sphere:
            z = 1.0 - 2.0 * u
            s = math.sqrt(max(0.0, 1.0 - z * z))
            phi = 2.0 * math.pi * v
            normal = Float3(s * math.cos(phi), s * math.sin(phi), z)
            return self.v0 + normal * self.radius, normal
        su = math.sqrt(u)
        point = self.v0 + (self.e0 * v + self.e1 * (1.0 - v)) * su
        return point, normalize(cross(self.e0, self.e1))

    def sample_area(self, pos: Float3, normal: Float3, u: float, v: float) -> Light:
        """PathTrace's sample: L_i = L_e A cos(theta_l) / ||p' - pos||^2 toward the point
        p' = sample_point(u, v), zero from behind (``normal``, the receiving surface's, is
        not needed here)."""
        point, n_l = self.sample_point(u, v)
        to_light = point - pos
        dist = to_light.length()
        if not dist > 0.0:                   # the point lit is the point drawn: no direction
            return Light(Float3(0.0), n_l, 0.0)
        w_i = to_light / dist
        cos_l = -dot(n_l, w_i)
        if not cos_l > 0.0:
            return Light(Float3(0.0), w_i, dist)
        return Light(self.emission * (self.area * cos_l / (dist * dist)), w_i, dist)

    def __repr__(self) -> str:
        return "AreaLight(%r)" % (self.shape,)
