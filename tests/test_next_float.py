"""rtfgu.kernels.next_float: the kernels' next float up and down, computed on the float's bits,
against numpy's nextafter on the floats where a step is hardest to get right (the zeros, the
subnormals, the edge of the normal range, the largest finite floats, the infinities, NaN) and
on random bit patterns of every exponent, in both precisions, compiled."""
from __future__ import annotations

import numpy as np
import pytest
from numba import njit

from rtfgu.kernels.next_float import next_down, next_up


@njit(cache=True, error_model="numpy")
def _steps(values, up, down):
    for i in range(values.shape[0]):
        up[i] = next_up(values[i])
        down[i] = next_down(values[i])


def _hard_values(dtype) -> np.ndarray:
    info = np.finfo(dtype)
    tiny = info.smallest_subnormal
    edges = [0.0, tiny, 2 * tiny, info.tiny - tiny, info.tiny, info.tiny + info.tiny * info.eps, 0.5, 1.0, 1.5,
             2.0, info.max / 2, np.nextafter(info.max, dtype(0)), info.max, np.inf]
    values = np.array(edges, dtype=dtype)
    # NaNs, the quiet one and those of the least payload of each sign, whose bits one step
    # from them are an infinity's.
    bits = np.dtype(dtype).itemsize * 8
    unsigned = np.uint32 if bits == 32 else np.uint64
    exponent = int(np.array(np.inf, dtype=dtype).view(unsigned))
    nans = np.array([exponent | 1, exponent | 1 | 1 << bits - 1], dtype=unsigned).view(dtype)
    return np.concatenate([values, -values, np.array([np.nan], dtype=dtype), nans])


def _random_values(dtype, count: int = 20000) -> np.ndarray:
    bits = np.dtype(dtype).itemsize * 8
    unsigned = np.uint32 if bits == 32 else np.uint64
    rng = np.random.default_rng(2562)
    return rng.integers(0, np.iinfo(unsigned).max, size=count, dtype=unsigned, endpoint=True).view(dtype)


@pytest.mark.parametrize("dtype", [np.float32, np.float64], ids=["float32", "float64"])
@pytest.mark.parametrize("values", ["hard", "random"])
def test_next_up_and_down_are_numpys_nextafter_bit_for_bit(dtype, values):
    x = _hard_values(dtype) if values == "hard" else _random_values(dtype)
    up = np.empty_like(x)
    down = np.empty_like(x)
    _steps(x, up, down)
    with np.errstate(over="ignore", invalid="ignore"):
        want_up = np.nextafter(x, dtype(np.inf))
        want_down = np.nextafter(x, dtype(-np.inf))
    for got, want, name in ((up, want_up, "next_up"), (down, want_down, "next_down")):
        nan = np.isnan(want)
        assert np.array_equal(np.isnan(got), nan), name
        wrong = np.flatnonzero(got[~nan].view(f"u{x.itemsize}") != want[~nan].view(f"u{x.itemsize}"))
        assert wrong.size == 0, f"{name}({x[~nan][wrong[0]]!r}) = {got[~nan][wrong[0]]!r}, not {want[~nan][wrong[0]]!r}"
    if values == "hard":
        # The cases the bits' arithmetic must treat apart: both zeros step to the least
        # subnormal of the step's sign, the infinities stay or come back to the largest float.
        assert up[0] == np.finfo(dtype).smallest_subnormal and down[0] == -np.finfo(dtype).smallest_subnormal
        assert np.isinf(up[list(x).index(np.inf)]) and down[list(x).index(-np.inf)] == -np.inf
