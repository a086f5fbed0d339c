"""The lecture layer in Suffern's classes: BRDFs and BTDFs, materials built from them, lights
with the book's methods, and tracers (rtfgu/brdfs, btdfs, materials, lights, tracers).

* every class has the book's methods and setters;
* a scene built the book's way (Matte with set_kd and set_cd, a PointLight with set_ls,
  Whitted) renders on every path with the parity of the homework scenes;
* Whitted sends a transparent surface's reflected *and* transmitted rays, RayCast none;
* AreaLighting's estimate of the light of a triangle lamp has the exact irradiance (Lambert's
  polygon formula) as its mean; GlobalTrace and PathTrace have the same mean;
* samplers set on lights change the draws but not the mean;
* bad input names the class and the field; the flat paths refuse what they do not model yet,
  naming the field.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

import rtfgu
from rtfgu import (Ambient, AmbientOccluder, AreaLight, AreaLighting, Dielectric, Directional, Emissive, Float3,
                   GlobalTrace, GlossyReflector, GlossySpecular, Lambertian, Material, Matte, MultiJittered,
                   PathTrace, PerfectSpecular, PerfectTransmitter, Phong, PinholeCamera, Plane, PointLight, Ray,
                   RayCast, Reflective, Scene, Sphere, Transparent, Triangle, Whitted, dot, normalize)
from rtfgu.brdfs import FresnelReflector
from rtfgu.btdfs import FresnelTransmitter
from rtfgu.image import to_8bit
from rtfgu.renderer import trace
from wgsl_support import wgpu_device  # noqa: F401  (fixture)

BOOK_METHODS = [
    (Lambertian, ("f", "sample_f", "rho", "set_kd", "set_cd", "set_sampler")),
    (GlossySpecular, ("f", "sample_f", "rho", "set_ks", "set_cs", "set_exp", "set_sampler")),
    (PerfectSpecular, ("f", "sample_f", "rho", "set_kr", "set_cr")),
    (FresnelReflector, ("f", "sample_f", "rho", "set_ior")),
    (PerfectTransmitter, ("f", "sample_f", "tir", "set_kt", "set_ior")),
    (FresnelTransmitter, ("f", "sample_f", "tir", "set_ior")),
    (Matte, ("shade", "area_light_shade", "path_shade", "global_shade", "get_Le", "set_ka", "set_kd", "set_cd")),
    (Phong, ("shade", "set_ka", "set_kd", "set_cd", "set_ks", "set_cs", "set_exp")),
    (Reflective, ("shade", "path_shade", "set_kr", "set_cr", "set_ks", "set_exp")),
    (GlossyReflector, ("shade", "path_shade", "set_ks", "set_exp")),
    (Transparent, ("shade", "path_shade", "set_kr", "set_kt", "set_ior")),
    (Dielectric, ("shade", "path_shade", "set_ior", "set_absorption")),
    (Emissive, ("shade", "path_shade", "get_Le", "set_ls", "set_ce")),
    (Ambient, ("get_direction", "L", "G", "pdf", "in_shadow", "casts_shadows", "set_ls", "set_color")),
    (PointLight, ("get_direction", "L", "G", "pdf", "in_shadow", "casts_shadows", "set_shadows", "set_ls",
                  "set_color", "set_location")),
    (Directional, ("get_direction", "L", "G", "pdf", "in_shadow", "set_direction", "set_ls")),
    (AreaLight, ("get_direction", "L", "G", "pdf", "in_shadow", "set_sampler")),
    (AmbientOccluder, ("get_direction", "L", "pdf", "set_sampler")),
    (RayCast, ("trace_ray",)), (Whitted, ("trace_ray",)), (AreaLighting, ("trace_ray",)),
    (PathTrace, ("trace_ray",)), (GlobalTrace, ("trace_ray",)),
]


@pytest.mark.parametrize("cls,methods", BOOK_METHODS, ids=[c.__name__ for c, _ in BOOK_METHODS])
def test_every_class_has_the_books_methods(cls, methods):
    missing = [m for m in methods if not callable(getattr(cls, m, None))]
    assert not missing, "%s lacks %s" % (cls.__name__, ", ".join(missing))


def test_the_hierarchy_is_the_books():
    assert issubclass(Phong, Matte) and issubclass(Reflective, Phong) and issubclass(Transparent, Reflective)
    assert issubclass(GlossyReflector, Phong) and issubclass(Dielectric, Phong)
    phong = Phong()
    assert isinstance(phong.ambient_brdf, Lambertian) and isinstance(phong.diffuse_brdf, Lambertian)
    assert isinstance(phong.specular_brdf, GlossySpecular)
    assert isinstance(Reflective().reflective_brdf, PerfectSpecular)
    assert isinstance(Transparent().specular_btdf, PerfectTransmitter)
    glass = Dielectric()
    assert isinstance(glass.fresnel_brdf, FresnelReflector) and isinstance(glass.fresnel_btdf, FresnelTransmitter)


def book_scene(tracer=None) -> Scene:
    """Suffern's way: materials from setters, a point light with set_ls, the tracer named."""
    scene = Scene(PinholeCamera(Float3(0.0, 1.0, 4.0), Float3(0.0, 0.4, 0.0), Float3(0.0, 1.0, 0.0), d=1.4))
    scene.background = Float3(0.05, 0.1, 0.2)
    scene.ambient_light = Ambient(0.5)
    floor = Matte()
    floor.set_ka(0.25)
    floor.set_kd(0.65)
    floor.set_cd(Float3(0.7, 0.7, 0.6))
    scene.shapes.append(Plane(Float3(0.0), Float3(0.0, 1.0, 0.0), Float3(1.0), floor))
    ball = Phong()
    ball.set_ka(0.2)
    ball.set_kd(0.6)
    ball.set_cd(Float3(0.8, 0.2, 0.1))
    ball.set_ks(0.5)
    ball.set_cs(Float3(1.0, 1.0, 1.0))
    ball.set_exp(20.0)
    scene.shapes.append(Sphere(Float3(-0.5, 0.5, 0.0), 0.5, Float3(1.0), ball))
    scene.shapes.append(Sphere(Float3(0.7, 0.4, -0.3), 0.4, Float3(0.0), Reflective()))
    light = PointLight()
    light.set_location(Float3(2.0, 4.0, 3.0))
    light.set_color(Float3(1.0, 0.95, 0.9))
    light.set_ls(20.0)
    scene.lights.append(light)
    scene.tracer = Whitted() if tracer is None else tracer
    return scene


