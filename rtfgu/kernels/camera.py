# release: solves a02
"""gen_ray for the cameras of the flat layout (lecture 01 "Orthographic Camera"; 02562
worksheet 1 "get_camera_ray"; Suffern ch. 10 "Thin-Lens Camera", ch. 11 "Fish-Eye Camera"
and "Spherical Panoramic Camera", ch. 12 "Stereoscopy"), operation for operation as in
rtfgu/cameras/.

A ray is returned as (origin, direction, tmin, tmax). An image point a camera sees nothing
through (outside a fish-eye's circle, in a stereo pair's gap) gets a blank ray, the
interval [BLANK_TMIN, BLANK_TMAX) empty (rtfgu.cameras.camera.blank_ray): it hits nothing
and the pixel is what a ray leaving the scene sees.
"""
from __future__ import annotations

import math

from numba import njit

from ..cameras.camera import BLANK_TMAX, BLANK_TMIN
from ..layout import (FISH_EYE, FISH_EYE_PSI_MAX, FOCAL_DISTANCE, LENS_RADIUS, ORTHO_BOTTOM, ORTHO_HITHER,
                      ORTHO_LEFT, ORTHO_RIGHT, ORTHO_TMIN, ORTHO_TOP, ORTHO_YON, ORTHOGRAPHIC, PINHOLE,
                      PINHOLE_ASPECT, PINHOLE_B1, PINHOLE_B2, PINHOLE_D, PINHOLE_EYE, PINHOLE_V, SPHERICAL,
                      SPHERICAL_LAMBDA_MAX, SPHERICAL_PSI_MAX, STEREO, STEREO_HRES, STEREO_OFFSET,
                      STEREO_PIXEL_GAP, STEREO_SHIFT)
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
    if camera_kind == FISH_EYE:
        return fish_eye_ray(camera, sx, sy)
    if camera_kind == SPHERICAL:
        return spherical_ray(camera, sx, sy)
    if camera_kind == STEREO:
        return stereo_ray(camera, sx, sy)
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


@njit(cache=True, error_model="numpy")
def blank_ray(camera, like):
    """rtfgu.cameras.camera.blank_ray: from the eye along v, hitting nothing."""
    return (load3(camera, PINHOLE_EYE), load3(camera, PINHOLE_V), lit(BLANK_TMIN, like),
            lit(BLANK_TMAX, like))


@njit(cache=True, error_model="numpy")
def fish_eye_ray(camera, sx, sy):
    """FishEye.gen_ray (Suffern ch. 11.2): psi = r psi_max from v, alpha around it from b1."""
    r_squared = sx * sx + sy * sy
    if r_squared > lit(1, sx):
        return blank_ray(camera, sx)
    r = math.sqrt(r_squared)
    psi = r * camera[FISH_EYE_PSI_MAX]
    sin_psi = math.sin(psi)
    cos_psi = math.cos(psi)
    if r > lit(0, sx):
        sin_alpha = sy / r
        cos_alpha = sx / r
    else:
        sin_alpha = lit(0, sx)
        cos_alpha = lit(1, sx)
    direction = add(add(scale(load3(camera, PINHOLE_B1), sin_psi * cos_alpha),
                        scale(load3(camera, PINHOLE_B2), sin_psi * sin_alpha)),
                    scale(load3(camera, PINHOLE_V), cos_psi))
    return load3(camera, PINHOLE_EYE), normalize(direction), lit(0, sx), lit(math.inf, sx)


@njit(cache=True, error_model="numpy")
def spherical_ray(camera, sx, sy):
    """Spherical.gen_ray (Suffern ch. 11.3): longitude sx lambda_max, latitude sy psi_max."""
    lam = sx * camera[SPHERICAL_LAMBDA_MAX]
    psi = sy * camera[SPHERICAL_PSI_MAX]
    cos_psi = math.cos(psi)
    direction = add(add(scale(load3(camera, PINHOLE_B1), cos_psi * math.sin(lam)),
                        scale(load3(camera, PINHOLE_B2), math.sin(psi))),
                    scale(load3(camera, PINHOLE_V), cos_psi * math.cos(lam)))
    return load3(camera, PINHOLE_EYE), normalize(direction), lit(0, sx), lit(math.inf, sx)


@njit(cache=True, error_model="numpy")
def stereo_ray(camera, sx, sy):
    """StereoCamera.gen_ray (Suffern ch. 12): the column c of the stereo image picks the
    view on the left, the gap (a blank ray) or the view on the right."""
    hres = camera[STEREO_HRES]
    gap = camera[STEREO_PIXEL_GAP]
    c = (sx + lit(1, sx)) * lit(0.5, sx) * (hres + hres + gap)
    if c < hres:
        offset = camera[STEREO_OFFSET]
        shift = camera[STEREO_SHIFT]
    elif c >= hres + gap:
        offset = -camera[STEREO_OFFSET]
        shift = -camera[STEREO_SHIFT]
        c = c - (hres + gap)
    else:
        return blank_ray(camera, sx)
    u = (c / hres - lit(0.5, sx)) * camera[PINHOLE_ASPECT] + shift
    w = sy * lit(0.5, sx)
    q = add(add(scale(load3(camera, PINHOLE_B1), u), scale(load3(camera, PINHOLE_B2), w)),
            scale(load3(camera, PINHOLE_V), camera[PINHOLE_D]))
    origin = add(load3(camera, PINHOLE_EYE), scale(load3(camera, PINHOLE_B1), offset))
    return origin, normalize(q), lit(0, sx), lit(math.inf, sx)
