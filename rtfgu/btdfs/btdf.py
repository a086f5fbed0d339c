"""BTDF: how a surface transmits light (Suffern ch. 27, "BTDFs").

``f(sr, wo, wi)`` is zero for a perfect transmitter (all its light goes one way);
``sample_f(sr, wo)`` returns (f, w_t, pdf), the transmitted direction and its weight, with
the cosine in the pdf as for PerfectSpecular (f (n . w_t) / pdf = kt exactly); ``tir(sr)``
says whether the ray of ``sr`` is totally internally reflected, so that nothing is
transmitted.
"""
from __future__ import annotations

from ..float3 import Float3


class BTDF:
    def f(self, sr, wo, wi) -> Float3:
        return Float3(0.0)

    def sample_f(self, sr, wo) -> tuple:
        raise NotImplementedError("%s has no sample_f" % type(self).__name__)

    def tir(self, sr) -> bool:
        return False

    def rho(self, sr, wo=None) -> Float3:
        return Float3(0.0)
