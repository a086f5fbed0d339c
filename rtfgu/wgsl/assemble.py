"""Join the .wgsl files of this package into one program for one scene.

Only the pieces a scene uses are joined, in a stated order (a function is defined before
the functions that call it, as a student reads it): the structs and constants generated
from rtfgu.layout, the ray, the camera, the intersection function of every shape kind the
scene has (rtfgu.registry), the light samples, the shaders, shade, intersect_scene and
main. Two directives shape a file for the scene:

* ``// #if FEATURE`` (``a|b`` for either), ``// #else``, ``// #endif``: the lines are kept
  only when the scene has that feature, e.g. shadows.
* ``// #each shape`` (or ``row``: the shape kinds not in the BVH; ``light``, ``shader``,
  ``brdf``) ... ``// #end``: the lines are repeated for every kind of that list that the
  scene has, with ``$kind``, ``$table``,
  ``$TABLE``, ``$index``, ``$args`` (the row's fields as arguments, from ``rec``), ``$ID``,
  ``$body`` and ``$of`` filled in. This is how intersect_scene, in_shadow, the light loop
  and shade name every kind without a list of kinds of their own.

A shape kind's formula other than "slide" is its own file defining the same function
(robust_sphere.wgsl for the sphere); ``formula`` picks it. An override of a piece (a
student's own file) is used whatever the formula.

Only counts and kinds go into the program text; the scene's numbers go into buffers
(``Binding.pack``), so moving the camera or a light reuses the compiled pipeline.
"""
from __future__ import annotations

import dataclasses
import re
from dataclasses import dataclass, field
from importlib import resources

import numpy as np

from .. import layout
from ..registry import INSTANCED, LIGHTS, SHADERS, SHAPE_BY_NAME, SHAPES, TEXTURES
from ..options import DEFAULT_FORMULAS
from . import structs

GENERATED = "<generated from rtfgu.layout>"
# The formula of a WGSL render unless one is asked for (decided in rtfgu.renderer).
DEFAULT_SPHERE_FORMULA = DEFAULT_FORMULAS["wgpu"]


def check_formula(formula) -> str:
    """``formula`` ("slide", "robust"; None: DEFAULT_SPHERE_FORMULA), checked."""
    if formula is None:
        formula = DEFAULT_SPHERE_FORMULA
    known = sorted({f for kind in SHAPES for f in kind.formulas})
    if formula not in known:
        raise ValueError("formula must be one of %s, got %r" % (", ".join(known), formula))
    return formula


def _brdf_shaders(features):
    return [k for k in SHADERS if k.brdf and k.name in features]


def _lit(features) -> bool:
    """Whether the program samples lights: a shader that reflects them, or a path tracer
    (whose path_trace.wgsl holds its own light loop)."""
    return "lights" in features and (bool(_brdf_shaders(features)) or "path_trace" in features)


def _shape_kinds(features):
    """The shape kinds the program needs: the scene's, those its instances hold, and the
    kinds they call."""
    names = {k.name for k in SHAPES if k.name in features or "instanced_" + k.name in features}
    for kind in SHAPES:
        if kind.name in names:
            names.update(kind.uses)
    return [k for k in SHAPES if k.name in names]


def _helpers(kinds) -> list:
    """The WGSL pieces of helpers that ``kinds`` name in ``uses`` (a name that is no shape
    kind: "next_after" is next_after.wgsl), in order of name."""
    return sorted({name + ".wgsl" for kind in kinds for name in kind.uses if name not in SHAPE_BY_NAME})


