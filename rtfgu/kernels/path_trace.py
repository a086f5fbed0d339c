# release: solves a04 a05 a09 a11
"""PathTrace on the numba path: rtfgu.tracers.PathTrace.trace_ray, operation for operation, over the
flat layout (the same random numbers, so the same paths as the lecture layer).

rtfgu.kernels.render's ``render_tile`` calls it when its ``path`` is the tuple (max_depth,),
and the ray-cast loop otherwise, so a ray-cast scene compiles none of it.
"""
from __future__ import annotations

import math

from numba import njit

from ..layout import (MAT_ABSORPTION, MAT_DIFFUSE_SAMPLER, MAT_EMISSION, MAT_IOR, MAT_KD, MAT_SHININESS, MAT_SPECULAR,
                      MAT_SPECULAR_SAMPLER)
from ..materials.material import BASE_COLOR, DIELECTRIC, GLOSSY_REFLECTOR, LAMBERTIAN, MIRROR, TRANSPARENT
from ..registry import LIGHTS
from ..sampling.random import BOUNCE_U, CHOICE, LOBE, ROULETTE, VERTEX_DIMENSIONS
from ..ray import SPAWN_EPSILON
from ..tracers.path_trace import ROULETTE_DEPTH
from .environment import ENVIRONMENT, MATERIAL_OF, background_radiance
from .dispatch import direct_path, intersect_scene, shape_normal, surface_color
from .float3 import add, div, dot, lit, load3, mul, neg, scale
from .glossy import about, lobe_direction
from .sampling import hemisphere_map, random_float, sampler_point, sampler_sets
from .shaders import mirror, transparent

# Where ``lights`` holds the own samplers' sets (rtfgu.kernels.own_sets): after a table per light kind.
OWN_SAMPLES = len(LIGHTS)
OWN_SHUFFLED = len(LIGHTS) + 1
SOBOL = len(LIGHTS) + 2       # and whether the render's 2D draws are Sobol's


@njit(cache=True, error_model="numpy")
def cosine_direction(n, u, v):
    """The direction of rtfgu.brdfs.Lambertian.sample_f: density cos(theta) / pi about
    the unit n."""
    return about(n, hemisphere_map(u, v, lit(1.0, u)))


@njit(cache=True, error_model="numpy")
def fresnel_reflectance(cos_i, eta):
    """rtfgu.brdfs.fresnel_reflector.fresnel_reflectance: R for unpolarised light, 1 under total internal
    reflection."""
    one = lit(1.0, cos_i)
    sin2_t = eta * eta * (one - cos_i * cos_i)
    if sin2_t >= one:
        return one
    cos_t = math.sqrt(one - sin2_t)
    r_perp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t)
    r_par = (cos_i - eta * cos_t) / (cos_i + eta * cos_t)
    return lit(0.5, one) * (r_perp * r_perp + r_par * r_par)


@njit(cache=True, error_model="numpy")
def scatter(direction, normal, ior, xi):
    """rtfgu.materials.dielectric.scatter: reflected if xi < R, refracted otherwise."""
    zero = lit(0.0, ior)
    one = lit(1.0, ior)
    cos_i = -dot(direction, normal)
    if cos_i >= zero:
        eta = one / ior
        n = normal
    else:
        eta = ior
        n = neg(normal)
        cos_i = -cos_i
    if xi < fresnel_reflectance(cos_i, eta):
        return add(direction, scale(n, lit(2.0, one) * cos_i))
    cos_t = math.sqrt(one - eta * eta * (one - cos_i * cos_i))
    return add(scale(direction, eta), scale(n, eta * cos_i - cos_t))


