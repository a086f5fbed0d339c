# release: solves a07
"""Texture coordinates and texture lookups for the kernels, operation for operation as
rtfgu/shapes/*.texcoord and rtfgu/textures/ (image_texture.py, checker.py).

``texcoord_<shape>(position, *fields)``: (u, v) of a point on that shape, its fields in the
registry's order. ``texture_<kind>(table, row, texels, u, v, position)``: the colour of row
``row`` of that texture kind's table at the hit point ``position``, whose texture
coordinates on the shape are (u, v) (Texture.color_at).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..layout import TEXTURE_ADDRESSES, TEXTURE_FILTERS, offset
from ..textures.checker3d import EPSILON as CHECKER3D_EPSILON
from .float3 import add, cross, dot, lit, load3, normalize, scale, sub
from .noise import row_fbm, value_noise, vector_fbm, vector_noise
from .intersect import box_face
from .mappings import mapped_coordinates

IMAGE_WIDTH = offset("ImageTexture", "width")
IMAGE_HEIGHT = offset("ImageTexture", "height")
IMAGE_OFFSET = offset("ImageTexture", "offset")
IMAGE_FILTER = offset("ImageTexture", "filter_mode")
IMAGE_ADDRESS = offset("ImageTexture", "address_mode")
IMAGE_SCALE = offset("ImageTexture", "scale")
IMAGE_MAPPING = offset("ImageTexture", "mapping_id")
CHECKER_COLOR1 = offset("Checker", "color1")
CHECKER_SIZE = offset("Checker", "size")
CHECKER_COLOR2 = offset("Checker", "color2")
CHECKER_SCALE = offset("Checker", "scale")
CHECKER3D_COLOR1 = offset("Checker3D", "color1")
CHECKER3D_SIZE = offset("Checker3D", "size")
CHECKER3D_COLOR2 = offset("Checker3D", "color2")
CHECKER3D_SCALE = offset("Checker3D", "scale")
FBM_COLOR = offset("FBmTexture", "color")
FBM_MIN = offset("FBmTexture", "min_value")
FBM_MAX = offset("FBmTexture", "max_value")
FBM_SCALE = offset("FBmTexture", "scale")
FBM_NOISE = offset("FBmTexture", "noise_id")
WRAPPED_COLOR = offset("WrappedFBmTexture", "color")
WRAPPED_MIN = offset("WrappedFBmTexture", "min_value")
WRAPPED_MAX = offset("WrappedFBmTexture", "max_value")
WRAPPED_EXPANSION = offset("WrappedFBmTexture", "expansion_number")
WRAPPED_SCALE = offset("WrappedFBmTexture", "scale")
WRAPPED_NOISE = offset("WrappedFBmTexture", "noise_id")
RAMP_OFFSET = offset("RampFBmTexture", "offset")
RAMP_WIDTH = offset("RampFBmTexture", "width")
RAMP_PERTURBATION = offset("RampFBmTexture", "perturbation")
RAMP_SCALE = offset("RampFBmTexture", "scale")
RAMP_NOISE = offset("RampFBmTexture", "noise_id")
WOOD_LIGHT = offset("Wood", "light_color")
WOOD_DARK = offset("Wood", "dark_color")
WOOD_RING_FREQUENCY = offset("Wood", "ring_frequency")
WOOD_RING_UNEVENESS = offset("Wood", "ring_uneveness")
WOOD_RING_NOISE = offset("Wood", "ring_noise")
WOOD_RING_NOISE_FREQUENCY = offset("Wood", "ring_noise_frequency")
WOOD_TRUNK_WOBBLE = offset("Wood", "trunk_wobble")
WOOD_TRUNK_WOBBLE_FREQUENCY = offset("Wood", "trunk_wobble_frequency")
WOOD_ANGULAR_WOBBLE = offset("Wood", "angular_wobble")
WOOD_ANGULAR_WOBBLE_FREQUENCY = offset("Wood", "angular_wobble_frequency")
WOOD_GRAIN_FREQUENCY = offset("Wood", "grain_frequency")
WOOD_GRAINY = offset("Wood", "grainy")
WOOD_RINGY = offset("Wood", "ringy")
WOOD_SCALE = offset("Wood", "scale")
WOOD_NOISE = offset("Wood", "noise_id")
NEAREST = TEXTURE_FILTERS["nearest"]
REPEAT = TEXTURE_ADDRESSES["repeat"]


@njit(cache=True, error_model="numpy")
def texcoord_plane(position, point, normal):
    """rtfgu.shapes.shape.plane_texcoord."""
    zero = lit(0.0, position[0])
    one = lit(1.0, zero)
    n = normalize(normal)
    binormal = sub((zero, zero, one), scale(n, n[2]))
    if dot(binormal, binormal) < lit(1e-12, zero):
        binormal = sub((one, zero, zero), scale(n, n[0]))
    binormal = normalize(binormal)
    tangent = cross(binormal, n)
    d = sub(position, point)
    return dot(d, tangent), dot(d, binormal)


@njit(cache=True, error_model="numpy")
def texcoord_disk(position, center, normal, radius):
    return texcoord_plane(position, center, normal)


@njit(cache=True, error_model="numpy")
def texcoord_rectangle(position, p0, a, b, normal):
    """Rectangle.texcoord: the projections onto a and b over |a|^2 and |b|^2."""
    d = sub(position, p0)
    return dot(d, a) / dot(a, a), dot(d, b) / dot(b, b)


@njit(cache=True, error_model="numpy")
def texcoord_box(position, p0, p1):
    """Box.texcoord: the two other coordinates of the face hit, from p0, over the box's size."""
    axis = box_face(position, p0, p1) % 3
    i = (axis + 1) % 3
    j = (axis + 2) % 3
    return (position[i] - p0[i]) / (p1[i] - p0[i]), (position[j] - p0[j]) / (p1[j] - p0[j])


