"""The numba path gives the same bits for any thread count, and the kernels run as plain
Python (NUMBA_DISABLE_JIT=1) to the same image, which catches what compiled code hides."""
from __future__ import annotations

import os
import subprocess
import sys

import numpy as np

from rtfgu.renderer import render
from rtfgu.scenes import SCENES

RENDER_SCRIPT = r"""
import sys
import numba
import numpy as np
from rtfgu.renderer import render
from rtfgu.scenes import SCENES
name, width, height, precision, out, formula = sys.argv[1:7]
image = render(SCENES[name](), int(width), int(height), backend="numba", precision=precision,
               formula=None if formula == "default" else formula)
np.save(out, image)
print(numba.config.DISABLE_JIT, numba.config.NUMBA_NUM_THREADS)
"""


def render_in_subprocess(tmp_path, env_overrides, name, width, height, precision,
                         formula="default"):
    out = tmp_path / ("%s_%s_%s_%s.npy" % (name, precision, formula, "_".join(
        "%s%s" % kv for kv in sorted(env_overrides.items()))))
    env = dict(os.environ, **env_overrides)
    done = subprocess.run([sys.executable, "-c", RENDER_SCRIPT, name, str(width), str(height),
                           precision, str(out), formula], env=env, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return np.load(out), done.stdout.split()


def test_one_and_two_threads_agree_bit_for_bit(tmp_path):
    # The glossy scene exercises every kind of ray: primary, shadow, reflected, refracted;
    # the depth-of-field scene the random stream (64 samples per pixel and a thin lens).
    for name, precision in (("default_glossy_sphere", "float64"), ("default_glossy_sphere", "float32"),
                            ("suffern_depth_of_field", "float32")):
        one, said_one = render_in_subprocess(tmp_path, {"NUMBA_NUM_THREADS": "1"},
                                             name, 48, 48, precision)
        two, said_two = render_in_subprocess(tmp_path, {"NUMBA_NUM_THREADS": "2"},
                                             name, 48, 48, precision)
        assert said_one[1] == "1" and said_two[1] == "2"
        assert one.tobytes() == two.tobytes()


def test_kernels_run_without_jit_to_the_same_image(tmp_path):
    # Tiny, since every kernel then runs as Python; the scene has planes, a triangle, a
    # sphere, a light with shadow rays, Phong and refraction. The slide sphere formula, the
    # reference's, so that the images agree bit for bit.
    name, width, height = "default_glossy_sphere", 10, 10
    plain, said = render_in_subprocess(tmp_path, {"NUMBA_DISABLE_JIT": "1"}, name, width,
                                       height, "float64", formula="slide")
    assert said[0] in ("1", "True")
    compiled = render(SCENES[name](), width, height, backend="numba", precision="float64",
                      formula="slide")
    reference = render(SCENES[name](), width, height, backend="reference")
    assert plain.tobytes() == compiled.tobytes()
    assert np.array_equal(plain, reference)
