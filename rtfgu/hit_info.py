"""HitInfo: what a ray-surface intersection records, and what a material's ``shade`` reads.

The 02562 slides' ``struct HitInfo { has_hit, dist, position, normal, color, ... }`` doing
the job of Suffern's ``ShadeRec`` (ch. 14, "ShadeRec"): after the slide's fields come the
book's: the ``material`` of the shape hit, the ``ray`` that hit it, the ``depth`` of that
ray along its path (0 for an eye ray) and the ``scene`` (the book's ``w``, the world, whose
tracer, lights and ambient light a material reaches through it). ``color`` is the surface's
colour at the hit: its texture's there, else its material's ``cd``, else the shape's
(lecture 01: a shape carries a colour). ``pixel``, ``sample`` and ``seed`` say whose
numbers a stochastic step draws from the random stream (rtfgu.sampling.random).
"""
from __future__ import annotations

from .float3 import Float3


class HitInfo:
    __slots__ = ("has_hit", "dist", "position", "normal", "color", "material", "ray", "depth",
                 "scene", "pixel", "sample", "seed")

    def __init__(self, scene=None, depth: int = 0):
        self.has_hit = False
        self.dist = 0.0
        self.position = Float3(0.0)
        self.normal = Float3(0.0)
        self.color = Float3(0.0)
        self.material = None
        self.ray = None
        self.depth = depth
        self.scene = scene
        self.pixel = 0
        self.sample = 0
        self.seed = 0

    @property
    def shader(self) -> int:
        """The flat dispatch id of the material hit (rtfgu.registry.SHADERS)."""
        from .materials.material import BASE_COLOR
        return BASE_COLOR if self.material is None else self.material.shader

    @property
    def emission(self) -> Float3:
        """L_e of the surface hit (its material's ``get_Le``)."""
        return Float3(0.0) if self.material is None else self.material.get_Le(self)
