# release: solves a13
"""Instances on the numba path (Suffern ch. 21, rtfgu/shapes/instance.py): the inverse matrix
of an instance's row applied to a point, a vector and a normal, operation for operation as
rtfgu.matrix.Matrix (each sum left to right), so that float64 renders equal the lecture
layer's bit for bit.

A row of the instance table (rtfgu.layout.RECORDS["Instance"]) is [row0, t0], [row1, t1],
[row2, t2], [object_kind, object_row, 0, 0]: the 3 x 4 inverse matrix a row at a time, then
the kind (its id in rtfgu.registry.SHAPES) and the row of the object in that kind's
instanced table; for a Mesh, the first node of its tree (rtfgu.layout.compile_mesh), whose
faces the instance's loop tests through rtfgu.kernels.mesh.instanced_mesh_t. The loops over instances, which call the object's kind through a switch,
are generated from the registry (rtfgu.kernels.dispatch).
"""
from __future__ import annotations

from numba import njit

# A hit on an instance of a Mesh carries the face's row in rtfgu.layout.FlatMesh.faces above
# this bit of its row, the instance's row below (rtfgu.kernels.dispatch's scan_instance).
FACE_SHIFT = 32
FACE_MASK = (1 << FACE_SHIFT) - 1


@njit(cache=True, error_model="numpy")
def instance_point(table, i, p):
    """inv_matrix * p (Matrix.transform_point)."""
    return (table[i, 0] * p[0] + table[i, 1] * p[1] + table[i, 2] * p[2] + table[i, 3],
            table[i, 4] * p[0] + table[i, 5] * p[1] + table[i, 6] * p[2] + table[i, 7],
            table[i, 8] * p[0] + table[i, 9] * p[1] + table[i, 10] * p[2] + table[i, 11])


@njit(cache=True, error_model="numpy")
def instance_vector(table, i, v):
    """inv_matrix applied to a vector (Matrix.transform_vector): no translation."""
    return (table[i, 0] * v[0] + table[i, 1] * v[1] + table[i, 2] * v[2],
            table[i, 4] * v[0] + table[i, 5] * v[1] + table[i, 6] * v[2],
            table[i, 8] * v[0] + table[i, 9] * v[1] + table[i, 10] * v[2])


@njit(cache=True, error_model="numpy")
def instance_normal(table, i, n):
    """The transpose of inv_matrix times n (Matrix.transform_normal), not normalised."""
    return (table[i, 0] * n[0] + table[i, 4] * n[1] + table[i, 8] * n[2],
            table[i, 1] * n[0] + table[i, 5] * n[1] + table[i, 9] * n[2],
            table[i, 2] * n[0] + table[i, 6] * n[1] + table[i, 10] * n[2])
