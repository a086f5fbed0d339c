"""Bad input gives a ValueError that names the parameter; no NaN reaches a PNG."""
from __future__ import annotations

import math

import numpy as np
import pytest

import rtfgu
from rtfgu import (AreaLight, Box, Float3, Material, Matte, OpenCylinder, OrthographicCamera, PinholeCamera, Plane, PointLight, Ray,
                   Rectangle, Scene, Sphere, Torus, Triangle)
from rtfgu.image import to_8bit, write_png
from rtfgu.scenes import get_scene
from rtfgu.shapes.annulus import Annulus
from rtfgu.shapes.compound import Compound
from rtfgu.shapes.concave_part_sphere import ConcavePartSphere
from rtfgu.shapes.convex_part_sphere import ConvexPartSphere
from rtfgu.shapes.flat_rimmed_bowl import FlatRimmedBowl
from rtfgu.shapes.open_part_cylinder import OpenPartCylinder
from rtfgu.shapes.solid_cylinder import SolidCylinder
from rtfgu.shapes.thick_ring import ThickRing
from wgsl_support import wgpu_device  # noqa: F401  (fixture)

NAN = math.nan
INF = math.inf
RED = Float3(1, 0, 0)


def raises_naming(*names):
    """pytest.raises(ValueError) whose message must contain every one of ``names``."""
    class Check:
        def __enter__(self):
            self.ctx = pytest.raises(ValueError)
            self.info = self.ctx.__enter__()
            return self.info

        def __exit__(self, *exc):
            suppressed = self.ctx.__exit__(*exc)
            message = str(self.info.value)
            for name in names:
                assert name in message, "%r does not name %r" % (message, name)
            return suppressed
    return Check()


# --- rays ----------------------------------------------------------------------------

@pytest.mark.parametrize("direction", [
    Float3(0, 0, 0), Float3(NAN, 0, 1), Float3(0, INF, 0), Float3(0, 0, -INF),
], ids=["zero", "nan", "inf", "minus_inf"])
def test_ray_direction_zero_or_non_finite(direction):
    with raises_naming("direction"):
        Ray(Float3(0, 0, 0), direction)


def test_ray_origin_non_finite():
    with raises_naming("origin"):
        Ray(Float3(NAN, 0, 0), Float3(0, 0, 1))


def test_ray_nan_interval():
    with raises_naming("tmin"):
        Ray(Float3(0, 0, 0), Float3(0, 0, 1), NAN, 1.0)
    with raises_naming("tmax"):
        Ray(Float3(0, 0, 0), Float3(0, 0, 1), 0.0, NAN)


# --- shapes --------------------------------------------------------------------------

@pytest.mark.parametrize("radius", [0.0, -1.0, NAN, INF, -INF, "1"])
def test_sphere_radius(radius):
    with raises_naming("radius"):
        Sphere(Float3(0, 0, 0), radius, RED)


def test_sphere_center_non_finite():
    with raises_naming("center"):
        Sphere(Float3(0, INF, 0), 1.0, RED)


@pytest.mark.parametrize("v0, v1, v2", [
    ((0, 0, 0), (1, 1, 1), (2, 2, 2)),      # collinear
    ((0, 0, 0), (0, 0, 0), (1, 0, 0)),      # repeated vertex
    ((1, 2, 3), (1, 2, 3), (1, 2, 3)),      # a point
], ids=["collinear", "repeated", "point"])
def test_triangle_zero_area(v0, v1, v2):
    with raises_naming("v0", "v1", "v2"):
        Triangle(Float3(*v0), Float3(*v1), Float3(*v2), RED)


def test_triangle_vertex_non_finite():
    with raises_naming("v1"):
        Triangle(Float3(0, 0, 0), Float3(NAN, 0, 0), Float3(0, 1, 0), RED)


