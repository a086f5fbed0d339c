"""Transparent: Phong plus perfect mirror reflection and perfect transmission (Suffern ch. 27,
"Simple Transparency"; 02562 worksheet 3, "transparent" and "glossy").

    L_o = Phong's L_o + kr L(w_r) + kt L(w_t)       (one ray: L(w_r) under total internal
                                                     reflection, with no kr)

with w_t by Snell's law (PerfectTransmitter) and both rays traced one level deeper. The
defaults are the 02562 ``transparent`` shader: nothing but the refracted ray (ka = kd = ks =
kr = 0, kt = 1); with a Phong part it is the 02562 ``glossy`` shader (Phong at the surface,
then refraction). A Transparent that also reflects (kr > 0) sends two rays; the numba and
WGSL paths follow the second one from a stack of rays (rtfgu.kernels.render.trace, main.wgsl).
"""
from __future__ import annotations

from ..btdfs.perfect_transmitter import PerfectTransmitter
from ..float3 import Float3, dot
from ..ray import SPAWN_EPSILON, Ray
from ..validation import number, positive
from .material import GLOSSY, TRANSPARENT, PathVertex, read_from, set_on
from .phong import Phong
from .reflective import Reflective, specular_scale


class Transparent(Reflective):
    # The book's setters of the transmitter; kt and ior are the flat layout's fields.
    set_kt = set_on("specular_btdf", "set_kt", number, "kt")
    set_ior = set_on("specular_btdf", "set_ior", positive, "ior")
    kt = read_from("specular_btdf", "kt", "kt, the weight of the transmitted ray")
    ior = read_from("specular_btdf", "ior", "the index of refraction inside the surface")

    def __init__(self, ior: float = 1.0, kt: float = 1.0, kr: float = 0.0, ka: float = 0.0, kd: float = 0.0,
                 cd=None, ks: float = 0.0, cs=(1.0, 1.0, 1.0), exp: float = 1.0, emission=None):
        super().__init__(kr, (1.0, 1.0, 1.0), ka, kd, cd, ks, cs, exp, emission)
        self.specular_btdf = PerfectTransmitter()
        self.set_kt(kt)
        self.set_ior(ior)

    @property
    def is_02562(self) -> bool:
        """One ray: refraction with kt = 1 and no reflection (the 02562 transparent or glossy)."""
        return self.reflective_brdf.kr == 0.0 and self.specular_btdf.kt == 1.0

    @property
    def shader(self) -> int:
        return GLOSSY if self.reflects_light() or self.ka > 0.0 else TRANSPARENT

    def shade(self, sr) -> Float3:
        wo = -sr.ray.direction
        L = Phong.shade(self, sr)
        tracer = sr.scene.tracer
        fr, wi, pdf_r = self.reflective_brdf.sample_f(sr, wo)
        if self.specular_btdf.tir(sr):
            return L + tracer.trace_ray(Ray(sr.position, wi, SPAWN_EPSILON), sr.depth + 1)
        if self.reflective_brdf.kr > 0.0:
            L_r = tracer.trace_ray(Ray(sr.position, wi, SPAWN_EPSILON), sr.depth + 1)
            L = L + fr * L_r * specular_scale(abs(dot(sr.normal, wi)), pdf_r)
        ft, wt, pdf_t = self.specular_btdf.sample_f(sr, wo)
        L_t = tracer.trace_ray(Ray(sr.position, wt, SPAWN_EPSILON), sr.depth + 1)
        return L + ft * L_t * specular_scale(abs(dot(sr.normal, wt)), pdf_t)

    def path_shade(self, sr) -> PathVertex:
        """The 02562 transparent shader in a path: it goes on along the refracted ray (the
        mirrored one under total internal reflection)."""
        wt = self.specular_btdf.transmitted_direction(sr.ray.direction, sr.normal)
        return PathVertex(None, ray=Ray(sr.position, wt, SPAWN_EPSILON), sees_emission=True)

    def check_path_trace(self, where: str, color) -> None:
        if not self.is_02562 or self.reflects_light() or self.ka > 0.0:
            raise ValueError("%s: PathTrace traces a Transparent as pure refraction only (ka = kd = ks = kr = 0, "
                             "kt = 1); use a Dielectric for glass" % where)

    def __repr__(self) -> str:
        return "Transparent(ior=%r, kt=%r, kr=%r, ka=%r, kd=%r, ks=%r)" % (
            self.ior, self.specular_btdf.kt, self.reflective_brdf.kr, self.ka, self.kd, self.specular_brdf.ks)