@njit(cache=True, error_model="numpy", inline="always")
def trace_path(ray, shapes, lights, scene, terms, candidates, n_candidates, settings, path, pixel, sample):
    """One path's radiance (rtfgu.tracers.PathTrace.trace_ray): (radiance, shadow rays, secondary
    rays). ``path``: (max_depth, whether every vertex samples the lights: GlobalTrace samples
    them at the first vertex only and counts the emission that later bounces hit)."""
    max_depth, every_vertex = path
    origin, direction, tmin, tmax = ray
    materials, shaders, background = scene[0], scene[1], scene[2]
    shadows, formula, seed = settings[0], settings[2], settings[3]
    zero = lit(0, tmin)
    one = lit(1, zero)
    result = (zero, zero, zero)
    throughput = (one, one, one)
    sees_emission = True
    n_shadow = 0
    n_secondary = 0
    for depth in range(max_depth):
        if depth > ROULETTE_DEPTH:
            # Russian roulette on the throughput, for the ray from the vertex before (PathTrace).
            q = max(throughput[0], throughput[1], throughput[2])
            if q < one:
                if not random_float(pixel, sample, 2 + (depth - 1) * VERTEX_DIMENSIONS + ROULETTE, seed, zero) < q:
                    break
                throughput = div(throughput, q)
        if depth > 0:
            n_secondary += 1
        t, idx, kind, row = intersect_scene(shapes, terms, candidates, n_candidates if depth == 0 else -1,
                                            origin, direction, tmin, tmax, formula)
        if idx < 0:
            result = add(result, mul(throughput, background_radiance(scene[ENVIRONMENT], background, direction)))
            break
        position = add(origin, scale(direction, t))
        m = scene[MATERIAL_OF][idx]
        shader = shaders[m]
        mat = materials[m]
        normal = shape_normal(shapes, kind, row, position, direction)
        facing = dot(normal, direction)
        if sees_emission and facing < zero:
            result = add(result, mul(throughput, load3(mat, MAT_EMISSION)))
        first = 2 + depth * VERTEX_DIMENSIONS
        if shader == LAMBERTIAN or shader == GLOSSY_REFLECTOR:
            if facing > zero:
                normal = neg(normal)
            rho = scale(surface_color(scene, shapes, mat, kind, row, position),
                        mat[MAT_KD])
            specular = (zero, zero, zero)
            if shader == GLOSSY_REFLECTOR:
                specular = load3(mat, MAT_SPECULAR)
            shininess = mat[MAT_SHININESS]
            if every_vertex or depth == 0:
                light, shadow_rays = direct_path(lights, shapes, (position, normal, neg(direction)),
                                                 (rho, specular, shininess), (first, pixel, sample, seed), shadows,
                                                 formula)
                n_shadow += shadow_rays
                result = add(result, mul(throughput, light))
            if depth + 1 == max_depth:
                break
            # The lobe, in the ratio of the albedos (GlossyReflector.path_shade; a Matte's q_d is 1).
            three = lit(3.0, zero)
            q_d = (rho[0] + rho[1] + rho[2]) / three
            q_s = (specular[0] + specular[1] + specular[2]) / three
            if not q_d + q_s > zero:
                break
            q_d, q_s = q_d / (q_d + q_s), q_s / (q_d + q_s)
            xi = random_float(pixel, sample, first + LOBE, seed, zero)
            # the chosen BRDF's own sampler's point, or the render's pair (BRDF.sample_point)
            u, v = sampler_point(sampler_sets(lights[OWN_SAMPLES], lights[OWN_SHUFFLED], lights[SOBOL]), materials, m,
                                 MAT_DIFFUSE_SAMPLER if xi < q_d else MAT_SPECULAR_SAMPLER, pixel, sample,
                                 first + BOUNCE_U, seed, zero)
            if xi < q_d:
                # rtfgu.brdfs.Lambertian.sample_f: f = rho / pi, pdf = cos(theta) / pi
                f = div(rho, lit(math.pi, zero))
                w_i = cosine_direction(normal, u, v)
                cos_theta = dot(normal, w_i)
                pdf = cos_theta / lit(math.pi, zero)
                if not (pdf > zero and cos_theta > zero):
                    break
                throughput = scale(mul(throughput, f), cos_theta / (pdf * q_d))
                direction = w_i
            elif q_s > zero:
                w_i = lobe_direction(mirror(direction, normal), shininess, u, v)
                cos_theta = dot(normal, w_i)
                if not cos_theta > zero:
                    break
                weight = (shininess + lit(2.0, zero)) / (shininess + one) * cos_theta / q_s
                throughput = mul(throughput, scale(specular, weight))
                direction = w_i
            else:
                break
            sees_emission = not (every_vertex or depth == 0)
        elif shader == MIRROR:
            direction = mirror(direction, normal)
            sees_emission = True
        elif shader == TRANSPARENT:
            direction = transparent(direction, normal, mat[MAT_IOR])
            sees_emission = True
        elif shader == DIELECTRIC:
            if facing > zero:
                throughput = mul(throughput, (math.exp(-mat[MAT_ABSORPTION] * t),
                                              math.exp(-mat[MAT_ABSORPTION + 1] * t),
                                              math.exp(-mat[MAT_ABSORPTION + 2] * t)))
            xi = random_float(pixel, sample, first + CHOICE, seed, zero)
            direction = scatter(direction, normal, mat[MAT_IOR], xi)
            sees_emission = True
        else:
            if shader == BASE_COLOR:
                color = surface_color(scene, shapes, mat, kind, row, position)
                result = add(result, mul(throughput, color))
            break
        origin = position
        tmin = lit(SPAWN_EPSILON, zero)
        tmax = lit(math.inf, zero)
    return result, n_shadow, n_secondary

