"""Noise (Suffern ch. 31): lattice noise with linear or cubic interpolation, and its sums."""
from .cubic_noise import CubicNoise
from .lattice_noise import LatticeNoise
from .linear_noise import LinearNoise

__all__ = ["LatticeNoise", "LinearNoise", "CubicNoise"]
