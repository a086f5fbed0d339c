# release: solves a04 a05
"""PathTrace: progressive Monte Carlo path tracing (Suffern ch. 26, "Global Illumination";
02562 worksheet 7, "Progressive path tracing").

A scene with ``scene.tracer = PathTrace()`` is rendered by ``trace_path`` instead of the
ray-cast loop (rtfgu.renderer.trace, which stays the default). Every sample of a pixel is
one path, and the image is the mean over the samples. At each diffuse vertex x with albedo
rho (the surface's colour: no ambient term, and no DIFFUSE_FRACTION) the path

1. adds the light of every light source, reflected by f_r = rho / pi (next-event
   estimation, 02562 worksheet 5): a point light or a directional light as in the ray-cast
   loop, an ``AreaLight`` through one point of it sampled by area
   (AreaLight.sample_area: L_i = L_e A cos(theta_l) / d^2), each unless shadowed;
2. continues with probability q = (rho_r + rho_g + rho_b) / 3 (Russian roulette, worksheet
   7), in the direction w_i that ``Lambertian(rho).sample_f`` draws (rtfgu/lambertian.py:
   cosine-weighted, pdf = cos(theta) / pi), so that the throughput is multiplied by
   f_r cos(theta) / (pdf q), which is rho / q. A direction with pdf or cos(theta) not above 0
   ends the path.

A ``GlossyReflector`` vertex reflects by Phong's BRDF, rho / pi plus the normalised lobe
rho_s (s + 2) / (2 pi) cos^s(alpha) about the mirror direction, in step 1 as well; in step
2 Russian roulette picks the diffuse part with probability q_d = mean(rho), the lobe with
q_s = mean(rho_s) (both scaled down if they add up to more than 1), or the end of the path;
the lobe's direction is sampled with density (s + 1) / (2 pi) cos^s(alpha) (Suffern ch. 25),
so the throughput is multiplied by rho_s (s + 2) / (s + 1) cos(theta) / q_s, and a direction
below the surface ends the path.

Emitted light is counted where the eye sees it and after a mirror or a refraction, and not
after a diffuse bounce, whose light sources step 1 counted already; so every emitting shape
must be an ``AreaLight``'s (Scene.validate says which is not). A surface emits from its
front only (the side its normal points to). A ray that leaves the scene sees
``scene.environment`` (an EnvironmentLight's image), or ``scene.background`` as a constant
environment: radiance from every direction. A mirror
and a refracting surface (the 02562 ``mirror`` and ``transparent``) continue the path as in
the ray-cast loop, a ``Dielectric`` reflects or refracts by Fresnel's reflectance and absorbs
inside (rtfgu.fresnel); ``base_color`` and ``emissive`` end it.

The random numbers of vertex ``depth`` are the stream's dimensions ``path_dimension(depth,
k)`` (rtfgu.sampling.random), so the numba path draws the same numbers for the same path.
A path has at most ``max_depth`` vertices.
"""
from __future__ import annotations

import math

from .area_light import AreaLight
from .float3 import Float3, dot
from .fresnel import scatter, transmittance
from .lambertian import Lambertian
from .material import (BASE_COLOR, DIELECTRIC, EMISSIVE, GLOSSY_REFLECTOR, LAMBERTIAN, MIRROR, SHADER_NAMES,
                       TRANSPARENT)
from .ray import Ray
from .sampling.maps import about, hemisphere_map
from .sampling.random import (BOUNCE_U, BOUNCE_V, CHOICE, LIGHT_U, LIGHT_V, ROULETTE, VERTEX_DIMENSIONS,
                              path_dimension, random_float)
from .shading import SPAWN_EPSILON, HitInfo, in_shadow, mirror, transparent

# The shaders a path goes through; any other is refused by Scene.validate.
PATH_SHADERS = (BASE_COLOR, LAMBERTIAN, MIRROR, TRANSPARENT, EMISSIVE, DIELECTRIC, GLOSSY_REFLECTOR)
# The deepest path: vertex dimensions stay below 2^32 far beyond it.
MAX_PATH_DEPTH = 1024
# The most area lights a path samples (two dimensions each per vertex).
MAX_AREA_LIGHTS = (VERTEX_DIMENSIONS - LIGHT_U) // 2


