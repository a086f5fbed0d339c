# release: solves a04 a12
"""The lights as the materials' light loop asks them (rtfgu/lights): sample_point_light (02562
"Sampling light in the shader", Kepler's inverse square law) operation for operation as
PointLight.get_direction and L, sample_directional as Directional's, and an area light's two
ways as AreaLight's: worksheet 5's point at the centre under the ray-cast tracers
(sample_area_light) and a point drawn by area under PathTrace (sample_area_light_area,
L G / pdf as AreaLight.incident)."""
from __future__ import annotations

import math

from numba import njit

from ..layout import LIGHT_INTENSITY, LIGHT_POSITION, offset
from .glossy import about
from .sampling import hemisphere_map
from .float3 import add, cross, div, dot, length, lit, neg, normalize, row3, scale, sub

DIRECTIONAL_DIRECTION = offset("Directional", "direction")
DIRECTIONAL_INTENSITY = offset("Directional", "intensity")
AREA_V0 = offset("AreaLight", "v0")
AREA_RADIUS = offset("AreaLight", "radius")
AREA_E0 = offset("AreaLight", "e0")
AREA_E1 = offset("AreaLight", "e1")
AREA_RECTANGLE = offset("AreaLight", "rectangle")
AREA_EMISSION = offset("AreaLight", "emission")
AMBIENT_RADIANCE = offset("AmbientOccluder", "radiance")


@njit(cache=True, error_model="numpy")
def point_light(position, intensity, pos):
    """The slide's Light struct (L_i, w_i, dist) of a point light at ``position`` seen from
    pos: L_i = I / ||p - x||^2."""
    to_light = sub(position, pos)
    dist_squared = to_light[0] * to_light[0] + to_light[1] * to_light[1] + to_light[2] * to_light[2]
    dist = math.sqrt(dist_squared)
    L_i = div(intensity, dist_squared)
    return L_i, div(to_light, dist), dist


@njit(cache=True, error_model="numpy")
def sample_point_light(lights, j, pos):
    """(L_i, w_i, dist) for point light j of the layout seen from pos."""
    return point_light(row3(lights, j, LIGHT_POSITION), row3(lights, j, LIGHT_INTENSITY), pos)


@njit(cache=True, error_model="numpy")
def sample_directional(lights, j, pos):
    """(L_i, w_i, dist) of directional light j: its intensity, normalize(direction) (toward the
    light, the book's), inf."""
    w_i = normalize(row3(lights, j, DIRECTIONAL_DIRECTION))
    return row3(lights, j, DIRECTIONAL_INTENSITY), w_i, lit(math.inf, pos[0])


@njit(cache=True, error_model="numpy")
def sample_area_light(lights, j, pos):
    """AreaLight.sample: area light j as a point light at its shape's centre (02562 worksheet
    5), with the intensity it sends toward pos; a rectangle's centre is p0 + (a + b) / 2."""
    v0 = row3(lights, j, AREA_V0)
    radius = lights[j, AREA_RADIUS]
    emission = row3(lights, j, AREA_EMISSION)
    zero = lit(0.0, radius)
    if radius > zero:
        L_i, w_i, dist = point_light(v0, scale(emission, lit(math.pi, zero) * radius * radius), pos)
        return L_i, w_i, dist - radius
    e0 = row3(lights, j, AREA_E0)
    e1 = row3(lights, j, AREA_E1)
    n = cross(e0, e1)
    if lights[j, AREA_RECTANGLE] > zero:
        center = add(v0, scale(add(e0, e1), lit(0.5, zero)))
        area = length(e0) * length(e1)
    else:
        center = add(v0, div(add(e0, e1), lit(3.0, zero)))
        area = lit(0.5, zero) * length(n)
    L_i, w_i, dist = point_light(center, scale(emission, area), pos)
    cos_l = -dot(normalize(n), w_i)
    if zero > cos_l:
        cos_l = zero
    return scale(L_i, cos_l), w_i, dist


@njit(cache=True, error_model="numpy")
def sample_area_light_area(lights, j, pos, normal, u, v):
    """AreaLight.sample_area: L_e A cos(theta_l) / d^2 toward a point of area light j uniform
    by area (AreaLight.sample_point), zero from behind."""
    v0 = row3(lights, j, AREA_V0)
    radius = lights[j, AREA_RADIUS]
    emission = row3(lights, j, AREA_EMISSION)
    zero = lit(0.0, radius)
    one = lit(1.0, zero)
    if radius > zero:
        z = one - lit(2.0, zero) * u
        s2 = one - z * z
        if zero > s2:
            s2 = zero
        s = math.sqrt(s2)
        phi = lit(2.0 * math.pi, zero) * v
        n_l = (s * math.cos(phi), s * math.sin(phi), z)
        point = add(v0, scale(n_l, radius))
        area = lit(4.0 * math.pi, zero) * radius * radius
    else:
        e0 = row3(lights, j, AREA_E0)
        e1 = row3(lights, j, AREA_E1)
        n = cross(e0, e1)
        n_l = normalize(n)
        if lights[j, AREA_RECTANGLE] > zero:
            # Rectangle.sample: p0 + u a + v b, area |a| |b| (Suffern ch. 18.6)
            point = add(add(v0, scale(e0, u)), scale(e1, v))
            area = length(e0) * length(e1)
        else:
            su = math.sqrt(u)
            point = add(v0, scale(add(scale(e0, v), scale(e1, one - v)), su))
            area = lit(0.5, zero) * length(n)
    to_light = sub(point, pos)
    dist = length(to_light)
    if not dist > zero:
        return (zero, zero, zero), n_l, zero
    w_i = div(to_light, dist)
    cos_l = -dot(n_l, w_i)
    if not cos_l > zero:
        return (zero, zero, zero), w_i, dist
    return scale(emission, area * cos_l / (dist * dist)), w_i, dist


@njit(cache=True, error_model="numpy")
def sample_ambient_occluder_area(lights, j, pos, normal, u, v):
    """AmbientOccluder.sample_area: 2 pi L toward a direction uniform on the hemisphere about
    the normal, unbounded."""
    w_i = about(normal, hemisphere_map(u, v, lit(0.0, u)))
    return scale(row3(lights, j, AMBIENT_RADIANCE), lit(2.0 * math.pi, u)), w_i, lit(math.inf, u)
