"""load_ply: a PLY file (the Stanford polygon format, Turk 1994) as a ``Mesh``. Suffern ch. 23
reads his meshes (the bunny, the horse, ...) from PLY files into a Mesh, with
Turk's ply.c; load_ply reads the same files.

    mesh = rtfgu.load_ply("bunny.ply", material=rtfgu.Matte())
    scene.shapes.append(mesh)                      # its faces (or scene.shapes += mesh.triangles())

What is read: ``format ascii 1.0``, ``binary_little_endian 1.0`` and ``binary_big_endian 1.0``;
the element ``vertex`` with the properties ``x``, ``y``, ``z``, optionally ``nx``, ``ny``,
``nz`` (all three: the mesh is smooth-shaded, ``SmoothMeshTriangle``) and a texture
coordinate pair ``u v``, ``s t``, ``texture_u texture_v`` or ``texture_s texture_t``
(checked to be finite; the mesh's ``uvs``, as load_obj's ``vt``); the
element ``face`` with the list ``vertex_indices`` (or ``vertex_index``), 0-based. A face of
more than three corners becomes the fan of triangles (c0, c_i, c_i+1) around its first corner,
wound as the face. Every other element and property (colours, edges, materials) is read past
and not used; each face gets ``default_color`` and ``material``. The property types are the
PLY ones, ``char uchar short ushort int uint float double`` and their sized names (``int8``
... ``float64``). An ASCII body holds one element per line, as every PLY writer writes it.

Bad input is a ValueError naming the file and, in the header or an ASCII body, the line; in
a binary body, the element, its number and its byte offset: a missing file, a file that does
not start with ``ply``, a malformed or unknown header line, an unknown property type, a
missing ``end_header``, a missing vertex or face element or x/y/z property, a line with too
few or too many values, a value that is not a number, a vertex not finite, a zero normal, a
face of fewer than three corners, a face index out of range, a body cut short (truncated) or
with bytes after its last element, and a triangle of zero area (refused; ``drop_degenerate=
True`` drops such triangles with a warning instead, as for load_obj).

The reader is rtfgu's own, not trimesh's (``trimesh.exchange.ply``, which rtfgu already
depends on for OBJ): trimesh's errors name neither the line nor the element ("PLY is
unexpected length!", numpy's "string or file could not be read to its end due to unmatched
data"), and it returns an ASCII body cut short, or a face index out of range, without an
error. A PLY body is a table per element whose
layout the header states, so a reader is short: numpy reads the table at once (np.frombuffer
for binary, one float conversion of the split text for ASCII) when every face has the same
number of corners, as in Suffern's files, and walks the rows one by one only for faces of
mixed sizes or to find the row that is wrong.
"""
from __future__ import annotations

import math
import re
import warnings
from pathlib import Path

from .lazy_import import numpy as np

from .materials.material import Material
from .obj import DEFAULT_COLOR, _fan
from .shapes.mesh import Mesh, zero_area_faces
from .validation import colour

# The PLY property types (Turk's ply.c names and the sized names of later writers) as numpy
# type codes, without byte order.
TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1",
    "short": "i2", "int16": "i2", "ushort": "u2", "uint16": "u2",
    "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
    "float": "f4", "float32": "f4", "double": "f8", "float64": "f8",
}
FORMATS = {"ascii": None, "binary_little_endian": "<", "binary_big_endian": ">"}
NORMALS = ("nx", "ny", "nz")
TEXCOORDS = (("u", "v"), ("s", "t"), ("texture_u", "texture_v"), ("texture_s", "texture_t"))
FACE_LISTS = ("vertex_indices", "vertex_index")


class _Property:
    """``property TYPE NAME`` (``count`` None) or ``property list COUNT TYPE NAME``."""

    def __init__(self, name: str, type: str, count: str | None, line: int):
        self.name, self.type, self.count, self.line = name, type, count, line