def test_a_scene_built_the_books_way_renders_alike_on_every_path():
    reference = rtfgu.render(book_scene(), 24, 24)
    numba64 = rtfgu.render(book_scene(), 24, 24, backend="numba", precision="float64")
    assert np.array_equal(reference, numba64), float(np.max(np.abs(reference - numba64)))
    numba32 = rtfgu.render(book_scene(), 24, 24, backend="numba", precision="float32")
    close = np.abs(to_8bit(numba32).astype(int) - to_8bit(reference).astype(int)) <= 1
    assert close.mean() >= 0.999
    # the setters reach the flat layout: another kd is another image on the numba path too
    other = book_scene()
    other.shapes[0].material.set_kd(0.3)
    assert not np.array_equal(rtfgu.render(other, 24, 24, backend="numba", precision="float64"), numba64)


def test_a_scene_built_the_books_way_renders_alike_in_wgsl(wgpu_device):
    reference = rtfgu.render(book_scene(), 24, 24)
    wgsl = rtfgu.render(book_scene(), 24, 24, backend="wgpu")
    close = np.abs(to_8bit(wgsl).astype(int) - to_8bit(reference).astype(int)) <= 1
    assert close.mean() >= 0.999


# The book's two materials that send weighted rays: a Reflective with a Phong part, and a
# Transparent that also reflects (two rays at every hit, a stack of rays on the flat paths).
TWO_RAY_MATERIALS = {
    "reflective_with_phong": lambda: Reflective(kr=0.6, cr=(1.0, 0.9, 0.7), ka=0.2, kd=0.4,
                                                cd=Float3(0.2, 0.5, 0.9), ks=0.3, exp=40.0),
    "transparent_reflecting": lambda: Transparent(ior=1.5, kr=0.2, kt=0.8, ks=0.3, exp=200.0),
    "tinted_mirror": lambda: Reflective(kr=0.8, cr=(1.0, 0.6, 0.3)),
}


