"""Probes: the code that runs next to student code, in the sandboxed child.

A probe is a function ``probe(rt, **kwargs)`` of a module of this package, with ``rt`` the
student's copy of the package; it calls the student's functions on fixed inputs and returns
plain JSON data (the inputs it tried and what came back). It holds no hint, no solution
maths and no reference data, and imports nothing outside this package (relative imports
only), so that this folder can be copied anywhere under any package name (the grader copies
it into the sandbox as ``rtfgu_probes``; a student release ships the visible modules).

Modules: ``support`` (Cases, num, vec, boolean, describe_exception, image), ``images``
(``render_scene``), one module per assignment with its visible tests' probes (``a03``) and
one with its hidden tests' probes (``a03_hidden``, never in a student release), and
``boot`` (the entry of a test's interpreter).
"""
from __future__ import annotations

import importlib
import re

_NAME = re.compile(r"^[a-z][a-z0-9_]*$")


def run(module: str, function: str, kwargs: dict, rt):
    """The JSON data probe ``module.function(rt, **kwargs)`` returns (``module`` is a module
    of this package, e.g. "a03" or "images")."""
    if not _NAME.match(module) or not _NAME.match(function) or function.startswith("_"):
        raise ValueError("no probe %s.%s" % (module, function))
    probe = getattr(importlib.import_module("." + module, __name__), function)
    return probe(rt, **(kwargs or {}))
