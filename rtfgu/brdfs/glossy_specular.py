"""GlossySpecular: the glossy lobe about the mirror direction (Suffern ch. 15, "Specular
Highlights"; ch. 25, "Glossy Reflection"; 02562 worksheet 3, "Phong").

With w_r = 2 (n . w_i) n - w_i, the direction into which a mirror would send light from w_i,
the lobe is

    02562 (normalised, the default):  f_r = ks cs (e + 2) / (2 pi) max(w_o . w_r, 0)^e
    Suffern (``normalized = False``): f_r = ks cs max(w_o . w_r, 0)^e

The 02562 lobe keeps its reflected energy as the exponent e grows (a sharper highlight is a
brighter one); the book's is the classic Phong term, whose highlight dims as it narrows. The
default scene and every 02562 image use the normalised lobe; docs/suffern.md says which
scene uses which. ``sample_f`` draws w_i about the mirror direction of w_o with density
(e + 1) / (2 pi) cos^e(alpha) (Suffern's GlossySpecular::sample_f, ch. 25).
"""
from __future__ import annotations

import math

from ..float3 import Float3, dot
from ..sampling.maps import about, hemisphere_map
from ..validation import colour, number
from .brdf import BRDF
from .perfect_specular import reflect


class GlossySpecular(BRDF):
    def __init__(self, ks: float = 1.0, cs=(1.0, 1.0, 1.0), exp: float = 1.0, normalized: bool = True):
        self.set_ks(ks)
        self.set_cs(cs)
        self.set_exp(exp)
        self.normalized = bool(normalized)

    def set_ks(self, ks: float) -> None:
        self.ks = number(ks, "GlossySpecular.ks")

    def set_cs(self, cs) -> None:
        self.cs = colour(cs, "GlossySpecular.cs")

    def set_exp(self, exp: float) -> None:
        self.exp = number(exp, "GlossySpecular.exp")

    @property
    def specular(self) -> Float3:
        """rho_s = ks cs, the lobe's colour."""
        return self.cs * self.ks

    def f(self, sr, wo, wi) -> Float3:
        """The lobe toward wo of light from wi (both unit, away from the surface)."""
        ### BEGIN SOLUTION
        cos_i = dot(sr.normal, wi)
        w_r = sr.normal * (2.0 * cos_i) - wi
        cos_r = max(dot(wo, w_r), 0.0)
        if self.normalized:
            return self.cs * self.ks * ((self.exp + 2.0) / (2.0 * math.pi) * cos_r ** self.exp)
        return self.cs * self.ks * cos_r ** self.exp
        ### END SOLUTION

    def sample_f(self, sr, wo, u: float, v: float) -> tuple:
        """(f, w_i, pdf): w_i about the mirror direction of wo with density
        (e + 1) / (2 pi) cos^e(alpha), alpha its angle to that direction."""
        w_r = reflect(sr.normal, wo)
        w_i = about(w_r, hemisphere_map(u, v, self.exp))
        cos_alpha = max(dot(w_r, w_i), 0.0)
        pdf = (self.exp + 1.0) / (2.0 * math.pi) * cos_alpha ** self.exp
        f = self.f(sr, wo, w_i)
        return f, w_i, pdf

    def rho(self, sr, wo=None) -> Float3:
        """The lobe's albedo where it lies wholly above the surface: ks cs (e + 2) / (e + 1)
        times the mean cosine, bounded by ks cs (e + 2) / (e + 1); used to bound energy."""
        return self.specular