def two_ray_scene(material) -> Scene:
    scene = book_scene()
    scene.shapes[2].material = material
    # a second glass ball behind, so that rays inside rays meet glass again
    scene.shapes.append(Sphere(Float3(0.1, 0.3, -1.2), 0.3, Float3(1.0), Transparent(ior=1.3, kr=0.3, kt=0.7)))
    return scene


@pytest.mark.parametrize("name", sorted(TWO_RAY_MATERIALS))
def test_weighted_and_second_rays_render_alike_on_the_numba_path(name):
    """numba follows the reflected ray after the refracted one from a stack: the lecture
    layer's sum in another order, equal to rounding in float64; float32 within 1/255."""
    reference = rtfgu.render(two_ray_scene(TWO_RAY_MATERIALS[name]()), 24, 24)
    numba64 = rtfgu.render(two_ray_scene(TWO_RAY_MATERIALS[name]()), 24, 24, backend="numba")
    assert np.abs(numba64 - reference).max() <= 1e-12 * max(1.0, reference.max())
    numba32 = rtfgu.render(two_ray_scene(TWO_RAY_MATERIALS[name]()), 24, 24, backend="numba", precision="float32")
    close = np.abs(to_8bit(numba32).astype(int) - to_8bit(reference).astype(int)) <= 1
    assert close.mean() >= 0.999
    # the weights matter: the same sphere as the 02562 mirror is another image
    plain = book_scene()
    assert not np.allclose(rtfgu.render(plain, 24, 24, backend="numba"), numba64)


@pytest.mark.parametrize("name", sorted(TWO_RAY_MATERIALS))
def test_weighted_and_second_rays_render_alike_in_wgsl(wgpu_device, name):
    reference = rtfgu.render(two_ray_scene(TWO_RAY_MATERIALS[name]()), 24, 24)
    wgsl = rtfgu.render(two_ray_scene(TWO_RAY_MATERIALS[name]()), 24, 24, backend="wgpu")
    close = np.abs(to_8bit(wgsl).astype(int) - to_8bit(reference).astype(int)) <= 1
    assert close.mean() >= 0.999


def test_the_second_ray_is_traced_only_where_a_material_sends_one():
    """The stack of rays is compiled into a program only for a scene with a Transparent that
    reflects: the 02562 scenes pay nothing for it."""
    from rtfgu.layout import compile_scene
    from rtfgu.wgsl.assemble import assemble

    assert "two_rays" not in compile_scene(book_scene()).features
    both = compile_scene(two_ray_scene(TWO_RAY_MATERIALS["transparent_reflecting"]()))
    assert "two_rays" in both.features
    assert "WaitingRay" in assemble(both).source
    assert "WaitingRay" not in assemble(compile_scene(book_scene())).source


class Recording(Whitted):
    """Whitted, noting every ray it is asked to trace with its depth."""

    def __init__(self, max_depth=10):
        super().__init__(max_depth)
        self.rays = []

    def trace_ray(self, ray, depth=0):
        self.rays.append((depth, ray.origin, ray.direction))
        return super().trace_ray(ray, depth)