class PathTrace:
    """Suffern's ``PathTrace`` tracer; ``max_depth``: the most vertices of a path (Russian
    roulette ends most paths well before it)."""

    def __init__(self, max_depth: int = 64):
        if isinstance(max_depth, bool) or not isinstance(max_depth, int) or not 1 <= max_depth <= MAX_PATH_DEPTH:
            raise ValueError("PathTrace.max_depth must be an integer in [1, %d], got %r"
                             % (MAX_PATH_DEPTH, max_depth))
        self.max_depth = max_depth

    def trace_ray(self, scene, ray: Ray, pixel: int, sample: int, seed: int) -> Float3:
        """The radiance of one path: sample ``sample`` of ``pixel``."""
        return trace_path(scene, ray, self.max_depth, pixel, sample, seed)

    def validate(self, scene) -> None:
        """Raise a ValueError naming the field if ``scene`` cannot be path traced."""
        lit = {id(light.shape) for light in scene.lights if isinstance(light, AreaLight)}
        if len(lit) > MAX_AREA_LIGHTS:
            raise ValueError("Scene.lights: PathTrace samples at most %d area lights, got %d"
                             % (MAX_AREA_LIGHTS, len(lit)))
        for i, shape in enumerate(scene.shapes):
            m = shape.material
            if m.shader not in PATH_SHADERS:
                raise ValueError("Scene.shapes[%d].material: PathTrace traces the shaders %s, not %s"
                                 % (i, ", ".join(SHADER_NAMES[s] for s in PATH_SHADERS), SHADER_NAMES[m.shader]))
            e = m.emission
            if max(e.x, e.y, e.z) > 0.0 and id(shape) not in lit:
                raise ValueError("Scene.shapes[%d] emits (material.emission %r) but no AreaLight in "
                                 "Scene.lights samples it: add AreaLight(scene.shapes[%d])" % (i, e, i))
            c = shape.color
            if m.shader == LAMBERTIAN and max(c.x, c.y, c.z) > 1.0:
                raise ValueError("Scene.shapes[%d].color %r: a diffuse albedo above 1 reflects more light "
                                 "than it receives; PathTrace refuses it (scale the colour to <= 1)"
                                 % (i, c))
            s = m.specular
            if m.shader == GLOSSY_REFLECTOR and max(c.x + s.x, c.y + s.y, c.z + s.z) > 1.0:
                raise ValueError("Scene.shapes[%d]: color %r plus material.specular %r is above 1, an albedo "
                                 "that reflects more light than it receives; PathTrace refuses it" % (i, c, s))


def lobe_direction(w_r: Float3, shininess: float, u: float, v: float) -> Float3:
    """A direction about the unit mirror direction w_r with density (s + 1) / (2 pi) cos^s(alpha),
    alpha its angle to w_r (Suffern's GlossySpecular::sample_f)."""
    return about(w_r, hemisphere_map(u, v, shininess))


def glossy_lobe(specular: Float3, shininess: float, normal: Float3, w_o: Float3, w_i: Float3,
                cos_theta: float) -> Float3:
    """The normalised Phong lobe rho_s (s + 2) / (2 pi) max(w_o . w_r, 0)^s with
    w_r = 2 (n . w_i) n - w_i (02562 worksheet 3)."""
    w_r = normal * (2.0 * cos_theta) - w_i
    cos_r = max(dot(w_o, w_r), 0.0)
    return specular * ((shininess + 2.0) / (2.0 * math.pi) * cos_r ** shininess)


