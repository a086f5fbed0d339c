# release: solves a05
"""FresnelReflector: the mirror reflection of a dielectric, weighted by Fresnel's reflectance
(Suffern ch. 28, "Realistic Transparency"; 02562 worksheet 8, "Fresnel").

With the relative index eta = n1 / n2 (the side the light comes from over the other) and
cos_t = sqrt(1 - eta^2 (1 - cos_i^2)), for unpolarised light

    r_perp = (eta cos_i - cos_t) / (eta cos_i + cos_t)
    r_par  = (cos_i - eta cos_t) / (cos_i + eta cos_t)
    R      = (r_perp^2 + r_par^2) / 2,      1 under total internal reflection,

and the transmitted fraction is 1 - R (rtfgu.btdfs.FresnelTransmitter). ``ior`` is the
index inside over the index outside (the book's eta_in / eta_out); the side is that of the
normal: a ray with d . n < 0 arrives from outside.
"""
from __future__ import annotations

import math

from ..float3 import Float3, dot
from ..validation import positive
from .brdf import BRDF
from .perfect_specular import reflect


def fresnel_reflectance(cos_i: float, eta: float) -> float:
    """R for unpolarised light arriving at cos_i (> 0) with relative index eta = n1 / n2."""
    # TODO a11: fresnel_reflectance
    #   Fresnel's reflectance for unpolarised light (Suffern ch. 28; 02562 worksheet 8), arriving at
    #   cos_i > 0 with relative index eta = n1 / n2 (the side the light comes from over the other):
    #   sin^2(theta_t) = eta^2 (1 - cos_i^2); at or beyond 1 the light is totally reflected, return 1.
    #   Else cos_t = sqrt(1 - sin^2(theta_t)), r_perp = (eta cos_i - cos_t) / (eta cos_i + cos_t),
    #   r_par = (cos_i - eta cos_t) / (cos_i + eta cos_t); return the mean of r_perp^2 and r_par^2.
    raise NotImplementedError('a11: fresnel_reflectance')


def incidence(d: Float3, n: Float3, ior: float) -> tuple:
    """(cos_i, eta, n') for a ray along d meeting a surface of normal n: entering (d . n < 0
    or 0) eta = 1 / ior, leaving eta = ior with the normal turned to the ray's side."""
    cos_i = -dot(d, n)
    if cos_i >= 0.0:
        return cos_i, 1.0 / ior, n
    return -cos_i, ior, -n


class Interface:
    """What a Fresnel BRDF and BTDF share: the interface's index of refraction ``ior``
    (inside over outside)."""

    def __init__(self, ior: float = 1.5):
        self.set_ior(ior)

    def set_ior(self, ior: float) -> None:
        self.ior = positive(ior, type(self).__name__ + ".ior")


class FresnelReflector(Interface, BRDF):
    def reflectance(self, sr) -> float:
        """Fresnel's R for the ray of ``sr`` at its hit."""
        cos_i, eta, _ = incidence(sr.ray.direction, sr.normal, self.ior)
        return fresnel_reflectance(cos_i, eta)

    def sample_f(self, sr, wo, u: float = 0.0, v: float = 0.0) -> tuple:
        """(R, w_i, |n . w_i|): the mirror direction with the reflectance R (the cosine in
        the pdf, as PerfectSpecular)."""
        w_i = reflect(sr.normal, wo)
        return Float3(self.reflectance(sr)), w_i, abs(dot(sr.normal, w_i))
