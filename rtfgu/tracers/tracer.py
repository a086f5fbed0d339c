"""Tracer: how a ray becomes a colour (Suffern ch. 3 and 14, "Tracers").

``trace_ray(ray, depth)`` returns the radiance arriving along ``ray``, a ray ``depth``
levels below the eye's (0 for an eye ray); the materials' ``shade`` methods call it for the
rays they send on (a mirror's, a refraction's). The tracer reaches the scene through
``world`` (the book's ``world_ptr``), which the renderer sets, and the random stream's
(pixel, sample, seed) through ``stream``, which the renderer sets before each eye ray
(rtfgu.sampling.random: the numbers a pixel's sample draws).

Which material method a tracer calls, and how deep it goes:

=================  ========================  ==========================================
tracer             calls                     rays
=================  ========================  ==========================================
RayCast            ``shade``                 the eye ray only (secondary rays are black)
Whitted            ``shade``                 reflected and transmitted, to ``max_depth``
AreaLighting       ``area_light_shade``      as Whitted; area lights sampled
PathTrace          ``path_shade``            one path, lights sampled at every vertex
GlobalTrace        ``global_shade``          one path, lights sampled at the first vertex
=================  ========================  ==========================================

``max_depth`` counts the rays along a path, the eye's included (02562: ``const max_depth =
10``): a ray at depth ``max_depth`` is not traced. The book counts from 0 (``depth >
max_depth``), so its max_depth 9 is 10 here.
"""
from __future__ import annotations

from ..float3 import Float3
from ..hit_info import HitInfo


def check_max_depth(value, name: str, top: int) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= top:
        raise ValueError("%s must be an integer in [1, %d], got %r" % (name, top, value))
    return value


class Tracer:
    samples_area_lights = False     # AreaLight.get_direction draws points of the shape
    max_depth = 1

    def __init__(self):
        self.world = None
        self.stream = (0, 0, 0)

    def trace_ray(self, ray, depth: int = 0) -> Float3:
        raise NotImplementedError

    def hit(self, ray, depth: int):
        """The HitInfo of ``ray``'s nearest hit in the world (its material, the ray, the
        depth, the world and the stream filled in), or None on a miss."""
        sr = HitInfo(self.world, depth)
        sr.pixel, sr.sample, sr.seed = self.stream
        if not self.world.intersect(ray, sr):
            return None
        sr.ray = ray
        return sr

    def validate(self, scene) -> None:
        """Raise a ValueError naming the field if ``scene`` cannot be traced so."""

    def __repr__(self) -> str:
        return "%s(max_depth=%r)" % (type(self).__name__, self.max_depth)
