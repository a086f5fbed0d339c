"""load_ply (rtfgu/ply.py) and load_mesh: PLY files in ASCII and binary of both byte orders,
written here byte by byte and by trimesh's PLY writer, load to the mesh the same OBJ file
loads to, and bad input names the file and the line (ASCII) or the element and byte (binary)."""
from __future__ import annotations

import struct
import warnings

import numpy as np
import pytest

import rtfgu
from rtfgu import Float3, Scene, load_mesh, load_obj, load_ply
from rtfgu.obj import mesh_path
from rtfgu.shapes.mesh import FlatMeshTriangle, SmoothMeshTriangle

FORMATS = ("ascii", "binary_little_endian", "binary_big_endian")
CODES = {"float": "f", "double": "d", "uchar": "B", "int": "i", "uint": "I", "short": "h", "char": "b"}

# A unit square, a pentagon and a triangle, facing +z (the polygons of test_mesh's OBJ test).
POLYGON_VERTICES = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (3, 0, 0), (4, 0, 0), (4.5, 1, 0),
                    (3.5, 2, 0), (2.5, 1, 0), (6, 0, 0), (7, 0, 0), (6, 1, 0)]
POLYGONS = [(0, 1, 2, 3), (4, 5, 6, 7, 8), (9, 10, 11)]


def ply_bytes(fmt: str, vertex_props, vertices, faces, face_count="uchar", face_index="int",
              extra_header="", extra_rows=b"") -> tuple:
    """(the file, the header's length): ``vertices`` rows of the ``vertex_props`` (type,
    name), ``faces`` lists as ``property list face_count face_index vertex_indices``."""
    header = ["ply", "format %s 1.0" % fmt, "comment written by test_ply", "element vertex %d" % len(vertices)]
    header += ["property %s %s" % p for p in vertex_props]
    header += ["element face %d" % len(faces), "property list %s %s vertex_indices" % (face_count, face_index)]
    text = "\n".join(header) + "\n" + extra_header + "end_header\n"
    if fmt == "ascii":
        body = "".join(" ".join(repr(float(x)) if t in ("float", "double") else str(int(x))
                                for (t, _), x in zip(vertex_props, row)) + "\n" for row in vertices)
        body += "".join("%d %s\n" % (len(f), " ".join(str(i) for i in f)) for f in faces)
        return text.encode() + body.encode() + extra_rows, len(text)
    order = "<" if fmt == "binary_little_endian" else ">"
    body = b"".join(struct.pack(order + "".join(CODES[t] for t, _ in vertex_props), *row) for row in vertices)
    body += b"".join(struct.pack(order + CODES[face_count] + CODES[face_index] * len(f), len(f), *f)
                     for f in faces)
    return text.encode() + body + extra_rows, len(text)


XYZ = [("float", "x"), ("float", "y"), ("float", "z")]


def write_ply(folder, name, *args, **kwargs):
    path = folder / name
    data, _ = ply_bytes(*args, **kwargs)
    path.write_bytes(data)
    return path


# --- what is read ------------------------------------------------------------------------

@pytest.mark.parametrize("fmt", FORMATS)
def test_polygons_become_fans_keeping_their_winding(tmp_path, fmt):
    mesh = load_ply(write_ply(tmp_path, "polygons.ply", fmt, XYZ, POLYGON_VERTICES, POLYGONS))
    assert mesh.num_triangles == 2 + 3 + 1 and mesh.normals is None
    assert mesh.vertices.tolist() == [list(map(float, v)) for v in POLYGON_VERTICES]
    assert mesh.faces.tolist() == [[0, 1, 2], [0, 2, 3], [4, 5, 6], [4, 6, 7], [4, 7, 8], [9, 10, 11]]
    v, f = mesh.vertices, mesh.faces
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    assert (n[:, 2] > 0).all() and n[:, 2].sum() / 2 == 1 + 2.5 + 0.5
    assert all(type(t) is FlatMeshTriangle for t in mesh.triangles())


