"""A scene's flat layout kept between numba renders while nothing it was made from changed.

``compile_scene`` (rtfgu.layout) reads every shape, material, light and the camera in Python,
about 3.5 us a shape: a 1024x1024 render of 64 spheres then spends a tenth of its time
laying the scene out again, though a second render of the same scene would lay out the same
tables. ``kept_layout`` reads instead every value the layout is made of (the fingerprint
below) and, where they all equal those of the scene's last layout in that precision, returns
that layout; else it compiles the scene and keeps the new layout.

A value changed in place (``light.position.y += 1``, ``sphere.material.diffuse_brdf.kd =
0.2``) changes the fingerprint, which holds values, never the objects holding them (compared
as Python compares numbers: a zero whose sign alone changed keeps the layout). Only
scenes whose every input to the layout the fingerprint reads take this path: shapes of the
row kinds (no meshes, compounds or instances: a mesh's BVH is kept by rtfgu.layout's own
cache, keyed by its arrays), materials without textures, point and directional lights, the
ray-cast tracer (no samplers of a light's or a BRDF's own), no environment. Any other scene
is compiled at every render, as before. ``tests/test_layout_cache.py`` changes every value
of such scenes, one at a time, and checks that the layout returned is the one
``compile_scene`` makes.
"""
from __future__ import annotations

import operator
import weakref

from .float3 import Float3
from .layout import MATERIAL_FIELDS, attribute_paths, compile_camera, compile_scene, compile_tracer, row_values
from .lights.directional import Directional
from .lights.point_light import PointLight
from .registry import LIGHTS, shape_kind_of
from .shapes.compound import Compound

# The Material row's fields compile_scene computes rather than reads from the material
# (color: the material's or the shape's; ambient: the scene's ambient times ka; the texture
# and samplers: none on this path); the others are the material's attributes of that name.
_COMPUTED = {"color", "texture", "texture_row", "ambient", "diffuse_sampler", "specular_sampler"}

# A material's values in its row, ka (the ambient's factor) and its shader, in one C call.
_MATERIAL_VALUES = operator.attrgetter(
    *attribute_paths([field for field in MATERIAL_FIELDS if field[0] not in _COMPUTED]), "ka", "shader")
_COLOR = operator.attrgetter("x", "y", "z")
_LIGHT_KINDS = {kind.cls: kind for kind in LIGHTS if kind.cls in (PointLight, Directional)}

# type -> (its kind's name, its record) for a shape of a row kind, False
# for any other (a mesh, an instance, a compound, an unregistered type): found once a type.
_SHAPE_ROWS = {}


def _shape_row(shape):
    row = _SHAPE_ROWS.get(type(shape))
    if row is None:
        _, kind = shape_kind_of(shape)
        plain = kind is not None and not kind.bvh and not kind.instance and not isinstance(shape, Compound)
        row = _SHAPE_ROWS[type(shape)] = (kind.name, kind.record) if plain else False
    return row


# precision -> (weak reference to the scene, its fingerprint, its layout): the last scene
# laid out in each precision (a layout of a few rows, kept until the next scene's).
_KEPT = {}


def fingerprint(scene):
    """Every value ``compile_scene`` makes this scene's layout of, as a tuple of numbers,
    types and Nones (equal tuples: the same layout); None for a scene outside this path
    (module docstring). ``scene`` has been validated."""
    camera_kind, camera = compile_camera(scene.camera)   # in compile_scene's order: its errors first
    tracer = compile_tracer(scene)
    if scene.environment is not None or tracer[0] is not None:
        return None
    values = [camera_kind, camera.tobytes(), tracer, bool(scene.show_ray_direction),
              _COLOR(scene.background), _COLOR(scene.ambient_light.L(None)),
              bool(getattr(scene.tracer, "samples_lights_at", lambda depth: True)(1))]
    for light in scene.lights:
        kind = _LIGHT_KINDS.get(type(light))
        if kind is None:
            return None
        values += [kind.name, row_values(kind.record, light), light.casts_shadows(), light.flat_limit()]
    first = {}   # id(material) -> the shape that has it first: a shared material is one row
    for i, shape in enumerate(scene.shapes):
        row = _shape_row(shape)
        if not row:
            return None
        m = shape.material
        cd = m.cd
        if isinstance(cd, Float3):
            color = ("cd",) + _COLOR(cd)
        elif cd is None:
            color = _COLOR(shape.color)
        else:   # a texture
            return None
        try:
            material = _MATERIAL_VALUES(m)
        except AttributeError:   # a field compile_scene computes that this file does not know
            return None
        values += [row[0], row_values(row[1], shape), type(m), first.setdefault(id(m), i), color, material,
                   m.flat_limit(scene.tracer)]
    return tuple(values)


def kept_layout(scene, precision: str):
    """compile_scene(scene, precision), or the layout of the last call in this precision if
    that was this scene with the same fingerprint (module docstring). The layout returned
    is shared between such calls: its users read it and never change it."""
    scene.validate()
    key = fingerprint(scene)
    if key is not None:
        kept = _KEPT.get(precision)
        if kept is not None and kept[0]() is scene and kept[1] == key:
            return kept[2]
    flat = compile_scene(scene, precision)
    if key is not None:
        _KEPT[precision] = (weakref.ref(scene), key, flat)
    else:
        _KEPT.pop(precision, None)
    return flat
