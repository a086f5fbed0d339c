"""Textures (Suffern ch. 29-30, 02562 worksheet 3): texture coordinates of every shape kind,
image lookup with each filter and address mode, the checker, sRGB decoding and bad input.

The lookups are checked on every path (the ``path`` fixture) against an oracle written here
in fractions from the worksheet's formulas, not against the lecture layer: texel centres at
((i + 1/2) / width, 1 - (j + 1/2) / height), bilinear weights from the distances to them,
repeat = u - floor(u), clamp to [0, 1]. Inputs are small dyadic numbers, so the oracle's
answers are exact in both precisions up to the float32 rounding of the hit point.
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
from PIL import Image

from rtfgu import Disk, Float3, OrthographicCamera, Plane, Scene, Sphere, Triangle
from rtfgu.materials import Material, Matte
from rtfgu.registry import SHAPES, TEXTURES
from rtfgu.scenes import SCENES
from rtfgu.shapes.shape import Shape, plane_texcoord
from rtfgu.textures import Checker, ImageTexture, Texture
from rtfgu.textures.image_texture import read_texture, srgb_to_linear

CLOSE = {"float64": 1e-12, "float32": 2e-6}
# 3 columns x 2 rows, row 0 at the top; eighths, so every bilinear mix below is dyadic.
TEXELS = np.array([[[0.125, 0.5, 1.0], [0.25, 0.0, 0.5], [1.0, 0.875, 0.0]],
                   [[0.0, 0.25, 0.75], [0.5, 0.5, 0.5], [0.75, 0.125, 0.375]]])


# ---------------------------------------------------------------- the oracle, in fractions
def oracle_texel(i, j, address, texels=TEXELS):
    h, w = texels.shape[:2]
    if address == "repeat":
        i, j = i % w, j % h
    else:
        i, j = min(max(i, 0), w - 1), min(max(j, 0), h - 1)
    return tuple(Fraction(float(c)) for c in texels[j, i])


def oracle_color(u, v, filter, address, texels=TEXELS):
    """Worksheet 3's lookup at (u, v), exactly."""
    h, w = texels.shape[:2]
    u, v = Fraction(u), Fraction(v)
    if address == "repeat":
        u, v = u - math.floor(u), v - math.floor(v)
    else:
        u, v = min(max(u, Fraction(0)), Fraction(1)), min(max(v, Fraction(0)), Fraction(1))
    x, y = u * w, (1 - v) * h
    if filter == "nearest":
        return oracle_texel(math.floor(x), math.floor(y), address, texels)
    x, y = x - Fraction(1, 2), y - Fraction(1, 2)
    i, j = math.floor(x), math.floor(y)
    fx, fy = x - i, y - j
    c = [oracle_texel(i + a, j + b, address, texels) for b in (0, 1) for a in (0, 1)]
    weights = ((1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy)
    return tuple(sum(wt * t[k] for wt, t in zip(weights, c)) for k in range(3))


# (u, v) on a plane facing +y with worksheet 3's frame: u = -x, v = z (scale 1).
LOOKUPS = [
    ((0.5 / 3, 0.75), "the top-left texel's centre"),
    ((2.5 / 3, 0.25), "the bottom-right texel's centre"),
    ((0.5, 0.5), "between four texels"),
    ((0.25, 0.625), "a quarter and an eighth off the centres"),
    ((-0.25, 0.5), "u below 0"),
    ((1.375, -0.125), "u above 1, v below 0"),
    ((0.015625, 0.875), "across the seam at u = 0"),
    ((3.0625, 2.9375), "several periods away"),
]


def flat_plane_scene(texture) -> Scene:
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes.append(Plane(Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), Float3(0.0),
                              Material(cd=texture)))
    return scene


def close(got, want, precision) -> bool:
    return all(abs(float(g) - float(w)) <= CLOSE[precision] for g, w in zip(got, want))


