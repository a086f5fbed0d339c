"""ConcavePartSphere: a ConvexPartSphere seen from inside (Suffern ch. 19, "Part objects":
the inside of a bowl). It is hit where the convex part is; its normal is the sphere's
turned inward, -(p - c) / r, the book's ``sr.normal = -sr.normal``.
"""
from __future__ import annotations

from ..float3 import Float3
from .convex_part_sphere import ConvexPartSphere


class ConcavePartSphere(ConvexPartSphere):
    def normal_at(self, position: Float3) -> Float3:
        """The sphere's normal, pointing in."""
        return -super().normal_at(position)
