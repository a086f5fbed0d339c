"""Matte: a perfectly diffuse surface (Suffern ch. 14, "Matte"; 02562, "Lambert's cosine law"
and "Sampling light in the shader").

Two Lambertian BRDFs of one colour cd: the ambient one (ka) reflects the scene's ambient
light, the diffuse one (kd) the light of every light:

    L_o = ka cd L_a + sum over lights of kd cd / pi L_i (n . w_i),   where n . w_i > 0
                                                                      and the light is not hidden.

The 02562 default scene's diffuse shader, "rho_d = 90 % and L_a = 10 % of the object's
colour", is a Matte with ``ka = 0.1`` and ``kd = 0.9`` under ``Ambient()`` (ls 1, white):
the defaults here. A path-traced scene uses kd = 1 (rho = cd) and no ambient term.
"""
from __future__ import annotations

from ..brdfs.lambertian import Lambertian
from ..float3 import Float3, dot
from ..ray import SPAWN_EPSILON, Ray
from ..sampling.random import BOUNCE_U
from ..validation import number
from .material import LAMBERTIAN, Material, PathVertex, read_from, set_on

# The 02562 split of an object's colour into ambient and diffuse reflectance.
KA_02562 = 0.1
KD_02562 = 0.9


class Matte(Material):
    shader = LAMBERTIAN

    def __init__(self, ka: float = KA_02562, kd: float = KD_02562, cd=None, emission=None):
        super().__init__(cd, emission)
        self.ambient_brdf = Lambertian(0.0, self.cd)
        self.diffuse_brdf = Lambertian(0.0, self.cd)
        self.set_ka(ka)
        self.set_kd(kd)

    # -- the book's setters: ka and kd are the kd of the ambient and the diffuse BRDF
    set_ka = set_on("ambient_brdf", "set_kd", number, "ka")
    set_kd = set_on("diffuse_brdf", "set_kd", number, "kd")
    ka = read_from("ambient_brdf", "kd", "ka, the ambient reflection coefficient")
    kd = read_from("diffuse_brdf", "kd", "kd, the diffuse reflection coefficient")

    def set_cd(self, cd) -> None:
        super().set_cd(cd)
        self.ambient_brdf.set_cd(self.cd)
        self.diffuse_brdf.set_cd(self.cd)

    # -- shading
    def f(self, sr, wo, wi) -> Float3:
        """The BRDF the light loop reflects light by: kd cd / pi."""
        return self.diffuse_brdf.f(sr, wo, wi)

    def ambient(self, sr, wo) -> Float3:
        """L_e + ka cd L_a: where the light loop starts."""
        # TODO a04: Matte.ambient
        #   Return L_e + ka cd L_a: self.get_Le(sr) + self.ambient_brdf.rho(sr, wo) * sr.scene.ambient_light.L(sr).
        raise NotImplementedError('a04: Matte.ambient')

    def shade(self, sr) -> Float3:
        """L_e + ka cd L_a + the light of every light (the 02562 diffuse shader); a
        surface that reflects no light (kd = 0, and no lobe) casts no shadow rays."""
        wo = -sr.ray.direction
        L = self.ambient(sr, wo)
        return self.direct_light(sr, wo, L) if self.reflects_light() else L

    def reflects_light(self) -> bool:
        """Whether the light loop can add anything: a BRDF that is not 0."""
        return self.diffuse_brdf.kd > 0.0

    def direct_light(self, sr, wo, L: Float3) -> Float3:
        """The light loop, written once for every material that reflects light: to L add
        f L G / pdf (n . w_i) for every light above the surface and, where the light casts
        shadows, not hidden (Light.incident is L G / pdf)."""
        # TODO a04: Matte.direct_light
        #   For each light of sr.scene.lights: wi = light.get_direction(sr), L_i = light.incident(sr) (skip an
        #   all-zero L_i); ndotwi = n . wi with n = sr.normal; skip the light unless ndotwi > 0. If
        #   light.casts_shadows(), skip it when light.in_shadow(Ray(sr.position, wi), sr) (in_shadow is
        #   assignment 5). Otherwise L += self.f(sr, wo, wi) * L_i * ndotwi. Return L.
        raise NotImplementedError('a04: Matte.direct_light')

    def path_shade(self, sr) -> PathVertex:
        """Next-event estimation (the light of every light, sampled) and a diffuse bounce
        drawn by ``diffuse_brdf.sample_f``: the throughput is multiplied by f (n . w_i) / pdf.
        A surface of albedo 0 ends the path; Russian roulette is the tracer's (PathTrace)."""
        self.face_ray(sr)
        wo = -sr.ray.direction
        tracer = sr.scene.tracer
        L = self.direct_light(sr, wo, Float3(0.0)) if tracer.samples_lights_at(sr.depth) else None
        if sr.depth + 1 == tracer.max_depth:
            return PathVertex(L)
        rho = self.diffuse_brdf.rho(sr, wo)
        if not (rho.x + rho.y + rho.z) > 0.0:
            return PathVertex(L)
        u, v = self.diffuse_brdf.sample_point(sr, BOUNCE_U)
        f, wi, pdf = self.diffuse_brdf.sample_f(sr, wo, u, v)
        n_dot_wi = dot(sr.normal, wi)
        if not (pdf > 0.0 and n_dot_wi > 0.0):
            return PathVertex(L)
        return PathVertex(L, f, n_dot_wi / pdf, Ray(sr.position, wi, SPAWN_EPSILON))

    def check_path_trace(self, where: str, color) -> None:
        rho = self.diffuse_brdf.rho(_Colour(color))
        if max(rho.x, rho.y, rho.z) > 1.0:
            raise ValueError("%s: a diffuse albedo kd cd = %r above 1 reflects more light than it receives; "
                             "PathTrace refuses it (scale the colour or kd to <= 1)" % (where, rho))

    def __repr__(self) -> str:
        return "%s(ka=%r, kd=%r, cd=%r)" % (type(self).__name__, self.ka, self.kd, self.cd)


class _Colour:
    """A stand-in hit whose surface colour is ``color`` (a shape's, to check an albedo)."""

    def __init__(self, color):
        self.color = color
