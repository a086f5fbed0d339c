"""Triangle meshes (Suffern ch. 23, "Triangle Meshes"): a ``Mesh`` holds the vertices, the
vertex normals and the faces once, and each face is a ``MeshTriangle`` that refers to its
three vertices by index.

Suffern's two kinds of mesh triangle differ only in their normal:

* ``FlatMeshTriangle``: the geometric normal (v1 - v0) x (v2 - v0), normalised, the same
  over the whole face (as ``Triangle``);
* ``SmoothMeshTriangle``: the vertex normals interpolated with the hit's barycentric
  coordinates (Suffern's ``interpolate_normal``),
  n = normalize((1 - beta - gamma) n0 + beta n1 + gamma n2).

Both are intersected by the watertight ray-triangle test (Woop, Benthin and Wald 2013,
rtfgu.robust.intersect_triangle_watertight): the faces of a mesh share their edges, and the
02562 barycentric test of ``Triangle`` lets a ray through a shared edge miss both faces
(docs/meshes.md counts the leaks). A mesh triangle holds a ``Triangle`` through its three
vertices for its normal and its barycentric (beta, gamma) ``texcoord``.

    mesh = Mesh(vertices, faces, color)            # vertices (n, 3), faces (m, 3) indices
    scene.shapes.append(mesh)                      # the mesh itself: its faces, in order
    scene.shapes += mesh.triangles()               # or one Shape per face

A ``Mesh`` in ``Scene.shapes`` stands for its faces in the order of ``faces``, as Suffern's
grid holds a mesh's triangles (ch. 23): the numba and WGSL paths read its arrays
(rtfgu.layout.compile_scene packs them with numpy) and never make a ``MeshTriangle``; the
lecture layer traces the scene's ``with_faces()`` view, whose shapes are the faces made by
``triangles()`` (once, then kept by the mesh). On the numba and WGSL paths the mesh
triangles of a scene are one registered kind ("mesh", rtfgu.registry): their vertices and
faces in arrays, found through a BVH.
"""
from __future__ import annotations

from abc import abstractmethod

from ..lazy_import import numpy as np

try:
    from ..robust import watertight_hit
except ImportError:
    # A student release before the triangle assignment (a03) is revealed ships no other
    # ray-triangle test: the faces then use the student's own Triangle.intersect_p.
    watertight_hit = None

from ..float3 import Float3, normalize
from ..materials.material import Material
from ..ray import Ray
from ..same_arrays import same_arrays
from .shape import Shape
from .triangle import Triangle


