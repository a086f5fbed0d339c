"""Material: which shader a shape uses and the few numbers that shader reads.

The shader ids are the cases of the 02562 ``shade`` switch ("The signature of an
intersection function and that of a shader"): 1 lambertian, 2 phong, 3 mirror, and the
default case returns the base colour. 4 (transparent) and 5 (glossy) are the 02562
worksheet-3 shaders that follow them; 6 (emissive) is Suffern's ``Emissive`` (ch. 18): a
surface that only emits, the shape of an ``AreaLight``; 7 (dielectric) is Suffern's
``Dielectric`` (ch. 28), glass with Fresnel reflection and absorption (rtfgu.fresnel); 8
(glossy_reflector) is Suffern's ``GlossyReflector`` (ch. 25), Phong whose lobe PathTrace
also samples.

Lecture 01's shapes carry a colour only; a shape built that way gets ``BASE_COLOR`` and
the slide's render loop shows each pixel in the colour of the nearest shape.
"""
from __future__ import annotations

import math

from .float3 import Float3, as_float3

BASE_COLOR = 0
LAMBERTIAN = 1
PHONG = 2
MIRROR = 3
TRANSPARENT = 4
GLOSSY = 5
EMISSIVE = 6
DIELECTRIC = 7
GLOSSY_REFLECTOR = 8

SHADER_NAMES = {
    BASE_COLOR: "base_color",
    LAMBERTIAN: "lambertian",
    PHONG: "phong",
    MIRROR: "mirror",
    TRANSPARENT: "transparent",
    GLOSSY: "glossy",
    EMISSIVE: "emissive",
    DIELECTRIC: "dielectric",
    GLOSSY_REFLECTOR: "glossy_reflector",
}


class Material:
    """shader id; specular reflectance rho_s and shininess s (Phong, glossy); index of
    refraction (transparent, glossy, dielectric); emitted radiance L_e (any shader that sees
    light); a texture (rtfgu.textures), whose colour at the hit replaces the shape's colour;
    absorption sigma_a per unit length inside a dielectric (Bouguer's law, rtfgu.fresnel)."""

    __slots__ = ("shader", "specular", "shininess", "ior", "emission", "texture", "absorption")

    def __init__(self, shader: int = BASE_COLOR, specular=None, shininess: float = 0.0,
                 ior: float = 1.0, emission=None, texture=None, absorption=None):
        if shader not in SHADER_NAMES:
            raise ValueError("Material.shader must be one of %s, got %r" % (sorted(SHADER_NAMES), shader))
        self.shader = shader
        self.specular = Float3(0.0) if specular is None else as_float3(specular, "Material.specular")
        self.emission = Float3(0.0) if emission is None else as_float3(emission, "Material.emission")
        if min(self.emission.x, self.emission.y, self.emission.z) < 0.0:
            raise ValueError("Material.emission must be >= 0 in every component (radiance), got %r"
                             % (self.emission,))
        if not (math.isfinite(shininess) and shininess >= 0):
            raise ValueError("Material.shininess must be finite and >= 0, got %r" % (shininess,))
        if not (math.isfinite(ior) and ior > 0):
            raise ValueError("Material.ior must be finite and > 0, got %r" % (ior,))
        self.absorption = Float3(0.0) if absorption is None else as_float3(absorption, "Material.absorption")
        if min(self.absorption.x, self.absorption.y, self.absorption.z) < 0.0:
            raise ValueError("Material.absorption must be >= 0 in every component (per unit length), got %r"
                             % (self.absorption,))
        self.shininess = float(shininess)
        self.ior = float(ior)
        if texture is not None:
            from .textures.texture import Texture
            if not isinstance(texture, Texture):
                raise ValueError("Material.texture must be a Texture or None, got %r" % (texture,))
        self.texture = texture

    def __repr__(self) -> str:
        return "Material(%s, specular=%r, shininess=%r, ior=%r, emission=%r, texture=%r)" % (
            SHADER_NAMES[self.shader], self.specular, self.shininess, self.ior, self.emission,
            self.texture)


class Emissive(Material):
    """Suffern's ``Emissive`` (ch. 18): emitted radiance L_e = ls * ce and no reflection; a
    shape with it is seen in L_e from its front (the side its normal points to) and lights
    the scene through an ``AreaLight`` (rtfgu.area_light)."""

    __slots__ = ()

    def __init__(self, ls: float = 1.0, ce=(1.0, 1.0, 1.0)):
        if not (math.isfinite(ls) and ls >= 0):
            raise ValueError("Emissive.ls (radiance scale) must be finite and >= 0, got %r" % (ls,))
        super().__init__(EMISSIVE, emission=as_float3(ce, "Emissive.ce") * float(ls))


class Dielectric(Material):
    """Suffern's ``Dielectric`` (ch. 28; 02562 worksheet 8): glass with index of refraction
    ``ior`` (inside over outside) and ``absorption`` sigma_a per unit length, (0, 0, 0) for
    clear glass. PathTrace reflects or refracts it by Fresnel's reflectance and absorbs
    inside it (rtfgu/fresnel.py); the ray-cast loop refracts it as ``transparent``."""

    __slots__ = ()

    def __init__(self, ior: float = 1.5, absorption=(0.0, 0.0, 0.0)):
        super().__init__(DIELECTRIC, ior=ior, absorption=absorption)


class GlossyReflector(Material):
    """Suffern's ``GlossyReflector`` (ch. 25, "Glossy Reflection"): Phong's BRDF, a diffuse
    part (the shape's colour) and the normalised lobe rho_s (s + 2) / (2 pi) cos^s(alpha)
    about the mirror direction (02562 worksheet 3). The ray-cast loop shades it as ``phong``;
    PathTrace also reflects light through the lobe, sampling it (rtfgu.path_trace)."""

    __slots__ = ()

    def __init__(self, specular=(0.5, 0.5, 0.5), shininess: float = 100.0):
        super().__init__(GLOSSY_REFLECTOR, specular=as_float3(specular, "GlossyReflector.specular"),
                         shininess=shininess)
