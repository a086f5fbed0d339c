# release: solves a02
"""gen_ray for the cameras of the flat layout (lecture 01 "Orthographic Camera"; 02562
worksheet 1 "get_camera_ray"; Suffern ch. 10 "Thin-Lens Camera"), operation for operation
as in rtfgu/cameras/.

A ray is returned as (origin, direction, tmin, tmax).
"""
from __future__ import annotations

import math

from numba import njit

from ..layout import (FOCAL_DISTANCE, LENS_RADIUS, ORTHO_BOTTOM, ORTHO_HITHER, ORTHO_LEFT,
                      ORTHO_RIGHT, ORTHO_TMIN, ORTHO_TOP, ORTHO_YON, ORTHOGRAPHIC, PINHOLE, PINHOLE_ASPECT, PINHOLE_B1,
                      PINHOLE_B2, PINHOLE_D, PINHOLE_EYE, PINHOLE_V)
from .float3 import add, dot, lit, load3, normalize, scale, sub


@njit(cache=True, error_model="numpy")
def gen_ray(camera_kind, camera, sx, sy):
    """The ray through (sx, sy) of the image plane [-1, 1]^2; ``camera`` is the layout's
    camera block read as one flat row."""
    if camera_kind == ORTHOGRAPHIC:
        # OrthographicCamera.gen_ray: sx = 0.5 + sx / 2, x = left + (right - left) * sx.
        sx = lit(0.5, sx) + sx / lit(2, sx)
        sy = lit(0.5, sy) + sy / lit(2, sy)
        x = camera[ORTHO_LEFT] + (camera[ORTHO_RIGHT] - camera[ORTHO_LEFT]) * sx
        y = camera[ORTHO_BOTTOM] + (camera[ORTHO_TOP] - camera[ORTHO_BOTTOM]) * sy
        hither = camera[ORTHO_HITHER]
        zero = lit(0, sx)
        return ((x, y, hither), (zero, zero, lit(-1, sx)), camera[ORTHO_TMIN],
                camera[ORTHO_YON] - hither)
    # PinholeCamera.gen_ray: q = b1 u + b2 w + v d with (u, w) = (sx aspect / 2, sy / 2).
    u = sx * camera[PINHOLE_ASPECT] * lit(0.5, sx)
    w = sy * lit(0.5, sy)
    q = add(add(scale(load3(camera, PINHOLE_B1), u), scale(load3(camera, PINHOLE_B2), w)),
            scale(load3(camera, PINHOLE_V), camera[PINHOLE_D]))
    return load3(camera, PINHOLE_EYE), normalize(q), lit(0, sx), lit(math.inf, sx)


@njit(cache=True, error_model="numpy")
def thin_lens_ray(camera, sx, sy, lens):
    """ThinLens.gen_ray: from eye + lens_radius (l_x b1 + l_y b2) to where the pinhole ray
    through (sx, sy) meets the focal plane; ``lens`` is a point of the unit disk."""
    eye, direction, tmin, tmax = gen_ray(PINHOLE, camera, sx, sy)
    t = camera[FOCAL_DISTANCE] / dot(direction, load3(camera, PINHOLE_V))
    focus = add(eye, scale(direction, t))
    lx = lens[0] * camera[LENS_RADIUS]
    ly = lens[1] * camera[LENS_RADIUS]
    origin = add(add(eye, scale(load3(camera, PINHOLE_B1), lx)), scale(load3(camera, PINHOLE_B2), ly))
    return origin, normalize(sub(focus, origin)), tmin, tmax
