"""Probes of a12's visible tests: points of a shape drawn uniformly by area
(``Triangle.sample``, ``Rectangle.sample``), Suffern's AreaLight (``get_direction``, ``G``,
``pdf``, ``incident``) and the AreaLighting tracer (Suffern ch. 18, "Area Lights").

A probe returns what the student's code made: the points at chosen (u, v) and, for the
distribution, the parts of the shape that many drawn points fall in (16 parts of equal area:
the rectangle's 4 x 4 grid of (s, t), the triangle's 16 triangles of its edges cut in four;
the judge applies a chi-square test). The light's methods run at a chosen shading point with
the point of the unit square they draw given (``Scene.light_sample`` answers it), and G, pdf
and L G / pdf with the light's point set first, so that each method is seen on its own."""
from __future__ import annotations

import importlib
import random

from .a04 import _hit
from .support import Cases, StudentError, image, num, vec

PARTS = 4           # each of s and t cut in PARTS: 16 parts of equal area
SHOWN = 5           # the points off the shape shown in a message


def _shape(rt, kind: str, corners, material=None):
    """A Triangle (v0, v1, v2), a Rectangle (p0, a, b) or a Sphere ((centre), (radius,), _)."""
    F = rt.Float3
    if kind == "triangle":
        return rt.Triangle(F(*corners[0]), F(*corners[1]), F(*corners[2]), F(1.0), material)
    if kind == "rectangle":
        return rt.Rectangle(F(*corners[0]), F(*corners[1]), F(*corners[2]), F(1.0), material)
    return rt.Sphere(F(*corners[0]), corners[1][0], F(1.0), material)


def _edges(kind: str, corners) -> tuple:
    """(origin, e0, e1) of the shape's plane: p = origin + s e0 + t e1."""
    o = corners[0]
    if kind == "triangle":
        return o, [corners[1][k] - o[k] for k in range(3)], [corners[2][k] - o[k] for k in range(3)]
    return o, list(corners[1]), list(corners[2])


def _coordinates(p, origin, e0, e1) -> tuple:
    """(s, t) with p - origin = s e0 + t e1 (least squares), and the distance off the plane."""
    d = [p[k] - origin[k] for k in range(3)]
    a, b, c = (sum(x * y for x, y in zip(u, w)) for u, w in ((e0, e0), (e0, e1), (e1, e1)))
    f, g = sum(x * y for x, y in zip(d, e0)), sum(x * y for x, y in zip(d, e1))
    det = a * c - b * b
    s, t = (f * c - g * b) / det, (g * a - f * b) / det
    off = [d[k] - s * e0[k] - t * e1[k] for k in range(3)]
    return s, t, sum(x * x for x in off) ** 0.5


def _part(kind: str, s: float, t: float):
    """The part (0..15) of the shape that holds (s, t), or None off the shape."""
    eps = 1e-9
    if kind == "rectangle":
        if not (-eps <= s <= 1 + eps and -eps <= t <= 1 + eps):
            return None
        i, j = min(int(max(s, 0.0) * PARTS), PARTS - 1), min(int(max(t, 0.0) * PARTS), PARTS - 1)
        return i * PARTS + j
    if not (s >= -eps and t >= -eps and s + t <= 1 + eps):
        return None
    x, y = max(s, 0.0) * PARTS, max(t, 0.0) * PARTS
    i, j = min(int(x), PARTS - 1), min(int(y), PARTS - 1)
    while i + j > PARTS - 1:            # on the far edge, by rounding
        if i >= j:
            i -= 1
        else:
            j -= 1
    upper = (x - i) + (y - j) > 1.0 and i + j < PARTS - 1
    # the triangles (i, j) with i + j < PARTS point up (10), those with i + j < PARTS - 1 down (6)
    lower = [(a, b) for a in range(PARTS) for b in range(PARTS) if a + b < PARTS]
    upper_cells = [(a, b) for a in range(PARTS) for b in range(PARTS) if a + b < PARTS - 1]
    return len(lower) + upper_cells.index((i, j)) if upper else lower.index((i, j))


def observe_sample(rt, cases):
    """shape.sample(u, v) for each (kind, corners, u, v)."""
    out = Cases()
    for kind, corners, u, v in cases:
        label = "%s%s.sample(%r, %r)" % (kind.capitalize(), tuple(tuple(c) for c in corners), u, v)
        out.run(label, lambda kind=kind, corners=corners, u=u, v=v:
                {"point": vec(_shape(rt, kind, corners).sample(u, v), "sample's result")},
                kind=kind, corners=[list(c) for c in corners], u=u, v=v)
    return out.result()