def test_plane_zero_or_non_finite_normal():
    with raises_naming("normal"):
        Plane(Float3(0, 0, 0), Float3(0, 0, 0), RED)
    with raises_naming("normal"):
        Plane(Float3(0, 0, 0), Float3(0, NAN, 1), RED)
    with raises_naming("point"):
        Plane(Float3(INF, 0, 0), Float3(0, 1, 0), RED)


@pytest.mark.parametrize("p0, a, b, names", [
    ((0, 0, 0), (0, 0, 0), (0, 1, 0), ("Rectangle.a",)),                   # zero-length edge
    ((0, 0, 0), (1, 0, 0), (0, 0, 0), ("Rectangle.b",)),
    ((0, 0, 0), (1, 0, 0), (2, 0, 0), ("Rectangle.a", "Rectangle.b", "perpendicular")),  # parallel
    ((0, 0, 0), (1, 0, 0), (1, 1, 0), ("Rectangle.a", "Rectangle.b", "perpendicular")),  # skew
    ((0, NAN, 0), (1, 0, 0), (0, 1, 0), ("Rectangle.p0",)),
    ((0, 0, 0), (1, INF, 0), (0, 1, 0), ("Rectangle.a",)),
], ids=["a_zero", "b_zero", "parallel", "not_perpendicular", "p0_nan", "a_inf"])
def test_rectangle_edges(p0, a, b, names):
    with raises_naming(*names):
        Rectangle(Float3(*p0), Float3(*a), Float3(*b), RED)


@pytest.mark.parametrize("p0, p1, names", [
    ((0, 0, 0), (1, 1, 0), ("Box.p0", "Box.p1", "axis z")),      # flat
    ((0, 2, 0), (1, 1, 1), ("Box.p0", "Box.p1", "axis y")),      # corners swapped in y
    ((0, 0, NAN), (1, 1, 1), ("Box.p0",)),
    ((0, 0, 0), (INF, 1, 1), ("Box.p1",)),
], ids=["flat", "swapped", "p0_nan", "p1_inf"])
def test_box_corners(p0, p1, names):
    with raises_naming(*names):
        Box(Float3(*p0), Float3(*p1), RED)


@pytest.mark.parametrize("y0, y1, radius, names", [
    (0.0, 1.0, -1.0, ("OpenCylinder.radius",)),
    (0.0, 1.0, 0.0, ("OpenCylinder.radius",)),
    (1.0, 1.0, 1.0, ("OpenCylinder.y0", "OpenCylinder.y1")),     # y0 = y1: no height
    (2.0, 1.0, 1.0, ("OpenCylinder.y0", "OpenCylinder.y1")),     # y0 > y1
    (NAN, 1.0, 1.0, ("OpenCylinder.y0",)),
    (0.0, INF, 1.0, ("OpenCylinder.y1",)),
    (0.0, 1.0, NAN, ("OpenCylinder.radius",)),
    ("0", 1.0, 1.0, ("OpenCylinder.y0",)),
], ids=["radius_negative", "radius_zero", "y0_equals_y1", "y0_above_y1", "y0_nan", "y1_inf", "radius_nan",
        "y0_string"])
def test_open_cylinder_heights_and_radius(y0, y1, radius, names):
    with raises_naming(*names):
        OpenCylinder(y0, y1, radius, RED)


@pytest.mark.parametrize("a, b, names", [
    (2.0, -1.0, ("Torus.b",)),
    (2.0, 0.0, ("Torus.b",)),
    (0.0, 1.0, ("Torus.a",)),
    (NAN, 1.0, ("Torus.a",)),
    (2.0, INF, ("Torus.b",)),
    (1.0, 1.0, ("Torus.b", "Torus.a", "below")),    # b = a: a horn torus
    (1.0, 2.0, ("Torus.b", "Torus.a", "below")),    # b > a: a spindle torus
    ("2", 1.0, ("Torus.a",)),
], ids=["b_negative", "b_zero", "a_zero", "a_nan", "b_inf", "b_equals_a", "b_above_a", "a_string"])
def test_torus_radii(a, b, names):
    with raises_naming(*names):
        Torus(a, b, RED)


