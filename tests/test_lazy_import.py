"""numpy imported at its first use (rtfgu.lazy_import): ``import rtfgu`` and what a graded
test's interpreter imports load no numpy, and a name read through the stand-in is numpy's
own, from any thread."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from rtfgu.grading.probes.boot import SUBMODULES
from rtfgu.grading.sandbox import _site_dirs

ROOT = Path(__file__).resolve().parent.parent


def _fresh(code: str) -> dict:
    """What ``code`` (which sets ``out``) gives in a new interpreter started as a graded
    test's is (-I -S, the package and the site-packages on the path)."""
    head = "import sys, json\nsys.path[:0] = %r\n" % ([str(ROOT)] + _site_dirs())
    tail = "\nprint(json.dumps(out))\n"
    done = subprocess.run([sys.executable, "-I", "-S", "-c", head + code + tail], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout.splitlines()[-1])


def test_the_package_and_a_graded_tests_modules_import_no_numpy():
    out = _fresh("import importlib\n"
                 "import rtfgu\n"
                 "loaded = {'rtfgu': 'numpy' in sys.modules}\n"
                 "for name in %r:\n"
                 "    importlib.import_module('rtfgu.' + name)\n"
                 "    loaded[name] = 'numpy' in sys.modules\n"
                 "out = loaded\n" % (SUBMODULES,))
    assert out.pop("rtfgu") is False
    assert [name for name, loaded in out.items() if loaded] == []
    assert set(out) == set(SUBMODULES)


def test_a_lecture_render_of_a_mesh_loads_numpy_when_it_needs_it():
    # The stand-in is not a dead end: a mesh's arrays and the image are numpy's.
    out = _fresh("import rtfgu\n"
                 "from rtfgu.scenes import meshes\n"
                 "before = 'numpy' in sys.modules\n"
                 "scene = meshes.bunny()\n"
                 "image = rtfgu.render(scene, 4, 4)\n"
                 "import numpy\n"
                 "out = [before, type(image).__module__, bool(numpy.isfinite(image).all()), list(image.shape)]\n")
    assert out == [False, "numpy", True, [4, 4, 3]]


def test_names_read_from_many_threads_at_once_are_numpys_own():
    out = _fresh("import threading\n"
                 "from rtfgu.lazy_import import numpy as np\n"
                 "names = ['ndarray', 'float32', 'float64', 'asarray', 'linalg', 'errstate', 'uint8', 'zeros'] * 4\n"
                 "got = [None] * len(names)\n"
                 "start = threading.Barrier(len(names))\n"
                 "def read(i):\n"
                 "    start.wait()\n"
                 "    got[i] = getattr(np, names[i])\n"
                 "threads = [threading.Thread(target=read, args=(i,)) for i in range(len(names))]\n"
                 "[t.start() for t in threads]\n"
                 "[t.join() for t in threads]\n"
                 "import numpy\n"
                 "out = {'same': [g is getattr(numpy, n) for g, n in zip(got, names)],\n"
                 "       'kept': sorted(set(names) - set(vars(np))),\n"
                 "       'module': sys.modules['numpy'] is numpy and type(numpy).__name__}\n")
    assert out["same"] == [True] * 32
    assert out["kept"] == []          # each name read once is then the stand-in's own attribute
    assert out["module"] == "module"  # sys.modules holds numpy itself, not the stand-in


def test_a_name_numpy_lacks_is_an_attribute_error_naming_it():
    from rtfgu.lazy_import import OnFirstUse
    with pytest.raises(AttributeError, match="no_such_name"):
        OnFirstUse("numpy").no_such_name
    with pytest.raises(ModuleNotFoundError, match="no_such_module_here"):
        OnFirstUse("no_such_module_here").anything