class _Element:
    """``element NAME COUNT`` and its properties, from header line ``line``."""

    def __init__(self, name: str, count: int, line: int):
        self.name, self.count, self.line = name, count, line
        self.properties: list[_Property] = []

    def property(self, names) -> _Property | None:
        return next((p for p in self.properties if p.name in names), None)


def load_ply(path, material: Material | None = None, default_color=DEFAULT_COLOR,
             drop_degenerate: bool = False) -> Mesh:
    """The triangles of the PLY file ``path`` as a Mesh, every face of colour
    ``default_color`` and material ``material`` (default ``Material()``)."""
    path = Path(path)
    if material is not None and not isinstance(material, Material):
        raise ValueError("load_ply: material must be a Material or None, got %r" % (material,))
    color = tuple(colour(default_color, "load_ply: default_color"))
    if not path.is_file():
        raise ValueError("load_ply: no such file %s" % path)
    data = path.read_bytes()
    order, elements, body, body_line = _read_header(data, path)
    if order is None:
        tables, where = _read_ascii(data, body, body_line, elements, path)
    else:
        tables, where = _read_binary(data, body, order, elements, path)
    vertex = next(e for e in elements if e.name == "vertex")
    face = next(e for e in elements if e.name == "face")
    vertices, normals, uvs = _vertices(tables["vertex"], vertex, where["vertex"], path)
    triangles, polygon_of = _triangles(tables["face"], face, where["face"], len(vertices), path)
    if len(triangles) == 0:
        raise ValueError("load_ply: %s, line %d: no faces (element face has 0 rows): an empty mesh"
                         % (path, face.line))

    flat = zero_area_faces(vertices, triangles)
    if len(flat):
        polygon = polygon_of[flat[0]]
        if not drop_degenerate:
            raise ValueError("%s: triangle %s spans zero area (collinear or repeated vertices)"
                             % (_where(path, "face", polygon, where["face"]),
                                tuple(int(i) for i in triangles[flat[0]])))
        warnings.warn("load_ply: %s: dropped %d triangles of zero area" % (path, len(flat)))
        triangles = np.delete(triangles, flat, axis=0)
        if len(triangles) == 0:
            raise ValueError("load_ply: %s: every triangle spans zero area" % path)
    return Mesh(vertices, triangles, color, normals=normals, uvs=uvs,
                material=Material() if material is None else material)


def _where(path: Path, element: str, row: int, where) -> str:
    """"load_ply: PATH, line L, element 'NAME' ROW" (ASCII) or "..., element 'NAME' ROW
    (byte B)" (binary); ``where(row)`` is the row's line or byte offset."""
    kind, place = where(row)
    if kind == "line":
        return "load_ply: %s, line %d, element '%s' %d" % (path, place, element, row)
    return "load_ply: %s, element '%s' %d (byte %d)" % (path, element, row, place)


# --- the header -----------------------------------------------------------------------------

