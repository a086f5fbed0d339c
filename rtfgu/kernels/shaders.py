"""The 02562 shaders and the ``shade`` switch, operation for operation as rtfgu.shading.

A shader returns (radiance, has_hit, direction, shadow rays cast). has_hit False means the
path continues from the hit position along ``direction`` (the lecture's _continue_path:
tmin SPAWN_EPSILON, a fresh tmax). ``lights`` is None in a scene without lights and
``bounces`` is None in a scene whose shaders never continue a path: their code then
compiles to nothing.
"""
from __future__ import annotations

import math

from numba import njit

from ..layout import MAT_COLOR, MAT_EMISSION, MAT_IOR, MAT_SHININESS, MAT_SPECULAR
from ..material import GLOSSY, LAMBERTIAN, MIRROR, PHONG, TRANSPARENT
from ..shading import AMBIENT_FRACTION, DIFFUSE_FRACTION, SPAWN_EPSILON
from .float3 import add, div, dot, lit, load3, mul, neg, scale, sub
from .intersect import in_shadow
from .lights import sample_point_light


@njit(cache=True, error_model="numpy", inline="always")
def lambertian(r_d, position, normal, mat, lights, shadows, planes, triangles, spheres,
               sphere_formula):
    """L_e + sum over lights of rho_d / pi * L_i * max(n . w_i, 0), unless shadowed, + L_a."""
    color = load3(mat, MAT_COLOR)
    rho_d = scale(color, lit(DIFFUSE_FRACTION, r_d[0]))
    L_a = scale(color, lit(AMBIENT_FRACTION, r_d[0]))
    result = add(load3(mat, MAT_EMISSION), L_a)
    n_shadow = 0
    if lights is not None:
        zero = lit(0, r_d[0])
        eps = lit(SPAWN_EPSILON, r_d[0])
        for j in range(lights.shape[0]):
            L_i, w_i, dist = sample_point_light(lights, j, position)
            cos_theta = dot(normal, w_i)
            if zero > cos_theta:  # Python's max(cos_theta, 0.0)
                cos_theta = zero
            if cos_theta == zero:
                continue
            if shadows:
                n_shadow += 1
                if in_shadow(position, w_i, eps, dist - eps, planes, triangles, spheres,
                             sphere_formula):
                    continue
            result = add(result, scale(mul(div(rho_d, lit(math.pi, zero)), L_i), cos_theta))
    return result, n_shadow


@njit(cache=True, error_model="numpy", inline="always")
def phong(r_d, position, normal, mat, lights, shadows, planes, triangles, spheres,
          sphere_formula):
    """Lambertian plus the normalised Phong lobe (02562 worksheet 3):
    (rho_d / pi + rho_s (s + 2) / (2 pi) max(w_o . w_r, 0)^s) L_i (n . w_i)."""
    color = load3(mat, MAT_COLOR)
    rho_d = scale(color, lit(DIFFUSE_FRACTION, r_d[0]))
    L_a = scale(color, lit(AMBIENT_FRACTION, r_d[0]))
    w_o = neg(r_d)
    result = add(load3(mat, MAT_EMISSION), L_a)
    n_shadow = 0
    if lights is not None:
        zero = lit(0, r_d[0])
        eps = lit(SPAWN_EPSILON, r_d[0])
        two = lit(2.0, zero)
        pi = lit(math.pi, zero)
        specular = load3(mat, MAT_SPECULAR)
        shininess = mat[MAT_SHININESS]
        for j in range(lights.shape[0]):
            L_i, w_i, dist = sample_point_light(lights, j, position)
            cos_theta = dot(normal, w_i)
            if zero > cos_theta:
                cos_theta = zero
            if cos_theta == zero:
                continue
            if shadows:
                n_shadow += 1
                if in_shadow(position, w_i, eps, dist - eps, planes, triangles, spheres,
                             sphere_formula):
                    continue
            w_r = sub(scale(normal, two * cos_theta), w_i)
            cos_r = dot(w_o, w_r)
            if zero > cos_r:
                cos_r = zero
            lobe = scale(specular, (shininess + two) / (two * pi) * cos_r ** shininess)
            result = add(result, scale(mul(add(div(rho_d, pi), lobe), L_i), cos_theta))
    return result, n_shadow


@njit(cache=True, error_model="numpy")
def mirror(r_d, normal):
    """Perfect reflection: the path continues along d - 2 (d . n) n."""
    return sub(r_d, scale(normal, lit(2.0, r_d[0]) * dot(r_d, normal)))


@njit(cache=True, error_model="numpy")
def transparent(r_d, normal, ior):
    """Snell's law with eta = n1 / n2; d . n < 0 enters (eta = 1 / ior), otherwise the ray
    leaves (eta = ior, normal flipped); total internal reflection mirrors the ray."""
    d = r_d
    n = normal
    one = lit(1.0, ior)
    cos_i = -dot(d, n)
    if cos_i >= lit(0.0, ior):
        eta = one / ior
    else:
        eta = ior
        n = neg(n)
        cos_i = -cos_i
    sin2_t = eta * eta * (one - cos_i * cos_i)
    if sin2_t > one:
        return add(d, scale(n, lit(2.0, ior) * cos_i))
    cos_t = math.sqrt(one - sin2_t)
    return add(scale(d, eta), scale(n, eta * cos_i - cos_t))


@njit(cache=True, error_model="numpy", inline="always")
def shade(shader, mat, r_d, position, normal, lights, shadows, bounces, planes, triangles,
          spheres, sphere_formula):
    """The slide's ``switch (*hit).shader``; the default case is the base colour. Glossy is
    Phong at the surface (which counts the emission) and then refraction, so the Phong case
    serves both and is compiled once."""
    if shader == LAMBERTIAN:
        result, n_shadow = lambertian(r_d, position, normal, mat, lights, shadows, planes,
                                      triangles, spheres, sphere_formula)
        return result, True, r_d, n_shadow
    if shader == PHONG or (bounces is not None and shader == GLOSSY):
        result, n_shadow = phong(r_d, position, normal, mat, lights, shadows, planes,
                                 triangles, spheres, sphere_formula)
        if shader == PHONG:
            return result, True, r_d, n_shadow
        return result, False, transparent(r_d, normal, mat[MAT_IOR]), n_shadow
    if bounces is not None:
        if shader == MIRROR:
            return load3(mat, MAT_EMISSION), False, mirror(r_d, normal), 0
        if shader == TRANSPARENT:
            return load3(mat, MAT_EMISSION), False, transparent(r_d, normal, mat[MAT_IOR]), 0
    return load3(mat, MAT_COLOR), True, r_d, 0
