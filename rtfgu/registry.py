"""The kinds rtfgu knows, each described once: shapes, shaders and lights.

PBRT-v4 lists its shapes once in a tagged pointer and Nori registers a class with one line;
here one entry per kind says everything the three paths need, and every list of kinds
(the flat layout's tables and ids, the numba ``intersect_scene``/``in_shadow``/
``shape_normal`` and ``shade``, the WGSL bindings, structs and dispatch) is derived from
these tuples. A kind's id is its place in its tuple.

A shape kind named ``disk`` (``ShapeKind("disk", Disk, fields)``) promises:

* the lecture class ``Disk`` with an attribute per field (``center``, ``normal``, ...);
* ``fields``: the layout record, in the order in which both intersection functions take
  them after the ray; 3 components is a vector, 1 a scalar;
* numba: ``intersect_disk(origin, direction, tmin, tmax, *fields)`` returning t in
  [tmin, tmax] or inf, and ``normal_disk(position, *fields)``, in ``numba_module``
  (``normal_<kind>(position, direction, *fields)`` for a kind marked ``faces_ray``, whose
  normal turns toward the ray: the lecture class's ``hit_normal``);
  a formula other than "slide" is ``intersect_disk_<formula>`` with the same arguments;
* WGSL: the file ``intersect_disk.wgsl`` with
  ``fn intersect_disk(r: Ray, hit: ptr<function, HitInfo>, <fields>) -> bool`` filling
  the hit as the 02562 slides do; a formula other than "slide" is the file
  ``<formula>_disk.wgsl`` defining the same function; ``uses`` names the kinds and the
  helper pieces (the torus's ``solve_quartic``: ``solve_quartic.wgsl``) it calls.

docs/adding_a_shape.md walks through it. Nothing here imports numba or wgpu: the kernels
and the WGSL files are named, and loaded only by the paths that use them.
"""
from __future__ import annotations

from dataclasses import dataclass

from .lights import AmbientOccluder, AreaLight, Directional, PointLight
from .materials.material import (BASE_COLOR, DIELECTRIC, EMISSIVE, GLOSSY, GLOSSY_REFLECTOR, LAMBERTIAN, MIRROR,
                                 PHONG, REFLECTIVE, TRANSPARENT)
from .shapes.annulus import Annulus
from .shapes.box import Box
from .shapes.concave_part_sphere import ConcavePartSphere
from .shapes.convex_part_sphere import ConvexPartSphere
from .shapes.disk import Disk
from .shapes.instance import Instance
from .shapes.mesh import MeshTriangle
from .shapes.open_cylinder import OpenCylinder
from .shapes.open_part_cylinder import OpenPartCylinder
from .shapes.plane import Plane
from .shapes.rectangle import Rectangle
from .shapes.sphere import Sphere
from .shapes.torus import Torus
from .shapes.triangle import Triangle
from .textures import Checker, Checker3D, FBmTexture, ImageTexture, RampFBmTexture, Wood, WrappedFBmTexture


class _Rows:
    """A kind with a row per object in the flat layout: its table and record names."""

    @property
    def table(self) -> str:
        """The FlatScene table and WGSL binding: "spheres"."""
        return self.name + "s"

    @property
    def record(self) -> str:
        """The layout record and WGSL struct: "Sphere"."""
        return self.cls.__name__


@dataclass(frozen=True)
class ShapeKind(_Rows):
    name: str
    cls: type
    fields: tuple                       # ((field, components), ...), the intersection's arguments
    formulas: tuple = ("slide",)        # the intersection formulas the kernels and WGSL provide
    numba_module: str = "rtfgu.kernels.intersect"
    from_eye: bool = False              # numba: rays from a pinhole eye share per-frame terms
    uses: tuple = ()                    # WGSL: kinds whose intersection functions this one calls,
                                        # or helper pieces (next_after: next_after.wgsl)
    faces_ray: bool = False             # the normal depends on the ray's direction (Shape.hit_normal)
    # A mesh kind: its rows are the faces of meshes, found through the scene's BVH (which
    # may hold the spheres too, rtfgu.layout.FlatMesh) and not by a loop over rows (numba ``mesh_closest``/``mesh_any``/``normal_mesh``/``texcoord_mesh`` in
    # ``numba_module``, WGSL ``mesh.wgsl``); its arrays are rtfgu.layout.FlatMesh's.
    bvh: bool = False
    # An instance kind (Suffern ch. 21): its row is an inverse transformation and the kind
    # and row of the object it holds, which lies in a table of that kind's own, one per
    # INSTANCED kind (numba: generated in rtfgu.kernels.dispatch; WGSL: intersect_<name>.wgsl
    # calls the object's intersection through a generated switch).
    instance: bool = False

    @property
    def wgsl_file(self) -> str:
        return "intersect_%s.wgsl" % self.name

    def formula_file(self, formula: str) -> str:
        return self.wgsl_file if formula == "slide" else "%s_%s.wgsl" % (formula, self.name)

    def formula_function(self, formula: str) -> str:
        base = "intersect_" + self.name
        return base if formula == "slide" else "%s_%s" % (base, formula)


