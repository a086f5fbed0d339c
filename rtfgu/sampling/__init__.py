"""Sampling (Suffern ch. 5-7): the random stream, the samplers and the maps of their points
to the disk and the hemisphere."""
from .hammersley import Hammersley
from .jittered import Jittered
from .maps import concentric_map, hemisphere_map
from .multi_jittered import MultiJittered
from .n_rooks import NRooks
from .random import random_float, random_u32
from .regular import Regular
from .sampler import Sampler
from .sobol import Sobol

__all__ = ["Sampler", "Regular", "Jittered", "NRooks", "MultiJittered", "Hammersley", "Sobol",
           "concentric_map", "hemisphere_map", "random_float", "random_u32"]
