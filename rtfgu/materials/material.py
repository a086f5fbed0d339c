"""Material: how a surface turns the light that reaches it into the light it sends to the eye
(Suffern ch. 14, "Materials").

A material is built from BRDFs and BTDFs (rtfgu/brdfs, rtfgu/btdfs) and has the book's
methods, one per tracer that calls it (rtfgu/tracers):

* ``shade(sr)``: the ray-cast tracers (RayCast, Whitted): direct light from every light, the
  ambient term, and for a reflective or transparent material the rays it traces further;
* ``area_light_shade(sr)``: AreaLighting: the same with area lights sampled (L G / pdf);
* ``path_shade(sr)``: PathTrace: what a path gains and how it goes on at this vertex;
* ``global_shade(sr)``: GlobalTrace: path_shade with the direct light only at the first
  vertex's emitters counted (rtfgu/tracers/global_trace.py);
* ``get_Le(sr)``: the radiance the surface emits.

``sr`` is the HitInfo (rtfgu/hit_info.py). ``cd`` is the surface's colour: a colour, a
texture (the book's ``SV_`` materials: the texture's colour at the hit), or None, the colour
of the shape (lecture 01's shapes carry one). ``emission`` L_e is what ``get_Le`` returns:
an ``Emissive``'s radiance, or a reflecting surface's own glow (an OBJ material's ``Ke``).

The numba and WGSL paths dispatch on ``shader``, the id of the case of the 02562 ``shade``
switch this material is ("The signature of an intersection function and that of a
shader"); its BRDF parameters reach them as the flat layout's Material row (rtfgu.layout:
``specular``, ``shininess``, ``ior``, ``absorption``, ``kd``, ``ka``). ``Material`` itself
is the switch's default case: the surface's colour, what lecture 01's render loop shows.
"""
from __future__ import annotations

from ..float3 import Float3, dot
from ..textures.texture import Texture
from ..validation import colour

BASE_COLOR = 0
LAMBERTIAN = 1
PHONG = 2
MIRROR = 3
TRANSPARENT = 4
GLOSSY = 5
EMISSIVE = 6
DIELECTRIC = 7
GLOSSY_REFLECTOR = 8
REFLECTIVE = 9

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
    REFLECTIVE: "reflective",
}


def set_on(part: str, method: str, check, field: str):
    """The book's ``set_<field>`` of a material built from parts: the value, checked by
    ``check`` (rtfgu/validation.py) under the name ``<Class>.<field>``, is handed to
    ``self.<part>.<method>``; Matte's ``set_kd`` sets its diffuse BRDF's kd, as the book's does."""
    def setter(self, value) -> None:
        getattr(getattr(self, part), method)(check(value, "%s.%s" % (type(self).__name__, field)))
    setter.__name__ = "set_" + field
    setter.__doc__ = "Set %s: ``self.%s.%s`` after checking the value." % (field, part, method)
    return setter


def read_from(part: str, attribute: str, doc: str) -> property:
    """A material's field that lives in one of its parts: ``self.<part>.<attribute>``."""
    return property(lambda self: getattr(getattr(self, part), attribute), doc=doc)


class PathVertex:
    """What ``path_shade`` returns: the radiance ``L`` the vertex adds (None: nothing; its
    emission, where the path may count it, is the tracer's to add), the factors ``f`` (a
    colour, None: 1) and ``scale`` (a number) by which the path's throughput is multiplied,
    in that order, the next ``ray`` (None: the path ends here) and whether emission seen by
    that ray counts (``sees_emission``: after a mirror or a refraction; not after a diffuse
    bounce, whose lights were sampled already).

    The book's ``path_shade`` recurses into ``trace_ray`` and returns the radiance; here it
    says how the path goes on and PathTrace multiplies the throughput along a loop, as the
    numba and WGSL kernels do, so the three paths agree bit for bit (docs/suffern.md)."""

    __slots__ = ("L", "f", "scale", "ray", "sees_emission")

    def __init__(self, L: Float3 | None, f: Float3 | None = None, scale: float = 1.0, ray=None,
                 sees_emission: bool = False):
        self.L, self.f, self.scale, self.ray, self.sees_emission = L, f, scale, ray, sees_emission


class Material:
    shader = BASE_COLOR
    cd = None

    def __init__(self, cd=None, emission=None):
        self.cd = colour(cd, type(self).__name__ + ".cd", surface=True)
        self.emission = Float3(0.0) if emission is None else colour(emission, type(self).__name__ + ".emission")

    # -- the book's methods
    def shade(self, sr) -> Float3:
        """The switch's default case: the surface's colour."""
        return sr.color

    def area_light_shade(self, sr) -> Float3:
        return self.shade(sr)

    def path_shade(self, sr) -> PathVertex:
        """A path that meets a flat colour sees that colour and ends."""
        return PathVertex(sr.color)

    @staticmethod
    def face_ray(sr) -> None:
        """Turn sr.normal to the side the ray comes from (a surface seen from behind)."""
        if dot(sr.normal, sr.ray.direction) > 0.0:
            sr.normal = -sr.normal

    def global_shade(self, sr) -> PathVertex:
        return self.path_shade(sr)

    def get_Le(self, sr=None) -> Float3:
        return self.emission

    def set_cd(self, cd) -> None:
        self.cd = colour(cd, type(self).__name__ + ".cd", surface=True)

    # -- the colour at a hit, and the flat layout's fields
    @property
    def texture(self):
        return self.cd if isinstance(self.cd, Texture) else None

    def color_at(self, shape, position) -> Float3:
        """The surface's colour at ``position`` on ``shape``: the texture's there, cd, or the
        shape's colour."""
        cd = self.cd
        if isinstance(cd, Float3):
            return cd
        if cd is None:
            return shape.color
        return cd.color_at(shape, position)

    specular = Float3(0.0)
    shininess = 0.0
    ior = 1.0
    absorption = Float3(0.0)
    kd = 0.0
    ka = 0.0
    # What the ray-cast tracers' further rays are weighted by: kr cr for the reflected ray,
    # kt for the transmitted one (Reflective, Transparent).
    reflection = Float3(0.0)
    kt = 0.0

    def check_path_trace(self, where: str, color) -> None:
        """Raise a ValueError naming ``where`` if PathTrace cannot follow this material."""

    def flat_limit(self, tracer):
        """None if the numba and WGSL paths render this material under ``tracer`` as the
        lecture layer does; else why not (the flat layout raises it, naming the shape). The
        samplers of its diffuse_brdf and specular_brdf, the BRDFs PathTrace draws directions
        from, travel in the Material row (rtfgu.layout.MATERIAL_FIELDS)."""
        return None

    def __repr__(self) -> str:
        return "%s(cd=%r)" % (type(self).__name__, self.cd)
