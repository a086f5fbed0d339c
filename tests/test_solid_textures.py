"""Suffern ch. 29-31 on every path: the 3D checker, the mappings of an image texture and the
lattice noises with their textures. The lecture layer defines each colour; the noise values
of the numba path equal the lecture layer's bit for bit in float64, and the WGSL ones agree
within float32 rounding."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest

from rtfgu import Box, Float3, OrthographicCamera, Plane, Scene, Sphere
from rtfgu.materials import Material
from rtfgu.noise import CubicNoise, LinearNoise
from rtfgu.noise.lattice_noise import PERMUTATION_TABLE, VALUE_TABLE, VECTOR_TABLE, lattice_value
from rtfgu.layout import compile_scene
from rtfgu.mappings import CylindricalMap, LightProbe, RectangularMap, SphericalMap
from rtfgu.textures import Checker3D, FBmTexture, ImageTexture, RampFBmTexture, Wood, WrappedFBmTexture
from rtfgu.textures.noise_texture import NOISE_IDS
from wgsl_support import wgpu_device  # noqa: F401  (a fixture)

RED, BLUE = Float3(1.0, 0.0, 0.0), Float3(0.0, 0.0, 1.0)


def out_of_the_rays_way(scene, textures) -> Scene:
    """``scene`` with a sphere of each texture where no ray of these tests goes: the 3D checker
    test and the noise test then hold the same texture kinds, so each numba path traces both
    with one compiled kernel (docs/compile_time.md)."""
    for k, texture in enumerate(textures):
        scene.shapes.append(Sphere(Float3(-100.0, 100.0 + 3.0 * k, 0.0), 1.0, Float3(0.0), Material(cd=texture)))
    return scene


def colours(path, scene, rays):
    bounces = path.trace(scene, [(o, d, 0.0, math.inf) for o, d in rays])
    return [b[0].color for b in bounces]


# ------------------------------------------------------------------------- the 3D checker
def test_checker3d_colours_cubes_of_space_on_every_path(path):
    """The cube of the hit point decides, whatever the shape: a floor at y = 0 lies in the
    cubes below it (the book's epsilon), a sphere and a box show the cubes they cut."""
    checker = Checker3D(RED, BLUE, size=0.5)
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes.append(Plane(Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), Float3(0.0), Material(cd=checker)))
    scene.shapes.append(Sphere(Float3(10.0, 1.0, 0.0), 1.0, Float3(0.0), Material(cd=checker)))
    scene.shapes.append(Box(Float3(20.0, 0.0, 0.0), Float3(22.0, 2.0, 2.0), Float3(0.0), Material(cd=checker)))
    out_of_the_rays_way(scene, _noise_scene()[1])
    rays = [((0.25, 5.0, 0.25), (0.0, -1.0, 0.0)),    # floor: cubes (0, -1, 0): odd
            ((0.75, 5.0, 0.25), (0.0, -1.0, 0.0)),    # (1, -1, 0): even
            ((-0.25, 5.0, -0.75), (0.0, -1.0, 0.0)),  # (-1, -1, -2): even
            ((10.2, 1.3, 5.0), (0.0, 0.0, -1.0)),     # sphere at z = 0.94: (20, 2, 1): odd
            ((10.7, 0.6, 5.0), (0.0, 0.0, -1.0)),     # z = 0.58: (21, 1, 1): odd
            ((20.7, 1.3, 5.0), (0.0, 0.0, -1.0))]     # box face z = 2: (41, 2, 3): even
    want = [BLUE, RED, RED, BLUE, BLUE, RED]
    for k, ((o, d), got, colour) in enumerate(zip(rays, colours(path, scene, rays), want)):
        assert got == (colour.x, colour.y, colour.z), "%s ray %d from %s: %s" % (path, k, o, got)


def test_checker3d_parity_is_the_books(path):
    """A point just below a cube boundary and one just above it differ; the book's epsilon
    moves a point on the boundary to the cube below."""
    checker = Checker3D(RED, BLUE, size=1.0)
    assert checker.get_color(Float3(0.5, 0.5, 0.5)) == RED
    assert checker.get_color(Float3(1.5, 0.5, 0.5)) == BLUE
    assert checker.get_color(Float3(-0.5, 0.5, 0.5)) == BLUE
    assert checker.get_color(Float3(1.0, 0.5, 0.5)) == RED      # on x = 1: the cube below
    assert checker.get_color(Float3(1.001, 0.5, 0.5)) == BLUE


