"""The flat scene layout shared by the numba kernels and the WGSL program.

One module owns the memory layout: dtypes, ids, and the place of every field in every
row. The records of shapes and lights come from their kinds in rtfgu.registry, so a new
kind brings its row with it; ``compile_scene`` turns a lecture-layer ``Scene`` into these
arrays after validating it, so bad input never reaches a kernel.

Every row is a whole number of 4-component vectors, so the same arrays upload to WGSL
``array<Record, N>`` buffers unchanged (16-byte stride in float32). A vector field starts
a new vec4; a scalar takes the unused fourth component of the vector declared just before
it, or the next free column. For example

    camera      (5, 4)   ORTHOGRAPHIC: [left, right, bottom, top], [hither, yon, tmin, 0], 0, 0, 0
                         PINHOLE:      [eye, d], [b1, aspect], [b2, 0], [v, 0], 0
                         THIN_LENS:    [eye, d], [b1, aspect], [b2, lens_radius], [v, focal_distance], 0
                         FISH_EYE:     [eye, psi_max], [b1, 0], [b2, 0], [v, 0], 0     (psi_max in radians)
                         SPHERICAL:    [eye, lambda_max], [b1, psi_max], [b2, 0], [v, 0], 0   (radians)
                         STEREO:       [eye, d], [b1, aspect], [b2, offset], [v, shift], [hres, pixel_gap, 0, 0]
    Plane       (P, 8)   [point, 0], [normal, 0]             (the normal as given, not normalised)
    Triangle    (T, 16)  [v0, 0], [e0, 0], [e1, 0], [n, 0]   (e0 = v1 - v0, e1 = v2 - v0, n = e0 x e1)
    Sphere      (S, 4)   [center, radius]
    Material    (N, 20)  [color, 0], [specular, shininess], [emission, ior], [texture, texture_row, 0, 0],
                         [absorption, 0]
    PointLight  (L, 8)   [position, 0], [intensity, 0]
    Directional (D, 8)   [direction, 0], [intensity, 0]      (the direction as given)
    ImageTexture (X, 8)  [width, height, offset, filter_mode], [address_mode, scale, 0, 0]
    Checker     (C, 8)   [color1, size], [color2, scale]

Mesh triangles (the registry's ``bvh`` kind) are laid out as a FlatMesh instead: the vertices
of every mesh once, a row per face ``[i0, i1, i2, scene index]`` (int32) in the order of
the leaves of the scene's BVH (rtfgu.accelerators.flat_bvh), and the vertex normals when a
mesh is smooth. ``shapes["mesh"]`` is (faces, their scene indices).

A shape table comes with an int32 index: each row's place in Scene.shapes, a Mesh there
counted as its faces (face k of a Mesh whose faces start at index i is shape i + k), which is
also its material row (and decides ties: the earlier shape wins). A Mesh held in
Scene.shapes is packed from its arrays with numpy: no MeshTriangle is made for it.
``shaders`` holds each shape's shader id; ``background`` is [rgb, 0]. ``texels`` holds
every image texture's linear RGB, row after row from the top, 3 numbers a texel (an
ImageTexture row's ``offset`` is its first texel).
"""
from __future__ import annotations

import dataclasses
import math
import operator
import weakref
from types import SimpleNamespace
from dataclasses import dataclass, field

import numpy as np

from .cameras import FishEye, OrthographicCamera, PinholeCamera, Spherical, StereoCamera, ThinLens
from .float3 import Float3
from .ray import RAY_EPSILON
from .same_arrays import same_arrays
from .registry import (INSTANCED, LIGHTS, MAPPING_IDS, ROW_SHAPES, SHADER_BY_ID, SHAPE_IDS, SHAPES, TEXTURES, light_kind_of,
                       shape_kind_of, texture_kind_of)
from .shapes.mesh import Mesh

DTYPES = {"float64": np.float64, "float32": np.float32}


