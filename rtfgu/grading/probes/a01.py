"""Probes of a01's visible tests: Float3 and Ray (lecture 01, "Float3 Structure" and "Ray")."""
from __future__ import annotations

from .support import Cases, num, vec

A = (1.5, -2.0, 0.25)
B = (-0.5, 4.0, 2.0)
C = (3.0, 0.0, -4.0)


def _ops(rt, pairs, ops):
    cases = Cases()
    F = rt.Float3
    for a, b in pairs:
        for label, op in ops:
            def run(a=a, b=b, op=op):
                return {"result": vec(op(F(*a), F(*b)), "the result")}
            cases.run(label % {"a": "(%g, %g, %g)" % a, "b": "(%g, %g, %g)" % b}, run, a=list(a), b=list(b))
    return cases.result()


def observe_add_sub(rt):
    return _ops(rt, [(A, B), (C, A)], [
        ("%(a)s + %(b)s", lambda a, b: a + b),
        ("%(a)s - %(b)s", lambda a, b: a - b),
        ("-%(a)s", lambda a, b: -a),
    ])


def observe_mul_div(rt):
    return _ops(rt, [(A, B), (C, (2.0, -0.5, 8.0))], [
        ("%(a)s * %(b)s (componentwise)", lambda a, b: a * b),
        ("%(a)s * 2.5", lambda a, b: a * 2.5),
        ("2.5 * %(a)s", lambda a, b: 2.5 * a),
        ("%(a)s / %(b)s (componentwise)", lambda a, b: a / b),
        ("%(a)s / 4", lambda a, b: a / 4.0),
    ])


def observe_dot_cross(rt):
    cases = Cases()
    F, f3 = rt.Float3, rt.float3
    for a, b in [(A, B), (C, A), ((1, 0, 0), (0, 1, 0))]:
        label = "(%g, %g, %g) and (%g, %g, %g)" % (a + b)
        cases.run("dot of " + label, lambda a=a, b=b: {"dot": num(f3.dot(F(*a), F(*b)), "dot(a, b)")},
                  a=list(a), b=list(b))
        cases.run("cross of " + label, lambda a=a, b=b: {"cross": vec(f3.cross(F(*a), F(*b)), "cross(a, b)")},
                  a=list(a), b=list(b))
    return cases.result()




def observe_length(rt):
    cases = Cases()
    F, f3 = rt.Float3, rt.float3
    for a in (A, C, (0.0, 0.0, -2.0)):
        label = "(%g, %g, %g)" % a
        cases.run("length_squared of " + label, lambda a=a: {"length_squared": num(F(*a).length_squared(), "length_squared()")})
        cases.run("length of " + label, lambda a=a: {"length": num(F(*a).length(), "length()")})
        cases.run("normalize of " + label, lambda a=a: {"normalize": vec(f3.normalize(F(*a)), "normalize(v)")})
    return cases.result()




def observe_ray(rt):
    cases = Cases()
    F = rt.Float3
    for o, d, t in [((0, 0, 0), (0, 0, -1), 2.0), ((1, 2, 3), (0.5, -1, 2), 1.5), ((-1, 0, 4), (3, 0, 0), 0.0)]:
        def run(o=o, d=d, t=t):
            ray = rt.Ray(F(*o), F(*d))
            return {"r(t)": vec(ray(t), "ray(t)")}
        cases.run("the ray from (%g, %g, %g) along (%g, %g, %g) at t = %g" % (o + d + (t,)), run)
    return cases.result()
