# release: solves a03
"""Suffern's part objects (ch. 19, "Part objects"), operation for operation as their lecture
classes (rtfgu/shapes/convex_part_sphere.py, concave_part_sphere.py, open_part_cylinder.py,
annulus.py): the whole shape's test from rtfgu/kernels/intersect.py, then the part's test on
the point hit, near root first and then, from just beyond it, the far one. The arguments
are the kinds' fields in rtfgu.registry's order; ``intersect_*`` returns t in [tmin, tmax]
or inf, as every kernel's intersection does.
"""
from __future__ import annotations

import math

from numba import njit

from .float3 import add, lit, neg, normalize, scale, sub
from .next_float import next_up
from .intersect import intersect_open_cylinder, intersect_sphere, normal_open_cylinder, plane_hit_offset


@njit(cache=True, error_model="numpy")
def azimuth(p):
    """rtfgu.shapes.part.azimuth: the book's phi = atan2(x, z) in [0, 2 pi)."""
    phi = math.atan2(p[0], p[2])
    if phi < lit(0, phi):
        phi += lit(2.0 * math.pi, phi)
    return phi


@njit(cache=True, error_model="numpy")
def intersect_convex_part_sphere(origin, direction, tmin, tmax, center, radius, phi_min, phi_max,
                                 cos_theta_min, cos_theta_max):
    # ConvexPartSphere.intersect_p: the sphere's root (intersect_sphere), kept when the point
    # p - c has r cos(theta_max) <= y <= r cos(theta_min) and phi in [phi_min, phi_max].
    inf = lit(math.inf, radius)
    t = intersect_sphere(origin, direction, tmin, tmax, center, radius)
    for _ in range(2):
        if t == inf:
            return t
        hit = sub(add(origin, scale(direction, t)), center)
        if radius * cos_theta_max <= hit[1] and hit[1] <= radius * cos_theta_min:
            phi = azimuth(hit)
            if phi_min <= phi and phi <= phi_max:
                return t
        t = intersect_sphere(origin, direction, next_up(t), tmax, center, radius)
    return inf


@njit(cache=True, error_model="numpy")
def intersect_concave_part_sphere(origin, direction, tmin, tmax, center, radius, phi_min, phi_max,
                                  cos_theta_min, cos_theta_max):
    # The convex part's surface, seen from inside.
    return intersect_convex_part_sphere(origin, direction, tmin, tmax, center, radius, phi_min, phi_max,
                                        cos_theta_min, cos_theta_max)


@njit(cache=True, error_model="numpy")
def intersect_open_part_cylinder(origin, direction, tmin, tmax, y0, y1, radius, phi_min, phi_max):
    # OpenPartCylinder.intersect_p: the open cylinder's hit (intersect_open_cylinder), kept
    # when its azimuth is in [phi_min, phi_max], else the next one.
    inf = lit(math.inf, radius)
    t = intersect_open_cylinder(origin, direction, tmin, tmax, y0, y1, radius)
    for _ in range(2):
        if t == inf:
            return t
        phi = azimuth(add(origin, scale(direction, t)))
        if phi_min <= phi and phi <= phi_max:
            return t
        t = intersect_open_cylinder(origin, direction, next_up(t), tmax, y0, y1, radius)
    return inf


@njit(cache=True, error_model="numpy")
def intersect_annulus(origin, direction, tmin, tmax, center, normal, inner_radius, outer_radius):
    # Annulus.intersect_p: the plane, then r_i^2 <= (p - c) . (p - c) <= r_o^2 (plane_hit_offset).
    t, d2 = plane_hit_offset(origin, direction, tmin, tmax, center, normal)
    if inner_radius * inner_radius <= d2 and d2 <= outer_radius * outer_radius:
        return t
    return lit(math.inf, t)


@njit(cache=True, error_model="numpy")
def normal_convex_part_sphere(position, center, radius, phi_min, phi_max, cos_theta_min, cos_theta_max):
    return normalize(sub(position, center))


@njit(cache=True, error_model="numpy")
def normal_concave_part_sphere(position, center, radius, phi_min, phi_max, cos_theta_min, cos_theta_max):
    # ConcavePartSphere.normal_at: the sphere's normal, pointing in.
    return neg(normalize(sub(position, center)))


@njit(cache=True, error_model="numpy")
def normal_open_part_cylinder(position, direction, y0, y1, radius, phi_min, phi_max):
    return normal_open_cylinder(position, direction, y0, y1, radius)


@njit(cache=True, error_model="numpy")
def normal_annulus(position, center, normal, inner_radius, outer_radius):
    return normalize(normal)
