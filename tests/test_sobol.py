"""Burley's shuffled, Owen-scrambled Sobol points (rtfgu.sampling.sobol) are the same on every
path, bit for bit, and have the stratification Burley's paper promises:

1. numba's masked int64 and WGSL's u32 give the lecture layer's 32-bit fractions and floats
   for the same (pixel, index, dimension, seed), edges included.
2. The pieces: reverse_bits reverses, Sobol's second dimension is its generator matrix
   (Pascal's triangle mod 2), the nested uniform scramble keeps every aligned block of 2^k
   values a block (Owen's property).
3. For every k with 2^k <= 256 the first 2^k samples of a pixel in a dimension pair are a
   (0, k, 2)-net (checked on the integer bits); a count that is not a power of two takes
   points of distinct cells; pixels and dimension pairs are scrambled differently.
4. A path-traced render with a Sobol sampler: numba float64 is the lecture layer, float32 and
   WGSL close; every 2D draw changes with it and nothing changes without it; bad input is named.
"""
from __future__ import annotations

import numpy as np
import pytest
from numba import njit

from rtfgu import PathTrace, Sobol, render
from rtfgu.image import to_8bit
from rtfgu.kernels import sampling as ks
from rtfgu.sampling.random import LENS_SET, MASK, PIXEL_SET, BOUNCE_U, LIGHT_U, path_dimension
from rtfgu.sampling.sobol import (laine_karras_permutation, nested_uniform_scramble, reverse_bits, sobol_0,
                                  sobol_1, sobol_pair, sobol_pair_u32)

EDGES = [0, 1, 2, 255, 256, 0x7FFFFFFF, 0x80000000, MASK - 1, MASK]


