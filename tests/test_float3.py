"""Float3 against the lecture-01 "Float3 Structure" slides, values worked out by hand."""
from __future__ import annotations

import math

import pytest

from rtfgu import Float3, cross, dot, normalize


def components(v):
    return (v.x, v.y, v.z)


# --- constructors: Float3(), Float3(c), Float3(x, y, z) ---------------------------------

def test_default_constructor_is_zero():
    assert components(Float3()) == (0.0, 0.0, 0.0)


def test_one_argument_fills_all_three():
    assert components(Float3(2.5)) == (2.5, 2.5, 2.5)
    # The slide also has Float3(int i) and Float3(double x): the components are floats.
    v = Float3(3)
    assert components(v) == (3.0, 3.0, 3.0)
    assert all(type(c) is float for c in components(v))


def test_three_arguments():
    assert components(Float3(1, -2, 3.5)) == (1.0, -2.0, 3.5)


# --- the union's aliases, read and write -----------------------------------------------

ALIASES = [("x", "y", "z"), ("r", "g", "b"), ("s", "t", "u"), ("alpha", "beta", "gamma")]


@pytest.mark.parametrize("names", ALIASES, ids=["xyz", "rgb", "stu", "alpha_beta_gamma"])
def test_alias_read(names):
    v = Float3(1, 2, 3)
    assert tuple(getattr(v, n) for n in names) == (1.0, 2.0, 3.0)


@pytest.mark.parametrize("names", ALIASES, ids=["xyz", "rgb", "stu", "alpha_beta_gamma"])
def test_alias_write_shares_storage(names):
    # In the C++ union every view is the same memory: writing r is writing x and d[0].
    v = Float3(1, 2, 3)
    for i, n in enumerate(names):
        setattr(v, n, 10.0 * (i + 1))
    assert components(v) == (10.0, 20.0, 30.0)
    assert (v[0], v[1], v[2]) == (10.0, 20.0, 30.0)
    for other in ALIASES:
        assert tuple(getattr(v, n) for n in other) == (10.0, 20.0, 30.0)


# --- operator[] ----------------------------------------------------------------------

def test_index_get_and_set():
    v = Float3(4, 5, 6)
    assert (v[0], v[1], v[2]) == (4.0, 5.0, 6.0)
    v[0] = -1
    v[1] = -2
    v[2] = -3
    assert components(v) == (-1.0, -2.0, -3.0)


def test_index_out_of_range():
    v = Float3(1, 2, 3)
    with pytest.raises(IndexError):
        v[3]
    with pytest.raises(IndexError):
        v[3] = 1.0


# --- compound assignment: += -= *= /= with a vector or a scalar ----------------------------

def test_iadd_vector_and_scalar():
    v = Float3(1, 2, 3)
    same = v
    v += Float3(10, 20, 30)
    assert components(v) == (11.0, 22.0, 33.0)
    v += 1
    assert components(v) == (12.0, 23.0, 34.0)
    assert v is same  # in place, like "return *this"


def test_isub_vector_and_scalar():
    v = Float3(10, 20, 30)
    same = v
    v -= Float3(1, 2, 3)
    assert components(v) == (9.0, 18.0, 27.0)
    v -= 2
    assert components(v) == (7.0, 16.0, 25.0)
    assert v is same


def test_imul_vector_and_scalar():
    v = Float3(1, 2, 3)
    same = v
    v *= Float3(2, 3, 4)
    assert components(v) == (2.0, 6.0, 12.0)
    v *= 0.5
    assert components(v) == (1.0, 3.0, 6.0)
    assert v is same


def test_idiv_vector_and_scalar():
    v = Float3(8, 6, 4)
    same = v
    v /= Float3(2, 3, 4)
    assert components(v) == (4.0, 2.0, 1.0)
    v /= 4
    assert components(v) == (1.0, 0.5, 0.25)
    assert v is same


# --- arithmetic ----------------------------------------------------------------------

def test_add_sub_neg_leave_operands_unchanged():
    a = Float3(1, 2, 3)
    b = Float3(0.5, -1, 4)
    assert components(a + b) == (1.5, 1.0, 7.0)
    assert components(a - b) == (0.5, 3.0, -1.0)
    assert components(-a) == (-1.0, -2.0, -3.0)
    assert components(a) == (1.0, 2.0, 3.0)
    assert components(b) == (0.5, -1.0, 4.0)


def test_mul_componentwise_and_scalar_on_either_side():
    a = Float3(1, 2, 3)
    assert components(a * Float3(4, 5, 6)) == (4.0, 10.0, 18.0)
    assert components(a * 2) == (2.0, 4.0, 6.0)
    # "inline Float3 operator*(float f, const Float3 &v) { return v*f; }"
    assert components(2 * a) == (2.0, 4.0, 6.0)
    assert components(a) == (1.0, 2.0, 3.0)


def test_div_componentwise():
    assert components(Float3(1, 4, 9) / Float3(2, 8, 3)) == (0.5, 0.5, 3.0)


def test_div_by_scalar_multiplies_by_the_reciprocal():
    # The slide: inv = 1.0f / x; return Float3(d[0] * inv, ...). In binary floating point
    # 3 * (1/10) is 0.30000000000000004 while 3 / 10 is 0.3, so the form is observable.
    v = Float3(3, 7, 0.5) / 10
    assert components(v) == (0.30000000000000004, 0.7000000000000001, 0.05)
    assert v.x != 3 / 10  # plain division would give a different x


def test_length_squared_and_length():
    v = Float3(2, -3, 6)
    assert v.length_squared() == 49.0
    assert v.length() == 7.0


def test_normalize():
    n = normalize(Float3(0, 3, 4))
    assert n.x == 0.0
    assert n.y == pytest.approx(0.6, abs=1e-15)
    assert n.z == pytest.approx(0.8, abs=1e-15)
    assert n.length() == pytest.approx(1.0, abs=1e-15)


def test_dot():
    assert dot(Float3(1, 2, 3), Float3(4, -5, 6)) == 4 - 10 + 18
    assert dot(Float3(1, 0, 0), Float3(0, 1, 0)) == 0.0


def test_cross():
    # Right-handed: x cross y = z, y cross z = x, z cross x = y, and anticommutative.
    assert components(cross(Float3(1, 0, 0), Float3(0, 1, 0))) == (0.0, 0.0, 1.0)
    assert components(cross(Float3(0, 1, 0), Float3(0, 0, 1))) == (1.0, 0.0, 0.0)
    assert components(cross(Float3(0, 0, 1), Float3(1, 0, 0))) == (0.0, 1.0, 0.0)
    # (1,2,3) x (4,5,6) = (2*6 - 3*5, 3*4 - 1*6, 1*5 - 2*4) = (-3, 6, -3)
    assert components(cross(Float3(1, 2, 3), Float3(4, 5, 6))) == (-3.0, 6.0, -3.0)
    assert components(cross(Float3(4, 5, 6), Float3(1, 2, 3))) == (3.0, -6.0, 3.0)


def test_cross_is_perpendicular_with_parallelogram_length():
    a = Float3(2, 0, 0)
    b = Float3(1, 3, 0)
    c = cross(a, b)
    assert dot(c, a) == 0.0 and dot(c, b) == 0.0
    assert c.length() == 6.0  # |a||b| sin(theta) = base 2 * height 3


def test_no_nan_from_normal_use():
    v = normalize(Float3(1e-150, 0, 0))
    assert math.isfinite(v.x) and v.x == pytest.approx(1.0)
