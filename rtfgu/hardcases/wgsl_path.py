# release: solves a03
"""The WGSL float32 path of the hard cases: rtfgu/wgsl/hardcase_main.wgsl runs a batch of
rays, each against its own shape, with the kind's slide function (the registry's
intersect_<kind>.wgsl, and the files of the kinds it uses) or its robust one
(robust_<kind>.wgsl), and spawns secondary rays with PBRT's offset (robust_spawn.wgsl);
rtfgu/wgsl/harness.py assembles and runs it.
"""
from __future__ import annotations

from functools import lru_cache

import numpy as np

from ..layout import FAR
from ..registry import SHAPE_BY_NAME
from .kinds import KINDS
from .paths import Path, slide_spawn


def _piece(kind: str, formula: str) -> str:
    if kind not in SHAPE_BY_NAME:      # a helper piece a kind uses (rtfgu.wgsl.assemble)
        return kind + ".wgsl"
    return SHAPE_BY_NAME[kind].wgsl_file if formula == "slide" else "robust_%s.wgsl" % kind


def program(kind: str, formula: str, spawn: bool = False):
    """The assembled hard-case program for ``kind`` and ``formula`` (rtfgu.wgsl.assemble.Program)."""
    from ..wgsl.harness import batch_program

    pieces = ["ray.wgsl", "hitinfo.wgsl"]
    pieces += [_piece(used, formula) for used in KINDS[kind].pieces or SHAPE_BY_NAME[kind].uses + (kind,)]
    if spawn:
        pieces.append("robust_spawn.wgsl")
    pieces.append("hardcase_main.wgsl")
    features = {kind, formula} | ({"spawn"} if spawn else set())
    return batch_program(pieces, features, {"SHAPE_WIDTH": KINDS[kind].width})


@lru_cache(maxsize=1)
def wgsl_unavailable_reason() -> str | None:
    """None if a WebGPU adapter exists, else why not (naming the missing package)."""
    try:
        from ..wgsl.device import get_device
        get_device()
    except Exception as error:  # no wgpu, or no adapter
        return str(error) or type(error).__name__
    return None


def wgsl_available() -> bool:
    return wgsl_unavailable_reason() is None


def _run(kind, formula, spawn, rays, shapes, count):
    from ..wgsl.harness import run_batch

    zero = np.zeros(1, np.uint32)
    return run_batch(program(kind, formula, spawn), [zero, np.ascontiguousarray(rays, np.float32),
                                                     np.ascontiguousarray(shapes, np.float32)], count)[:, 0]


class WgslPath(Path):
    """The WGSL float32 path: one dispatch per batch of rays."""

    name = "wgsl"
    precision = "float32"

    def __call__(self, kind, origins, directions, tmin, tmax, shapes):
        n = origins.shape[0]
        rays = np.zeros((n, 2, 4), np.float32)
        rays[:, 0, :3] = origins
        rays[:, 0, 3] = tmin
        rays[:, 1, :3] = directions
        # WGSL has no inf literal and may assume finite floats: a far tmax stands in for inf.
        rays[:, 1, 3] = np.where(np.isposinf(tmax), FAR, tmax)
        out = _run(kind, self.formula, False, rays, shapes, n)
        return np.where(out[:, 0] > 0.5, out[:, 1], np.inf).astype(np.float32)

    def spawn(self, kind, positions, normals, directions, shapes):
        if self.formula == "slide":
            return slide_spawn(positions)
        n = positions.shape[0]
        rays = np.zeros((n, 3, 4), np.float32)
        rays[:, 0, :3] = positions
        rays[:, 1, :3] = normals
        rays[:, 2, :3] = directions
        out = _run(kind, self.formula, True, rays, shapes, n)
        return out[:, :3].copy(), np.zeros(n, np.float32)
