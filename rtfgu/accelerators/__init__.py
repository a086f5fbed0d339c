"""Acceleration structures of the lecture layer (Suffern ch. 19 bounding boxes, ch. 22;
PBRT-v4 ch. 7): ``BBox`` (an axis-aligned bounding box and its slab test) and ``BVH`` (a
bounding volume hierarchy built with the binned surface area heuristic)."""
from .bbox import BBox
from .bvh import BVH

__all__ = ["BBox", "BVH"]
