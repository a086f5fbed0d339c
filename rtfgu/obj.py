"""load_obj: a Wavefront OBJ file and its MTL materials as a ``Mesh`` (Suffern ch. 23 reads
PLY files into a Mesh; the 02562 worksheets read their triangle meshes from OBJ files).

    mesh = rtfgu.load_obj(rtfgu.obj.mesh_path("bunny.obj"))
    scene.shapes.append(mesh)                      # its faces (or scene.shapes += mesh.triangles())

What is read: ``v`` (x y z, optionally w or r g b, which are ignored), ``vn``, ``vt``
(u v, an optional w ignored), ``f`` with 3 or more corners, ``mtllib`` (one per file) and ``usemtl``.
A polygon becomes the fan of triangles (c0, c_i, c_i+1) around its first corner, wound as
the polygon. From the MTL file, ``Kd`` is a face's colour and ``Ke`` its emission (on a copy
of ``material``); a face before any ``usemtl``, or whose MTL material has no ``Kd``, gets
``default_color``. Vertex normals, when every ``f`` corner names one (``v//vn`` or
``v/vt/vn``), make the mesh smooth-shaded (``SmoothMeshTriangle``); otherwise it is flat.
Texture coordinates, when every corner names one (``v/vt`` or ``v/vt/vn``), are the mesh's
``uvs``: a face's (u, v) is its corners' interpolated (Suffern's UV mesh triangles), with
(0, 0) the image's bottom-left corner as in ``ImageTexture``. A vertex met with two ``vt``s
becomes two vertices at the same place (trimesh's split), so the faces still share edges
exactly.
``g``, ``o``, ``s``, ``l``, ``p`` and comments are skipped. The faces come grouped by
material, the materials in the order they first appear, each material's faces in file order.

The loader is trimesh (``trimesh.exchange.obj.load_obj``): maintained, MIT, a pure Python +
numpy wheel for every Python rtfgu supports, vectorised with numpy, so that a
million-triangle file loads in seconds; it parses the numbers, triangulates the polygons
and pairs each vertex with its normal. The alternatives: tinyobjloader's Python bindings
are faster but published as release candidates only; PyWavefront and meshio read OBJ line
by line in Python, and meshio reads no materials. trimesh is imported only when a file is
loaded. It is given the geometry only: load_obj reads the MTL file itself (a few lines) and
hands trimesh one text per material (rtfgu.obj._material_sections).

trimesh is lenient: it skips what it cannot read and misreads some input (a face index 0,
a short ``v`` line, faces written in two corner formats) without an error. So load_obj
checks the text first, with one regular expression per statement, and the arrays trimesh
returns afterwards. Bad input is a ValueError naming the file, the line and the statement:
a missing file (OBJ or MTL), a malformed line, a face index out of range, a vertex that is
not finite (NaN, an overflow), a zero vertex normal, an unknown ``usemtl`` name, a file
without faces, and a triangle of zero area (refused; ``drop_degenerate=True`` drops such
triangles with a warning instead, for scanned data). Where trimesh itself fails, the file
is read once more, line by line, to find the line (rtfgu.obj._diagnose).
"""
from __future__ import annotations

import copy

import io
import math
import re
import warnings
from pathlib import Path

from .lazy_import import numpy as np

from .materials.material import Material
from .shapes.mesh import Mesh, zero_area_faces
from .validation import colour

DEFAULT_COLOR = (0.8, 0.8, 0.8)
MESHES_DIR = Path(__file__).resolve().parent / "meshes"

_NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_IDX = r"-?[1-9]\d*"
_S = r"[ \t]+"
# The four ways an f corner is written; a file must use one of them throughout, as the
# corner format of its first face decides how trimesh reads every face.
_CORNERS = {
    "v": _IDX,
    "v/vt": _IDX + "/" + _IDX,
    "v//vn": _IDX + "//" + _IDX,
    "v/vt/vn": _IDX + "/" + _IDX + "/" + _IDX,
}
_STATEMENTS = {
    "v": rf"v(?:{_S}{_NUM}){{3}}(?:{_S}{_NUM}|(?:{_S}{_NUM}){{3}})?",
    "vn": rf"vn(?:{_S}{_NUM}){{3}}",
    "vt": rf"vt(?:{_S}{_NUM}){{1,3}}",
    "usemtl": r"usemtl[ \t]+\S+",
    "mtllib": r"mtllib[ \t]+\S+",
    "other": r"(?:g|o|s|l|p|vp)(?:[ \t][^\n]*)?",
}