@pytest.mark.parametrize("size", [0.0, -1.0, float("nan"), float("inf")])
def test_a_non_positive_checker3d_size_names_the_field(size):
    with pytest.raises(ValueError, match=r"Checker3D\.size"):
        Checker3D(RED, BLUE, size=size)


# ---------------------------------------------------------------------------- the noise
def _points(n=400):
    """Points over many lattice cells, negative coordinates and exact lattice points included."""
    rng = np.random.default_rng(31)
    points = rng.uniform(-40.0, 40.0, size=(n, 3))
    points[:20] = np.round(points[:20])          # on lattice points
    points[20:40, 0] = np.floor(points[20:40, 0])  # on a lattice plane
    return points


@pytest.mark.parametrize("cls", [LinearNoise, CubicNoise])
def test_numba_noise_equals_the_lecture_layers_bit_for_bit(cls):
    from rtfgu.kernels.noise import (value_fbm, value_fractal_sum, value_noise, value_turbulence, vector_fbm,
                                     vector_noise)

    noise = cls(num_octaves=4, lacunarity=2.5, gain=0.6)
    kind = NOISE_IDS[cls.__name__]
    for x, y, z in _points():
        p = Float3(float(x), float(y), float(z))
        q = (float(x), float(y), float(z))
        assert value_noise(kind, q) == noise.value_noise(p), (cls.__name__, q)
        assert value_fbm(kind, 4, 2.5, 0.6, noise.fbm_max, q) == noise.value_fbm(p), q
        assert value_turbulence(kind, 4, noise.fbm_max, q) == noise.value_turbulence(p), q
        assert value_fractal_sum(kind, 4, noise.fbm_max, q) == noise.value_fractal_sum(p), q
        assert vector_noise(kind, q) == tuple(noise.vector_noise(p)), q
        assert vector_fbm(kind, 4, 2.5, 0.6, q) == tuple(noise.vector_fbm(p)), q


def test_the_noise_interpolates_the_lattice_values():
    """At a lattice point both noises are the lattice value; between, the linear noise is
    the mean of two neighbours on an edge midpoint, and both stay in [-1, 1]."""
    linear, cubic = LinearNoise(), CubicNoise()
    for ix, iy, iz in ((0, 0, 0), (3, -2, 7), (-5, -1, -9)):
        p = Float3(ix, iy, iz)
        assert linear.value_noise(p) == cubic.value_noise(p) == lattice_value(ix, iy, iz)
    mid = linear.value_noise(Float3(3.5, -2.0, 7.0))
    assert mid == 0.5 * (lattice_value(3, -2, 7) + lattice_value(4, -2, 7))
    values = [n.value_noise(Float3(*map(float, p))) for p in _points(200) for n in (linear, cubic)]
    assert -1.0 <= min(values) < -0.3 and 0.3 < max(values) <= 1.0
    assert len(set(VALUE_TABLE)) == 256


def test_the_wgsl_lattice_tables_are_the_lecture_layers():
    from rtfgu.wgsl.assemble import read_piece

    text = read_piece("lattice_tables.wgsl")
    perm = re.search(r"PERMUTATION_TABLE: array<u32, 256> = array<u32, 256>\((.*?)\);", text, re.S).group(1)
    values = re.search(r"VALUE_TABLE: array<f32, 256> = array<f32, 256>\((.*?)\);", text, re.S).group(1)
    assert [int(v.strip().rstrip("u")) for v in perm.split(",")] == list(PERMUTATION_TABLE)
    assert [float(v) for v in values.split(",")] == list(VALUE_TABLE)
    vectors = re.search(r"VECTOR_TABLE: array<vec3f, 256> = array<vec3f, 256>\((.*?)\);", text, re.S).group(1)
    vectors = np.array([[float(c) for c in v.split(",")] for v in re.findall(r"vec3f\(([^)]*)\)", vectors)])
    assert np.array_equal(vectors, np.array(VECTOR_TABLE, dtype=np.float32))
    assert np.allclose(np.linalg.norm(np.array(VECTOR_TABLE), axis=1), 1.0, rtol=0, atol=1e-15)


