# release: solves a05
"""Fresnel's reflection and Bouguer's absorption of a ``Dielectric`` (rtfgu.material; Suffern
ch. 28, "Realistic Transparency"; 02562 worksheet 8, "Fresnel, Russian roulette and
Bouguer's law").

A ray that meets the surface is reflected with probability R, Fresnel's reflectance for
unpolarised light, and refracted otherwise (Russian roulette on R: the throughput is
unchanged, since R / R = (1 - R) / (1 - R) = 1). With the relative index eta = n1 / n2 and
cos_t = sqrt(1 - eta^2 (1 - cos_i^2)):

    r_perp = (eta cos_i - cos_t) / (eta cos_i + cos_t)
    r_par  = (cos_i - eta cos_t) / (cos_i + eta cos_t)
    R      = (r_perp^2 + r_par^2) / 2,      1 under total internal reflection.

Inside, light is absorbed by Bouguer's (Beer-Lambert) law: a ray that has travelled a
distance s through the medium keeps exp(-sigma_a s) of its radiance, sigma_a the
material's ``absorption`` per unit length (per colour channel). A ray is taken to have
been inside when it meets the surface from behind (its normal points the same way as
the ray); nested media are not modelled.

``PathTrace`` follows this; the ray-cast loop, which draws no random numbers, refracts as
``transparent`` does.
"""
from __future__ import annotations

import math

from .float3 import Float3, dot


def fresnel_reflectance(cos_i: float, eta: float) -> float:
    """R for unpolarised light arriving at cos_i (> 0) with relative index eta = n1 / n2."""
    sin2_t = eta * eta * (1.0 - cos_i * cos_i)
    if sin2_t >= 1.0:
        return 1.0
    cos_t = math.sqrt(1.0 - sin2_t)
    r_perp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t)
    r_par = (cos_i - eta * cos_t) / (cos_i + eta * cos_t)
    return 0.5 * (r_perp * r_perp + r_par * r_par)


def transmittance(absorption: Float3, distance: float) -> Float3:
    """Bouguer's law: exp(-sigma_a s) per channel."""
    return Float3(math.exp(-absorption.x * distance), math.exp(-absorption.y * distance),
                  math.exp(-absorption.z * distance))


def scatter(direction: Float3, normal: Float3, ior: float, xi: float) -> Float3:
    """The next direction: reflected if xi < R, refracted otherwise (xi uniform in [0, 1))."""
    cos_i = -dot(direction, normal)
    if cos_i >= 0.0:
        eta = 1.0 / ior
        n = normal
    else:
        eta = ior
        n = -normal
        cos_i = -cos_i
    if xi < fresnel_reflectance(cos_i, eta):
        return direction + n * (2.0 * cos_i)
    cos_t = math.sqrt(1.0 - eta * eta * (1.0 - cos_i * cos_i))
    return direction * eta + n * (eta * cos_i - cos_t)

