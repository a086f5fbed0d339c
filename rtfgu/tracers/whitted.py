"""Whitted: recursive ray tracing (Suffern ch. 24, "Whitted"; Whitted 1980; 02562 "Intersecting
with the scene and tracing a path").

A material's ``shade`` calls ``trace_ray(ray, depth + 1)`` for each ray it sends on: a
mirror its reflected ray, a transparent surface its reflected *and* its refracted ray; a
ray at depth ``max_depth`` is not traced (black). The default, 10 rays along a path, is
the 02562 path loop's ``const max_depth = 10``; it is the default tracer of a Scene.
"""
from __future__ import annotations

from .ray_cast import RayCast
from .tracer import check_max_depth

# The 02562 path loop's bound (``main_fs``: const max_depth = 10).
MAX_DEPTH = 10
# The deepest Whitted recursion Python's stack allows with room to spare.
MAX_WHITTED_DEPTH = 64


class Whitted(RayCast):
    def __init__(self, max_depth: int = MAX_DEPTH):
        super().__init__()
        self.max_depth = check_max_depth(max_depth, "%s.max_depth" % type(self).__name__, MAX_WHITTED_DEPTH)

    def __repr__(self) -> str:
        return "%s(max_depth=%r)" % (type(self).__name__, self.max_depth)
