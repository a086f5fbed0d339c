"""PathTrace (rtfgu.tracers.path_trace) against exact truths, on the lecture layer and numba (float64
and float32).

What is checked, and the exact value each check compares with:

1. White furnace. ``scene.background = 1`` (radiance 1 from every direction):
   * albedo-1 Lambertian shapes (and a lossless mirror and glass sphere), no lights:
     Russian roulette continues with q = 1 and the throughput stays rho / q = 1, so every
     path that leaves the scene brings exactly 1. Every pixel is 1 (to rounding), for one
     sphere and for shapes that reflect light between them alike: this estimator has no
     variance at all.
   * shapes with albedo rho < 1 that emit L_e = 1 - rho, each an AreaLight, and a mirror:
     the radiance L = 1 everywhere solves the rendering equation (L_e + rho * 1 = 1, and a
     mirror sends on the 1 it receives), so every pixel's expectation is 1, now with
     variance from roulette, the bounce directions and the light samples: the mean within
     3 standard errors of 1, and the error falls as 1 / sqrt(spp).
   Emission is one-sided: an emitter seen from the back is black (exact, every path).
2. A closed box of emitting (e) diffuse (rho) faces, the camera inside: with next-event
   estimation over all the faces a path of at most D vertices has the expectation
   e * sum_{k=0}^{D} rho^k (derived at box_truth).
3. Chi-square tests (as tests/test_sampling.py): cosine_direction has the density
   cos(theta) / pi about its normal, the points an AreaLight draws (get_direction) are
   uniform by area on a triangle and on a sphere; the numba twins give the lecture layer's
   numbers.
4. The direct light of a spherical and of a square AreaLight on a diffuse floor (PathTrace
   with one vertex) against the closed-form irradiance: pixel = rho / pi * E.
5. Bad input is a ValueError naming the field; a render with shading points on a light's
   plane and edge stays finite.
6. Parity: numba float64 is the lecture layer to 1e-9, float32 close; seeds repeat.

The paths: the lecture layer ("reference", pure Python), numba float64 and numba float32.
The wgpu path does not path trace yet. All numba scenes here use few kinds of shape, so
numba compiles few kernels: spheres + triangles + area lights, spheres + triangles without
a light (the furnaces), and the box (a mesh + area lights, as the Cornell box scenes).
"""
from __future__ import annotations

import inspect
import math
import re
from fractions import Fraction

import numpy as np
import pytest

from rtfgu import (AreaLight, AreaLighting, Emissive, Float3, GlossySpecular, Lambertian, Mesh, PathTrace,
                   PinholeCamera, Plane, Rectangle, Reflective, Regular, Scene, Sphere, Transparent, Triangle, render)
from rtfgu.brdfs.perfect_specular import reflect
from rtfgu.hit_info import HitInfo
from rtfgu.image import to_8bit
from rtfgu.layout import compile_scene
from rtfgu.float3 import dot, normalize
from rtfgu.materials import Matte
from rtfgu.scenes.meshes import path_matte
from warp_support import chi_square_p

# (label, backend, precision) of every path that path traces.
PATHS = (("reference", "reference", "float64"), ("numba-float64", "numba", "float64"),
         ("numba-float32", "numba", "float32"), ("wgpu-float32", "wgpu", "float32"))
# How far an exact result may be from its truth on a path: rounding only.
ROUNDING = {"float64": 1e-12, "float32": 1e-6}
# A correct sampler fails a chi-square test at this level once in 10^4 runs.
ALPHA = 1e-4
# A Monte Carlo mean is within this many standard errors of its expectation (a normal
# variable is outside once in 370 draws).
Z = 3.0


@pytest.fixture(params=PATHS, ids=[label for label, _, _ in PATHS])
def path(request):
    """Each path; WGSL skipped only where no adapter exists, naming the package to install."""
    if request.param[1] == "wgpu":
        from rtfgu.wgsl.device import NoAdapterError, get_device

        try:
            get_device()
        except NoAdapterError as error:
            pytest.skip(str(error))
    return request.param


def render_on(path, scene, width, spp, seed):
    """``scene`` rendered on ``path`` as a square image: (width, width, 3) mean radiance."""
    _, backend, precision = path
    return render(scene, width, width, backend, precision, spp=spp, seed=seed)


def mean_and_standard_error(image):
    """The mean of the pixels and its standard error, from the spread of the pixel means.

    Used where every pixel has the same expectation (every check here but parity): the
    pixel means are then independent draws (each pixel draws its own random numbers) of
    that expectation, whatever the variance of each, so the spread of the pixel means
    estimates the standard error of their mean."""
    pixels = image.mean(axis=2).ravel()
    return pixels.mean(), pixels.std(ddof=1) / math.sqrt(pixels.size)


def rmse_ratio(path, scene, truth, width, spp, seeds):
    """The RMSE over pixels at ``spp`` samples over the RMSE at 16 * spp (two seeds, so
    the two images share no path): 4 if the error falls as 1 / sqrt(spp)."""
    coarse = render_on(path, scene, width, spp, seeds[0]).mean(axis=2)
    fine = render_on(path, scene, width, 16 * spp, seeds[1]).mean(axis=2)
    return math.sqrt(np.mean((coarse - truth) ** 2)) / math.sqrt(np.mean((fine - truth) ** 2))


# 4 is the expected ratio (the mean squared error falls by 16 exactly). Its estimate from
# P pixels has a relative spread of about sqrt((kurtosis - 1) / P) in the squared error,
# about 10 % in the ratio for the 256-4096 pixels used here; the band [2.5, 6] is
# several of those spreads wide and still tells 1 / sqrt(spp) from 1 / spp^(1/4) (ratio 2)
# or from a bias that does not fall (ratio near 1), and from 1 / spp (ratio 16).
RATIO_BAND = (2.5, 6.0)


# ---------------------------------------------------------------------------------------
# 1. The white furnace

FURNACE_CAMERA = dict(eye=(0.0, 1.0, 4.0), lookat=(0.0, 0.6, 0.0), up=(0.0, 1.0, 0.0), d=1.0)
# A floor triangle (its front, (v1 - v0) x (v2 - v0) = (0, 36, 0), faces up).
FLOOR = ((-3.0, 0.0, 3.0), (3.0, 0.0, 3.0), (0.0, 0.0, -3.0))
# A small triangle 6 behind the camera of the furnace, facing it, out of its view.
BEHIND_THE_CAMERA = ((-0.5, 0.5, 10.0), (0.0, 1.5, 10.0), (0.5, 0.5, 10.0))


