"""MultiJittered: Chiu, Shirley and Wang's multi-jittered points (Suffern ch. 5,
"Multi-Jittered Sampling"): jittered in the n x n grid and n-rooks in the n^2 x n^2
subgrid. Points start in the canonical arrangement, then x is shuffled within each
column and y within each row of the grid, which keeps both properties."""
from __future__ import annotations

import math

from .sampler import Sampler


class MultiJittered(Sampler):
    needs_square = True

    def generate_samples(self) -> None:
        ### BEGIN SOLUTION
        n = math.isqrt(self.num_samples)
        subcell = 1.0 / self.num_samples
        for i, j in self.grid_cells():
            self.samples.append(((i * n + j) * subcell + self.rand_float() * subcell,
                                 (j * n + i) * subcell + self.rand_float() * subcell))
        # Shuffle x within each column of cells, then y within each row (Suffern's two loops,
        # one per axis: ``cell(i, j)`` is the place of cell j of column or row i).
        for axis, cell in ((0, lambda i, j: i * n + j), (1, lambda i, j: j * n + i)):
            for p in range(self.num_sets):
                base = p * self.num_samples
                for i in range(n):
                    for j in range(n):
                        k = self.rand_int(j, n - 1)
                        self._swap(base + cell(i, j), base + cell(i, k), axis)
        ### END SOLUTION

    def _swap(self, a: int, b: int, axis: int) -> None:
        pa, pb = list(self.samples[a]), list(self.samples[b])
        pa[axis], pb[axis] = pb[axis], pa[axis]
        self.samples[a], self.samples[b] = tuple(pa), tuple(pb)
