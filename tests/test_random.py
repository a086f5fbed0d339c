"""The random stream is the same on every path, bit for bit: the lecture layer's Python
integers, numba's masked int64 and WGSL's u32 give the same 32 bits for the same
(pixel, index, dimension, seed), and the same float in [0, 1)."""
from __future__ import annotations

import numpy as np
import pytest
from numba import njit

from rtfgu.kernels import sampling as ks
from rtfgu.sampling.random import MASK, check_seed, pcg, random_float, random_u32

EDGES = [0, 1, 2, 0x7FFFFFFF, 0x80000000, MASK - 1, MASK]


def inputs(n: int, seed: int = 1) -> np.ndarray:
    rng = np.random.default_rng(seed)
    counters = rng.integers(0, 2 ** 32, size=(n, 4), dtype=np.uint64)
    edges = np.array([[a, b, c, d] for a in EDGES for b in (0, MASK) for c in (0, 7) for d in (0, MASK)],
                     dtype=np.uint64)
    return np.concatenate([edges, counters])


@njit(cache=True)
def _numba_u32(counters, out):
    for k in range(counters.shape[0]):
        out[k] = ks.random_u32(np.int64(counters[k, 0]), np.int64(counters[k, 1]),
                               np.int64(counters[k, 2]), np.int64(counters[k, 3]))


def numba_u32(counters) -> np.ndarray:
    out = np.zeros(len(counters), dtype=np.int64)
    _numba_u32(counters, out)
    return out


def test_pcg_of_known_values():
    """Jarzynski and Olano's pcg, worked by hand for 0: state 2891336453, shift 14."""
    state = 2891336453
    word = (((state >> ((state >> 28) + 4)) ^ state) * 277803737) & MASK
    assert pcg(0) == (word >> 22) ^ word
    assert len({pcg(v) for v in range(10000)}) == 10000  # a permutation of u32


def test_numba_draws_the_lecture_layers_numbers():
    counters = inputs(20_000)
    expected = [random_u32(*map(int, row)) for row in counters]
    assert numba_u32(counters).tolist() == expected
    for row in counters[:500]:
        a = [int(v) for v in row]
        assert ks.random_float(*a, 1.0) == random_float(*a)
        assert ks.random_float(*a, np.float32(1)) == np.float32(random_float(*a))


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
    let h = random_u32(c.x, c.y, c.z, c.w);
    out[id.x] = vec4f(bitcast<f32>(h), random_float(c.x, c.y, c.z, c.w), 0.0, 0.0);
}
"""


def test_wgsl_draws_the_same_numbers():
    from rtfgu.wgsl.device import NoAdapterError, get_device

    try:
        get_device()
    except NoAdapterError as error:
        pytest.skip(str(error))
    from rtfgu.wgsl.harness import batch_program, run_batch

    counters = inputs(200_000)
    program = batch_program(["random.wgsl", "random_main.wgsl"],
                            overrides={"random_main.wgsl": _WGSL_MAIN})
    out = run_batch(program, [counters.astype(np.uint32)], len(counters))
    hashes = out[:, 0, 0].view(np.uint32).astype(np.int64)
    assert np.array_equal(hashes, numba_u32(counters))
    floats = out[:, 0, 1].astype(np.float64)
    assert np.array_equal(floats, (hashes >> 8) * 2.0 ** -24)


def test_the_floats_are_uniform_and_below_one():
    values = np.array([random_float(k, 0, 0, 0) for k in range(50_000)])
    assert values.min() >= 0 and values.max() < 1
    counts, _ = np.histogram(values, bins=20, range=(0, 1))
    expected = len(values) / 20
    assert np.sum((counts - expected) ** 2 / expected) < 43.8  # chi-square 19 dof, p = 0.001


@pytest.mark.parametrize("bad", [-1, 2 ** 32, 1.5, "0", True, None])
def test_a_bad_seed_names_the_field(bad):
    with pytest.raises(ValueError, match="seed"):
        check_seed(bad)