@njit(cache=True, error_model="numpy")
def texcoord_open_cylinder(position, y0, y1, radius):
    """OpenCylinder.texcoord: Suffern's CylindricalMap."""
    two_pi = lit(2.0 * math.pi, radius)
    phi = math.atan2(position[0], position[2])
    if phi < lit(0.0, radius):
        phi += two_pi
    return phi / two_pi, (position[1] - y0) / (y1 - y0)


@njit(cache=True, error_model="numpy")
def texcoord_torus(position, a, b):
    """Torus.texcoord: u about the y axis, v about the tube (0 on the outer equator)."""
    x = position[0]
    y = position[1]
    z = position[2]
    two_pi = lit(2.0 * math.pi, a)
    phi = math.atan2(x, z)
    if phi < lit(0.0, a):
        phi += two_pi
    theta = math.atan2(y, math.sqrt(x * x + z * z) - a)
    if theta < lit(0.0, a):
        theta += two_pi
    return phi / two_pi, theta / two_pi


@njit(cache=True, error_model="numpy")
def texcoord_open_part_cylinder(position, y0, y1, radius, phi_min, phi_max):
    """OpenPartCylinder.texcoord: the whole cylinder's."""
    return texcoord_open_cylinder(position, y0, y1, radius)


@njit(cache=True, error_model="numpy")
def texcoord_annulus(position, center, normal, inner_radius, outer_radius):
    """Annulus.texcoord: the plane's coordinates about the centre, as the disk's."""
    return texcoord_plane(position, center, normal)


@njit(cache=True, error_model="numpy")
def texcoord_convex_part_sphere(position, center, radius, phi_min, phi_max, cos_theta_min, cos_theta_max):
    """ConvexPartSphere.texcoord: the whole sphere's."""
    return texcoord_sphere(position, center, radius)


@njit(cache=True, error_model="numpy")
def texcoord_concave_part_sphere(position, center, radius, phi_min, phi_max, cos_theta_min, cos_theta_max):
    return texcoord_sphere(position, center, radius)


@njit(cache=True, error_model="numpy")
def texcoord_sphere(position, center, radius):
    """Sphere.texcoord: Suffern's SphericalMap."""
    one = lit(1.0, radius)
    two_pi = lit(2.0 * math.pi, one)
    d = sub(position, center)
    y = min(max(d[1] / radius, -one), one)
    theta = math.acos(y)
    phi = math.atan2(d[0] / radius, d[2] / radius)
    if phi < lit(0.0, one):
        phi += two_pi
    return phi / two_pi, one - theta / lit(math.pi, one)


@njit(cache=True, error_model="numpy")
def texcoord_triangle(position, v0, e0, e1, n):
    """Triangle.texcoord: the barycentric (beta, gamma) of the point."""
    d = sub(position, v0)
    nn = dot(n, n)
    return dot(cross(d, e1), n) / nn, dot(cross(e0, d), n) / nn


@njit(cache=True, error_model="numpy")
def _texel(texels, first, width, height, address, i, j):
    """ImageTexture.texel: column i, row j from the top, wrapped or clamped."""
    if address == REPEAT:
        i = i % width
        j = j % height
    else:
        i = min(max(i, 0), width - 1)
        j = min(max(j, 0), height - 1)
    k = 3 * (first + j * width + i)
    return texels[k], texels[k + 1], texels[k + 2]