class Mesh:
    """Suffern's ``Mesh``: the shared data of a triangle mesh.

    vertices  (n, 3) floats, every one finite.
    faces     (m, 3) integer indices into ``vertices`` (0-based); a face's front is where
              (v1 - v0) x (v2 - v0) points, as for ``Triangle``. No face may span zero area.
    color     one colour for every face, or (m, 3): a colour per face.
    normals   None (flat shading: ``FlatMeshTriangle``) or (n, 3) vertex normals, non-zero
              and finite, stored normalised (smooth shading: ``SmoothMeshTriangle``).
    material  None (``Material()``), one Material for every face, or a sequence of m.
    uvs       None or (n, 2) texture coordinates (u, v) per vertex, finite (an OBJ file's
              ``vt``): a face's (u, v) at a point is its corners' interpolated with the
              point's barycentric coordinates (Suffern ch. 29, UV mesh triangles,
              ``interpolate_u``/``interpolate_v``); without them it is the barycentric
              (beta, gamma) itself.

    Colours and materials are kept per face, ``colors`` (m, 3) and ``materials`` (a tuple of
    m: another material for a face is a new tuple).
    Bad input is a ValueError naming the field and, for a face, its number.

    The arrays may be changed in place (a vertex moved): ``geometry_key()`` changes with
    them, and what was made from them (the faces of ``triangles()``, a scene's BVH) is made
    again.
    """

    def __init__(self, vertices, faces, color, normals=None, material=None, uvs=None):
        self.vertices = _rows_of_three(vertices, "Mesh.vertices", np.float64)
        self.faces = _face_indices(faces, len(self.vertices))
        self.normals = None if normals is None else _unit_normals(normals, len(self.vertices))
        self.uvs = None if uvs is None else _vertex_uvs(uvs, len(self.vertices))
        m = len(self.faces)
        self.colors = _per_face_colors(color, m)
        self.materials = _per_face_materials(material, m)
        # The tuple of one Material for every face, while it is self.materials (surfaces()).
        self._one_material = self.materials if material is None or isinstance(material, Material) else None
        _refuse_zero_area(self.vertices, self.faces)
        self._triangles = None      # (key, [MeshTriangle per face]) once triangles() made them
        # (materials, colours, surfaces(), [(material, cd is a colour)]) once surfaces() ran
        self._surfaces = None

    @property
    def num_vertices(self) -> int:
        return len(self.vertices)

    @property
    def num_triangles(self) -> int:
        return len(self.faces)

    def intersect_p(self, ray: Ray) -> bool:
        """A Mesh is not a Shape: the lecture layer traces its faces (module docstring)."""
        raise TypeError("a Mesh in Scene.shapes stands for its faces: trace scene.with_faces(), whose shapes "
                        "are mesh.triangles() (rtfgu.render does)")

    def geometry_key(self) -> str:
        """A digest of the bytes of ``vertices``, ``faces``, ``normals`` and ``uvs``, what the
        faces of ``triangles()`` are made from. It is computed again on every call (the arrays
        hashed whole, no Python per face), so a change in place is seen. (A scene's BVH is
        kept by comparing the arrays themselves, rtfgu.layout._cached.)"""
        import hashlib   # here, not with the package: most scenes never ask

        digest = hashlib.blake2b(digest_size=16)
        for array in (self.vertices, self.faces, self.normals, self.uvs):
            digest.update(b"-" if array is None else np.ascontiguousarray(array).tobytes())
        return digest.hexdigest()

    def color(self, face: int) -> Float3:
        """The colour of face ``face``, as its MeshTriangle holds it."""
        return Float3(*(float(c) for c in self.colors[face]))

    def surfaces(self) -> list:
        """The faces grouped by what they look like: (first face, material, faces) for each
        distinct material and, where the material takes its colour from the shape (its cd is
        not a colour of its own), each distinct face colour with it; in the order of their
        first faces, the order a loop over ``triangles()`` meets them. ``faces`` is an int
        array. numpy groups the faces: no Python per face but the materials' ids. The groups
        are kept until ``materials`` is another tuple or ``colors`` changes."""
        if self._surfaces is not None and self._surfaces[0] is self.materials \
                and same_arrays([(self._surfaces[1], self.colors)]) \
                and all(isinstance(m.cd, Float3) == own for m, own in self._surfaces[3]):
            return self._surfaces[2]
        m = len(self.faces)
        if self._one_material is self.materials:    # made from one Material: one group
            groups = [np.arange(m)]
        else:
            groups = _groups(np.fromiter(map(id, self.materials), dtype=np.uint64, count=m))
        out = []
        for faces in groups:
            material = self.materials[faces[0]]
            if isinstance(material.cd, Float3):
                out.append((int(faces[0]), material, faces))
                continue
            colors = self.colors if len(faces) == m else self.colors[faces]    # no copy of them all
            for part in _groups(colors):
                out.append((int(faces[part[0]]), material, faces if len(part) == len(faces) else faces[part]))
        out.sort(key=lambda group: group[0])
        kinds = [(m, isinstance(m.cd, Float3)) for m in {id(g[1]): g[1] for g in out}.values()]
        self._surfaces = (self.materials, self.colors.copy(), out, kinds)
        return out

    def triangles(self) -> list:
        """A ``SmoothMeshTriangle`` per face if the mesh has vertex normals, otherwise a
        ``FlatMeshTriangle`` per face, in the order of ``faces`` (a new list of them).

        They are made on the first call and kept, so every call gives the same objects (an
        ``AreaLight`` of one of them is the light of the face the scene holds); they are
        made again when the geometry, the colours or the materials have changed."""
        key = (self.geometry_key(), self.colors.tobytes(), self.materials)
        if self._triangles is None or self._triangles[0] != key:
            kind = FlatMeshTriangle if self.normals is None else SmoothMeshTriangle
            self._triangles = (key, [kind(self, face) for face in range(len(self.faces))])
        return list(self._triangles[1])


