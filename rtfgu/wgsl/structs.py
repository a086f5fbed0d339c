"""WGSL text generated from rtfgu.layout: the id constants, one struct per layout record,
and the buffer bindings. Nothing here chooses an offset: every offset and id is read from
rtfgu.layout, so the numba arrays and the WGSL structs cannot drift apart."""
from __future__ import annotations

import math

import numpy as np

from .. import layout
from ..materials.material import SHADER_NAMES
from ..cameras.camera import BLANK_TMAX, BLANK_TMIN
from ..ray import RAY_EPSILON
from ..ray import SPAWN_EPSILON
from ..tracers.whitted import MAX_DEPTH

# WGSL alignment and size of the field types the records use (WGSL spec, "Alignment and Size").
_TYPES = {3: ("vec3f", 16, 12), 1: ("f32", 4, 4)}


def _round_up(n: int, k: int) -> int:
    return (n + k - 1) // k * k


def _padding(start: int, end: int, first: int) -> list:
    """Explicit padding fields filling bytes [start, end): f32s up to a 16-byte boundary,
    then vec4fs, then f32s. (Explicit fields rather than @size: naga's OpenGL backend, the
    one llvmpipe runs, lays out @size members of uniform arrays wrongly.)"""
    pads, k = [], first
    while start < end:
        if start % 16 == 0 and end - start >= 16:
            pads.append(("_pad%d" % k, "vec4f", start))
            start += 16
        else:
            pads.append(("_pad%d" % k, "f32", start))
            start += 4
        k += 1
    return pads


def struct_fields(name: str) -> list:
    """(field, wgsl type, byte offset) for the record ``name``, in memory order, with the
    padding fields WGSL needs to put every field at the layout's offset. An offset WGSL
    cannot reach is a ValueError."""
    width, fields = layout.RECORDS[name]
    fields = sorted(fields, key=lambda f: f[2])
    out = []
    cur, struct_align = 0, 4
    for k, (field, components, column) in enumerate(fields):
        wgsl_type, align, size = _TYPES[components]
        offset = 4 * column
        if offset % align:
            raise ValueError("layout.RECORDS[%r].%s: column %d is not %d-byte aligned for %s"
                             % (name, field, column, align, wgsl_type))
        if offset < cur:
            raise ValueError("layout.RECORDS[%r].%s overlaps the field before it" % (name, field))
        if _round_up(cur, align) != offset:
            out += _padding(cur, offset, sum(1 for f in out if f[0].startswith("_pad")))
        out.append((field, wgsl_type, offset))
        struct_align = max(struct_align, align)
        cur = offset + size
    end = 4 * width
    if end < cur:
        raise ValueError("layout.RECORDS[%r]: fields run past the row width" % name)
    if _round_up(cur, struct_align) != end:
        out += _padding(cur, end, sum(1 for f in out if f[0].startswith("_pad")))
    return out


def struct_size(name: str) -> int:
    return 4 * layout.RECORDS[name][0]


def struct_wgsl(name: str) -> str:
    lines = ["struct %s {  // rtfgu.layout.RECORDS[%r], %d bytes" % (name, name, struct_size(name))]
    for field, wgsl_type, offset in struct_fields(name):
        lines.append("    %s: %s,  // byte %d" % (field, wgsl_type, offset))
    lines.append("};")
    return "\n".join(lines)


def _f32(x: float) -> str:
    return repr(float(x)) if math.isfinite(x) else "0.0"


def constants_wgsl() -> str:
    """Shader, shape-kind and camera-kind ids and the numbers the shaders share with the
    tracers and rays of the lecture layer, as WGSL constants."""
    lines = ["// Shader ids: the cases of shade's switch (rtfgu.materials)."]
    for shader_id, name in sorted(SHADER_NAMES.items()):
        lines.append("const %s: i32 = %d;" % (name.upper(), shader_id))
    lines.append("// Shape kinds and camera kinds (rtfgu.layout).")
    for kind, name in sorted(layout.SHAPE_KINDS.items()):
        lines.append("const %s: i32 = %d;" % (name.upper(), kind))
    for kind, name in sorted(layout.CAMERA_KINDS.items()):
        lines.append("const %s: i32 = %d;" % (name.upper(), kind))
    lines += [
        "// rtfgu.tracers.Whitted (02562: const max_depth = 10) and rtfgu.ray.",
        "const max_depth = %d;" % MAX_DEPTH,
        "const SPAWN_EPSILON = %sf;" % _f32(SPAWN_EPSILON),
        "const RAY_EPSILON = %sf;" % _f32(RAY_EPSILON),
        "// WGSL has no infinity literal: a fresh ray's tmax (rtfgu.layout.FAR).",
        "const FAR = %sf;" % _f32(layout.FAR),
        "const PI = %sf;" % _f32(math.pi),
        "// A blank ray's empty interval (rtfgu.cameras.camera.blank_ray).",
        "const BLANK_TMIN = %sf;" % _f32(BLANK_TMIN),
        "const BLANK_TMAX = %sf;" % _f32(BLANK_TMAX),
    ]
    return "\n".join(lines)


# The per-image values that are not scene arrays; the tile being rendered changes per dispatch.
UNIFORMS_WGSL = """struct Uniforms {
    background: vec3f,  // rtfgu.layout: FlatScene.background
    seed: u32,          // the random stream's seed (rtfgu/sampling/random.py)
    width: u32,
    height: u32,
    tile_origin: vec2u, // (column, row) of the tile's top-left pixel, row 0 at the top
    tile_size: vec2u,
    first_sample: u32,  // the dispatch adds samples first_sample <= s < end_sample
    end_sample: u32,
};"""
UNIFORMS_SIZE = 48


def uniforms(background, seed: int, width: int, height: int, origin=(0, 0), size=(0, 0),
             samples=(0, 1)) -> bytes:
    """The bytes of ``struct Uniforms``."""
    words = np.zeros(UNIFORMS_SIZE // 4, dtype=np.uint32)
    words.view(np.float32)[0:3] = background[:3]
    words[3] = seed
    words[4:12] = (width, height, origin[0], origin[1], size[0], size[1], samples[0], samples[1])
    return words.tobytes()
