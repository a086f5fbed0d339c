# release: solves a03
"""The shape kinds of the hard cases, each described once, keyed by its rtfgu.registry name.

A hard-case shape is a row of the lecture constructor's arguments before the colour,
flattened: a sphere (center, radius) is 4 floats, a triangle (v0, v1, v2) 9. From that row

* the exact truth is ``rtfgu.hardcases.exact.<name>(o, d, tmin, tmax, *args)``;
* the reference path builds the lecture class of the registry (``Sphere(center, radius,
  color)``) for the slide formula, and calls ``robust`` for the robust one;
* the numba path runs ``rtfgu.kernels.robust.ADAPTERS[name, formula]`` and, for spawned
  rays, ``POINT_ERRORS[name]``;
* the WGSL path runs ``rtfgu/wgsl/hardcase_main.wgsl`` with the feature ``<name>``, which
  reads the row with ``arg3``/``arg1`` and calls the kind's WGSL function.

A kind without a robust formula (the disk, the rectangle, the box, the open cylinder, the torus,
the part sphere, the annulus, the instance) runs the slide formula only. The instance's row is
(scale, translate) of an ellipsoid made from the unit sphere (``ellipsoid``).
"""
from __future__ import annotations

from dataclasses import dataclass

from .. import robust
from ..float3 import Float3
from ..registry import SHAPE_BY_NAME


@dataclass(frozen=True)
class HardCaseKind:
    name: str
    args: tuple                  # components of each constructor argument: (3, 1) for a sphere
    robust: object = None        # rtfgu.robust's test (ray, *args) -> bool, or None
    point_error: object = None   # rtfgu.robust's error bound of a hit point (p, *args) -> Float3
    make: object = None          # (*args, color) -> the lecture shape, where it is not cls(*args, color)
    pieces: tuple = ()           # the kinds whose WGSL pieces the WGSL path needs, where not its own

    @property
    def cls(self) -> type:
        return SHAPE_BY_NAME[self.name].cls

    @property
    def width(self) -> int:
        return sum(self.args)

    @property
    def formulas(self) -> tuple:
        return ("slide", "robust") if self.robust is not None else ("slide",)

    def split(self, row) -> list:
        """The constructor's arguments of ``row``: slices of 3 and scalars."""
        out, k = [], 0
        for components in self.args:
            out.append(row[k:k + 3] if components == 3 else row[k])
            k += components
        return out

    def build(self, row, color):
        """The lecture shape of ``row``."""
        args = self.lecture_args(row)
        return self.make(*args, color) if self.make is not None else self.cls(*args, color)

    def lecture_args(self, row) -> list:
        return [Float3(float(a[0]), float(a[1]), float(a[2])) if hasattr(a, "__len__") else float(a)
                for a in self.split(row)]


def ellipsoid(scale, translate, color):
    """The hard cases' instance (Suffern ch. 21): the unit sphere at the origin scaled by
    ``scale``, then moved by ``translate``."""
    from ..shapes.instance import Instance
    from ..shapes.sphere import Sphere

    return Instance(Sphere(Float3(0.0), 1.0, color)).scale(scale.x, scale.y, scale.z).translate(
        translate.x, translate.y, translate.z)


KINDS = {kind.name: kind for kind in (
    HardCaseKind("sphere", (3, 1), robust.intersect_sphere_robust,
                 lambda p, center, radius: robust.sphere_point_error(p, center)),
    HardCaseKind("plane", (3, 3), robust.intersect_plane_robust,
                 lambda p, point, normal: robust.plane_point_error(p, point)),
    HardCaseKind("triangle", (3, 3, 3), robust.intersect_triangle_watertight,
                 lambda p, v0, v1, v2: robust.triangle_point_error(v0, v1, v2)),
    HardCaseKind("disk", (3, 3, 1)),
    HardCaseKind("rectangle", (3, 3, 3)),
    HardCaseKind("box", (3, 3)),
    HardCaseKind("open_cylinder", (1, 1, 1)),
    HardCaseKind("torus", (1, 1)),
    # The angles in degrees, as the lecture constructor takes them.
    HardCaseKind("convex_part_sphere", (3, 1, 1, 1, 1, 1)),
    HardCaseKind("annulus", (3, 3, 1, 1)),
    HardCaseKind("instance", (3, 3), make=ellipsoid, pieces=("sphere",)),
)}
assert set(KINDS) <= set(SHAPE_BY_NAME), "every hard-case kind is a kind of rtfgu.registry"