def glass_scene(material, tracer) -> Scene:
    scene = Scene(PinholeCamera(Float3(0.0, 0.0, 3.0), Float3(0.0), Float3(0.0, 1.0, 0.0), d=2.0))
    scene.background = Float3(0.2, 0.4, 0.8)
    scene.shapes.append(Sphere(Float3(0.0), 1.0, Float3(0.0), material))
    scene.tracer = tracer
    return scene


def test_whitted_sends_a_transparent_surfaces_reflected_and_transmitted_rays():
    eye = Ray(Float3(0.3, 0.2, 3.0), normalize(Float3(-0.1, -0.05, -1.0)))
    tracer = Recording(max_depth=2)
    scene = glass_scene(Transparent(ior=1.5, kr=0.25, kt=0.75), tracer)
    L = trace(scene, eye)
    children = [(o, d) for depth, o, d in tracer.rays if depth == 1]
    assert len(children) == 2, tracer.rays
    hit_point = children[0][0]
    n = normalize(hit_point)
    d = eye.direction
    mirror = d - n * (2.0 * dot(d, n))
    cos_i = -dot(d, n)
    eta = 1.0 / 1.5
    cos_t = math.sqrt(1.0 - eta * eta * (1.0 - cos_i * cos_i))
    snell = d * eta + n * (eta * cos_i - cos_t)
    for got, want in zip([c[1] for c in children], (mirror, snell)):
        assert all(abs(a - b) < 1e-12 for a, b in zip(got, want))
    # at max_depth 2 the reflected ray sees the sky and the transmitted one is cut (black)
    assert all(abs(a - 0.25 * b) < 1e-15 for a, b in zip(L, scene.background))


def test_ray_cast_follows_no_secondary_ray():
    tracer = RayCast()
    scene = glass_scene(Reflective(), tracer)
    L = trace(scene, Ray(Float3(0.0, 0.0, 3.0), Float3(0.0, 0.0, -1.0)))
    assert (L.x, L.y, L.z) == (0.0, 0.0, 0.0)
    assert tracer.max_depth == 1


def polygon_irradiance(x, n, vertices, L_e):
    """Lambert's formula: the irradiance at x (normal n) from a polygon of radiance L_e,
    E = L_e / 2 |sum_i Theta_i (n . Gamma_i)| (Arvo, "Irradiance Tensors", 1995)."""
    total = 0.0
    k = len(vertices)
    for i in range(k):
        a = normalize(vertices[i] - x)
        b = normalize(vertices[(i + 1) % k] - x)
        theta = math.acos(max(-1.0, min(1.0, dot(a, b))))
        total += theta * dot(n, normalize(rtfgu.cross(a, b)))
    return 0.5 * L_e * abs(total)


def lamp_scene(tracer, shadows=True):
    scene = Scene(PinholeCamera(Float3(0.0, 2.0, 4.0), Float3(0.0), Float3(0.0, 1.0, 0.0)))
    scene.ambient_light = Ambient(0.0)
    scene.shapes.append(Plane(Float3(0.0), Float3(0.0, 1.0, 0.0), Float3(0.8, 0.6, 0.4), Matte(ka=0.0, kd=1.0)))
    lamp = Triangle(Float3(-0.5, 1.0, -0.4), Float3(0.6, 1.0, -0.5), Float3(0.1, 1.0, 0.7), Float3(0.0),
                    Emissive(3.0))
    if (lamp.n.y) > 0.0:            # emit downward
        lamp = Triangle(lamp.v0, lamp.v2, lamp.v1, Float3(0.0), Emissive(3.0))
    scene.shapes.append(lamp)
    scene.lights.append(AreaLight(lamp))
    scene.lights[0].set_shadows(shadows)
    scene.tracer = tracer
    return scene, lamp


def mean_and_error(scene, ray_to, n):
    values = []
    for s in range(n):
        ray = Ray(Float3(0.0, 2.0, 4.0), normalize(ray_to - Float3(0.0, 2.0, 4.0)))
        L = trace(scene, ray, (7, s, 3))
        values.append((L.x, L.y, L.z))
    values = np.array(values)
    return values.mean(axis=0), values.std(axis=0, ddof=1) / math.sqrt(n)