@pytest.mark.parametrize("filter", ["nearest", "bilinear"])
@pytest.mark.parametrize("address", ["repeat", "clamp"])
def test_image_lookup_on_every_path(path, filter, address):
    texture = ImageTexture(texels=TEXELS, filter=filter, address=address)
    rays = [((-u, 1.0, v), (0.0, -1.0, 0.0), 0.0, math.inf) for (u, v), _ in LOOKUPS]
    bounces = path.trace(flat_plane_scene(texture), rays)
    for ((u, v), what), ray_bounces in zip(LOOKUPS, bounces):
        want = oracle_color(u, v, filter, address)
        got = ray_bounces[0].color
        assert close(got, want, path.precision), "%s %s %s at %s: %s, want %s" % (
            path, filter, address, what, got, tuple(map(float, want)))


def test_the_oracle_tells_the_filters_and_modes_apart():
    """Each case above decides something: the filters and address modes give other colours."""
    for (u, v), what in LOOKUPS[2:]:
        answers = {(f, a): oracle_color(u, v, f, a) for f in ("nearest", "bilinear")
                   for a in ("repeat", "clamp")}
        assert len(set(answers.values())) >= 2, what


def test_texture_scale_multiplies_the_coordinates(path):
    texture = ImageTexture(texels=TEXELS, filter="bilinear", address="repeat", scale=0.25)
    # The hit at x = -1, z = 2.5 has (u, v) = (1, 2.5), scaled to (0.25, 0.625).
    bounces = path.trace(flat_plane_scene(texture), [((-1.0, 1.0, 2.5), (0.0, -1.0, 0.0), 0.0, math.inf)])
    assert close(bounces[0][0].color, oracle_color(0.25, 0.625, "bilinear", "repeat"), path.precision)


def test_checker_on_a_sphere_a_triangle_and_a_disk(path):
    """The sphere's spherical map, the triangle's barycentrics and the disk's plane frame
    pick the checker's square: the points are chosen inside squares, far from their edges."""
    red, blue = Float3(1.0, 0.0, 0.0), Float3(0.0, 0.0, 1.0)
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes.append(Sphere(Float3(0.0, 0.0, 0.0), 1.0, Float3(0.0),
                               Material(cd=Checker(red, blue, size=0.125))))
    scene.shapes.append(Triangle(Float3(10.0, 0.0, 0.0), Float3(14.0, 0.0, 0.0), Float3(10.0, 4.0, 0.0),
                                 Float3(0.0), Material(cd=Checker(red, blue, size=0.5))))
    scene.shapes.append(Disk(Float3(20.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), 4.0, Float3(0.0),
                             Material(cd=Checker(red, blue, size=1.0))))
    rays, want = [], []
    # The sphere at (phi, theta): u = phi / 2 pi, v = 1 - theta / pi, inside a square.
    for phi, theta in ((0.2, math.pi / 2 - 0.1), (1.1, 1.3), (4.2, 0.3), (5.6, 2.7)):
        p = (math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi))
        rays.append((tuple(5 * c for c in p), tuple(-c for c in p)))
        cells = (phi / (2 * math.pi) / 0.125, (1 - theta / math.pi) / 0.125)
        assert all(0.01 < c - math.floor(c) < 0.99 for c in cells)   # far from an edge
        want.append(red if (math.floor(cells[0]) + math.floor(cells[1])) % 2 == 0 else blue)
    rays += [((11.0, 3.0, 5.0), (0.0, 0.0, -1.0)),   # triangle (beta, gamma) = (1/4, 3/4): squares (0, 1)
             ((10.5, 0.5, 5.0), (0.0, 0.0, -1.0)),   # (1/8, 1/8): squares (0, 0)
             ((21.5, 5.0, 2.5), (0.0, -1.0, 0.0)),   # disk (u, v) = (-1.5, 2.5): squares (-2, 2)
             ((20.5, 5.0, 2.5), (0.0, -1.0, 0.0))]   # (-0.5, 2.5): squares (-1, 2)
    want += [blue, red, red, blue]
    assert red in want and blue in want
    bounces = path.trace(scene, [(o, d, 0.0, math.inf) for o, d in rays])
    for k, (ray_bounces, colour) in enumerate(zip(bounces, want)):
        assert ray_bounces[0].color == (colour.x, colour.y, colour.z), "%s ray %d: %s" % (
            path, k, ray_bounces[0].color)


