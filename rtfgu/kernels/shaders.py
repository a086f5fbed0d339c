# release: solves a04 a05
"""The 02562 shaders, operation for operation as the materials' shade (rtfgu/materials), as
the terms the generated ``shade`` (rtfgu.kernels.dispatch) combines.

A shader kind of rtfgu.registry with ``brdf`` adds light through the one light loop
(``direct_<light>`` in the dispatch module) with its BRDF term
``brdf_<name>(mat, color, normal, w_o, w_i, cos_theta)``, the f_r that multiplies
L_i (n . w_i); the loop starts from ``surface(mat, color)``, L_e + L_a. ``color`` is the
surface's colour at the hit: the material's, or its texture's there. A kind that ``continues`` the path gives
its further rays with ``continue_<name>(mat, r_d, normal)``: (direction, weight, second
direction, second weight), the material's next ray (tmin SPAWN_EPSILON, a fresh tmax) and
the factor its radiance is weighted by (kr cr for a mirror, kt for a refraction), and a
second ray (a Transparent's reflection, where kr > 0) whose weight is 0 where there is none. Suffern's Phong is Lambertian plus a glossy lobe, and so
is ``brdf_phong`` here. kd and ka L_a come from the material's row (MAT_KD, MAT_AMBIENT).
"""
from __future__ import annotations

import math

from numba import njit

from ..layout import MAT_AMBIENT, MAT_EMISSION, MAT_IOR, MAT_KD, MAT_KT, MAT_REFLECTION, MAT_SHININESS, MAT_SPECULAR
from .float3 import add, div, dot, lit, load3, mul, neg, scale, sub


@njit(cache=True, error_model="numpy")
def surface(mat, color):
    """L_e + ka cd L_a (Matte.ambient): where every light loop starts."""
    return add(load3(mat, MAT_EMISSION), mul(color, load3(mat, MAT_AMBIENT)))


@njit(cache=True, error_model="numpy")
def brdf_lambertian(mat, color, normal, w_o, w_i, cos_theta):
    """kd cd / pi (Lambertian.f; Lambert's cosine law)."""
    rho_d = scale(color, mat[MAT_KD])
    return div(rho_d, lit(math.pi, cos_theta))


@njit(cache=True, error_model="numpy")
def brdf_phong(mat, color, normal, w_o, w_i, cos_theta):
    """rho_d / pi + rho_s (s + 2) / (2 pi) max(w_o . w_r, 0)^s, w_r = 2 (n . w_i) n - w_i
    (the normalised Phong lobe, 02562 worksheet 3)."""
    zero = lit(0, cos_theta)
    two = lit(2.0, zero)
    pi = lit(math.pi, zero)
    shininess = mat[MAT_SHININESS]
    w_r = sub(scale(normal, two * cos_theta), w_i)
    cos_r = dot(w_o, w_r)
    if zero > cos_r:
        cos_r = zero
    lobe = scale(load3(mat, MAT_SPECULAR), (shininess + two) / (two * pi) * cos_r ** shininess)
    rho_d = scale(color, mat[MAT_KD])
    return add(div(rho_d, pi), lobe)


@njit(cache=True, error_model="numpy")
def mirror(r_d, normal):
    """Perfect reflection: d - 2 (d . n) n."""
    return sub(r_d, scale(normal, lit(2.0, r_d[0]) * dot(r_d, normal)))


@njit(cache=True, error_model="numpy")
def snell(r_d, normal, ior):
    """Snell's law with eta = n1 / n2; d . n < 0 enters (eta = 1 / ior), otherwise the ray
    leaves (eta = ior, normal flipped): (direction, total internal reflection), the direction
    mirrored under total internal reflection (PerfectTransmitter.transmitted_direction)."""
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
        return add(d, scale(n, lit(2.0, ior) * cos_i)), True
    cos_t = math.sqrt(one - sin2_t)
    return add(scale(d, eta), scale(n, eta * cos_i - cos_t)), False


@njit(cache=True, error_model="numpy")
def transparent(r_d, normal, ior):
    """The refracted direction (the mirrored one under total internal reflection)."""
    return snell(r_d, normal, ior)[0]


@njit(cache=True, error_model="numpy")
def ends(r_d):
    """What a shader that ends the path gives for its further rays: none (weights 0)."""
    zero = lit(0.0, r_d[0])
    return r_d, (zero, zero, zero), r_d, (zero, zero, zero)


@njit(cache=True, error_model="numpy")
def continue_mirror(mat, r_d, normal):
    """Reflective: the mirror ray, weighted by kr cr (1 for the 02562 mirror)."""
    zero = lit(0.0, r_d[0])
    return mirror(r_d, normal), load3(mat, MAT_REFLECTION), r_d, (zero, zero, zero)


# Reflective with a Phong part: Phong's light loop (brdf_phong), then the same mirror ray.
continue_reflective = continue_mirror


@njit(cache=True, error_model="numpy")
def continue_transparent(mat, r_d, normal):
    """Transparent (Suffern ch. 27): the refracted ray weighted by kt and the reflected ray
    by kr cr; under total internal reflection only the reflected ray, weighted by 1."""
    zero = lit(0.0, r_d[0])
    one = lit(1.0, zero)
    w_t, tir = snell(r_d, normal, mat[MAT_IOR])
    if tir:
        return w_t, (one, one, one), r_d, (zero, zero, zero)
    kt = mat[MAT_KT]
    return w_t, (kt, kt, kt), mirror(r_d, normal), load3(mat, MAT_REFLECTION)


@njit(cache=True, error_model="numpy")
def continue_dielectric(mat, r_d, normal):
    """A Dielectric is traced by PathTrace only (its Fresnel choice); never reached here."""
    return continue_transparent(mat, r_d, normal)


# Glossy: Phong at the surface (its light loop), then the rays of a Transparent.
continue_glossy = continue_transparent
