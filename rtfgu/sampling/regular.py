"""Regular: the centres of an n x n grid of cells (Suffern ch. 5, "Regular Sampling")."""
from __future__ import annotations

import math

from .sampler import Sampler


class Regular(Sampler):
    needs_square = True

    def generate_samples(self) -> None:
        n = math.isqrt(self.num_samples)
        for j, k in self.grid_cells():
            self.samples.append(((k + 0.5) / n, (j + 0.5) / n))
