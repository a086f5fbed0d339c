"""Camera: maps a point (sx, sy) of the image plane [-1, 1]^2 to a ray (lecture 01, "Camera")."""
from __future__ import annotations

from abc import ABC, abstractmethod

from ..ray import Ray


class Camera(ABC):
    # True for a camera whose gen_ray also takes a point of the lens (ThinLens).
    uses_lens = False

    @abstractmethod
    def gen_ray(self, sx: float, sy: float) -> Ray:
        """The ray through (sx, sy), with -1 <= sx, sy <= 1; (-1, -1) is the bottom left."""
