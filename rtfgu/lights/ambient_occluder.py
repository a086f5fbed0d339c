"""AmbientOccluder: ambient light that only reaches a point through the directions nothing
blocks (Suffern ch. 17, "Ambient Occlusion").

``scene.lights.append(AmbientOccluder(ls, color))``: radiance L = ls * color arrives from
every direction of the hemisphere above a surface that no shape hides; a diffuse surface
of albedo rho then reflects rho L times the fraction of its (cosine-weighted) hemisphere
that is open. A tracer that samples lights (PathTrace) asks it as a light: ``get_direction``
draws one direction w_i uniform on the hemisphere about the normal (density 1 / (2 pi),
Suffern's hemisphere map with e = 0; the light's sampler's point, ``set_sampler``, or the
random stream's), the shadow ray has no end, and

    L / pdf = 2 pi L,   so f_r (L / pdf) (n . w_i) = rho L 2 (n . w_i) has expectation rho L

for an open hemisphere. With ``PathTrace(max_depth=1)`` and no other light that is
Suffern's ambient-occlusion image. The book makes the occluder the world's ambient light
instead, asked once per shading point by the ray-cast tracers; here the ray-cast tracers
draw no random numbers, so a scene with an AmbientOccluder needs PathTrace (Scene.validate
says so).
"""
from __future__ import annotations

import math

from ..float3 import Float3
from ..sampling.maps import about, hemisphere_map
from .light import Light


class AmbientOccluder(Light):
    drawn_by_ray_casting = False
    def __init__(self, ls: float = 1.0, color=(1.0, 1.0, 1.0)):
        self.set_ls(ls)
        self.set_color(color)

    @property
    def radiance(self) -> Float3:
        """L = ls cl, the flat layout's field."""
        return self.intensity

    def get_direction(self, sr) -> Float3:
        u, v = sr.scene.light_sample(self, sr)
        return about(sr.normal, hemisphere_map(u, v, 0.0))

    def L(self, sr) -> Float3:
        return self.radiance

    def pdf(self, sr) -> float:
        return 1.0 / (2.0 * math.pi)

    def incident(self, sr) -> Float3:
        """L / pdf = 2 pi L."""
        return self.radiance * (2.0 * math.pi)
