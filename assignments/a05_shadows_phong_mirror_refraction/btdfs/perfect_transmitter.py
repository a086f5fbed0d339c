"""PerfectTransmitter: refraction by Snell's law (Suffern ch. 27, "Perfect Transmission";
02562 worksheet 3, "transparent").

With the relative index eta = n1 / n2 and the ray arriving along d at cos_i = |d . n|:

    sin^2(theta_t) = eta^2 (1 - cos_i^2),   cos_t = sqrt(1 - sin^2(theta_t)),
    w_t = eta d + (eta cos_i - cos_t) n',

n' the normal on the ray's side; sin^2(theta_t) > 1 is total internal reflection (``tir``).
Entering (d . n < 0, or 0) eta = 1 / ior; leaving eta = ior and the normal turns.
The book's ``sample_f`` also divides by eta^2, radiance compressed into a narrower cone on
entering; the 02562 slides do not, and neither does rtfgu (docs/suffern.md): a ray that
enters and leaves a body carries the same radiance either way.
"""
from __future__ import annotations

import math

from ..float3 import Float3, dot
from ..validation import number, positive
from .btdf import BTDF


class PerfectTransmitter(BTDF):
    def __init__(self, kt: float = 1.0, ior: float = 1.0):
        self.set_kt(kt)
        self.set_ior(ior)

    def set_kt(self, kt: float) -> None:
        self.kt = number(kt, "PerfectTransmitter.kt")

    def set_ior(self, ior: float) -> None:
        self.ior = positive(ior, "PerfectTransmitter.ior")

    def tir(self, sr) -> bool:
        """Total internal reflection: no real cos_t."""
        d = sr.ray.direction
        cos_i = -dot(d, sr.normal)
        eta = 1.0 / self.ior if cos_i >= 0.0 else self.ior
        return eta * eta * (1.0 - cos_i * cos_i) > 1.0

    def sample_f(self, sr, wo=None) -> tuple:
        """(kt, w_t, |n . w_t|) for a ray that is not totally internally reflected."""
        w_t = self.transmitted_direction(sr.ray.direction, sr.normal)
        return Float3(self.kt), w_t, abs(dot(sr.normal, w_t))

    def transmitted_direction(self, d: Float3, n: Float3) -> Float3:
        """w_t by Snell's law for a ray along d at a surface of normal n; the mirror
        direction under total internal reflection."""
        # TODO a05: PerfectTransmitter.transmitted_direction
        #   cos_i = -(d . n). Entering (cos_i >= 0): eta = 1 / ior. Leaving: eta = ior, flip n and cos_i.
        #   sin2_t = eta^2 (1 - cos_i^2); if sin2_t > 1 return the mirror direction d + n (2 cos_i) (total
        #   internal reflection), else d * eta + n * (eta cos_i - sqrt(1 - sin2_t)).
        raise NotImplementedError('a05: PerfectTransmitter.transmitted_direction')
