"""Reflective: Phong plus perfect mirror reflection (Suffern ch. 24, "Mirror Reflection";
02562 worksheet 3, "mirror").

    L_o = Phong's L_o + kr cr L(w_r),   w_r = -w_o + 2 (n . w_o) n,

L(w_r) traced by the scene's tracer one level deeper (``trace_ray(ray, depth + 1)``). The
defaults are the 02562 mirror: no ambient, diffuse or glossy part (ka = kd = ks = 0) and
kr cr = 1, so the mirror shows exactly what its reflected ray sees (the 02562 ``mirror``
shader). Suffern's chapter 24 figures set both: a coloured Phong surface with a reflection
(the ``reflective`` case of the flat paths' switch: the light loop with Phong's BRDF, then
the reflected ray weighted by kr cr).
"""
from __future__ import annotations

from ..brdfs.perfect_specular import PerfectSpecular
from ..float3 import Float3, dot
from ..ray import SPAWN_EPSILON, Ray
from ..validation import colour, number
from .material import MIRROR, REFLECTIVE, PathVertex, set_on
from .phong import Phong


def specular_scale(cos: float, pdf: float) -> float:
    """|n . w| / pdf of a perfectly specular direction: 1 exactly where the pdf is the cosine."""
    return 1.0 if cos == pdf else cos / pdf


class Reflective(Phong):
    def __init__(self, kr: float = 1.0, cr=(1.0, 1.0, 1.0), ka: float = 0.0, kd: float = 0.0, cd=None,
                 ks: float = 0.0, cs=(1.0, 1.0, 1.0), exp: float = 1.0, emission=None):
        super().__init__(ka, kd, cd, ks, cs, exp, emission)
        self.reflective_brdf = PerfectSpecular()
        self.set_kr(kr)
        self.set_cr(cr)

    set_kr = set_on("reflective_brdf", "set_kr", number, "kr")
    set_cr = set_on("reflective_brdf", "set_cr", colour, "cr")

    @property
    def is_mirror(self) -> bool:
        """The 02562 mirror: nothing but kr cr = 1."""
        b = self.reflective_brdf
        return (not self.reflects_light() and self.ka == 0.0 and b.kr == 1.0
                and (b.cr.x, b.cr.y, b.cr.z) == (1.0, 1.0, 1.0))

    @property
    def reflection(self) -> Float3:
        """kr cr, the weight of the reflected ray (the flat layout's ``reflection``)."""
        return self.reflective_brdf.rho(None)

    @property
    def shader(self) -> int:
        """The mirror case when nothing but the mirror reflects (any kr cr), else Phong
        followed by the mirror."""
        return MIRROR if not self.reflects_light() and self.ka == 0.0 else REFLECTIVE

    def shade(self, sr) -> Float3:
        ### BEGIN SOLUTION
        L = super().shade(sr)
        fr, wi, pdf = self.reflective_brdf.sample_f(sr, -sr.ray.direction)
        reflected = Ray(sr.position, wi, SPAWN_EPSILON)
        L_r = sr.scene.tracer.trace_ray(reflected, sr.depth + 1)
        return L + fr * L_r * specular_scale(abs(dot(sr.normal, wi)), pdf)
        ### END SOLUTION

    def path_shade(self, sr) -> PathVertex:
        """The 02562 mirror in a path: the path goes on along the reflected ray."""
        _, wi, _ = self.reflective_brdf.sample_f(sr, -sr.ray.direction)
        return PathVertex(None, ray=Ray(sr.position, wi, SPAWN_EPSILON), sees_emission=True)

    def check_path_trace(self, where: str, color) -> None:
        if not self.is_mirror:
            raise ValueError("%s: PathTrace traces a Reflective as a perfect mirror only (ka = kd = ks = 0, "
                             "kr = 1, cr white)" % where)

    def __repr__(self) -> str:
        return "Reflective(kr=%r, cr=%r, ka=%r, kd=%r, ks=%r)" % (
            self.reflective_brdf.kr, self.reflective_brdf.cr, self.ka, self.kd, self.specular_brdf.ks)