def test_checker_on_a_rectangle_a_box_and_an_open_cylinder(path):
    """The rectangle's edge projections, the box's face frame and Suffern's CylindricalMap
    pick the checker's square on every path: the points are inside squares, far from edges."""
    from rtfgu import Box, OpenCylinder, Rectangle

    red, blue = Float3(1.0, 0.0, 0.0), Float3(0.0, 0.0, 1.0)
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes.append(Rectangle(Float3(30.0, 0.0, 0.0), Float3(4.0, 0.0, 0.0), Float3(0.0, 0.0, 4.0), Float3(0.0),
                                  Material(cd=Checker(red, blue, size=0.5))))
    scene.shapes.append(Box(Float3(40.0, 0.0, 0.0), Float3(44.0, 4.0, 4.0), Float3(0.0),
                            Material(cd=Checker(red, blue, size=0.5))))
    scene.shapes.append(OpenCylinder(-1.0, 1.0, 1.0, Float3(0.0), Material(cd=Checker(red, blue, size=0.25))))
    rays = [((31.0, 5.0, 3.0), (0.0, -1.0, 0.0)),     # rectangle (u, v) = (1/4, 3/4): squares (0, 1)
            ((30.5, 5.0, 0.5), (0.0, -1.0, 0.0)),     # (1/8, 1/8): squares (0, 0)
            ((41.0, 9.0, 3.0), (0.0, -1.0, 0.0)),     # box face +y: (z, x) -> (3/4, 1/4): squares (1, 0)
            ((49.0, 1.0, 0.5), (-1.0, 0.0, 0.0))]     # box face +x: (y, z) -> (1/4, 1/8): squares (0, 0)
    want = [blue, red, blue, red]
    # The cylinder at (phi, y): u = phi / 2 pi, v = (y - y0) / (y1 - y0).
    for phi, y in ((1.0, 0.6), (4.0, -0.6)):
        rays.append(((5 * math.sin(phi), y, 5 * math.cos(phi)), (-math.sin(phi), 0.0, -math.cos(phi))))
        cells = (phi / (2 * math.pi) / 0.25, (y + 1.0) / 2.0 / 0.25)
        assert all(0.01 < c - math.floor(c) < 0.99 for c in cells)   # far from an edge
        want.append(red if (math.floor(cells[0]) + math.floor(cells[1])) % 2 == 0 else blue)
    assert red in want[4:] and blue in want[4:]
    bounces = path.trace(scene, [(o, d, 0.0, math.inf) for o, d in rays])
    for k, (ray_bounces, colour) in enumerate(zip(bounces, want)):
        assert ray_bounces[0].color == (colour.x, colour.y, colour.z), "%s ray %d: %s" % (
            path, k, ray_bounces[0].color)


def test_a_textured_diffuse_surface_is_lit_in_the_textures_colour(path):
    """Shading multiplies the texture's colour, not the shape's, on every path."""
    from rtfgu.lights import PointLight

    texture = ImageTexture(texels=TEXELS, filter="nearest", address="repeat")
    scene = flat_plane_scene(texture)
    scene.shapes[0].material = Matte(cd=texture)
    scene.shapes[0].color = Float3(1.0, 1.0, 1.0)
    scene.lights.append(PointLight(Float3(-0.5 / 3, 1.0, 0.75), Float3(math.pi)))
    bounce = path.trace(scene, [((-0.5 / 3, 1.0, 0.75), (0.0, -1.0, 0.0), 0.0, math.inf)])[0][0]
    # L = rho_d / pi * pi / r^2 * cos + L_a with r = 1, cos = 1: (0.9 + 0.1) * texel.
    from rtfgu.materials.matte import KA_02562 as AMBIENT_FRACTION, KD_02562 as DIFFUSE_FRACTION
    want = [(DIFFUSE_FRACTION + AMBIENT_FRACTION) * c for c in TEXELS[0, 0]]
    assert close(bounce.color, want, path.precision), (path, bounce.color, want)


