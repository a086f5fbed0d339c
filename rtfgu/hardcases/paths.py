# release: solves a03
"""The paths a family runs through: the lecture layer (reference, float64), the numba kernels
of rtfgu.kernels.robust (float64 and float32) and the WGSL programs (float32, see
``wgsl_path``), each with the slide or the robust formula of every kind that has it
(rtfgu.hardcases.kinds)."""
from __future__ import annotations

import numpy as np

from ..float3 import Float3
from ..robust import offset_ray_origin
from ..ray import Ray
from ..ray import SPAWN_EPSILON
from .kinds import KINDS

FORMULAS = ("slide", "robust")
WHITE = (1.0, 1.0, 1.0)


def check_formula(formula):
    if formula not in FORMULAS:
        raise ValueError("formula must be one of %s, got %r" % (", ".join(FORMULAS), formula))


def slide_spawn(positions):
    """The slide's secondary rays: from the hit point itself, with tmin = SPAWN_EPSILON."""
    return positions.copy(), np.full(positions.shape[0], SPAWN_EPSILON, positions.dtype)


def _f3(row) -> Float3:
    return Float3(float(row[0]), float(row[1]), float(row[2]))


class Path:
    """A path runs the slide or the robust formula (``formula``) in ``precision``."""

    name = ""
    precision = ""

    def __init__(self, formula: str):
        check_formula(formula)
        self.formula = formula


class ReferencePath(Path):
    """The lecture layer: a Ray and a Shape per ray, ``intersect_p`` (slide) or the
    functions of rtfgu.robust (robust). Bad input raises the lecture layer's ValueError."""

    name = "reference"
    precision = "float64"

    def __call__(self, kind, origins, directions, tmin, tmax, shapes):
        k = KINDS[kind]
        out = np.full(origins.shape[0], np.inf)
        for i in range(origins.shape[0]):
            ray = Ray(_f3(origins[i]), _f3(directions[i]), float(tmin[i]), float(tmax[i]))
            hit = (k.build(shapes[i], WHITE).intersect_p(ray) if self.formula == "slide"
                   else k.robust(ray, *k.lecture_args(shapes[i])))
            if hit:
                out[i] = ray.tmax
        return out

    def spawn(self, kind, positions, normals, directions, shapes):
        if self.formula == "slide":
            return slide_spawn(positions)
        origins = np.empty_like(positions)
        for i in range(positions.shape[0]):
            p = _f3(positions[i])
            err = KINDS[kind].point_error(p, *KINDS[kind].lecture_args(shapes[i]))
            o = offset_ray_origin(p, err, _f3(normals[i]), _f3(directions[i]))
            origins[i] = (o.x, o.y, o.z)
        return origins, np.zeros(positions.shape[0])


class NumbaPath(Path):
    """rtfgu.kernels.robust's batch evaluators in float64 or float32."""

    name = "numba"

    def __init__(self, formula: str, precision: str):
        super().__init__(formula)
        if precision not in ("float32", "float64"):
            raise ValueError("precision must be float32 or float64, got %r" % (precision,))
        from ..kernels import robust as kernels
        self.kernels = kernels
        self.precision = precision

    def __call__(self, kind, origins, directions, tmin, tmax, shapes):
        adapter = self.kernels.ADAPTERS[kind, self.formula]
        with np.errstate(all="ignore"):
            return self.kernels.batch(*adapter, origins, directions, tmin, tmax, shapes)

    def spawn(self, kind, positions, normals, directions, shapes):
        if self.formula == "slide":
            return slide_spawn(positions)
        origins = self.kernels.batch_spawn(self.kernels.POINT_ERRORS[kind], positions, normals,
                                           directions, shapes)
        return origins, np.zeros(positions.shape[0], positions.dtype)


def runs(family, path) -> bool:
    """Whether ``path`` has a formula for the family's kind (the disk has no robust one)."""
    return path.formula in KINDS[family.kind].formulas


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