# Suffern's ch. 19 part objects: every field, the angles in degrees within their ranges and in order.
PART_SPHERE = dict(center=(0, 0, 0), radius=1.0, phi_min=0.0, phi_max=360.0, theta_min=0.0, theta_max=180.0)


@pytest.mark.parametrize("cls", [ConvexPartSphere, ConcavePartSphere])
@pytest.mark.parametrize("changes, names", [
    (dict(center=(0, NAN, 0)), ("center",)),
    (dict(radius=0.0), ("radius",)),
    (dict(radius=-1.0), ("radius",)),
    (dict(phi_min=-10.0), ("phi_min", "[0, 360]")),
    (dict(phi_max=361.0), ("phi_max", "[0, 360]")),
    (dict(phi_min=90.0, phi_max=90.0), ("phi_min", "phi_max")),
    (dict(phi_min=180.0, phi_max=90.0), ("phi_min", "phi_max")),
    (dict(phi_max=NAN), ("phi_max",)),
    (dict(theta_min=-1.0), ("theta_min", "[0, 180]")),
    (dict(theta_max=270.0), ("theta_max", "[0, 180]")),
    (dict(theta_min=120.0, theta_max=60.0), ("theta_min", "theta_max")),
    (dict(theta_max="90"), ("theta_max",)),
], ids=["center_nan", "radius_zero", "radius_negative", "phi_min_negative", "phi_max_above_360", "phi_equal",
        "phi_reversed", "phi_max_nan", "theta_min_negative", "theta_max_above_180", "theta_reversed",
        "theta_max_string"])
def test_part_sphere_fields(cls, changes, names):
    args = dict(PART_SPHERE, **changes)
    with raises_naming(*(cls.__name__ + "." + n if n[0].isalpha() else n for n in names)):
        cls(args["center"], args["radius"], args["phi_min"], args["phi_max"], args["theta_min"],
            args["theta_max"], RED)


@pytest.mark.parametrize("args, names", [
    ((0.0, 1.0, 0.0, 0.0, 90.0), ("OpenPartCylinder.radius",)),
    ((1.0, 0.0, 1.0, 0.0, 90.0), ("OpenPartCylinder.y0", "OpenPartCylinder.y1")),
    ((NAN, 1.0, 1.0, 0.0, 90.0), ("OpenPartCylinder.y0",)),
    ((0.0, 1.0, 1.0, -5.0, 90.0), ("OpenPartCylinder.phi_min", "[0, 360]")),
    ((0.0, 1.0, 1.0, 0.0, 400.0), ("OpenPartCylinder.phi_max", "[0, 360]")),
    ((0.0, 1.0, 1.0, 90.0, 45.0), ("OpenPartCylinder.phi_min", "OpenPartCylinder.phi_max")),
], ids=["radius_zero", "y0_above_y1", "y0_nan", "phi_min_negative", "phi_max_above_360", "phi_reversed"])
def test_open_part_cylinder_fields(args, names):
    with raises_naming(*names):
        OpenPartCylinder(*args, RED)


@pytest.mark.parametrize("args, names", [
    (((0, NAN, 0), (0, 1, 0), 0.5, 1.0), ("Annulus.center",)),
    (((0, 0, 0), (0, 0, 0), 0.5, 1.0), ("Annulus.normal",)),
    (((0, 0, 0), (0, 1, 0), -0.5, 1.0), ("Annulus.inner_radius",)),
    (((0, 0, 0), (0, 1, 0), 0.5, 0.0), ("Annulus.outer_radius",)),
    (((0, 0, 0), (0, 1, 0), 1.5, 1.0), ("Annulus.inner_radius", "Annulus.outer_radius")),
    (((0, 0, 0), (0, 1, 0), 1.0, 1.0), ("Annulus.inner_radius", "Annulus.outer_radius")),
    (((0, 0, 0), (0, 1, 0), 0.5, INF), ("Annulus.outer_radius",)),
], ids=["center_nan", "normal_zero", "inner_negative", "outer_zero", "inner_above_outer", "inner_equals_outer",
        "outer_inf"])