def furnace_scene(layout: str, rho=None) -> Scene:
    """The furnace: a white environment (background 1) and diffuse shapes.

    layout "sphere": one sphere, and behind the camera a triangle of albedo 1 like it (a
    path that meets it still brings exactly 1) that keeps the kinds of the cluster, so numba
    compiles no other kernel; "cluster": three spheres 10^-3 apart above a floor 10^-3 below
    them (light goes back and forth between them), and beside them a mirror sphere and a
    glass sphere (ior 1.5), both lossless; "emissive": two diffuse spheres 0.35 apart above
    a floor 0.3 below (the gaps bound the light samples' 1 / d^2, so the variance stays
    moderate), with albedos ``rho`` (three greys) and each emitting 1 - rho as an AreaLight,
    and a mirror sphere (it reflects the radiance 1 it receives, so the truth stays 1; a
    path that did not count the emission it sees after the mirror, or counted the emission
    it sees after a diffuse bounce, would be off). Without ``rho`` every albedo is 1 and
    nothing emits."""
    scene = Scene(PinholeCamera(**FURNACE_CAMERA))
    scene.background = Float3(1.0)
    # max_depth 256: with albedo 1 a path stops only when it leaves the scene, which it does
    # after a few bounces unless it is trapped between the shapes 256 times (the gaps let a
    # path out with a probability well above 1/2 a bounce). With albedo <= 0.8 a path
    # reaches vertex 256 with probability <= 0.8^255 < 10^-24: the truncation is far below
    # any standard error here.
    scene.tracer = PathTrace(max_depth=256)

    def material(albedo):
        # kd 1, no ambient term: the albedo is the shape's colour
        if rho is None:
            return path_matte()
        return Matte(ka=0.0, kd=1.0, emission=(1.0 - albedo,) * 3)

    specular = []
    if layout == "sphere":
        spheres = [((0.0, 0.6, 0.0), 1.2)]
        floor = BEHIND_THE_CAMERA
    elif layout == "cluster":
        spheres = [((-0.5005, 0.501, 0.0), 0.5), ((0.5005, 0.501, 0.0), 0.5),
                   ((0.0, 0.501 + 0.5005 * math.sqrt(3.0), 0.0), 0.5)]
        floor = FLOOR
        specular = [Sphere((1.6, 0.5, 0.3), 0.4, (1.0, 1.0, 1.0), Reflective()),
                    Sphere((-1.6, 0.5, 0.3), 0.4, (1.0, 1.0, 1.0), Transparent(ior=1.5))]
    else:
        spheres = [((-0.7, 0.8, 0.0), 0.5), ((0.65, 0.8, 0.1), 0.5)]
        floor = FLOOR
        specular = [Sphere((0.0, 0.55, 1.1), 0.45, (1.0, 1.0, 1.0), Reflective())]
    albedos = list(rho) if rho is not None else [1.0] * (len(spheres) + (floor is not None))
    for (center, radius), albedo in zip(spheres, albedos):
        scene.shapes.append(Sphere(center, radius, (albedo,) * 3, material(albedo)))
    if floor is not None:
        scene.shapes.append(Triangle(*floor, (albedos[-1],) * 3, material(albedos[-1])))
    if rho is not None:
        scene.lights += [AreaLight(shape) for shape in scene.shapes]
    scene.shapes += specular
    return scene


def seen_fraction(scene, width):
    """The fraction of the pixel centres whose eye ray meets a shape (lecture layer)."""
    seen = 0
    for iy in range(width):
        for ix in range(width):
            ray = scene.camera.gen_ray(2 * (ix + 0.5) / width - 1, 2 * (iy + 0.5) / width - 1)
            seen += scene.intersect(ray, HitInfo())
    return seen / width ** 2


# Three albedos (two spheres and the floor) of the emitting furnace.
FURNACE_RHO = (0.5, 0.8, 0.3)


@pytest.fixture(scope="module")
def furnace_scenes():
    return {name: furnace_scene(name) for name in ("sphere", "cluster")}


@pytest.fixture(scope="module")
def emissive_furnace():
    return furnace_scene("emissive", FURNACE_RHO)


@pytest.mark.parametrize("layout", ["sphere", "cluster"])
def test_albedo_one_furnace_is_exactly_one_in_every_pixel(path, furnace_scenes, layout):
    """Albedo 1, no light, radiance 1 from the environment: every path is exactly 1 (q = 1,
    rho / q = 1, a path ends only when it leaves the scene, with throughput 1). A path
    that ended early (a ray trapped inside a sphere by a bad offset, a lossy mirror or
    refraction, roulette with q < 1), a wrong weight or a missing background would show
    as a pixel below or above 1."""
    scene = furnace_scenes[layout]
    assert seen_fraction(scene, 12) > 0.25          # the shapes fill a good part of the image
    image = render_on(path, scene, 12, 8, seed=3)
    assert np.abs(image - 1.0).max() <= ROUNDING[path[2]]


def test_emissive_furnace_mean_is_one(path, emissive_furnace):
    """rho + L_e = 1 on every shape, environment 1: the expectation of every pixel is 1."""
    width, spp = (24, 16) if path[1] == "reference" else (48, 64)
    image = render_on(path, emissive_furnace, width, spp, seed=11)
    mean, se = mean_and_standard_error(image)
    assert seen_fraction(emissive_furnace, 12) > 0.25
    assert se > 0.0                       # the scene has variance: the test can fail
    assert abs(mean - 1.0) <= Z * se, (mean, se)
    assert abs(image.mean(axis=2) - 1.0).max() > 10 * se   # pixels do scatter about 1


def test_emissive_furnace_error_falls_as_one_over_sqrt_spp(path, emissive_furnace):
    width, spp = (32, 8) if path[1] == "reference" else (64, 16)
    ratio = rmse_ratio(path, emissive_furnace, 1.0, width, spp, seeds=(21, 22))
    assert RATIO_BAND[0] < ratio < RATIO_BAND[1], ratio


def one_sided_scene() -> Scene:
    """Two emitting triangles in the plane z = 0 that fill the view, meeting on x = 0: the
    left one faces the camera (+z, L_e = 2), the right one faces away (-z, L_e = 3). The
    edge x = 0 falls between the columns of the Regular(4) samples (the nearest are 1/16 of
    the image away), so every sample meets the triangle its pixel shows. A spherical light
    behind the camera, which no ray meets, keeps the kinds of the other scenes."""
    scene = Scene(PinholeCamera((0.0, 0.0, 5.0), (0.0, 0.0, 0.0), (0.0, 1.0, 0.0), d=1.0))
    scene.background = Float3(0.25)
    scene.shapes += [Triangle((0.0, -100.0, 0.0), (0.0, 100.0, 0.0), (-100.0, 0.0, 0.0), (1.0, 1.0, 1.0),
                              Emissive(2.0)),
                     Triangle((0.0, -100.0, 0.0), (0.0, 100.0, 0.0), (100.0, 0.0, 0.0), (1.0, 1.0, 1.0),
                              Emissive(3.0)),
                     Sphere((0.0, 0.0, 10.0), 0.5, (1.0, 1.0, 1.0), Emissive(1.0))]
    scene.lights += [AreaLight(shape) for shape in scene.shapes]
    scene.tracer = PathTrace()
    scene.sampler = Regular(4)
    return scene


