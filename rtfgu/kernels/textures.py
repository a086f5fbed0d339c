# release: solves a07
"""Texture coordinates and texture lookups for the kernels, operation for operation as
rtfgu/shapes/*.texcoord and rtfgu/textures/ (image_texture.py, checker.py).

``texcoord_<shape>(position, *fields)``: (u, v) of a point on that shape, its fields in the
registry's order. ``texture_<kind>(table, row, texels, u, v)``: the colour of row ``row``
of that texture kind's table at the shape's (u, v), scaled by the texture's ``scale``.
"""
from __future__ import annotations

import math

from numba import njit

from ..layout import TEXTURE_ADDRESSES, TEXTURE_FILTERS, offset
from .float3 import add, cross, dot, lit, normalize, scale, sub
from .intersect import box_face

IMAGE_WIDTH = offset("ImageTexture", "width")
IMAGE_HEIGHT = offset("ImageTexture", "height")
IMAGE_OFFSET = offset("ImageTexture", "offset")
IMAGE_FILTER = offset("ImageTexture", "filter_mode")
IMAGE_ADDRESS = offset("ImageTexture", "address_mode")
IMAGE_SCALE = offset("ImageTexture", "scale")
CHECKER_COLOR1 = offset("Checker", "color1")
CHECKER_SIZE = offset("Checker", "size")
CHECKER_COLOR2 = offset("Checker", "color2")
CHECKER_SCALE = offset("Checker", "scale")
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
def texture_image_texture(table, row, texels, u, v):
    """ImageTexture.color_at: nearest or bilinear, repeat or clamp (worksheet 3)."""
    rec = table[row]
    u = u * rec[IMAGE_SCALE]
    v = v * rec[IMAGE_SCALE]
    zero = lit(0.0, u)
    one = lit(1.0, u)
    width = int(rec[IMAGE_WIDTH])
    height = int(rec[IMAGE_HEIGHT])
    first = int(rec[IMAGE_OFFSET])
    address = int(rec[IMAGE_ADDRESS])
    if address == REPEAT:
        u = u - math.floor(u)
        v = v - math.floor(v)
    else:
        u = min(max(u, zero), one)
        v = min(max(v, zero), one)
    x = u * lit(width, u)
    y = (one - v) * lit(height, u)
    if int(rec[IMAGE_FILTER]) == NEAREST:
        return _texel(texels, first, width, height, address, int(math.floor(x)), int(math.floor(y)))
    half = lit(0.5, u)
    x = x - half
    y = y - half
    fi = math.floor(x)
    fj = math.floor(y)
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
def texture_checker(table, row, texels, u, v):
    """Checker.color_at: colour1 where floor(u / size) + floor(v / size) is even."""
    rec = table[row]
    u = u * rec[CHECKER_SCALE]
    v = v * rec[CHECKER_SCALE]
    size = rec[CHECKER_SIZE]
    if (int(math.floor(u / size)) + int(math.floor(v / size))) % 2 == 0:
        return rec[CHECKER_COLOR1], rec[CHECKER_COLOR1 + 1], rec[CHECKER_COLOR1 + 2]
    return rec[CHECKER_COLOR2], rec[CHECKER_COLOR2 + 1], rec[CHECKER_COLOR2 + 2]
