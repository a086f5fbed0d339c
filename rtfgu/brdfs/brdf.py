"""BRDF: how a surface reflects light from one direction into another (Suffern ch. 13,
"BRDFs").

``f(sr, wo, wi)`` is the BRDF f_r for light arriving along wi and leaving along wo (both unit,
pointing away from the surface); ``sample_f(sr, wo, u, v)`` draws a direction wi and returns
(f, wi, pdf), the pdf per unit solid angle with which wi was drawn; ``rho(sr, wo)`` is the
bihemispherical reflectance, the albedo. The book's ``sample_f`` draws its point from the
BRDF's own sampler; here the caller passes the point (u, v) of the unit square, as PBRT-v4's
``Sample_f(wo, uc, u)`` does, and ``sample_point`` draws it: from the BRDF's sampler where
one is set (``set_sampler``, the book's, for its sampler comparisons), else from the random
stream (rtfgu.sampling.random) in the dimensions the path tracer gives, the same numbers on
every path. So a test can hand ``sample_f`` any point and check the map it makes.
"""
from __future__ import annotations

from ..float3 import Float3


class BRDF:
    sampler = None

    def set_sampler(self, sampler) -> None:
        """The book's ``set_sampler``: the points ``sample_f`` turns into directions come from
        this sampler (its own sets, rtfgu.sampling) instead of the random stream."""
        from ..sampling.sobol import check_own_sampler

        self.sampler = check_own_sampler(type(self).__name__, sampler)

    def sample_point(self, sr, u_dimension: int) -> tuple:
        """(u, v) in [0, 1)^2 for the direction drawn at ``sr``: the sampler's point for the
        pixel's sample, or the scene's pair (rtfgu.sampling.sobol.pair_sample: the stream's numbers,
        or Sobol's pair where the scene's sampler is a Sobol) in path dimensions u_dimension and the next."""
        from ..sampling.random import path_dimension
        from ..sampling.sobol import pair_sample

        dimension = path_dimension(sr.depth, u_dimension)
        if self.sampler is not None:
            return self.sampler.sample_unit_square(sr.pixel, sr.sample, sr.seed, dimension)
        return pair_sample(getattr(sr.scene, "sampler", None), sr.pixel, sr.sample, dimension, sr.seed)

    def f(self, sr, wo, wi) -> Float3:
        return Float3(0.0)

    def sample_f(self, sr, wo, u: float, v: float) -> tuple:
        raise NotImplementedError("%s has no sample_f" % type(self).__name__)

    def rho(self, sr, wo) -> Float3:
        return Float3(0.0)

    @staticmethod
    def surface_color(cd, sr) -> Float3:
        """cd, or the surface's colour at the hit where cd is None or a texture."""
        return cd if isinstance(cd, Float3) else sr.color
