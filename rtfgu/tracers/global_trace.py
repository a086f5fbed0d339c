"""GlobalTrace: path tracing with the lights sampled at the first vertex only (Suffern ch. 26,
"GlobalTrace").

The direct light at the point the eye sees is sampled as AreaLighting does (next-event
estimation); every later vertex only bounces, and the light of an emitter is counted when a
path hits it, except by the bounce right after the first vertex, whose light that vertex
sampled already. Beside PathTrace (which samples the lights at every vertex) it shows what
next-event estimation buys: the same mean, more noise.
"""
from __future__ import annotations

from .path_trace import PathTrace


class GlobalTrace(PathTrace):
    def samples_lights_at(self, depth: int) -> bool:
        return depth == 0
