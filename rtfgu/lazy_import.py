"""Modules imported at their first use, not at ``import rtfgu``.

The lecture layer's scalar classes (Float3, Ray, the shapes, materials, lights, tracers) need
no numpy; the images, meshes and textures do. numpy's import takes about as long as the rest
of the package's (some 40 ms), and every test of a graded submission runs in an interpreter
of its own that imports the package (rtfgu.grading.sandbox). So a module of the package that
uses numpy writes ``from .lazy_import import numpy as np``: numpy is imported when one of
its names is first read, and ``import rtfgu`` imports no numpy
(tests/test_lazy_import.py).
"""
from __future__ import annotations

import importlib
import types


class OnFirstUse(types.ModuleType):
    """Stands for the module of its name: reading a name of it imports that module (an
    ordinary import, thread-safe, shared with every other importer through sys.modules) and
    returns the module's value, which is kept here, so the next read of that name is a plain
    attribute read. Nothing is imported until then."""

    def __getattr__(self, name):
        # Called only for a name not yet kept (a module's own attributes are found first).
        value = getattr(importlib.import_module(self.__name__), name)
        setattr(self, name, value)
        return value


numpy = OnFirstUse("numpy")
