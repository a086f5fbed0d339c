"""rtfgu.show: the fastest backend this installation has, a notebook display updated pass by
pass with the samples done and the time left, and outside a notebook a PNG whose path it
prints. (notebooks/first_render.ipynb itself runs as a test through pytest --nbmake.)"""
from __future__ import annotations

import importlib.util
import sys
import types

import numpy as np

import rtfgu
from rtfgu import notebook
from rtfgu.image import read_png, to_8bit
from rtfgu.scenes import get_scene


def test_outside_a_notebook_show_writes_the_image_and_says_where(tmp_path, monkeypatch, capsys):
    assert notebook.in_notebook() is False          # IPython may be installed: no kernel runs here
    monkeypatch.setitem(sys.modules, "IPython", None)   # and where it is not installed at all
    assert notebook.in_notebook() is False
    monkeypatch.chdir(tmp_path)
    scene = get_scene("default_phong_sphere")()
    image = rtfgu.show(scene, 24, 16)
    printed = capsys.readouterr().out
    assert "rtfgu.show: wrote rtfgu_show.png (24x16, 1 sample, numba backend" in printed, printed
    assert np.array_equal(read_png(tmp_path / "rtfgu_show.png"), to_8bit(image))
    assert np.array_equal(image, rtfgu.render(scene, 24, 16, backend="numba"))
    rtfgu.show(scene, 24, 16, backend="reference", out=tmp_path / "mine.png")
    assert "wrote %s" % (tmp_path / "mine.png") in capsys.readouterr().out


def test_the_best_backend_is_numba_where_the_kernels_are_and_the_lecture_layer_where_not(monkeypatch):
    assert notebook.best_backend() == "numba"
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *a: None if name == "rtfgu.kernels" else real(name, *a))
    assert notebook.best_backend() == "reference"          # a student release leaves the kernels out


def test_in_a_notebook_show_updates_one_picture_and_a_caption_per_pass(monkeypatch):
    shown = []

    class Handle:
        def __init__(self, kind):
            self.kind = kind

        def update(self, value):
            shown.append(("update", self.kind, value))

    def display(value, display_id=False):
        kind = "caption" if isinstance(value, Pretty) else "picture"
        shown.append(("display", kind, value))
        return Handle(kind)

    class Pretty(str):
        pass

    fake = types.ModuleType("IPython.display")
    fake.display, fake.Pretty = display, Pretty
    monkeypatch.setitem(sys.modules, "IPython.display", fake)
    monkeypatch.setattr(notebook, "in_notebook", lambda: True)
    scene = get_scene("default_antialiasing_4")()
    final = rtfgu.show(scene, 16, 16, backend="numba", spp=16, passes=4)
    assert [(a, k) for a, k, _ in shown] == [("display", "picture"), ("display", "caption")] + \
        [("update", "picture"), ("update", "caption")] * 3
    captions = [v for a, k, v in shown if k == "caption"]
    assert [c.split(",")[0] for c in captions] == ["4 of 16 samples", "8 of 16 samples", "12 of 16 samples",
                                                   "16 of 16 samples"]
    assert captions[0].endswith("estimating the time left (numba)") and captions[-1].endswith("done (numba)")
    assert " s left (numba)" in captions[1]
    last = [v for a, k, v in shown if k == "picture"][-1]
    assert np.array_equal(np.asarray(last), to_8bit(final))
    assert np.array_equal(final, rtfgu.render(scene, 16, 16, backend="numba", spp=16))
