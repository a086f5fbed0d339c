# release: solves a05
"""Dielectric: glass and water, with Fresnel's reflection and Bouguer's absorption (Suffern
ch. 28, "Realistic Transparency"; 02562 worksheet 8, "Fresnel, Russian roulette and
Bouguer's law").

A FresnelReflector and a FresnelTransmitter (rtfgu/brdfs/fresnel_reflector.py,
rtfgu/btdfs/fresnel_transmitter.py) of index ``ior`` (inside over outside): light meeting
the surface is reflected with Fresnel's reflectance R and refracted with 1 - R. Inside, it
is absorbed by Bouguer's (Beer-Lambert) law: over a distance s through the medium it keeps
exp(-sigma_a s) of its radiance, sigma_a the ``absorption`` per unit length (per channel;
the book's ``cf_in`` filter colour is exp(-sigma_a)). A ray is inside when it meets the
surface from behind (its normal points the same way as the ray); nested media are not
modelled.

* ``shade`` (Whitted): both rays, R L(w_r) + (1 - R) L(w_t), each ray that runs inside
  attenuated over its length (one ray under total internal reflection);
* ``path_shade`` (PathTrace): one ray, reflected with probability R and refracted otherwise
  (Russian roulette on R: the throughput is unchanged, since R / R = (1 - R) / (1 - R) = 1),
  the throughput attenuated where the ray met the surface from inside.
"""
from __future__ import annotations

import math

from ..brdfs.fresnel_reflector import FresnelReflector, fresnel_reflectance, incidence
from ..brdfs.perfect_specular import reflect
from ..btdfs.fresnel_transmitter import FresnelTransmitter
from ..float3 import Float3, dot
from ..ray import SPAWN_EPSILON, Ray
from ..sampling.random import CHOICE, path_dimension, random_float
from ..validation import colour, positive
from .material import DIELECTRIC, PathVertex
from .phong import Phong


def transmittance(absorption: Float3, distance: float) -> Float3:
    """Bouguer's law: exp(-sigma_a s) per channel."""
    ### BEGIN SOLUTION
    return Float3(math.exp(-absorption.x * distance), math.exp(-absorption.y * distance),
                  math.exp(-absorption.z * distance))
    ### END SOLUTION


class Dielectric(Phong):
    shader = DIELECTRIC

    def __init__(self, ior: float = 1.5, absorption=(0.0, 0.0, 0.0), ka: float = 0.0, kd: float = 0.0,
                 cd=None, ks: float = 0.0, cs=(1.0, 1.0, 1.0), exp: float = 1.0):
        super().__init__(ka, kd, cd, ks, cs, exp)
        self.fresnel_brdf = FresnelReflector()
        self.fresnel_btdf = FresnelTransmitter()
        self.set_ior(ior)
        self.absorption = colour(absorption, "Dielectric.absorption")

    def set_ior(self, ior: float) -> None:
        ior = positive(ior, "Dielectric.ior")
        self.fresnel_brdf.set_ior(ior)
        self.fresnel_btdf.set_ior(ior)

    def set_absorption(self, absorption) -> None:
        self.absorption = colour(absorption, "Dielectric.absorption")

    @property
    def ior(self) -> float:
        return self.fresnel_brdf.ior

    def flat_limit(self, tracer):
        from ..tracers.path_trace import PathTrace

        if not isinstance(tracer, PathTrace):
            return ("numba and WGSL follow one ray per vertex: a Dielectric sends two under the ray-cast "
                    "tracers; render it with PathTrace, or with backend='reference'")
        return super().flat_limit(tracer)

    def _through(self, ray: Ray, L: Float3, normal: Float3) -> Float3:
        """L arriving along ``ray`` (traced: its tmax is where it hit) from where it hit,
        attenuated if it ran inside (against the outward ``normal``)."""
        if dot(ray.direction, normal) < 0.0 and math.isfinite(ray.tmax):
            return L * transmittance(self.absorption, ray.tmax)
        return L

    def shade(self, sr) -> Float3:
        ### BEGIN SOLUTION
        wo = -sr.ray.direction
        L = super().shade(sr)           # the Phong part (none by default)
        tracer = sr.scene.tracer
        fr, wi, _ = self.fresnel_brdf.sample_f(sr, wo)
        reflected = Ray(sr.position, wi, SPAWN_EPSILON)
        L_r = self._through(reflected, tracer.trace_ray(reflected, sr.depth + 1), sr.normal)
        if self.fresnel_btdf.tir(sr):
            return L + L_r
        ft, wt, _ = self.fresnel_btdf.sample_f(sr, wo)
        transmitted = Ray(sr.position, wt, SPAWN_EPSILON)
        L_t = self._through(transmitted, tracer.trace_ray(transmitted, sr.depth + 1), sr.normal)
        return L + fr * L_r + ft * L_t
        ### END SOLUTION

    def path_shade(self, sr) -> PathVertex:
        d, n = sr.ray.direction, sr.normal
        f = transmittance(self.absorption, sr.dist) if dot(n, d) > 0.0 else None
        xi = random_float(sr.pixel, sr.sample, path_dimension(sr.depth, CHOICE), sr.seed)
        cos_i, eta, _ = incidence(d, n, self.ior)
        if xi < fresnel_reflectance(cos_i, eta):
            w = reflect(n, -d)
        else:
            w = self.fresnel_btdf.transmitted_direction(d, n)
        return PathVertex(None, f, 1.0, Ray(sr.position, w, SPAWN_EPSILON), sees_emission=True)

    def check_path_trace(self, where: str, color) -> None:
        if self.reflects_light() or self.ka > 0.0:
            raise ValueError("%s: PathTrace traces a Dielectric without a Phong part (ka = kd = ks = 0)" % where)

    def __repr__(self) -> str:
        return "Dielectric(ior=%r, absorption=%r)" % (self.ior, self.absorption)
