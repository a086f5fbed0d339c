"""GlossyReflector: Phong whose lobe also reflects the light of the scene, sampled (Suffern
ch. 25, "Glossy Reflection").

A diffuse part (kd cd / pi) and the normalised lobe ks cs (e + 2) / (2 pi) cos^e(alpha)
about the mirror direction (rtfgu/brdfs/glossy_specular.py). The ray-cast tracers shade it
as Phong; PathTrace also follows the light it reflects: the path goes on through the diffuse
part with probability q_d = mean(kd cd) / (mean(kd cd) + mean(ks cs)), through the lobe with
q_s = 1 - q_d (Russian roulette, which may end it, is the tracer's); the lobe's direction is drawn with
density (e + 1) / (2 pi) cos^e(alpha) (GlossySpecular.sample_f), so the throughput is
multiplied by

    f (n . w_i) / (pdf q_s) = ks cs (e + 2) / (e + 1) (n . w_i) / q_s,

computed in that closed form (as the numba and WGSL kernels do), and a direction below the
surface ends the path. The book's GlossyReflector samples a lobe of its own (``kr``, ``cr``);
here the highlight's lobe is the one sampled, so the light it reflects and the highlights
of the lights agree.
"""
from __future__ import annotations

from ..float3 import Float3, dot
from ..ray import SPAWN_EPSILON, Ray
from ..sampling.random import BOUNCE_U, LOBE, path_dimension, random_float
from .material import GLOSSY_REFLECTOR, PathVertex
from .matte import KA_02562, KD_02562
from .phong import Phong


class GlossyReflector(Phong):
    shader = GLOSSY_REFLECTOR

    def __init__(self, ka: float = KA_02562, kd: float = KD_02562, cd=None, ks: float = 1.0,
                 cs=(0.5, 0.5, 0.5), exp: float = 100.0, emission=None):
        super().__init__(ka, kd, cd, ks, cs, exp, emission)

    def path_shade(self, sr) -> PathVertex:
        self.face_ray(sr)
        d, n = sr.ray.direction, sr.normal
        wo = -d
        tracer = sr.scene.tracer
        L = self.direct_light(sr, wo, Float3(0.0)) if tracer.samples_lights_at(sr.depth) else None
        if sr.depth + 1 == tracer.max_depth:
            return PathVertex(L)
        rho = self.diffuse_brdf.rho(sr, wo)
        specular = self.specular
        # The lobe: diffuse or glossy with probabilities in the ratio of their albedos.
        q_d = (rho.x + rho.y + rho.z) / 3.0
        q_s = (specular.x + specular.y + specular.z) / 3.0
        if not q_d + q_s > 0.0:
            return PathVertex(L)
        q_d, q_s = q_d / (q_d + q_s), q_s / (q_d + q_s)
        xi = random_float(sr.pixel, sr.sample, path_dimension(sr.depth, LOBE), sr.seed)
        if xi < q_d:
            u, v = self.diffuse_brdf.sample_point(sr, BOUNCE_U)
            f, wi, pdf = self.diffuse_brdf.sample_f(sr, wo, u, v)
            cos_theta = dot(n, wi)
            if not (pdf > 0.0 and cos_theta > 0.0):
                return PathVertex(L)
            return PathVertex(L, f, cos_theta / (pdf * q_d), Ray(sr.position, wi, SPAWN_EPSILON))
        if q_s > 0.0:
            u, v = self.specular_brdf.sample_point(sr, BOUNCE_U)
            _, wi, _ = self.specular_brdf.sample_f(sr, wo, u, v)
            cos_theta = dot(n, wi)
            if not cos_theta > 0.0:          # the lobe reaches below the surface: no light
                return PathVertex(L)
            s = self.shininess
            return PathVertex(L, specular, (s + 2.0) / (s + 1.0) * cos_theta / q_s,
                              Ray(sr.position, wi, SPAWN_EPSILON))
        return PathVertex(L)

    def check_path_trace(self, where: str, color) -> None:
        from .matte import _Colour

        rho, s = self.diffuse_brdf.rho(_Colour(color)), self.specular
        if max(rho.x + s.x, rho.y + s.y, rho.z + s.z) > 1.0:
            raise ValueError("%s: kd cd %r plus ks cs %r is above 1, an albedo that reflects more light than "
                             "it receives; PathTrace refuses it" % (where, rho, s))
