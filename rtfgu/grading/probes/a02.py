"""Probes of a02's visible tests: cameras (lecture 01, "Orthographic Camera"; 02562 week 1,
the pinhole camera)."""
from __future__ import annotations

from .support import Cases, num, vec

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


def ray_origin_image(rt, scene, width, height):
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