def test_annulus_fields(args, names):
    with raises_naming(*names):
        Annulus(*args, RED)


@pytest.mark.parametrize("make, names", [
    (lambda: SolidCylinder(1.0, 0.0, 1.0, RED), ("SolidCylinder.bottom", "SolidCylinder.top")),
    (lambda: SolidCylinder(0.0, 1.0, 0.0, RED), ("SolidCylinder.radius",)),
    (lambda: FlatRimmedBowl((0, 0, 0), 1.0, 0.5, RED), ("FlatRimmedBowl.inner_radius", "FlatRimmedBowl.outer_radius")),
    (lambda: FlatRimmedBowl((0, 0, 0), 0.0, 0.5, RED), ("FlatRimmedBowl.inner_radius",)),
    (lambda: FlatRimmedBowl((NAN, 0, 0), 0.4, 0.5, RED), ("FlatRimmedBowl.center",)),
    (lambda: ThickRing(0.0, 1.0, 1.0, 0.5, RED), ("ThickRing.inner_radius", "ThickRing.outer_radius")),
    (lambda: ThickRing(1.0, 0.0, 0.5, 1.0, RED), ("ThickRing.bottom", "ThickRing.top")),
    (lambda: ThickRing(0.0, 1.0, 0.0, 1.0, RED), ("ThickRing.inner_radius",)),
    (lambda: Compound().add_object("a sphere"), ("Compound.add_object", "Shape")),
    (lambda: Compound().set_material(None), ("Compound.set_material", "Material")),
], ids=["solid_cylinder_reversed", "solid_cylinder_radius", "bowl_radii_reversed", "bowl_inner_zero",
        "bowl_center_nan", "ring_radii_reversed", "ring_reversed", "ring_inner_zero", "compound_non_shape", "compound_non_material"])
def test_compound_objects(make, names):
    with raises_naming(*names):
        make()


@pytest.mark.parametrize("call,names", [
    (lambda i: i.scale(0.0, 1.0, 1.0), ("Instance.scale", "a", "singular")),
    (lambda i: i.scale(1.0, 1.0, 0.0), ("Instance.scale", "c", "singular")),
    (lambda i: i.scale(0.0), ("Instance.scale", "a", "singular")),
    (lambda i: i.scale(1.0, NAN, 1.0), ("Instance.scale", "b")),
    (lambda i: i.translate(0.0, 0.0, NAN), ("Instance.translate", "dz")),
    (lambda i: i.translate(INF, 0.0, 0.0), ("Instance.translate", "dx")),
    (lambda i: i.rotate_x(NAN), ("Instance.rotate_x", "theta")),
    (lambda i: i.rotate_z("90"), ("Instance.rotate_z", "theta")),
    (lambda i: i.shear(hxy=1.0, hyx=1.0), ("Instance.shear", "singular")),
    (lambda i: i.shear(hzy=NAN), ("Instance.shear", "hzy")),
], ids=["scale_a_zero", "scale_c_zero", "uniform_scale_zero", "scale_nan", "translate_nan", "translate_inf",
        "rotate_nan", "rotate_string", "shear_singular", "shear_nan"])
def test_instance_transformations(call, names):
    instance = rtfgu.Instance(Sphere(Float3(0, 0, 0), 1.0, RED))
    before = (instance.inv_matrix, instance.forward_matrix)
    with raises_naming(*names):
        call(instance)
    assert (instance.inv_matrix, instance.forward_matrix) == before, "a refused transformation changed the instance"


def test_instance_object_must_be_a_shape():
    with raises_naming("Instance.object"):
        rtfgu.Instance(Float3(0, 0, 0))


def test_area_light_names_the_shapes_it_takes():
    with raises_naming("AreaLight.shape", "Rectangle"):
        AreaLight(Plane(Float3(0, 0, 0), Float3(0, 1, 0), RED))


