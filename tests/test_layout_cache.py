"""The layout kept between numba renders (rtfgu.layout_cache): a scene unchanged since its
last layout gets that layout again; a scene with any value changed, in place or by a new
object, gets the layout compile_scene makes of it now; a scene outside the kept path is
compiled at every render."""
from __future__ import annotations

import copy
import dataclasses

import numpy as np
import pytest

from rtfgu.float3 import Float3
from rtfgu.layout import compile_scene
from rtfgu.layout_cache import fingerprint, kept_layout
from rtfgu.lights.point_light import PointLight
from rtfgu.materials.material import Material
from rtfgu.renderer import render
from rtfgu.scenes import SCENES
from rtfgu.shapes.sphere import Sphere

PRECISIONS = ("float64", "float32")


def _same(a, b, where="layout") -> None:
    """Assert that two layouts (or parts of them) hold the same values, naming the part that
    differs."""
    assert type(a) is type(b), "%s: %s against %s" % (where, type(a).__name__, type(b).__name__)
    if isinstance(a, np.ndarray):
        assert a.dtype == b.dtype and a.shape == b.shape and np.array_equal(a, b, equal_nan=True), where
    elif isinstance(a, dict):
        assert a.keys() == b.keys(), where
        for key in a:
            _same(a[key], b[key], "%s[%r]" % (where, key))
    elif isinstance(a, (tuple, list)):
        assert len(a) == len(b), where
        for k, (x, y) in enumerate(zip(a, b)):
            _same(x, y, "%s[%d]" % (where, k))
    elif dataclasses.is_dataclass(a):
        for f in dataclasses.fields(a):
            _same(getattr(a, f.name), getattr(b, f.name), "%s.%s" % (where, f.name))
    elif hasattr(a, "__dict__") and not isinstance(a, type):
        _same(vars(a), vars(b), where)
    else:
        assert a == b, "%s: %r against %r" % (where, a, b)


def _outcome(make):
    """make()'s layout, or the (type, message) of the error it raised."""
    try:
        return make()
    except (ValueError, TypeError) as error:
        return type(error), str(error)


def _check(scene, precision, what) -> None:
    kept = _outcome(lambda: kept_layout(scene, precision))
    fresh = _outcome(lambda: compile_scene(scene, precision))
    if isinstance(fresh, tuple):
        assert kept == fresh, "%s: compile_scene raised %r, the kept path gave %r" % (what, fresh, kept)
    else:
        _same(kept, fresh, what)


def _values(scene):
    """(holder, attribute, what) of every number and bool the scene's objects hold, a Float3's
    x, y and z each: the camera, the ambient light, the tracer, the lights, the shapes, their
    materials and what those hold (a BRDF), walked through their attributes."""
    seen, found = set(), []

    def walk(obj, what, depth):
        if id(obj) in seen or depth > 4:
            return
        seen.add(id(obj))
        for name, value in list(vars(obj).items()):
            here = "%s.%s" % (what, name)
            if isinstance(value, Float3):
                found.extend((value, c, here + "." + c) for c in "xyz")
            elif isinstance(value, (int, float)):   # a bool too
                found.append((obj, name, here))
            elif type(value).__module__.startswith("rtfgu.") and hasattr(value, "__dict__"):
                walk(value, here, depth + 1)
            elif isinstance(value, list):
                for k, item in enumerate(value):
                    if type(item).__module__.startswith("rtfgu.") and hasattr(item, "__dict__"):
                        walk(item, "%s[%d]" % (here, k), depth + 1)

    walk(scene, "scene", 0)
    return found


# The homework scenes on the kept path, and one of each layout among them (the scenes that
# differ only in their pixel sampler, which is not part of the layout, once).
FINGERPRINTS = {name: fingerprint(SCENES[name]()) for name in sorted(SCENES)}
KEPT = [name for name, key in FINGERPRINTS.items() if key is not None]
KEPT_SCENES = sorted({FINGERPRINTS[name]: name for name in reversed(KEPT)}.values())