def _read_header(data: bytes, path: Path):
    """(byte order: None for ASCII, "<" or ">"; the elements; the offset of the body; the
    number of the body's first line)."""
    def fail(line: int, what: str):
        raise ValueError("load_ply: %s, line %d: %s" % (path, line, what))

    end = re.search(rb"^end_header[ \t]*\r?\n", data, re.M)
    if not data.startswith((b"ply\n", b"ply\r\n")):
        raise ValueError("load_ply: %s, line 1: a PLY file starts with the line 'ply', got %r"
                         % (path, data[:data.find(b"\n")][:40].decode("latin-1").rstrip("\r")))
    if end is None:
        raise ValueError("load_ply: %s: no 'end_header' line: the header never ends" % path)
    try:
        lines = data[:end.start()].decode("ascii").split("\n")
    except UnicodeDecodeError as error:
        fail(data.count(b"\n", 0, error.start) + 1, "the header is not ASCII text")
    order, elements = "", []
    for number, line in enumerate(lines[1:-1], 2):
        fields = line.split()
        key = fields[0] if fields else ""
        if key in ("comment", "obj_info"):
            continue
        if key == "format":
            if order != "":
                fail(number, "a second 'format' line")
            if len(fields) != 3 or fields[1] not in FORMATS or fields[2] != "1.0":
                fail(number, "'format ascii|binary_little_endian|binary_big_endian 1.0' expected, "
                             "got %r" % line.strip())
            order = FORMATS[fields[1]]
        elif key == "element":
            if len(fields) != 3 or not fields[2].isdigit():
                fail(number, "'element NAME COUNT' expected (COUNT a whole number >= 0), got %r"
                     % line.strip())
            if any(e.name == fields[1] for e in elements):
                fail(number, "a second element %r" % fields[1])
            elements.append(_Element(fields[1], int(fields[2]), number))
        elif key == "property":
            if not elements:
                fail(number, "a property before any 'element' line")
            is_list = len(fields) > 1 and fields[1] == "list"
            if len(fields) != (5 if is_list else 3):
                fail(number, "'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME' "
                             "expected, got %r" % line.strip())
            types = fields[2:4] if is_list else fields[1:2]
            for t in types:
                if t not in TYPES:
                    fail(number, "unknown property type %r (PLY's types: %s)"
                         % (t, ", ".join(TYPES)))
            if is_list and TYPES[types[0]][0] == "f":
                fail(number, "a list's count type must be an integer type, got %r" % types[0])
            if elements[-1].property((fields[-1],)) is not None:
                fail(number, "a second property %r of element %r" % (fields[-1], elements[-1].name))
            elements[-1].properties.append(
                _Property(fields[-1], TYPES[types[-1]], TYPES[types[0]] if is_list else None, number))
        else:
            fail(number, "not a PLY header line (format, element, property, comment, obj_info, "
                         "end_header): %r" % line.strip())
    if order == "":
        fail(2, "no 'format' line")
    _check_mesh_elements(elements, path, len(lines))
    return order, elements, end.end(), len(lines) + 1


def _check_mesh_elements(elements: list, path: Path, end_line: int) -> None:
    def fail(line: int, what: str):
        raise ValueError("load_ply: %s, line %d: %s" % (path, line, what))

    vertex = next((e for e in elements if e.name == "vertex"), None)
    face = next((e for e in elements if e.name == "face"), None)
    if vertex is None:
        fail(end_line, "the header has no 'element vertex'")
    if face is None:
        raise ValueError("load_ply: %s: no faces (the header has no 'element face'): an empty mesh"
                         % path)
    for p in vertex.properties:
        if p.count is not None and p.name in ("x", "y", "z") + NORMALS:
            fail(p.line, "vertex property %r must be a number, not a list" % p.name)
    missing = [n for n in ("x", "y", "z") if vertex.property((n,)) is None]
    if missing:
        fail(vertex.line, "element vertex has no property %s" % ", ".join(missing))
    normals = [n for n in NORMALS if vertex.property((n,)) is not None]
    if normals and len(normals) != 3:
        fail(vertex.line, "element vertex has %s but not %s: vertex normals need nx, ny and nz"
             % (", ".join(normals), ", ".join(n for n in NORMALS if n not in normals)))
    indices = face.property(FACE_LISTS)
    if indices is None:
        fail(face.line, "element face has no list property vertex_indices (or vertex_index)")
    if indices.count is None or indices.type[0] == "f":
        fail(indices.line, "face property %r must be a list of integers" % indices.name)


# --- the body --------------------------------------------------------------------------------

