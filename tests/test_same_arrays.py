"""same_arrays: the comparison by which a render keeps a scene's BVH and a Mesh's face groups."""
import numpy as np
import pytest

from rtfgu.same_arrays import CHUNK, same_arrays


def big(dtype=np.float64):
    """An array of 2.5 CHUNKs: compared in slices on the threads."""
    n = 5 * CHUNK // 2 // np.dtype(dtype).itemsize // 3
    return np.arange(3 * n, dtype=dtype).reshape(n, 3)


@pytest.mark.parametrize("dtype", [np.float64, np.int64, np.int32, np.float32])
def test_equal_arrays_are_the_same(dtype):
    a = big(dtype)
    assert a.nbytes >= 2 * CHUNK
    assert same_arrays([(a, a.copy()), (a[:5], a[:5].copy())])


@pytest.mark.parametrize("where", [0, CHUNK // 8 - 1, CHUNK // 8, -1])
def test_one_value_changed_anywhere_is_seen(where):
    # The first and last value, and either side of a slice's edge.
    a = big()
    b = a.copy()
    b.reshape(-1)[where] += 1
    assert not same_arrays([(a, b)])
    assert not same_arrays([(a[:3], a[:3].copy()), (a, b)])     # after an equal pair too


def test_another_dtype_or_shape_is_not_the_same():
    a = big()
    assert not same_arrays([(a, a.astype(np.float32))])
    assert not same_arrays([(a, a.reshape(-1))])
    assert not same_arrays([(np.zeros(3, np.int64), np.zeros(3, np.int32))])


def test_a_strided_view_is_compared_by_value():
    a = big()
    assert same_arrays([(a[:, 1], a.copy()[:, 1])])
    b = a.copy()
    b[-1, 1] = -1
    assert not same_arrays([(a[:, 1], b[:, 1])])


def test_bytes_are_compared_so_minus_zero_is_not_zero():
    # Equal bytes are equal values; where only the bytes differ the caller makes again what
    # it would have kept (never the reverse).
    assert not same_arrays([(np.zeros(4), -np.zeros(4))])
    a = np.zeros(2 * CHUNK // 8 + 3)
    b = a.copy()
    b[-2] = -0.0
    assert not same_arrays([(a, b)])


def test_no_pairs_are_the_same():
    assert same_arrays([])