def test_shape_colour_non_finite():
    with raises_naming("color"):
        Sphere(Float3(0, 0, 0), 1.0, Float3(NAN, 0, 0))


def test_material_bad_colour_and_bad_numbers():
    # A material's kind is its class (its ``shader`` follows from it); its first argument is
    # the surface colour cd.
    with raises_naming("Material.cd"):
        Material(99)
    with raises_naming("Transparent.ior"):
        rtfgu.Transparent(ior=0.0)
    with raises_naming("Phong.exp"):
        rtfgu.Phong(exp=NAN)


def test_point_light_non_finite():
    with raises_naming("position"):
        PointLight(Float3(NAN, 0, 0), Float3(1, 1, 1))
    with raises_naming("intensity"):
        PointLight(Float3(0, 0, 0), Float3(INF, 1, 1))


# --- cameras -------------------------------------------------------------------------

def test_pinhole_eye_equals_lookat():
    with raises_naming("lookat", "eye"):
        PinholeCamera(Float3(1, 2, 3), Float3(1, 2, 3), Float3(0, 1, 0))


@pytest.mark.parametrize("up", [Float3(0, 1, 0), Float3(0, -3, 0), Float3(0, 0, 0)],
                         ids=["parallel", "antiparallel", "zero"])
def test_pinhole_up_parallel_to_view(up):
    # looking straight down -y: an up along y leaves no image-plane basis
    with raises_naming("up"):
        PinholeCamera(Float3(0, 5, 0), Float3(0, 0, 0), up)


def test_pinhole_non_finite_eye_and_bad_constants():
    with raises_naming("eye"):
        PinholeCamera(Float3(NAN, 0, 0), Float3(0, 0, 0), Float3(0, 1, 0))
    with raises_naming("d"):
        PinholeCamera(Float3(0, 0, 1), Float3(0, 0, 0), Float3(0, 1, 0), d=0.0)
    with raises_naming("aspect"):
        PinholeCamera(Float3(0, 0, 1), Float3(0, 0, 0), Float3(0, 1, 0), aspect=-1.0)


def test_orthographic_degenerate_or_non_finite():
    with raises_naming("right", "left"):
        OrthographicCamera(1, 1, -1, 1)
    with raises_naming("top", "bottom"):
        OrthographicCamera(-1, 1, 2, 2)
    with raises_naming("left"):
        OrthographicCamera(NAN, 1, -1, 1)
    with raises_naming("yon"):
        OrthographicCamera(-1, 1, -1, 1, yon=NAN)


# --- render --------------------------------------------------------------------------

def tiny_scene():
    scene = Scene(OrthographicCamera(-1, 1, -1, 1))
    scene.shapes.append(Sphere(Float3(0, 0, -2), 0.5, RED))
    return scene


@pytest.mark.parametrize("width, height, name", [
    (0, 4, "width"), (-3, 4, "width"), (4, 0, "height"), (4, -1, "height"),
    (2.5, 4, "width"), (4, 3.0, "height"), ("4", 4, "width"), (True, 4, "width"),
    (NAN, 4, "width"),
])
def test_render_size(width, height, name):
    with raises_naming(name):
        rtfgu.render(tiny_scene(), width, height)


def test_render_numpy_integer_size_is_fine():
    assert rtfgu.render(tiny_scene(), np.int64(3), np.int32(2)).shape == (2, 3, 3)


def test_render_without_camera():
    with raises_naming("camera"):
        rtfgu.render(Scene(), 4, 4)


def test_render_unknown_backend():
    with raises_naming("backend"):
        rtfgu.render(tiny_scene(), 4, 4, backend="no-such-backend")


def test_render_refuses_to_return_nan():
    # A colour set to NaN after construction (bypassing Shape's check) must not come back
    # as an image silently.
    scene = tiny_scene()
    scene.shapes[0].color = Float3(NAN, 0, 0)
    with pytest.raises(ValueError):
        rtfgu.render(scene, 4, 4)


