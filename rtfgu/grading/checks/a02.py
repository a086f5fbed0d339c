"""a02: cameras (lecture 01, "Orthographic Camera"; 02562 week 1, the pinhole camera)."""
from __future__ import annotations

from . import Check, image_check, register
from .child import Cases, num, vec

PIXEL_CENTRES = [(-0.75, -0.75), (0.25, -0.25), (0.75, 0.75), (-0.25, 0.75), (0.0, 0.0)]


def _ray_out(ray):
    return {"origin": vec(ray.origin, "ray.origin"), "direction": vec(ray.direction, "ray.direction"),
            "tmin": num(ray.tmin, "ray.tmin"), "tmax": num(ray.tmax, "ray.tmax")}


def _ortho_cases(rt, cameras):
    cases = Cases()
    for args in cameras:
        for sx, sy in PIXEL_CENTRES:
            def run(args=args, sx=sx, sy=sy):
                return _ray_out(rt.OrthographicCamera(*args).gen_ray(sx, sy))
            cases.run("OrthographicCamera%s.gen_ray(%g, %g)" % (tuple(args), sx, sy), run,
                      camera=list(args), sx=sx, sy=sy)
    return cases.result()


def observe_ortho(rt):
    return _ortho_cases(rt, [(-2.0, 2.0, -1.0, 1.0)])


def _origin_image(rt, scene, width, height):
    """Each pixel's ray origin as a colour: (x, y) mapped from [left, right] x [bottom, top]
    to red and green. It shows the orthographic camera alone (the lecture 01 scene's shapes
    need assignment 3's intersections)."""
    import numpy as np

    camera = scene.camera
    image = np.zeros((height, width, 3))
    for iy in range(height):
        for ix in range(width):
            ray = camera.gen_ray(2 * (ix + 0.5) / width - 1, 2 * (iy + 0.5) / height - 1)
            image[height - 1 - iy, ix] = ((ray.origin.x - camera.left) / (camera.right - camera.left),
                                          (ray.origin.y - camera.bottom) / (camera.top - camera.bottom),
                                          0.5 + 0.5 * ray.direction.z)
    return image


# ### BEGIN HIDDEN
def observe_ortho_hidden(rt):
    return _ortho_cases(rt, [(0.0, 4.0, -3.0, 3.0, 0.5, 10.0), (-1.0, 1.0, -1.0, 1.0, 1e-5, 100.0)])
# ### END HIDDEN


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


def _pinhole_cases(rt, cameras):
    cases = Cases()
    F = rt.Float3
    for eye, lookat, up, d, aspect in cameras:
        for sx, sy in PIXEL_CENTRES:
            def run(eye=eye, lookat=lookat, up=up, d=d, aspect=aspect, sx=sx, sy=sy):
                camera = rt.PinholeCamera(F(*eye), F(*lookat), F(*up), d=d, aspect=aspect)
                out = _ray_out(camera.gen_ray(sx, sy))
                del out["tmin"], out["tmax"]
                out["direction length"] = sum(c * c for c in out["direction"]) ** 0.5
                return out
            cases.run("PinholeCamera(eye=%s, lookat=%s, d=%g, aspect=%g).gen_ray(%g, %g)"
                      % (eye, lookat, d, aspect, sx, sy), run)
    return cases.result()


def observe_pinhole(rt):
    return _pinhole_cases(rt, [((2.0, 1.5, 2.0), (0.0, 0.5, 0.0), (0.0, 1.0, 0.0), 1.0, 1.0)])


# ### BEGIN HIDDEN
def observe_pinhole_hidden(rt):
    return _pinhole_cases(rt, [((0.0, 0.0, 5.0), (0.0, 0.0, 0.0), (0.0, 1.0, 0.0), 2.0, 16 / 9),
                               ((-1.0, 3.0, 1.0), (1.0, 0.0, -2.0), (0.0, 1.0, 0.0), 1.5, 0.75)])
# ### END HIDDEN


def hint_pinhole(inputs, want, got):
    length = got.get("direction length")
    if isinstance(length, float) and abs(length - 1.0) > 1e-6:
        return "the direction has length %.6g: normalize q before you put it in the ray" % length
    return None


register("a02_cameras", [
    Check("OrthographicCamera.gen_ray: ray origin, direction and interval at pixel centres", 3,
          observe_ortho, hint=hint_ortho, needs=("cameras/orthographic.py",)),
    Check("PinholeCamera.gen_ray: unit directions through the image plane", 3, observe_pinhole,
          hint=hint_pinhole, needs=("cameras/pinhole.py",)),
    image_check("image: ray origins of the lecture 01 orthographic camera", 1, "lecture01_flat_colors",
                render=_origin_image, needs=("cameras/orthographic.py",)),
    image_check("image: ray directions of the 02562 default camera", 1, "default_ray_directions"),
    # ### BEGIN HIDDEN
    Check("orthographic cameras with other bounds, hither and yon", 1, observe_ortho_hidden,
          visibility="hidden", hint=hint_ortho, needs=("cameras/orthographic.py",)),
    # ### END HIDDEN
    # ### BEGIN HIDDEN
    Check("pinhole cameras with other eyes, camera constants and aspect ratios", 1,
          observe_pinhole_hidden, visibility="hidden", hint=hint_pinhole, needs=("cameras/pinhole.py",)),
    # ### END HIDDEN
])