def pack_fields(fields) -> tuple:
    """(row width, ((field, components, column), ...)) for ((field, components), ...)."""
    placed, free_w, column = [], None, 0
    for name, components in fields:
        if components == 3:
            column = -(-column // 4) * 4
            placed.append((name, 3, column))
            free_w = column + 3
            column += 4
        elif components == 1:
            if free_w is not None:
                placed.append((name, 1, free_w))
                free_w = None
            else:
                placed.append((name, 1, column))
                column += 1
        else:
            raise ValueError("a layout field has 1 or 3 components, %s has %d" % (name, components))
    return -(-column // 4) * 4, tuple(placed)


# texture: the texture kind's id (its place in rtfgu.registry.TEXTURES), -1 for none;
# texture_row: its row in that kind's table.
# color: the surface's colour (its material's cd, or the shape's); kd: the diffuse BRDF's kd;
# ambient: ka times the scene's ambient radiance (rtfgu/materials/matte.py).
MATERIAL_FIELDS = (("color", 3), ("kd", 1), ("specular", 3), ("shininess", 1), ("emission", 3), ("ior", 1),
                   ("texture", 1), ("texture_row", 1), ("absorption", 3), ("ambient", 3), ("reflection", 3),
                   ("kt", 1), ("diffuse_sampler", 3), ("specular_sampler", 3))
CAMERA_FIELDS = {
    "OrthographicCamera": (("left", 1), ("right", 1), ("bottom", 1), ("top", 1), ("hither", 1),
                           ("yon", 1), ("tmin", 1)),
    "PinholeCamera": (("eye", 3), ("d", 1), ("b1", 3), ("aspect", 1), ("b2", 3), ("v", 3)),
    "ThinLens": (("eye", 3), ("d", 1), ("b1", 3), ("aspect", 1), ("b2", 3), ("lens_radius", 1),
                 ("v", 3), ("focal_distance", 1)),
    "FishEye": (("eye", 3), ("psi_max", 1), ("b1", 3), ("b2", 3), ("v", 3)),
    "Spherical": (("eye", 3), ("lambda_max", 1), ("b1", 3), ("psi_max", 1), ("b2", 3), ("v", 3)),
    "StereoCamera": (("eye", 3), ("d", 1), ("b1", 3), ("aspect", 1), ("b2", 3), ("offset", 1),
                     ("v", 3), ("shift", 1), ("hres", 1), ("pixel_gap", 1)),
}
# The rows of the widest camera record (StereoCamera's); every camera block has them.
CAMERA_ROWS = 5
CAMERA_WIDTH = CAMERA_ROWS * 4

# Every row as a record: name -> (row width, ((field, components, column), ...)). The WGSL
# structs are generated from these records (rtfgu/wgsl/structs.py).
RECORDS = {kind.record: pack_fields(kind.fields) for kind in ROW_SHAPES + LIGHTS + TEXTURES}
RECORDS["Material"] = pack_fields(MATERIAL_FIELDS)
for _name, _fields in CAMERA_FIELDS.items():
    RECORDS[_name] = (CAMERA_WIDTH, pack_fields(_fields)[1])


def offset(record: str, name: str) -> int:
    """The column of field ``name`` in ``record``."""
    for field_name, _, column in RECORDS[record][1]:
        if field_name == name:
            return column
    raise KeyError("%s has no field %r" % (record, name))


def width(record: str) -> int:
    return RECORDS[record][0]


# Shape kind ids: places in rtfgu.registry.SHAPES (a closed list dispatched by id, as PBRT's
# tagged shapes).
SHAPE_KINDS = {i: kind.name for i, kind in enumerate(SHAPES)}
PLANE = SHAPE_IDS["plane"]
TRIANGLE = SHAPE_IDS["triangle"]
SPHERE = SHAPE_IDS["sphere"]
DISK = SHAPE_IDS["disk"]
MESH = SHAPE_IDS["mesh"]
MESH_KIND = SHAPES[MESH]    # the kind of a Mesh's faces (the registry's BVH kind)

ORTHOGRAPHIC = 0
PINHOLE = 1
THIN_LENS = 2
FISH_EYE = 3
SPHERICAL = 4
STEREO = 5
CAMERA_KINDS = {ORTHOGRAPHIC: "orthographic", PINHOLE: "pinhole", THIN_LENS: "thin_lens",
                FISH_EYE: "fish_eye", SPHERICAL: "spherical", STEREO: "stereo"}
CAMERA_RECORDS = {ORTHOGRAPHIC: "OrthographicCamera", PINHOLE: "PinholeCamera",
                  THIN_LENS: "ThinLens", FISH_EYE: "FishEye", SPHERICAL: "Spherical", STEREO: "StereoCamera"}

# Columns the hand-written kernels read (the generated ones read RECORDS).
MAT_COLOR = offset("Material", "color")
MAT_SPECULAR = offset("Material", "specular")
MAT_SHININESS = offset("Material", "shininess")
MAT_EMISSION = offset("Material", "emission")
MAT_IOR = offset("Material", "ior")
MAT_TEXTURE = offset("Material", "texture")
MAT_TEXTURE_ROW = offset("Material", "texture_row")
MAT_ABSORPTION = offset("Material", "absorption")
MAT_KD = offset("Material", "kd")
MAT_AMBIENT = offset("Material", "ambient")
MAT_REFLECTION = offset("Material", "reflection")
MAT_KT = offset("Material", "kt")
MAT_DIFFUSE_SAMPLER = offset("Material", "diffuse_sampler")
MAT_SPECULAR_SAMPLER = offset("Material", "specular_sampler")
# ImageTexture.filter and .address as numbers in the layout.
TEXTURE_FILTERS = {"nearest": 0, "bilinear": 1}
TEXTURE_ADDRESSES = {"repeat": 0, "clamp": 1}
MATERIAL_WIDTH = width("Material")
LIGHT_POSITION = offset("PointLight", "position")
LIGHT_INTENSITY = offset("PointLight", "intensity")
SPHERE_CENTER = offset("Sphere", "center")
SPHERE_RADIUS = offset("Sphere", "radius")
ORTHO_LEFT = offset("OrthographicCamera", "left")
ORTHO_RIGHT = offset("OrthographicCamera", "right")
ORTHO_BOTTOM = offset("OrthographicCamera", "bottom")
ORTHO_TOP = offset("OrthographicCamera", "top")
ORTHO_HITHER = offset("OrthographicCamera", "hither")
ORTHO_YON = offset("OrthographicCamera", "yon")
ORTHO_TMIN = offset("OrthographicCamera", "tmin")
PINHOLE_EYE = offset("PinholeCamera", "eye")
PINHOLE_D = offset("PinholeCamera", "d")
PINHOLE_B1 = offset("PinholeCamera", "b1")
PINHOLE_ASPECT = offset("PinholeCamera", "aspect")
PINHOLE_B2 = offset("PinholeCamera", "b2")
PINHOLE_V = offset("PinholeCamera", "v")
LENS_RADIUS = offset("ThinLens", "lens_radius")
FOCAL_DISTANCE = offset("ThinLens", "focal_distance")
FISH_EYE_PSI_MAX = offset("FishEye", "psi_max")
SPHERICAL_LAMBDA_MAX = offset("Spherical", "lambda_max")
SPHERICAL_PSI_MAX = offset("Spherical", "psi_max")
STEREO_OFFSET = offset("StereoCamera", "offset")
STEREO_SHIFT = offset("StereoCamera", "shift")
STEREO_HRES = offset("StereoCamera", "hres")
STEREO_PIXEL_GAP = offset("StereoCamera", "pixel_gap")
assert all(offset("ThinLens", f) == offset("PinholeCamera", f) for f in ("eye", "d", "b1", "aspect",
                                                                       "b2", "v"))

# A far-away tmax for APIs that cannot hold infinity (WGSL has no inf literal).
FAR = 1.0e30


@dataclass
class FlatMesh:
    """The scene's BVH and what it holds: every mesh triangle and, in a scene with a mesh or
    with BVH_MIN_SPHERES spheres or more and rays other than a pinhole's primary ones, every
    sphere. ``vertices`` (V, 3) in the scene's
    float type, each mesh's once; ``faces`` (F, 4) int32 in the BVH's leaf order, a face
    [i0, i1, i2, scene index] or a sphere [SPHERE_ROW, row in the sphere table, 0, scene
    index]; ``normals`` (V, 3) vertex normals (zero for a flat mesh's vertices) or None when
    every mesh is flat; ``uvs`` (V, 3) per vertex (u, v, 1), (0, 0, 0) for a vertex of a mesh
    without uvs (whose faces' (u, v) are then their barycentrics), or None when no mesh has
    uvs; ``bvh`` the FlatBVH over the rows (its build_seconds: 0 when it came
    from the scene's cache); ``spheres``: whether it holds the spheres (the sphere table then
    has no loop of its own); ``instances``: whether it holds the instances, rows
    [INSTANCE_ROW, instance row, 0, scene index] (their loop then has none either). ``scene_tree``: whether the scene's own tree is there, from node
    0 (False where every mesh is an instance's); ``roots``: the first node of the tree of each
    mesh instances hold, whose rows end in the face's place in its mesh (compile_mesh)."""

    vertices: np.ndarray
    faces: np.ndarray
    normals: np.ndarray
    bvh: object
    build_seconds: float = 0.0
    spheres: bool = False
    uvs: np.ndarray = None
    roots: tuple = ()
    scene_tree: bool = True
    instances: bool = False

    @property
    def tree_roots(self) -> tuple:
        """The first node of every tree in the table: the scene's (0) where it has one, then ``roots``."""
        return ((0,) if self.scene_tree else ()) + tuple(self.roots)

    @property
    def nbytes(self) -> int:
        """The bytes of the BVH and the triangle data (vertices, faces, normals, uvs)."""
        return self.vertices.nbytes + self.faces.nbytes + self.bvh.nbytes + sum(
            0 if a is None else a.nbytes for a in (self.normals, self.uvs))


@dataclass
class FlatScene:
    """A scene as flat arrays, in one float dtype. ``shapes`` maps every registered shape
    kind's name to (table, index), empty for a kind the scene lacks; ``lights`` every light
    kind's name to its table. ``features`` names what the scene uses (shape kinds, shader
    names, "lights", "shadows", "ray_direction") so that a path leaves out the rest."""

    dtype: type
    camera_kind: int
    camera: np.ndarray
    shapes: dict
    # The distinct materials' rows (M, MATERIAL_WIDTH) and shader ids (M,), and each shape's
    # row among them (S,) int32 (a Mesh counted as its faces): a mesh of a million faces of
    # one material has one row, not a million.
    materials: np.ndarray
    shaders: np.ndarray
    material_of: np.ndarray
    lights: dict
    background: np.ndarray
    shadows: bool
    show_ray_direction: bool
    features: frozenset = field(default_factory=frozenset)
    # A table per texture kind (empty for a kind the scene lacks) and the image texels.
    textures: dict = field(default_factory=dict)
    texels: np.ndarray = None
    # The render's FlatSampler (compile_sampler), set by the path that renders; None: one
    # sample through each pixel's centre.
    sampler: object = None
    # The mesh triangles (FlatMesh), None in a scene without any.
    mesh: object = None
    # The objects of the instances (rtfgu.registry.INSTANCED): a table per kind, a row per
    # distinct object (instances of one object share its row), empty for a kind none holds.
    instanced: dict = field(default_factory=dict)
    # PathTrace's or GlobalTrace's max_depth (rtfgu/tracers), 0 for the ray-cast loop.
    max_depth: int = 0
    # Whether a path samples the lights at every vertex (PathTrace) or at the first only
    # (GlobalTrace).
    lights_at_every_vertex: bool = True
    # Whether the ray-cast loop draws points of area lights (AreaLighting) instead of
    # worksheet 5's point at their centre.
    area_lighting: bool = False
    # The sets of the samplers lights and BRDFs have of their own (set_sampler), one after
    # another: points (n, 2) and each set's order (n,) int32; None where none has one. A
    # light's row (rtfgu.registry.LightKind) and a material's row (diffuse_sampler,
    # specular_sampler) say where its sampler's sets start.
    own_samples: np.ndarray = None
    own_shuffled: np.ndarray = None
    # The EnvironmentLight's image (height, width, 3), or None: rays that leave the scene
    # see ``background`` then.
    environment: np.ndarray = None

    def table(self, kind: str) -> np.ndarray:
        return self.shapes[kind][0]

    def index(self, kind: str) -> np.ndarray:
        return self.shapes[kind][1]

    def count(self, kind: str) -> int:
        return len(self.shapes[kind][0])

    @property
    def light_count(self) -> int:
        return sum(len(t) for t in self.lights.values())


def _vec(v) -> list:
    return [v.x, v.y, v.z]


def attribute_paths(fields) -> list:
    """operator.attrgetter's paths of a record's fields ((name, components, ...) each): a
    Float3 field as its x, y and z."""
    paths = []
    for name, components, *_ in fields:
        paths += [name + ".x", name + ".y", name + ".z"] if components == 3 else [name]
    return paths


# record -> what _packer makes of it, made on first use.
_PACKERS = {}


def _packer(record: str) -> tuple:
    """(row width, a getter of the record's values from an object, each value's column), made
    once per record: operator.attrgetter reads every field (a Float3's x, y, z) in one call."""
    packer = _PACKERS.get(record)
    if packer is None:
        size, fields = RECORDS[record]
        paths, columns = attribute_paths(fields), []
        for _, components, column in fields:
            columns += [column, column + 1, column + 2] if components == 3 else [column]
        getter = operator.attrgetter(*paths)
        if len(paths) == 1:   # attrgetter of one name gives the value, not a tuple
            getter = lambda obj, one=getter: (one(obj),)   # noqa: E731
        packer = _PACKERS[record] = (size, getter, tuple(columns))
    return packer


def row_values(record: str, obj) -> tuple:
    """The values of ``obj``'s attributes named by the fields of ``record``, in their order
    (a Float3 as its x, y, z): what pack_table places in a row."""
    return _packer(record)[1](obj)


# record -> the function row_builder makes for it, made on first use.
_BUILDERS = {}


def row_builder(record: str):
    """A function of the fields of ``record``, by name, that returns what row_values returns
    for an object holding them: ``row_builder("Material")(color=..., kd=..., ...)``. For a
    row whose values do not all live on one object; it makes no object to read them from
    (a row a shape, in compile_scene's loop). Written once per record from its fields."""
    build = _BUILDERS.get(record)
    if build is None:
        names, values = [], []
        for name, components, _ in RECORDS[record][1]:
            names.append(name)
            values += ["%s.%s" % (name, c) for c in "xyz"] if components == 3 else [name]
        source = "def %s_row(*, %s):\n    return (%s,)\n" % (record, ", ".join(names), ", ".join(values))
        scope = {}
        exec(source, scope)
        build = _BUILDERS[record] = scope[record + "_row"]
    return build


def pack_table(record: str, values: list, dtype) -> np.ndarray:
    """The (len(values), width) table of ``record`` whose rows hold ``values`` (row_values
    of each object), zero in the columns no field takes. A value beyond ``dtype`` becomes
    inf without a warning: compile_scene refuses it, naming the table."""
    size, _, columns = _packer(record)
    table = np.zeros((len(values), size), dtype=dtype)
    if values:
        with np.errstate(over="ignore"):
            table[:, columns] = np.array(values, dtype=np.float64)
    return table


# The row field of an object without a sampler of its own (read, never changed).
NO_SAMPLER = Float3(0.0)


class _OwnSamplers:
    """The sets of the samplers that lights and BRDFs have of their own (set_sampler), one
    after another, each sampler once: what FlatScene.own_samples and own_shuffled hold.
    ``drawn``: whether the scene's tracer draws points at all (PathTrace, GlobalTrace,
    AreaLighting); under the others a sampler is never asked and is not laid out."""

    def __init__(self, drawn: bool):
        self.samples, self.shuffled, self.first, self.drawn = [], [], {}, drawn

    def place(self, sampler) -> Float3:
        """The row field of an object with ``sampler``: (its first sample, num_samples,
        num_sets); (0, 0, 0) for None, which draws from the random stream."""
        if sampler is None or not self.drawn:
            return NO_SAMPLER
        if id(sampler) not in self.first:
            self.first[id(sampler)] = len(self.samples)
            self.samples.extend(sampler.samples)
            self.shuffled.extend(sampler.shuffled_indices)
        return Float3(float(self.first[id(sampler)]), float(sampler.num_samples), float(sampler.num_sets))

    def place_brdf(self, material, part: str) -> Float3:
        """place() of the sampler of the material's BRDF ``part`` (PathTrace draws its
        directions), looked up only where the tracer draws."""
        if not self.drawn:
            return NO_SAMPLER
        return self.place(getattr(getattr(material, part, None), "sampler", None))




def compile_tracer(scene) -> tuple:
    """("path_trace", max_depth) for PathTrace and GlobalTrace, (None, 0) for the 02562
    ray-cast loop (Whitted with its 10 rays); a ValueError naming Scene.tracer for a tracer the
    flat paths do not run yet (they take it by its kind, so a subclass is not taken for its
    base)."""
    from .tracers import MAX_DEPTH, AreaLighting, GlobalTrace, PathTrace, Whitted

    tracer = scene.tracer
    if type(tracer) in (PathTrace, GlobalTrace):
        return "path_trace", tracer.max_depth
    if type(tracer) in (Whitted, AreaLighting) and tracer.max_depth == MAX_DEPTH:
        return ("area_lighting" if type(tracer) is AreaLighting else None), 0
    if scene.show_ray_direction:
        return None, 0
    raise ValueError("Scene.tracer (%r): numba and WGSL run Whitted and AreaLighting with max_depth=%d (the 02562 "
                     "loop), PathTrace and GlobalTrace; render this one with backend='reference'" % (tracer, MAX_DEPTH))


def compile_shadows(scene) -> bool:
    """Whether the flat paths cast shadow rays: every light casts shadows, or none does (the
    flat paths hold one switch for the scene)."""
    casts = {light.casts_shadows() for light in scene.lights}
    if len(casts) > 1:
        raise ValueError("Scene.lights: numba and WGSL cast shadow rays toward every light or none; these lights "
                         "differ in casts_shadows() (render with backend='reference')")
    return casts == {True}


def compile_camera(camera) -> tuple[int, np.ndarray]:
    if isinstance(camera, OrthographicCamera):
        # gen_ray's ray: origin z = hither, tmin = RAY_EPSILON, tmax = yon - hither.
        source = SimpleNamespace(left=camera.left, right=camera.right, bottom=camera.bottom,
                                 top=camera.top, hither=camera.hither, tmin=RAY_EPSILON,
                                 yon=camera.yon if math.isfinite(camera.yon) else FAR)
        kind, record = ORTHOGRAPHIC, "OrthographicCamera"
    elif isinstance(camera, ThinLens):
        kind, record, source = THIN_LENS, "ThinLens", camera
    elif isinstance(camera, PinholeCamera):
        kind, record, source = PINHOLE, "PinholeCamera", camera
    elif isinstance(camera, FishEye):
        kind, record = FISH_EYE, "FishEye"
        source = SimpleNamespace(eye=camera.eye, psi_max=camera.psi_max_radians, b1=camera.b1, b2=camera.b2,
                                 v=camera.v)
    elif isinstance(camera, Spherical):
        kind, record = SPHERICAL, "Spherical"
        source = SimpleNamespace(eye=camera.eye, lambda_max=camera.lambda_max_radians,
                                 psi_max=camera.psi_max_radians, b1=camera.b1, b2=camera.b2, v=camera.v)
    elif isinstance(camera, StereoCamera):
        kind, record, source = STEREO, "StereoCamera", camera
    else:
        raise ValueError("Scene.camera: the flat layout knows %s, got %s"
                         % (", ".join(CAMERA_RECORDS.values()), type(camera).__name__))
    return kind, pack_table(record, [row_values(record, source)], np.float64).reshape(CAMERA_ROWS, 4)


def _leaves(shapes):
    """(where, shape) of Scene.shapes with each Compound (rtfgu.shapes.compound) replaced by its
    leaves, in order: a compound has no row of its own, its children take its place; an
    Instance of a Compound by an Instance of each leaf (Instance.parts)."""
    from .shapes.compound import Compound
    from .shapes.instance import Instance

    for p, shape in enumerate(shapes):
        if isinstance(shape, Compound):
            for k, child in enumerate(shape.leaves()):
                yield "Scene.shapes[%d] (leaf %d of its %s)" % (p, k, type(shape).__name__), child
        elif isinstance(shape, Instance) and isinstance(shape.object, Compound):
            # An instance of each leaf (Instance.parts), each leaf's row shared by them all.
            for k, part in enumerate(shape.parts()):
                yield "Scene.shapes[%d] (leaf %d of its Instance's %s)" % (p, k, type(shape.object).__name__), part
        else:
            yield "Scene.shapes[%d]" % p, shape


def compile_scene(scene, precision: str = "float64") -> FlatScene:
    """Validate ``scene`` and lay it out in ``precision`` ("float64" or "float32")."""
    if precision not in DTYPES:
        raise ValueError("precision must be one of %s, got %r" % (", ".join(DTYPES), precision))
    dtype = DTYPES[precision]
    scene.validate()
    camera_kind, camera = compile_camera(scene.camera)

    tracer_feature, max_depth = compile_tracer(scene)
    shadows = compile_shadows(scene)
    ambient = scene.ambient_light.L(None)
    rows = {kind.name: ([], []) for kind in SHAPES}
    mesh_faces = []
    own = _OwnSamplers(tracer_feature in ("path_trace", "area_lighting"))
    texture_rows = {kind.name: [] for kind in TEXTURES}
    texels = []
    placed = {}  # id(texture) -> (kind id, row): a texture shared by shapes is laid out once
    material_rows = {}  # (id(material), surface colour if not cd) -> its place in unique_rows
    unique_rows, unique_shaders = [], []
    # Each shape's place in unique_rows (a Mesh's faces: an array of them), in the order of
    # the shapes' indices.
    material_of_shape = []
    features = {CAMERA_KINDS[camera_kind]}
    material_values = row_builder("Material")

    def material_row(where: str, m, color) -> int:
        """The place in unique_rows of material ``m`` on a surface of colour ``color``: laid
        out on first use. A material shared by shapes (a mesh's thousands of faces) is
        checked and laid out once per surface colour: its row depends on nothing else."""
        key = (id(m),) if isinstance(m.cd, Float3) else (id(m), color.x, color.y, color.z)
        if key in material_rows:
            return material_rows[key]
        texture, texture_row = -1, 0
        if m.texture is not None:
            if id(m.texture) not in placed:
                k, tkind = texture_kind_of(m.texture)
                if tkind is None:
                    raise ValueError("%s.material.texture: the flat layout knows %s, got %s"
                                     % (where, ", ".join(t.record for t in TEXTURES), type(m.texture).__name__))
                source = m.texture
                if tkind.name == "image_texture":
                    source = SimpleNamespace(
                        width=m.texture.width, height=m.texture.height, offset=len(texels) // 3,
                        filter_mode=TEXTURE_FILTERS[m.texture.filter],
                        address_mode=TEXTURE_ADDRESSES[m.texture.address], scale=m.texture.scale,
                        mapping_id=-1 if m.texture.mapping is None else MAPPING_IDS[m.texture.mapping.name])
                    if m.texture.mapping is not None:
                        features.add(m.texture.mapping.name)
                    texels.extend(m.texture.texels.reshape(-1).tolist())
                elif "offset" in dict(tkind.fields):   # texels of its own (a marble's ramp)
                    source = SimpleNamespace(**{name: getattr(m.texture, name) for name, _ in tkind.fields
                                                if name not in ("offset", "width")},
                                             offset=len(texels) // 3, width=m.texture.texels.shape[1])
                    texels.extend(m.texture.texels.reshape(-1).tolist())
                placed[id(m.texture)] = (k, len(texture_rows[tkind.name]))
                texture_rows[tkind.name].append(row_values(tkind.record, source))
                features.update((tkind.name, "textures"))
                if hasattr(m.texture, "noise_features"):
                    features.update(m.texture.noise_features)   # which noise WGSL assembles
                if m.texture.uses_texcoord:
                    features.add("texcoord")   # the paths compute the shape's (u, v)
            texture, texture_row = placed[id(m.texture)]
        limit = m.flat_limit(scene.tracer)
        if limit is not None:
            raise ValueError("%s.material (%r): %s" % (where, m, limit))
        unique_rows.append(material_values(
            color=m.cd if isinstance(m.cd, Float3) else color, kd=m.kd, specular=m.specular,
            shininess=m.shininess, emission=m.emission, ior=m.ior, texture=texture, texture_row=texture_row,
            absorption=m.absorption, ambient=ambient * m.ka, reflection=m.reflection, kt=m.kt,
            diffuse_sampler=own.place_brdf(m, "diffuse_brdf"),
            specular_sampler=own.place_brdf(m, "specular_brdf")))
        unique_shaders.append(m.shader)
        material_rows[key] = len(unique_rows) - 1
        features.add(SHADER_BY_ID[m.shader].name)
        if SHADER_BY_ID[m.shader].splits and max(m.reflection.x, m.reflection.y, m.reflection.z) > 0.0:
            features.add("two_rays")   # the ray-cast loops keep a stack of rays
        return material_rows[key]

    instanced = {kind.name: [] for kind in INSTANCED}
    instanced_rows = {}   # id(object) -> its row in its kind's instanced table

    instanced_meshes = []   # the Meshes instances hold, each laid out once (compile_mesh)
    instance_shapes = []    # the Instances, in the order of their rows

    def instance_row(where: str, kind, shape) -> list:
        """The row of an Instance: its inverse matrix and its object's kind and instanced row
        (for a Mesh, its place in instanced_meshes until compile_mesh gives its tree's root)."""
        obj = shape.object
        if isinstance(obj, Mesh):
            if id(obj) not in instanced_rows:
                instanced_rows[id(obj)] = len(instanced_meshes)
                instanced_meshes.append(obj)
            features.add("instanced_mesh")
            return row_values(kind.record, SimpleNamespace(
                **{name: getattr(shape, name) for name, _ in kind.fields if not name.startswith("object_")},
                object_kind=SHAPE_IDS[MESH_KIND.name], object_row=instanced_rows[id(obj)]))
        k, obj_kind = shape_kind_of(obj)
        if obj_kind not in INSTANCED:
            raise ValueError("%s: the numba and WGSL paths take an Instance of a %s, got an Instance "
                             "of a %s (the reference path renders it)"
                             % (where, ", ".join(o.record for o in INSTANCED), type(obj).__name__))
        if id(obj) not in instanced_rows:
            instanced_rows[id(obj)] = len(instanced[obj_kind.name])
            instanced[obj_kind.name].append(row_values(obj_kind.record, obj))
            features.add("instanced_" + obj_kind.name)
        return row_values(kind.record, SimpleNamespace(
            **{name: getattr(shape, name) for name, _ in kind.fields if not name.startswith("object_")},
            object_kind=k, object_row=instanced_rows[id(obj)]))

    i = 0   # the shape's index: its place in Scene.shapes, a Mesh counted as its faces
    for where, shape in _leaves(scene.shapes):
        if isinstance(shape, Mesh):
            # Its faces, m shapes from index i on, packed from its arrays (compile_mesh).
            mesh_faces.append((i, shape))
            places = np.empty(shape.num_triangles, dtype=np.int32)
            for face, m, faces in shape.surfaces():
                # One group of all the faces (one look) is a fill, not a scatter of m places.
                places[faces if len(faces) < len(places) else slice(None)] = material_row(
                    "%s.faces[%d]" % (where, face), m, shape.color(face))
            material_of_shape.append(places)
            features.add(MESH_KIND.name)
            i += shape.num_triangles
            continue
        _, kind = shape_kind_of(shape)
        if kind is None:
            raise ValueError("%s: the flat layout knows %s, got %s"
                             % (where, ", ".join(k.record for k in SHAPES), type(shape).__name__))
        if kind.bvh:
            mesh_faces.append((i, shape))
        elif kind.instance:
            rows[kind.name][0].append(instance_row(where, kind, shape))
            instance_shapes.append(shape)
            if isinstance(shape.object, Mesh):
                # As the lecture layer traces it (Instance.parts): an instance of each face,
                # in the mesh's order, each with the instance's material or the face's own.
                mesh = shape.object
                places = np.empty(mesh.num_triangles, dtype=np.int32)
                its = shape._own_material
                for face, m, faces in mesh.surfaces():
                    if its is None or isinstance(its.cd, Float3):
                        places[faces] = material_row("%s.faces[%d]" % (where, face), m if its is None else its,
                                                     mesh.color(face))
                    else:   # the instance's material, coloured by each face's colour
                        for f in faces.tolist():
                            places[f] = material_row("%s.faces[%d]" % (where, f), its, mesh.color(f))
                rows[kind.name][1].append(i)
                features.add(kind.name)
                material_of_shape.append(places)
                i += mesh.num_triangles
                continue
        else:
            rows[kind.name][0].append(row_values(kind.record, shape))
        rows[kind.name][1].append(i)
        features.add(kind.name)
        material_of_shape.append(material_row(where, shape.material, shape.color))
        i += 1
    if all(isinstance(x, int) for x in material_of_shape):   # no mesh: a row each
        material_of = np.array(material_of_shape, dtype=np.int32)
    else:
        material_of = np.concatenate([np.atleast_1d(np.asarray(x, dtype=np.int32)) for x in material_of_shape])
    materials = pack_table("Material", unique_rows, dtype)
    shaders = np.array(unique_shaders, dtype=np.int32)

    lights = {kind.name: [] for kind in LIGHTS}
    for j, light in enumerate(scene.lights):
        _, kind = light_kind_of(light)
        if kind is None:
            raise ValueError("Scene.lights[%d]: the flat layout knows %s, got %s"
                             % (j, ", ".join(k.record for k in LIGHTS), type(light).__name__))
        limit = light.flat_limit()
        if limit is not None:
            raise ValueError("Scene.lights[%d] (%r): %s" % (j, light, limit))
        if kind.area:
            light = SimpleNamespace(**{name: getattr(light, name) for name, _ in kind.fields if name != "light_sampler"},
                                    light_sampler=own.place(light.sampler))
        lights[kind.name].append(row_values(kind.record, light))
        features.add(kind.name)
    if scene.lights:
        features.add("lights")
    if own.samples:
        features.add("own_sampler")
    if shadows:
        features.add("shadows")
    if scene.show_ray_direction:
        features.add("ray_direction")
    elif tracer_feature:
        features.add(tracer_feature)
    if scene.environment is not None:
        features.add("environment")

    def table(rows, record):
        return pack_table(record, rows, dtype)

    shapes = {kind.name: (table(rows[kind.name][0], kind.record),
                          np.array(rows[kind.name][1], dtype=np.int32)) for kind in ROW_SHAPES}
    spheres = shapes["sphere"]
    # Only primary rays from a pinhole: the per-tile culling finds a tile's spheres for less.
    eye_rays_only = camera_kind == PINHOLE and "shadows" not in features and "path_trace" not in features \
        and not any(SHADER_BY_ID[s].continues for s in shaders.tolist())
    bvh_spheres = len(spheres[0]) > 0 and (bool(mesh_faces) or (len(spheres[0]) >= BVH_MIN_SPHERES
                                                                and not eye_rays_only))
    # The instances go into the scene's tree as the spheres do, with their boxes
    # (Instance.bounds), where each has one: an instance of a Mesh is then a row of the
    # scene's tree whose test enters its mesh's tree (two levels, as Embree's instances).
    wanted = len(instance_shapes) > 0 and (bool(mesh_faces) or bvh_spheres
                                           or len(instance_shapes) >= BVH_MIN_SPHERES)
    boxes = [shape.bounds() for shape in instance_shapes] if wanted else []
    bvh_instances = wanted and all(box is not None for box in boxes)
    mesh = compile_mesh(scene, mesh_faces, spheres if bvh_spheres else None, dtype, instanced_meshes,
                        (shapes["instance"][1], boxes) if bvh_instances else None) \
        if mesh_faces or bvh_spheres or instanced_meshes or bvh_instances else None
    if instanced_meshes:
        # An instance of a Mesh names the root of its mesh's tree (compile_mesh).
        instances = shapes["instance"][0]
        kind_column, row_column = offset("Instance", "object_kind"), offset("Instance", "object_row")
        of_mesh = instances[:, kind_column] == SHAPE_IDS[MESH_KIND.name]
        places = instances[of_mesh, row_column].astype(np.int64)
        instances[of_mesh, row_column] = np.asarray(mesh.roots, dtype=np.int64)[places]
        if mesh.bvh.num_nodes >= 2 ** 24:
            raise ValueError("Scene: the instanced meshes' trees have %d nodes, more than a float32 row "
                             "names exactly (2^24)" % mesh.bvh.num_nodes)
    if mesh is not None:
        if mesh.scene_tree:
            features.add("mesh")
        if mesh.normals is not None:
            features.add("smooth_mesh")
        if mesh.uvs is not None:
            features.add("uv_mesh")
        if bvh_spheres:
            features.add("bvh_spheres")
        if bvh_instances:
            features.add("bvh_instances")
    for kind in SHAPES:
        if kind.bvh:
            faces = mesh.faces if mesh is not None else np.zeros((0, 4), dtype=np.int32)
            shapes[kind.name] = (faces, faces[:, 3])

    flat = FlatScene(
        dtype=dtype,
        camera_kind=camera_kind,
        camera=camera.astype(dtype),
        shapes=shapes,
        materials=materials,
        shaders=shaders,
        material_of=material_of,
        lights={kind.name: table(lights[kind.name], kind.record) for kind in LIGHTS},
        own_samples=np.array(own.samples, dtype=dtype).reshape(-1, 2) if own.samples else None,
        own_shuffled=np.array(own.shuffled, dtype=np.int32) if own.samples else None,
        background=np.array(_vec(scene.background) + [0.0], dtype=dtype),
        shadows=shadows,
        show_ray_direction=bool(scene.show_ray_direction),
        features=frozenset(features),
        textures={kind.name: table(texture_rows[kind.name], kind.record) for kind in TEXTURES},
        texels=np.array(texels or [0.0, 0.0, 0.0], dtype=dtype),
        mesh=mesh,
        instanced={kind.name: table(instanced[kind.name], kind.record) for kind in INSTANCED},
        max_depth=max_depth if "path_trace" in features else 0,
        lights_at_every_vertex=bool(getattr(scene.tracer, "samples_lights_at", lambda depth: True)(1)),
        area_lighting=tracer_feature == "area_lighting",
        environment=None if scene.environment is None else scene.environment.texels.astype(dtype),
    )
    arrays = [("camera", flat.camera), ("materials", materials),
              ("background", flat.background)]
    arrays += [(kind.table, flat.table(kind.name)) for kind in ROW_SHAPES]
    arrays += [("instanced " + kind.table, flat.instanced[kind.name]) for kind in INSTANCED]
    if mesh is not None:
        arrays.append(("mesh vertices", mesh.vertices))
    arrays += [(kind.table, flat.lights[kind.name]) for kind in LIGHTS]
    arrays += [(kind.table, flat.textures[kind.name]) for kind in TEXTURES] + [("texels", flat.texels)]
    for name, array in arrays:
        if array.size and not np.isfinite(array).all():
            raise ValueError("Scene: %s is not finite in %s (a value overflows the precision)"
                             % (name, precision))
    return flat


# A scene with this many spheres finds them through the BVH (a scene with a mesh, with any),
# unless its only rays are primary rays from a pinhole: below it, and there, a loop over the
# spheres (with the eye's per-tile culling of primary rays) costs less (docs/bvh.md).
BVH_MIN_SPHERES = 16
# The first entry of a sphere's row in FlatMesh.faces.
SPHERE_ROW = -1
# The first entry of an instance's row in FlatMesh.faces.
INSTANCE_ROW = -2

# What compile_scene made for a scene from its meshes, per precision: the BVH and the
# FlatMesh arrays. {scene: {name: (inputs, value)}}: a value is reused
# while every input array is equal to the one it was made from (numpy compares them; no
# Python per face), so that a scene compiled again (another render, a moved camera, a
# notebook cell run twice) builds nothing again, and a vertex moved in place builds again.
_SCENE_CACHE = weakref.WeakKeyDictionary()


def _cached(scene, name, inputs: tuple, make):
    """(value, reused): make() for ``inputs`` (arrays), or the value the scene keeps from
    equal inputs."""
    try:
        store = _SCENE_CACHE.setdefault(scene, {})
    except TypeError:       # a scene object that cannot be weakly referenced: no cache
        store = {}
    entry = store.get(name)
    if entry is not None and len(entry[0]) == len(inputs) and same_arrays(zip(entry[0], inputs)):
        return entry[1], True
    value = make()
    store[name] = (tuple(np.array(a, copy=True) for a in inputs), value)
    return value, False


def _joined(parts: list) -> np.ndarray:
    """np.concatenate(parts), without a copy of the one part that is not empty."""
    full = [p for p in parts if len(p)]
    return full[0] if len(full) == 1 else np.concatenate(parts)


def compile_mesh(scene, mesh_faces, spheres, dtype, instanced=(), instances=None) -> FlatMesh:
    """The FlatMesh of the mesh triangles ``mesh_faces`` ((index, MeshTriangle) or (index of
    its first face, Mesh), ...) and, unless ``spheres`` is None, of the sphere table and index
    ``spheres``, with the scene's BVH over them (built, or taken from the scene's cache).

    Each Mesh of ``instanced`` (the meshes instances hold: Suffern ch. 21, one mesh, many
    instances) follows with its faces and a tree of its own, over its own coordinates: its
    rows' last entry is the face's place in the mesh (an instance adds its first index), its
    tree's nodes come after the scene's, and ``roots`` names each tree's first node.

    ``instances``: None, or the instance index and each Instance's box (Instance.bounds), for
    rows [INSTANCE_ROW, instance row, 0, scene index] in the scene's tree after the spheres'.

    A Mesh is packed from its arrays (its faces' rows are its ``faces`` plus the place of its
    first vertex); a MeshTriangle gives its row itself. Either way the rows, and so the BVH,
    are those of the same faces in the same order."""
    from .accelerators import flat_bvh
    from .accelerators.bbox import PAD
    from .shapes.mesh import SmoothMeshTriangle

    blocks = {}     # (id(mesh), smooth) -> first vertex: a mesh's vertices are laid out once
    vertex_parts, normal_parts, uv_parts = [], [], []
    # The rows in order: an int32 array, or a Mesh's as (its faces, first vertex, first index),
    # made only when the BVH is built (rows_of). loose: MeshTriangles' rows not yet in a part.
    face_parts, loose = [], []

    def first_vertex(mesh, smooth: bool) -> int:
        key = (id(mesh), smooth)
        if key not in blocks:
            blocks[key] = sum(len(v) for v in vertex_parts)
            vertex_parts.append(mesh.vertices)
            normal_parts.append(mesh.normals if smooth else None)
            uv_parts.append(mesh.uvs)
        return blocks[key]

    def rows_of(part) -> np.ndarray:
        if not isinstance(part, tuple):
            return part
        faces, first, index = part
        rows = np.empty((len(faces), 4), dtype=np.int32)
        np.add(faces, first, out=rows[:, :3], casting="unsafe")    # no int64 temporary
        rows[:, 3] = np.arange(index, index + len(faces), dtype=np.int32)
        return rows

    for i, shape in mesh_faces:
        if isinstance(shape, Mesh):
            if loose:
                face_parts.append(np.array(loose, dtype=np.int32).reshape(-1, 4))
                loose = []
            face_parts.append((shape.faces, first_vertex(shape, shape.normals is not None), i))
        else:
            first = first_vertex(shape.mesh, isinstance(shape, SmoothMeshTriangle))
            loose.append((shape.index0 + first, shape.index1 + first, shape.index2 + first, i))
    if loose:
        face_parts.append(np.array(loose, dtype=np.int32).reshape(-1, 4))
    object_parts = [(mesh.faces, first_vertex(mesh, mesh.normals is not None), 0) for mesh in instanced]
    num_triangles = sum(len(p[0]) if isinstance(p, tuple) else len(p) for p in face_parts)
    if spheres is not None:
        # A sphere's row: [-1, its row in the sphere table, 0, its place in Scene.shapes];
        # its box is centre +- radius grown as BBox.padded grows it (by 2^-20 in float32,
        # whose sphere test accepts grazing hits further out by rounding).
        table, index = spheres
        center = table[:, SPHERE_CENTER:SPHERE_CENTER + 3].astype(np.float64)
        radius = table[:, SPHERE_RADIUS].astype(np.float64)
        pad = PAD if dtype == np.float64 else 2.0 ** -20
        reach = radius + pad * (np.abs(center).max(axis=1) + radius)
        face_parts.append(np.stack([np.full(len(table), SPHERE_ROW), np.arange(len(table)),
                                    np.zeros(len(table)), index], axis=1).astype(np.int32))
        bound_lo, bound_hi = center - reach[:, None], center + reach[:, None]
    else:
        bound_lo = bound_hi = np.zeros((0, 3))
    if instances is not None:
        # An instance's box, grown in float32 by 2^-16 of its size and distance from the
        # origin: its float32 test transforms the ray with a rounded matrix.
        index, boxes = instances
        box_lo = np.array([[b.p0.x, b.p0.y, b.p0.z] for b in boxes])
        box_hi = np.array([[b.p1.x, b.p1.y, b.p1.z] for b in boxes])
        if dtype != np.float64:
            pad = 2.0 ** -16 * (np.abs(np.concatenate([box_lo, box_hi], axis=1)).max(axis=1)
                                + (box_hi - box_lo).max(axis=1))
            box_lo, box_hi = box_lo - pad[:, None], box_hi + pad[:, None]
        face_parts.append(np.stack([np.full(len(index), INSTANCE_ROW), np.arange(len(index)),
                                    np.zeros(len(index)), index], axis=1).astype(np.int32))
        bound_lo, bound_hi = np.concatenate([bound_lo, box_lo]), np.concatenate([bound_hi, box_hi])
    num_rows = num_triangles + len(bound_lo)

    def make():
        vertices = np.concatenate(vertex_parts) if vertex_parts else np.zeros((0, 3))
        normals = np.concatenate([np.zeros_like(v) if n is None else n for v, n in zip(vertex_parts, normal_parts)]) \
            if any(n is not None for n in normal_parts) else None
        uvs = np.concatenate([np.zeros_like(v) if t is None else np.column_stack([t, np.ones(len(t))])
                              for v, t in zip(vertex_parts, uv_parts)]) \
            if any(t is not None for t in uv_parts) else None
        trees, rows, roots = [], [], []
        if num_rows:
            faces = _joined([rows_of(p) for p in face_parts])
            bvh = flat_bvh.build_rows(flat_bvh.triangle_rows(vertices, faces[:num_triangles], bound_lo, bound_hi))
            trees.append(bvh)
            rows.append(np.take(faces, bvh.order, axis=0))   # a row's 16 bytes at once
        for part in map(rows_of, object_parts):
            bvh = flat_bvh.build_rows(flat_bvh.triangle_rows(vertices, part))
            roots.append(sum(t.num_nodes for t in trees))
            trees.append(flat_bvh.offset(bvh, roots[-1], sum(len(r) for r in rows)))
            rows.append(np.take(part, bvh.order, axis=0))
        bvh = trees[0] if len(trees) == 1 else flat_bvh.FlatBVH(
            np.concatenate([t.nodes for t in trees]), np.concatenate([t.order for t in trees]),
            sum(t.build_seconds for t in trees), np.concatenate([t.boxes for t in trees]))
        return FlatMesh(vertices=vertices.astype(dtype), faces=_joined(rows),
                        normals=None if normals is None else normals.astype(dtype),
                        uvs=None if uvs is None else uvs.astype(dtype),
                        bvh=bvh, build_seconds=bvh.build_seconds, spheres=spheres is not None,
                        roots=tuple(roots), scene_tree=num_rows > 0, instances=instances is not None)

    # What the BVH and the arrays depend on, compared with those of the last compile
    # (_cached): the meshes' own arrays (not the rows made from them: a second render makes
    # nothing per face), where each part starts, the other rows and the spheres' boxes.
    def source(part) -> tuple:
        return (part[0], np.array(part[1:])) if isinstance(part, tuple) else (part,)

    none = np.zeros(0)
    inputs = tuple(a for v, n, t in zip(vertex_parts, normal_parts, uv_parts)
                   for a in (v, none if n is None else n, none if t is None else t))
    inputs += tuple(a for part in face_parts + object_parts for a in source(part)) + (bound_lo, bound_hi)
    mesh, reused = _cached(scene, ("mesh", np.dtype(dtype).name), inputs, make)
    return dataclasses.replace(mesh, build_seconds=0.0) if reused else mesh


@dataclass
class FlatSampler:
    """A sampler's sets as arrays: ``samples`` (num_sets * n, 2) in the render's float type,
    ``shuffled`` int32 (num_sets * n), each set's order (rtfgu.sampling.sampler). ``kind``
    "sets" for Suffern's samplers; "sobol" for rtfgu.sampling.sobol.Sobol, whose points are
    computed where they are drawn (sobol_pair) and whose arrays are empty."""

    samples: np.ndarray
    shuffled: np.ndarray
    num_samples: int
    num_sets: int
    kind: str = "sets"


def compile_sampler(sampler, precision: str = "float64"):
    """The FlatSampler of ``sampler``, or None for none (one sample at each pixel's centre)."""
    from .sampling.sobol import Sobol

    if sampler is None:
        return None
    if isinstance(sampler, Sobol):
        return FlatSampler(np.zeros((0, 2), dtype=DTYPES[precision]), np.zeros(0, dtype=np.int32),
                           sampler.num_samples, 0, "sobol")
    return FlatSampler(np.array(sampler.samples, dtype=DTYPES[precision]).reshape(-1, 2),
                       np.array(sampler.shuffled_indices, dtype=np.int32),
                       sampler.num_samples, sampler.num_sets)