_NOISE_MAIN = """
@group(0) @binding(0) var<storage, read> points: array<vec4f>;
@group(0) @binding(1) var<storage, read_write> out: array<vec4f>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3u)
{
    let i = id.x;
    if (i >= arrayLength(&points)) {
        return;
    }
    let p = points[i].xyz;
    let kind = points[i].w;
    out[i] = vec4f(value_noise(kind, p), value_fbm(kind, 4.0, 2.5, 0.6, FBM_MAX, p),
                   value_turbulence(kind, 4.0, FBM_MAX, p), value_fractal_sum(kind, 4.0, FBM_MAX, p));
}
"""


def test_wgsl_noise_is_the_lecture_layers_within_float32(wgpu_device):
    from rtfgu.wgsl.harness import batch_program, run_batch

    pieces = ["lattice_tables.wgsl", "linear_noise.wgsl", "cubic_noise.wgsl", "lattice_noise.wgsl", "noise_main.wgsl"]
    for cls in (LinearNoise, CubicNoise):
        noise = cls(num_octaves=4, lacunarity=2.5, gain=0.6)
        main = _NOISE_MAIN.replace("FBM_MAX", repr(float(np.float32(noise.fbm_max))))
        program = batch_program(pieces, features={"lattice_noise", "linear_noise", "cubic_noise"},
                                overrides={"noise_main.wgsl": main})
        # float32 points, so both sides see the same point
        points = _points().astype(np.float32)
        data = np.concatenate([points, np.full((len(points), 1), NOISE_IDS[cls.__name__], np.float32)], axis=1)
        out = run_batch(program, [data.reshape(-1)], len(points))[:, 0, :]
        for k, (x, y, z) in enumerate(points.astype(np.float64)):
            p = Float3(x, y, z)
            want = (noise.value_noise(p), noise.value_fbm(p), noise.value_turbulence(p), noise.value_fractal_sum(p))
            assert np.allclose(out[k], want, rtol=0, atol=2e-5), (cls.__name__, (x, y, z), out[k], want)


def _noise_scene():
    """The noise textures, each on a sphere of its own, with both interpolations."""
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    textures = [FBmTexture(CubicNoise(num_octaves=6), Float3(0.9, 0.7, 0.3), scale=3.0),
                FBmTexture(LinearNoise(num_octaves=3, gain=0.8), Float3(0.2, 0.9, 0.4), min_value=0.2, max_value=0.9),
                WrappedFBmTexture(LinearNoise(num_octaves=5), Float3(1.0, 0.8, 0.6), expansion_number=7.0,
                                  scale=2.0),
                RampFBmTexture(CubicNoise(num_octaves=4), [(0.9, 0.9, 0.85), (0.5, 0.4, 0.3), (0.1, 0.1, 0.2),
                                                          (0.7, 0.6, 0.5)], perturbation=4.0, scale=2.5),
                Wood(Float3(0.9, 0.6, 0.3), Float3(0.4, 0.2, 0.1), scale=2.0),
                Wood(Float3(0.8, 0.7, 0.5), Float3(0.3, 0.2, 0.1), LinearNoise(3, 3.0, 0.6), ring_frequency=6.0)]
    for k, texture in enumerate(textures):
        scene.shapes.append(Sphere(Float3(10.0 * k, 0.0, 0.0), 1.0, Float3(0.0), Material(cd=texture)))
    return scene, textures


def test_noise_textures_on_every_path(path):
    """Each path's colour at 25 points of each sphere against the lecture layer's: equal in
    numba float64, within float32 rounding (and the band or ramp entry it picks) elsewhere."""
    scene, textures = _noise_scene()
    out_of_the_rays_way(scene, [Checker3D(RED, BLUE, size=0.5)])
    rays = []
    for k in range(len(textures)):
        for a in np.linspace(-0.8, 0.8, 5):
            for b in np.linspace(-0.8, 0.8, 5):
                rays.append(((10.0 * k + float(a), float(b), 5.0), (0.0, 0.0, -1.0)))
    want = colours(path.reference, scene, rays)
    got = colours(path, scene, rays)
    assert len(set(want)) > 3 * len(textures)   # the noise varies over each sphere
    off = [k for k, (g, w) in enumerate(zip(got, want)) if not np.allclose(g, w, rtol=0, atol=1e-4)]
    if path.precision == "float64":
        assert got == want
    else:
        # A wrapped band's edge or a ramp entry's may fall on the other side in float32.
        assert len(off) <= 3, [(k, got[k], want[k]) for k in off]


