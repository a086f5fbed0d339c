"""Join the .wgsl files of this package into one program for one scene.

Only the pieces a scene uses are joined, in the order of ``PIECES`` (a function is defined
before the functions that call it, as a student reads it): the structs and constants
generated from rtfgu.layout, the ray, the camera, the intersection functions, the light
sample, the shaders, shade, intersect_scene and main. Inside a file, lines between
``// #if FEATURE`` (``a|b`` for either) and ``// #endif`` (with an optional ``// #else``)
are kept only when the scene has that feature, so that e.g. shade's switch holds only the
cases the scene uses.

The sphere test has two files with the same ``fn intersect_sphere``: the slide's quadratic
(intersect_sphere.wgsl) and Ray Tracing Gems ch. 7 (robust_sphere.wgsl); ``formula`` picks
one for the piece ``intersect_sphere.wgsl``. An override of that piece (a student's own
file) is used whatever the formula.

Only counts and kinds go into the program text; the scene's numbers go into buffers
(``Binding.pack``), so moving the camera or a light reuses the compiled pipeline.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from importlib import resources

import numpy as np

from .. import layout
from . import structs

# Shaders that sample the lights.
LIGHT_SHADERS = frozenset({"lambertian", "phong", "glossy"})


def _needs(*any_of):
    return lambda f: any(name in f for name in any_of)


def _has_all(*all_of):
    return lambda f: all(name in f for name in all_of)


# (file, when it is needed): the stated order of the assembled program.
PIECES = (
    ("ray.wgsl", lambda f: True),
    ("hitinfo.wgsl", lambda f: "trace" in f),
    ("camera_orthographic.wgsl", _needs("orthographic")),
    ("camera_pinhole.wgsl", _needs("pinhole")),
    ("intersect_plane.wgsl", _has_all("trace", "plane")),
    ("intersect_triangle.wgsl", _has_all("trace", "triangle")),
    ("intersect_sphere.wgsl", _has_all("trace", "sphere")),
    ("lights.wgsl", _needs("sample_lights")),
    ("in_shadow.wgsl", _has_all("sample_lights", "shadows")),
    ("lambertian.wgsl", _has_all("trace", "lambertian")),
    ("phong.wgsl", lambda f: "trace" in f and ("phong" in f or "glossy" in f)),
    ("continue_path.wgsl", lambda f: "trace" in f and bool({"mirror", "transparent", "glossy"} & f)),
    ("mirror.wgsl", _has_all("trace", "mirror")),
    ("transparent.wgsl", lambda f: "trace" in f and ("transparent" in f or "glossy" in f)),
    ("glossy.wgsl", _has_all("trace", "glossy")),
    ("shade.wgsl", _needs("trace")),
    ("intersect_scene.wgsl", _needs("trace")),
    ("main.wgsl", lambda f: True),
)

GENERATED = "<generated from rtfgu.layout>"

# The file that holds intersect_sphere, per sphere formula.
SPHERE_FILES = {"slide": "intersect_sphere.wgsl", "robust": "robust_sphere.wgsl"}
# The sphere formula of a WGSL render unless one is asked for (docs/robust_defaults.md).
DEFAULT_SPHERE_FORMULA = "robust"


def sphere_file(formula) -> str:
    """The .wgsl file of intersect_sphere for ``formula`` ("slide", "robust", None: default)."""
    if formula is None:
        formula = DEFAULT_SPHERE_FORMULA
    if formula not in SPHERE_FILES:
        raise ValueError("formula must be one of %s, got %r" % (", ".join(SPHERE_FILES), formula))
    return SPHERE_FILES[formula]

# The largest uniform buffer binding WebGPU guarantees (maxUniformBufferBindingSize).
MAX_UNIFORM_BYTES = 65536
SCENE_BUFFER_KINDS = ("uniform", "storage")


def read_piece(name: str) -> str:
    return resources.files(__package__).joinpath(name).read_text(encoding="utf-8")


def piece_names() -> list:
    return [name for name, _ in PIECES]


def _packed_index(values: np.ndarray) -> np.ndarray:
    packed = np.zeros(4 * max(1, -(-len(values) // 4)), dtype=np.int32)
    packed[:len(values)] = values
    return packed


@dataclass(frozen=True)
class Binding:
    """One scene buffer: @group(0) @binding(number) var<kind> name: wgsl_type."""

    number: int
    name: str
    wgsl_type: str
    kind: str  # "uniform" or "storage"
    size: int  # bytes
    source: str  # FlatScene field the bytes come from

    def pack(self, flat) -> bytes:
        data = getattr(flat, self.source)
        if self.source in ("plane_index", "triangle_index", "sphere_index", "shaders"):
            return _packed_index(data).tobytes()
        return np.ascontiguousarray(data, dtype=np.float32).tobytes()


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
    loop runs (not the ray-direction image), "sample_lights" when a shader samples lights,
    "shapes" when there is any shape."""
    f = set(flat.features)
    if len(flat.shaders):
        f.add("shapes")
    if not flat.show_ray_direction:
        f.add("trace")
        if "lights" in f and LIGHT_SHADERS & f:
            f.add("sample_lights")
    return frozenset(f)