def mesh_path(name: str) -> Path:
    """The path of a mesh shipped with rtfgu (rtfgu/meshes/: ``bunny.obj``,
    ``teapot.obj``, ``cornell_box.obj``; rtfgu/meshes/README.md says where each is from)."""
    path = MESHES_DIR / name
    if not path.is_file():
        shipped = sorted(p.name for p in MESHES_DIR.glob("*.obj"))
        raise ValueError("mesh_path: rtfgu ships no mesh %r (it ships %s)" % (name, ", ".join(shipped)))
    return path


def load_obj(path, material: Material | None = None, default_color=DEFAULT_COLOR,
             drop_degenerate: bool = False) -> Mesh:
    """The triangles of the OBJ file ``path`` as a Mesh: a colour per face from its MTL
    ``Kd``, ``material`` (default ``Material()``) for every face, with the MTL's ``Ke`` as
    emission where it is given."""
    path = Path(path)
    if material is not None and not isinstance(material, Material):
        raise ValueError("load_obj: material must be a Material or None, got %r" % (material,))
    text = _read_text(path)
    form = _check_statements(text, path)
    library = _material_library(text, path)
    _check_usemtl(text, path, library)
    _check_relative_indices(text, path)
    geometries = [(name, geometry) for name, part in _material_sections(text)
                  for geometry in _trimesh_geometries(part, text, path)]

    smooth, textured = "vn" in form, "vt" in form
    vertices, faces, normals, uvs, names = [], [], [], [], []
    offset = 0
    for name, geometry in geometries:
        polygons = np.asarray(geometry.get("faces"))
        v = np.asarray(geometry.get("vertices"), dtype=np.float64)
        if polygons.ndim != 2 or polygons.shape[1] < 3 or v.ndim != 2 or v.shape[1] != 3:
            _diagnose(text, path)
            raise ValueError("load_obj: %s: trimesh returned faces %s and vertices %s"
                             % (path, polygons.shape, v.shape))
        if not np.isfinite(v).all():
            _diagnose(text, path)
        n = geometry.get("vertex_normals")
        if smooth and (n is None or np.shape(n) != v.shape):
            _diagnose(text, path)
            warnings.warn("load_obj: %s: trimesh returned no vertex normals for some faces; "
                          "the mesh is flat-shaded" % path)
            smooth = False
        uv = getattr(geometry.get("visual"), "uv", None) if textured else None
        if textured and (uv is None or np.shape(uv) != (len(v), 2)):
            _diagnose(text, path)
            raise ValueError("load_obj: %s: trimesh returned texture coordinates %s for %d vertices"
                             % (path, None if uv is None else np.shape(uv), len(v)))
        uvs.append(uv)
        vertices.append(v)
        faces.append(_fan(polygons) + offset)
        normals.append(n)
        names.append(name)
        offset += len(v)

    vertices = np.concatenate(vertices)
    triangles = np.concatenate(faces).astype(np.int64)
    if smooth:
        normals = np.asarray(np.concatenate(normals), dtype=np.float64)
        if not (np.isfinite(normals).all() and (np.abs(normals).sum(axis=1) > 0).all()):
            _diagnose(text, path)
            raise ValueError("load_obj: %s: a vertex normal is zero or not finite" % path)
    else:
        normals = None
    uvs = np.asarray(np.concatenate(uvs), dtype=np.float64) if textured else None
    if uvs is not None and not np.isfinite(uvs).all():
        _diagnose(text, path)
        raise ValueError("load_obj: %s: a texture coordinate is not finite" % path)
    counts = [len(f) for f in faces]
    colors, materials = _face_materials(names, counts, library, material, default_color)

    flat = zero_area_faces(vertices, triangles)
    if len(flat):
        if not drop_degenerate:
            _diagnose(text, path, check_area=True)
            raise ValueError("load_obj: %s: triangle %d spans zero area" % (path, flat[0]))
        warnings.warn("load_obj: %s: dropped %d triangles of zero area" % (path, len(flat)))
        keep = np.ones(len(triangles), dtype=bool)
        keep[flat] = False
        triangles, colors = triangles[keep], colors[keep]
        materials = [m for m, k in zip(materials, keep) if k]
        if len(triangles) == 0:
            raise ValueError("load_obj: %s: every triangle spans zero area" % path)
    return Mesh(vertices, triangles, colors, normals=normals, material=materials, uvs=uvs)


def _where(path: Path, line: int, field: str) -> str:
    return "load_obj: %s, line %d, %s" % (path, line, field)


def _line_of(text: str, offset: int) -> int:
    return text.count("\n", 0, offset) + 1