# ------------------------------------------------------------------ lecture layer details
def test_every_shape_kind_has_texture_coordinates():
    """A registered kind without texcoord could not carry a texture."""
    for kind in SHAPES:
        assert kind.cls.texcoord is not Shape.texcoord, kind.name


@pytest.mark.parametrize("texture, filter", [("image_texture", "nearest"), ("image_texture", "bilinear")]
                         + [(t.name, None) for t in TEXTURES if t.name != "image_texture"])
def test_a_float32_lookup_stays_in_float32(texture, filter):
    """Every texture kind's numba lookup (rtfgu.kernels.textures.texture_<kind>) gives a
    float32 colour for float32 (u, v) and point, in both image filters: a float64 colour
    would make the float32 shading that follows float64 (numba's math.floor gives an int64,
    and a float32 less it is a float64)."""
    from numba import njit, types

    import rtfgu.kernels.textures as kernels
    from rtfgu.layout import TEXTURE_FILTERS, offset

    lookup = getattr(kernels, "texture_" + texture)
    table = np.zeros((1, 64), dtype=np.float32)
    if texture == "image_texture":
        table[0, offset("ImageTexture", "filter_mode")] = TEXTURE_FILTERS[filter]
        table[0, offset("ImageTexture", "mapping_id")] = -1
        table[0, offset("ImageTexture", "width")] = table[0, offset("ImageTexture", "height")] = 2
        table[0, offset("ImageTexture", "scale")] = 1
    texels = np.linspace(0, 1, 12, dtype=np.float32)
    call = njit(lambda table, texels, u, v, p: lookup(table, 0, texels, u, v, p))
    half = np.float32(0.3)
    call(table, texels, half, half, (half, half, half))
    assert call.nopython_signatures[0].return_type == types.UniTuple(types.float32, 3), texture


def test_every_texture_kind_is_a_texture():
    for kind in TEXTURES:
        assert issubclass(kind.cls, Texture), kind.name


def test_worksheet3_plane_frame_on_a_floor():
    """Worksheet 3: tangent (-1, 0, 0) and binormal (0, 0, 1) on the plane y = 0."""
    assert plane_texcoord(Float3(2.0, 0.0, 3.0), Float3(0.0), Float3(0.0, 1.0, 0.0)) == (-2.0, 3.0)
    assert plane_texcoord(Float3(2.0, 0.0, 3.0), Float3(1.0, 0.0, 1.0), Float3(0.0, 5.0, 0.0)) == (-1.0, 2.0)


def test_plane_frame_of_a_wall_facing_z_is_orthonormal():
    for normal in (Float3(0.0, 0.0, 1.0), Float3(0.0, 0.0, -2.0), Float3(1.0, 2.0, 3.0)):
        n = normal * (1.0 / normal.length())
        u1, v1 = plane_texcoord(Float3(0.0), Float3(0.0), normal)
        assert (u1, v1) == (0.0, 0.0)
        # A unit step along the plane moves (u, v) by a unit vector: the frame is orthonormal.
        a = Float3(1.0, 0.0, 0.0) if abs(n.x) < 0.9 else Float3(0.0, 1.0, 0.0)
        step = a - n * (a.x * n.x + a.y * n.y + a.z * n.z)
        step = step * (1.0 / step.length())
        u, v = plane_texcoord(step, Float3(0.0), normal)
        assert math.isclose(u * u + v * v, 1.0, rel_tol=1e-12)