@pytest.mark.parametrize("fmt", FORMATS)
def test_the_obj_polygons_and_the_ply_polygons_are_one_mesh(tmp_path, fmt):
    obj = tmp_path / "polygons.obj"
    obj.write_text("".join("v %r %r %r\n" % tuple(map(float, v)) for v in POLYGON_VERTICES)
                   + "".join("f %s\n" % " ".join(str(i + 1) for i in f) for f in POLYGONS))
    a, b = load_obj(obj), load_ply(write_ply(tmp_path, "polygons.ply", fmt, XYZ, POLYGON_VERTICES, POLYGONS))
    assert np.array_equal(a.vertices, b.vertices)

    def turned(faces):      # each triangle from its smallest index, keeping its winding
        return [tuple(np.roll(f, -int(np.argmin(f)))) for f in faces.tolist()]
    assert turned(a.faces) == turned(b.faces)


@pytest.mark.parametrize("fmt", FORMATS)
def test_normals_texture_coordinates_and_other_elements(tmp_path, fmt):
    """Vertex normals make the mesh smooth; u v are its uvs; colours and an extra element are read past."""
    props = XYZ + [("double", "nx"), ("double", "ny"), ("double", "nz"), ("float", "u"), ("float", "v"),
                   ("uchar", "red"), ("uchar", "green"), ("uchar", "blue")]
    rows = [(0, 0, 0, 0, 0, 2, 0, 0, 255, 0, 0), (1, 0, 0, 0.6, 0, 0.8, 1, 0, 0, 255, 0),
            (0, 1, 0, 0, -0.6, 0.8, 0, 1, 0, 0, 255), (1, 1, 0, 0, 0, 1, 1, 1, 7, 7, 7)]
    extra_header = "element edge 2\nproperty int vertex1\nproperty short vertex2\nproperty list uchar float weights\n"
    if fmt == "ascii":
        extra = b"0 1 2 0.5 0.25\n2 3 0\n"
    else:
        o = "<" if fmt == "binary_little_endian" else ">"
        extra = struct.pack(o + "ihBff", 0, 1, 2, 0.5, 0.25) + struct.pack(o + "ihB", 2, 3, 0)
    path = write_ply(tmp_path, "normals.ply", fmt, props, rows, [(0, 1, 2), (1, 3, 2)],
                     extra_header=extra_header, extra_rows=extra)
    mesh = load_ply(path)
    assert mesh.num_triangles == 2 and mesh.normals is not None
    assert mesh.normals.tolist() == [[0, 0, 1], [0.6, 0, 0.8], [0, -0.6, 0.8], [0, 0, 1]]
    assert mesh.uvs.tolist() == [[0, 0], [1, 0], [0, 1], [1, 1]]
    expected = {(0, 0, 0): (0, 0, 1), (1, 0, 0): (0.6, 0, 0.8), (0, 1, 0): (0, -0.6, 0.8), (1, 1, 0): (0, 0, 1)}
    for shape in mesh.triangles():
        assert isinstance(shape, SmoothMeshTriangle)
        for i in (shape.index0, shape.index1, shape.index2):
            p = tuple(mesh.vertices[i])
            n = shape.normal_at(Float3(*p))
            assert np.allclose((n.x, n.y, n.z), expected[p], rtol=0, atol=1e-15)


@pytest.mark.parametrize("fmt", ["ascii", "binary_big_endian"])
def test_index_and_count_types_and_s_t_coordinates(tmp_path, fmt):
    props = [("double", "x"), ("double", "y"), ("double", "z"), ("double", "s"), ("double", "t")]
    rows = [v + (0.5, 0.5) for v in POLYGON_VERTICES]
    for count, index in (("uchar", "uint"), ("int", "short"), ("char", "int")):
        mesh = load_ply(write_ply(tmp_path, "types.ply", fmt, props, rows, POLYGONS, count, index))
        assert mesh.num_triangles == 6 and mesh.faces[-1].tolist() == [9, 10, 11]


def test_material_and_colour_are_every_faces(tmp_path):
    matte = rtfgu.Matte()
    mesh = load_ply(write_ply(tmp_path, "m.ply", "ascii", XYZ, POLYGON_VERTICES, POLYGONS),
                    material=matte, default_color=(0.25, 0.5, 1))
    assert all(m is matte for m in mesh.materials) and (mesh.colors == (0.25, 0.5, 1)).all()


