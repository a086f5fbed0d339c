"""AreaLight: a shape that emits light (Suffern ch. 18, "Area Lights"; 02562 worksheets 5 and 7).

An area light is one emitting shape that offers the book's ``sample(u, v)``, ``pdf`` and
``get_normal`` (a ``Triangle``, a mesh's ``MeshTriangle``, a ``Rectangle`` or a ``Sphere``),
whose material's emission L_e is its radiance; the shape stays in ``Scene.shapes``, where rays
see it. It emits from its front: for a triangle the side (v1 - v0) x (v2 - v0) points to, for
a rectangle the side a x b points to (Suffern ch. 18.6), for a sphere the outside.

How it is asked depends on the tracer (``Tracer.samples_area_lights``):

* A tracer that samples area lights (AreaLighting, PathTrace, GlobalTrace) gets the book's
  light: ``get_direction`` draws a point p' of the shape uniformly by area (its sampler's
  point, ``set_sampler``, or the random stream's), ``L`` is L_e where p' is seen from the
  front, ``G = cos(theta_l) / |p' - x|^2`` and ``pdf = 1 / A``, so that

      L G / pdf = L_e A cos(theta_l) / |p' - x|^2.

* The ray-cast tracers (RayCast, Whitted) get 02562 worksheet 5's approximation: the light as
  a point light at the shape's centre. A triangle or a rectangle of area A sends
  I = L_e A cos(theta_l) toward x, theta_l the angle between its normal and the way to x
  (the centre of a triangle is v0 + (e0 + e1) / 3, of a rectangle p0 + (a + b) / 2); a sphere of radius r sends
  L_e pi r^2 every way, and the shadow ray stops at its surface (distance |c - x| - r).

Like the book's, the light keeps the point it drew last (``sample_point``, ``light_normal``)
for the ``L``, ``G`` and ``pdf`` that follow ``get_direction``.

The layout row (rtfgu.registry): [v0, radius], [e0, rectangle], [e1, 0], [emission, 0]; a
sphere's v0 is its centre and its radius > 0, a triangle's and a rectangle's radius is 0; a
rectangle's v0, e0, e1 are its p0, a, b and ``rectangle`` is 1 (0 for the others).
"""
from __future__ import annotations

import math

from ..float3 import Float3, cross, dot, normalize
from .light import Light
from .point_light import PointLight


class AreaLight(Light):
    def __init__(self, shape):
        from ..shapes.mesh import MeshTriangle
        from ..shapes.rectangle import Rectangle
        from ..shapes.sphere import Sphere
        from ..shapes.triangle import Triangle

        self.rectangle = 0.0
        if isinstance(shape, Sphere):
            self.v0, self.radius = shape.center, shape.radius
            self.e0 = self.e1 = Float3(0.0)
            self.geometry = shape
        elif isinstance(shape, (Triangle, MeshTriangle)):
            triangle = shape if isinstance(shape, Triangle) else shape.triangle
            self.v0, self.e0, self.e1, self.radius = triangle.v0, triangle.e0, triangle.e1, 0.0
            self.geometry = triangle
        elif isinstance(shape, Rectangle):
            self.v0, self.e0, self.e1, self.radius = shape.p0, shape.a, shape.b, 0.0
            self.rectangle = 1.0
            self.geometry = shape
        else:
            raise ValueError("AreaLight.shape must be a Triangle, a mesh triangle, a Rectangle or a Sphere, got %s"
                             % type(shape).__name__)
        self.area = self.geometry.area
        emission = shape.material.emission
        if max(emission.x, emission.y, emission.z) <= 0.0:
            raise ValueError("AreaLight.shape: its material emits nothing (its emission is %r); "
                             "give it Emissive(ls, ce)" % (emission,))
        self.shape = shape
        self.emission = emission
        self.sample_point, self.light_normal = self.v0, Float3(0.0, 0.0, 1.0)

    @property
    def is_sphere(self) -> bool:
        return self.radius > 0.0

    @staticmethod
    def _sampled(sr) -> bool:
        tracer = sr.scene.tracer if sr.scene is not None else None
        return bool(getattr(tracer, "samples_area_lights", False))

    def _centre(self) -> PointLight:
        """Worksheet 5's point light: at the centre, with the intensity toward the front."""
        if self.is_sphere:
            return PointLight(self.v0, self.emission * (math.pi * self.radius * self.radius))
        if self.rectangle:
            return PointLight(self.v0 + (self.e0 + self.e1) * 0.5, self.emission * self.area)
        return PointLight(self.v0 + (self.e0 + self.e1) / 3.0, self.emission * self.area)

    def get_direction(self, sr) -> Float3:
        if not self._sampled(sr):
            return self._centre().get_direction(sr)
        u, v = sr.scene.light_sample(self, sr)       # the point of the unit square this sample draws
        # TODO a12: AreaLight.get_direction
        #   Suffern's AreaLight::get_direction: with (u, v) the point of the unit square drawn (given), keep
        #   the shape's point there and its unit normal, (self.sample_point, self.light_normal) =
        #   self.geometry.sample_with_normal(u, v), and return the unit vector from sr.position toward
        #   the point (the point's normal if the point lit is the point drawn, at distance 0).
        raise NotImplementedError('a12: AreaLight.get_direction')

    def _cos_l(self, sr) -> float:
        to_light = self.sample_point - sr.position
        dist = to_light.length()
        if not dist > 0.0:
            return 0.0
        return -dot(self.light_normal, to_light / dist)

    def L(self, sr) -> Float3:
        if not self._sampled(sr):
            centre = self._centre()
            L_i = centre.L(sr)
            if self.is_sphere:
                return L_i
            return L_i * max(-dot(normalize(cross(self.e0, self.e1)), centre.get_direction(sr)), 0.0)
        return self.emission if self._cos_l(sr) > 0.0 else Float3(0.0)

    def G(self, sr) -> float:
        if not self._sampled(sr):
            return 1.0
        # TODO a12: AreaLight.G
        #   The geometry factor (Suffern ch. 18, AreaLight::G): cos(theta_l) / d^2, with d the distance from
        #   sr.position to self.sample_point and cos(theta_l) = -n_l . w_i (self._cos_l(sr)) the cosine at
        #   the light; 0 where the light is seen from behind (cos(theta_l) <= 0) or at d = 0.
        raise NotImplementedError('a12: AreaLight.G')

    def pdf(self, sr) -> float:
        if not self._sampled(sr):
            return 1.0
        # TODO a12: AreaLight.pdf
        #   The density of the point drawn, per unit area of the shape (Suffern ch. 18, AreaLight::pdf):
        #   a point uniform by area has the density 1 / A (self.area).
        raise NotImplementedError('a12: AreaLight.pdf')

    def incident(self, sr) -> Float3:
        """L G / pdf = L_e A cos(theta_l) / |p' - x|^2 (0 from behind), in the order the
        numba and WGSL kernels compute it."""
        if not self._sampled(sr):
            return self.L(sr)
        # TODO a12: AreaLight.incident
        #   L G / pdf in the order the numba and WGSL paths compute it: with to_light = sample_point -
        #   sr.position, dist its length and cos_l = -n_l . to_light / dist, return
        #   emission * (area * cos_l / (dist * dist)); Float3(0) where dist is not > 0 or cos_l is not > 0.
        raise NotImplementedError('a12: AreaLight.incident')

    def distance(self, sr) -> float:
        if not self._sampled(sr):
            dist = self._centre().distance(sr)
            return dist - self.radius if self.is_sphere else dist
        return (self.sample_point - sr.position).length()

    def __repr__(self) -> str:
        return "AreaLight(%r)" % (self.shape,)
