# release: solves a05
"""The glossy lobe of PathTrace's GlossyReflector on the numba path, operation for operation
as rtfgu.tracers.path_trace.glossy_lobe and lobe_direction."""
from __future__ import annotations

import math

from numba import njit

from .float3 import add, dot, lit, scale, sub
from .sampling import hemisphere_map


@njit(cache=True, error_model="numpy")
def glossy_lobe(specular, shininess, normal, w_o, w_i, cos_theta):
    """rho_s (s + 2) / (2 pi) max(w_o . w_r, 0)^s with w_r = 2 (n . w_i) n - w_i: zero
    without a power where rho_s is (a Matte's lobe: rho_s times a finite factor, the same
    zeros)."""
    zero = lit(0.0, cos_theta)
    if specular[0] == zero and specular[1] == zero and specular[2] == zero:
        return (zero, zero, zero)
    two = lit(2.0, zero)
    w_r = sub(scale(normal, two * cos_theta), w_i)
    cos_r = dot(w_o, w_r)
    if zero > cos_r:
        cos_r = zero
    return scale(specular, (shininess + two) / (two * lit(math.pi, zero)) * cos_r ** shininess)


@njit(cache=True, error_model="numpy")
def orthonormal_basis(n):
    """rtfgu.tracers.path_trace.orthonormal_basis (Duff et al. 2017)."""
    one = lit(1.0, n[0])
    sign = one if n[2] >= lit(0.0, one) else -one
    a = -one / (sign + n[2])
    b = n[0] * n[1] * a
    return (one + sign * n[0] * n[0] * a, sign * b, -sign * n[0]), (b, sign + n[1] * n[1] * a, -n[1])


@njit(cache=True, error_model="numpy")
def about(axis, local):
    """local (x, y, z) in the frame whose z is the unit ``axis``."""
    t, b = orthonormal_basis(axis)
    return add(add(scale(t, local[0]), scale(b, local[1])), scale(axis, local[2]))


@njit(cache=True, error_model="numpy")
def lobe_direction(w_r, shininess, u, v):
    """Density (s + 1) / (2 pi) cos^s(alpha) about the unit mirror direction w_r."""
    return about(w_r, hemisphere_map(u, v, shininess))