# --- scene names ---------------------------------------------------------------------

def test_unknown_scene_name():
    with raises_naming("no_such_scene"):
        get_scene("no_such_scene")


# --- no NaN reaches a PNG --------------------------------------------------------------

@pytest.mark.parametrize("bad", [NAN, INF, -INF])
def test_write_png_refuses_non_finite(tmp_path, bad):
    image = np.zeros((2, 3, 3))
    image[1, 2, 0] = bad
    path = tmp_path / "bad.png"
    with raises_naming("image", "row 1", "column 2"):
        write_png(image, path)
    assert not path.exists()
    with pytest.raises(ValueError):
        to_8bit(image)


def test_write_png_wrong_shape(tmp_path):
    with raises_naming("image"):
        write_png(np.zeros((4, 4)), tmp_path / "flat.png")


def test_render_non_finite_background():
    scene = tiny_scene()
    scene.background = Float3(0, NAN, 0)
    with raises_naming("background"):
        rtfgu.render(scene, 4, 4)


def _overflowing_scene():
    """A point light of 3e38 a tenth of a unit above a plane: its 1/r^2 falloff is 3e40 at
    the plane, beyond float32 (not float64)."""
    scene = rtfgu.Scene(PinholeCamera(Float3(0, 2, 0), Float3(0, 0, 0), Float3(0, 0, -1)))
    scene.shapes.append(Plane(Float3(0, 0, 0), Float3(0, 1, 0), Float3(0.8), Matte()))
    scene.lights.append(PointLight(Float3(0, 0.1, 0), Float3(3e38)))
    return scene


@pytest.mark.parametrize("backend", ["numba", "wgpu"])
def test_a_render_whose_float32_radiance_overflows_is_refused_not_written(backend, request):
    if backend == "wgpu":
        request.getfixturevalue("wgpu_device")
    with pytest.raises(ValueError, match="the %s backend produced non-finite pixels" % backend):
        rtfgu.render(_overflowing_scene(), 8, 8, backend=backend, precision="float32")
    image = rtfgu.render(_overflowing_scene(), 8, 8, backend="numba", precision="float64")
    assert image.dtype == np.float64 and np.isfinite(image).all() and image.max() > 1e38


def test_a_float64_render_of_one_sample_whose_radiance_overflows_is_refused():
    """One float64 sample's sums are the image (not divided, only checked): an infinite
    pixel there is refused as a divided one is."""
    scene = _overflowing_scene()
    scene.lights[0] = PointLight(Float3(0, 0.1, 0), Float3(1e307))   # 1e309 at the plane: beyond float64
    with pytest.raises(ValueError, match="the numba backend produced non-finite pixels"):
        rtfgu.render(scene, 8, 8, backend="numba", precision="float64")


@pytest.mark.parametrize("where", ["sphere", "material", "light"])
def test_a_value_beyond_float32_is_refused_by_the_layout_naming_its_table(where):
    """compile_scene checks every table it lays out: a number that float32 cannot hold
    (here 1e39) names the table in float32, and lays out as given in float64."""
    from rtfgu.layout import compile_scene

    scene = Scene(PinholeCamera(Float3(0, 0, 5), Float3(0, 0, 0), Float3(0, 1, 0)))
    big = 1e39
    scene.shapes.append(Sphere(Float3(0, 0, 0), big if where == "sphere" else 1.0, Float3(0.5),
                               material=Matte(kd=big if where == "material" else 0.5)))
    scene.lights.append(PointLight(Float3(0, 5, 0), Float3(big if where == "light" else 1.0)))
    table = {"sphere": "sphere", "material": "materials", "light": "light"}[where]
    with pytest.raises(ValueError, match=r"Scene: \S*%s\S* is not finite in float32" % table):
        compile_scene(scene, "float32")
    flat = compile_scene(scene, "float64")
    assert big in np.concatenate([flat.table("sphere").ravel(), flat.materials.ravel(),
                                  flat.lights["point_light"].ravel()])