def pieces(features, formula: str = "slide") -> list:
    """(piece name, file read for it) in the stated order, for a scene with ``features``."""
    f = features
    trace = "trace" in f
    out = [("ray.wgsl", "ray.wgsl")]
    if trace:
        out.append(("hitinfo.wgsl", "hitinfo.wgsl"))
    path = trace and "path_trace" in f
    sampled_lights = path or (trace and "area_lighting" in f)
    if "sampler" in f or "sobol" in f or sampled_lights:
        out.append(("random.wgsl", "random.wgsl"))
    if "sobol" in f:
        out.append(("sobol.wgsl", "sobol.wgsl"))
    out.append(("pixel_sample.wgsl", "pixel_sample.wgsl"))
    for camera in layout.CAMERA_KINDS.values():
        # The thin lens bends the pinhole's ray (camera_thin_lens.wgsl calls it).
        if camera in f or (camera == "pinhole" and "thin_lens" in f):
            out.append(("camera_%s.wgsl" % camera, "camera_%s.wgsl" % camera))
    if "thin_lens" in f:
        out.append(("concentric_map.wgsl", "concentric_map.wgsl"))
    if trace:
        for helper in _helpers(_shape_kinds(f)):
            out.append((helper, helper))
        for kind in _shape_kinds(f):
            chosen = formula if formula in kind.formulas else "slide"
            out.append((kind.wgsl_file, kind.formula_file(chosen)))
    if trace and "textures" in f:
        if "texcoord" in f:
            out.append(("texcoord.wgsl", "texcoord.wgsl"))
        used = []
        for kind in TEXTURES:
            if kind.name in f:
                used += [piece for piece in kind.uses if piece not in used] + [kind.name + ".wgsl"]
        out += [(piece, piece) for piece in used]
    if sampled_lights:
        out.append(("light_sample.wgsl", "light_sample.wgsl"))
    if trace and _lit(f):
        out.append(("lights.wgsl", "lights.wgsl"))
        if "shadows" in f:
            out.append(("in_shadow.wgsl", "in_shadow.wgsl"))
    if trace and _brdf_shaders(f) and not path:   # a path's diffuse vertex has its own light loop
        for name in sorted({k.brdf_of or k.name for k in _brdf_shaders(f)},
                           key=[k.name for k in SHADERS].index):
            out.append((name + ".wgsl", name + ".wgsl"))
        out.append(("direct_light.wgsl", "direct_light.wgsl"))
    continuing = [k for k in SHADERS if k.continues and k.name in f] if trace else []
    if continuing:
        out.append(("continue_path.wgsl", "continue_path.wgsl"))
        names = {k.name for k in continuing}
        if "glossy" in names or "dielectric" in names:
            names.add("transparent")
        if "reflective" in names:
            names.add("mirror")
        for kind in SHADERS:
            if kind.name in names:
                out.append((kind.name + ".wgsl", kind.name + ".wgsl"))
    if trace and not path:
        out.append(("shade.wgsl", "shade.wgsl"))
    if trace:
        out += [("intersect_scene.wgsl", "intersect_scene.wgsl"), ("environment.wgsl", "environment.wgsl")]
    if path:
        out += [("hemisphere_map.wgsl", "hemisphere_map.wgsl"), ("path_trace.wgsl", "path_trace.wgsl")]
    out.append(("main.wgsl", "main.wgsl"))
    return out


def piece_names() -> list:
    """Every piece a program may hold, for ``overrides``."""
    names = ["ray.wgsl", "hitinfo.wgsl", "random.wgsl", "sobol.wgsl", "pixel_sample.wgsl"]
    names += ["camera_%s.wgsl" % camera for camera in layout.CAMERA_KINDS.values()]
    names += ["concentric_map.wgsl"]
    names += _helpers(SHAPES) + [kind.wgsl_file for kind in SHAPES]
    names += ["texcoord.wgsl"] + sorted({piece for kind in TEXTURES for piece in kind.uses})
    names += [kind.name + ".wgsl" for kind in TEXTURES]
    names += ["light_sample.wgsl", "lights.wgsl", "in_shadow.wgsl", "direct_light.wgsl", "continue_path.wgsl"]
    names += [kind.name + ".wgsl" for kind in SHADERS if kind.name != "base_color"]
    return names + ["shade.wgsl", "intersect_scene.wgsl", "environment.wgsl", "hemisphere_map.wgsl",
                     "path_trace.wgsl", "main.wgsl"]