def _read_ascii(data: bytes, start: int, first_line: int, elements: list, path: Path):
    """{element name: {property name: values}} and {element name: where(row)}, one element
    per line; blank lines are skipped."""
    try:
        text = data[start:].decode("ascii")
    except UnicodeDecodeError as error:
        raise ValueError("load_ply: %s, line %d: the ASCII body holds a byte that is not ASCII"
                         % (path, first_line + data.count(b"\n", start, start + error.start))) from None
    lines = text.split("\n")
    numbers = [first_line + i for i, line in enumerate(lines) if line.strip()]
    rows = [line for line in lines if line.strip()]
    tables, wheres, used = {}, {}, 0
    for element in elements:
        mine = rows[used:used + element.count]
        lines_of = np.asarray(numbers[used:used + element.count], dtype=np.int64)
        wheres[element.name] = lambda row, lines_of=lines_of: ("line", int(lines_of[row]))
        if len(mine) < element.count:
            raise ValueError("load_ply: %s: truncated: element '%s' has %d rows (header line %d), the "
                             "file ends after %d of them (line %d)"
                             % (path, element.name, element.count, element.line, len(mine),
                                first_line + len(lines) - 1))
        tables[element.name] = _ascii_table(mine, element, wheres[element.name], path)
        used += element.count
    if used < len(rows):
        raise ValueError("load_ply: %s, line %d: %d lines after the last element's rows (are the "
                         "header's element counts too small?)" % (path, numbers[used], len(rows) - used))
    return tables, wheres


def _ascii_table(rows: list, element: _Element, where, path: Path) -> dict:
    if not rows:
        return {p.name: np.zeros((0,) if p.count is None else (0, 0)) for p in element.properties}
    layout = _ascii_layout(rows[0].split(), element)
    if layout is not None:
        width = sum(1 if n is None else n + 1 for n in layout)
        tokens = " ".join(rows).split()
        if len(tokens) == width * len(rows):
            try:
                values = np.array(tokens, dtype=np.float64).reshape(len(rows), width)
            except ValueError:
                values = None
            if values is not None:
                table, column = {}, 0
                for p, n in zip(element.properties, layout):
                    if n is None:
                        table[p.name] = values[:, column]
                        column += 1
                    elif (values[:, column] == n).all():
                        table[p.name] = values[:, column + 1:column + 1 + n]
                        column += n + 1
                    else:
                        table = None
                        break
                if table is not None:
                    _check_integers(table, element, where, path)
                    return table
    # faces of mixed sizes, or a row that is wrong: one row at a time
    table = {p.name: [] for p in element.properties}
    for row, line in enumerate(rows):
        tokens = line.split()
        at = 0
        for p in element.properties:
            if p.count is None:
                table[p.name].append(_ascii_number(tokens, at, p, element, row, where, path))
                at += 1
            else:
                n = _ascii_number(tokens, at, p, element, row, where, path, count=True)
                table[p.name].append([_ascii_number(tokens, at + 1 + k, p, element, row, where, path)
                                      for k in range(n)])
                at += 1 + n
        if at != len(tokens):
            raise ValueError("%s: %d values expected, got %d"
                             % (_where(path, element.name, row, where), at, len(tokens)))
    table = {name: np.asarray(v, dtype=np.float64) if element.property((name,)).count is None else v
             for name, v in table.items()}
    _check_integers(table, element, where, path)
    return table


def _ascii_layout(tokens: list, element: _Element):
    """The list lengths of the first row (None for a scalar property), or None if the row
    cannot be read that far."""
    layout, at = [], 0
    for p in element.properties:
        if p.count is None:
            layout.append(None)
            at += 1
            continue
        try:
            n = int(tokens[at])
        except (IndexError, ValueError):
            return None
        if n < 0:
            return None
        layout.append(n)
        at += 1 + n
    return layout


def _ascii_number(tokens, at, p, element, row, where, path, count=False):
    if at >= len(tokens):
        raise ValueError("%s: the line ends before property '%s'%s"
                         % (_where(path, element.name, row, where), p.name, " (its list)" if at else ""))
    token = tokens[at]
    try:
        value = int(token) if count else float(token)
    except ValueError:
        raise ValueError("%s, property '%s': %r is not %s" % (_where(path, element.name, row, where), p.name,
                                                               token, "a list length" if count else "a number")) from None
    if count and value < 0:
        raise ValueError("%s, property '%s': a list length of %d" % (_where(path, element.name, row, where),
                                                                       p.name, value))
    return value