def direct_light(scene, position: Float3, normal: Float3, w_o: Float3, rho: Float3, specular: Float3,
                 shininess: float, depth: int, pixel: int, sample: int, seed: int) -> Float3:
    """The light of every light source reflected at ``position`` by f_r = rho / pi plus the
    glossy lobe (zero ``specular`` for a Lambertian surface): the sum of f_r L_i (n . w_i)
    over the lights that are above the surface and not shadowed, an area light through one
    point of it (step 1 above)."""
    result = Float3(0.0)
    drawn = {}          # per light kind, the lights that drew a point so far
    for light in scene.lights:
        if hasattr(light, "sample_area"):       # AreaLight, AmbientOccluder
            j = drawn.get(type(light), 0)
            drawn[type(light)] = j + 1
            u = random_float(pixel, sample, path_dimension(depth, LIGHT_U + 2 * j), seed)
            v = random_float(pixel, sample, path_dimension(depth, LIGHT_V + 2 * j), seed)
            light_sample = light.sample_area(position, normal, u, v)
        else:
            light_sample = light.sample(position)
        L_i = light_sample.L_i
        if L_i.x == 0.0 and L_i.y == 0.0 and L_i.z == 0.0:
            continue
        cos_theta = dot(normal, light_sample.w_i)
        if not cos_theta > 0.0:
            continue
        if scene.shadows and in_shadow(scene, position, light_sample.w_i, light_sample.dist):
            continue
        f_r = rho / math.pi + glossy_lobe(specular, shininess, normal, w_o, light_sample.w_i, cos_theta)
        result += f_r * L_i * cos_theta
    return result


def trace_path(scene, r: Ray, max_depth: int, pixel: int, sample: int, seed: int) -> Float3:
    """One path's radiance (the steps in the module's docstring)."""
    result = Float3(0.0)
    throughput = Float3(1.0)
    sees_emission = True        # the eye ray, or a ray after a mirror or a refraction
    for depth in range(max_depth):
        hit = HitInfo()
        if not scene.intersect(r, hit):
            result += throughput * scene.background_radiance(r.direction)
            break
        d = r.direction
        n = hit.normal
        facing = dot(n, d)
        if sees_emission and facing < 0.0:
            result += throughput * hit.emission
        shader = hit.shader
        if shader == LAMBERTIAN or shader == GLOSSY_REFLECTOR:
            if facing > 0.0:                 # seen from behind: the side the ray is on
                n = -n
            rho = hit.color
            specular = hit.specular if shader == GLOSSY_REFLECTOR else Float3(0.0)
            result += throughput * direct_light(scene, hit.position, n, -d, rho, specular, hit.shininess,
                                                depth, pixel, sample, seed)
            if depth + 1 == max_depth:
                break
            # Russian roulette picks the lobe the path follows, or ends it.
            q_d = (rho.x + rho.y + rho.z) / 3.0
            q_s = (specular.x + specular.y + specular.z) / 3.0
            if q_d + q_s > 1.0:
                q_d, q_s = q_d / (q_d + q_s), q_s / (q_d + q_s)
            xi = random_float(pixel, sample, path_dimension(depth, ROULETTE), seed)
            u = random_float(pixel, sample, path_dimension(depth, BOUNCE_U), seed)
            v = random_float(pixel, sample, path_dimension(depth, BOUNCE_V), seed)
            if xi < q_d:
                f, w_i, pdf = Lambertian(rho).sample_f(n, u, v)
                cos_theta = dot(n, w_i)
                if not (pdf > 0.0 and cos_theta > 0.0):
                    break
                throughput = throughput * f * (cos_theta / (pdf * q_d))
            elif xi < q_d + q_s:
                w_i = lobe_direction(d - n * (2.0 * dot(d, n)), hit.shininess, u, v)
                cos_theta = dot(n, w_i)
                if not cos_theta > 0.0:          # the lobe reaches below the surface: no light
                    break
                # f_r cos / pdf = rho_s (s + 2) / (s + 1) cos(theta), over the lobe's chance q_s
                throughput = throughput * specular * ((hit.shininess + 2.0) / (hit.shininess + 1.0)
                                                      * cos_theta / q_s)
            else:
                break
            r = Ray(hit.position, w_i, SPAWN_EPSILON, math.inf)
            sees_emission = False
        elif shader == MIRROR:
            mirror(scene, r, hit)            # r becomes the reflected ray
            sees_emission = True
        elif shader == TRANSPARENT:
            transparent(scene, r, hit)       # r becomes the refracted (or reflected) ray
            sees_emission = True
        elif shader == DIELECTRIC:
            if facing > 0.0:                 # met from inside: the way here was through the medium
                throughput = throughput * transmittance(hit.absorption, hit.dist)
            xi = random_float(pixel, sample, path_dimension(depth, CHOICE), seed)
            r = Ray(hit.position, scatter(d, n, hit.ior, xi), SPAWN_EPSILON, math.inf)
            sees_emission = True
        else:
            if shader == BASE_COLOR:
                result += throughput * hit.color
            break
    return result
