"""The shapes: ``Shape`` (lecture 01, "Class Shape") and every shape kind of rtfgu.registry,
one lecture class per file (plane.py, sphere.py, triangle.py, disk.py, ...)."""
from .shape import Shape


def __getattr__(name):
    # The registered shape classes by name (PEP 562): a new kind is exported by its entry
    # in rtfgu.registry, with no list of classes to keep here.
    from ..registry import SHAPES

    for kind in SHAPES:
        if kind.cls.__name__ == name:
            return kind.cls
    raise AttributeError("module %r has no attribute %r" % (__name__, name))


def __dir__():
    from ..registry import SHAPES

    return sorted(["Shape"] + [kind.cls.__name__ for kind in SHAPES])