def _read_text(path: Path) -> str:
    if not path.is_file():
        raise ValueError("load_obj: no such file %s" % path)
    data = path.read_bytes()
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as error:
        line = data.count(b"\n", 0, error.start) + 1
        raise ValueError("%s: not UTF-8 text (byte %d)" % (_where(path, line, "text"), error.start)) from None
    text = text.replace("\r\n", "\n").replace("\r", "\n")
    # What trimesh reads is the text without comments, tabs as spaces and no indent, line
    # for line the file (so that line numbers stay those of the file).
    if "#" in text:
        text = re.sub(r"#[^\n]*", "", text)
    continued = text.find("\\\n")
    if continued >= 0:
        raise ValueError("%s: a line continued with '\\' is not supported"
                         % _where(path, _line_of(text, continued), "text"))
    if "\t" in text:
        text = text.replace("\t", " ")
    if re.search(r"^ +\S", text, re.M):
        text = re.sub(r"^ +", "", text, flags=re.M)
    return text


def _check_statements(text: str, path: Path) -> str:
    """The corner format of the faces ("v", "v/vt", "v//vn", "v/vt/vn"); a ValueError at
    the first line that is not a statement load_obj reads, or is malformed."""
    first = re.search(r"^f(?= |$) *(\S*)", text, re.M)
    if first is None:
        raise ValueError("load_obj: %s: no faces (no 'f' line): an empty mesh" % path)
    corner = first.group(1) or ""
    form = next((name for name, pattern in _CORNERS.items() if re.fullmatch(pattern, corner)), None)
    if form is None:
        _explain(text, path, first.start(), None)
    face = rf"f(?:{_S}{_CORNERS[form]}){{3,}}"
    good = "|".join([face] + list(_STATEMENTS.values()) + [""])
    bad = re.search(r"^(?!(?:%s) *$)[^\n]*" % good, text, re.M)
    if bad is not None:
        _explain(text, path, bad.start(), (form, first.start()))
    return form


def _explain(text: str, path: Path, offset: int, form) -> None:
    """Raise the ValueError for the malformed line at ``offset``, naming what is wrong."""
    line = _line_of(text, offset)
    end = text.find("\n", offset)
    fields = text[offset:end if end >= 0 else len(text)].split()
    key = fields[0]
    where = _where(path, line, "'%s'" % key)
    numbers = {"v": (3, 4, 6), "vn": (3,), "vt": (1, 2, 3)}
    if key in numbers:
        for i, token in enumerate(fields[1:], 1):
            if not re.fullmatch(_NUM, token):
                try:
                    value = float(token)
                except ValueError:
                    raise ValueError("%s: value %d, %r, is not a number" % (where, i, token)) from None
                raise ValueError("%s: value %d, %r, is not finite" % (where, i, value))
        counts = [str(n) for n in numbers[key]]
        expected = counts[0] if len(counts) == 1 else ", ".join(counts[:-1]) + " or " + counts[-1]
        raise ValueError("%s: %s numbers expected, got %d" % (where, expected, len(fields) - 1))
    if key == "f":
        if len(fields) < 4:
            raise ValueError("%s: a face needs at least 3 corners, got %d" % (where, len(fields) - 1))
        for i, token in enumerate(fields[1:], 1):
            written = next((n for n, p in _CORNERS.items() if re.fullmatch(p, token)), None)
            if written is None:
                zero = any(part.lstrip("-") == "0" for part in token.split("/"))
                raise ValueError("%s: corner %d, %r, is not v, v/vt, v//vn or v/vt/vn with indices %s"
                                 % (where, i, token, "starting at 1 (0 is no index in OBJ)" if zero
                                    else "that are whole numbers other than 0"))
            if form is not None and written != form[0]:
                raise ValueError("%s: corner %d, %r, is written %s, but the first face (line %d) "
                                 "is written %s; load_obj needs one corner format per file"
                                 % (where, i, token, written, _line_of(text, form[1]), form[0]))
    if key in ("usemtl", "mtllib"):
        raise ValueError("%s: one name without spaces expected, got %d words"
                         % (where, len(fields) - 1))
    raise ValueError("%s: not a statement load_obj reads (v, vn, vt, f, g, o, s, l, p, "
                     "usemtl, mtllib)" % where)


