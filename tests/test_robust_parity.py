"""One operation sequence per formula: the lecture layer (rtfgu.shapes, rtfgu.robust) and the
numba float64 kernels (rtfgu.kernels.intersect, rtfgu.kernels.robust) round alike, bit for
bit, on every ray of every hard-case family, for the slide and the robust formulas and for
the origins of spawned rays."""
from __future__ import annotations

import numpy as np
import pytest

from rtfgu.hardcases import FAMILIES, NumbaPath, ReferencePath, build, runs
from rtfgu.hardcases.evaluate import closest


def _spawned(path, family):
    s = family.spawn
    return path.spawn(family.kind, s["positions"], s["normals"], s["directions"], family.shapes[0])


@pytest.mark.parametrize("formula", ["slide", "robust"])
@pytest.mark.parametrize("name", [n for n, spec in FAMILIES.items() if spec.group != "invalid"])
def test_numba_float64_is_the_lecture_layer_bit_for_bit(name, formula):
    family = build(name, "float64")
    reference, numba = ReferencePath(formula), NumbaPath(formula, "float64")
    if not runs(family, reference):
        pytest.skip("%s has no %s formula" % (family.kind, formula))
    if family.spawn is not None:
        (ref_origins, ref_tmin), (nb_origins, nb_tmin) = _spawned(reference, family), _spawned(numba, family)
        assert np.array_equal(ref_origins, nb_origins) and np.array_equal(ref_tmin, nb_tmin)
    else:
        ref_origins, ref_tmin = nb_origins, nb_tmin = family.origins, family.tmin
    try:
        expected = closest(reference, family, ref_origins, ref_tmin)
    except ValueError:
        assert name == "tri_zero_area" and formula == "slide"  # the lecture's Triangle refuses it
        return
    got = closest(numba, family, nb_origins, nb_tmin)
    differ = np.flatnonzero(expected.view(np.int64) != got.view(np.int64))
    assert differ.size == 0, "%d of %d rays differ, first %d: reference %r, numba %r" % (
        differ.size, family.size, differ[0], expected[differ[0]], got[differ[0]])
