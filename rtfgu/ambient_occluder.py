"""AmbientOccluder: ambient light that only reaches a point through the directions nothing
blocks (Suffern ch. 17, "Ambient Occlusion").

``scene.lights.append(AmbientOccluder(ls, color))``: radiance L = ls * color arrives from
every direction of the hemisphere above a surface that no shape hides; a diffuse surface
of albedo rho then reflects rho L times the fraction of its (cosine-weighted) hemisphere
that is open. ``PathTrace`` samples it as a light (next-event estimation): one direction
w_i uniform on the hemisphere about the normal (density 1 / (2 pi), Suffern's hemisphere
map with e = 0), a shadow ray without end, and

    L_i = 2 pi L,   so f_r L_i (n . w_i) = rho L 2 (n . w_i) has expectation rho L

for an open hemisphere. With ``PathTrace(max_depth=1)`` and no other light that is
Suffern's ambient-occlusion image. The ray-cast loop draws no random numbers, so a scene
with an AmbientOccluder needs PathTrace (Scene.validate says so).
"""
from __future__ import annotations

import math

from .float3 import Float3, as_float3
from .lights import Light
from .sampling.maps import about, hemisphere_map


class AmbientOccluder:
    def __init__(self, ls: float = 1.0, color=(1.0, 1.0, 1.0)):
        if not (math.isfinite(ls) and ls >= 0):
            raise ValueError("AmbientOccluder.ls must be finite and >= 0, got %r" % (ls,))
        color = as_float3(color, "AmbientOccluder.color")
        if min(color.x, color.y, color.z) < 0.0:
            raise ValueError("AmbientOccluder.color must be >= 0 in every component, got %r" % (color,))
        self.radiance = color * float(ls)

    def sample_area(self, pos: Float3, normal: Float3, u: float, v: float) -> Light:
        """2 pi L toward a direction uniform on the hemisphere about ``normal``, unbounded."""
        return Light(self.radiance * (2.0 * math.pi), about(normal, hemisphere_map(u, v, 0.0)), math.inf)