def each_kinds(flat, features, formula):
    """For ``// #each``: per list, the substitutions of each kind the scene has."""
    shapes = []
    for kind in SHAPES:
        if kind.name not in features or kind.bvh:   # a mesh kind has no rows to loop over
            continue
        args = ", ".join("rec." + name for name, _ in kind.fields)
        # An instance of a Mesh hits at its first index plus the face's place, and keeps the
        # face (intersect_instance.wgsl).
        of_mesh = kind.instance and "instanced_mesh" in features
        shapes.append({"$kind": kind.name, "$table": kind.table, "$TABLE": kind.table.upper(),
                       "$index": kind.name + "_index", "$args": args, "$KIND": kind.name.upper(),
                       "$place": " + instanced_place" if of_mesh else "",
                       "$keep": "instanced_face = candidate_face;" if of_mesh else ""})
    # The kinds intersect_scene and in_shadow loop over: the BVH holds the others.
    rows = [entry for entry in shapes
            if not (entry["$kind"] == "sphere" and "bvh_spheres" in features)
            and not (entry["$kind"] == "instance" and "bvh_instances" in features)]
    lights = [{"$kind": kind.name, "$table": kind.table, "$TABLE": kind.table.upper()}
              for kind in LIGHTS if len(flat.lights[kind.name])]
    shaders, brdfs = [], []
    for kind in SHADERS:
        if kind.name in features and kind.emits:
            shaders.append({"$ID": kind.name.upper(), "$body": "(*hit).emission"})
            continue
        if kind.name not in features or not (kind.brdf or kind.continues):
            continue
        if kind.continues and "trace" not in features:
            continue
        body = "direct_light(r, hit)" if kind.brdf and not kind.continues else "%s(r, hit)" % kind.name
        shaders.append({"$ID": kind.name.upper(), "$body": body})
        if kind.brdf:
            brdfs.append({"$ID": kind.name.upper(), "$of": kind.brdf_of or kind.name})
    textures = [{"$kind": kind.name, "$ID": str(k)} for k, kind in enumerate(TEXTURES)
                if kind.name in features]
    # The kinds the scene's instances hold, in their instanced tables (intersect_instance.wgsl).
    instanced = [{"$kind": kind.name, "$table": "instanced_" + kind.table, "$KIND": kind.name.upper(),
                  "$args": ", ".join("rec." + name for name, _ in kind.fields)}
                 for kind in INSTANCED if "instanced_" + kind.name in features]
    return {"shape": shapes, "row": rows, "light": lights, "instanced": instanced, "shader": shaders, "brdf": brdfs, "texture": textures}


# The arrays bound as storage buffers whatever their size.
STORAGE_ONLY = ("samples", "shuffled", "own_samples", "own_shuffled", "texels", "environment")
# The largest uniform buffer binding WebGPU guarantees (maxUniformBufferBindingSize).
MAX_UNIFORM_BYTES = 65536
# WebGPU's default maxUniformBuffersPerShaderStage (the adapters here and Chromium's hold to it).
MAX_UNIFORM_BUFFERS = 12
SCENE_BUFFER_KINDS = ("uniform", "storage")


class PieceNotInRelease(ValueError):
    """A WGSL piece this copy of rtfgu leaves out: a student release has no piece that
    computes an assignment's function again (rtfgu.grading.release)."""


def read_piece(name: str) -> str:
    piece = resources.files(__package__).joinpath(name)
    if not piece.is_file():
        raise PieceNotInRelease("rtfgu/wgsl/%s is not part of this release of rtfgu (it computes an assignment's "
                         "function again); render with backend='reference'" % name)
    return piece.read_text(encoding="utf-8")


