"""The registry of kinds: every registered kind brings the pieces each path needs, and the
lists the paths use are derived from it (rtfgu/registry.py, docs/adding_a_shape.md)."""
from __future__ import annotations

import importlib
import inspect
import pkgutil
import re

import pytest

import rtfgu
from rtfgu import layout, registry
from rtfgu.wgsl.assemble import read_piece

MAX_PARAMETERS = 12


def _kernel_functions():
    import numba.core.registry

    import rtfgu.kernels
    from rtfgu.kernels import dispatch

    modules = [importlib.import_module("rtfgu.kernels." + m.name)
               for m in pkgutil.iter_modules(rtfgu.kernels.__path__)]
    modules.append(dispatch.load())
    for module in modules:
        for name, value in vars(module).items():
            if isinstance(value, numba.core.registry.CPUDispatcher):
                yield module.__name__, name, value.py_func
            elif inspect.isfunction(value) and value.__module__ == module.__name__:
                yield module.__name__, name, value


def test_no_kernel_function_takes_more_than_twelve_parameters():
    too_many = ["%s.%s (%d)" % (module, name, len(inspect.signature(fn).parameters))
                for module, name, fn in _kernel_functions()
                if len(inspect.signature(fn).parameters) > MAX_PARAMETERS]
    assert not too_many, "kernel functions with more than %d parameters: %s" % (MAX_PARAMETERS, too_many)


@pytest.mark.parametrize("kind", [k for k in registry.ROW_SHAPES if not k.instance], ids=lambda k: k.name)
def test_a_shape_kind_brings_its_numba_functions_and_wgsl_piece(kind):
    module = importlib.import_module(kind.numba_module)
    fields = [name for name, _ in kind.fields]
    for formula in kind.formulas:
        fn = getattr(module, kind.formula_function(formula)).py_func
        assert list(inspect.signature(fn).parameters) == ["origin", "direction", "tmin", "tmax"] + fields
        text = read_piece(kind.formula_file(formula))
        m = re.search(r"fn intersect_%s\(([^)]*)\)" % kind.name, text)
        assert m, "%s defines no fn intersect_%s" % (kind.formula_file(formula), kind.name)
        names = re.findall(r"(\w+)\s*:", m.group(1))
        assert len(names) == 2 + len(fields), names
    normal = getattr(module, "normal_" + kind.name).py_func
    # a kind whose normal turns toward the ray takes its direction, as the class's hit_normal
    assert list(inspect.signature(normal).parameters) == (["position"] + ["direction"] * kind.faces_ray + fields)
    assert (kind.cls.hit_normal is not rtfgu.Shape.hit_normal) == kind.faces_ray
    assert kind.record in layout.RECORDS
    assert getattr(rtfgu, kind.record) is kind.cls
    init = inspect.signature(kind.cls.__init__).parameters
    assert "color" in init and "material" in init


@pytest.mark.parametrize("kind", [k for k in registry.SHAPES if k.instance], ids=lambda k: k.name)
def test_an_instance_kind_brings_its_matrix_functions_and_wgsl_piece(kind):
    """An instance's numba functions transform a point, a vector and a normal by its row (the
    loops that call its object are generated); its WGSL intersection takes the ray, the hit
    and its fields, and every kind an instance may hold has a row of its own."""
    module = importlib.import_module(kind.numba_module)
    for name in ("instance_point", "instance_vector", "instance_normal"):
        assert list(inspect.signature(getattr(module, name).py_func).parameters)[:2] == ["table", "i"], name
    m = re.search(r"fn intersect_%s\(([^)]*)\)" % kind.name, read_piece(kind.wgsl_file))
    assert m and len(re.findall(r"(\w+)\s*:", m.group(1))) == 2 + len(kind.fields)
    assert kind.record in layout.RECORDS and getattr(rtfgu, kind.record) is kind.cls
    assert all(not k.bvh and not k.instance for k in registry.INSTANCED)
    assert set(registry.INSTANCED) | {kind} == set(registry.ROW_SHAPES)


@pytest.mark.parametrize("kind", [k for k in registry.SHAPES if k.bvh], ids=lambda k: k.name)
def test_a_mesh_kind_brings_its_traversal_normal_and_texcoord_on_both_paths(kind):
    module = importlib.import_module(kind.numba_module)
    for name in ("mesh_closest", "mesh_any", "normal_mesh", "texcoord_mesh"):
        assert callable(getattr(module, name)), name
    text = read_piece(kind.wgsl_file)
    for name in ("mesh_closest", "mesh_any", "mesh_normal", "texcoord_mesh"):
        assert re.search(r"fn %s\(" % name, text), "%s defines no fn %s" % (kind.wgsl_file, name)
    assert kind.record not in layout.RECORDS            # no row: FlatMesh's arrays instead
    assert getattr(rtfgu, kind.record) is kind.cls


def test_kind_ids_are_places_in_the_registry_and_every_kind_has_a_wgsl_count():
    assert layout.SHAPE_KINDS == {i: k.name for i, k in enumerate(registry.SHAPES)}
    assert [s.id for s in registry.SHADERS] == list(range(len(registry.SHADERS)))
    from rtfgu.scenes import SCENES
    from rtfgu.wgsl.assemble import assemble

    source = assemble(layout.compile_scene(SCENES["default_flat_colors"](), "float32")).source
    for kind in registry.SHAPES:
        assert "const NUM_%s = " % kind.table.upper() in source


def test_an_unregistered_shape_is_refused_by_name():
    class Cone(rtfgu.Shape):
        def intersect_p(self, ray):
            return False

        def normal_at(self, position):
            return position

    scene = rtfgu.Scene(rtfgu.PinholeCamera((0, 0, 5), (0, 0, 0), (0, 1, 0)))
    scene.shapes.append(Cone((1, 1, 1)))
    with pytest.raises(ValueError, match=r"Scene.shapes\[0\].*Cone"):
        layout.compile_scene(scene)