def inputs(n: int, seed: int = 5) -> np.ndarray:
    """(pixel, index, dimension, seed) rows: the edges, small indices (a render's), and random ones."""
    rng = np.random.default_rng(seed)
    edges = np.array([[a, b, c, d] for a in EDGES for b in EDGES for c in (0, 1, 2, MASK) for d in (0, MASK)],
                     dtype=np.uint64)
    small = rng.integers(0, 2 ** 32, size=(n // 2, 4), dtype=np.uint64)
    small[:, 1] %= 4096
    small[:, 2] %= 1 << 20
    wide = rng.integers(0, 2 ** 32, size=(n - n // 2, 4), dtype=np.uint64)
    return np.concatenate([edges, small, wide])


@njit(cache=True)
def _numba_pairs(counters, out):
    for k in range(counters.shape[0]):
        u, v = ks.sobol_pair_u32(np.int64(counters[k, 0]), np.int64(counters[k, 1]),
                                 np.int64(counters[k, 2]), np.int64(counters[k, 3]))
        out[k, 0] = u
        out[k, 1] = v


def numba_pairs(counters) -> np.ndarray:
    out = np.zeros((len(counters), 2), dtype=np.int64)
    _numba_pairs(counters, out)
    return out


@pytest.fixture(scope="module")
def counters():
    return inputs(100_000)


@pytest.fixture(scope="module")
def expected(counters):
    return np.array([sobol_pair_u32(*map(int, row)) for row in counters], dtype=np.int64)


# ---------------------------------------------------------------------------------------
# 1. The same numbers on every path

def test_numba_gives_the_lecture_layers_pairs(counters, expected):
    got = numba_pairs(counters)
    assert np.array_equal(got, expected)
    assert got.min() >= 0 and got.max() <= MASK
    for row in counters[:300]:
        a = [int(v) for v in row]
        assert ks.sobol_pair(*a, 1.0) == sobol_pair(*a)
        assert ks.sobol_pair(*a, np.float32(1)) == tuple(np.float32(x) for x in sobol_pair(*a))


_WGSL_MAIN = """
@group(0) @binding(0) var<storage, read> counters: array<vec4u>;
@group(0) @binding(1) var<storage, read_write> out: array<vec4f>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3u)
{
    if (id.x >= arrayLength(&counters)) {
        return;
    }
    let c = counters[id.x];
    let h = sobol_pair_u32(c.x, c.y, c.z, c.w);
    let f = sobol_pair(c.x, c.y, c.z, c.w);
    out[id.x] = vec4f(bitcast<f32>(h.x), bitcast<f32>(h.y), f.x, f.y);
}
"""


def test_wgsl_gives_the_same_pairs(counters, expected):
    from rtfgu.wgsl.device import NoAdapterError, get_device

    try:
        get_device()
    except NoAdapterError as error:
        pytest.skip(str(error))
    from rtfgu.wgsl.harness import batch_program, run_batch

    program = batch_program(["random.wgsl", "sobol.wgsl", "sobol_main.wgsl"],
                            overrides={"sobol_main.wgsl": _WGSL_MAIN})
    out = run_batch(program, [counters.astype(np.uint32)], len(counters))
    pairs = out[:, 0, :2].view(np.uint32).astype(np.int64)
    assert np.array_equal(pairs, expected)
    assert np.array_equal(out[:, 0, 2:].astype(np.float64), (expected >> 8) * 2.0 ** -24)


# ---------------------------------------------------------------------------------------
# 2. The pieces

def test_reverse_bits_reverses():
    rng = np.random.default_rng(2)
    for x in EDGES + [int(v) for v in rng.integers(0, 2 ** 32, 200)]:
        assert reverse_bits(x) == int(format(x, "032b")[::-1], 2)


def test_sobols_second_dimension_is_pascals_triangle_mod_2():
    """Index bit j adds the column j of the generator: digit i (from the point) set where
    binom(j, i) is odd, i.e. where i's bits are a subset of j's (Lucas)."""
    columns = [sum(1 << (31 - i) for i in range(32) if i & j == i) for j in range(32)]
    rng = np.random.default_rng(3)
    for index in list(range(64)) + [int(v) for v in rng.integers(0, 2 ** 32, 200)]:
        x = 0
        for j in range(32):
            if index >> j & 1:
                x ^= columns[j]
        assert sobol_1(index) == x
        assert sobol_0(index) == reverse_bits(index)
    # the first points: 0, 1/2, 3/4, 1/4, 5/8 (Burley, figure 1's second coordinate)
    assert [sobol_1(i) / 2 ** 32 for i in range(5)] == [0.0, 0.5, 0.75, 0.25, 0.625]


def test_the_scramble_keeps_aligned_blocks():
    """Owen's property: output bit m depends only on the bits above it (the point's first digits
    scrambled by those before them), so the values sharing their top k bits land together."""
    rng = np.random.default_rng(4)
    for seed in [0, 1, MASK] + [int(v) for v in rng.integers(0, 2 ** 32, 20)]:
        for k in (1, 3, 8):
            top = int(rng.integers(0, 2 ** k))
            block = [(top << (32 - k)) | int(low) for low in rng.integers(0, 2 ** (32 - k), 50)]
            assert len({nested_uniform_scramble(x, seed) >> (32 - k) for x in block}) == 1
        values = [nested_uniform_scramble(x << 24, seed) >> 24 for x in range(256)]
        assert sorted(values) == list(range(256))   # a permutation of the 8-bit cells
    # the hash mixes: its low bit follows x's low bit only, higher bits depend on more
    assert laine_karras_permutation(0, 0) == 0 and laine_karras_permutation(1, 0) != 1


# ---------------------------------------------------------------------------------------
# 3. Stratification (Burley 2020, section 4)

def is_net(points, k: int) -> bool:
    """Every elementary interval of area 2^-k (2^a x 2^b cells, a + b = k) holds one of the
    2^k points ``points`` (32-bit fractions)."""
    for a in range(k + 1):
        cells = {(u >> (32 - a) if a else 0, v >> (32 - (k - a)) if k - a else 0) for u, v in points}
        if len(cells) != 2 ** k:
            return False
    return True


@pytest.mark.parametrize("pixel, dimension, seed", [(0, PIXEL_SET, 0), (77, LENS_SET, 3),
                                                    (4095, path_dimension(2, BOUNCE_U), 9),
                                                    (MASK, path_dimension(0, LIGHT_U + 2), MASK)])
def test_every_power_of_two_prefix_is_a_0_k_2_net(pixel, dimension, seed):
    points = [sobol_pair_u32(pixel, index, dimension, seed) for index in range(256)]
    for k in range(9):
        assert is_net(points[:2 ** k], k), k
        # and the 24 bits a float keeps still are one
        assert is_net([(u >> 8 << 8, v >> 8 << 8) for u, v in points[:2 ** k]], k)
    # the next aligned blocks of the pixel's sequence too
    later = [sobol_pair_u32(pixel, index, dimension, seed) for index in range(256, 512)]
    assert is_net(later, 8)


def test_the_net_check_can_fail():
    """The net check can fail: the same point twice, or points all in one half."""
    assert not is_net([(0, 0), (0, 0)], 1)
    assert not is_net([(0, 0), (1 << 30, 1 << 31)], 1)
    assert is_net([(0, 0), (1 << 31, 1 << 31)], 1)


def test_three_samples_take_three_cells_of_a_net_of_four():
    points = [sobol_pair_u32(12, index, PIXEL_SET, 0) for index in range(3)]
    for a in range(3):
        cells = {(u >> (32 - a) if a else 0, v >> (32 - (2 - a)) if 2 - a else 0) for u, v in points}
        assert len(cells) == 3


def test_pixels_and_dimension_pairs_are_scrambled_differently():
    """Different pixels, dimension pairs and seeds draw different points, and the first points
    of many pixels are spread like independent ones (no shared pattern: Burley's padding)."""
    base = [sobol_pair_u32(0, i, PIXEL_SET, 0) for i in range(16)]
    for other in ([sobol_pair_u32(1, i, PIXEL_SET, 0) for i in range(16)],
                  [sobol_pair_u32(0, i, LENS_SET, 0) for i in range(16)],
                  [sobol_pair_u32(0, i, PIXEL_SET, 1) for i in range(16)]):
        assert not set(base) & set(other)
    # sample 0 of 4096 pixels: uniform on 16 x 16 cells (chi-square, 255 dof, p = 0.001: 330.5)
    first = np.array([sobol_pair(p, 0, path_dimension(0, BOUNCE_U), 0) for p in range(4096)])
    counts = np.histogram2d(first[:, 0], first[:, 1], bins=16, range=[[0, 1], [0, 1]])[0]
    assert np.sum((counts - 16) ** 2 / 16) < 330.5
    # the two coordinates of a pixel's pair and of consecutive pairs are uncorrelated
    u = first[:, 0]
    v = np.array([sobol_pair(p, 0, path_dimension(0, BOUNCE_U) + 2, 0)[0] for p in range(4096)])
    assert abs(np.corrcoef(u, first[:, 1])[0, 1]) < 0.06
    assert abs(np.corrcoef(u, v)[0, 1]) < 0.06


# ---------------------------------------------------------------------------------------
# 4. Renders

def sobol_scene(spp: int = 4):
    from rtfgu.scenes.meshes import cornell_box_area_light

    scene = cornell_box_area_light()
    scene.tracer = PathTrace(max_depth=4)
    scene.sampler = Sobol(spp)
    return scene


@pytest.fixture(scope="module")
def reference():
    return render(sobol_scene(), 16, 16, "reference", seed=3)


def test_the_sampler_gives_its_pixel_points():
    sampler = Sobol(8, seed=2)
    assert sampler.sample_unit_square(5, 3, 7) == sobol_pair(5, 3, PIXEL_SET, 7)
    assert sampler.sample_unit_square(5, 3, 7, LENS_SET) == sobol_pair(5, 3, LENS_SET, 7)
    assert sampler.samples == [sobol_pair(0, i, PIXEL_SET, 2) for i in range(8)]
    assert sampler.with_num_samples(3).sample_unit_square(5, 1, 7) == sobol_pair(5, 1, PIXEL_SET, 7)


def test_numba_float64_renders_the_lecture_layers_sobol_image(reference):
    numba = render(sobol_scene(), 16, 16, "numba", "float64", seed=3)
    assert reference.max() > 0.05
    assert np.abs(numba - reference).max() <= 1e-9


def test_the_2d_draws_are_sobols_too(reference, monkeypatch):
    """Sobol reaches the bounces and the light points, not only the pixels: the same pixel
    points with the stream's 2D draws (pair_sample as without a Sobol) give another image."""
    import rtfgu.sampling.sobol as sobol_module
    from rtfgu.sampling.random import random_float

    monkeypatch.setattr(sobol_module, "pair_sample", lambda sampler, p, i, d, s: (
        random_float(p, i, d, s), random_float(p, i, d + 1, s)))
    stream_draws = render(sobol_scene(), 16, 16, "reference", seed=3)
    assert np.abs(stream_draws - reference).max() > 1e-3


def test_numba_float32_is_close(reference):
    numba = render(sobol_scene(), 16, 16, "numba", "float32", seed=3)
    close = np.abs(to_8bit(numba).astype(int) - to_8bit(reference).astype(int)) <= 2
    assert close.mean() >= 0.99, close.mean()


def test_wgsl_is_close(reference):
    from rtfgu.wgsl.device import NoAdapterError, get_device

    try:
        get_device()
    except NoAdapterError as error:
        pytest.skip(str(error))
    image = render(sobol_scene(), 16, 16, "wgpu", seed=3)
    close = np.abs(to_8bit(image).astype(int) - to_8bit(reference).astype(int)) <= 2
    assert close.mean() >= 0.99, close.mean()


def test_the_lens_draws_sobols_pairs():
    """A ThinLens takes its lens points from the pair LENS_SET: numba float64 is the lecture
    layer, and the image is not the one the stream's sets give."""
    from rtfgu.scenes.sampling import suffern_depth_of_field

    scene = suffern_depth_of_field()
    scene.sampler = Sobol(4)
    reference = render(scene, 12, 9, "reference", seed=2)
    assert np.abs(render(scene, 12, 9, "numba", "float64", seed=2) - reference).max() <= 1e-9
    scene.sampler = None
    assert np.abs(render(scene, 12, 9, "numba", "float64", spp=4, seed=2) - reference).max() > 1e-3


def test_three_samples_render_on_every_path():
    scene = sobol_scene(3)
    reference = render(scene, 6, 6, "reference", seed=1)
    assert np.abs(render(scene, 6, 6, "numba", "float64", seed=1) - reference).max() <= 1e-9


@pytest.mark.parametrize("bad", [0, -1, 1.5, True])
def test_bad_num_samples_is_named(bad):
    with pytest.raises(ValueError, match="Sobol.num_samples"):
        Sobol(bad)


def test_a_light_or_brdf_takes_no_sobol_of_its_own():
    from rtfgu import AmbientOccluder, Lambertian

    for owner in (AmbientOccluder(), Lambertian()):
        with pytest.raises(ValueError, match="Scene.sampler"):
            owner.set_sampler(Sobol(4))
