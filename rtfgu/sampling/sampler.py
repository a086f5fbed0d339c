"""Sampler: sets of sample points in the unit square (Suffern ch. 5, "Sampler").

A sampler holds ``num_sets`` sets of ``num_samples`` points each, made once when it is
built (``generate_samples``), and a shuffled order of each set (``setup_shuffled_indices``).
Suffern's ``sample_unit_square()`` keeps a counter and jumps to a random set every
``num_samples`` calls; that counter is shared by all pixels, so it cannot run on many
cores. Here the jump is the random stream's hash of the pixel and the sample index
(rtfgu/sampling/random.py), so a pixel's samples do not depend on the order pixels are
rendered in, and numba and WGSL pick the same points from the same arrays.

The sets are made with the sampler's own ``seed``; ``render(..., seed=...)`` picks which
set each pixel uses. The maps to the unit disk and the hemisphere (ch. 6-7) are in
rtfgu/sampling/maps.py.
"""
from __future__ import annotations

import functools
import math
from abc import ABC, abstractmethod

from .maps import concentric_map, hemisphere_map
from .random import LENS_SET, PIXEL_SET, check_seed, random_float, random_u32

# The dimension of the random stream the sets are generated from (the pixel counter is 0).
GENERATION = 0xFFFF


class Sampler(ABC):
    """num_samples points per set, num_sets sets (Suffern's default 83)."""

    # Regular, Jittered and MultiJittered lay their points on an n x n grid.
    needs_square = False

    def __init__(self, num_samples: int = 1, num_sets: int = 83, seed: int = 0):
        name = type(self).__name__
        for field, value in (("num_samples", num_samples), ("num_sets", num_sets)):
            if isinstance(value, bool) or not isinstance(value, int) or value < 1:
                raise ValueError("%s.%s must be an integer >= 1, got %r" % (name, field, value))
        if self.needs_square and math.isqrt(num_samples) ** 2 != num_samples:
            raise ValueError("%s.num_samples must be a square number (n x n grid), got %d; "
                             "NRooks and Hammersley take any number" % (name, num_samples))
        self.num_samples = num_samples
        self.num_sets = num_sets
        self.seed = check_seed(seed)
        self.samples = []            # num_sets * num_samples points (x, y) in [0, 1)^2
        self.shuffled_indices = []   # per set, a permutation of 0 .. num_samples - 1
        self._count = 0
        self.generate_samples()
        self.setup_shuffled_indices()

    @abstractmethod
    def generate_samples(self) -> None:
        """Append num_sets * num_samples points to self.samples, set after set."""

    def grid_cells(self):
        """(row, column) of every cell of the n x n grid (n^2 = num_samples), row by row, set
        after set: the three loops of Suffern's Regular, Jittered and MultiJittered."""
        n = math.isqrt(self.num_samples)
        for _ in range(self.num_sets):
            for j in range(n):
                for k in range(n):
                    yield j, k

    def rand_float(self) -> float:
        """The next number in [0, 1) of this sampler's generation stream."""
        self._count += 1
        return random_float(0, self._count - 1, GENERATION, self.seed)

    def rand_int(self, low: int, high: int) -> int:
        """An integer in [low, high]."""
        return low + min(int(self.rand_float() * (high - low + 1)), high - low)

    def setup_shuffled_indices(self) -> None:
        """A shuffled order of every set (Fisher-Yates)."""
        n = self.num_samples
        for _ in range(self.num_sets):
            order = list(range(n))
            for i in range(n - 1, 0, -1):
                j = self.rand_int(0, i)
                order[i], order[j] = order[j], order[i]
            self.shuffled_indices.extend(order)

    def sample_unit_square(self, pixel: int, index: int, seed: int = 0,
                           dimension: int = PIXEL_SET) -> tuple:
        """Sample ``index`` of ``pixel``: a point of the set the random stream picks for
        this pixel (and every num_samples samples), in the set's shuffled order."""
        n = self.num_samples
        jump = (random_u32(pixel, index // n, dimension, seed) % self.num_sets) * n
        return self.samples[jump + self.shuffled_indices[jump + index % n]]

    def sample_unit_disk(self, pixel: int, index: int, seed: int = 0,
                         dimension: int = LENS_SET) -> tuple:
        """A point of the unit disk: the square sample through the concentric map."""
        return concentric_map(*self.sample_unit_square(pixel, index, seed, dimension))

    def sample_hemisphere(self, pixel: int, index: int, e: float, seed: int = 0,
                          dimension: int = PIXEL_SET):
        """A direction of the hemisphere about +z with density cos^e (theta)."""
        return hemisphere_map(*self.sample_unit_square(pixel, index, seed, dimension), e)

    def with_num_samples(self, num_samples: int) -> "Sampler":
        """The same kind of sampler with another number of samples (render(..., spp=N)),
        made once per kind, count, number of sets and seed (sampler_of)."""
        return sampler_of(type(self), num_samples, self.num_sets, self.seed)

    def __repr__(self) -> str:
        return "%s(%d, num_sets=%d, seed=%d)" % (type(self).__name__, self.num_samples,
                                                 self.num_sets, self.seed)


@functools.lru_cache(maxsize=32)
def sampler_of(cls, num_samples: int, num_sets: int = 83, seed: int = 0) -> "Sampler":
    """``cls(num_samples, num_sets, seed)``, kept for the next render that asks for it:
    making the sets is pure Python (Suffern's loops) and a progressive render or a notebook
    asks for the same sampler pass after pass. Rendering reads a sampler and never changes it."""
    return cls(num_samples, num_sets, seed)
