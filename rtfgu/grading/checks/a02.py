"""a02: cameras (lecture 01, "Orthographic Camera"; 02562 week 1, the pinhole camera). The
probes are in rtfgu/grading/probes/a02.py (visible) and a02_hidden.py."""
from __future__ import annotations

from . import Check, image_check, register


def hint_ortho(inputs, want, got):
    o_want, o_got = want["origin"], got.get("origin")
    if not isinstance(o_got, list):
        return None
    left, right, bottom, top = inputs["camera"][:4]
    dx, dy = o_got[0] - o_want[0], o_got[1] - o_want[1]
    if abs(dx) < 1e-12 and abs(dy) < 1e-12:
        return None
    fx, fy = dx / (right - left), dy / (top - bottom)
    text = ("the ray starts %g to the side and %g up from the pixel centre (%g%% and %g%% of the image): "
            "the camera itself must add no offset, since sx and sy already point at the pixel's centre, "
            "sx = 2 (ix + 0.5) / width - 1; x = left + (right - left) (0.5 + sx / 2)"
            % (dx, dy, 100 * fx, 100 * fy))
    if abs(fx) > 1e-12 and abs(fx - fy) < 1e-9:
        pixels = 1.0 / (2.0 * abs(fx))
        if abs(pixels - round(pixels)) < 1e-6:
            text += ". The shift is exactly half a pixel of a %d-pixel image: a half-pixel offset" % round(pixels)
    return text


def hint_pinhole(inputs, want, got):
    length = got.get("direction length")
    if isinstance(length, float) and abs(length - 1.0) > 1e-6:
        return "the direction has length %.6g: normalize q before you put it in the ray" % length
    return None


register("a02_cameras", [
    Check("OrthographicCamera.gen_ray: ray origin, direction and interval at pixel centres", 3,
          ("a02", "observe_ortho"), hint=hint_ortho, needs=("cameras/orthographic.py",)),
    Check("PinholeCamera.gen_ray: unit directions through the image plane", 3, ("a02", "observe_pinhole"),
          hint=hint_pinhole, needs=("cameras/pinhole.py",)),
    image_check("image: ray origins of the lecture 01 orthographic camera", 1, "lecture01_flat_colors",
                render="a02.ray_origin_image", needs=("cameras/orthographic.py",)),
    image_check("image: ray directions of the 02562 default camera", 1, "default_ray_directions"),
    # ### BEGIN HIDDEN
    Check("orthographic cameras with other bounds, hither and yon", 1, ("a02_hidden", "observe_ortho_hidden"),
          visibility="hidden", hint=hint_ortho, needs=("cameras/orthographic.py",)),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    Check("pinhole cameras with other eyes, camera constants and aspect ratios", 1,
          ("a02_hidden", "observe_pinhole_hidden"), visibility="hidden", hint=hint_pinhole,
          needs=("cameras/pinhole.py",)),
    # ### END HIDDEN
])