@pytest.mark.parametrize("encoding", ["ascii", "binary"])
def test_trimesh_written_bunny_renders_as_the_obj_bunny(tmp_path, encoding):
    """trimesh's PLY writer (float32 vertices and normals, written "%.8f" in ASCII) against
    the same numbers in an OBJ file: the same arrays, and the lecture layer renders the same
    image. The numbers are multiples of 1/256, which both writers write exactly."""
    import trimesh
    from trimesh.exchange.ply import export_ply

    bunny = load_obj(mesh_path("bunny.obj"))
    vertices = np.round(bunny.vertices * 256) / 256
    normals = np.zeros_like(vertices)
    a, b, c = (vertices[bunny.faces[:, k]] for k in range(3))
    for k in range(3):
        np.add.at(normals, bunny.faces[:, k], np.cross(b - a, c - a))
    normals = np.round(normals / np.linalg.norm(normals, axis=1)[:, None] * 256) / 256
    obj = tmp_path / "bunny.obj"
    obj.write_text("".join("v %r %r %r\n" % tuple(map(float, v)) for v in vertices)
                   + "".join("vn %r %r %r\n" % tuple(map(float, n)) for n in normals)
                   + "".join("f %d//%d %d//%d %d//%d\n" % tuple(i + 1 for i in f for _ in (0, 1))
                             for f in bunny.faces))
    ply = tmp_path / "bunny.ply"
    written = trimesh.Trimesh(vertices, bunny.faces, vertex_normals=normals, process=False)
    ply.write_bytes(export_ply(written, encoding=encoding, vertex_normal=True))
    from_obj, from_ply = load_obj(obj), load_ply(ply)
    assert from_ply.num_triangles == 3674 and from_ply.normals is not None
    for name in ("vertices", "faces", "normals", "colors"):
        assert np.array_equal(getattr(from_obj, name), getattr(from_ply, name)), name

    def image(mesh):
        scene = Scene(rtfgu.PinholeCamera(Float3(0, 4, 14), Float3(0, 4, 0), Float3(0, 1, 0), 1.0, 1.0))
        scene.shapes = mesh.triangles()
        scene.lights = [rtfgu.PointLight(Float3(5, 10, 10), Float3(1, 1, 1))]
        return rtfgu.render(scene, 5, 5)
    seen = image(from_ply)
    assert (seen != seen[0, 0]).any(axis=2).sum() >= 5            # the bunny is in the picture
    assert np.array_equal(seen, image(from_obj))


def test_load_mesh_picks_the_loader_by_suffix(tmp_path):
    ply = write_ply(tmp_path, "square.PLY", "ascii", XYZ, POLYGON_VERTICES[:4], POLYGONS[:1])
    obj = tmp_path / "square.obj"
    obj.write_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n")
    for path in (ply, obj):
        mesh = load_mesh(path, default_color=(0, 1, 0))
        assert mesh.faces.tolist() == [[0, 1, 2], [0, 2, 3]] and (mesh.colors == (0, 1, 0)).all()
    with pytest.raises(ValueError, match=r"load_mesh: .*square\.stl: unknown mesh suffix '\.stl' "
                                         r"\(it reads \.obj and \.ply\)"):
        load_mesh(tmp_path / "square.stl")
    assert rtfgu.load_ply is load_ply and rtfgu.load_mesh is load_mesh
    assert {"load_ply", "load_mesh"} <= set(rtfgu.__all__)


# --- bad input ---------------------------------------------------------------------------

GOOD_HEADER = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n" \
              "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
GOOD_BODY = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"