class MeshTriangle(Shape):
    """Face ``face`` of ``mesh``: indices ``index0``, ``index1``, ``index2`` into the mesh's
    vertices (Suffern's ``MeshTriangle``), its colour and material those of the face."""

    def __init__(self, mesh: Mesh, face: int):
        super().__init__(mesh.colors[face], mesh.materials[face])
        self.mesh = mesh
        self.face = face
        self.index0, self.index1, self.index2 = (int(i) for i in mesh.faces[face])
        v0, v1, v2 = (mesh.vertices[i] for i in (self.index0, self.index1, self.index2))
        try:
            self._triangle = Triangle(v0, v1, v2, self.color, self.material)
        except ValueError as error:
            raise ValueError("Mesh.faces[%d]: %s" % (face, error)) from None
        # The corners' (u, v) (Suffern's UV mesh triangles), or None: the barycentrics.
        self.uvs = None if mesh.uvs is None else \
            tuple((float(mesh.uvs[i, 0]), float(mesh.uvs[i, 1])) for i in (self.index0, self.index1, self.index2))

    def intersect_p(self, ray: Ray) -> bool:
        """The watertight test (rtfgu.robust.intersect_triangle_watertight, Woop, Benthin and
        Wald 2013): two faces that share an edge never both miss a ray through it."""
        if watertight_hit is None:
            return self._triangle.intersect_p(ray)
        # The corners were checked when the face was made (Triangle).
        return watertight_hit(ray, self._triangle.v0, self._triangle.v1, self._triangle.v2)

    @abstractmethod
    def normal_at(self, position: Float3) -> Float3:
        """The unit normal at a point of the face (flat or interpolated)."""

    def bounds(self):
        return self._triangle.bounds()

    @property
    def triangle(self) -> Triangle:
        """The face as a ``Triangle`` through its three vertices."""
        return self._triangle

    def barycentric(self, position: Float3) -> tuple:
        """The barycentric (beta, gamma) of the point, as ``Triangle.texcoord``."""
        return self._triangle.texcoord(position)

    def texcoord(self, position: Float3) -> tuple:
        """(u, v): the corners' uvs interpolated as Suffern's ``interpolate_u``/``interpolate_v``,
        (1 - beta - gamma) u0 + beta u1 + gamma u2, or (beta, gamma) for a mesh without uvs."""
        beta, gamma = self.barycentric(position)
        if self.uvs is None:
            return beta, gamma
        (u0, v0), (u1, v1), (u2, v2) = self.uvs
        alpha = 1.0 - beta - gamma
        return alpha * u0 + beta * u1 + gamma * u2, alpha * v0 + beta * v1 + gamma * v2


class FlatMeshTriangle(MeshTriangle):
    """Suffern's ``FlatMeshTriangle``: one normal for the whole face, (v1 - v0) x (v2 - v0)."""

    def normal_at(self, position: Float3) -> Float3:
        return self._triangle.normal_at(position)


class SmoothMeshTriangle(MeshTriangle):
    """Suffern's ``SmoothMeshTriangle``: the vertex normals interpolated with the point's
    barycentric coordinates, n = normalize((1 - beta - gamma) n0 + beta n1 + gamma n2).

    At a vertex the result is that vertex's normal. Where the interpolation cancels to the
    zero vector (vertex normals pointing against each other) the face's geometric normal is
    returned, so that the normal is always a unit vector."""

    def __init__(self, mesh: Mesh, face: int):
        super().__init__(mesh, face)
        if mesh.normals is None:
            raise ValueError("SmoothMeshTriangle needs a Mesh with normals")
        self.n0, self.n1, self.n2 = (Float3(*mesh.normals[i])
                                     for i in (self.index0, self.index1, self.index2))

    def normal_at(self, position: Float3) -> Float3:
        beta, gamma = self.barycentric(position)
        n = self.n0 * (1.0 - beta - gamma) + self.n1 * beta + self.n2 * gamma
        if n.length_squared() == 0.0:
            return self._triangle.normal_at(position)
        return normalize(n)


def _groups(keys: np.ndarray) -> list:
    """The indices of equal keys (rows of a 2D ``keys``), one int array per distinct key, in
    increasing order within each."""
    if (keys == keys[0]).all():
        return [np.arange(len(keys))]
    _, inverse = np.unique(keys, axis=0 if keys.ndim == 2 else None, return_inverse=True)
    inverse = inverse.reshape(-1)
    order = np.argsort(inverse, kind="stable")
    return np.split(order, np.cumsum(np.bincount(inverse))[:-1])


def _rows_of_three(value, name: str, dtype) -> np.ndarray:
    try:
        array = np.asarray(value, dtype=dtype)
    except (TypeError, ValueError):
        raise ValueError("%s must be an (n, 3) array of numbers" % name) from None
    if array.ndim != 2 or array.shape[1] != 3:
        raise ValueError("%s must have shape (n, 3), got %s" % (name, array.shape))
    if len(array) == 0:
        raise ValueError("%s is empty" % name)
    return _finite_rows(array, name)


