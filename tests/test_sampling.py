"""The samplers and the maps of Suffern ch. 5-7, on every path.

Every map passes Pearson's chi-square test against its density on every path (the lecture
layer, numba float64 and float32, WGSL), and a deliberately skewed map fails it: the test
can tell. The samplers' points are checked for the property that names each one.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from rtfgu.sampling import Hammersley, Jittered, MultiJittered, NRooks, Regular
from rtfgu.sampling.hammersley import phi
from warp_support import (MAP_PATHS, chi_square_p, disk_histogram, hemisphere_histogram,
                          map_points, uniform_points)

N = 40_000
# A correct map fails at this level once in 10^4 runs; a skewed one passes never.
ALPHA = 1e-4


@pytest.fixture(scope="module")
def points():
    return uniform_points(N)


@pytest.fixture(params=MAP_PATHS)
def map_path(request):
    if request.param.startswith("wgpu"):
        from rtfgu.wgsl.device import NoAdapterError, get_device

        try:
            get_device()
        except NoAdapterError as error:
            pytest.skip(str(error))
    return request.param


def test_the_concentric_map_is_uniform_on_the_disk(map_path, points):
    disk = map_points(map_path, "disk", points)
    assert np.all(disk[:, 0] ** 2 + disk[:, 1] ** 2 <= 1 + 1e-6)
    observed, expected = disk_histogram(disk)
    assert chi_square_p(observed, expected) > ALPHA


@pytest.mark.parametrize("e", [0.0, 1.0, 20.0])
def test_the_hemisphere_map_has_density_cos_e(map_path, points, e):
    directions = map_points(map_path, "hemisphere", points, e)
    assert np.allclose(np.linalg.norm(directions, axis=1), 1, atol=1e-5)
    observed, expected = hemisphere_histogram(directions, e)
    assert chi_square_p(observed, expected) > ALPHA


def test_a_skewed_disk_map_fails(points):
    # The polar map r = x, phi = 2 pi y crowds the centre (density 1 / (2 pi r)).
    r, a = points[:, 0], 2 * math.pi * points[:, 1]
    observed, expected = disk_histogram(np.stack([r * np.cos(a), r * np.sin(a)], axis=1))
    assert chi_square_p(observed, expected) < 1e-12


def test_a_skewed_hemisphere_map_fails(points):
    # cos(theta) = (1 - y)^(1 / e) instead of ^(1 / (e + 1)): density cos^(e - 1).
    directions = map_points("reference", "hemisphere", points, 2.0)
    observed, expected = hemisphere_histogram(directions, 3.0)
    assert chi_square_p(observed, expected) < 1e-12


def test_the_paths_map_the_same_points_alike(points):
    """numba float64 is the lecture layer bit for bit; float32 paths within a few ulps."""
    reference = map_points("reference", "disk", points[:2000])
    assert np.array_equal(map_points("numba-float64", "disk", points[:2000]), reference)
    assert np.abs(map_points("numba-float32", "disk", points[:2000]) - reference).max() < 1e-5
    reference = map_points("reference", "hemisphere", points[:2000], 5.0)
    assert np.array_equal(map_points("numba-float64", "hemisphere", points[:2000], 5.0), reference)


SAMPLERS = (Regular, Jittered, NRooks, MultiJittered, Hammersley)


@pytest.mark.parametrize("cls", SAMPLERS, ids=lambda c: c.__name__)
def test_every_sampler_covers_the_square_uniformly(cls):
    """Over many pixels a sampler's points are uniform in the pixel: chi-square on an 8 x 8
    grid of the points of 64 sets of 64 samples (Regular's points are cell centres, so its
    grid is the sampler's own)."""
    sampler = cls(64, num_sets=64)
    pts = np.array(sampler.samples)
    assert pts.shape == (64 * 64, 2) and np.all((pts >= 0) & (pts < 1))
    observed, _, _ = np.histogram2d(pts[:, 0], pts[:, 1], bins=8, range=[[0, 1], [0, 1]])
    assert chi_square_p(observed, np.full((8, 8), len(pts) / 64)) > ALPHA


@pytest.mark.parametrize("cls", [Jittered, MultiJittered], ids=lambda c: c.__name__)
def test_jittered_sets_have_one_point_per_cell(cls):
    sampler = cls(16, num_sets=5)
    for s in range(5):
        pts = np.array(sampler.samples[16 * s:16 * (s + 1)])
        cells = {(int(x * 4), int(y * 4)) for x, y in pts}
        assert len(cells) == 16


@pytest.mark.parametrize("cls", [NRooks, MultiJittered], ids=lambda c: c.__name__)
def test_n_rooks_sets_have_one_point_per_row_and_column(cls):
    n = 16
    sampler = cls(n, num_sets=5)
    for s in range(5):
        pts = np.array(sampler.samples[n * s:n * (s + 1)])
        assert sorted(int(x * n) for x, _ in pts) == list(range(n))
        assert sorted(int(y * n) for _, y in pts) == list(range(n))


def test_hammersley_is_the_radical_inverse():
    assert [phi(j) for j in range(8)] == [0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875]
    assert Hammersley(8, num_sets=1).samples[3] == (3 / 8, 0.75)


def test_shuffled_indices_are_permutations_and_sets_differ():
    sampler = Jittered(16, num_sets=10)
    for s in range(10):
        assert sorted(sampler.shuffled_indices[16 * s:16 * (s + 1)]) == list(range(16))
    assert sampler.samples[:16] != sampler.samples[16:32]


def test_a_pixel_takes_every_point_of_its_set_once():
    sampler = MultiJittered(16, num_sets=7)
    for pixel in (0, 1, 12345):
        pts = [sampler.sample_unit_square(pixel, s, seed=3) for s in range(16)]
        jump = sampler.samples.index(pts[0]) // 16 * 16
        assert sorted(pts) == sorted(sampler.samples[jump:jump + 16])


def test_the_same_seed_gives_the_same_sets():
    assert NRooks(9, seed=5).samples == NRooks(9, seed=5).samples
    assert NRooks(9, seed=5).samples != NRooks(9, seed=6).samples


@pytest.mark.parametrize("bad, field", [((0,), "num_samples"), ((4, 0), "num_sets"),
                                        ((2.5,), "num_samples")])
def test_bad_sampler_arguments_name_the_field(bad, field):
    with pytest.raises(ValueError, match=field):
        NRooks(*bad)


@pytest.mark.parametrize("cls", [Regular, Jittered, MultiJittered], ids=lambda c: c.__name__)
def test_grid_samplers_need_a_square_number(cls):
    with pytest.raises(ValueError, match="num_samples must be a square"):
        cls(8)