def _material_library(text: str, path: Path) -> dict:
    """name -> {"Kd": (r, g, b) or None, "Ke": (r, g, b) or None} of the file's mtllib."""
    libraries = list(re.finditer(r"^mtllib +(\S+)", text, re.M))
    if not libraries:
        return {}
    if len(libraries) > 1:
        raise ValueError("%s: a second material library; load_obj reads one per file"
                         % _where(path, _line_of(text, libraries[1].start()), "'mtllib'"))
    mtl = path.parent / libraries[0].group(1)
    if not mtl.is_file():
        raise ValueError("%s: no such material library %s"
                         % (_where(path, _line_of(text, libraries[0].start()), "'mtllib'"), mtl))
    return _read_mtl(mtl)


def _read_mtl(path: Path) -> dict:
    library = {}
    current = None
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except UnicodeDecodeError:
        raise ValueError("load_obj: %s: not UTF-8 text" % path) from None
    for number, line in enumerate(lines, 1):
        fields = line.split("#", 1)[0].split()
        if not fields:
            continue
        key = fields[0]
        where = _where(path, number, "'%s'" % key)
        if key == "newmtl":
            if len(fields) != 2:
                raise ValueError("%s: one name without spaces expected, got %d words"
                                 % (where, len(fields) - 1))
            if fields[1] in library:
                raise ValueError("%s: material %r is defined twice" % (where, fields[1]))
            current = library[fields[1]] = {"Kd": None, "Ke": None}
        elif key in ("Kd", "Ke"):
            if current is None:
                raise ValueError("%s: before any newmtl" % where)
            try:
                values = [float(x) for x in fields[1:]]
            except ValueError:
                raise ValueError("%s: r g b numbers expected, got %r (spectral and xyz "
                                 "colours are not read)" % (where, " ".join(fields[1:]))) from None
            if len(values) == 1:
                values *= 3
            if len(values) != 3 or not all(math.isfinite(x) and x >= 0 for x in values):
                raise ValueError("%s: r g b expected, three finite numbers >= 0, got %r"
                                 % (where, " ".join(fields[1:])))
            current[key] = tuple(values)
    return library


def _check_usemtl(text: str, path: Path, library: dict) -> None:
    uses = re.finditer(r"^usemtl +(\S+)", text, re.M)
    for use in uses:
        if use.group(1) not in library:
            raise ValueError("%s: material %r is not in the material library%s"
                             % (_where(path, _line_of(text, use.start()), "'usemtl'"), use.group(1),
                                "" if library else " (the file has no mtllib)"))


def _check_relative_indices(text: str, path: Path) -> None:
    """A negative index counts back from the last vertex read so far (the OBJ
    specification); trimesh counts back from the file's last vertex. The two agree when
    every vertex comes before the first face."""
    negative = re.search(r"^f [^\n]*[ /]-", text, re.M)
    if negative is None:
        return
    first_face = re.search(r"^f ", text, re.M).start()
    later = re.compile(r"^v[nt]? ", re.M).search(text, first_face)
    if later is not None:
        raise ValueError("%s: negative (relative) indices are read only in a file whose "
                         "vertices all come before its first face (line %d), but line %d "
                         "defines another" % (_where(path, _line_of(text, negative.start()), "'f'"),
                                              _line_of(text, first_face), _line_of(text, later.start())))


def _material_sections(text: str) -> list:
    """(material name or None, OBJ text) per material, in the order the materials first
    appear. trimesh reads each text on its own and is never asked about materials: with
    one material the text is the file's, otherwise it is every v, vn and vt line followed
    by that material's f lines (the indices stay those of the file)."""
    uses = list(re.finditer(r"^usemtl +(\S+)", text, re.M))
    if not uses:
        return [(None, text)]
    bounds = [0] + [use.start() for use in uses] + [len(text)]
    names = [None] + [use.group(1) for use in uses]
    face_lines = re.compile(r"^f [^\n]*", re.M)
    faces = {}
    for name, start, end in zip(names, bounds, bounds[1:]):
        lines = face_lines.findall(text, start, end)
        if lines:
            faces.setdefault(name, []).extend(lines)
    if len(faces) == 1:
        return [(next(iter(faces)), text)]
    vertex_lines = "\n".join(re.findall(r"^v[nt]? [^\n]*", text, re.M))
    return [(name, vertex_lines + "\n" + "\n".join(lines) + "\n") for name, lines in faces.items()]