def _face_indices(faces, num_vertices: int) -> np.ndarray:
    array = np.asarray(faces)
    if array.ndim != 2 or array.shape[1] != 3:
        raise ValueError("Mesh.faces must have shape (m, 3), got %s" % (array.shape,))
    if len(array) == 0:
        raise ValueError("Mesh.faces is empty: a mesh needs at least one triangle")
    if not np.issubdtype(array.dtype, np.integer):
        raise ValueError("Mesh.faces must hold integer vertex indices, got %s" % array.dtype)
    bad = np.flatnonzero(((array < 0) | (array >= num_vertices)).any(axis=1)) \
        if array.min() < 0 or array.max() >= num_vertices else ()
    if len(bad):
        raise ValueError("Mesh.faces[%d] = %s refers to a vertex outside 0..%d"
                         % (bad[0], tuple(int(i) for i in array[bad[0]]), num_vertices - 1))
    return array.astype(np.int64)


def _unit_normals(normals, num_vertices: int) -> np.ndarray:
    array = _rows_of_three(normals, "Mesh.normals", np.float64)
    if len(array) != num_vertices:
        raise ValueError("Mesh.normals must have one row per vertex (%d), got %d"
                         % (num_vertices, len(array)))
    length = np.sqrt((array * array).sum(axis=1))
    bad = np.flatnonzero(length == 0.0)
    if len(bad):
        raise ValueError("Mesh.normals[%d] is the zero vector" % bad[0])
    return array / length[:, None]


def _vertex_uvs(uvs, num_vertices: int) -> np.ndarray:
    try:
        array = np.asarray(uvs, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError("Mesh.uvs must be an (n, 2) array of numbers") from None
    if array.shape != (num_vertices, 2):
        raise ValueError("Mesh.uvs must have one (u, v) row per vertex (%d, 2), got shape %s"
                         % (num_vertices, array.shape))
    return _finite_rows(array, "Mesh.uvs")


def _finite_rows(array: np.ndarray, name: str) -> np.ndarray:
    """``array``, refused with a ValueError naming its first row that is not finite."""
    bad = np.flatnonzero(~np.isfinite(array).all(axis=1))
    if len(bad):
        raise ValueError("%s[%d] must be finite, got %s" % (name, bad[0], tuple(array[bad[0]])))
    return array


def _per_face_colors(color, m: int) -> np.ndarray:
    array = np.asarray(color, dtype=np.float64) if not isinstance(color, Float3) else \
        np.array([color.x, color.y, color.z])
    if array.shape == (3,):
        _finite_rows(array[None, :], "Mesh.color")      # checked once, not once per face
        return np.repeat(array[None, :], m, axis=0)
    elif array.shape != (m, 3):
        raise ValueError("Mesh.color must be one colour or one per face (%d, 3), got shape %s"
                         % (m, array.shape))
    return _finite_rows(array, "Mesh.color")


def _per_face_materials(material, m: int) -> tuple:
    if material is None or isinstance(material, Material):
        return (Material() if material is None else material,) * m
    materials = tuple(material)
    if len(materials) != m:
        raise ValueError("Mesh.material must be one Material or one per face (%d), got %d"
                         % (m, len(materials)))
    for i, each in enumerate(materials):
        if not isinstance(each, Material):
            raise ValueError("Mesh.material[%d] must be a Material, got %r" % (i, each))
    return materials


def zero_area_faces(vertices: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """The numbers of the faces whose n = (v1 - v0) x (v2 - v0) has n . n == 0, the test
    ``Triangle`` refuses a triangle by (the same products in the same order, so both agree).
    numpy, in blocks of ZERO_AREA_BLOCK faces: the lecture layer imports no numba, and a
    block's temporaries stay small enough to be reused, not fresh memory for every face."""
    out = []
    for start in range(0, len(faces), ZERO_AREA_BLOCK):
        block = faces[start:start + ZERO_AREA_BLOCK]
        v0 = np.take(vertices, block[:, 0], axis=0)      # np.take: a row at a time
        e0 = np.take(vertices, block[:, 1], axis=0) - v0
        e1 = np.take(vertices, block[:, 2], axis=0) - v0
        nx = e0[:, 1] * e1[:, 2] - e0[:, 2] * e1[:, 1]
        ny = e0[:, 2] * e1[:, 0] - e0[:, 0] * e1[:, 2]
        nz = e0[:, 0] * e1[:, 1] - e0[:, 1] * e1[:, 0]
        out.append(start + np.flatnonzero(nx * nx + ny * ny + nz * nz == 0.0))
    return np.concatenate(out) if out else np.zeros(0, dtype=np.int64)


# Faces per block of zero_area_faces.
ZERO_AREA_BLOCK = 1 << 14


def _refuse_zero_area(vertices: np.ndarray, faces: np.ndarray) -> None:
    bad = zero_area_faces(vertices, faces)
    if len(bad):
        raise ValueError("Mesh.faces[%d] = %s spans zero area (collinear or repeated vertices)"
                         % (bad[0], tuple(int(i) for i in faces[bad[0]])))
