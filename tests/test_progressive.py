"""Samples per pixel, seeds and passes on every path.

A render adds each pixel's samples in order to the pixel's sum, so a render in passes is
the same, bit for bit, as one render with all the samples; the same seed gives the same
image, another seed another image; the thin lens focuses the focal plane.
"""
from __future__ import annotations

import numpy as np
import pytest

import rtfgu
from rtfgu import Float3
from rtfgu.cameras import PinholeCamera, ThinLens
from rtfgu.renderer import render, render_passes
from rtfgu.sampling import Hammersley, Jittered, NRooks
from rtfgu.scenes import SCENES

W, H = 20, 14


@pytest.fixture(params=[("reference", "float64"), ("numba", "float64"), ("numba", "float32"),
                        ("wgpu", "float32")], ids=lambda p: "-".join(p))
def backend(request):
    if request.param[0] == "wgpu":
        from rtfgu.wgsl.device import NoAdapterError, get_device

        try:
            get_device()
        except NoAdapterError as error:
            pytest.skip(str(error))
    return request.param


def dof_scene():
    scene = SCENES["suffern_depth_of_field"]()
    scene.sampler = Jittered(9)
    return scene


def test_passes_sum_to_one_render_bit_for_bit(backend):
    name, precision = backend
    whole = render(dof_scene(), W, H, name, precision, spp=9)
    steps = list(render_passes(dof_scene(), W, H, name, precision, spp=9, passes=4))
    assert [done for done, _ in steps] == [2, 4, 6, 9]
    assert np.array_equal(steps[-1][1], whole)
    assert not np.array_equal(steps[0][1], whole)  # the first pass is a coarser estimate


@pytest.mark.parametrize("precision", ["float64", "float32"])
def test_the_numba_sums_start_at_the_first_sample_whatever_they_held(precision):
    """The accumulator's sums are not zeroed: a range from sample 0 writes them, a first
    range past 0 zeroes them; its last pass hands float64 sums over as the image."""
    from rtfgu.kernels import NumbaAccumulator
    from rtfgu.renderer import pixel_sampler
    whole = render(dof_scene(), W, H, "numba", precision, spp=9)

    def accumulator():
        accumulate = NumbaAccumulator(dof_scene(), W, H, precision, sampler=pixel_sampler(dof_scene(), 9))
        accumulate.sums[...] = np.nan                       # what a fresh np.empty may hold
        return accumulate
    accumulate = accumulator()
    accumulate((0, 4))
    assert np.array_equal(accumulate((4, 9), last=True), whole)
    if precision == "float64":
        assert accumulate.sums is None
        with pytest.raises(ValueError, match="last pass"):
            accumulate((0, 9))
    again = accumulator()
    again((0, 9))
    assert np.array_equal(again((0, 9)), whole)             # from sample 0 again: written over
    later = accumulator()
    assert np.isfinite(later((4, 9))).all()                 # samples 4..8 alone: zeroed first


def test_the_seed_decides_the_image(backend):
    name, precision = backend
    a = render(dof_scene(), W, H, name, precision, seed=5)
    assert np.array_equal(a, render(dof_scene(), W, H, name, precision, seed=5))
    b = render(dof_scene(), W, H, name, precision, seed=6)
    assert not np.array_equal(a, b)
    assert np.abs(a - b).mean() < 0.05  # the same picture, other noise


def test_one_centre_sample_is_the_image_without_a_sampler():
    scene = SCENES["default_lambertian_shadows"]()
    plain = render(scene, W, H, "numba")
    scene.sampler = NRooks(1)
    one = render(scene, W, H, "numba")
    # NRooks(1)'s one point is random in the pixel: near the centre's image, not equal.
    assert not np.array_equal(plain, one) and np.abs(plain - one).mean() < 0.05
    assert np.array_equal(plain, render(SCENES["default_lambertian_shadows"](), W, H, "numba", spp=1))


def test_spp_overrides_the_scenes_sampler_count_and_keeps_its_kind():
    from rtfgu.renderer import pixel_sampler

    scene = SCENES["default_lambertian"]()
    scene.sampler = Hammersley(4, seed=3)
    chosen = pixel_sampler(scene, 10)
    assert isinstance(chosen, Hammersley) and chosen.num_samples == 10 and chosen.seed == 3
    assert pixel_sampler(scene, None) is scene.sampler
    scene.sampler = None
    assert isinstance(pixel_sampler(scene, 16), Jittered)
    assert isinstance(pixel_sampler(scene, 10), NRooks)
    assert pixel_sampler(scene, 1) is None


