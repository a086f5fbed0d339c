"""NRooks: one point in each row and each column of an n x n grid, as n rooks that do not
attack each other (Suffern ch. 5, "n-Rooks Sampling"): points on the diagonal, then the x
and the y coordinates shuffled within each set."""
from __future__ import annotations

from .sampler import Sampler


class NRooks(Sampler):
    def generate_samples(self) -> None:
        n = self.num_samples
        for p in range(self.num_sets):
            for j in range(n):
                x = (j + self.rand_float()) / n
                y = (j + self.rand_float()) / n
                self.samples.append((x, y))
        self.shuffle_x_coordinates()
        self.shuffle_y_coordinates()

    def _shuffle(self, axis: int) -> None:
        n = self.num_samples
        for p in range(self.num_sets):
            base = p * n
            for i in range(n - 1):
                target = base + self.rand_int(0, n - 1)
                a, b = list(self.samples[base + i + 1]), list(self.samples[target])
                a[axis], b[axis] = b[axis], a[axis]
                self.samples[base + i + 1] = tuple(a)
                self.samples[target] = tuple(b)

    def shuffle_x_coordinates(self) -> None:
        self._shuffle(0)

    def shuffle_y_coordinates(self) -> None:
        self._shuffle(1)