def test_sphere_texcoord_is_suffern_spherical_map():
    s = Sphere(Float3(1.0, 2.0, 3.0), 2.0, Float3(1.0))
    assert s.texcoord(Float3(1.0, 2.0, 5.0)) == (0.0, 0.5)               # +z: phi = 0, equator
    assert s.texcoord(Float3(3.0, 2.0, 3.0)) == pytest.approx((0.25, 0.5))  # +x: phi = pi / 2
    assert s.texcoord(Float3(1.0, 2.0, 1.0)) == pytest.approx((0.5, 0.5))   # -z: phi = pi
    assert s.texcoord(Float3(1.0, 4.0, 3.0))[1] == 1.0                     # north pole: v = 1
    assert s.texcoord(Float3(1.0, 0.0, 3.0))[1] == 0.0                     # south pole: v = 0
    # A point a little outside the sphere (a hit in float32) still gives finite coordinates.
    assert all(math.isfinite(c) for c in s.texcoord(Float3(1.0, 4.000001, 3.0)))


def test_triangle_texcoord_is_barycentric():
    t = Triangle(Float3(1.0, 0.0, 0.0), Float3(3.0, 0.0, 0.0), Float3(1.0, 4.0, 1.0), Float3(1.0))
    assert t.texcoord(Float3(1.0, 0.0, 0.0)) == (0.0, 0.0)
    assert t.texcoord(Float3(3.0, 0.0, 0.0)) == (1.0, 0.0)
    assert t.texcoord(Float3(1.0, 4.0, 1.0)) == (0.0, 1.0)
    assert t.texcoord(Float3(1.5, 2.0, 0.5)) == (0.25, 0.5)


def test_srgb_decoding_is_the_exact_transfer_function():
    c = np.array([0.0, 0.04045, 0.5, 1.0])
    linear = srgb_to_linear(c)
    assert linear[0] == 0.0 and linear[3] == 1.0
    assert linear[1] == 0.04045 / 12.92
    assert linear[2] == pytest.approx(((0.5 + 0.055) / 1.055) ** 2.4, rel=1e-15)
    # The two pieces meet: continuous at the threshold to 1e-7 (the standard's rounding).
    assert abs(((0.04045 + 0.055) / 1.055) ** 2.4 - 0.04045 / 12.92) < 1e-7


def test_an_image_file_is_read_top_row_first_and_decoded(tmp_path):
    pixels = np.array([[[255, 0, 0], [0, 255, 0]], [[0, 0, 255], [128, 128, 128]]], dtype=np.uint8)
    Image.fromarray(pixels).save(tmp_path / "t.png")
    texels = read_texture(tmp_path / "t.png")
    assert texels.shape == (2, 2, 3)
    assert tuple(texels[0, 0]) == (1.0, 0.0, 0.0)
    assert tuple(texels[1, 0]) == (0.0, 0.0, 1.0)
    assert texels[1, 1, 0] == pytest.approx(srgb_to_linear(128 / 255))
    texture = ImageTexture(tmp_path / "t.png", filter="nearest")
    top_left = texture.get_color(0.25, 0.75)
    assert (top_left.x, top_left.y, top_left.z) == (1.0, 0.0, 0.0)


def test_a_texture_shared_by_shapes_is_laid_out_once():
    from rtfgu.layout import compile_scene

    texture = ImageTexture(texels=TEXELS)
    scene = flat_plane_scene(texture)
    scene.shapes.append(Sphere(Float3(0.0, 2.0, 0.0), 0.5, Float3(0.0), Material(cd=texture)))
    flat = compile_scene(scene)
    assert len(flat.textures["image_texture"]) == 1
    assert flat.texels.size == TEXELS.size