def test_emission_is_seen_from_the_front_only(path):
    """The eye sees L_e where it looks at a light's front and nothing (0, not the
    background) at its back: an emissive surface ends the path either way."""
    scene = one_sided_scene()
    assert scene.shapes[0].normal_at(Float3(-1.0, 0.0, 0.0)).z > 0
    assert scene.shapes[1].normal_at(Float3(1.0, 0.0, 0.0)).z < 0
    image = render_on(path, scene, 8, 4, seed=1)
    tolerance = ROUNDING[path[2]]
    assert np.abs(image[:, :4] - 2.0).max() <= tolerance
    assert np.abs(image[:, 4:]).max() <= tolerance


# ---------------------------------------------------------------------------------------
# 2. The emitting box

# The cube [-1, 1]^3; vertex 4 ix + 2 iy + iz is (x, y, z) with ix, iy, iz = 0 for -1 and
# 1 for +1. Each face is two triangles wound so that (v1 - v0) x (v2 - v0) points into the
# box (test_box_faces_face_inward checks it): the front, which emits, is inside.
BOX_VERTICES = [[x, y, z] for x in (-1.0, 1.0) for y in (-1.0, 1.0) for z in (-1.0, 1.0)]
BOX_FACES = [(0, 3, 1), (0, 2, 3),      # x = -1
             (4, 7, 6), (4, 5, 7),      # x = +1
             (0, 5, 4), (0, 1, 5),      # y = -1
             (2, 7, 3), (2, 6, 7),      # y = +1
             (0, 6, 2), (0, 4, 6),      # z = -1
             (1, 7, 5), (1, 3, 7)]      # z = +1
BOX_RHO = Fraction(1, 2)
BOX_EMISSION = Fraction(1)


def box_scene(max_depth: int) -> Scene:
    """The camera at the centre of the box, looking at the middle of the face z = -1; with
    d = 1 the image spans [-1/2, 1/2]^2 of that face, so the points the eye sees are at
    least 1/2 from every edge (see test_box_mean_is_exact)."""
    scene = Scene(PinholeCamera((0.0, 0.0, 0.0), (0.0, 0.0, -1.0), (0.0, 1.0, 0.0), d=1.0))
    mesh = Mesh(BOX_VERTICES, BOX_FACES, (float(BOX_RHO),) * 3,
                material=Matte(ka=0.0, kd=1.0, emission=(float(BOX_EMISSION),) * 3))
    scene.shapes += mesh.triangles()
    scene.lights += [AreaLight(face) for face in scene.shapes]
    scene.tracer = PathTrace(max_depth=max_depth)
    return scene


def box_truth(max_depth: int) -> Fraction:
    """The expectation of a path of at most D = max_depth vertices inside the box.

    The eye sees a face from the front: e. At vertex k (k = 0 .. D-1) next-event
    estimation over all twelve faces estimates without bias the light reflected from the
    whole sphere of directions the closed box fills, integral of rho / pi * e * cos = rho e
    (a point's own face subtends no solid angle, and its samples give 0). The vertex adds
    throughput_k * rho * e. Vertex k + 1 exists if roulette kept the path at vertices
    0 .. k (probability q^(k+1), q = rho for a grey albedo) and k + 1 < D; the throughput
    is then (rho / q)^(k+1) = 1. So E[throughput_k] = rho^k for k < D, and the path's
    expectation is e + sum_{k=0}^{D-1} rho^k * rho e = e * sum_{k=0}^{D} rho^k."""
    return BOX_EMISSION * sum(BOX_RHO ** k for k in range(max_depth + 1))


@pytest.fixture(scope="module")
def box_scenes():
    return {depth: box_scene(depth) for depth in (1, 3, 64)}


def test_box_faces_face_inward():
    vertices = np.array(BOX_VERTICES)
    for face in BOX_FACES:
        v0, v1, v2 = vertices[list(face)]
        normal = np.cross(v1 - v0, v2 - v0)
        centroid = (v0 + v1 + v2) / 3
        assert np.dot(normal, -centroid) > 0, face        # points to the centre (0, 0, 0)
    assert len({frozenset(f) for f in BOX_FACES}) == 12


def test_box_truth():
    assert box_truth(1) == Fraction(3, 2)
    assert box_truth(3) == Fraction(15, 8)
    assert abs(box_truth(64) - 2) < Fraction(1, 2 ** 60)


@pytest.mark.parametrize("depth", [1, 3, 64])
def test_box_mean_is_exact(path, box_scenes, depth):
    """The mean against e * sum_{k<=D} rho^k.

    With D = 1 every vertex is one the eye sees, at least 1/2 from every edge: the light
    samples' geometry term is bounded, the path's value too, and the mean is within 3
    standard errors. From vertex 1 on, a vertex lands anywhere, also next to an edge,
    where the adjacent face is sampled at a small distance d: the estimate L_e A cos cos /
    d^2 has an infinite variance there (its tail falls as about t^(-3/2)), and the mean
    of such samples lies *below* its expectation by a few standard errors more often than a
    normal one (the rare large samples that make up for it are missing, and the sample
    standard error misses them too), while it lies above it only with a large sample,
    which widens its standard error with it. So for D > 1 the check is one-sided strict,
    mean <= truth + 3 SE, and below it allows 6 SE (over 300 seeds of these renders the
    lowest was -4.6 SE, the highest +2.4 SE). The smallest error the check is meant to
    catch, a vertex too many or too few (rho^D e), stays outside both bands (asserted)."""
    scene = box_scenes[depth]
    width, spp = (16, 8) if path[1] == "reference" else (64, 16)
    image = render_on(path, scene, width, spp, seed=5)
    mean, se = mean_and_standard_error(image)
    truth = float(box_truth(depth))
    assert se > 0.0
    below = Z if depth == 1 else 2 * Z
    assert truth - below * se <= mean <= truth + Z * se, (mean, truth, se)
    if depth < 64:      # a vertex too many or too few is outside either band
        assert float(BOX_RHO ** depth * BOX_EMISSION) > (below + Z) * se


def test_box_error_falls_as_one_over_sqrt_spp(path, box_scenes):
    """With one vertex (a finite variance, test_box_mean_is_exact). One sample per pixel
    goes through the pixel's centre; every eye ray has the same expectation, so that does
    not change the ratio."""
    width, spp = (16, 1) if path[1] == "reference" else (32, 16)
    ratio = rmse_ratio(path, box_scenes[1], float(box_truth(1)), width, spp, seeds=(31, 32))
    assert RATIO_BAND[0] < ratio < RATIO_BAND[1], ratio


# ---------------------------------------------------------------------------------------
# 3. Chi-square tests of the sampling maps

N = 40_000


@pytest.fixture(scope="module")
def uv():
    return np.random.default_rng(2024).random((N, 2))


