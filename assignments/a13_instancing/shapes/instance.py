"""Instance: a shape seen through an affine transformation (Suffern ch. 21, "Instancing").

An Instance holds a shape (``object``: any Shape, a Mesh or another Instance) and the inverse
of the transformation that places it, ``inv_matrix``; ``forward_matrix`` is the
transformation itself, kept for the bounding box (the book keeps one static forward matrix
for the instance being built; here every instance keeps its own). Each call composes one
more transformation after those before it, as the book's ``Instance`` does:

    translate(dx, dy, dz), scale(a, b, c) or scale(s), rotate_x/y/z(degrees), shear(...)
    forward_matrix = T forward_matrix,   inv_matrix = inv_matrix T^-1

``intersect_p`` hits the object with the inverse-transformed ray, whose direction is not
normalised: the object's t is then the t of the world ray (ch. 21.1). The normal at a hit is
the object's normal at the object-space point, transformed by the transpose of the inverse
and normalised (ch. 20.5, 21.1). The texture coordinates are the object's at the
object-space point: the texture moves with the object (the book's ``transform_the_texture``,
its default).

The material: ``Instance(shape, material)`` gives the instance a material of its own;
without one it shows the object's (each face's, for a Mesh), as the book's ``hit`` takes the
object's material when the object has one.

rtfgu departs from the book's ``shear``, whose inverse listing transposes the off-diagonal
cofactors and miscopies one term of the determinant: the inverse here is the adjugate over
the determinant (ch. 20.3's matrix, inverted exactly), and a shear with determinant 0 is
refused.
"""
from __future__ import annotations

import math

from ..float3 import Float3, normalize
from ..matrix import Matrix
from ..ray import Ray
from ..validation import finite
from .shape import Shape


def _matrix3(rows) -> Matrix:
    """The 4 x 4 matrix with ``rows`` (3 x 3) top left, no translation."""
    m = Matrix()
    for i in range(3):
        for j in range(3):
            m.m[i][j] = rows[i][j]
    return m


def _inverse3(a, name: str) -> Matrix:
    """The inverse of the 3 x 3 matrix ``a`` (its adjugate over its determinant), refused
    with a ValueError naming ``name`` where the determinant is 0."""
    cof = [[a[(i + 1) % 3][(j + 1) % 3] * a[(i + 2) % 3][(j + 2) % 3]
            - a[(i + 1) % 3][(j + 2) % 3] * a[(i + 2) % 3][(j + 1) % 3] for j in range(3)] for i in range(3)]
    det = a[0][0] * cof[0][0] + a[0][1] * cof[0][1] + a[0][2] * cof[0][2]
    if det == 0.0 or not math.isfinite(det):
        raise ValueError("%s: the matrix is singular (determinant %r), it has no inverse" % (name, det))
    return _matrix3([[cof[j][i] / det for j in range(3)] for i in range(3)])