def select_lines(text: str, features, name: str = "") -> list:
    """The (line number, text) pairs of ``text`` kept for ``features``."""
    keep = [True]
    out = []
    for number, line in enumerate(text.splitlines(), start=1):
        s = line.strip()
        if s.startswith("// #if "):
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
            out.append((number, line))
    if len(keep) != 1:
        raise ValueError("%s: #if without #endif" % name)
    return out


def _bindings(flat, features, scene_buffer: str) -> list:
    if scene_buffer not in SCENE_BUFFER_KINDS:
        raise ValueError("scene_buffer must be one of %s, got %r"
                         % (", ".join(SCENE_BUFFER_KINDS), scene_buffer))
    trace = "trace" in features
    camera_struct = ("OrthographicCamera" if flat.camera_kind == layout.ORTHOGRAPHIC
                     else "PinholeCamera")
    wanted = [(1, "camera", camera_struct, "camera", None)]
    if trace:
        for kind, table, record, count in (("plane", "planes", "Plane", "NUM_PLANES"),
                                           ("triangle", "triangles", "Triangle", "NUM_TRIANGLES"),
                                           ("sphere", "spheres", "Sphere", "NUM_SPHERES")):
            if kind in features:
                number = {"plane": 2, "triangle": 4, "sphere": 6}[kind]
                wanted.append((number, table, "array<%s, %s>" % (record, count), table,
                               len(getattr(flat, table))))
                wanted.append((number + 1, kind + "_index",
                               "array<vec4i, %d>" % (len(_packed_index(getattr(flat, kind + "_index"))) // 4),
                               kind + "_index", None))
        if len(flat.shaders):
            wanted.append((8, "materials", "array<Material, NUM_SHAPES>", "materials", None))
            wanted.append((9, "shaders", "array<vec4i, %d>" % (len(_packed_index(flat.shaders)) // 4),
                           "shaders", None))
        if "sample_lights" in features:
            wanted.append((10, "lights", "array<PointLight, NUM_LIGHTS>", "lights", None))
    result = []
    for number, name, wgsl_type, source, _ in wanted:
        data = getattr(flat, source)
        size = (len(_packed_index(data)) * 4 if source.endswith("index") or source == "shaders"
                else data.size * 4)
        kind = scene_buffer if size <= MAX_UNIFORM_BYTES else "storage"
        if source == "camera":
            kind = "uniform"
        result.append(Binding(number, name, wgsl_type, kind, size, source))
    return result


def _header(flat, features, bindings) -> str:
    parts = ["// The scene layout and ids, generated from rtfgu/layout.py.", structs.constants_wgsl()]
    counts = [("NUM_SHAPES", len(flat.shaders)), ("NUM_PLANES", len(flat.planes)),
              ("NUM_TRIANGLES", len(flat.triangles)), ("NUM_SPHERES", len(flat.spheres)),
              ("NUM_LIGHTS", len(flat.lights))]
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
             formula: str | None = None) -> Program:
    """The WGSL program for the FlatScene ``flat`` (float32 layout).

    scene_buffer: "uniform" or "storage", the address space of the scene arrays (an array
    larger than MAX_UNIFORM_BYTES goes to storage either way).
    overrides: {file name: WGSL text} used instead of the package's file, e.g. a student's
    own lambertian.wgsl.
    formula: the sphere test, "slide" or "robust" (None: DEFAULT_SPHERE_FORMULA)."""
    sphere_source = sphere_file(formula)
    overrides = dict(overrides or {})
    unknown = set(overrides) - set(piece_names())
    if unknown:
        raise ValueError("overrides: unknown WGSL file(s) %s; known: %s"
                         % (", ".join(sorted(unknown)), ", ".join(piece_names())))
    features = scene_features(flat)
    bindings = _bindings(flat, features, scene_buffer)
    lines, origin, used = [], [], []
    for number, line in enumerate(_header(flat, features, bindings).splitlines(), start=1):
        lines.append(line)
        origin.append((GENERATED, number))
    for name, needed in PIECES:
        if not needed(features):
            continue
        source = name
        if name == "intersect_sphere.wgsl" and name not in overrides:
            source = sphere_source
        used.append(source)
        text = overrides[name] if name in overrides else read_piece(source)
        lines.append("")
        origin.append((GENERATED, 0))
        lines.append("// ---- rtfgu/wgsl/%s" % source)
        origin.append((source, 0))
        for number, line in select_lines(text, features, source):
            lines.append(line)
            origin.append((source, number))
    return Program("\n".join(lines) + "\n", origin, bindings, features, used)