@dataclass(frozen=True)
class ShaderKind:
    """A material kind: a case of the slide's ``shade`` switch, which the numba and WGSL
    paths dispatch on by id, and the lecture layer's material class it stands for
    (``material``, rtfgu/materials; a class's ``shader`` property says which case an
    instance is). ``brdf``: the shader adds light from the lights through the one light
    loop with this BRDF term (numba ``brdf_<name>``, WGSL ``fn brdf_<name>`` in
    ``<name>.wgsl``); ``continues``: the shader may continue the path (numba
    ``continue_<name>``, WGSL ``fn continue_<name>``), so the path loop is needed."""

    id: int
    name: str
    material: str
    brdf: bool = False
    continues: bool = False
    brdf_of: str = ""                   # the shader whose BRDF term this one uses ("" : its own)
    emits: bool = False
    splits: bool = False                # may send a second ray (a reflection beside a refraction)


@dataclass(frozen=True)
class LightKind(_Rows):
    """A light: the lecture class (rtfgu/lights, the book's get_direction, L, G, pdf) with an
    attribute per field, numba ``sample_<name>(lights, j, position)`` and WGSL ``fn
    sample_<name>(pos, i) -> Light`` in ``lights.wgsl``, both returning the slide's (L_i,
    w_i, dist) as the ray-cast tracers ask the class. ``area``: a tracer that samples lights
    draws a point or a direction of it with two random numbers (the class's get_direction
    then incident = L G / pdf, numba ``sample_<name>_area(lights, j, position, normal, u,
    v)``, WGSL ``sample_<name>_area(pos, normal, i, u, v)``); ``ray_cast``: the ray-cast
    tracers have it too (a light without it needs PathTrace, Scene.validate says so). An
    ``area`` kind's row ends with ``light_sampler``: (first sample, num_samples, num_sets) of
    its sampler's sets in the scene's light sample arrays (set_sampler; num_samples 0: the
    random stream), filled in by rtfgu.layout.compile_scene."""

    name: str
    cls: type
    fields: tuple
    area: bool = False

    @property
    def ray_cast(self) -> bool:
        return self.cls.drawn_by_ray_casting


PART_SPHERE_FIELDS = (("center", 3), ("radius", 1), ("phi_min", 1), ("phi_max", 1), ("cos_theta_min", 1),
                      ("cos_theta_max", 1))

SHAPES = (
    ShapeKind("plane", Plane, (("point", 3), ("normal", 3))),
    ShapeKind("triangle", Triangle, (("v0", 3), ("e0", 3), ("e1", 3), ("n", 3))),
    ShapeKind("sphere", Sphere, (("center", 3), ("radius", 1)), formulas=("slide", "robust"),
              from_eye=True),
    ShapeKind("disk", Disk, (("center", 3), ("normal", 3), ("radius", 1)), uses=("plane",)),
    ShapeKind("rectangle", Rectangle, (("p0", 3), ("a", 3), ("b", 3), ("normal", 3)), uses=("plane",)),
    ShapeKind("box", Box, (("p0", 3), ("p1", 3)), uses=("record_hit",)),
    # Both sides of the open cylinder are seen: its normal turns toward the ray.
    ShapeKind("open_cylinder", OpenCylinder, (("y0", 1), ("y1", 1), ("radius", 1)), uses=("sphere", "next_after"),
              faces_ray=True),
    # Suffern's part objects (ch. 19): the sphere's, the open cylinder's and the plane's tests
    # with an angle or radius test (rtfgu/kernels/part_objects.py).
    ShapeKind("convex_part_sphere", ConvexPartSphere, PART_SPHERE_FIELDS, numba_module="rtfgu.kernels.part_objects",
              uses=("sphere", "next_after")),
    ShapeKind("concave_part_sphere", ConcavePartSphere, PART_SPHERE_FIELDS,
              numba_module="rtfgu.kernels.part_objects", uses=("sphere", "next_after", "convex_part_sphere")),
    ShapeKind("open_part_cylinder", OpenPartCylinder, (("y0", 1), ("y1", 1), ("radius", 1), ("phi_min", 1),
                                                        ("phi_max", 1)),
              numba_module="rtfgu.kernels.part_objects", uses=("sphere", "next_after", "open_cylinder"),
              faces_ray=True),
    ShapeKind("annulus", Annulus, (("center", 3), ("normal", 3), ("inner_radius", 1), ("outer_radius", 1)),
              numba_module="rtfgu.kernels.part_objects", uses=("plane",)),
    # Suffern's mesh triangles (rtfgu.shapes.mesh): watertight, through the BVH.
    ShapeKind("mesh", MeshTriangle, (), numba_module="rtfgu.kernels.mesh", bvh=True),
    # Suffern's torus: a quartic, solved by Schwarze's closed form (its WGSL piece with it).
    ShapeKind("torus", Torus, (("a", 1), ("b", 1)), numba_module="rtfgu.kernels.torus",
              uses=("record_hit", "solve_quartic")),
    # Suffern's Instance (rtfgu.shapes.instance): the rows of the inverse matrix (the
    # translation after each) and the kind and row of its object in that kind's instanced table.
    ShapeKind("instance", Instance, (("row0", 3), ("t0", 1), ("row1", 3), ("t1", 1), ("row2", 3), ("t2", 1),
                                     ("object_kind", 1), ("object_row", 1)),
              numba_module="rtfgu.kernels.instance", instance=True),
)
ROW_SHAPES = tuple(kind for kind in SHAPES if not kind.bvh)   # the kinds laid out a row per shape
# The kinds an instance may hold on the numba and WGSL paths: each has an instanced table.
INSTANCED = tuple(kind for kind in ROW_SHAPES if not kind.instance)

