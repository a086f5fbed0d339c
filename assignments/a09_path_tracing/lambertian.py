"""Suffern's ``Lambertian`` BRDF, sampled: the diffuse bounce of PathTrace (Suffern ch. 13,
"Lambertian", and ch. 26, "Lambertian::sample_f"; 02562 worksheet 7, "cosine-weighted
hemisphere sampling").

A diffuse surface reflects f_r = rho / pi into every direction. A path that leaves a diffuse
point x picks its next direction w_i with some density pdf(w_i) and carries on with the
weight f_r (n . w_i) / pdf(w_i), so that the mean of many paths is the reflected light

    L_r(x) = integral over the hemisphere of f_r L_i(x, w_i) (n . w_i) dw_i

whatever the density, as long as it is not 0 where the integrand is not (importance
sampling). With pdf = (n . w_i) / pi, cosine-weighted, the weight is exactly rho: no noise
comes from the direction when the incident light is the same from everywhere.
"""
from __future__ import annotations

import math

from .float3 import Float3, dot
from .sampling.maps import about, hemisphere_map


class Lambertian:
    """The diffuse BRDF of albedo ``rho`` (a Float3, each channel in [0, 1])."""

    def __init__(self, rho: Float3):
        self.rho = rho

    def f(self) -> Float3:
        """f_r = rho / pi, the same for every pair of directions."""
        return self.rho / math.pi

    def sample_f(self, n: Float3, u: float, v: float) -> tuple:
        """(f, w_i, pdf): a direction w_i about the unit normal n drawn from (u, v), uniform in
        [0, 1)^2, the BRDF f_r for it and the density pdf > 0 with which w_i was drawn
        (per unit solid angle). PathTrace multiplies the path's throughput by
        f (n . w_i) / pdf."""
        # TODO a09: Lambertian.sample_f
        #   Draw w_i cosine-weighted about n: about(n, hemisphere_map(u, v, 1.0)) turns a direction about
        #   +z into one about n. Its density is pdf = (n . w_i) / pi. Return (self.f(), w_i, pdf).
        raise NotImplementedError('a09: Lambertian.sample_f')