# -------------------------------------------------------------------------- the mappings
def test_the_mappings_give_the_books_coordinates():
    s, c, r, probe, panorama = SphericalMap(), CylindricalMap(), RectangularMap(), LightProbe(), LightProbe(True)
    assert s.get_texel_coordinates(Float3(0.0, 0.0, 1.0)) == (0.0, 0.5)
    assert s.get_texel_coordinates(Float3(1.0, 0.0, 0.0)) == (0.25, 0.5)
    assert s.get_texel_coordinates(Float3(0.0, 1.0, 0.0)) == (0.0, 1.0)
    assert c.get_texel_coordinates(Float3(-1.0, 0.5, 0.0)) == (0.75, 0.75)
    assert r.get_texel_coordinates(Float3(-1.0, 0.0, 1.0)) == (1.0, 0.0)
    assert r.get_texel_coordinates(Float3(0.5, 0.0, -0.5)) == (0.25, 0.75)
    assert probe.get_texel_coordinates(Float3(0.0, 0.0, 1.0)) == (0.5, 0.5)       # the centre
    assert probe.get_texel_coordinates(Float3(1.0, 0.0, 0.0)) == (0.75, 0.5)      # alpha = pi / 2
    assert probe.get_texel_coordinates(Float3(0.0, 0.0, -1.0)) == (1.0, 0.5)      # the rim
    assert panorama.get_texel_coordinates(Float3(0.0, 0.0, -1.0)) == (0.5, 0.5)
    assert panorama.get_texel_coordinates(Float3(0.0, -1.0, 0.0)) == (0.5, 0.25)


def test_a_spherical_map_on_the_unit_sphere_is_the_spheres_own_texcoord():
    sphere = Sphere(Float3(0.0), 1.0, Float3(0.0))
    for x, y, z in np.random.default_rng(29).normal(size=(50, 3)):
        p = Float3(x, y, z) / math.sqrt(x * x + y * y + z * z)
        assert SphericalMap().get_texel_coordinates(p) == sphere.texcoord(p)


MAP_TEXELS = np.array([[[0.125, 0.5, 1.0], [0.25, 0.0, 0.5], [1.0, 0.875, 0.0]],
                       [[0.0, 0.25, 0.75], [0.5, 0.5, 0.5], [0.75, 0.125, 0.375]]])


@pytest.mark.parametrize("mapping", [SphericalMap(), CylindricalMap(), RectangularMap(), LightProbe(),
                                     LightProbe(panoramic=True)], ids=lambda m: m.name)
def test_an_image_texture_through_each_mapping_on_every_path(path, mapping):
    """A unit sphere about the origin (and the square of the plane y = 0 for the rectangular
    map) seen at 25 points: the colours of the lecture layer, bit for bit in float64."""
    texture = ImageTexture(texels=MAP_TEXELS, filter="bilinear", address="repeat", mapping=mapping)
    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    if isinstance(mapping, RectangularMap):
        scene.shapes.append(Plane(Float3(0.0), Float3(0.0, 1.0, 0.0), Float3(0.0), Material(cd=texture)))
        rays = [((float(a), 3.0, float(b)), (0.0, -1.0, 0.0)) for a in np.linspace(-0.9, 0.9, 5)
                for b in np.linspace(-0.9, 0.9, 5)]
    else:
        scene.shapes.append(Sphere(Float3(0.0), 1.0, Float3(0.0), Material(cd=texture)))
        rays = [((float(a), float(b), 3.0 * side), (0.0, 0.0, -side)) for a in np.linspace(-0.8, 0.8, 4)
                for b in np.linspace(-0.8, 0.8, 4) for side in (1.0, -1.0)]
    want = colours(path.reference, scene, rays)
    got = colours(path, scene, rays)
    assert len(set(want)) > 8
    if path.precision == "float64":
        assert got == want
    else:
        assert np.allclose(got, want, rtol=0, atol=1e-4)
    assert mapping.name in compile_scene(scene).features