def _packed_index(values: np.ndarray) -> np.ndarray:
    packed = np.zeros(4 * max(1, -(-len(values) // 4)), dtype=np.int32)
    packed[:len(values)] = values
    return packed


def binding_data(flat, name: str) -> np.ndarray:
    """The FlatScene array behind the binding ``name``."""
    if name in ("camera", "materials", "shaders", "material_of"):
        return getattr(flat, name)
    if name in ("samples", "shuffled"):
        return getattr(flat.sampler, name)
    if name in ("own_samples", "own_shuffled"):
        return getattr(flat, name)
    if name == "texels":
        return flat.texels
    if name == "environment":
        return flat.environment
    for kind in TEXTURES:
        if name == kind.table:
            return flat.textures[kind.name]
    if name in MESH_BINDINGS:
        return MESH_BINDINGS[name](flat)
    for kind in INSTANCED:
        if name == "instanced_" + kind.table:
            return flat.instanced[kind.name]
    for kind in SHAPES:
        if name == kind.table:
            return flat.table(kind.name)
        if name == kind.name + "_index":
            return flat.index(kind.name)
    for kind in LIGHTS:
        if name == kind.table:
            return flat.lights[kind.name]
    raise KeyError("no scene array is bound as %r" % name)


# The FlatMesh arrays of a scene with mesh triangles (intersect_mesh.wgsl), all in storage.
MESH_BINDINGS = {
    "mesh_vertices": lambda flat: flat.mesh.vertices,
    "mesh_faces": lambda flat: flat.mesh.faces,
    "mesh_normals": lambda flat: flat.mesh.normals,
    "mesh_uvs": lambda flat: flat.mesh.uvs,
    "bvh_nodes": lambda flat: flat.mesh.bvh.nodes,
}


@dataclass(frozen=True)
class Binding:
    """One scene buffer: @group(0) @binding(number) var<kind> name: wgsl_type."""

    number: int
    name: str
    wgsl_type: str
    kind: str  # "uniform" or "storage"
    size: int  # bytes
    is_index: bool  # int32 entries packed four to a vec4i

    def pack(self, flat) -> bytes:
        data = binding_data(flat, self.name)
        if self.is_index:
            return _packed_index(data).tobytes()
        if self.name in ("mesh_faces", "bvh_nodes"):   # int32 rows, and nodes that hold int32 bits
            raw = np.ascontiguousarray(data).tobytes()
            return raw + bytes(self.size - len(raw))
        packed = np.zeros(self.size // 4, dtype=np.float32)  # an empty array still binds 16 bytes
        packed[:data.size] = np.ascontiguousarray(data, dtype=np.float32).reshape(-1)
        return packed.tobytes()


@dataclass
class Program:
    """An assembled WGSL program: its text, where each line came from, and its bindings."""

    source: str
    line_origin: list  # per line of source: (file, line in that file)
    bindings: list
    features: frozenset
    pieces: list = field(default_factory=list)

    def origin(self, line: int) -> tuple:
        """(file, line in that file, enclosing function or None) of ``line`` (1-based)."""
        file, file_line = self.line_origin[line - 1]
        function = None
        lines = self.source.splitlines()
        for k in range(line - 1, -1, -1):
            m = re.match(r"\s*fn\s+(\w+)\s*\(", lines[k])
            if m:
                function = m.group(1)
                break
            if k < line - 1 and lines[k].startswith("}"):
                break
        return file, file_line, function


def scene_features(flat) -> frozenset:
    """FlatScene.features plus what the assembly derives from it: "trace" when the path
    loop runs (not the ray-direction image), "shapes" when there is any shape, "sampler"
    when the render has a sampler with sets (FlatScene.sampler), "sobol" when it is a Sobol
    (sobol.wgsl), "continues" when a shader of the scene
    continues the path (continue_path.wgsl)."""
    f = set(flat.features)
    if any(kind.continues and kind.name in f for kind in SHADERS):
        f.add("continues")
    if flat.sampler is not None:
        f.add("sampler" if flat.sampler.kind == "sets" else flat.sampler.kind)
    if len(flat.material_of):
        f.add("shapes")
    if not flat.show_ray_direction:
        f.add("trace")
    return frozenset(f)


def select_lines(text: str, features, name: str = "", each=None) -> list:
    """The (line number, text) pairs of ``text`` kept for ``features``, with every
    ``// #each LIST`` block repeated for the kinds in ``each[LIST]``."""
    each = each or {}
    keep = [True]
    out = []
    block = None  # (list name, line number of #each, [(number, line)])
    for number, line in enumerate(text.splitlines(), start=1):
        s = line.strip()
        if s.startswith("// #each "):
            if block is not None:
                raise ValueError("%s:%d: #each inside #each" % (name, number))
            block = (s[len("// #each "):].strip(), number, [])
        elif s == "// #end":
            if block is None:
                raise ValueError("%s:%d: #end without #each" % (name, number))
            what, start, lines = block
            if what not in each:
                raise ValueError("%s:%d: #each %s: no such list (known: %s)"
                                 % (name, start, what, ", ".join(sorted(each))))
            for substitutions in each[what]:
                for n, body in lines:
                    for key in sorted(substitutions, key=len, reverse=True):
                        body = body.replace(key, substitutions[key])
                    out.append((n, body))
            block = None
        elif s.startswith("// #if "):
            wanted = s[len("// #if "):].split("|")
            keep.append(keep[-1] and any(w.strip() in features for w in wanted))
        elif s == "// #else":
            if len(keep) < 2:
                raise ValueError("%s:%d: #else without #if" % (name, number))
            keep[-1] = keep[-2] and not keep[-1]
        elif s == "// #endif":
            if len(keep) < 2:
                raise ValueError("%s:%d: #endif without #if" % (name, number))
            keep.pop()
        elif keep[-1]:
            (block[2] if block is not None else out).append((number, line))
    if len(keep) != 1:
        raise ValueError("%s: #if without #endif" % name)
    if block is not None:
        raise ValueError("%s:%d: #each without #end" % (name, block[1]))
    return out


def _object_tree(name: str, text: str, features, each) -> list:
    """intersect_mesh.wgsl's mesh_closest once more as object_mesh_closest, without the rows of
    spheres and instances, where the scene's tree holds instances of a Mesh: the scene's
    mesh_closest tests such an instance, whose test enters its mesh's tree, and WGSL has no
    recursion (intersect_instance.wgsl). Else nothing."""
    if name != "intersect_mesh.wgsl" or not {"bvh_instances", "instanced_mesh"} <= set(features):
        return []
    selected = select_lines(text, set(features) - {"bvh_spheres", "bvh_instances"}, name, each)
    start = next(k for k, (_, line) in enumerate(selected) if line.startswith("fn mesh_closest("))
    end = next(k for k in range(start, len(selected)) if selected[k][1] == "}")
    return [(0, "")] + [(number, line.replace("fn mesh_closest(", "fn object_mesh_closest("))
                        for number, line in selected[start:end + 1]]


def _bindings(flat, features, scene_buffer: str) -> list:
    """The scene buffers, numbered in a stated order: the camera, then table and index of
    every shape kind the scene has, materials and shaders, then every light kind's table."""
    if scene_buffer not in SCENE_BUFFER_KINDS:
        raise ValueError("scene_buffer must be one of %s, got %r"
                         % (", ".join(SCENE_BUFFER_KINDS), scene_buffer))
    wanted = [("camera", layout.CAMERA_RECORDS[flat.camera_kind], flat.camera, False)]
    if flat.sampler is not None and flat.sampler.kind == "sets":
        wanted.append(("samples", "array<vec2f, %d>" % len(flat.sampler.samples),
                       flat.sampler.samples, False))
        wanted.append(("shuffled", "array<i32, %d>" % len(_packed_index(flat.sampler.shuffled)),
                       flat.sampler.shuffled, True))
    if "trace" in features:
        for kind in SHAPES:
            if kind.bvh and "instanced_mesh" in features and kind.name not in features:
                pass     # the meshes instances hold have their trees in the FlatMesh
            elif kind.name not in features:
                continue
            if kind.bvh:
                mesh = flat.mesh
                wanted.append(("mesh_vertices", "array<f32>", mesh.vertices, False))
                wanted.append(("mesh_faces", "array<vec4i>", mesh.faces, False))
                if mesh.normals is not None:
                    wanted.append(("mesh_normals", "array<f32>", mesh.normals, False))
                if mesh.uvs is not None and "texcoord" in features:
                    wanted.append(("mesh_uvs", "array<f32>", mesh.uvs, False))
                wanted.append(("bvh_nodes", "array<BVHNode>", mesh.bvh.nodes, False))
                continue
            count = "NUM_" + kind.table.upper()
            wanted.append((kind.table, "array<%s, %s>" % (kind.record, count),
                           flat.table(kind.name), False))
            index = flat.index(kind.name)
            wanted.append((kind.name + "_index", "array<vec4i, %d>" % (len(_packed_index(index)) // 4),
                           index, True))
        for kind in INSTANCED:   # the objects of the instances (intersect_instance.wgsl)
            table = flat.instanced[kind.name]
            if len(table):
                wanted.append(("instanced_" + kind.table, "array<%s, %d>" % (kind.record, len(table)), table, False))
        if len(flat.material_of):
            wanted.append(("materials", "array<Material, NUM_MATERIALS>", flat.materials, False))
            wanted.append(("shaders", "array<vec4i, %d>" % (len(_packed_index(flat.shaders)) // 4),
                           flat.shaders, True))
            wanted.append(("material_of", "array<vec4i, %d>" % (len(_packed_index(flat.material_of)) // 4),
                           flat.material_of, True))
        if "textures" in features:
            for kind in TEXTURES:
                table = flat.textures[kind.name]
                if len(table):
                    wanted.append((kind.table, "array<%s, %d>" % (kind.record, len(table)), table, False))
            wanted.append(("texels", "array<f32, %d>" % len(flat.texels), flat.texels, False))
        if "environment" in features:
            wanted.append(("environment", "array<f32, %d>" % flat.environment.size, flat.environment, False))
        if _lit(features):
            for kind in LIGHTS:
                table = flat.lights[kind.name]
                if len(table):
                    wanted.append((kind.table, "array<%s, NUM_%s>" % (kind.record, kind.table.upper()),
                                   table, False))
        if "own_sampler" in features:
            wanted.append(("own_samples", "array<vec2f, %d>" % len(flat.own_samples), flat.own_samples, False))
            wanted.append(("own_shuffled", "array<i32, %d>" % len(_packed_index(flat.own_shuffled)),
                           flat.own_shuffled, True))
    result = []
    for number, (name, wgsl_type, data, is_index) in enumerate(wanted, start=1):
        size = len(_packed_index(data)) * 4 if is_index else max(data.size, 4) * 4
        if name == "camera":
            kind = "uniform"
        elif name in STORAGE_ONLY or name in MESH_BINDINGS:
            kind = "storage"
        else:
            kind = scene_buffer if size <= MAX_UNIFORM_BYTES else "storage"
        result.append(Binding(number, name, wgsl_type, kind, size, is_index))
    # WebGPU's default limit of uniform buffers per shader stage counts ``uniforms`` too: the
    # largest of the others go to storage until the rest fit (a browser holds to the default).
    uniform = sorted((b for b in result if b.kind == "uniform" and b.name != "camera"), key=lambda b: -b.size)
    excess = len(uniform) + 2 - MAX_UNIFORM_BUFFERS
    moved = {b.name for b in uniform[:max(0, excess)]}
    return [dataclasses.replace(b, kind="storage") if b.name in moved else b for b in result]


def _header(flat, features, bindings) -> str:
    parts = ["// The scene layout and ids, generated from rtfgu/layout.py.", structs.constants_wgsl()]
    counts = [("NUM_MATERIALS", len(flat.materials))]
    if flat.sampler is not None:
        counts += [("NUM_SAMPLES", flat.sampler.num_samples), ("NUM_SETS", flat.sampler.num_sets)]
    counts += [("NUM_" + kind.table.upper(), flat.count(kind.name)) for kind in SHAPES]
    counts += [("NUM_" + kind.table.upper(), len(flat.lights[kind.name])) for kind in LIGHTS]
    if "path_trace" in features:
        counts += [("PATH_MAX_DEPTH", flat.max_depth), ("PATH_LIGHTS_AT_EVERY_VERTEX", int(flat.lights_at_every_vertex))]
    if "environment" in features:
        counts += [("ENVIRONMENT_HEIGHT", flat.environment.shape[0]), ("ENVIRONMENT_WIDTH", flat.environment.shape[1])]
    parts.append("\n".join("const %s = %du;" % c for c in counts))
    used = {b.wgsl_type.split("<")[-1].split(",")[0].rstrip(">") for b in bindings}
    for record in layout.RECORDS:
        if record in used:
            parts.append(structs.struct_wgsl(record))
    parts.append(structs.UNIFORMS_WGSL)
    decls = ["@group(0) @binding(0) var<uniform> uniforms: Uniforms;"]
    for b in bindings:
        space = "uniform" if b.kind == "uniform" else "storage, read"
        decls.append("@group(0) @binding(%d) var<%s> %s: %s;" % (b.number, space, b.name, b.wgsl_type))
    decls.append("@group(1) @binding(0) var<storage, read_write> image: array<vec4f>;")
    parts.append("\n".join(decls))
    return "\n\n".join(parts)


def assemble(flat, scene_buffer: str = "uniform", overrides: dict | None = None,
             formula: str | None = None, entry: str = "main.wgsl") -> Program:
    """The WGSL program for the FlatScene ``flat`` (float32 layout).

    scene_buffer: "uniform" or "storage", the address space of the scene arrays (an array
    larger than MAX_UNIFORM_BYTES goes to storage either way).
    overrides: {file name: WGSL text} used instead of the package's file, e.g. a student's
    own lambertian.wgsl.
    formula: the intersection formula, "slide" or "robust" (None: DEFAULT_SPHERE_FORMULA),
    for every shape kind that has it.
    entry: the piece with ``fn main``: main.wgsl (the image) or debug_main.wgsl (the
    pixel debugger's records, rtfgu/wgsl/debug.py), which adds the feature "debug"."""
    formula = check_formula(formula)
    overrides = dict(overrides or {})
    unknown = set(overrides) - set(piece_names())
    if unknown:
        raise ValueError("overrides: unknown WGSL file(s) %s; known: %s"
                         % (", ".join(sorted(unknown)), ", ".join(piece_names())))
    features = scene_features(flat)
    if entry != "main.wgsl":
        features |= {"debug"}
    bindings = _bindings(flat, features, scene_buffer)
    each = each_kinds(flat, features, formula)
    lines, origin, used = [], [], []
    for number, line in enumerate(_header(flat, features, bindings).splitlines(), start=1):
        lines.append(line)
        origin.append((GENERATED, number))
    for name, source in pieces(features, formula):
        if name == "main.wgsl":
            source = entry
        if name in overrides:
            source = name
        used.append(source)
        text = overrides[name] if name in overrides else read_piece(source)
        lines.append("")
        origin.append((GENERATED, 0))
        lines.append("// ---- rtfgu/wgsl/%s" % source)
        origin.append((source, 0))
        for number, line in select_lines(text, features, source, each) + _object_tree(name, text, features, each):
            lines.append(line)
            origin.append((source, number))
    return Program("\n".join(lines) + "\n", origin, bindings, features, used)
