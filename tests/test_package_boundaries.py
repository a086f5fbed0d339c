"""The renderer stands on its own: rendering on every path, the command line and the
benchmark scenes never import the course tools (rtfgu.grading), and the lecture layer
imports neither numba nor wgpu."""
from __future__ import annotations

import subprocess
import sys

SCRIPT = r"""
import sys
import rtfgu
from rtfgu.scenes import SCENES
scene = SCENES["suffern_disks"]()
rtfgu.render(scene, 4, 4)
lecture_only = sorted(m for m in ("numba", "wgpu") if m in sys.modules)
rtfgu.render(scene, 4, 4, backend="numba")
try:
    rtfgu.render(scene, 4, 4, backend="wgpu")
except Exception as error:  # no adapter: the import boundary is what is tested here
    print("wgpu:", type(error).__name__, file=sys.stderr)
import rtfgu.__main__  # noqa: F401
print(",".join(lecture_only))
print(",".join(sorted(m for m in sys.modules if m.startswith("rtfgu.grading"))))
"""


def test_rendering_imports_no_grading_code_and_the_lecture_layer_no_numba_or_wgpu():
    done = subprocess.run([sys.executable, "-c", SCRIPT], capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stderr
    lecture_only, grading = done.stdout.split("\n")[-3:-1]
    assert lecture_only == "", "the lecture layer imported %s" % lecture_only
    assert grading == "", "the renderer imported %s" % grading