def test_area_lighting_has_the_exact_irradiance_of_a_triangle_lamp_as_its_mean():
    scene, lamp = lamp_scene(AreaLighting())
    x = Float3(0.2, 0.0, 0.1)
    mean, error = mean_and_error(scene, x, 3000)
    E = polygon_irradiance(x, Float3(0.0, 1.0, 0.0), [lamp.v0, lamp.v1, lamp.v2], 3.0)
    exact = np.array([0.8, 0.6, 0.4]) / math.pi * E
    assert np.all(np.abs(mean - exact) <= 5 * error), (mean, exact, error)
    assert np.all(error < 0.02 * exact)
    # Whitted sees worksheet 5's point at the centre instead: one value, no noise
    whitted, _ = lamp_scene(Whitted())
    once = [trace(whitted, Ray(Float3(0.0, 2.0, 4.0), normalize(x - Float3(0.0, 2.0, 4.0))), (7, s, 3)).x
            for s in range(3)]
    assert once[0] > 0.0
    assert once[0] == once[1] == once[2]


def test_area_lighting_renders_alike_on_every_path(wgpu_device):
    def soft():
        scene, _ = lamp_scene(AreaLighting())
        scene.shapes.append(Sphere(Float3(0.0, 0.35, 0.0), 0.2, Float3(0.5), Matte()))
        scene.sampler = rtfgu.Jittered(4)
        return scene

    reference = rtfgu.render(soft(), 12, 12)
    assert np.array_equal(rtfgu.render(soft(), 12, 12, backend="numba", precision="float64"), reference)
    for backend, precision in (("numba", "float32"), ("wgpu", "float32")):
        image = rtfgu.render(soft(), 12, 12, backend=backend, precision=precision)
        assert np.abs(to_8bit(image).astype(int) - to_8bit(reference).astype(int)).max() <= 1, backend


def test_area_lighting_makes_soft_shadows_where_whitted_makes_hard_ones():
    def shadow_row(tracer, spp):
        scene, _ = lamp_scene(tracer)
        scene.shapes.append(Sphere(Float3(0.0, 0.35, 0.0), 0.2, Float3(0.5), Matte()))
        row = []
        for k in range(24):
            x = Float3(-0.6 + 1.2 * k / 23, 0.0, 0.0)
            d = normalize(x - Float3(0.0, 2.0, 4.0))      # a fresh ray per sample: tracing shrinks tmax
            row.append(np.mean([trace(scene, Ray(Float3(0.0, 2.0, 4.0), d), (k, s, 0)).x for s in range(spp)]))
        return np.array(row)

    hard = shadow_row(Whitted(), 1)
    soft = shadow_row(AreaLighting(), 64)
    lit, dark = soft.max(), soft.min()
    between = ((soft > dark + 0.1 * (lit - dark)) & (soft < lit - 0.1 * (lit - dark))).sum()
    hard_between = ((hard > hard.min() + 0.1 * np.ptp(hard)) & (hard < hard.max() - 0.1 * np.ptp(hard))).sum()
    assert between > hard_between, (soft, hard)


def test_global_trace_and_path_trace_have_the_same_mean():
    x = Float3(0.25, 0.0, 0.0)

    def box(tracer):
        scene, _ = lamp_scene(tracer)
        scene.shapes.append(Sphere(Float3(-0.4, 0.3, 0.0), 0.3, Float3(0.7, 0.7, 0.7), Matte(ka=0.0, kd=1.0)))
        scene.shapes.append(Plane(Float3(0.0, 0.0, -1.0), Float3(0.0, 0.0, 1.0), Float3(0.6, 0.6, 0.6),
                                  Matte(ka=0.0, kd=1.0)))
        return scene

    m_path, e_path = mean_and_error(box(PathTrace(max_depth=4)), x, 1500)
    m_global, e_global = mean_and_error(box(GlobalTrace(max_depth=4)), x, 1500)
    z = np.abs(m_path - m_global) / np.sqrt(e_path ** 2 + e_global ** 2)
    assert np.all(z < 5), (m_path, m_global, z)


