"""Phong: a diffuse surface with a glossy highlight (Suffern ch. 15, "Specular Reflection";
02562 worksheet 3, "Phong").

A Matte (ambient and diffuse Lambertian BRDFs of colour cd) plus a GlossySpecular lobe of
colour ks cs and exponent exp, both reflecting the light of every light:

    L_o = ka cd L_a + sum over lights of (kd cd / pi + GlossySpecular.f) L_i (n . w_i).

The 02562 sphere's "rho_s = 0.1, s = 42" is ``Phong(cs=(0.1, 0.1, 0.1), exp=42)`` with ks = 1;
its lobe is the normalised one (GlossySpecular, rtfgu/brdfs/glossy_specular.py), and
``specular_brdf.normalized = False`` gives the book's.
"""
from __future__ import annotations

from ..brdfs.glossy_specular import GlossySpecular
from ..float3 import Float3
from ..validation import colour, number
from .material import PHONG, read_from, set_on
from .matte import KA_02562, KD_02562, Matte


class Phong(Matte):
    shader = PHONG
    # The book's setters of the glossy lobe; the flat layout's rho_s = ks cs and s.
    set_ks = set_on("specular_brdf", "set_ks", number, "ks")
    set_cs = set_on("specular_brdf", "set_cs", colour, "cs")
    specular = read_from("specular_brdf", "specular", "rho_s = ks cs, the flat layout's ``specular``")
    shininess = read_from("specular_brdf", "exp", "the lobe's exponent, the flat layout's ``shininess``")

    def __init__(self, ka: float = KA_02562, kd: float = KD_02562, cd=None, ks: float = 1.0,
                 cs=(1.0, 1.0, 1.0), exp: float = 1.0, emission=None):
        super().__init__(ka, kd, cd, emission)
        self.specular_brdf = GlossySpecular()
        self.set_ks(ks)
        self.set_cs(cs)
        self.set_exp(exp)

    def set_exp(self, exp: float) -> None:
        try:
            self.specular_brdf.set_exp(exp)
        except ValueError:
            raise ValueError("%s.exp must be finite and >= 0, got %r" % (type(self).__name__, exp)) from None

    def f(self, sr, wo, wi) -> Float3:
        """kd cd / pi plus the glossy lobe."""
        return self.diffuse_brdf.f(sr, wo, wi) + self.specular_brdf.f(sr, wo, wi)

    def reflects_light(self) -> bool:
        return self.diffuse_brdf.kd > 0.0 or self.specular_brdf.ks > 0.0

    def flat_limit(self, tracer):
        if not self.specular_brdf.normalized:
            return ("numba and WGSL compute the normalised (02562) Phong lobe; the book's lobe "
                    "(normalized = False) renders with backend='reference'")
        return super().flat_limit(tracer)

    def check_path_trace(self, where: str, color) -> None:
        raise ValueError("%s: PathTrace does not trace %s (its highlight is not sampled); use a "
                         "GlossyReflector" % (where, type(self).__name__))

    def __repr__(self) -> str:
        return "%s(ka=%r, kd=%r, cd=%r, ks=%r, cs=%r, exp=%r)" % (
            type(self).__name__, self.ka, self.kd, self.cd, self.specular_brdf.ks, self.specular_brdf.cs,
            self.specular_brdf.exp)