@njit(cache=True, error_model="numpy")
def texture_image_texture(table, row, texels, u, v, position):
    """ImageTexture.color_at: nearest or bilinear, repeat or clamp (worksheet 3), at the
    shape's (u, v) or its mapping's of the point. Floors by np.floor, in the precision of
    (u, v) (numba's math.floor gives an int64, and a float32 less it a float64)."""
    rec = table[row]
    mapping = int(rec[IMAGE_MAPPING])
    if mapping >= 0:
        u, v = mapped_coordinates(mapping, position)
    u = u * rec[IMAGE_SCALE]
    v = v * rec[IMAGE_SCALE]
    zero = lit(0.0, u)
    one = lit(1.0, u)
    width = int(rec[IMAGE_WIDTH])
    height = int(rec[IMAGE_HEIGHT])
    first = int(rec[IMAGE_OFFSET])
    address = int(rec[IMAGE_ADDRESS])
    if address == REPEAT:
        u = u - np.floor(u)
        v = v - np.floor(v)
    else:
        u = min(max(u, zero), one)
        v = min(max(v, zero), one)
    x = u * lit(width, u)
    y = (one - v) * lit(height, u)
    if int(rec[IMAGE_FILTER]) == NEAREST:
        return _texel(texels, first, width, height, address, int(np.floor(x)), int(np.floor(y)))
    half = lit(0.5, u)
    x = x - half
    y = y - half
    fi = np.floor(x)
    fj = np.floor(y)
    fx = x - fi
    fy = y - fj
    i = int(fi)
    j = int(fj)
    top = add(scale(_texel(texels, first, width, height, address, i, j), one - fx),
              scale(_texel(texels, first, width, height, address, i + 1, j), fx))
    bottom = add(scale(_texel(texels, first, width, height, address, i, j + 1), one - fx),
                 scale(_texel(texels, first, width, height, address, i + 1, j + 1), fx))
    return add(scale(top, one - fy), scale(bottom, fy))


@njit(cache=True, error_model="numpy")
def texture_checker(table, row, texels, u, v, position):
    """Checker.color_at: colour1 where floor(u / size) + floor(v / size) is even."""
    rec = table[row]
    u = u * rec[CHECKER_SCALE]
    v = v * rec[CHECKER_SCALE]
    size = rec[CHECKER_SIZE]
    if (int(math.floor(u / size)) + int(math.floor(v / size))) % 2 == 0:
        return rec[CHECKER_COLOR1], rec[CHECKER_COLOR1 + 1], rec[CHECKER_COLOR1 + 2]
    return rec[CHECKER_COLOR2], rec[CHECKER_COLOR2 + 1], rec[CHECKER_COLOR2 + 2]


@njit(cache=True, error_model="numpy")
def texture_checker3d(table, row, texels, u, v, position):
    """Checker3D.color_at: colour1 where floor(x / size) + floor(y / size) + floor(z / size)
    of the point (scaled, moved by the book's epsilon) is even."""
    rec = table[row]
    p = scale(position, rec[CHECKER3D_SCALE])
    eps = lit(CHECKER3D_EPSILON, position[0])
    size = rec[CHECKER3D_SIZE]
    cells = (int(math.floor((p[0] + eps) / size)) + int(math.floor((p[1] + eps) / size))
             + int(math.floor((p[2] + eps) / size)))
    if cells % 2 == 0:
        return rec[CHECKER3D_COLOR1], rec[CHECKER3D_COLOR1 + 1], rec[CHECKER3D_COLOR1 + 2]
    return rec[CHECKER3D_COLOR2], rec[CHECKER3D_COLOR2 + 1], rec[CHECKER3D_COLOR2 + 2]


@njit(cache=True, error_model="numpy")
def texture_fbm_texture(table, row, texels, u, v, position):
    """FBmTexture.color_at: value_fbm mapped to [min_value, max_value] times the colour, red
    outside [0, 1]."""
    rec = table[row]
    p = scale(position, rec[FBM_SCALE])
    value = row_fbm(rec, FBM_NOISE, p)
    value = rec[FBM_MIN] + (rec[FBM_MAX] - rec[FBM_MIN]) * value
    zero = lit(0.0, value)
    one = lit(1.0, value)
    if value < zero or value > one:
        return one, zero, zero
    return scale(load3(rec, FBM_COLOR), value)


@njit(cache=True, error_model="numpy")
def texture_wrapped_fbm_texture(table, row, texels, u, v, position):
    """WrappedFBmTexture.color_at: the fractional part of expansion_number value_fbm."""
    rec = table[row]
    p = scale(position, rec[WRAPPED_SCALE])
    noise = rec[WRAPPED_EXPANSION] * row_fbm(rec, WRAPPED_NOISE, p)
    value = noise - np.floor(noise)
    value = rec[WRAPPED_MIN] + (rec[WRAPPED_MAX] - rec[WRAPPED_MIN]) * value
    return scale(load3(rec, WRAPPED_COLOR), value)


