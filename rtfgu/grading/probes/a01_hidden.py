"""Probes of a01's hidden tests."""
from __future__ import annotations

from .support import Cases, vec


def observe_unchanged(rt):
    """Operators return new vectors and leave their operands as they were."""
    cases = Cases()
    F, f3 = rt.Float3, rt.float3
    ops = [("a + b", lambda a, b: a + b), ("a - b", lambda a, b: a - b), ("a * b", lambda a, b: a * b),
           ("a * 3", lambda a, b: a * 3.0), ("a / b", lambda a, b: a / b), ("-a", lambda a, b: -a),
           ("normalize(a)", lambda a, b: f3.normalize(a)), ("cross(a, b)", lambda a, b: f3.cross(a, b))]
    for label, op in ops:
        def run(op=op):
            a, b = F(2.0, -3.0, 6.0), F(0.5, 0.25, -2.0)
            result = op(a, b)
            return {"result": vec(result, "the result"), "a afterwards": vec(a, "a"),
                    "b afterwards": vec(b, "b"), "a new vector": result is not a and result is not b}
        cases.run("%s with a = (2, -3, 6), b = (0.5, 0.25, -2)" % label, run)
    return cases.result()