def test_more_samples_converge():
    """The RMSE against a 256-sample image falls as samples are added (Jittered)."""
    scene = SCENES["suffern_samplers_jittered"]()
    truth = render(scene, 24, 24, "numba", spp=256, seed=99)
    errors = [np.sqrt(np.mean((render(scene, 24, 24, "numba", spp=n) - truth) ** 2)) for n in (1, 4, 16, 64)]
    assert all(a > b for a, b in zip(errors, errors[1:])), errors


def test_a_thin_lens_with_radius_zero_is_the_pinhole():
    args = (Float3(1.0, 2.0, 3.0), Float3(0.0, 0.5, 0.0), Float3(0.0, 1.0, 0.0))
    pinhole = PinholeCamera(*args, d=1.3, aspect=1.5)
    lens = ThinLens(*args, d=1.3, aspect=1.5, lens_radius=0.0)
    for sx, sy in ((0.0, 0.0), (-0.9, 0.4), (0.7, -0.99)):
        a, b = pinhole.gen_ray(sx, sy), lens.gen_ray(sx, sy, (0.3, -0.2))
        assert (b.origin - a.origin).length() == 0.0
        assert (b.direction - a.direction).length() < 1e-15


def test_every_lens_ray_of_a_pixel_meets_at_the_focal_plane():
    camera = ThinLens(Float3(0.0, 0.0, 5.0), Float3(0.0, 0.0, 0.0), Float3(0.0, 1.0, 0.0),
                      lens_radius=0.5, focal_distance=3.0)
    points = []
    for lens in ((0.0, 0.0), (1.0, 0.0), (-0.6, 0.8), (0.1, -0.3)):
        ray = camera.gen_ray(0.3, -0.2, lens)
        t = 3.0 / -ray.direction.z       # the plane z = 5 - 3
        points.append(ray(t))
    for p in points[1:]:
        assert (p - points[0]).length() < 1e-12
    assert abs(points[0].z - 2.0) < 1e-12


def test_the_depth_of_field_blurs_off_the_focal_plane():
    """In focus the middle sphere's outline is as sharp as the pinhole's; the near one is
    not: its image differs more from the pinhole image than the middle one's."""
    scene = SCENES["suffern_depth_of_field"]()
    sharp = SCENES["suffern_depth_of_field"]()
    sharp.camera.lens_radius = 0.0
    a = render(scene, 64, 48, "numba")
    b = render(sharp, 64, 48, "numba")
    diff = np.abs(a - b).max(axis=2)
    assert diff[28:40, 0:12].mean() > 3 * diff[18:30, 26:38].mean()


@pytest.mark.parametrize("kwargs, field", [
    ({"spp": 0}, "spp"), ({"spp": -2}, "spp"), ({"spp": 2.0}, "spp"), ({"spp": True}, "spp"),
    ({"seed": -1}, "seed"), ({"seed": 2 ** 32}, "seed"), ({"passes": 0}, "passes")])
def test_bad_render_options_name_the_field(kwargs, field):
    with pytest.raises(ValueError, match=field):
        render(SCENES["default_lambertian"](), 4, 4, "reference", **kwargs)


def test_a_square_sampler_refuses_another_count_naming_spp():
    scene = SCENES["default_antialiasing_2"]()
    with pytest.raises(ValueError, match="spp.*square"):
        render(scene, 4, 4, "reference", spp=5)


@pytest.mark.parametrize("kwargs, field", [({"lens_radius": -0.1}, "lens_radius"),
                                           ({"lens_radius": float("nan")}, "lens_radius"),
                                           ({"focal_distance": 0.0}, "focal_distance"),
                                           ({"focal_distance": float("inf")}, "focal_distance")])
def test_bad_thin_lens_names_the_field(kwargs, field):
    with pytest.raises(ValueError, match="ThinLens.%s" % field):
        ThinLens(Float3(0.0, 0.0, 5.0), Float3(0.0), Float3(0.0, 1.0, 0.0), **kwargs)


def test_a_scene_sampler_that_is_not_a_sampler_is_refused():
    scene = SCENES["default_lambertian"]()
    scene.sampler = 16
    with pytest.raises(ValueError, match="Scene.sampler"):
        rtfgu.render(scene, 4, 4)


def test_a_sampler_asked_for_again_is_made_once():
    """spp=N makes the sets of the scene's kind once; the next render, pass or notebook
    refresh reuses them (making them is pure Python)."""
    from rtfgu.renderer import pixel_sampler

    scene = SCENES["default_antialiasing_4"]()
    first, again = pixel_sampler(scene, 64), pixel_sampler(SCENES["default_antialiasing_4"](), 64)
    assert first is again and type(first) is type(scene.sampler) and first.num_samples == 64
    assert pixel_sampler(scene, 36) is not first
    plain = SCENES["default_lambertian"]()
    assert pixel_sampler(plain, 16) is pixel_sampler(plain, 16)
    assert type(pixel_sampler(plain, 5)).__name__ == "NRooks"
