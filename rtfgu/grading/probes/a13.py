"""Probes of a13's visible tests: Suffern's Matrix products (``transform_point``,
``transform_vector``, ``transform_normal``, ch. 20) and the Instance (``_compose``,
``object_ray``, ``normal_at``, ``hit_normal``, ch. 21).

A transformation is given as a chain of calls, [["translate", 1, 2, 3], ["rotate_y", 90], ...],
applied to an Instance in that order. The probes return the numbers the student's code makes:
the products of chosen matrices, the composed matrices, the object-space ray, and the t and
normal of hits on transformed shapes."""
from __future__ import annotations

import importlib

from .support import Cases, StudentError, image, num, vec


def _matrix_module(rt):
    return importlib.import_module(rt.__name__ + ".matrix")


def _instance_module(rt):
    return importlib.import_module(rt.__name__ + ".shapes.instance")


def _matrix(rt, rows):
    return _matrix_module(rt).Matrix(rows)


def _rows(matrix, what: str) -> list:
    m = getattr(matrix, "m", None)
    if not isinstance(m, list) or len(m) != 4 or any(not isinstance(r, list) or len(r) != 4 for r in m):
        raise StudentError("%s is not a 4 x 4 Matrix (its m is %r)" % (what, m))
    return [[num(c, what) for c in row] for row in m]


def _shape(rt, spec):
    """A Sphere (center, radius), a Box (p0, p1) or an OpenCylinder (y0, y1, radius)."""
    F = rt.Float3
    kind, args = spec[0], spec[1:]
    if kind == "sphere":
        return rt.Sphere(F(*args[0]), args[1], F(0.8))
    if kind == "box":
        return rt.Box(F(*args[0]), F(*args[1]), F(0.8))
    return rt.OpenCylinder(args[0], args[1], args[2], F(0.8))


def _instance(rt, spec, chain):
    instance = _instance_module(rt).Instance(_shape(rt, spec))
    for call in chain:
        result = getattr(instance, call[0])(*call[1:])
        if result is not instance:
            raise StudentError("Instance.%s returned %r, not the instance itself (return self, so that calls "
                               "chain)" % (call[0], result))
    return instance


def _describe(chain) -> str:
    return ".".join("%s(%s)" % (c[0], ", ".join("%g" % a for a in c[1:])) for c in chain) or "(no call)"


def observe_products(rt, cases):
    """transform_point, transform_vector and transform_normal of a matrix (rows) at a Float3."""
    out = Cases()
    F = rt.Float3
    for rows, x in cases:
        def run(rows=rows, x=x):
            m = _matrix(rt, rows)
            return {"point": vec(m.transform_point(F(*x)), "transform_point's result"),
                    "vector": vec(m.transform_vector(F(*x)), "transform_vector's result"),
                    "normal": vec(m.transform_normal(F(*x)), "transform_normal's result")}
        out.run("Matrix(%s) at %s" % (rows, tuple(x)), run, rows=rows, x=list(x))
    return out.result()


def observe_compose(rt, cases):
    """The inverse and forward matrices an Instance composes along a chain of calls."""
    out = Cases()
    for chain in cases:
        def run(chain=chain):
            instance = _instance(rt, ("sphere", (0, 0, 0), 1.0), chain)
            return {"inv_matrix": _rows(instance.inv_matrix, "inv_matrix"),
                    "forward_matrix": _rows(instance.forward_matrix, "forward_matrix")}
        out.run("Instance(sphere).%s" % _describe(chain), run, chain=chain)
    return out.result()


def observe_object_ray(rt, cases):
    """Instance.object_ray of a ray (origin, direction, tmin, tmax) along a chain."""
    out = Cases()
    F = rt.Float3
    for chain, origin, direction in cases:
        def run(chain=chain, origin=origin, direction=direction):
            instance = _instance(rt, ("sphere", (0, 0, 0), 1.0), chain)
            ray = rt.Ray(F(*origin), F(*direction), 0.001, 100.0)
            r = instance.object_ray(ray)
            if r is ray:
                raise StudentError("object_ray returned the world ray itself: return a new Ray")
            return {"origin": vec(r.origin, "the object ray's origin"),
                    "direction": vec(r.direction, "the object ray's direction"),
                    "tmin": num(r.tmin, "the object ray's tmin"), "tmax": num(r.tmax, "the object ray's tmax")}
        out.run("Instance(sphere).%s: object_ray of the ray from %s along %s"
                % (_describe(chain), tuple(origin), tuple(direction)), run,
                chain=chain, origin=list(origin), direction=list(direction))
    return out.result()


def observe_hits(rt, cases):
    """The t of the nearest hit of a ray on an instance of a shape, and the instance's
    normal_at and hit_normal there (none on a miss)."""
    out = Cases()
    F = rt.Float3
    for spec, chain, origin, direction in cases:
        def run(spec=spec, chain=chain, origin=origin, direction=direction):
            instance = _instance(rt, spec, chain)
            ray = rt.Ray(F(*origin), F(*direction), 0.001, 100.0)
            if not instance.intersect_p(ray):
                return {"hit": False}
            p = ray.origin + ray.direction * ray.tmax
            return {"hit": True, "t": num(ray.tmax, "the hit's t"),
                    "normal_at": vec(instance.normal_at(p), "normal_at's result"),
                    "hit_normal": vec(instance.hit_normal(p, ray.direction), "hit_normal's result")}
        out.run("Instance(%s).%s hit by the ray from %s along %s"
                % (spec[0], _describe(chain), tuple(origin), tuple(direction)), run,
                spec=[list(s) if isinstance(s, tuple) else s for s in spec], chain=chain, origin=list(origin),
                direction=list(direction))
    return out.result()


def render_instances(rt, width: int, height: int):
    """Suffern's figure of chapter 21 (the scene ``suffern_21_instances``), by the lecture layer."""
    scene = rt.scenes.get_scene("suffern_21_instances")()
    return image(rt.renderer.render_reference(scene, width, height))
