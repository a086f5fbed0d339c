"""SolidCylinder: a closed cylinder about the y axis, a Compound of an OpenCylinder and two
Disks, the bottom one facing -y and the top one +y (Suffern ch. 19, "Solid cylinder").

The children are added in the book's order: the bottom disk, the top disk, the side.
"""
from __future__ import annotations

from ..float3 import Float3
from .compound import Compound
from .disk import Disk
from .open_cylinder import OpenCylinder


class SolidCylinder(Compound):
    def __init__(self, bottom: float, top: float, radius: float, color, material=None):
        super().__init__()
        try:   # the open cylinder checks the three numbers, under the solid cylinder's names
            side = OpenCylinder(bottom, top, radius, color, material)
        except ValueError as error:
            raise ValueError(str(error).replace("OpenCylinder.y0", "SolidCylinder.bottom")
                             .replace("OpenCylinder.y1", "SolidCylinder.top")
                             .replace("OpenCylinder.radius", "SolidCylinder.radius")) from None
        self.add_object(Disk(Float3(0.0, side.y0, 0.0), Float3(0.0, -1.0, 0.0), side.radius, color, material))
        self.add_object(Disk(Float3(0.0, side.y1, 0.0), Float3(0.0, 1.0, 0.0), side.radius, color, material))
        self.add_object(side)
