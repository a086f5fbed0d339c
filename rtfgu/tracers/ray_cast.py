"""RayCast: the nearest hit's shading, no secondary rays (Suffern ch. 14, "RayCast"): a
mirror or a refraction shows only its own surface's shading (what its rays would see is
black). Whitted (rtfgu/tracers/whitted.py) follows them."""
from __future__ import annotations

from ..float3 import Float3
from .tracer import Tracer


class RayCast(Tracer):
    max_depth = 1

    def trace_ray(self, ray, depth: int = 0) -> Float3:
        if depth >= self.max_depth:
            return Float3(0.0)
        sr = self.hit(ray, depth)
        if sr is None:
            return self.world.background_radiance(ray.direction)
        return self.shade(sr)

    def shade(self, sr) -> Float3:
        return sr.material.shade(sr)

    def __repr__(self) -> str:
        return "RayCast()"
