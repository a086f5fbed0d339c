"""Matrix: a 4 x 4 matrix of an affine transformation (Suffern ch. 20, "Affine Transformations").

The book's class: ``m[row][column]``, the identity on construction and after
``set_identity()``, ``*`` the matrix product, ``/`` a division by a number. A point is a
column vector with w = 1, a vector one with w = 0 (no translation), and a normal is
transformed by the transpose of the inverse (ch. 20.5: a normal stays perpendicular to a
transformed surface only so); the book writes all three as ``matrix * p`` on its Point3D,
Vector3D and Normal types, which Python's Float3 cannot tell apart, so here

    matrix * p                   a point (the book's Matrix * Point3D)
    matrix.transform_vector(v)   a vector (Matrix * Vector3D)
    matrix.transform_normal(n)   a normal, with ``matrix`` the inverse: the transpose's
                                 product (Matrix * Normal, ch. 20.5)

Every sum is taken left to right, as the book's listings take it (m[0][0] x + m[0][1] y +
m[0][2] z + m[0][3]); the numba and WGSL paths transform in this order too, so that the
float64 paths agree bit for bit.
"""
from __future__ import annotations

import math

from .float3 import Float3


class Matrix:
    __slots__ = ("m",)

    def __init__(self, rows=None):
        """The identity, or the matrix of ``rows`` (4 rows of 4 numbers, every one finite)."""
        if rows is None:
            self.set_identity()
            return
        try:
            m = [[float(c) for c in row] for row in rows]
        except (TypeError, ValueError):
            raise ValueError("Matrix: rows must be 4 rows of 4 numbers, got %r" % (rows,)) from None
        if len(m) != 4 or any(len(row) != 4 for row in m):
            raise ValueError("Matrix: rows must be 4 rows of 4 numbers, got %r" % (rows,))
        if not all(math.isfinite(c) for row in m for c in row):
            raise ValueError("Matrix: every entry must be finite, got %r" % (rows,))
        self.m = m

    def set_identity(self) -> None:
        self.m = [[1.0 if row == column else 0.0 for column in range(4)] for row in range(4)]

    def __mul__(self, other):
        """The matrix product (the book's operator*: each entry a sum from 0 over j of
        m[x][j] other.m[j][y]), or the transformed point of a Float3."""
        if isinstance(other, Float3):
            return self.transform_point(other)
        if not isinstance(other, Matrix):
            return NotImplemented
        product = Matrix()
        for y in range(4):
            for x in range(4):
                total = 0.0
                for j in range(4):
                    total += self.m[x][j] * other.m[j][y]
                product.m[x][y] = total
        return product

    def __truediv__(self, d: float) -> "Matrix":
        """Every entry divided by ``d`` (the book's operator/, here a new matrix)."""
        return Matrix([[c / d for c in row] for row in self.m])

    def __eq__(self, other) -> bool:
        return isinstance(other, Matrix) and self.m == other.m

    def __repr__(self) -> str:
        return "Matrix(%r)" % (self.m,)

    def transform_point(self, p: Float3) -> Float3:
        """The point p (w = 1) through this matrix: the book's Matrix * Point3D."""
        ### BEGIN SOLUTION
        m = self.m
        return Float3(m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
                      m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
                      m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3])
        ### END SOLUTION

    def transform_vector(self, v: Float3) -> Float3:
        ### BEGIN SOLUTION
        m = self.m
        return Float3(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
                      m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                      m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z)
        ### END SOLUTION

    def transform_normal(self, n: Float3) -> Float3:
        """The transpose of this matrix times ``n``: with this matrix the inverse of a
        transformation, the normal of the transformed surface (not normalised)."""
        ### BEGIN SOLUTION
        m = self.m
        return Float3(m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z,
                      m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z,
                      m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z)
        ### END SOLUTION