def test_a_mapped_texture_computes_no_shape_texcoord():
    """Only the mappings a scene uses are assembled, and no shape's (u, v) without a texture
    that reads them."""
    from rtfgu.wgsl.assemble import pieces, scene_features

    scene = Scene(OrthographicCamera(-1.0, 1.0, -1.0, 1.0))
    scene.shapes.append(Sphere(Float3(0.0), 1.0, Float3(0.0), Material(cd=ImageTexture(
        texels=MAP_TEXELS, mapping=CylindricalMap()))))
    scene.shapes.append(Sphere(Float3(3.0, 0.0, 0.0), 1.0, Float3(0.0), Material(cd=Checker3D(RED, BLUE))))
    flat = compile_scene(scene)
    features = scene_features(flat)
    assert "texcoord" not in features and "cylindrical_map" in features
    from rtfgu.wgsl.assemble import assemble

    source = assemble(flat).source
    assert "fn cylindrical_map" in source and "fn texture_checker3d" in source
    for absent in ("fn spherical_map", "fn light_probe", "fn shape_texcoord", "fn value_noise", "fn texture_checker("):
        assert absent not in source, absent


def test_a_mapping_must_be_a_mapping():
    with pytest.raises(ValueError, match=r"ImageTexture\.mapping"):
        ImageTexture(texels=MAP_TEXELS, mapping="spherical")
    with pytest.raises(ValueError, match=r"LightProbe\.panoramic"):
        LightProbe(panoramic="yes")


# --------------------------------------------------------------------------- bad input
@pytest.mark.parametrize("make, field", [
    (lambda: LinearNoise(num_octaves=0), "LinearNoise.num_octaves"),
    (lambda: CubicNoise(num_octaves=-2), "CubicNoise.num_octaves"),
    (lambda: CubicNoise(num_octaves=2.5), "CubicNoise.num_octaves"),
    (lambda: LinearNoise(lacunarity=0.0), "LinearNoise.lacunarity"),
    (lambda: LinearNoise(gain=float("nan")), "LinearNoise.gain"),
    (lambda: FBmTexture("noise"), "FBmTexture.noise"),
    (lambda: FBmTexture(LinearNoise(), min_value=-1.0), "FBmTexture.min_value"),
    (lambda: WrappedFBmTexture(LinearNoise(), expansion_number=0.0), "WrappedFBmTexture.expansion_number"),
    (lambda: RampFBmTexture(CubicNoise(), "/no/such/ramp.png"), "RampFBmTexture.ramp: no such file"),
    (lambda: RampFBmTexture(CubicNoise(), []), "RampFBmTexture.ramp"),
    (lambda: RampFBmTexture(CubicNoise(), [(1.0, 0.0)]), r"RampFBmTexture.ramp\[0\]"),
    (lambda: RampFBmTexture(CubicNoise(), 3), "RampFBmTexture.ramp"),
    (lambda: Wood(ring_frequency=-1.0), "Wood.ring_frequency"),
    (lambda: Wood(ring_frequncy=4.0), "Wood has no parameter ring_frequncy"),
    (lambda: Checker3D(RED, BLUE, scale=0.0), "Checker3D.scale"),
    (lambda: Checker3D((1.0, -1.0, 0.0), BLUE), "Checker3D.color1"),
])
def test_bad_noise_and_solid_textures_name_the_field(make, field):
    with pytest.raises(ValueError, match=field.replace(".", r"\.") if "\\" not in field else field):
        make()


def test_a_ramp_file_that_is_not_an_image_names_the_field(tmp_path):
    bad = tmp_path / "ramp.png"
    bad.write_text("not an image")
    with pytest.raises(ValueError, match=r"RampFBmTexture\.ramp: .*ramp\.png is not an image"):
        RampFBmTexture(CubicNoise(), bad)


def test_a_ramp_image_gives_its_top_row(tmp_path):
    from PIL import Image

    path = tmp_path / "ramp.png"
    Image.fromarray(np.array([[[255, 0, 0], [0, 255, 0], [0, 0, 255]], [[9, 9, 9]] * 3], dtype=np.uint8)).save(path)
    ramp = RampFBmTexture(CubicNoise(), path).ramp
    assert ramp == [Float3(1.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0), Float3(0.0, 0.0, 1.0)]