SHADERS = (
    ShaderKind(BASE_COLOR, "base_color", "Material"),
    ShaderKind(LAMBERTIAN, "lambertian", "Matte", brdf=True),
    ShaderKind(PHONG, "phong", "Phong", brdf=True),
    # A Reflective with nothing but its mirror (kr cr = 1 in the course: its reflected ray's weight).
    ShaderKind(MIRROR, "mirror", "Reflective", continues=True),
    # A Transparent without a Phong part; "glossy" is one with it (02562 worksheet 3). Both
    # send the refracted ray on weighted by kt and, where kr > 0, the reflected one by kr cr.
    ShaderKind(TRANSPARENT, "transparent", "Transparent", continues=True, splits=True),
    ShaderKind(GLOSSY, "glossy", "Transparent", brdf=True, continues=True, brdf_of="phong", splits=True),
    ShaderKind(EMISSIVE, "emissive", "Emissive", emits=True),
    # PathTrace picks reflection or refraction by Fresnel's reflectance (numba and WGSL trace it
    # under PathTrace only: under the ray-cast tracers it sends two rays).
    ShaderKind(DIELECTRIC, "dielectric", "Dielectric", continues=True),
    # Phong under the ray-cast tracers; PathTrace samples its lobe.
    ShaderKind(GLOSSY_REFLECTOR, "glossy_reflector", "GlossyReflector", brdf=True, brdf_of="phong"),
    # A Reflective with a Phong part (Suffern ch. 24): Phong, then the mirror ray weighted by kr cr.
    ShaderKind(REFLECTIVE, "reflective", "Reflective", brdf=True, continues=True, brdf_of="phong"),
)

LIGHTS = (
    LightKind("point_light", PointLight, (("position", 3), ("intensity", 3))),
    LightKind("directional", Directional, (("direction", 3), ("intensity", 3))),
    # rtfgu/lights/area_light.py: one emitting triangle, rectangle or sphere.
    LightKind("area_light", AreaLight, (("v0", 3), ("radius", 1), ("e0", 3), ("rectangle", 1), ("e1", 3),
                                        ("emission", 3), ("light_sampler", 3)), area=True),
    # rtfgu/lights/ambient_occluder.py: ambient light seen through the unoccluded directions.
    LightKind("ambient_occluder", AmbientOccluder, (("radiance", 3), ("light_sampler", 3)), area=True),
)


@dataclass(frozen=True)
class TextureKind(_Rows):
    """A texture: the lecture class (rtfgu/textures/) with an attribute per field (the
    layout fills ``offset``, the texture's first texel in FlatScene.texels), numba
    ``texture_<name>(table, row, texels, u, v, position)`` in rtfgu/kernels/textures.py and
    WGSL ``fn texture_<name>(row: u32, uv: vec2f, p: vec3f) -> vec3f`` in ``<name>.wgsl``,
    both returning the colour at the hit point ``position`` whose texture coordinates on the
    shape are (u, v) (Texture.color_at, the book's get_color(ShadeRec)). ``texcoord``: the
    kind may read (u, v), so the paths compute them (a solid texture reads the point only
    and gets zeros). Every shape kind gives (u, v): numba ``texcoord_<shape>(position,
    *fields)``, WGSL ``fn texcoord_<shape>`` in texcoord.wgsl (Shape.texcoord in the
    lecture layer). ``uses``: WGSL pieces the kind's piece calls, assembled before it."""

    name: str
    cls: type
    fields: tuple
    texcoord: bool = True
    uses: tuple = ()