def cornell_global(tracer):
    from rtfgu.scenes import SCENES

    scene = SCENES["cornell_box_progressive"]()
    scene.tracer = tracer
    return scene


def test_global_trace_renders_alike_on_the_lecture_layer_and_numba():
    reference = rtfgu.render(cornell_global(GlobalTrace(max_depth=5)), 10, 10, spp=4, seed=3)
    numba64 = rtfgu.render(cornell_global(GlobalTrace(max_depth=5)), 10, 10, backend="numba",
                           precision="float64", spp=4, seed=3)
    assert np.array_equal(reference, numba64), float(np.max(np.abs(reference - numba64)))
    path = rtfgu.render(cornell_global(PathTrace(max_depth=5)), 10, 10, backend="numba", precision="float64",
                        spp=4, seed=3)
    assert not np.array_equal(path, numba64)       # the lights are sampled at other vertices


def test_global_trace_and_path_trace_agree_in_wgsl_on_average(wgpu_device):
    means = {}
    for tracer in (GlobalTrace(max_depth=6), PathTrace(max_depth=6)):
        for backend in ("numba", "wgpu"):
            image = rtfgu.render(cornell_global(tracer), 16, 16, backend=backend, precision="float32", spp=256)
            means[type(tracer).__name__, backend] = image.mean()
    for (name, backend), mean in means.items():
        assert abs(mean - means["PathTrace", "numba"]) < 0.03 * means["PathTrace", "numba"], means


def test_a_sampler_on_an_ambient_occluder_changes_the_draws_not_the_mean():
    def occluded(sampler):
        scene = Scene(PinholeCamera(Float3(0.0, 2.0, 4.0), Float3(0.0), Float3(0.0, 1.0, 0.0)))
        scene.shapes.append(Plane(Float3(0.0), Float3(0.0, 1.0, 0.0), Float3(0.5), Matte(ka=0.0, kd=1.0)))
        light = AmbientOccluder(1.0)
        if sampler is not None:
            light.set_sampler(sampler)
        scene.lights.append(light)
        scene.tracer = PathTrace(max_depth=1)
        return scene

    d = normalize(Float3(0.3, 0.0, 0.0) - Float3(0.0, 2.0, 4.0))
    by_stream, by_sampler = occluded(None), occluded(MultiJittered(256))
    stream = [trace(by_stream, Ray(Float3(0.0, 2.0, 4.0), d), (0, s, 0)).x for s in range(256)]
    sampled = [trace(by_sampler, Ray(Float3(0.0, 2.0, 4.0), d), (0, s, 0)).x for s in range(256)]
    assert stream != sampled
    for values in (stream, sampled):          # an open plane: rho L = 0.5 exactly in expectation
        assert abs(np.mean(values) - 0.5) <= 5 * np.std(values, ddof=1) / 16 + 1e-12


def assert_drawn_alike(scene):
    """``scene(True)`` (its own samplers set) on numba float64 equals the lecture layer bit
    for bit and WGSL within 1/255, and differs from ``scene(False)`` (the random stream)."""
    reference = rtfgu.render(scene(True), 16, 16)
    numba64 = rtfgu.render(scene(True), 16, 16, backend="numba")
    assert np.array_equal(reference, numba64), float(np.max(np.abs(reference - numba64)))
    assert not np.array_equal(numba64, rtfgu.render(scene(False), 16, 16, backend="numba"))
    wgsl = rtfgu.render(scene(True), 16, 16, backend="wgpu")
    close = np.abs(to_8bit(wgsl).astype(int) - to_8bit(reference).astype(int)) <= 1
    assert close.mean() >= 0.999


