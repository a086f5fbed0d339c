"""The BRDFs materials are built from (Suffern ch. 13, 15, 24, 25, 28)."""
from .brdf import BRDF
from .glossy_specular import GlossySpecular
from .lambertian import Lambertian
from .perfect_specular import PerfectSpecular

__all__ = ["BRDF", "Lambertian", "GlossySpecular", "PerfectSpecular"]
try:        # a student release before a05 leaves it out: it refracts as a05 does
    from .fresnel_reflector import FresnelReflector
    __all__.append("FresnelReflector")
except ImportError:
    pass