@pytest.mark.parametrize("text,words", [
    ("plx\n" + GOOD_HEADER[4:] + GOOD_BODY, r"line 1: a PLY file starts with the line 'ply', got 'plx'"),
    (GOOD_HEADER.replace("end_header\n", "") + GOOD_BODY, r"no 'end_header' line"),
    (GOOD_HEADER.replace("ascii 1.0", "ascii 2.0") + GOOD_BODY, r"line 2: 'format ascii\|binary"),
    (GOOD_HEADER.replace("format ascii 1.0\n", "") + GOOD_BODY, r"line 2: no 'format' line"),
    (GOOD_HEADER.replace("vertex 3", "vertex three") + GOOD_BODY, r"line 3: 'element NAME COUNT' expected"),
    (GOOD_HEADER.replace("float y", "float128 y") + GOOD_BODY, r"line 5: unknown property type 'float128'"),
    (GOOD_HEADER.replace("list uchar int", "list float int") + GOOD_BODY, r"line 8: a list's count type"),
    (GOOD_HEADER.replace("float z", "float z\nproperty float z") + GOOD_BODY, r"line 7: a second property 'z'"),
    (GOOD_HEADER.replace("element face 1", "elephant face 1") + GOOD_BODY, r"line 7: not a PLY header line"),
    (GOOD_HEADER.replace("float z", "float w") + GOOD_BODY, r"line 3: element vertex has no property z"),
    (GOOD_HEADER.replace("vertex_indices", "corners") + GOOD_BODY, r"line 7: element face has no list property"),
    (GOOD_HEADER.replace("element face 1\nproperty list uchar int vertex_indices\n", "")
     + GOOD_BODY[:-8], r"no faces \(the header has no 'element face'\)"),
    (GOOD_HEADER.replace("face 1", "face 0") + GOOD_BODY[:-8], r"line 7: no faces \(element face has 0 rows\)"),
    (GOOD_HEADER.replace("float z", "float z\nproperty float nx\nproperty float ny\nproperty float nz")
     + "0 0 0 0 0 1\n1 0 0 0 0 0\n0 1 0 0 0 1\n3 0 1 2\n", r"line 14, element 'vertex' 1: the normal \(nx, ny, nz\) is the zero vector"),
    (GOOD_HEADER.replace("float z", "float z\nproperty float nx\nproperty float ny") + GOOD_BODY,
     r"line 3: element vertex has nx, ny but not nz"),
])
def test_bad_ascii_input_names_the_file_and_the_line(tmp_path, text, words):
    path = tmp_path / "bad.ply"
    path.write_text(text)
    with pytest.raises(ValueError, match=words) as error:
        load_ply(path)
    assert str(error.value).startswith("load_ply: %s" % path), str(error.value)


@pytest.mark.parametrize("body,words", [
    ("0 0 0\n1 0\n0 1 0\n3 0 1 2\n", r"line 11, element 'vertex' 1: the line ends before property 'z'"),
    ("0 0 0\n1 0 0 0\n0 1 0\n3 0 1 2\n", r"line 11, element 'vertex' 1: 3 values expected, got 4"),
    ("0 0 0\n1 0 0\n0 one 0\n3 0 1 2\n", r"line 12, element 'vertex' 2, property 'y': 'one' is not a number"),
    ("0 0 0\n1 0 0\n0 1 nan\n3 0 1 2\n", r"line 12, element 'vertex' 2: the position \(0.0, 1.0, nan\) is not finite"),
    ("0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", r"line 13, element 'face' 0: vertex index 3 is out of range, the file has 3 vertices"),
    ("0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", r"line 13, element 'face' 0: vertex index -1 is out of range"),
    ("0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n", r"line 13, element 'face' 0, property 'vertex_indices': 1.5 is not a whole number"),
    ("0 0 0\n1 0 0\n0 1 0\n4 0 1 2 nan\n", r"line 13, element 'face' 0, property 'vertex_indices': nan is not a whole number"),
    ("0 0 0\n1 0 0\n0 1 0\n2 0 1\n", r"line 13, element 'face' 0: a face needs at least 3 corners, got 2"),
    ("0 0 0\n1 0 0\n0 1 0\n3 0 1\n", r"line 13, element 'face' 0: the line ends before property 'vertex_indices'"),
    ("0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n", r"line 13, element 'face' 0: triangle \(0, 1, 2\) spans zero area"),
    ("0 0 0\n1 0 0\n", r"truncated: element 'vertex' has 3 rows \(header line 3\), the file ends after 2"),
    ("0 0 0\n1 0 0\n0 1 0\n", r"truncated: element 'face' has 1 rows \(header line 7\), the file ends after 0"),
    (GOOD_BODY + "3 0 1 2\n", r"line 14: 1 lines after the last element's rows"),
])
def test_a_bad_ascii_body_names_the_line_and_the_element(tmp_path, body, words):
    test_bad_ascii_input_names_the_file_and_the_line(tmp_path, GOOD_HEADER + body, words)