def _check_integers(table: dict, element: _Element, where, path: Path) -> None:
    """An integer property of an ASCII file must be written as a whole number."""
    for p in element.properties:
        if p.type[0] == "f":
            continue
        values = table[p.name]
        bad = _first_fraction(values)
        if bad is not None:
            raise ValueError("%s, property '%s': %r is not a whole number"
                             % (_where(path, element.name, bad[0], where), p.name, bad[1]))


def _first_fraction(values):
    if isinstance(values, list):
        for row, items in enumerate(values):
            for x in items:
                if not math.isfinite(x) or x != math.floor(x):
                    return row, x
        return None
    wrong = np.flatnonzero((values != np.floor(values)).reshape(len(values), -1).any(axis=1))
    if len(wrong) == 0:
        return None
    row = int(wrong[0])
    return row, next(float(x) for x in np.ravel(values[row]) if x != np.floor(x))


def _read_binary(data: bytes, start: int, order: str, elements: list, path: Path):
    tables, wheres, offset = {}, {}, start
    for element in elements:
        table, offsets, offset = _binary_table(data, offset, order, element, path)
        wheres[element.name] = lambda row, offsets=offsets: ("byte", int(offsets(row)))
        tables[element.name] = table
    if offset != len(data):
        raise ValueError("load_ply: %s: %d bytes after the last element, from byte %d (are the "
                         "header's element counts too small?)" % (path, len(data) - offset, offset))
    return tables, wheres


def _binary_table(data: bytes, offset: int, order: str, element: _Element, path: Path):
    """(the element's table, offsets(row), the offset after it). When every row's lists
    have the lengths of the first row's, the rows are one numpy structured array."""
    n = element.count
    layout = _binary_layout(data, offset, order, element)
    if layout is not None:
        fields, names = [], {}
        for i, (p, k) in enumerate(zip(element.properties, layout)):
            if p.count is None:
                fields.append(("p%d" % i, order + p.type))
            else:
                fields += [("c%d" % i, order + p.count), ("p%d" % i, order + p.type, (k,))]
            names[p.name] = i
        dtype = np.dtype(fields)
        if offset + n * dtype.itemsize <= len(data):
            rows = np.frombuffer(data, dtype=dtype, count=n, offset=offset)
            if all((rows["c%d" % i] == k).all() for i, (p, k) in enumerate(zip(element.properties, layout))
                   if p.count is not None):
                table = {p.name: rows["p%d" % i].astype(np.float64) for i, p in enumerate(element.properties)}
                size = dtype.itemsize
                return table, (lambda row: offset + row * size), offset + n * size
    # faces of mixed sizes, or a file cut short: one row at a time
    table = {p.name: [] for p in element.properties}
    starts = []
    at = offset
    for row in range(n):
        starts.append(at)
        for p in element.properties:
            if p.count is None:
                value, at = _binary_value(data, at, order + p.type, element, row, starts[-1], p, path)
                table[p.name].append(value)
            else:
                k, at = _binary_value(data, at, order + p.count, element, row, starts[-1], p, path)
                if k < 0:
                    raise ValueError("load_ply: %s, element '%s' %d (byte %d), property '%s': a list "
                                     "length of %d" % (path, element.name, row, starts[-1], p.name, k))
                size = np.dtype(p.type).itemsize * int(k)
                if at + size > len(data):
                    _truncated(path, element, row, starts[-1], p)
                table[p.name].append(np.frombuffer(data, dtype=order + p.type, count=int(k), offset=at)
                                     .astype(np.float64))
                at += size
    table = {p.name: np.asarray(table[p.name], dtype=np.float64) if p.count is None else table[p.name]
             for p in element.properties}
    return table, (lambda row: starts[row]), at


def _binary_layout(data: bytes, offset: int, order: str, element: _Element):
    """The list lengths of the first row (None for a scalar property), or None if the row is
    cut short."""
    layout = []
    if element.count == 0:
        return [0 if p.count is not None else None for p in element.properties]
    for p in element.properties:
        if p.count is None:
            layout.append(None)
            offset += np.dtype(p.type).itemsize
            continue
        size = np.dtype(p.count).itemsize
        if offset + size > len(data):
            return None
        k = int(np.frombuffer(data, dtype=order + p.count, count=1, offset=offset)[0])
        if k < 0:
            return None
        layout.append(k)
        offset += size + k * np.dtype(p.type).itemsize
    return layout