class Instance(Shape):
    def __init__(self, shape, material=None):
        from .mesh import Mesh

        if not isinstance(shape, (Shape, Mesh)):
            raise ValueError("Instance.object must be a Shape, a Mesh or an Instance, got %r" % (shape,))
        self.object = shape
        self._own_material = material
        from .compound import Compound

        if isinstance(shape, Mesh):
            color, inner = shape.color(0), shape.materials[0]
        elif isinstance(shape, Compound):   # no colour of its own: its first leaf's (each leaf shows its own)
            first = shape.leaves()[0] if shape.leaves() else None
            color, inner = (first.color, first.material) if first is not None else (Float3(0.0), None)
        else:
            color, inner = shape.color, shape.material
        super().__init__(color, inner if material is None else material)
        self.inv_matrix = Matrix()
        self.forward_matrix = Matrix()

    def _compose(self, forward: Matrix, inverse: Matrix) -> "Instance":
        """One more transformation after those before: ``forward`` its matrix, ``inverse`` the
        inverse of it (Suffern ch. 21, the order of the products)."""
        # TODO a13: Instance._compose
        #   Compose one more transformation after those before (ch. 21): the forward matrix becomes
        #   forward * self.forward_matrix, the inverse self.inv_matrix * inverse (the inverse of a product
        #   is the product of the inverses in the other order). Return self, so that calls chain.
        raise NotImplementedError('a13: Instance._compose')

    def translate(self, dx: float, dy: float, dz: float) -> "Instance":
        d = [finite(v, "Instance.translate: " + n) for v, n in ((dx, "dx"), (dy, "dy"), (dz, "dz"))]
        forward, inverse = Matrix(), Matrix()
        for i in range(3):
            forward.m[i][3] = d[i]
            inverse.m[i][3] = -d[i]
        return self._compose(forward, inverse)

    def scale(self, a: float, b: float | None = None, c: float | None = None) -> "Instance":
        """scale(a, b, c) along x, y, z; scale(s) the same in every direction."""
        if b is None and c is None:
            b = c = a
        s = [finite(v, "Instance.scale: " + n) for v, n in ((a, "a"), (b, "b"), (c, "c"))]
        for v, n in zip(s, "abc"):
            if v == 0.0:
                raise ValueError("Instance.scale: %s must be non-zero (a scale by 0 is singular, it has no inverse)" % n)
        forward, inverse = Matrix(), Matrix()
        for i in range(3):
            forward.m[i][i] = s[i]
            inverse.m[i][i] = 1.0 / s[i]
        return self._compose(forward, inverse)

    def _rotate(self, theta: float, name: str, i: int, j: int) -> "Instance":
        """A rotation by ``theta`` degrees in the plane of axes i, j (ch. 20.2's matrices:
        m[i][i] = m[j][j] = cos, m[i][j] = -sin, m[j][i] = sin; the inverse its transpose)."""
        theta = finite(theta, "Instance.%s: theta" % name)
        sin_theta = math.sin(theta * (math.pi / 180.0))
        cos_theta = math.cos(theta * (math.pi / 180.0))
        forward, inverse = Matrix(), Matrix()
        forward.m[i][i] = forward.m[j][j] = inverse.m[i][i] = inverse.m[j][j] = cos_theta
        forward.m[i][j], forward.m[j][i] = -sin_theta, sin_theta
        inverse.m[i][j], inverse.m[j][i] = sin_theta, -sin_theta
        return self._compose(forward, inverse)

    def rotate_x(self, theta: float) -> "Instance":
        """A rotation by ``theta`` degrees about the x axis, y toward z."""
        return self._rotate(theta, "rotate_x", 1, 2)

    def rotate_y(self, theta: float) -> "Instance":
        """A rotation by ``theta`` degrees about the y axis, z toward x."""
        return self._rotate(theta, "rotate_y", 2, 0)

    def rotate_z(self, theta: float) -> "Instance":
        """A rotation by ``theta`` degrees about the z axis, x toward y."""
        return self._rotate(theta, "rotate_z", 0, 1)

    def shear(self, hxy: float = 0.0, hxz: float = 0.0, hyx: float = 0.0, hyz: float = 0.0,
              hzx: float = 0.0, hzy: float = 0.0) -> "Instance":
        """The shear of ch. 20.3: h_ab is how much coordinate b grows with coordinate a,

            x' = x + hyx y + hzx z,   y' = hxy x + y + hzy z,   z' = hxz x + hyz y + z."""
        h = {n: finite(v, "Instance.shear: " + n) for v, n in
             ((hxy, "hxy"), (hxz, "hxz"), (hyx, "hyx"), (hyz, "hyz"), (hzx, "hzx"), (hzy, "hzy"))}
        rows = [[1.0, h["hyx"], h["hzx"]], [h["hxy"], 1.0, h["hzy"]], [h["hxz"], h["hyz"], 1.0]]
        return self._compose(_matrix3(rows), _inverse3(rows, "Instance.shear"))

    # --- the shape ---------------------------------------------------------------------
    def object_ray(self, ray: Ray) -> Ray:
        """The ray in the object's space: origin and direction through ``inv_matrix``, the
        direction not normalised, the same [tmin, tmax)."""
        # TODO a13: Instance.object_ray
        #   The ray in the object's space (ch. 21.1): the origin through self.inv_matrix as a point, the
        #   direction as a vector, NOT normalised (so the object's t is the world ray's t), the same tmin and
        #   tmax. Return a new Ray.
        raise NotImplementedError('a13: Instance.object_ray')

    def intersect_p(self, ray: Ray) -> bool:
        inv_ray = self.object_ray(ray)
        if self.object.intersect_p(inv_ray):
            ray.tmax = inv_ray.tmax
            return True
        return False

    def normal_at(self, position: Float3) -> Float3:
        """The object's normal at the object-space point, through the transpose of the
        inverse, normalised (Suffern ch. 20.5, 21.1)."""
        # TODO a13: Instance.normal_at
        #   The object's normal_at at the object-space point (position through self.inv_matrix), through
        #   self.inv_matrix.transform_normal, normalised.
        raise NotImplementedError('a13: Instance.normal_at')

    def hit_normal(self, position: Float3, direction: Float3) -> Float3:
        """The object's hit normal at the object-space point for the object-space direction,
        through the transpose of the inverse, normalised."""
        # TODO a13: Instance.hit_normal
        #   As normal_at, with the object's hit_normal at the object-space point and the object-space
        #   direction (the direction through self.inv_matrix as a vector), so that a normal that turns
        #   toward the ray turns toward it here too.
        raise NotImplementedError('a13: Instance.hit_normal')

    def texcoord(self, position: Float3) -> tuple:
        return self.object.texcoord(self.inv_matrix * position)

    def bounds(self):
        """The book's compute_bounding_box: the object's box with its 8 corners through
        ``forward_matrix``, the box of those, grown as a curved shape's is
        (rtfgu.accelerators.bbox.padded) for the rounding of the transformation. None for an
        object without a box (a plane)."""
        from ..accelerators.bbox import BBox, padded
        from .mesh import Mesh

        if isinstance(self.object, Mesh):
            v = self.object.vertices
            box = BBox(Float3(*(float(c) for c in v.min(axis=0))), Float3(*(float(c) for c in v.max(axis=0))))
        else:
            box = self.object.bounds()
        if box is None:
            return None
        corners = [self.forward_matrix * Float3(x, y, z) for x in (box.p0.x, box.p1.x)
                   for y in (box.p0.y, box.p1.y) for z in (box.p0.z, box.p1.z)]
        box = BBox.of_points(corners)
        return padded(box.centroid(), (box.p1 - box.p0) * 0.5)

    # --- the flat layout's row (rtfgu.registry): the rows of inv_matrix, each with its translation
    row0 = property(lambda self: Float3(*self.inv_matrix.m[0][:3]))
    row1 = property(lambda self: Float3(*self.inv_matrix.m[1][:3]))
    row2 = property(lambda self: Float3(*self.inv_matrix.m[2][:3]))
    t0 = property(lambda self: self.inv_matrix.m[0][3])
    t1 = property(lambda self: self.inv_matrix.m[1][3])
    t2 = property(lambda self: self.inv_matrix.m[2][3])

    # --- a Mesh or a Compound inside ------------------------------------------------------
    def holds_parts(self) -> bool:
        """Whether the object is a Mesh or a Compound (or an instance of one), which the
        lecture layer traces as an instance of each part (parts)."""
        from .compound import Compound
        from .mesh import Mesh

        inner = self.object
        return isinstance(inner, (Mesh, Compound)) or (isinstance(inner, Instance) and inner.holds_parts())

    def parts(self) -> list:
        """The instance of a Mesh or a Compound (or of an instance of one) as the lecture layer
        traces it: an Instance of each face of the mesh, or of each leaf of the compound
        (Compound.leaves), with this instance's matrices and material (Scene.with_faces), in
        their order: the nearest part is hit and the earlier one wins a tie, as the
        compound's intersect_p and the mesh's faces in Scene.shapes have it."""
        from .compound import Compound
        from .mesh import Mesh

        if isinstance(self.object, Mesh):
            inner = self.object.triangles()
        elif isinstance(self.object, Compound):
            inner = self.object.leaves()
        else:
            inner = self.object.parts()
        out = []
        for face in inner:
            one = Instance(face, self._own_material)
            one.inv_matrix, one.forward_matrix = self.inv_matrix, self.forward_matrix
            out.append(one)
        return out
