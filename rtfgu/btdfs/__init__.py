"""The BTDFs transparent materials are built from (Suffern ch. 27-28)."""
from .btdf import BTDF
from .perfect_transmitter import PerfectTransmitter

__all__ = ["BTDF", "PerfectTransmitter"]
try:        # a student release before a05 leaves it out: it refracts as a05 does
    from .fresnel_transmitter import FresnelTransmitter
    __all__.append("FresnelTransmitter")
except ImportError:
    pass