@pytest.mark.parametrize("fmt", FORMATS[1:])
@pytest.mark.parametrize("mixed", [False, True])
def test_bad_binary_input_names_the_element_and_its_byte(tmp_path, fmt, mixed):
    """Faces of one size (read as one numpy table) and of mixed sizes (read row by row)."""
    vertices = POLYGON_VERTICES
    faces = [(0, 1, 2), (0, 2, 3), (9, 10, 12)] if not mixed else [(0, 1, 2, 3), (4, 5, 6, 7, 8), (9, 10, 12)]
    data, header = ply_bytes(fmt, XYZ, vertices, faces)
    path = tmp_path / "bad.ply"
    path.write_bytes(data)
    third = header + 12 * len(vertices) + sum(1 + 4 * len(f) for f in faces[:2])
    with pytest.raises(ValueError, match=r"load_ply: .*bad.ply, element 'face' 2 \(byte %d\): vertex index 12 is "
                                         r"out of range, the file has 12 vertices \(0 to 11\)" % third):
        load_ply(path)
    good, _ = ply_bytes(fmt, XYZ, vertices, faces[:2] + [(9, 10, 11)])
    (tmp_path / "good.ply").write_bytes(good)
    assert load_ply(tmp_path / "good.ply").num_triangles == (2 if not mixed else 5) + 1
    path.write_bytes(good[:-2])
    with pytest.raises(ValueError, match=r"element 'face' 2 \(byte %d\), property 'vertex_indices': truncated" % third):
        load_ply(path)
    path.write_bytes(good[:header + 12 * 5 + 9])
    with pytest.raises(ValueError, match=r"element 'vertex' 5 \(byte %d\), property 'z': truncated" % (header + 60)):
        load_ply(path)
    path.write_bytes(good + b"\0\0")
    with pytest.raises(ValueError, match=r"2 bytes after the last element, from byte %d \(are the header's element counts too small\?\)" % len(good)):
        load_ply(path)
    nan = struct.pack("<f" if fmt == "binary_little_endian" else ">f", float("nan"))
    path.write_bytes(good[:header + 12 * 3 + 4] + nan + good[header + 12 * 3 + 8:])
    with pytest.raises(ValueError, match=r"element 'vertex' 3 \(byte %d\): the position \(0.0, nan, 0.0\) is not "
                                         r"finite" % (header + 36)):
        load_ply(path)


def test_zero_area_triangles_may_be_dropped_with_a_warning(tmp_path):
    path = write_ply(tmp_path, "flat.ply", "binary_little_endian", XYZ, POLYGON_VERTICES,
                     POLYGONS + [(0, 1, 1), (9, 10, 11)])
    with pytest.raises(ValueError, match=r"element 'face' 3 \(byte \d+\): triangle \(0, 1, 1\) spans zero area"):
        load_ply(path)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        mesh = load_ply(path, drop_degenerate=True)
    assert mesh.num_triangles == 7 and "dropped 1 triangles of zero area" in str(caught[0].message)


def test_a_missing_file_and_a_bad_material_are_named(tmp_path):
    with pytest.raises(ValueError, match="load_ply: no such file .*missing.ply"):
        load_ply(tmp_path / "missing.ply")
    path = write_ply(tmp_path, "m.ply", "ascii", XYZ, POLYGON_VERTICES, POLYGONS)
    with pytest.raises(ValueError, match="load_ply: material must be a Material"):
        load_ply(path, material="matte")
    with pytest.raises(ValueError, match="load_ply: default_color"):
        load_ply(path, default_color=(1, -1, 0))
