"""Lambertian: perfect diffuse reflection, f_r = kd cd / pi (Suffern ch. 13, "Lambertian";
sampled in ch. 26, "Lambertian::sample_f"; 02562 worksheet 7, "cosine-weighted hemisphere
sampling").

A path that leaves a diffuse point x picks its next direction w_i with some density
pdf(w_i) and carries on with the weight f_r (n . w_i) / pdf(w_i), so that the mean of many
paths is the reflected light

    L_r(x) = integral over the hemisphere of f_r L_i(x, w_i) (n . w_i) dw_i

whatever the density, as long as it is not 0 where the integrand is not (importance
sampling). With pdf = (n . w_i) / pi, cosine-weighted, the weight is exactly kd cd: no noise
comes from the direction when the incident light is the same from everywhere.

``cd`` None (or a texture: the book's ``SV_Lambertian``) is the surface's colour at the hit.
"""
from __future__ import annotations

import math

from ..float3 import Float3, dot
from ..sampling.maps import about, hemisphere_map
from ..validation import colour, number
from .brdf import BRDF


class Lambertian(BRDF):
    def __init__(self, kd: float = 1.0, cd=None):
        self.set_kd(kd)
        self.set_cd(cd)

    def set_kd(self, kd: float) -> None:
        self.kd = number(kd, "Lambertian.kd")

    def set_cd(self, cd) -> None:
        self.cd = colour(cd, "Lambertian.cd", surface=True)

    def rho(self, sr, wo=None) -> Float3:
        """The albedo kd cd."""
        # TODO a04: Lambertian.rho
        #   The albedo kd cd: self.surface_color(self.cd, sr) * self.kd (the surface colour is cd, or the
        #   shape's or texture's colour at the hit where cd is None).
        raise NotImplementedError('a04: Lambertian.rho')

    def f(self, sr, wo=None, wi=None) -> Float3:
        """f_r = kd cd / pi, the same for every pair of directions."""
        # TODO a04: Lambertian.f
        #   f_r = kd cd / pi: self.rho(sr) divided by pi.
        raise NotImplementedError('a04: Lambertian.f')

    def sample_f(self, sr, wo, u: float, v: float) -> tuple:
        """(f, w_i, pdf): a direction w_i about the unit normal sr.normal drawn from (u, v),
        uniform in [0, 1)^2, the BRDF f_r for it and the density pdf > 0 with which w_i was
        drawn (per unit solid angle). PathTrace multiplies the path's throughput by
        f (n . w_i) / pdf."""
        n = sr.normal
        # TODO a09: Lambertian.sample_f
        #   Draw w_i cosine-weighted about n = sr.normal: about(n, hemisphere_map(u, v, 1.0)) turns a direction
        #   about +z into one about n. Its density is pdf = (n . w_i) / pi. Return (self.f(sr, wo, w_i), w_i, pdf).
        raise NotImplementedError('a09: Lambertian.sample_f')
