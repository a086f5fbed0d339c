"""Compound: a shape made of shapes (Suffern ch. 19, "Compound objects").

``add_object(shape)`` adds a child (a Compound may hold Compounds); ``set_material(m)``
gives every child the material m, as the book's does. A ray hits the compound where it hits
its nearest child: ``intersect_p`` asks each child in turn with the ray's shrinking tmax,
so the last child that reports a hit is the nearest, and the earlier child wins a tie, as
the shapes of a Scene do. The book's ``Compound::hit`` then records that child's normal and
material; here the compound notes the child in ``hit_object`` (the innermost one, for a
compound in a compound) and Scene.intersect records the normal, material and colour of
``hit_object``.

The numba and WGSL paths have no compound: rtfgu.layout lays out its children in its place
in Scene.shapes, each as a shape of its own kind.
"""
from __future__ import annotations

from ..float3 import Float3
from ..materials.material import Material
from ..ray import Ray
from .shape import Shape


class Compound(Shape):
    def __init__(self):
        # No colour or material of its own: its children have theirs.
        self.objects = []
        self.hit_object = None      # the child hit by the last ray that intersect_p reported

    def add_object(self, shape: Shape) -> None:
        if not isinstance(shape, Shape):
            raise ValueError("%s.add_object takes a Shape, got %r" % (type(self).__name__, shape))
        if shape is self:
            raise ValueError("%s.add_object: a compound cannot hold itself" % type(self).__name__)
        self.objects.append(shape)

    def set_material(self, material: Material) -> None:
        """The book's set_material: the material of every child (and of theirs)."""
        if not isinstance(material, Material):
            raise ValueError("%s.set_material takes a Material, got %r" % (type(self).__name__, material))
        for shape in self.objects:
            if isinstance(shape, Compound):
                shape.set_material(material)
            else:
                shape.material = material

    def leaves(self) -> list:
        """The shapes this compound stands for, in order: its children, a compound child by
        its own leaves (what rtfgu.layout lays out in its place)."""
        out = []
        for shape in self.objects:
            out += shape.leaves() if isinstance(shape, Compound) else [shape]
        return out

    def intersect_p(self, ray: Ray) -> bool:
        hit = None
        for shape in self.objects:
            if shape.intersect_p(ray):
                hit = shape
        if hit is None:
            return False
        self.hit_object = hit.hit_object if isinstance(hit, Compound) else hit
        return True

    def normal_at(self, position: Float3) -> Float3:
        """The normal of the child last hit."""
        return self.hit_object.normal_at(position)

    def hit_normal(self, position: Float3, direction: Float3) -> Float3:
        return self.hit_object.hit_normal(position, direction)

    def texcoord(self, position: Float3) -> tuple:
        return self.hit_object.texcoord(position)

    def bounds(self):
        """The union of the children's boxes; None if a child has none (a plane) or there are
        no children."""
        boxes = [shape.bounds() for shape in self.objects]
        if not boxes or any(box is None for box in boxes):
            return None
        out = boxes[0]
        for box in boxes[1:]:
            out = out.union(box)
        return out
