"""PerfectSpecular: a perfect mirror (Suffern ch. 24, "Mirror Reflection"; 02562 worksheet 3,
"mirror").

All light from w_i leaves along its mirror direction: sample_f returns w_i = -w_o +
2 (n . w_o) n, the only direction with light, and the reflectance kr cr. The book returns
f = kr cr / |n . w_i| with an implied pdf of 1, so that f (n . w_i) / pdf = kr cr; here the
cosine sits in the pdf instead (f = kr cr, pdf = |n . w_i|: the same ratio), because then
f (n . w_i) / pdf is kr cr exactly, with no rounding of a division undone by a product, and
a perfect mirror (kr cr = 1) passes the light it reflects on bit for bit, as the 02562
``mirror`` shader does.
"""
from __future__ import annotations

from ..float3 import Float3, dot
from ..validation import colour, number
from .brdf import BRDF


def reflect(n: Float3, wo: Float3) -> Float3:
    """The mirror direction of wo about n: -wo + 2 (n . wo) n."""
    # TODO a05: reflect
    #   Return the mirror direction -wo + 2 (n . wo) n.
    raise NotImplementedError('a05: reflect')


class PerfectSpecular(BRDF):
    def __init__(self, kr: float = 1.0, cr=(1.0, 1.0, 1.0)):
        self.set_kr(kr)
        self.set_cr(cr)

    def set_kr(self, kr: float) -> None:
        self.kr = number(kr, "PerfectSpecular.kr")

    def set_cr(self, cr) -> None:
        self.cr = colour(cr, "PerfectSpecular.cr")

    def sample_f(self, sr, wo, u: float = 0.0, v: float = 0.0) -> tuple:
        """(kr cr, w_i, |n . w_i|): the mirror direction; (u, v) are not needed."""
        w_i = reflect(sr.normal, wo)
        return self.rho(sr), w_i, abs(dot(sr.normal, w_i))

    def rho(self, sr, wo=None) -> Float3:
        return self.cr * self.kr