def test_most_lecture_scenes_take_the_kept_path():
    # Not a vacuous list: the lecture's and the book's ray-cast scenes are on it.
    assert {"lecture01_flat_colors", "default_lambertian_shadows", "default_glossy_sphere",
            "suffern_depth_of_field"} <= set(KEPT)
    assert len(KEPT_SCENES) >= 12


@pytest.mark.parametrize("name", KEPT_SCENES)
def test_every_value_changed_in_place_gives_the_layout_compile_scene_makes(name):
    scene = SCENES[name]()
    values = _values(scene)
    assert len(values) >= 10
    for precision in PRECISIONS:
        first = kept_layout(scene, precision)
        assert kept_layout(scene, precision) is first, "an unchanged scene is laid out again"
        _same(first, compile_scene(scene, precision))
    for holder, attribute, what in values:
        before = getattr(holder, attribute)
        changed = (not before if isinstance(before, bool) else
                   before * 1.25 + 0.125 if isinstance(before, float) else before + 1)
        setattr(holder, attribute, changed)
        for precision in PRECISIONS:
            _check(scene, precision, "%s changed to %r" % (what, changed))
        setattr(holder, attribute, before)
        for precision in PRECISIONS:
            _check(scene, precision, "%s back to %r" % (what, before))


def test_new_objects_in_the_scene_give_the_layout_compile_scene_makes():
    scene = SCENES["default_lambertian_shadows"]()
    sphere = next(shape for shape in scene.shapes if isinstance(shape, Sphere))
    changes = [
        lambda: scene.shapes.append(Sphere(Float3(0.5, 0.2, -1.0), 0.3, Float3(0.9, 0.1, 0.1))),
        lambda: scene.shapes.pop(0),
        lambda: setattr(sphere, "material", Material(cd=Float3(0.2, 0.4, 0.6))),
        # one material shared by two shapes: one row, as compile_scene lays it out
        lambda: setattr(scene.shapes[-1], "material", sphere.material),
        lambda: scene.lights.append(PointLight(Float3(1.0, 2.0, 3.0), Float3(2.0))),
        lambda: setattr(scene, "background", Float3(0.3, 0.2, 0.1)),
        lambda: scene.shapes.reverse(),
    ]
    for change in changes:
        change()
        for precision in PRECISIONS:
            _check(scene, precision, "after a change")
    # The same values in another Scene object: its own layout, not the other's.
    twin = copy.deepcopy(scene)
    assert kept_layout(twin, "float64") is not kept_layout(scene, "float64")


@pytest.mark.parametrize("name", ["suffern_checker", "bunny", "suffern_21_instances", "suffern_19_parts",
                                  "cornell_box_area_light", "suffern_17_occlusion_regular"])
def test_a_scene_outside_the_kept_path_is_laid_out_at_every_call(name):
    # A texture, a mesh, instances, a compound, area lights under PathTrace, an ambient
    # occluder: values the fingerprint does not read.
    scene = SCENES[name]()
    assert fingerprint(scene) is None
    first = kept_layout(scene, "float64")
    assert kept_layout(scene, "float64") is not first
    _same(kept_layout(scene, "float64"), compile_scene(scene, "float64"))


def test_a_render_after_a_value_changed_in_place_is_the_render_of_the_scene_as_it_is():
    # The module's own examples: a light moved in place, a BRDF's kd changed in place.
    scene = SCENES["default_lambertian_shadows"]()
    render(scene, 24, 16, backend="numba")
    scene.lights[0].position.y += 1.0
    moved = render(scene, 24, 16, backend="numba")
    assert np.array_equal(moved, render(copy.deepcopy(scene), 24, 16, backend="numba"))
    matte = next(s.material for s in scene.shapes if hasattr(s.material, "diffuse_brdf"))
    matte.diffuse_brdf.kd = 0.2
    darker = render(scene, 24, 16, backend="numba")
    assert not np.array_equal(darker, moved)
    assert np.array_equal(darker, render(copy.deepcopy(scene), 24, 16, backend="numba"))
