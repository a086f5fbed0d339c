"""The command line, run as a user runs it: ``python -m rtfgu ...`` in a fresh process."""
from __future__ import annotations

import subprocess
import sys

import numpy as np

import rtfgu
from rtfgu.image import read_png, to_8bit
from rtfgu.scenes import SCENES


def run(*args, cwd):
    return subprocess.run([sys.executable, "-m", "rtfgu", *args], cwd=cwd,
                          capture_output=True, text=True, timeout=120)


def test_list_prints_every_scene_name(tmp_path):
    done = run("list", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == list(SCENES)


def test_render_writes_a_png_of_the_asked_size(tmp_path):
    out = tmp_path / "out.png"
    done = run("render", "lecture01_flat_colors", "-o", str(out), "--width", "16", "--height", "16",
               cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert read_png(out).shape == (16, 16, 3)
    assert str(out) in done.stdout


def test_render_reference_backend_writes_the_rendered_pixels(tmp_path):
    out = tmp_path / "out.png"
    done = run("render", "lecture01_flat_colors", "-o", str(out), "--width", "16", "--height", "16",
               "--backend", "reference", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    # the same pixels as rendering in this process and writing with gamma
    expected = to_8bit(rtfgu.render(SCENES["lecture01_flat_colors"](), 16, 16))
    assert np.array_equal(read_png(out), expected)
    assert "100%" in done.stderr  # the progress bar reached the last row


def test_render_with_spp_draws_a_bar_per_pass_and_writes_the_sampled_image(tmp_path):
    out = tmp_path / "aa.png"
    done = run("render", "default_lambertian_shadows", "-o", str(out), "--width", "12",
               "--height", "12", "--backend", "numba", "--spp", "16", "--seed", "3", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    expected = to_8bit(rtfgu.render(SCENES["default_lambertian_shadows"](), 12, 12,
                                    backend="numba", spp=16, seed=3))
    assert np.array_equal(read_png(out), expected)
    assert not np.array_equal(expected, to_8bit(rtfgu.render(
        SCENES["default_lambertian_shadows"](), 12, 12, backend="numba")))
    assert "[" + "#" * 30 + "] 100%" in done.stderr


def test_a_bad_spp_exits_2_and_names_it(tmp_path):
    done = run("render", "default_lambertian", "--spp", "0", "-o", str(tmp_path / "x.png"), cwd=tmp_path)
    assert done.returncode == 2
    assert "spp" in done.stderr and "Traceback" not in done.stderr


def test_render_non_square(tmp_path):
    out = tmp_path / "wide.png"
    done = run("render", "default_flat_colors", "-o", str(out), "--width", "12", "--height", "5",
               cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert read_png(out).shape == (5, 12, 3)


def test_unknown_scene_exits_2_and_names_it(tmp_path):
    out = tmp_path / "never.png"
    done = run("render", "no_such_scene", "-o", str(out), "--width", "4", "--height", "4",
               cwd=tmp_path)
    assert done.returncode == 2
    assert "no_such_scene" in done.stderr
    assert "Traceback" not in done.stderr
    assert not out.exists()


def test_bad_size_exits_2_and_names_it(tmp_path):
    for option, value in (("--width", "0"), ("--height", "-2"), ("--width", "1.5")):
        out = tmp_path / "never.png"
        args = {"--width": "4", "--height": "4"}
        args[option] = value
        done = run("render", "lecture01_flat_colors", "-o", str(out),
                   "--width", args["--width"], "--height", args["--height"], cwd=tmp_path)
        assert done.returncode == 2, (option, value, done.stderr)
        assert option.lstrip("-") in done.stderr, done.stderr
        assert "Traceback" not in done.stderr
        assert not out.exists()


def test_no_command_exits_2(tmp_path):
    assert run(cwd=tmp_path).returncode == 2


def test_the_time_left_comes_from_the_passes_after_the_first_which_holds_compiling(monkeypatch):
    # A 16-pass render whose first pass took 20 s (19 s of it compiling) and the others 1 s
    # each: after the second pass 14 s are left, not 20 s x 14 passes.
    import io

    import rtfgu.__main__ as cli

    clock = iter([0.0, 20.0, 21.0, 35.0])
    monkeypatch.setattr(cli.time, "perf_counter", lambda: next(clock))
    stream = io.StringIO()
    progress = cli._progress_printer("scene", stream)
    progress(1, 16)
    assert stream.getvalue().endswith("6%  20.0 s, estimating the time left")
    progress(2, 16)
    assert stream.getvalue().endswith("12%  21.0 s, 14.0 s left")
    progress(16, 16)
    assert stream.getvalue().endswith("100%  35.0 s, done\n")


def test_the_first_render_on_a_compiling_backend_says_so_before_it_starts(tmp_path):
    done = run("render", "lecture01_flat_colors", "-o", str(tmp_path / "a.png"), "--width", "8", "--height", "8",
               "--backend", "numba", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stderr.startswith("numba: compiling the kernels this scene needs, or loading them from "
                                  "numba's cache (about 20 s the first time)")
    assert done.stderr.count("compiling") == 1
    done = run("render", "lecture01_flat_colors", "-o", str(tmp_path / "b.png"), "--width", "8", "--height", "8",
               "--backend", "reference", cwd=tmp_path)
    assert done.returncode == 0 and "compiling" not in done.stderr, done.stderr