def _binary_value(data, at, dtype, element, row, start, p, path):
    size = np.dtype(dtype).itemsize
    if at + size > len(data):
        _truncated(path, element, row, start, p)
    return np.frombuffer(data, dtype=dtype, count=1, offset=at)[0].item(), at + size


def _truncated(path, element, row, start, p):
    raise ValueError("load_ply: %s, element '%s' %d (byte %d), property '%s': truncated, the file "
                     "ends (element '%s' has %d rows)" % (path, element.name, row, start, p.name,
                                                          element.name, element.count))


# --- the mesh ---------------------------------------------------------------------------------

def _vertices(table: dict, element: _Element, where, path: Path):
    """(the (n, 3) positions, the (n, 3) normals or None, the (n, 2) texture coordinates or
    None), each checked."""
    positions = np.stack([table[n] for n in ("x", "y", "z")], axis=1)
    _check_finite(positions, "the position", element, where, path)
    uvs = None
    for u, v in TEXCOORDS:
        if uvs is None and element.property((u,)) is not None and element.property((v,)) is not None:
            uvs = np.stack([table[u], table[v]], axis=1).astype(np.float64)
            _check_finite(uvs, "the texture coordinate", element, where, path)
    if element.property(("nx",)) is None:
        return positions, None, uvs
    normals = np.stack([table[n] for n in NORMALS], axis=1)
    _check_finite(normals, "the normal", element, where, path)
    zero = np.flatnonzero(~normals.any(axis=1))
    if len(zero):
        raise ValueError("%s: the normal (nx, ny, nz) is the zero vector"
                         % _where(path, element.name, int(zero[0]), where))
    return positions, normals, uvs


def _check_finite(values: np.ndarray, what: str, element, where, path) -> None:
    bad = np.flatnonzero(~np.isfinite(values).all(axis=1))
    if len(bad):
        row = int(bad[0])
        raise ValueError("%s: %s %s is not finite" % (_where(path, element.name, row, where), what,
                                                      tuple(float(x) for x in values[row])))


def _triangles(table: dict, element: _Element, where, count: int, path: Path):
    """((m, 3) vertex indices, the face of each triangle): the faces as fans."""
    lists = table[element.property(FACE_LISTS).name]
    if len(lists) == 0:
        return np.zeros((0, 3), dtype=np.int64), np.zeros(0, dtype=np.int64)
    if isinstance(lists, np.ndarray):                      # every face has the same corners
        polygons = lists.reshape(len(lists), -1)
        sizes = np.full(len(polygons), polygons.shape[1])
    else:
        sizes = np.array([len(f) for f in lists], dtype=np.int64)
        polygons = None
    small = np.flatnonzero(sizes < 3)
    if len(small):
        raise ValueError("%s: a face needs at least 3 corners, got %d"
                         % (_where(path, element.name, int(small[0]), where), sizes[small[0]]))
    flat = polygons.ravel() if polygons is not None else \
        (np.concatenate(lists) if lists else np.zeros(0))
    out = np.flatnonzero((flat < 0) | (flat >= count))
    if len(out):
        face = int(np.searchsorted(np.cumsum(sizes), out[0], side="right"))
        raise ValueError("%s: vertex index %d is out of range, the file has %d vertices (0 to %d)"
                         % (_where(path, element.name, face, where), flat[out[0]], count, count - 1))
    if polygons is not None:
        triangles = _fan(polygons.astype(np.int64)) if len(polygons) else np.zeros((0, 3), np.int64)
        return triangles, np.repeat(np.arange(len(polygons)), sizes - 2)
    triangles = [_fan(np.asarray(f, dtype=np.int64)[None, :]) for f in lists]
    return np.concatenate(triangles), np.repeat(np.arange(len(lists)), sizes - 2)
