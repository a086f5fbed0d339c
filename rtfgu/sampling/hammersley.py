"""Hammersley: the points (j / n, phi_2(j)), phi_2 the radical inverse in base 2 (Suffern
ch. 5, "Hammersley Sampling"). Every set holds the same points; the sets differ only in
their shuffled order."""
from __future__ import annotations

from .sampler import Sampler


def phi(j: int) -> float:
    """The radical inverse of j in base 2: its binary digits mirrored about the point."""
    x = 0.0
    f = 0.5
    while j:
        x += f * (j % 2)
        j //= 2
        f *= 0.5
    return x


class Hammersley(Sampler):
    def generate_samples(self) -> None:
        for p in range(self.num_sets):
            for j in range(self.num_samples):
                self.samples.append((j / self.num_samples, phi(j)))
