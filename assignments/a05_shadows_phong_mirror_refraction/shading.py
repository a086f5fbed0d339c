"""HitInfo and the shaders of 02562 weeks 1-3, with one ``shade`` dispatch by shader id.

A shader returns the radiance it adds along the path and may turn the ray into the next
ray of the path (``mirror``, ``transparent``); it then clears ``hit.has_hit`` so that the
path loop in ``trace`` continues ("Intersecting with the scene and tracing a path").

Diffuse surfaces (02562, "Sampling light in the shader"):
    L_o = L_e + rho_d / pi * L_i * (n . w_i) + L_a
with rho_d = 90 % and L_a = 10 % of the object's colour (the 02562 default scene).
"""
from __future__ import annotations

import math

from .float3 import Float3, dot, normalize
from .material import (BASE_COLOR, DIELECTRIC, EMISSIVE, GLOSSY, GLOSSY_REFLECTOR, LAMBERTIAN, MIRROR, PHONG, TRANSPARENT,
                       Material)
from .ray import Ray

# The split of an object's colour into diffuse reflectance and ambient radiance.
DIFFUSE_FRACTION = 0.9
AMBIENT_FRACTION = 0.1

# How far along its direction a secondary (shadow, mirror, refracted) ray starts, so that
# it does not hit the surface it leaves: the slide's tmin idea, sized for float32 too.
SPAWN_EPSILON = 1e-4

# The path loop's bound (02562 "main_fs": const max_depth = 10).
MAX_DEPTH = 10


class HitInfo:
    """The slide's ``struct HitInfo { has_hit, dist, position, normal, color, ... }``; the
    dots are the material of the shape hit (shader id, rho_s, s, ior, L_e)."""

    __slots__ = ("has_hit", "dist", "position", "normal", "color", "shader",
                 "specular", "shininess", "ior", "emission", "absorption")

    def __init__(self):
        self.has_hit = False
        self.dist = 0.0
        self.position = Float3(0.0)
        self.normal = Float3(0.0)
        self.color = Float3(0.0)
        self.shader = BASE_COLOR
        self.specular = Float3(0.0)
        self.shininess = 0.0
        self.ior = 1.0
        self.emission = Float3(0.0)
        self.absorption = Float3(0.0)

    def set_material(self, color: Float3, material: Material) -> None:
        self.color = color
        self.shader = material.shader
        self.specular = material.specular
        self.shininess = material.shininess
        self.ior = material.ior
        self.emission = material.emission
        self.absorption = material.absorption


def in_shadow(scene, position: Float3, w_i: Float3, dist: float) -> bool:
    """A shadow ray toward the light: is any shape hit strictly before it?"""
    # TODO a05: in_shadow
    #   Cast Ray(position, w_i, SPAWN_EPSILON, dist - SPAWN_EPSILON) and return True if any
    #   shape of scene.shapes hits it. The offset keeps the ray from hitting the surface it
    #   leaves (shadow acne) and from hitting the light's own position.
    raise NotImplementedError('a05: in_shadow')


def lambertian(scene, r: Ray, hit: HitInfo) -> Float3:
    """L_e + sum over lights of rho_d / pi * L_i * max(n . w_i, 0), unless shadowed, + L_a."""
    rho_d = hit.color * DIFFUSE_FRACTION
    L_a = hit.color * AMBIENT_FRACTION
    result = hit.emission + L_a
    for light in scene.lights:
        sample = light.sample(hit.position)
        cos_theta = max(dot(hit.normal, sample.w_i), 0.0)
        if cos_theta == 0.0:
            continue
        if scene.shadows and in_shadow(scene, hit.position, sample.w_i, sample.dist):
            continue
        result += rho_d / math.pi * sample.L_i * cos_theta
    return result


def phong(scene, r: Ray, hit: HitInfo) -> Float3:
    """Lambertian plus the normalised Phong lobe (02562 worksheet 3):
    L_r = (rho_d / pi + rho_s (s + 2) / (2 pi) max(w_o . w_r, 0)^s) L_i (n . w_i),
    with w_o = -r.direction and w_r = 2 (n . w_i) n - w_i, the mirrored light direction."""
    # TODO a05: phong
    #   As lambertian, plus the lobe rho_s (s + 2) / (2 pi) max(w_o . w_r, 0)^s with
    #   w_o = -r.direction and w_r = 2 (n . w_i) n - w_i; both terms times L_i (n . w_i).
    raise NotImplementedError('a05: phong')


def _continue_path(r: Ray, hit: HitInfo, direction: Float3) -> None:
    # A new ray of the path: fresh tmax, so it is not cut at the last hit's distance.
    r.origin = hit.position
    r.direction = direction
    r.tmin = SPAWN_EPSILON
    r.tmax = math.inf
    hit.has_hit = False


def mirror(scene, r: Ray, hit: HitInfo) -> Float3:
    """Perfect reflection: the path continues along d - 2 (d . n) n."""
    # TODO a05: mirror
    #   Continue the path along d - 2 (d . n) n with _continue_path(r, hit, direction)
    #   and return hit.emission.
    raise NotImplementedError('a05: mirror')


def transparent(scene, r: Ray, hit: HitInfo) -> Float3:
    """Refraction by Snell's law with relative index eta = n1 / n2.

    Outside or inside from the sign of the normal against the direction: d . n < 0 means the
    ray enters (eta = 1 / ior), otherwise it leaves (eta = ior, normal flipped). With no
    real refracted direction (total internal reflection) the ray is mirrored."""
    # TODO a05: transparent
    #   cos_i = -(d . n). Entering (cos_i >= 0): eta = 1 / ior. Leaving: eta = ior, flip n and
    #   cos_i. sin2_t = eta^2 (1 - cos_i^2); if sin2_t > 1 mirror (total internal reflection),
    #   else continue along d * eta + n * (eta cos_i - sqrt(1 - sin2_t)). Return hit.emission.
    raise NotImplementedError('a05: transparent')


def glossy(scene, r: Ray, hit: HitInfo) -> Float3:
    """Phong at the surface, then the path continues by refraction (02562 worksheet 3).
    The emission is counted once, by phong."""
    result = phong(scene, r, hit)
    transparent(scene, r, hit)
    return result


def base_color(scene, r: Ray, hit: HitInfo) -> Float3:
    return hit.color


def emissive(scene, r: Ray, hit: HitInfo) -> Float3:
    """Suffern's Emissive: its emitted radiance L_e, and nothing reflected."""
    return hit.emission


def shade(scene, r: Ray, hit: HitInfo) -> Float3:
    """The slide's ``switch (*hit).shader``."""
    shader = hit.shader
    if shader == LAMBERTIAN:
        return lambertian(scene, r, hit)
    elif shader == PHONG or shader == GLOSSY_REFLECTOR:
        return phong(scene, r, hit)
    elif shader == MIRROR:
        return mirror(scene, r, hit)
    elif shader == TRANSPARENT:
        return transparent(scene, r, hit)
    elif shader == GLOSSY:
        return glossy(scene, r, hit)
    elif shader == EMISSIVE:
        return emissive(scene, r, hit)
    elif shader == DIELECTRIC:
        return transparent(scene, r, hit)     # the ray-cast loop draws no Fresnel choice
    else:
        return base_color(scene, r, hit)