def observe_sample_binned(rt, kind: str, corners, count: int, seed: int):
    """``count`` points of the shape from uniform (u, v), counted in its 16 parts of equal
    area; the points off the shape counted (and the first few kept)."""
    stream = random.Random(seed)
    shape = _shape(rt, kind, corners)
    origin, e0, e1 = _edges(kind, corners)
    counts = [0] * (PARTS * PARTS)
    bad, n_bad = [], 0
    for _ in range(count):
        u, v = stream.random(), stream.random()
        p = vec(shape.sample(u, v), "sample(%r, %r)" % (u, v))
        s, t, off = _coordinates(p, origin, e0, e1)
        part = _part(kind, s, t) if off <= 1e-9 * (1.0 + max(abs(x) for x in p)) else None
        if part is None:
            n_bad += 1
            if len(bad) < SHOWN:
                bad.append([[u, v], p])
            continue
        counts[part] += 1
    return {"counts": counts, "bad": bad, "n_bad": n_bad, "count": count, "kind": kind}


def _area_light(rt, kind: str, corners, emission, position, normal, uv=None):
    """(light, sr): an AreaLight of the shape, emitting ``emission``, and the HitInfo of a
    point of a surface at ``position`` with ``normal``, in a scene traced by AreaLighting
    whose light_sample answers ``uv``."""
    F = rt.Float3
    materials = importlib.import_module(rt.__name__ + ".materials.emissive")
    shape = _shape(rt, kind, corners, materials.Emissive(1.0, tuple(emission)))
    scene = rt.Scene(None)
    scene.shapes.append(shape)
    light = rt.AreaLight(shape)
    scene.lights.append(light)
    scene.tracer = rt.AreaLighting()
    scene.tracer.world = scene
    if uv is not None:
        scene.light_sample = lambda light, sr, uv=tuple(uv): uv
    ray = rt.Ray(F(*position) + F(*normal), -rt.float3.normalize(F(*normal)))
    sr = _hit(rt, scene, ray, position, normal, (0.5, 0.5, 0.5))
    return light, sr


def observe_direction(rt, cases):
    """AreaLight.get_direction at ``position`` with (u, v) drawn: w_i, and the point and the
    normal the light keeps."""
    out = Cases()
    for kind, corners, position, u, v in cases:
        def run(kind=kind, corners=corners, position=position, u=u, v=v):
            light, sr = _area_light(rt, kind, corners, (1.0, 1.0, 1.0), position, (0, 1, 0), uv=(u, v))
            w_i = vec(light.get_direction(sr), "get_direction's result")
            if not hasattr(light, "sample_point") or not hasattr(light, "light_normal"):
                raise StudentError("get_direction must keep the point drawn and its normal in "
                                   "self.sample_point and self.light_normal")
            return {"w_i": w_i, "sample_point": vec(light.sample_point, "self.sample_point"),
                    "light_normal": vec(light.light_normal, "self.light_normal")}
        out.run("AreaLight of the %s %s: get_direction at %s with (u, v) = (%r, %r)"
                % (kind, tuple(tuple(c) for c in corners), tuple(position), u, v), run,
                kind=kind, corners=[list(c) for c in corners], position=list(position), u=u, v=v)
    return out.result()


def observe_light_terms(rt, cases):
    """G, pdf and incident (L G / pdf) of an AreaLight whose point is set to ``point`` with
    the shape's own normal there, seen from ``position``."""
    out = Cases()
    F = rt.Float3
    for kind, corners, emission, point, position in cases:
        def run(kind=kind, corners=corners, emission=emission, point=point, position=position):
            light, sr = _area_light(rt, kind, corners, emission, position, (0, 1, 0))
            light.sample_point = F(*point)
            light.light_normal = light.geometry.get_normal(F(*point))
            return {"G": num(light.G(sr), "G's result"), "pdf": num(light.pdf(sr), "pdf's result"),
                    "incident": vec(light.incident(sr), "incident's result")}
        out.run("AreaLight of the %s %s emitting %s: its point %s seen from %s"
                % (kind, tuple(tuple(c) for c in corners), tuple(emission), tuple(point), tuple(position)), run,
                kind=kind, corners=[list(c) for c in corners], emission=list(emission), point=list(point),
                position=list(position))
    return out.result()


def observe_tracer(rt):
    """AreaLighting.shade at a hit of a material whose area_light_shade and shade differ."""
    F = rt.Float3

    class Marked(rt.Matte):
        def shade(self, sr):
            return F(0.125, 0.125, 0.125)

        def area_light_shade(self, sr):
            return F(0.25, 0.5, 0.75)

    out = Cases()

    def run():
        scene = rt.Scene(None)
        scene.tracer = rt.AreaLighting()
        scene.tracer.world = scene
        sr = _hit(rt, scene, rt.Ray(F(0, 1, 0), F(0, -1, 0)), (0, 0, 0), (0, 1, 0), (1, 1, 1), material=Marked())
        return {"L": vec(scene.tracer.shade(sr), "AreaLighting.shade's result")}
    out.run("AreaLighting.shade at a hit whose material's area_light_shade gives (0.25, 0.5, 0.75) and "
            "shade (0.125, 0.125, 0.125)", run)
    return out.result()


def render_area_lighting(rt, width: int, height: int):
    """Suffern's figure of chapter 18 (the scene ``suffern_18_area_lighting``), one sample at
    each pixel's centre, each drawing its own point of the lamp, by the lecture layer."""
    scene = rt.scenes.get_scene("suffern_18_area_lighting")()
    return image(rt.renderer.render_reference(scene, width, height))