def _trimesh_geometries(part: str, text: str, path: Path) -> list:
    """The meshes trimesh reads from ``part`` (the file's ``text`` or a section of it)."""
    try:
        import trimesh.exchange.obj
    except ImportError:
        raise ImportError("load_obj reads OBJ files with trimesh: pip install trimesh") from None
    try:
        loaded = trimesh.exchange.obj.load_obj(io.StringIO(part), skip_materials=True)
    except (IndexError, ValueError, TypeError) as error:
        _diagnose(text, path)
        raise ValueError("load_obj: %s: trimesh could not read the file (%s)" % (path, error)) from error
    # one dict per group of faces; a single mesh may come as that dict itself
    geometries = list(loaded["geometry"].values()) if "geometry" in loaded else \
        [loaded] if "faces" in loaded else []
    if not geometries:
        _diagnose(text, path)
        raise ValueError("load_obj: %s: no faces: an empty mesh" % path)
    return geometries


def _fan(polygons: np.ndarray) -> np.ndarray:
    """(k, p) polygons as the k (p - 2) triangles (c0, c_i, c_i+1), a polygon's together."""
    p = polygons.shape[1]
    fans = [polygons[:, [0, i, i + 1]] for i in range(1, p - 1)]
    return np.stack(fans, axis=1).reshape(-1, 3)


def _face_materials(names, counts, library, material, default_color):
    """A colour and a Material per triangle: ``counts[i]`` triangles of MTL material
    ``names[i]`` (None: none)."""
    base = Material() if material is None else material
    emitting = {}
    colors, materials = [], []
    default = np.asarray(default_color, dtype=np.float64)
    if default.shape != (3,) or not np.isfinite(default).all():
        raise ValueError("load_obj: default_color must be three finite numbers, got %r" % (default_color,))
    for name, count in zip(names, counts):
        entry = library.get(name, {}) if name is not None else {}
        kd = entry.get("Kd")
        colors.append(np.broadcast_to(default if kd is None else np.asarray(kd), (count, 3)))
        ke = entry.get("Ke")
        if ke is not None and any(ke):
            if name not in emitting:
                emitting[name] = copy.copy(base)
                emitting[name].emission = colour(ke, "load_obj: material %r Ke" % (name,))
            materials += [emitting[name]] * count
        else:
            materials += [base] * count
    return np.concatenate(colors), materials


def _diagnose(text: str, path: Path, check_area: bool = False) -> None:
    """Read ``text`` line by line and raise a ValueError at the first line that is wrong
    (an index out of range, a vertex not finite, a zero normal, a zero-area triangle);
    return if there is none. Slow, and used only once something is known to be wrong."""
    lines = text.split("\n")
    totals = {key: sum(1 for s in lines if s.startswith(key + " ")) for key in ("v", "vt", "vn")}
    positions, seen = [], {"v": 0, "vt": 0, "vn": 0}
    for number, line in enumerate(lines, 1):
        fields = line.split()
        if not fields:
            continue
        key = fields[0]
        where = _where(path, number, "'%s'" % key)
        if key in ("v", "vn"):
            values = tuple(float(x) for x in fields[1:4])
            if not all(math.isfinite(x) for x in values):
                raise ValueError("%s: %s is not finite" % (where, values))
            if key == "vn" and not any(values):
                raise ValueError("%s: the normal is the zero vector" % where)
            if key == "v":
                positions.append(values)
        if key in seen:
            seen[key] += 1
        if key != "f":
            continue
        corners = []
        for i, token in enumerate(fields[1:], 1):
            for part, kind in zip(token.split("/"), ("v", "vt", "vn")):
                if part == "":
                    continue
                index = int(part)
                resolved = index - 1 if index > 0 else seen[kind] + index
                if not 0 <= resolved < totals[kind]:
                    raise ValueError("%s: corner %d, %r: %s index %d is out of range, the file has "
                                     "%d %s lines%s" % (where, i, token, kind, index, totals[kind], kind,
                                                        "" if index > 0 else " (%d before this one)"
                                                        % seen[kind]))
                if kind == "v":
                    corners.append(resolved)
        if check_area:
            for j in range(1, len(corners) - 1):
                a, b, c = (positions[k] if k < len(positions) else None
                           for k in (corners[0], corners[j], corners[j + 1]))
                if None in (a, b, c):
                    continue
                e0 = [b[k] - a[k] for k in range(3)]
                e1 = [c[k] - a[k] for k in range(3)]
                n = ((e0[1] * e1[2]) - (e0[2] * e1[1]),
                     (e0[2] * e1[0]) - (e0[0] * e1[2]),
                     (e0[0] * e1[1]) - (e0[1] * e1[0]))
                if n[0] * n[0] + n[1] * n[1] + n[2] * n[2] == 0.0:
                    raise ValueError("%s: triangle %d of the face, corners %d, %d and %d, spans zero "
                                     "area (collinear or repeated vertices)"
                                     % (where, j, 1, j + 1, j + 2))
