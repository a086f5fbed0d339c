"""Jittered: one random point in each cell of an n x n grid (Suffern ch. 5, "Jittered
Sampling"); 02562 worksheet 3's stratified jitter with subdivision level s is
Jittered(s * s)."""
from __future__ import annotations

import math

from .sampler import Sampler


class Jittered(Sampler):
    needs_square = True

    def generate_samples(self) -> None:
        n = math.isqrt(self.num_samples)
        for j, k in self.grid_cells():
            x = (k + self.rand_float()) / n
            y = (j + self.rand_float()) / n
            self.samples.append((x, y))