@njit(cache=True, error_model="numpy")
def texture_ramp_fbm_texture(table, row, texels, u, v, position):
    """RampFBmTexture.color_at: the ramp's entry int(u (n - 1)), u = (1 + sin(y + a fbm)) / 2."""
    rec = table[row]
    p = scale(position, rec[RAMP_SCALE])
    noise = row_fbm(rec, RAMP_NOISE, p)
    y = p[1] + rec[RAMP_PERTURBATION] * noise
    s = (lit(1.0, y) + math.sin(y)) / lit(2.0, y)
    k = 3 * (int(rec[RAMP_OFFSET]) + int(s * (rec[RAMP_WIDTH] - lit(1.0, y))))
    return texels[k], texels[k + 1], texels[k + 2]


@njit(cache=True, error_model="numpy")
def smooth_step(a, b, x):
    """rtfgu.textures.wood.smooth_step (a, b: Python floats, x of the kernel's precision)."""
    if x < lit(a, x):
        return lit(0.0, x)
    if x >= lit(b, x):
        return lit(1.0, x)
    y = (x - lit(a, x)) / (lit(b, x) - lit(a, x))
    return y * y * (lit(3.0, x) - lit(2.0, x) * y)


@njit(cache=True, error_model="numpy")
def smooth_pulse_train(e0, e1, e2, e3, period, x):
    """rtfgu.textures.wood.smooth_pulse_train with the book's mod."""
    b = lit(period, x)
    n = int(x / b)
    x = x - lit(n, x) * b
    if x < lit(0.0, x):
        x += b
    return smooth_step(e0, e1, x) - smooth_step(e2, e3, x)


@njit(cache=True, error_model="numpy")
def texture_wood(table, row, texels, u, v, position):
    """Wood.color_at, operation for operation."""
    rec = table[row]
    p = scale(position, rec[WOOD_SCALE])
    noise = int(rec[WOOD_NOISE])
    octaves = int(rec[WOOD_NOISE + 1])
    offset3 = vector_fbm(noise, octaves, rec[WOOD_NOISE + 2], rec[WOOD_NOISE + 3],
                         scale(p, rec[WOOD_RING_NOISE_FREQUENCY]))
    ring_point = add(p, scale(offset3, rec[WOOD_RING_NOISE]))
    zero = lit(0.0, p[0])
    one = lit(1.0, p[0])
    wobble = scale(vector_noise(noise, (zero, zero, p[1] * rec[WOOD_TRUNK_WOBBLE_FREQUENCY])), rec[WOOD_TRUNK_WOBBLE])
    rx = ring_point[0] + wobble[0]
    ry = ring_point[1]
    rz = ring_point[2] + wobble[2]
    r = math.sqrt(rx * rx + rz * rz) * rec[WOOD_RING_FREQUENCY]
    f = rec[WOOD_ANGULAR_WOBBLE_FREQUENCY]
    r += rec[WOOD_ANGULAR_WOBBLE] * smooth_step(0.0, 5.0, r) * value_noise(
        noise, (f * rx, f * ry * lit(0.1, r), f * rz))
    r += rec[WOOD_RING_UNEVENESS] * value_noise(noise, (r, r, r))
    in_ring = smooth_pulse_train(0.1, 0.55, 0.7, 0.95, 1.0, r)
    gx = p[0] * rec[WOOD_GRAIN_FREQUENCY]
    gy = p[1] * rec[WOOD_GRAIN_FREQUENCY] * lit(0.05, r)
    gz = p[2] * rec[WOOD_GRAIN_FREQUENCY]
    dpgrain = lit(0.2, r)
    grain = zero
    amplitude = one
    for i in range(2):
        grain_valid = one - smooth_step(0.2, 0.6, dpgrain)
        if grain_valid > zero:
            g = grain_valid * value_noise(noise, (gx, gy, gz))
            g *= lit(0.3, r) + lit(0.7, r) * in_ring
            g = min(max(lit(0.8, r) - g, zero), one)
            g = rec[WOOD_GRAINY] * smooth_step(0.5, 1.0, g * g)
            if i == 0:
                in_ring *= one - lit(0.4, r) * grain_valid
            grain = amplitude * max(grain, g)
        gx = lit(2.0, r) * gx
        gy = lit(2.0, r) * gy
        gz = lit(2.0, r) * gz
        dpgrain *= lit(2.0, r)
        amplitude *= lit(0.5, r)
    final_value = (one - grain) * (in_ring * rec[WOOD_RINGY]) + grain * one
    return add(scale(load3(rec, WOOD_LIGHT), one - final_value), scale(load3(rec, WOOD_DARK), final_value))