# Suffern ch. 29's mappings of an ImageTexture (rtfgu/mappings/, Mapping.name): numba
# rtfgu/kernels/mappings.py, WGSL the piece of each (cut to the mappings the scene uses).
MAPPING_IDS = {"spherical_map": 0, "cylindrical_map": 1, "rectangular_map": 2, "light_probe": 3, "panoramic": 4}
MAPPING_PIECES = ("spherical_map.wgsl", "cylindrical_map.wgsl", "rectangular_map.wgsl", "light_probe.wgsl")

# A LatticeNoise in a texture's row (rtfgu/textures/noise_texture.py): LinearNoise 0 or
# CubicNoise 1, and the parameters of its sums; WGSL: the lattice's tables, the noise the
# scene uses (each piece cut to its feature, "linear_noise" or "cubic_noise") and the sums.
NOISE_FIELDS = (("noise_id", 1), ("num_octaves", 1), ("lacunarity", 1), ("gain", 1), ("fbm_max", 1))
NOISE_PIECES = ("lattice_tables.wgsl", "linear_noise.wgsl", "cubic_noise.wgsl", "lattice_noise.wgsl")

TEXTURES = (
    # mapping_id: the image's Mapping (MAPPING_IDS), -1 for the shape's own (u, v).
    TextureKind("image_texture", ImageTexture, (("width", 1), ("height", 1), ("offset", 1),
                                                ("filter_mode", 1), ("address_mode", 1), ("scale", 1),
                                                ("mapping_id", 1)), uses=MAPPING_PIECES),
    TextureKind("checker", Checker, (("color1", 3), ("size", 1), ("color2", 3), ("scale", 1))),
    TextureKind("checker3d", Checker3D, (("color1", 3), ("size", 1), ("color2", 3), ("scale", 1)),
                texcoord=False),
    # Suffern ch. 31: a noise texture's row ends with its noise's fields (NOISE_FIELDS).
    TextureKind("fbm_texture", FBmTexture, (("color", 3), ("min_value", 1), ("max_value", 1), ("scale", 1))
                + NOISE_FIELDS, texcoord=False, uses=NOISE_PIECES),
    TextureKind("wrapped_fbm_texture", WrappedFBmTexture, (("color", 3), ("min_value", 1), ("max_value", 1),
                                                           ("expansion_number", 1), ("scale", 1)) + NOISE_FIELDS,
                texcoord=False, uses=NOISE_PIECES),
    # The ramp's colours sit in FlatScene.texels from ``offset``, ``width`` of them.
    TextureKind("ramp_fbm_texture", RampFBmTexture, (("offset", 1), ("width", 1), ("perturbation", 1), ("scale", 1))
                + NOISE_FIELDS, texcoord=False, uses=NOISE_PIECES),
    TextureKind("wood", Wood, (("light_color", 3), ("ring_frequency", 1), ("dark_color", 3), ("ring_uneveness", 1),
                               ("ring_noise", 1), ("ring_noise_frequency", 1), ("trunk_wobble", 1),
                               ("trunk_wobble_frequency", 1), ("angular_wobble", 1), ("angular_wobble_frequency", 1),
                               ("grain_frequency", 1), ("grainy", 1), ("ringy", 1), ("scale", 1)) + NOISE_FIELDS,
                texcoord=False, uses=NOISE_PIECES),
)

SHAPE_BY_NAME = {kind.name: kind for kind in SHAPES}
SHAPE_IDS = {kind.name: i for i, kind in enumerate(SHAPES)}
SHADER_BY_ID = {kind.id: kind for kind in SHADERS}
assert [kind.id for kind in SHADERS] == list(range(len(SHADERS))), "shader ids are their places"


def shape_kind_of(shape):
    """(id, ShapeKind) of a lecture-layer shape, or (None, None)."""
    for i, kind in enumerate(SHAPES):
        if type(shape) is kind.cls:
            return i, kind
    for i, kind in enumerate(SHAPES):   # a subclass of a registered class packs as its base
        if isinstance(shape, kind.cls):
            return i, kind
    return None, None


def texture_kind_of(texture):
    for i, kind in enumerate(TEXTURES):
        if isinstance(texture, kind.cls):
            return i, kind
    return None, None


def light_kind_of(light):
    for i, kind in enumerate(LIGHTS):
        if isinstance(light, kind.cls):
            return i, kind
    return None, None
