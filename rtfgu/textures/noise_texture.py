"""NoiseTexture: a solid texture drawn from a LatticeNoise (Suffern ch. 31): FBmTexture,
WrappedFBmTexture and RampFBmTexture hold the noise the book passes to their constructors.
Its fields (which interpolation, num_octaves, lacunarity, gain, fbm_max) are the noise's, so
the flat layout packs them into the texture's row."""
from __future__ import annotations

from ..noise.lattice_noise import LatticeNoise
from .solid_texture import SolidTexture

# The flat layout's id of each noise class (the ``noise`` field of a texture's row).
NOISE_IDS = {"LinearNoise": 0, "CubicNoise": 1}


class NoiseTexture(SolidTexture):
    def __init__(self, noise: LatticeNoise, scale: float = 1.0):
        super().__init__(scale)
        if not isinstance(noise, LatticeNoise) or type(noise).__name__ not in NOISE_IDS:
            raise ValueError("%s.noise must be a LinearNoise or a CubicNoise, got %r" % (type(self).__name__, noise))
        self.noise = noise

    @property
    def noise_id(self) -> int:
        return NOISE_IDS[type(self.noise).__name__]

    # Does get_color call the noise's vector_noise or vector_fbm?
    uses_vector_noise = False

    @property
    def noise_features(self) -> tuple:
        """The WGSL features of the noise: its interpolation and, where used, vector noise."""
        names = ("lattice_noise", {0: "linear_noise", 1: "cubic_noise"}[self.noise_id])
        return names + ("vector_noise",) if self.uses_vector_noise else names

    num_octaves = property(lambda self: self.noise.num_octaves)
    lacunarity = property(lambda self: self.noise.lacunarity)
    gain = property(lambda self: self.noise.gain)
    fbm_max = property(lambda self: self.noise.fbm_max)
