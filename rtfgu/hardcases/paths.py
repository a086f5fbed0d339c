"""The paths a family runs through: the lecture layer (reference, float64), the numba kernels
of rtfgu.kernels.robust (float64 and float32) and the WGSL programs (float32, see
``wgsl_path``), each with the slide or the robust formula."""
from __future__ import annotations

import numpy as np

from .. import robust
from ..float3 import Float3
from ..layout import PLANE, SPHERE, TRIANGLE
from ..ray import Ray
from ..shading import SPAWN_EPSILON
from ..shapes import Plane, Sphere, Triangle

FORMULAS = ("slide", "robust")
WHITE = (1.0, 1.0, 1.0)


def _check_formula(formula):
    if formula not in FORMULAS:
        raise ValueError("formula must be one of %s, got %r" % (", ".join(FORMULAS), formula))


def _f3(row) -> Float3:
    return Float3(float(row[0]), float(row[1]), float(row[2]))


class ReferencePath:
    """The lecture layer: a Ray and a Shape per ray, ``intersect_p`` (slide) or the
    functions of rtfgu.robust (robust). Bad input raises the lecture layer's ValueError."""

    name = "reference"
    precision = "float64"

    def __init__(self, formula: str):
        _check_formula(formula)
        self.formula = formula

    def _hit(self, kind, ray, s) -> bool:
        if self.formula == "slide":
            if kind == SPHERE:
                shape = Sphere(_f3(s[:3]), float(s[3]), WHITE)
            elif kind == PLANE:
                shape = Plane(_f3(s[:3]), _f3(s[3:6]), WHITE)
            else:
                shape = Triangle(_f3(s[:3]), _f3(s[3:6]), _f3(s[6:9]), WHITE)
            return shape.intersect_p(ray)
        if kind == SPHERE:
            return robust.intersect_sphere_robust(ray, _f3(s[:3]), float(s[3]))
        if kind == PLANE:
            return robust.intersect_plane_robust(ray, _f3(s[:3]), _f3(s[3:6]))
        return robust.intersect_triangle_watertight(ray, _f3(s[:3]), _f3(s[3:6]), _f3(s[6:9]))

    def __call__(self, kind, origins, directions, tmin, tmax, shapes):
        out = np.full(origins.shape[0], np.inf)
        for i in range(origins.shape[0]):
            ray = Ray(_f3(origins[i]), _f3(directions[i]), float(tmin[i]), float(tmax[i]))
            if self._hit(kind, ray, shapes[i]):
                out[i] = ray.tmax
        return out

    def spawn(self, kind, positions, normals, directions, shapes):
        n = positions.shape[0]
        if self.formula == "slide":
            return positions.copy(), np.full(n, SPAWN_EPSILON)
        origins = np.empty((n, 3))
        for i in range(n):
            p, s = _f3(positions[i]), shapes[i]
            if kind == SPHERE:
                err = robust.sphere_point_error(p, _f3(s[:3]))
            elif kind == TRIANGLE:
                err = robust.triangle_point_error(_f3(s[:3]), _f3(s[3:6]), _f3(s[6:9]))
            else:
                err = robust.plane_point_error(p, _f3(s[:3]))
            o = robust.offset_ray_origin(p, err, _f3(normals[i]), _f3(directions[i]))
            origins[i] = (o.x, o.y, o.z)
        return origins, np.zeros(n)


class NumbaPath:
    """rtfgu.kernels.robust's batch evaluators in float64 or float32."""

    name = "numba"

    def __init__(self, formula: str, precision: str):
        _check_formula(formula)
        if precision not in ("float32", "float64"):
            raise ValueError("precision must be float32 or float64, got %r" % (precision,))
        from ..kernels import robust as kernels
        self.kernels = kernels
        self.formula = formula
        self.precision = precision
        self.formula_id = kernels.ROBUST if formula == "robust" else kernels.SLIDE

    def __call__(self, kind, origins, directions, tmin, tmax, shapes):
        with np.errstate(all="ignore"):
            return self.kernels.BATCH[kind](self.formula_id, origins, directions, tmin, tmax, shapes)

    def spawn(self, kind, positions, normals, directions, shapes):
        return self.kernels.batch_spawn(self.formula_id, kind, positions, normals, directions, shapes)


def available_paths() -> list:
    """Every path that can run here: (name, precision, formula) -> path object."""
    paths = []
    for formula in FORMULAS:
        paths.append(ReferencePath(formula))
    for precision in ("float64", "float32"):
        for formula in FORMULAS:
            paths.append(NumbaPath(formula, precision))
    from .wgsl_path import wgsl_available, WgslPath
    if wgsl_available():
        for formula in FORMULAS:
            paths.append(WgslPath(formula))
    return paths

