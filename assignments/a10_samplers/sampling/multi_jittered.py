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
        # TODO a10: MultiJittered.generate_samples
        #   Append num_sets sets of n^2 = num_samples points (Suffern ch. 5, "Multi-Jittered Sampling"):
        #   start every set in the canonical arrangement, the point of grid cell (row i, column j) in
        #   subcell (i n + j) of x and (j n + i) of y (a subcell is 1 / num_samples wide), jittered inside
        #   its subcell with self.rand_float(); then shuffle x among the points of each grid column and y
        #   among those of each grid row, with k = self.rand_int(j, n - 1) as the book does, so that the
        #   points stay one per grid cell (jittered) and one per subcell column and row (n-rooks).
        #   self.grid_cells() gives the cells (row, column), set after set; draw every random number from
        #   the sampler's own stream (rand_float, rand_int), so that the seed decides the points.
        raise NotImplementedError('a10: MultiJittered.generate_samples')

    def _swap(self, a: int, b: int, axis: int) -> None:
        pa, pb = list(self.samples[a]), list(self.samples[b])
        pa[axis], pb[axis] = pb[axis], pa[axis]
        self.samples[a], self.samples[b] = tuple(pa), tuple(pb)