def frame(n):
    """An orthonormal (t, b, n) of our own (not the code's), to bin directions about n."""
    n = np.asarray(n, dtype=float)
    a = np.array([1.0, 0.0, 0.0]) if abs(n[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    t = a - np.dot(a, n) * n
    t /= np.linalg.norm(t)
    return t, np.cross(n, t), n


def cosine_histogram(directions, n, bins=16):
    """Counts in cells of cos^2(theta) x phi about n, each of probability 1 / bins^2 under
    the density cos(theta) / pi (P(cos theta <= c) = c^2, phi uniform)."""
    t, b, n = frame(n)
    z = np.clip(directions @ n, 0.0, np.nextafter(1.0, 0.0))
    phi = (np.arctan2(directions @ b, directions @ t) / (2 * math.pi)) % 1.0
    observed, _, _ = np.histogram2d(z * z, phi, bins=bins, range=[[0, 1], [0, 1]])
    return observed, np.full((bins, bins), len(directions) / bins ** 2)


NORMALS = [(0.0, 0.0, 1.0), (0.0, 0.0, -1.0), (1.0, 0.0, 0.0),
           tuple(np.array([0.3, -0.8, 0.52]) / np.linalg.norm([0.3, -0.8, 0.52]))]


def at_normal(n: Float3) -> HitInfo:
    """A hit whose normal is n (all a BRDF's sample_f reads of it)."""
    sr = HitInfo()
    sr.normal = n
    return sr


def cosine_direction(n: Float3, u: float, v: float) -> Float3:
    """The direction of the diffuse bounce (Lambertian.sample_f)."""
    return Lambertian(kd=1.0, cd=Float3(1.0)).sample_f(at_normal(n), -n, u, v)[1]


@pytest.mark.parametrize("n", NORMALS, ids=["+z", "-z", "+x", "generic"])
def test_cosine_direction_has_density_cos_over_pi(uv, n):
    directions = np.array([tuple(cosine_direction(Float3(*n), u, v)) for u, v in uv])
    assert np.allclose(np.linalg.norm(directions, axis=1), 1.0, atol=1e-12)
    assert (directions @ np.array(n)).min() >= -1e-12             # the hemisphere of n
    assert chi_square_p(*cosine_histogram(directions, n)) > ALPHA


def test_lambertian_sample_f_returns_rho_over_pi_and_the_density_it_drew_with(uv):
    rho = Float3(0.25, 0.5, 0.75)
    n = Float3(*NORMALS[3])
    for u, v in uv[:500]:
        f, w_i, pdf = Lambertian(kd=1.0, cd=rho).sample_f(at_normal(n), n, u, v)
        assert tuple(f) == tuple(rho / math.pi)
        assert pdf == pytest.approx(dot(n, w_i) / math.pi, rel=1e-15) and pdf > 0.0


def test_a_skewed_cosine_direction_fails(uv):
    # u -> u^2 moves cos^2(theta) = 1 - u to 1 - u^2: the test sees it.
    n = NORMALS[3]
    directions = np.array([tuple(cosine_direction(Float3(*n), u * u, v)) for u, v in uv])
    assert chi_square_p(*cosine_histogram(directions, n)) < 1e-12


@pytest.mark.parametrize("n", NORMALS, ids=["+z", "-z", "+x", "generic"])
def test_numba_cosine_direction_is_the_lecture_layers(uv, n):
    from rtfgu.kernels.path_trace import cosine_direction as cosine_direction_numba

    for u, v in uv[:2000]:
        expected = np.array(tuple(cosine_direction(Float3(*n), u, v)))
        got64 = np.array(cosine_direction_numba(tuple(float(c) for c in n), float(u), float(v)))
        assert np.abs(got64 - expected).max() <= 1e-12
    for u, v in uv[:200]:
        expected = np.array(tuple(cosine_direction(Float3(*n), u, v)))
        got32 = np.array(cosine_direction_numba(tuple(np.float32(c) for c in n), np.float32(u),
                                                np.float32(v)), dtype=np.float64)
        assert np.abs(got32 - expected).max() <= 1e-5


def power_histogram(directions, axis, power, bins=16):
    """Counts in cells of cos^power(alpha) x phi about ``axis``, each of probability
    1 / bins^2 under the density (power / (2 pi)) cos^(power - 1)(alpha) on the hemisphere
    (P(cos alpha <= c) = c^power, phi uniform); cosine_histogram is power 2."""
    t, b, a = frame(axis)
    z = np.clip(directions @ a, 0.0, np.nextafter(1.0, 0.0))
    phi = (np.arctan2(directions @ b, directions @ t) / (2 * math.pi)) % 1.0
    observed, _, _ = np.histogram2d(z ** power, phi, bins=bins, range=[[0, 1], [0, 1]])
    return observed, np.full((bins, bins), len(directions) / bins ** 2)


def lobe_direction(w_r: Float3, shininess: float, u: float, v: float) -> Float3:
    """The direction GlossySpecular.sample_f draws about the mirror direction w_r: at a
    surface whose normal is not w_r (halfway between w_r and another direction), for the
    w_o that this normal mirrors into w_r."""
    n = normalize(w_r + normalize(Float3(0.3, 0.9, 0.2)))
    wo = reflect(n, w_r)
    return GlossySpecular(exp=shininess).sample_f(at_normal(n), wo, u, v)[1]


@pytest.mark.parametrize("shininess", [1.0, 20.0, 300.0])
@pytest.mark.parametrize("w_r", NORMALS[1:], ids=["-z", "+x", "generic"])
def test_glossy_lobe_direction_has_density_of_the_phong_lobe(uv, w_r, shininess):
    """GlossyReflector's sampled lobe: (s + 1) / (2 pi) cos^s(alpha) about the mirror direction."""
    directions = np.array([tuple(lobe_direction(Float3(*w_r), shininess, u, v)) for u, v in uv])
    assert np.allclose(np.linalg.norm(directions, axis=1), 1.0, atol=1e-12)
    assert chi_square_p(*power_histogram(directions, w_r, shininess + 1.0)) > ALPHA
    # the lobe of a neighbouring exponent is told apart
    assert chi_square_p(*power_histogram(directions, w_r, 1.25 * shininess + 1.0)) < 1e-12


def test_numba_glossy_lobe_direction_is_the_lecture_layers(uv):
    from rtfgu.kernels.glossy import lobe_direction as lobe_numba

    w_r = NORMALS[3]
    for u, v in uv[:2000]:
        expected = np.array(tuple(lobe_direction(Float3(*w_r), 20.0, u, v)))
        got = np.array(lobe_numba(tuple(float(c) for c in w_r), 20.0, float(u), float(v)))
        assert np.abs(got - expected).max() <= 1e-12


class GivenSample(Scene):
    """A scene whose lights draw the given point (u, v) of the unit square (Scene.light_sample),
    traced by PathTrace, a tracer that samples area lights."""

    def __init__(self):
        super().__init__()
        self.tracer = PathTrace()
        self.uv = (0.0, 0.0)

    def light_sample(self, light, sr) -> tuple:
        return self.uv


def light_sample(light, position: Float3, normal: Float3, u: float, v: float):
    """What a tracer that samples lights gets from ``light`` at a hit (position, normal) for
    the point (u, v): the direction get_direction draws, then incident (L G / pdf) and
    distance, as the slide's record (L_i, w_i, dist)."""
    from rtfgu.lights import LightSample

    scene = GivenSample()
    scene.uv = (u, v)
    sr = HitInfo(scene)
    sr.position, sr.normal = position, normal
    w_i = light.get_direction(sr)
    return LightSample(light.incident(sr), w_i, light.distance(sr))


@pytest.mark.parametrize("n", NORMALS, ids=["+z", "-z", "+x", "generic"])
def test_ambient_occluder_directions_are_uniform_on_the_hemisphere(uv, n):
    """AmbientOccluder: a direction uniform on the hemisphere of n (P(cos <= c) = c),
    L_i = 2 pi L, unbounded; and the numba twin gives the same."""
    from rtfgu import AmbientOccluder
    from rtfgu.kernels.lights import sample_ambient_occluder_area

    light = AmbientOccluder(0.5, (1.0, 0.5, 0.25))
    samples = [light_sample(light, Float3(0.0), Float3(*n), u, v) for u, v in uv]
    directions = np.array([tuple(sample.w_i) for sample in samples])
    assert all(sample.dist == math.inf for sample in samples)
    assert np.allclose(tuple(samples[0].L_i), (math.pi, math.pi / 2, math.pi / 4), rtol=1e-15)
    assert chi_square_p(*power_histogram(directions, n, 1.0)) > ALPHA
    assert chi_square_p(*power_histogram(directions, n, 2.0)) < 1e-12     # not cosine-weighted
    table = np.array([[0.5, 0.25, 0.125, 0.0]])
    for (u, v), direction in zip(uv[:500], directions[:500]):
        L_i, w_i, dist = sample_ambient_occluder_area(table, 0, (0.0, 0.0, 0.0), tuple(float(c) for c in n),
                                                      float(u), float(v))
        assert np.abs(np.array(w_i) - direction).max() <= 1e-12 and dist == math.inf


# The shapes of the area lights sampled below.
LIGHT_TRIANGLE = ((0.3, -1.0, 2.0), (2.0, 0.5, 1.0), (-1.0, 1.0, 0.5))
LIGHT_SPHERE = ((1.0, -2.0, 0.5), 1.5)


@pytest.fixture(scope="module")
def light_scene():
    scene = Scene(PinholeCamera((0.0, 0.0, 8.0), (0.0, 0.0, 0.0), (0.0, 1.0, 0.0)))
    scene.shapes.append(Triangle(*LIGHT_TRIANGLE, (1.0, 1.0, 1.0), Emissive(2.0, (1.0, 0.5, 0.25))))
    scene.shapes.append(Sphere(*LIGHT_SPHERE, (1.0, 1.0, 1.0), Emissive(3.0)))
    scene.lights += [AreaLight(shape) for shape in scene.shapes]
    return scene


def barycentric_cells(points, v0, v1, v2, k=8):
    """The k^2 cells of equal area that cut each edge into k: cell (i, j, upper) holds the
    points with floor(k b1) = i, floor(k b2) = j, and k (b1 + b2) - i - j >= 1 (upper)."""
    v0, v1, v2 = (np.array(v) for v in (v0, v1, v2))
    e0, e1 = v1 - v0, v2 - v0
    d = points - v0
    gram = np.array([[e0 @ e0, e0 @ e1], [e0 @ e1, e1 @ e1]])
    b1, b2 = np.linalg.solve(gram, np.stack([d @ e0, d @ e1])).clip(0.0, 1.0 - 1e-12)
    i, j = np.floor(k * b1).astype(int), np.floor(k * b2).astype(int)
    upper = (k * b1 - i + k * b2 - j) >= 1.0
    counts = {}
    for cell in zip(i, j, upper):
        counts[cell] = counts.get(cell, 0) + 1
    cells = [(i, j, False) for i in range(k) for j in range(k - i)] + \
            [(i, j, True) for i in range(k) for j in range(k - 1 - i)]
    assert len(cells) == k * k and set(counts) <= set(cells)
    return np.array([counts.get(c, 0) for c in cells]), np.full(k * k, len(points) / k ** 2)


def sphere_cells(points, center, radius, bins=16):
    """Cells equal in z and in phi: of equal area on the sphere (Archimedes)."""
    p = (points - np.array(center)) / radius
    z = np.clip(p[:, 2], -1.0, np.nextafter(1.0, 0.0))
    phi = (np.arctan2(p[:, 1], p[:, 0]) / (2 * math.pi)) % 1.0
    observed, _, _ = np.histogram2d(z, phi, bins=bins, range=[[-1, 1], [0, 1]])
    return observed, np.full((bins, bins), len(points) / bins ** 2)


def drawn_point(light, u, v) -> tuple:
    """The point of ``light`` that get_direction draws for (u, v), and its normal."""
    light_sample(light, Float3(0.0, 0.0, 8.0), Float3(0.0, 0.0, -1.0), u, v)
    return light.sample_point, light.light_normal


def test_triangle_light_points_are_uniform_by_area(light_scene, uv):
    light = light_scene.lights[0]
    samples = [drawn_point(light, u, v) for u, v in uv]
    points = np.array([tuple(p) for p, _ in samples])
    normal = np.cross(np.subtract(LIGHT_TRIANGLE[1], LIGHT_TRIANGLE[0]),
                      np.subtract(LIGHT_TRIANGLE[2], LIGHT_TRIANGLE[0]))
    normal /= np.linalg.norm(normal)
    assert np.abs((points - LIGHT_TRIANGLE[0]) @ normal).max() < 1e-12     # in the plane
    assert all(np.allclose(tuple(n), normal, atol=1e-12) for _, n in samples[:100])
    assert chi_square_p(*barycentric_cells(points, *LIGHT_TRIANGLE)) > ALPHA
    # A map that forgets the square root of u crowds the vertex v0: the test sees it.
    v0 = np.array(LIGHT_TRIANGLE[0])
    e0, e1 = np.subtract(LIGHT_TRIANGLE[1], v0), np.subtract(LIGHT_TRIANGLE[2], v0)
    skewed = v0 + (np.outer(uv[:, 1], e0) + np.outer(1 - uv[:, 1], e1)) * uv[:, :1]
    assert chi_square_p(*barycentric_cells(skewed, *LIGHT_TRIANGLE)) < 1e-12


def test_sphere_light_points_are_uniform_by_area(light_scene, uv):
    light = light_scene.lights[1]
    center, radius = LIGHT_SPHERE
    samples = [drawn_point(light, u, v) for u, v in uv]
    points = np.array([tuple(p) for p, _ in samples])
    normals = np.array([tuple(n) for _, n in samples])
    assert np.allclose(np.linalg.norm(points - center, axis=1), radius, atol=1e-12)
    assert np.allclose(normals, (points - center) / radius, atol=1e-12)
    assert chi_square_p(*sphere_cells(points, center, radius)) > ALPHA
    # Uniform in theta instead of in z crowds the poles: the test sees it.
    z, phi = np.cos(math.pi * uv[:, 0]), 2 * math.pi * uv[:, 1]
    s = np.sqrt(1 - z * z)
    skewed = np.array(center) + radius * np.stack([s * np.cos(phi), s * np.sin(phi), z], axis=1)
    assert chi_square_p(*sphere_cells(skewed, center, radius)) < 1e-12


def takes_normal(function) -> bool:
    """Whether a light sample takes the normal of the point it lights (after the position)."""
    return "normal" in inspect.signature(getattr(function, "py_func", function)).parameters


@pytest.mark.parametrize("j, pos", [(0, (1.5, 2.0, 4.0)), (1, (-2.0, 1.0, 3.0))],
                         ids=["triangle", "sphere"])
def test_numba_area_light_sample_is_the_lecture_layers(light_scene, uv, j, pos):
    """sample_area_light_area (numba) against the AreaLight a tracer that samples area lights
    asks (get_direction, then incident = L G / pdf and distance) for the same (u, v): L_i,
    w_i, dist and the point p' = pos + w_i dist, to 1e-12 in float64 (and 1e-5 relative in
    float32); the lecture layer's p' is the shape's sample(u, v)."""
    from rtfgu.kernels.lights import sample_area_light_area

    light = light_scene.lights[j]
    p = Float3(*pos)
    # The normal of the lit point: toward the light's centre, so that the light is above it.
    centre = np.mean(LIGHT_TRIANGLE, axis=0) if j == 0 else np.array(LIGHT_SPHERE[0])
    n = (centre - pos) / np.linalg.norm(centre - pos)
    normal = Float3(*n)

    def lecture(u, v):
        return light_sample(light, p, normal, u, v)

    def numba(table, dtype, u, v):
        at, facing = tuple(dtype(c) for c in pos), tuple(dtype(c) for c in n)
        if takes_normal(sample_area_light_area):
            return sample_area_light_area(table, j, at, facing, dtype(u), dtype(v))
        return sample_area_light_area(table, j, at, dtype(u), dtype(v))

    table64 = compile_scene(light_scene, "float64").lights["area_light"]
    table32 = compile_scene(light_scene, "float32").lights["area_light"]
    lit = 0
    for k, (u, v) in enumerate(uv[:2000]):
        expected = lecture(u, v)
        scale = max(1.0, max(tuple(expected.L_i)))
        L_i, w_i, dist = numba(table64, float, u, v)
        assert np.abs(np.subtract(L_i, tuple(expected.L_i))).max() <= 1e-12 * scale
        assert np.abs(np.subtract(w_i, tuple(expected.w_i))).max() <= 1e-12
        assert abs(dist - expected.dist) <= 1e-12
        point = light.shape.sample(u, v)
        assert (light.sample_point - point).length() <= 1e-12     # the point the light drew
        assert (p + expected.w_i * expected.dist - point).length() <= 1e-12
        assert np.abs(np.add(pos, np.multiply(w_i, dist)) - tuple(point)).max() <= 1e-12
        lit += max(tuple(expected.L_i)) > 0
        if k < 200:
            L32, w32, d32 = numba(table32, np.float32, u, v)
            assert np.abs(np.subtract(L32, tuple(expected.L_i))).max() <= 1e-5 * scale
            assert abs(d32 - expected.dist) <= 1e-5 * expected.dist
    # pos is in front of the whole triangle; of the sphere it sees a cap, and the rest gives 0.
    assert lit == 2000 if j == 0 else 0 < lit < 2000


# ---------------------------------------------------------------------------------------
# 4. The direct light of an area light against the exact irradiance

FLOOR_RHO = 0.6
FLOOR_SIDE = 4.0


def floor_triangles():
    """The square [-4, 4]^2 of the plane y = 0, facing up, diffuse with albedo 0.6."""
    s = FLOOR_SIDE
    color = (FLOOR_RHO,) * 3
    return [Triangle((-s, 0.0, -s), (-s, 0.0, s), (s, 0.0, s), color, path_matte()),
            Triangle((-s, 0.0, -s), (s, 0.0, s), (s, 0.0, -s), color, path_matte())]


SPHERE_LIGHT = dict(center=(0.0, 2.0, 0.0), radius=0.5, L_e=3.0)
SQUARE_LIGHT = dict(height=1.0, half_side=0.5, L_e=2.0)


def sphere_irradiance(h, r, L_e):
    """E at a point facing the centre of a sphere at distance h (the sphere wholly above
    the point's horizon, h > r): L_e pi (r / h)^2."""
    return L_e * math.pi * (r / h) ** 2


def square_irradiance(h, a, L_e):
    """E at a point facing a parallel square of half side a at distance h on its axis: four
    rectangles a x a with a corner above the point, each of form factor (A = B = a / h)
    F = 1 / (2 pi) [A / sqrt(1 + A^2) atan(B / sqrt(1 + A^2))
                    + B / sqrt(1 + B^2) atan(A / sqrt(1 + B^2))],
    E = 4 pi L_e F."""
    A = B = a / h
    F = (A / math.sqrt(1 + A * A) * math.atan(B / math.sqrt(1 + A * A))
         + B / math.sqrt(1 + B * B) * math.atan(A / math.sqrt(1 + B * B))) / (2 * math.pi)
    return 4 * math.pi * L_e * F


def test_the_irradiance_formulas():
    """The closed forms against quadratures: the square's against a midpoint rule of
    E = int L_e cos(theta) cos(theta') / d^2 dA over the square (and a far square against
    L_e A / h^2), the sphere's against the integral over the cone it fills."""
    h, a, L_e = SQUARE_LIGHT["height"], SQUARE_LIGHT["half_side"], SQUARE_LIGHT["L_e"]
    m = 800
    x = (np.arange(m) + 0.5) / m * 2 * a - a
    X, Y = np.meshgrid(x, x)
    d2 = X ** 2 + Y ** 2 + h * h
    quadrature = L_e * np.sum(h * h / d2 ** 2) * (2 * a / m) ** 2
    assert abs(square_irradiance(h, a, L_e) - quadrature) < 1e-5
    assert abs(square_irradiance(1000.0, 1.0, 1.0) / (4.0 / 1e6) - 1) < 1e-5
    # The sphere: E = L_e * solid angle of the cap seen, cosine weighted. For a point facing
    # the centre, integrate over the cap's polar angle alpha <= asin(r / h) about the axis:
    # E = L_e int 2 pi cos(alpha) sin(alpha) d alpha = L_e pi sin^2(alpha_max).
    r, hs = SPHERE_LIGHT["radius"], SPHERE_LIGHT["center"][1]
    alpha = np.linspace(0.0, math.asin(r / hs), 200_001)
    integrate = np.trapezoid if hasattr(np, "trapezoid") else np.trapz
    cone = integrate(2 * math.pi * np.cos(alpha) * np.sin(alpha), alpha)
    assert abs(sphere_irradiance(hs, r, 1.0) - cone) < 1e-9


def irradiance_scene(light: str) -> Scene:
    """The floor and one area light above the origin, seen from the side: the camera's view
    (d = 1000: the image spans 1/1000 rad, seen from 3.3 away at 22 degrees above the
    floor) covers only the points within 0.005 of the origin, where E differs from E(0) by
    less than 1.5 (0.005 / h)^2 < 4e-5 relative, far below the standard errors (about 1 %)
    the check allows. One light, no bounce
    (max_depth 1), a black environment: the pixel is rho / pi * E."""
    scene = Scene(PinholeCamera((3.0, 1.2, 0.4), (0.0, 0.0, 0.0), (0.0, 1.0, 0.0), d=1000.0))
    scene.shapes += floor_triangles()
    if light == "sphere":
        c, r = SPHERE_LIGHT["center"], SPHERE_LIGHT["radius"]
        scene.shapes.append(Sphere(c, r, (1.0, 1.0, 1.0), Emissive(SPHERE_LIGHT["L_e"])))
    else:
        h, a = SQUARE_LIGHT["height"], SQUARE_LIGHT["half_side"]
        # Wound so that (v1 - v0) x (v2 - v0) points down (-y), to the floor.
        corners = [(-a, h, -a), (a, h, -a), (a, h, a), (-a, h, a)]
        for v in ((corners[0], corners[1], corners[2]), (corners[0], corners[2], corners[3])):
            scene.shapes.append(Triangle(*v, (1.0, 1.0, 1.0), Emissive(SQUARE_LIGHT["L_e"])))
        # A sphere under the floor, which no ray meets, keeps the scene's kinds those of the
        # other scenes (spheres, triangles, area lights): numba compiles no other kernel.
        scene.shapes.append(Sphere((0.0, -5.0, 0.0), 0.1, (0.5, 0.5, 0.5), path_matte()))
    scene.lights += [AreaLight(s) for s in scene.shapes if s.material.emission.x > 0]
    scene.tracer = PathTrace(max_depth=1)
    return scene


@pytest.fixture(scope="module")
def irradiance_scenes():
    return {light: irradiance_scene(light) for light in ("sphere", "square")}


@pytest.mark.parametrize("light", ["sphere", "square"])
def test_area_light_gives_the_exact_irradiance(path, irradiance_scenes, light):
    scene = irradiance_scenes[light]
    for shape in scene.shapes[:2]:                   # the floor faces up
        assert shape.normal_at(Float3(0.0)).y > 0
    if light == "sphere":
        E = sphere_irradiance(SPHERE_LIGHT["center"][1], SPHERE_LIGHT["radius"], SPHERE_LIGHT["L_e"])
    else:
        assert scene.shapes[2].normal_at(Float3(0.0, 1.0, 0.0)).y < 0
        E = square_irradiance(SQUARE_LIGHT["height"], SQUARE_LIGHT["half_side"], SQUARE_LIGHT["L_e"])
    truth = FLOOR_RHO / math.pi * E
    width, spp = (16, 64) if path[1] == "reference" else (32, 64)
    image = render_on(path, scene, width, spp, seed=7)
    mean, se = mean_and_standard_error(image)
    assert se > 0.0
    assert abs(mean - truth) <= Z * se, (mean, truth, se)
    # The check is sharp: 3 standard errors are a few per cent of the truth.
    assert Z * se < 0.05 * truth


# ---------------------------------------------------------------------------------------
# 5. Bad input

def lambertian_sphere(color, emission=None):
    return Sphere((0.0, 0.0, 0.0), 1.0, color, Matte(ka=0.0, kd=1.0, emission=emission))


def small_scene(*shapes, lights=()):
    scene = Scene(PinholeCamera((0.0, 0.0, 5.0), (0.0, 0.0, 0.0), (0.0, 1.0, 0.0)))
    scene.shapes += shapes
    scene.lights += lights
    scene.tracer = PathTrace()
    return scene


@pytest.mark.parametrize("make, field", [
    (lambda: Matte(ka=0.0, kd=1.0, emission=(-1.0, 0.0, 0.0)), "Matte.emission"),
    (lambda: Emissive(-1.0), "Emissive.ls"),
    (lambda: PathTrace(max_depth=0), "PathTrace.max_depth"),
    (lambda: PathTrace(max_depth=1.5), "PathTrace.max_depth"),
    (lambda: PathTrace(max_depth=True), "PathTrace.max_depth"),
    (lambda: PathTrace(max_depth=1025), "PathTrace.max_depth"),
    (lambda: AreaLight(Plane((0.0, 0.0, 0.0), (0.0, 1.0, 0.0), (1.0, 1.0, 1.0), Emissive(1.0))),
     "AreaLight.shape"),
    (lambda: AreaLight(lambertian_sphere((0.5, 0.5, 0.5))), "AreaLight.shape"),
], ids=["negative emission", "negative ls", "depth 0", "depth 1.5", "depth True", "depth 1025",
        "plane light", "dark light"])
def test_bad_arguments_name_the_field(make, field):
    with pytest.raises(ValueError, match=re.escape(field)):
        make()


def test_a_light_of_a_dark_shape_says_emission():
    with pytest.raises(ValueError, match="emission"):
        AreaLight(lambertian_sphere((0.5, 0.5, 0.5)))


@pytest.mark.parametrize("scene, field", [
    (lambda: small_scene(Sphere((0.0, 3.0, 0.0), 0.5, (1.0, 1.0, 1.0), path_matte()),
                         lambertian_sphere((0.2, 1.5, 0.2))), "Scene.shapes[1].material (Matte)"),
    (lambda: small_scene(lambertian_sphere((0.5, 0.5, 0.5)),
                         Sphere((0.0, 3.0, 0.0), 0.5, (1.0, 1.0, 1.0), Emissive(1.0))),
     "Scene.shapes[1]"),
], ids=["albedo above 1", "emitter without AreaLight"])
def test_scenes_path_tracing_refuses_name_the_field(path, scene, field):
    s = scene()
    with pytest.raises(ValueError, match=re.escape(field)) as error:
        render_on(path, s, 2, 1, seed=0)
    if field == "Scene.shapes[1]":
        assert "AreaLight" in str(error.value)
    else:
        assert "albedo" in str(error.value)


def test_an_emitter_with_its_area_light_is_accepted():
    emitter = Sphere((0.0, 3.0, 0.0), 0.5, (1.0, 1.0, 1.0), Emissive(1.0))
    scene = small_scene(lambertian_sphere((0.5, 0.5, 0.5)), emitter, lights=[AreaLight(emitter)])
    scene.validate()


def degenerate_scene() -> Scene:
    """Shading points on a light's plane and edge, and a light touching the floor.

    The floor (y = 0, z <= 0), an emitting panel in the floor's own plane next to it
    (z >= 0, facing up), a triangle light standing on the floor's edge z = 0 in the plane
    z = 0 (facing -z, over the floor), and a spherical light resting on the floor. The
    camera looks straight down on the origin: the scene's sampler is Regular(9), whose
    middle point is a pixel's centre, and with an odd width that sample of the middle pixel
    goes exactly along the standing light's plane to the point the floor, the panel and
    the standing light share."""
    scene = Scene(PinholeCamera((0.0, 3.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, -1.0), d=0.5))
    grey, white = (0.5, 0.5, 0.5), (1.0, 1.0, 1.0)
    scene.shapes += [
        Triangle((-2.0, 0.0, -2.0), (-2.0, 0.0, 0.0), (2.0, 0.0, 0.0), grey, path_matte()),
        Triangle((-2.0, 0.0, -2.0), (2.0, 0.0, 0.0), (2.0, 0.0, -2.0), grey, path_matte()),
        Triangle((-1.0, 0.0, 0.0), (-1.0, 0.0, 1.0), (1.0, 0.0, 0.0), white, Emissive(2.0)),     # panel
        Triangle((-1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (1.0, 0.0, 0.0), white, Emissive(3.0)),  # standing
        Sphere((-1.0, 0.3, -1.0), 0.3, white, Emissive(1.0))]
    scene.lights += [AreaLight(s) for s in scene.shapes[2:]]
    scene.tracer = PathTrace(max_depth=8)
    scene.sampler = Regular(9)
    return scene


def test_degenerate_scene_is_as_described():
    scene = degenerate_scene()
    assert scene.shapes[0].normal_at(Float3(0.0)).y > 0 and scene.shapes[1].normal_at(Float3(0.0)).y > 0
    assert scene.shapes[2].normal_at(Float3(0.0)).y > 0          # the panel faces up
    assert scene.shapes[3].normal_at(Float3(0.0)).z < 0          # the standing light faces the floor
    assert scene.sampler.samples[4] == (0.5, 0.5)         # the middle pixel's centre
    assert 2 * (4 + 0.5) / 9 - 1 == 0.0
    ray = scene.camera.gen_ray(0.0, 0.0)
    assert tuple(ray.direction) == (0.0, -1.0, 0.0)


@pytest.mark.parametrize("seed", [1, 2])
def test_shading_points_on_a_lights_plane_give_finite_pixels(path, seed):
    image = render_on(path, degenerate_scene(), 9, 9, seed=seed)
    assert np.all(np.isfinite(image)) and image.min() >= 0.0
    assert image.max() > 0.0


# ---------------------------------------------------------------------------------------
# 6. Parity and seeds

def parity_scene() -> Scene:
    """A diffuse floor, a triangle light facing down, a spherical light, a mirror sphere
    and a diffuse sphere."""
    scene = Scene(PinholeCamera((0.0, 1.0, 3.5), (0.0, 0.5, 0.0), (0.0, 1.0, 0.0), d=1.0))
    scene.background = Float3(0.05, 0.05, 0.1)
    floor = floor_triangles()
    for t in floor:
        t.color = Float3(0.7, 0.6, 0.5)
    scene.shapes += floor
    scene.shapes.append(Triangle((-0.5, 1.8, -0.5), (0.5, 1.8, -0.5), (0.0, 1.8, 0.5), (1.0, 1.0, 1.0),
                                 Emissive(4.0)))
    scene.shapes.append(Sphere((1.0, 1.2, -0.5), 0.25, (1.0, 1.0, 1.0), Emissive(2.0, (1.0, 0.8, 0.6))))
    scene.shapes.append(Sphere((-0.5, 0.5, 0.0), 0.5, (0.9, 0.9, 0.9), Reflective()))
    scene.shapes.append(Sphere((0.6, 0.3, 0.4), 0.3, (0.2, 0.5, 0.8), path_matte()))
    scene.lights += [AreaLight(scene.shapes[2]), AreaLight(scene.shapes[3])]
    scene.tracer = PathTrace(max_depth=16)
    return scene


@pytest.fixture(scope="module")
def parity():
    scene = parity_scene()
    return scene, render(scene, 8, 8, "reference", spp=4, seed=9)


def test_parity_scene_faces_its_light_down():
    assert parity_scene().shapes[2].normal_at(Float3(0.0, 1.8, 0.0)).y < 0


def test_numba_float64_is_the_reference(parity):
    scene, reference = parity
    assert reference.max() > 0.1                    # lit, not black
    numba = render(scene, 8, 8, "numba", "float64", spp=4, seed=9)
    assert np.abs(numba - reference).max() <= 1e-9


def test_numba_float32_is_close_to_the_reference(parity):
    scene, reference = parity
    numba = render(scene, 8, 8, "numba", "float32", spp=4, seed=9)
    close = np.abs(to_8bit(numba).astype(int) - to_8bit(reference).astype(int)) <= 2
    assert close.mean() >= 0.99, close.mean()


def test_the_same_seed_gives_the_same_image_and_another_seed_another(path, parity):
    scene, _ = parity
    first = render_on(path, scene, 8, 4, seed=9)
    assert np.array_equal(first, render_on(path, scene, 8, 4, seed=9))
    assert not np.array_equal(first, render_on(path, scene, 8, 4, seed=10))


# --- a rectangle as an area light (Suffern ch. 18.6) ---------------------------------------

def rectangle_lamp_scene(tracer):
    """A Matte floor and sphere under a rectangular lamp facing down (a x b = -y)."""
    scene = Scene(PinholeCamera((0.0, 2.0, 5.0), (0.0, 0.5, 0.0), (0.0, 1.0, 0.0), d=1.5))
    scene.shapes.append(Plane((0.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.8, 0.8, 0.8), Matte()))
    lamp = Rectangle((-0.5, 2.0, -0.5), (1.0, 0.0, 0.0), (0.0, 0.0, 1.0), (1.0, 1.0, 1.0), Emissive(3.0))
    scene.shapes.append(lamp)
    scene.shapes.append(Sphere((0.0, 0.5, 0.0), 0.5, (0.2, 0.4, 0.8), Matte()))
    scene.lights.append(AreaLight(lamp))
    scene.tracer = AreaLighting() if tracer == "area_lighting" else PathTrace()
    return scene


def test_a_rectangle_samples_uniformly_with_pdf_one_over_its_area():
    lamp = Rectangle((1.0, 2.0, 3.0), (0.0, 0.0, 2.0), (0.5, 0.0, 0.0), (1.0, 1.0, 1.0), Emissive(1.0))
    assert lamp.area == 1.0 and lamp.pdf() == 1.0 and lamp.get_normal() == Float3(0.0, 1.0, 0.0)
    rng = np.random.default_rng(3)
    points = np.array([tuple(lamp.sample(u, v)) for u, v in rng.random((4000, 2))])
    assert np.all(points[:, 1] == 2.0)
    assert points[:, 0].min() >= 1.0 and points[:, 0].max() <= 1.5
    assert points[:, 2].min() >= 3.0 and points[:, 2].max() <= 5.0
    # uniform by area: the mean is the centre, each half holds half the points
    assert np.abs(points.mean(axis=0) - (1.25, 2.0, 4.0)).max() < 0.03
    assert abs(np.mean(points[:, 2] < 4.0) - 0.5) < 0.03


@pytest.mark.parametrize("tracer", ["area_lighting", "path_trace"])
def test_a_rectangle_area_light_on_every_path(path, tracer):
    """The lamp lights the floor and the sphere on every path as in the lecture layer: float64
    numba to the bit, float32 within 1/255."""
    scene = rectangle_lamp_scene(tracer)
    reference = render_on(PATHS[0], scene, 16, 4, seed=2)
    assert reference.max() > 0.1   # the lamp is seen and lights what is below it
    image = render_on(path, scene, 16, 4, seed=2)
    if path[2] == "float64":
        assert np.array_equal(image, reference)
    else:
        assert np.abs(image - reference).max() < 1 / 255