@pytest.mark.parametrize("tracer", ["area_lighting", "path_trace"])
def test_a_lights_own_sampler_draws_alike_on_every_path(wgpu_device, tracer):
    """set_sampler on an AreaLight (under AreaLighting and PathTrace) and on an
    AmbientOccluder: numba float64 draws the same points as the lecture layer, bit for bit,
    WGSL within 1/255; and the points are the sampler's, not the stream's."""
    def scene(with_sampler):
        s, _ = lamp_scene(AreaLighting() if tracer == "area_lighting" else PathTrace(max_depth=2))
        s.shapes.append(Sphere(Float3(0.1, 0.35, 0.0), 0.25, Float3(0.5), Matte(ka=0.0, kd=1.0)))
        if tracer == "path_trace":
            s.lights.append(AmbientOccluder(0.3))
        if with_sampler:
            for light in s.lights:
                light.set_sampler(MultiJittered(4, num_sets=5, seed=7))
        s.sampler = rtfgu.Jittered(4)
        return s

    assert_drawn_alike(scene)


def test_a_brdfs_own_sampler_draws_alike_on_every_path(wgpu_device):
    """set_sampler on the BRDFs PathTrace draws directions from (a Matte's Lambertian, a
    GlossyReflector's Lambertian and GlossySpecular): numba float64 takes the same points
    as the lecture layer, bit for bit, WGSL within 1/255; and they are the sampler's."""
    def scene(with_sampler):
        s, _ = lamp_scene(PathTrace(max_depth=3))
        gloss = GlossyReflector(ka=0.0, kd=0.5, ks=0.4, cs=(1.0, 1.0, 1.0), exp=20.0)
        s.shapes.append(Sphere(Float3(0.1, 0.35, 0.0), 0.25, Float3(0.6, 0.5, 0.4), gloss))
        if with_sampler:
            s.shapes[0].material.diffuse_brdf.set_sampler(MultiJittered(4, num_sets=3, seed=1))
            gloss.diffuse_brdf.set_sampler(MultiJittered(4, num_sets=5, seed=2))
            gloss.specular_brdf.set_sampler(rtfgu.Hammersley(4, num_sets=2))
        s.sampler = rtfgu.Jittered(4)
        return s

    assert_drawn_alike(scene)


def test_directional_points_toward_the_light_as_the_books_does():
    scene = Scene(PinholeCamera(Float3(0.0, 2.0, 4.0), Float3(0.0), Float3(0.0, 1.0, 0.0)))
    scene.ambient_light = Ambient(0.0)
    scene.shapes.append(Plane(Float3(0.0), Float3(0.0, 1.0, 0.0), Float3(1.0), Matte(ka=0.0, kd=1.0)))
    scene.lights.append(Directional(Float3(0.0, 1.0, 0.0), Float3(math.pi)))      # the sun straight above
    L = trace(scene, Ray(Float3(0.0, 2.0, 4.0), normalize(Float3(0.0) - Float3(0.0, 2.0, 4.0))))
    assert abs(L.x - 1.0) < 1e-12        # kd cd / pi * pi * (n . w_i = 1)


