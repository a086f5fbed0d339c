"""The lecture-01 render loop ("Rendering a Scene") transcribed here, compared pixel for pixel
with rtfgu.render; and the image orientation: +y is row 0 of the array and the PNG's top row."""
from __future__ import annotations

import numpy as np
import pytest

import rtfgu
from rtfgu import Float3, OrthographicCamera, Plane, Scene, Triangle
from rtfgu.image import read_png, write_png
from rtfgu.scenes import SCENES


def slide_render(scene, image_width, image_height):
    """The slide, line for line. The slide's image[ix, iy] counts iy up from the bottom
    (sy = -1 is the bottom of the image plane); a numpy image stores row 0 at the top, so
    pixel (ix, iy) goes to row image_height - 1 - iy."""
    image = np.zeros((image_height, image_width, 3))
    for iy in range(image_height):
        for ix in range(image_width):
            sx = 2 * (ix + 0.5) / image_width - 1
            sy = 2 * (iy + 0.5) / image_height - 1

            ray = scene.camera.gen_ray(sx, sy)

            hit_shape = None
            for shape in scene.shapes:
                if shape.intersect_p(ray):
                    hit_shape = shape

            color = hit_shape.color if hit_shape is not None else scene.background
            image[image_height - 1 - iy, ix] = (color.x, color.y, color.z)
    return image


def distinct_colours(image):
    return {tuple(p) for p in image.reshape(-1, 3)}


@pytest.mark.parametrize("name, width, height", [
    ("lecture01_flat_colors", 48, 48),
    ("lecture01_flat_colors", 40, 24),      # not square, not a multiple of the other
    ("default_flat_colors", 32, 32),
])
def test_render_equals_the_slide_loop(name, width, height):
    expected = slide_render(SCENES[name](), width, height)
    got = rtfgu.render(SCENES[name](), width, height)
    assert got.shape == (height, width, 3)
    assert got.dtype == np.float64
    # every shape and the background show up, so the comparison is not of a blank image
    assert len(distinct_colours(expected)) >= 4
    mismatch = np.argwhere(np.any(got != expected, axis=2))
    assert mismatch.size == 0, "pixels (row, column) differ from the slide loop: %s" % mismatch[:10].tolist()


def test_lecture01_scene_is_built_as_on_the_slides():
    # a camera and coloured shapes, nothing else: no lights, every shape shows its colour flat
    scene = SCENES["lecture01_flat_colors"]()
    assert isinstance(scene.camera, OrthographicCamera)
    assert scene.lights == []
    assert all(s.material.shader == rtfgu.BASE_COLOR for s in scene.shapes)


# --- orientation ---------------------------------------------------------------------

RED = (1.0, 0.0, 0.0)
BLUE = (0.0, 0.0, 1.0)


def half_and_half(upper: bool):
    """A blue backdrop and a red triangle covering y > 0 (upper) or x > 0 (not upper) of the
    camera's [-1, 1]^2 window; at height y it spans |x| <= 3 - 0.6 y, wider than the window."""
    scene = Scene(OrthographicCamera(-1, 1, -1, 1))
    scene.shapes.append(Plane(Float3(0, 0, -1), Float3(0, 0, 1), Float3(*BLUE)))
    v = [(-3, 0), (3, 0), (0, 5)]
    if not upper:
        v = [(y, -x) for x, y in v]  # turned a quarter clockwise: +y becomes +x
    scene.shapes.append(Triangle(*(Float3(a, b, -0.5) for a, b in v), Float3(*RED)))
    return scene


def test_plus_y_is_row_zero_and_the_top_of_the_png(tmp_path):
    image = rtfgu.render(half_and_half(upper=True), 6, 8)
    assert np.all(image[:4] == RED), "the upper half (y > 0) must be rows 0..3"
    assert np.all(image[4:] == BLUE)
    path = tmp_path / "top_half.png"
    write_png(image, path)
    png = read_png(path)
    assert png.shape == (8, 6, 3)
    assert np.all(png[:4] == (255, 0, 0)), "the top rows of the PNG must be the +y half"
    assert np.all(png[4:] == (0, 0, 255))


def test_plus_x_is_the_right_of_the_image(tmp_path):
    image = rtfgu.render(half_and_half(upper=False), 8, 6)
    assert np.all(image[:, 4:] == RED), "the right half (x > 0) must be columns 4..7"
    assert np.all(image[:, :4] == BLUE)
    path = tmp_path / "right_half.png"
    write_png(image, path)
    png = read_png(path)
    assert np.all(png[:, 4:] == (255, 0, 0)) and np.all(png[:, :4] == (0, 0, 255))


def test_write_png_applies_gamma_and_clamps(tmp_path):
    # 8-bit value = round(255 * clamp(v, 0, 1) ** (1 / 2.2)); 0.5 -> 186, 0.2 -> 123
    image = np.array([[[0.5, 0.2, 0.0], [2.0, -1.0, 1.0]]])
    path = tmp_path / "gamma.png"
    write_png(image, path)
    png = read_png(path)
    assert png.dtype == np.uint8
    assert png[0, 0].tolist() == [186, 123, 0]
    assert png[0, 1].tolist() == [255, 0, 255]