def test_a_scene_without_textures_pays_nothing():
    """No texture table, no texel buffer, no texture WGSL in a scene that has no texture."""
    from rtfgu.layout import compile_scene
    from rtfgu.wgsl.assemble import pieces, scene_features

    flat = compile_scene(SCENES["default_lambertian_shadows"]())
    assert "textures" not in flat.features
    names = [name for name, _ in pieces(scene_features(flat))]
    assert not any("texcoord" in n or n in ("image_texture.wgsl", "checker.wgsl") for n in names)
    textured = compile_scene(SCENES["default_texture_bilinear_repeat"]())
    names = [name for name, _ in pieces(scene_features(textured))]
    assert "image_texture.wgsl" in names and "checker.wgsl" not in names


def test_the_worksheet3_texture_ships_with_the_package():
    scene = SCENES["default_texture_nearest_repeat"]()
    texture = scene.shapes[0].material.texture
    assert (texture.width, texture.height) == (16, 16)
    assert texture.scale == 0.2


# --------------------------------------------------------------------------- bad input
@pytest.mark.parametrize("kwargs, field", [
    (dict(path="/no/such/texture.png"), "ImageTexture.path"),
    (dict(texels=np.zeros((0, 4, 3))), "ImageTexture.texels"),
    (dict(texels=np.zeros((4, 0, 3))), "ImageTexture.texels"),
    (dict(texels=np.zeros((4, 4))), "ImageTexture.texels"),
    (dict(texels=np.full((2, 2, 3), np.nan)), "ImageTexture.texels"),
    (dict(texels=TEXELS, filter="trilinear"), "ImageTexture.filter"),
    (dict(texels=TEXELS, address="mirror"), "ImageTexture.address"),
    (dict(texels=TEXELS, scale=0.0), "ImageTexture.scale"),
    (dict(texels=TEXELS, scale=float("nan")), "ImageTexture.scale"),
    (dict(), "ImageTexture"),
])
def test_bad_image_textures_name_the_field(kwargs, field):
    with pytest.raises(ValueError, match=field.replace(".", r"\.")):
        ImageTexture(**kwargs)


def test_a_file_that_is_not_an_image_names_the_file(tmp_path):
    bad = tmp_path / "notes.png"
    bad.write_text("not an image")
    with pytest.raises(ValueError, match="ImageTexture.path: .*notes.png"):
        ImageTexture(bad)


def test_an_image_without_pixels_names_the_file(tmp_path, monkeypatch):
    empty = tmp_path / "empty.png"
    Image.new("RGB", (1, 1)).save(empty)
    import PIL.Image

    class Empty:
        def __enter__(self):
            return self

        def __exit__(self, *args):
            return False

        def convert(self, mode):
            return np.zeros((0, 0, 3), dtype=np.uint8)

    monkeypatch.setattr(PIL.Image, "open", lambda path: Empty())
    with pytest.raises(ValueError, match="ImageTexture.path: .*empty.png has no pixels"):
        read_texture(empty)


@pytest.mark.parametrize("kwargs, field", [
    (dict(color1=(1, 0, 0), color2=(0, 0, 1), size=0.0), "Checker.size"),
    (dict(color1=(1, 0, 0), color2=(0, 0, 1), size=-1.0), "Checker.size"),
    (dict(color1=(1, 0, float("nan")), color2=(0, 0, 1)), "Checker.color1"),
    (dict(color1=(1, 0, 0), color2=(0, 0, 1), scale=-2.0), "Checker.scale"),
])
def test_bad_checkers_name_the_field(kwargs, field):
    with pytest.raises(ValueError, match=field.replace(".", r"\.")):
        Checker(**kwargs)


def test_a_material_texture_must_be_a_texture():
    with pytest.raises(ValueError, match=r"Matte\.cd") as error:
        Matte(cd="grass.png")
    assert "Texture" in str(error.value)
    with pytest.raises(ValueError, match=r"Material\.cd"):
        Material(cd="grass.png")
