# release: solves a05
"""FresnelTransmitter: the refraction of a dielectric, weighted by 1 - R, Fresnel's
transmittance (Suffern ch. 28, "Realistic Transparency"; 02562 worksheet 8). R is the
FresnelReflector's (rtfgu.brdfs.fresnel_reflector); the direction is Snell's
(PerfectTransmitter.transmitted_direction)."""
from __future__ import annotations

from ..float3 import Float3, dot
from ..brdfs.fresnel_reflector import Interface, fresnel_reflectance, incidence
from .btdf import BTDF
from .perfect_transmitter import PerfectTransmitter


class FresnelTransmitter(Interface, BTDF):
    def tir(self, sr) -> bool:
        cos_i, eta, _ = incidence(sr.ray.direction, sr.normal, self.ior)
        return eta * eta * (1.0 - cos_i * cos_i) >= 1.0

    def transmitted_direction(self, d: Float3, n: Float3) -> Float3:
        """Snell's direction (PerfectTransmitter.transmitted_direction)."""
        return PerfectTransmitter(1.0, self.ior).transmitted_direction(d, n)

    def sample_f(self, sr, wo=None) -> tuple:
        """(1 - R, w_t, |n . w_t|)."""
        cos_i, eta, _ = incidence(sr.ray.direction, sr.normal, self.ior)
        w_t = self.transmitted_direction(sr.ray.direction, sr.normal)
        return Float3(1.0 - fresnel_reflectance(cos_i, eta)), w_t, abs(dot(sr.normal, w_t))