BAD = [
    (lambda: Matte(kd=-0.1), "Matte.kd"),
    (lambda: Matte().set_ka(float("nan")), "Matte.ka"),
    (lambda: Phong(exp=-1.0), "Phong.exp"),
    (lambda: Phong().set_cs((1.0, -1.0, 0.0)), "Phong.cs"),
    (lambda: Reflective(kr=-1.0), "Reflective.kr"),
    (lambda: Transparent(ior=0.0), "Transparent.ior"),
    (lambda: Dielectric(ior=0.0), "Dielectric.ior"),
    (lambda: Dielectric(absorption=(0.0, -1.0, 0.0)), "Dielectric.absorption"),
    (lambda: Emissive(-1.0), "Emissive.ls"),
    (lambda: Whitted(max_depth=0), "Whitted.max_depth"),
    (lambda: AreaLighting(max_depth=0), "AreaLighting.max_depth"),
    (lambda: PathTrace(max_depth=0), "PathTrace.max_depth"),
    (lambda: AreaLight(None), "AreaLight.shape"),
    (lambda: AreaLight(Plane(Float3(0.0), Float3(0.0, 1.0, 0.0), Float3(1.0), Emissive())), "AreaLight.shape"),
    (lambda: AreaLight(Sphere(Float3(0.0), 1.0, Float3(1.0), Matte())), "AreaLight.shape"),
    (lambda: PointLight().set_ls(-2.0), "PointLight.ls"),
    (lambda: Directional((0.0, 0.0, 0.0)), "Directional.direction"),
    (lambda: Lambertian(kd=float("inf")), "Lambertian.kd"),
    (lambda: Matte(cd="red"), "Matte.cd"),
    (lambda: PointLight().set_sampler("jittered"), "PointLight.sampler"),
]


@pytest.mark.parametrize("make,field", BAD, ids=[f for _, f in BAD])
def test_bad_input_names_the_class_and_the_field(make, field):
    with pytest.raises(ValueError, match=field.replace(".", r"\.")):
        make()


def test_a_scene_refuses_what_is_not_a_tracer_or_an_ambient_light():
    scene = book_scene()
    scene.tracer = "whitted"
    with pytest.raises(ValueError, match="Scene.tracer"):
        scene.validate()
    scene = book_scene()
    scene.lights.append(Ambient())
    with pytest.raises(ValueError, match=r"Scene.lights\[1\]"):
        scene.validate()
    scene = book_scene(RayCast())
    scene.lights.append(AmbientOccluder())
    with pytest.raises(ValueError, match=r"Scene.lights\[1\].*PathTrace"):
        scene.validate()


REFERENCE_ONLY = [
    (lambda s: setattr(s.shapes[2], "material", Dielectric()), r"Scene.shapes\[2\].material"),
    (lambda s: setattr(s, "tracer", Whitted(max_depth=3)), "Scene.tracer"),
    (lambda s: s.lights.append(PointLight((0.0, 3.0, 0.0), (1.0, 1.0, 1.0), inverse_square=False)),
     r"Scene.lights\[1\]"),
    (lambda s: s.shapes[1].material.specular_brdf.__setattr__("normalized", False), r"Scene.shapes\[1\].material"),
    (lambda s: s.lights[0].set_shadows(False) or s.lights.append(PointLight((0.0, 3.0, 0.0), (1.0, 1.0, 1.0))),
     "Scene.lights"),
]


@pytest.mark.parametrize("change,field", REFERENCE_ONLY, ids=[f for _, f in REFERENCE_ONLY])
def test_the_flat_paths_refuse_what_they_do_not_model_and_the_reference_renders_it(change, field):
    scene = book_scene()
    change(scene)
    with pytest.raises(ValueError, match=field):
        rtfgu.render(scene, 4, 4, backend="numba")
    assert np.all(np.isfinite(rtfgu.render(scene, 4, 4)))


def test_the_base_material_shows_the_shapes_colour_and_emissive_its_radiance():
    scene = glass_scene(Material(), Whitted())
    scene.shapes[0].color = Float3(0.1, 0.2, 0.3)
    L = trace(scene, Ray(Float3(0.0, 0.0, 3.0), Float3(0.0, 0.0, -1.0)))
    assert (L.x, L.y, L.z) == (0.1, 0.2, 0.3)
    scene.shapes[0].material = Emissive(2.0, (0.5, 0.25, 1.0))
    L = trace(scene, Ray(Float3(0.0, 0.0, 3.0), Float3(0.0, 0.0, -1.0)))
    assert (L.x, L.y, L.z) == (1.0, 0.5, 2.0)
