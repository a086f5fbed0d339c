# release: solves a03 a04 a05
"""The per-kind loops of the numba path, generated from rtfgu.registry.

``intersect_scene``, ``in_shadow``, ``shape_normal``, the light loop over every light kind
(``direct_light``) and the ``shade`` switch name every kind of the registry; they are
written here as Python source from the registry (as rtfgu/wgsl/assemble.py writes the
WGSL ones), saved under a name that is the hash of their text, and imported from there, so
that numba's cache (keyed on a source file) keeps them between runs.

The scene reaches the kernels as flat tuples in registry order (numba's parallel loop
takes a tuple of arrays, not a tuple of tuples): ``shapes`` holds table, index per shape
kind, ``lights`` a table per light kind, each None for a kind the scene lacks, and last the
sets of the samplers lights and BRDFs have of their own, samples and orders, both None where
none has one (rtfgu.kernels.sampling.sampler_point). A kind's
entries go to a function of its own as arguments, and numba compiles that function with
the ``is None`` branch taken or removed, so a scene pays only for the kinds it has. ``hit`` is (t, scene index, kind, row); of two hits at the same t the one earlier
in Scene.shapes wins, whichever kind is visited first.

Only one shape kind may be ``from_eye`` (the sphere): a primary ray from a pinhole eye
tests only the tile's ``candidates[:n_candidates]`` with the per-frame ``terms`` of each
row; ``terms`` is None without such an eye, and ``n_candidates`` is -1 for any other ray.
Arrays travel as arguments of their own, never unpacked from a tuple per ray (that would
cost a reference count per ray).
"""
from __future__ import annotations

import hashlib
import importlib
import importlib.util
import os
import re
import sys
import tempfile
import warnings
from pathlib import Path
from types import ModuleType

import numpy as np

from .. import layout
from ..registry import INSTANCED, LIGHTS, SHADERS, SHAPE_IDS, SHAPES, TEXTURES
from .inline_cleanup import skip_dead_code_after_inlining
from .inline_copy import copy_inlined_scope_once
from .inline_frontend import untyped_ir_once
from .inline_typing import cache_inline_typing, compile_inline_bodies_once
from .liveness import use_bitset_liveness
from .llvm_passes import optimize_kernels_once

# The texels' place in the kernels' ``scene`` tuple; a table per texture kind follows.
TEXELS = 3

# Formula ids, the same for every kind; a kind without a formula uses its slide formula.
FORMULAS = ("slide", "robust")

# The arrays of a mesh kind in ``shapes``: rtfgu.layout.FlatMesh's, then the BVH's nodes and
# their int32 view (rtfgu.kernels.mesh). A row kind has two: its table and index.
MESH_SLOTS = ("vertices", "faces", "normals", "nodes", "links", "uvs")


def slots(kind) -> int:
    """A mesh kind's MESH_SLOTS; an instance kind's table and index, then the instanced table
    of each kind an instance may hold (rtfgu.registry.INSTANCED), then MESH_SLOTS for the
    meshes instances hold; a row kind's table and index."""
    if kind.bvh:
        return len(MESH_SLOTS)
    return 2 + len(INSTANCED) + len(MESH_SLOTS) if kind.instance else 2


def slot_offsets() -> dict:
    """Each shape kind's first entry in ``shapes``."""
    out, at = {}, 0
    for kind in SHAPES:
        out[kind.name] = at
        at += slots(kind)
    return out


def _mesh_parts(k: int, kind, at: int) -> list:
    """scan_, any_hit_, normal_row_ and texcoord_row_ of a mesh kind: the BVH's traversal
    (of the faces, and of the spheres and the instances when it holds them:
    rtfgu.layout.FlatMesh; ``instances`` is the instance kind's table, index and objects)."""
    name = kind.name
    return [
        _overloaded("scan_" + name, "vertices, faces, nodes, links, spheres, instances, origin, direction, tmin, hit, "
                    "formula", "hit",
                    "    return mesh_closest(vertices, faces, nodes, links, spheres, origin, direction, tmin, hit, "
                    "formula, np.int64(0), instances)",
                    "The nearest hit among what the BVH holds, given the nearest so far"),
        _overloaded("any_hit_" + name, "vertices, faces, nodes, links, spheres, instances, origin, direction, tmin, "
                    "tmax, formula", "False",
                    "    return mesh_any(vertices, faces, nodes, links, spheres, origin, direction, tmin, tmax, formula, "
                    "0, instances)",
                    "Is anything the BVH holds hit in [tmin, tmax)?"),
        _overloaded("normal_row_" + name, "vertices, faces, normals, row, position, direction", "position",
                    "    return normal_mesh(vertices, faces, normals, row, position)",
                    "The unit normal of face ``row`` at ``position``"),
        _overloaded("texcoord_row_" + name, "vertices, faces, uvs, row, position", "(position[0], position[0])",
                    "    return texcoord_mesh(vertices, faces, uvs, row, position)",
                    "The (u, v) of face ``row`` at ``position``"),
    ]


def _given_or_scan(name: str) -> str:
    """given_or_scan_ of a mesh kind: scan_ (the BVH's traversal), or, where intersect_scene
    is given the BVH's hit already (a packet's: rtfgu.kernels.packet), that hit kept if nearer
    than ``hit`` by the tie rule: every hit is kept by the smaller (t, scene index), so this
    is the hit the traversal would give."""
    params = "vertices, faces, nodes, links, spheres, instances, origin, direction, tmin, hit, formula"
    scan = "scan_%s(%s)" % (name, params)
    return _overloaded("given_or_scan_" + name, "given, " + params, scan,
                       "    return nearer_hit(hit, given)",
                       "The nearest hit among what the BVH holds, given the nearest so far, or the BVH's hit "
                       "given")


def _object_switch(name: str, params: str, call: str, mesh_call: str, default: str, doc: str) -> str:
    """``name(objects, kind, row, <params>)``: ``call`` (a format of the object kind's name,
    its instanced table in the tuple ``objects`` and ``params``) for the object's kind,
    ``mesh_call`` (a format of the places of MESH_SLOTS in ``objects``) for a mesh;
    ``default`` for none."""
    lines = ["@njit(cache=True, error_model=\"numpy\", inline=\"always\")",
             "def %s(objects, kind, row, %s):" % (name, params),
             '    """%s"""' % doc]
    for m, obj in enumerate(INSTANCED):
        lines.append("    if kind == %d:\n        return %s" % (SHAPE_IDS[obj.name],
                                                               call.format(kind=obj.name, table="objects[%d]" % m)))
    mesh = {slot: "objects[%d]" % (len(INSTANCED) + m) for m, slot in enumerate(MESH_SLOTS)}
    lines.append("    if kind == %d:\n        return %s" % (SHAPE_IDS[layout.MESH_KIND.name], mesh_call.format(**mesh)))
    lines.append("    return " + default)
    return "\n".join(lines)


def _objects(at: int) -> str:
    """The tuple of an instance kind's instanced tables and the MESH_SLOTS of the meshes
    instances hold, whose slots follow its table and index from ``at`` on in ``shapes``."""
    return "(%s,)" % ", ".join("shapes[%d]" % (at + 2 + m) for m in range(len(INSTANCED) + len(MESH_SLOTS)))


def _instance_parts(k: int, kind) -> list:
    """An instance kind's scan_, any_hit_, normal_row_ and texcoord_row_ (Suffern ch. 21,
    rtfgu/shapes/instance.py): the ray, the point and the direction through the row's inverse
    matrix (rtfgu.kernels.instance), then the object's kind through a switch over the instanced
    tables, ``objects`` (a tuple in INSTANCED order); a table the scene lacks is None and its
    case compiles to nothing."""
    name = kind.name
    columns = {f: c for f, _, c in layout.RECORDS[kind.record][1]}
    assert [columns[f] for f in ("row0", "t0", "row1", "t1", "row2", "t2")] == [0, 3, 4, 7, 8, 11], \
        "rtfgu.kernels.instance reads the inverse matrix at columns 0-11"
    obj = "int(table[%%s, %d]), int(table[%%s, %d])" % (columns["object_kind"], columns["object_row"])
    parts = []
    for o in INSTANCED:
        body = []
        for formula in o.formulas[::-1]:
            call = "%s(origin, direction, tmin, tmax, %s)" % (o.formula_function(formula), _row_args(o, "table", "row"))
            body.append("    if formula == %d:\n        return %s" % (FORMULAS.index(formula), call)
                        if formula != "slide" else "    return " + call)
        parts.append(_overloaded("instanced_t_" + o.name, "table, row, origin, direction, tmin, tmax, formula",
                                 "lit(math.inf, tmin)", "\n".join(body),
                                 "t of row ``row`` of the instanced %ss, or inf" % o.name))
    parts.append(_object_switch(
        "instanced_t", "origin, direction, tmin, tmax, formula, best",
        "(instanced_t_{kind}({table}, row, origin, direction, tmin, tmax, formula), 0, -1)",
        "instanced_mesh_t({vertices}, {faces}, {nodes}, {links}, row, origin, direction, tmin, tmax, best)",
        "(lit(math.inf, tmin), 0, -1)",
        "(t, place, face) of the object along the object-space ray: t in [tmin, tmax] or inf; a "
        "mesh's face hit, its place in the mesh and its row in faces (instanced_mesh_t), else 0 and -1."))
    parts.append("\n".join([
        "@njit(cache=True, error_model=\"numpy\", inline=\"always\")",
        "def instance_t(table, objects, i, origin, direction, tmin, tmax, formula, best):",
        '    """(t, place, face) of instance ``i`` (instanced_t): the BVH\'s test of an instance it holds."""',
        "    return instanced_t(objects, %s, instance_point(table, i, origin), instance_vector(table, i, direction), "
        "tmin, tmax, formula, best)" % (obj % ("i", "i"))]))
    parts.append(_object_switch("instanced_normal", "face, position, direction",
                                "normal_row_{kind}({table}, row, position, direction)",
                                "normal_row_mesh({vertices}, {faces}, {normals}, face, position, direction)",
                                "position", "The object's hit normal at an object-space point."))
    parts.append(_object_switch("instanced_texcoord", "face, position", "texcoord_row_{kind}({table}, row, position)",
                                "texcoord_row_mesh({vertices}, {faces}, {uvs}, face, position)",
                                "(position[0], position[0])", "The object's (u, v) at an object-space point."))
    # A hit's row is the instance's row, with a mesh's face row above bit 32 (FACE_SHIFT).
    keep = _KEEP.format(kind=k).replace("idx = index[i]", "idx = index[i] + place").replace(
        "row = i", "row = i + (face << FACE_SHIFT) if face >= 0 else i")
    scan = ["    tmax, best, kind, row = hit",
            "    for i in range(index.shape[0]):",
            "        t, place, face = instanced_t(objects, %s, instance_point(table, i, origin), "
            "instance_vector(table, i, direction), tmin, tmax, formula, best - index[i])"
            % (obj % ("i", "i"))] + [line[4:] for line in keep.split("\n")] + [
            "    return tmax, best, kind, row"]
    parts.append(_overloaded("scan_" + name, "table, index, objects, origin, direction, tmin, hit, formula",
                             "hit", "\n".join(scan), "The nearest hit among the instances, given the nearest so far",
                             absent_on="index"))
    parts.append(_overloaded(
        "any_hit_" + name, "table, index, objects, origin, direction, tmin, tmax, formula", "False",
        "\n".join(["    for i in range(index.shape[0]):",
                   "        if instanced_t(objects, %s, instance_point(table, i, origin), instance_vector(table, i, direction), "
                   "tmin, tmax, formula, -1)[0] < tmax:" % (obj % ("i", "i")),
                   "            return True",
                   "    return False"]),
        "Is any instance hit in [tmin, tmax)?", absent_on="index"))
    parts.append(_overloaded(
        "normal_row_" + name, "table, objects, row, position, direction", "position",
        "\n".join(["    i = row & FACE_MASK",
                   "    n = instanced_normal(objects, %s, row >> FACE_SHIFT, instance_point(table, i, position), "
                   "instance_vector(table, i, direction))" % (obj % ("i", "i")),
                   "    return normalize(instance_normal(table, i, n))"]),
        "The object's normal at the object-space point through the inverse transpose, normalised"))
    parts.append(_overloaded(
        "texcoord_row_" + name, "table, objects, row, position", "(position[0], position[0])",
        "\n".join(["    i = row & FACE_MASK",
                   "    return instanced_texcoord(objects, %s, row >> FACE_SHIFT, instance_point(table, i, position))"
                   % (obj % ("i", "i"))]),
        "The object's (u, v) at the object-space point"))
    return parts


def _row_args(kind, table: str, row: str) -> str:
    """The kind's fields read from ``table[row]`` in its registry order."""
    columns = {name: (components, column) for name, components, column in
               layout.RECORDS[kind.record][1]}
    out = []
    for name, _ in kind.fields:
        components, column = columns[name]
        out.append("row3(%s, %s, %d)" % (table, row, column) if components == 3
                   else "%s[%s, %d]" % (table, row, column))
    return ", ".join(out)


_KEEP = """            idx = index[i]
            if t < tmax or (t == tmax and idx < best):
                tmax = t
                best = idx
                kind = {kind}
                row = i"""


def _overloaded(name: str, params: str, absent: str, present: str, doc: str,
                eye_free: str = "", inline: str = "always", absent_on: str = "") -> str:
    """A function typed per call by an overload: the body ``absent`` when its first argument
    is None (a kind the scene lacks), ``present`` otherwise; with ``eye_free``, that body
    instead when ``terms`` is None. The choice is made when numba types the call, so it
    costs nothing at run time; ``inline="always"`` puts the body into the caller.
    ``absent_on``: the argument whose None means absent, if not the first."""
    lines = ["def %s(%s):" % (name, params),
             '    """%s (typed by the overload below)."""' % doc,
             "    return as_python(_typed_%s, %s)" % (name, params),
             "",
             "",
             "@overload(%s, inline=\"%s\")" % (name, inline),
             "def _typed_%s(%s):" % (name, params),
             "    if isinstance(%s, types.NoneType):" % (absent_on or params.split(",")[0]),
             "        def absent(%s):" % params,
             "            return %s" % absent,
             "        return absent"]
    if eye_free:
        lines += ["    if isinstance(terms, types.NoneType):",
                  "        def no_eye(%s):" % params]
        lines += ["        " + line if line else line for line in eye_free.split("\n")]
        lines += ["        return no_eye"]
    lines += ["    def present(%s):" % params]
    lines += ["    " + line if line else line for line in present.split("\n")]
    lines += ["    return present"]
    return "\n".join(lines)


def _branches(cases) -> list:
    """One if/elif/else chain over (condition, loop header lines, call) cases, every branch a
    loop over rows that keeps the nearest hit, and a single return after it: numba inlines
    the whole chain into the caller, and one exit keeps (t, index, kind, row) in registers."""
    lines = []
    for n, (condition, header, call, keep) in enumerate(cases):
        if len(cases) > 1:
            lines.append("    %s %s:" % ("if" if n == 0 else "elif", condition) if condition
                         else "    else:")
        pad = "    " if len(cases) > 1 else ""
        lines += [pad + line for line in header]
        lines.append(pad + "        t = " + call)
        lines += [pad + line[4:] for line in keep.split("\n")]
    return lines


def _scan(k: int, kind) -> str:
    """scan_<kind>: the nearest hit of this kind's rows, given the nearest so far."""
    name = kind.name
    keep = _KEEP.format(kind=k)
    rows = ["    for i in range(index.shape[0]):"]
    # One loop per formula: the formula is the same for every row, and a test of it inside
    # the loop would be paid per row.
    cases = [("formula == %d" % FORMULAS.index(f) if f != "slide" else "", rows,
              "%s(origin, direction, tmin, tmax, %s)" % (kind.formula_function(f), _row_args(kind, "table", "i")),
              keep)
             for f in sorted(kind.formulas, key=lambda f: f == "slide")]
    start = ["    tmax, best, kind, row = hit"]
    end = ["    return tmax, best, kind, row"]
    if not kind.from_eye:
        return _overloaded("scan_" + name, "table, index, origin, direction, tmin, hit, formula",
                           "hit", "\n".join(start + _branches(cases) + end),
                           "The nearest hit among the %ss, given the nearest so far" % name,
                           absent_on="index")
    # Primary rays from the eye: the tile's candidate rows, o - center and c per frame.
    radius = layout.offset(kind.record, "radius")
    candidates = ["    for c in range(n_candidates):", "        i = candidates[c]"]
    eye_cases = [
        ("n_candidates >= 0 and formula == %d" % FORMULAS.index("robust"), candidates,
         "%s_roots_robust(row3(terms, i, 0), terms[i, 3], table[i, %d], direction, tmin, tmax)"
         % (name, radius), keep),
        ("n_candidates >= 0", candidates,
         "%s_roots(row3(terms, i, 0), terms[i, 3], direction, tmin, tmax)" % name, keep)]
    return _overloaded("scan_" + name,
                       "table, index, terms, candidates, n_candidates, origin, direction, tmin, hit, formula",
                       "hit", "\n".join(start + _branches(eye_cases + cases) + end),
                       "The nearest hit among the %ss, given the nearest so far" % name,
                       eye_free="\n".join(start + _branches(cases) + end), absent_on="index")


def _inlined(signature: str, doc: list, body: list) -> str:
    """A generated function that numba inlines into its caller: ``def signature:``, its
    docstring lines ``doc`` and its ``body`` lines."""
    quoted = ['    """' + doc[0]] + ["    " + line for line in doc[1:]]
    quoted[-1] += '"""'
    return "\n".join(['@njit(cache=True, error_model="numpy", inline="always")', "def %s:" % signature]
                     + quoted + body)


def _eye_scan(k: int, kind) -> str:
    """eye_scan_<kind>: the from-eye kind's culled candidates tested against every primary ray
    of a tile at once, candidate by candidate (render.hits_one_by_one). Each ray meets the
    candidates in the order scan_'s eye loop takes them, with the same test and the same keep
    rule, so its hit is scan_'s bit for bit; the loop over the rays has no branch and reads
    arrays of one field each, so LLVM's loop vectoriser tests 8 rays an instruction.
    ``rays``: the tile's rays, field f of ray r at rays[f * stride + r] (origin 0-2, direction
    3-5, tmin 6); ``ts``, ``hits``, ``rows``: each ray's nearest hit so far, its t, its scene
    index and kind at hits[r] and hits[stride + r] (int32), its row at rows[r]. The loop keeps
    the candidate's place at hits[2 * stride + r] (int32, so that every value it stores is
    32 bits: eight rays an instruction), made a kind and a row after it."""
    radius = layout.offset(kind.record, "radius")
    loops = []
    for formula in ("robust", "slide"):
        roots = ("%s_roots_robust(temp, terms[i, 3], table[i, %d], direction, rays[6 * stride + r], tmax)"
                 % (kind.name, radius) if formula == "robust"
                 else "%s_roots(temp, terms[i, 3], direction, rays[6 * stride + r], tmax)" % kind.name)
        loops.append("\n".join([
            "    %s:" % ("if formula == %d" % FORMULAS.index("robust") if formula == "robust" else "else"),
            "        for c in range(n_candidates):",
            "            i = candidates[c]",
            "            temp = row3(terms, i, 0)",
            "            idx = index[i]",
            "            for r in range(count):",
            "                tmax = ts[r]",
            "                direction = (rays[3 * stride + r], rays[4 * stride + r], rays[5 * stride + r])",
            "                t = " + roots,
            "                keep = (t < tmax) | ((t == tmax) & (idx < hits[r]))",
            "                ts[r] = t if keep else tmax",
            "                hits[r] = idx if keep else hits[r]",
            "                hits[2 * stride + r] = c if keep else hits[2 * stride + r]"]))
    start = ["    for r in range(count):",
             "        hits[2 * stride + r] = -1"]
    end = ["    for r in range(count):",
           "        if hits[2 * stride + r] >= 0:",
           "            hits[stride + r] = %d" % k,
           "            rows[r] = candidates[hits[2 * stride + r]]",
           "    return 0"]
    return _overloaded("eye_scan_" + kind.name,
                       "table, index, terms, candidates, n_candidates, rays, count, stride, ts, hits, rows, formula",
                       "0", "\n".join(start + loops + end),
                       "The nearest hits among the %ss' candidates of a tile's primary rays, given the "
                       "nearest so far" % kind.name, eye_free="    return 0", absent_on="index")


def _rest_of_eye_kind(kind) -> str:
    """rest_<kind>: the from-eye kind for intersect_scene_after_eye, where eye_scan_ has tested
    its candidates already: nothing left, or scan_ where there is no eye."""
    params = "table, index, terms, candidates, n_candidates, origin, direction, tmin, hit, formula"
    return _overloaded("rest_" + kind.name, params, "hit", "    return hit",
                       "What is left of the %ss after eye_scan_%s" % (kind.name, kind.name),
                       eye_free="    return scan_%s(%s)" % (kind.name, params), absent_on="index")


def _any_hit(kind) -> str:
    """any_hit_<kind>: is any row of this kind hit in [tmin, tmax)? (a shadow ray)"""
    lines = []
    for formula in kind.formulas[::-1]:
        loop = ["    for i in range(index.shape[0]):",
                "        if %s(origin, direction, tmin, tmax, %s) < tmax:"
                % (kind.formula_function(formula), _row_args(kind, "table", "i")),
                "            return True"]
        if formula != "slide":
            loop = ["    if formula == %d:" % FORMULAS.index(formula)] + ["    " + l for l in loop]
            loop.append("        return False")
        lines += loop
    lines.append("    return False")
    return _overloaded("any_hit_" + kind.name, "table, index, origin, direction, tmin, tmax, formula",
                       "False", "\n".join(lines),
                       "Is any %s hit in [tmin, tmax)?" % kind.name, absent_on="index")


def _texcoord(kind) -> str:
    return _overloaded("texcoord_row_" + kind.name, "table, row, position", "(position[0], position[0])",
                       "    return texcoord_%s(position, %s)" % (kind.name, _row_args(kind, "table", "row")),
                       "The texture coordinates (u, v) of row ``row`` of the %ss at ``position``" % kind.name)


def _texture_lookup(texture) -> str:
    # A kind that reads the shape's (u, v) computes them here, so a scene without such a
    # kind compiles no texcoord; a solid texture gets zeros.
    uv = ("    u, v = shape_texcoord(shapes, kind, shape_row, position)" if texture.texcoord else
          "    u = v = position[0] * lit(0.0, position[0])")
    return _overloaded("lookup_" + texture.name, "table, row, texels, shapes, kind, shape_row, position, fallback",
                       "fallback",
                       uv + "\n    return texture_%s(table, row, texels, u, v, position)" % texture.name,
                       "The colour of row ``row`` of the %s table at ``position`` on the shape hit" % texture.name)


def _normal(kind) -> str:
    # A kind whose normal turns toward the ray (ShapeKind.faces_ray) takes the direction too.
    position = "position, direction" if kind.faces_ray else "position"
    return _overloaded("normal_row_" + kind.name, "table, row, position, direction", "position",
                       "    return normal_%s(%s, %s)" % (kind.name, position, _row_args(kind, "table", "row")),
                       "The unit normal of row ``row`` of the %ss at ``position``, hit along ``direction``"
                       % kind.name)


def _by_kind(name, row_function, what, default, mesh_slots, extra="") -> str:
    """``name(shapes, kind, row, position<extra>)``: ``row_function<kind>`` of the kind hit; a
    mesh kind's function takes its ``mesh_slots`` (places in MESH_SLOTS) instead of a table."""
    at = slot_offsets()
    lines = []
    for k, kind in enumerate(SHAPES):
        arrays = ", ".join("shapes[%d]" % (at[kind.name] + m) for m in mesh_slots) if kind.bvh \
            else "shapes[%d]" % at[kind.name]
        if kind.instance:   # the instance table, then the instanced tables
            arrays += ", " + _objects(at[kind.name])
        lines.append("    if kind == %d:\n        return %s%s(%s, row, position%s)"
                     % (k, row_function, kind.name, arrays, extra))
    return "\n".join([
        "@njit(cache=True, error_model=\"numpy\", inline=\"always\")",
        "def %s(shapes, kind, row, position%s):" % (name, extra),
        '    """%s of row ``row`` of shape kind ``kind``."""' % what] + lines + ["    return " + default])


def _draw(light, pad: str, pixel: str, sample: str, first: str, seed: str) -> list:
    """The lines that ask light ``j`` of ``table`` for (L_i, w_i, dist) at ``position``: an
    area kind through a point (u, v) of its sampler or of the stream (sampler_point), as
    AreaLight.get_direction then incident do (L G / pdf); another kind has one answer."""
    if not light.area:
        return [pad + "L_i, w_i, dist = sample_%s(table, j, position)" % light.name]
    column = layout.offset(light.record, "light_sampler")
    return [pad + "u, v = sampler_point(sets, table, j, %d, %s, %s, %s + LIGHT_U + 2 * j, %s, zero)"
            % (column, pixel, sample, first, seed),
            pad + "L_i, w_i, dist = sample_%s_area(table, j, position, normal, u, v)" % light.name]


def _direct(light) -> str:
    """The light loop (02562 "Sampling light in the shader"), written once per light kind.
    ``stream`` is (the bounce's first dimension, pixel, sample, seed, sampled): under
    AreaLighting (sampled) an area light is asked for a point of it (_draw), else as
    worksheet 5's point at its centre. ``sets``: the own samplers' sets (sampler_point)."""
    draw = _draw(light, "        ", "stream[1]", "stream[2]", "stream[0]", "stream[3]")
    if light.area:
        draw = (["        if stream[4]:"] + ["    " + line for line in draw]
                + ["        else:", "            L_i, w_i, dist = sample_%s(table, j, position)" % light.name])
    body = "\n".join([
        "    position, normal = surface_point",
        "    zero = lit(0, mat[0])",
        "    eps = lit(SPAWN_EPSILON, zero)",
        "    n_shadow = 0",
        "    for j in range(table.shape[0]):"] + draw + [
        "        cos_theta = dot(normal, w_i)",
        "        if zero > cos_theta:  # Python's max(cos_theta, 0.0)",
        "            cos_theta = zero",
        "        if cos_theta != zero:  # a light below the surface adds nothing",
        "            visible = True",
        "            if shadows:",
        "                n_shadow += 1",
        "                visible = not in_shadow(shapes, position, w_i, eps, dist - eps, formula)",
        "            if visible:",
        "                f = brdf(shader, mat, color, normal, w_o, w_i, cos_theta)",
        "                result = add(result, scale(mul(f, L_i), cos_theta))",
        "    return result, n_shadow"])
    return _overloaded("direct_" + light.name,
                       "table, sets, shader, mat, color, surface_point, w_o, shapes, shadows, formula, stream, result",
                       "result, 0", body,
                       "The light of every %s reflected by the surface, added to ``result``" % light.name,
                       inline="always")


def _direct_path(light) -> str:
    """PathTrace's light loop (Matte.direct_light, rtfgu/materials/matte.py) for one light kind: f_r = rho / pi,
    an area light through a point of it drawn from its sampler or the stream (path_dimension)."""
    draw = _draw(light, "        ", "pixel", "sample", "first", "seed")
    body = "\n".join([
        "    position, normal, w_o = surface",
        "    rho, specular, shininess = brdf",
        "    first, pixel, sample, seed = stream",
        "    zero = lit(0, rho[0])",
        "    eps = lit(SPAWN_EPSILON, zero)",
        "    f = div(rho, lit(math.pi, zero))",
        "    n_shadow = 0",
        "    for j in range(table.shape[0]):"] + draw + [
        "        if L_i[0] == zero and L_i[1] == zero and L_i[2] == zero:",
        "            continue",
        "        cos_theta = dot(normal, w_i)",
        "        if not cos_theta > zero:",
        "            continue",
        "        if shadows:",
        "            n_shadow += 1",
        "            if in_shadow(shapes, position, w_i, eps, dist - eps, formula):",
        "                continue",
        "        f_r = add(f, glossy_lobe(specular, shininess, normal, w_o, w_i, cos_theta))",
        "        result = add(result, scale(mul(f_r, L_i), cos_theta))",
        "    return result, n_shadow"])
    return _overloaded("direct_path_" + light.name,
                       "table, sets, shapes, surface, brdf, stream, shadows, formula, result",
                       "result, 0", body,
                       "The light of every %s reflected by a diffuse surface on a path, added to ``result``"
                       % light.name, inline="always")


def source() -> str:
    """The generated module's text."""
    eye_kinds = [kind for kind in SHAPES if kind.from_eye]
    if len(eye_kinds) > 1:
        raise ValueError("rtfgu.registry: at most one shape kind may be from_eye, got %s"
                         % ", ".join(k.name for k in eye_kinds))
    imports = {}
    for kind in SHAPES:
        names = imports.setdefault(kind.numba_module, set())
        if kind.bvh:
            names.update(("mesh_closest", "mesh_any", "normal_mesh", "texcoord_mesh", "instanced_mesh_t"))
            continue
        if kind.instance:
            names.update(("instance_point", "instance_vector", "instance_normal", "FACE_SHIFT", "FACE_MASK"))
            continue
        names.update(kind.formula_function(f) for f in kind.formulas)
        names.add("normal_" + kind.name)
        if kind.from_eye:
            names.update((kind.name + "_roots", kind.name + "_roots_robust"))
    shader_names = set()
    for shader in SHADERS:
        if shader.brdf and not shader.brdf_of:
            shader_names.add("brdf_" + shader.name)
        if shader.continues:
            shader_names.add("continue_" + shader.name)
    header = ['"""Generated from rtfgu.registry by rtfgu.kernels.dispatch: do not edit."""',
             "from numba import njit, types",
             "from numba.extending import overload",
             "from rtfgu.kernels.dispatch_support import as_python",
             "from rtfgu.kernels.float3 import add, load3, lit, dot, mul, neg, row3, scale",
             "import math",
             "import numpy as np",
             "from rtfgu.kernels.float3 import div, normalize",
             "from rtfgu.kernels.lights import %s" % ", ".join(
                 ["sample_" + l.name for l in LIGHTS if l.ray_cast] + ["sample_%s_area" % l.name for l in LIGHTS if l.area]),
             "from rtfgu.kernels.sampling import sampler_point, sampler_sets",
             "from rtfgu.kernels.packet import mesh_closest_packet, nearer_hit",
             "from rtfgu.kernels.glossy import glossy_lobe",
             "from rtfgu.sampling.random import LIGHT_U",
             "from rtfgu.kernels.shaders import ends, surface, %s" % ", ".join(sorted(shader_names)),
             "from rtfgu.layout import MAT_COLOR, MAT_EMISSION, MAT_TEXTURE, MAT_TEXTURE_ROW",
             "from rtfgu.kernels.textures import %s" % ", ".join(
                 ["texcoord_" + k.name for k in SHAPES if not (k.bvh or k.instance)]
                 + ["texture_" + t.name for t in TEXTURES]),
             "from rtfgu.ray import SPAWN_EPSILON"]
    for module, names in sorted(imports.items()):
        header.append("from %s import %s" % (module, ", ".join(sorted(names))))
    parts = [header[0] + "\n" + "\n".join(header[1:])]
    at = slot_offsets()
    for k, kind in enumerate(SHAPES):
        if kind.bvh:
            parts += _mesh_parts(k, kind, at[kind.name])
        elif not kind.instance:
            parts += [_scan(k, kind), _any_hit(kind), _normal(kind), _texcoord(kind)]
            if kind.from_eye:
                parts += [_eye_scan(k, kind), _rest_of_eye_kind(kind)]
    for k, kind in enumerate(SHAPES):   # after the kinds an instance holds, whose functions they call
        if kind.instance:
            parts += _instance_parts(k, kind)
    for texture in TEXTURES:
        parts.append(_texture_lookup(texture))

    calls = []
    shadow_calls = []
    eye_at = len(SHAPES)   # calls[:eye_at]: the kinds intersect_scene tests before the from-eye kind
    for k, kind in enumerate(SHAPES):
        a = at[kind.name]
        if kind.from_eye:
            eye_at = len(calls)
        if eye_at == len(SHAPES) and eye_kinds and (kind.bvh or kind.instance):
            raise ValueError("rtfgu.registry: the from-eye kind must come before the %s kind" % kind.name)
        if kind.bvh:
            instance = at["instance"]
            mesh = "shapes[%d], shapes[%d], shapes[%d], shapes[%d], shapes[%d], (shapes[%d], shapes[%d], %s)" % (
                a, a + 1, a + 3, a + 4, at["sphere"], instance, instance + 1, _objects(instance))
            calls.append("    hit = given_or_scan_%s(given, %s, origin, direction, tmin, hit, formula)" % (kind.name, mesh))
            shadow_calls.append("    if any_hit_%s(%s, position, w_i, tmin, tmax, formula):\n        return True"
                                % (kind.name, mesh))
            parts.append(_given_or_scan(kind.name))
            parts.append("\n".join([
                "@njit(cache=True, error_model=\"numpy\", inline=\"always\")",
                "def trace_packet(shapes, origins, directions, count, tmin, t, best, kind, row, formula):",
                '    """The nearest hits among what the scene\'s BVH holds of a packet of rays, as',
                '    rtfgu.kernels.packet.mesh_closest_packet takes them (its wide tree: rtfgu.kernels.render',
                '    packs a pinhole\'s rays only where the scene has one)."""',
                "    mesh_closest_packet(shapes[%d], shapes[%d], shapes[%d], shapes[%d], shapes[%d], (origins, directions, "
                "count, tmin), (t, best, kind, row), formula, 0, (shapes[%d], shapes[%d], %s))"
                % (a, a + 1, a + 3, a + 4, at["sphere"], instance, instance + 1, _objects(instance))]))
            continue
        eye_args = "terms, candidates, n_candidates, " if kind.from_eye else ""
        if kind.instance:
            eye_args = _objects(a) + ", "
        calls.append("    hit = scan_%s(shapes[%d], shapes[%d], %sorigin, direction, tmin, hit, formula)"
                     % (kind.name, a, a + 1, eye_args))
        shadow_args = eye_args if kind.instance else ""
        shadow_calls.append("    if any_hit_%s(shapes[%d], shapes[%d], %sposition, w_i, tmin, tmax, formula):\n        return True"
                            % (kind.name, a, a + 1, shadow_args))
    parts.append("\n".join([
        "@njit(cache=True, error_model=\"numpy\", inline=\"always\")",
        "def intersect_scene(shapes, terms, candidates, n_candidates, origin, direction, tmin, tmax, formula, "
        "given=None):",
        '    """The nearest hit over every shape: (t, scene index, kind, row), index -1 on a miss.',
        "    ``given``: None, or the hit of what the BVH holds, found before (a packet's), taken",
        '    instead of traversing the BVH."""',
        "    hit = (tmax, -1, -1, -1)"] + calls + ["    return hit"]))
    # intersect_scene in three steps for a tile of primary rays (render.hits_one_by_one): the
    # kinds before the from-eye kind ray by ray, its candidates for all rays at once
    # (eye_scan), the rest ray by ray; each ray meets every shape in intersect_scene's order.
    if eye_at < len(SHAPES):
        eye = eye_kinds[0]
        a = at[eye.name]
        after = ["    hit = rest_%s(shapes[%d], shapes[%d], terms, candidates, n_candidates, origin, direction, "
                 "tmin, hit, formula)" % (eye.name, a, a + 1)] + calls[eye_at + 1:]
        eye_scan = ["    eye_scan_%s(shapes[%d], shapes[%d], terms, candidates, n_candidates, rays, count, stride, ts, "
                    "hits, rows, formula)" % (eye.name, a, a + 1)]
    else:
        after, eye_scan = calls[eye_at:], []
    parts.append(_inlined("intersect_scene_before_eye(shapes, origin, direction, tmin, hit, formula)",
                          ["intersect_scene's kinds before the from-eye kind, given the nearest hit so far."],
                          calls[:eye_at] + ["    return hit"]))
    parts.append(_inlined("eye_scan(shapes, terms, candidates, n_candidates, rays, count, stride, ts, hits, rows, formula)",
                          ["The from-eye kind's candidates against a tile's primary rays (eye_scan_ of the kind)."],
                          eye_scan + ["    return 0"]))
    parts.append(_inlined("intersect_scene_after_eye(shapes, terms, candidates, n_candidates, origin, direction, tmin, "
                          "hit, formula, given=None)",
                          ["intersect_scene's from-eye kind where eye_scan did not test it, and the kinds after it,",
                           "given the nearest hit so far."],
                          after + ["    return hit"]))
    parts.append(_inlined("in_shadow(shapes, position, w_i, tmin, tmax, formula)",
                          ["A shadow ray: is any shape hit in [tmin, tmax)? (Light.in_shadow, rtfgu/lights/light.py)"],
                          shadow_calls + ["    return False"]))
    parts.append(_by_kind("shape_normal", "normal_row_", "hit_normal(position, direction)", "position",
                          (0, 1, 2), extra=", direction"))
    parts.append(_by_kind("shape_texcoord", "texcoord_row_", "Shape.texcoord(position)",
                          "position[0], position[0]", (0, 1, 5)))
    # The colour of the surface hit: the material's, or its texture's at the hit. The
    # kernels' ``scene`` holds the texels at TEXELS and a table per texture kind after them
    # (rtfgu.kernels.render.scene_tuple).
    lookups = ["        if texture == %d:\n            return lookup_%s(scene[%d], int(mat[MAT_TEXTURE_ROW]), "
               "scene[%d], shapes, kind, row, position, color)" % (k, t.name, TEXELS + 1 + k, TEXELS)
               for k, t in enumerate(TEXTURES)]
    parts.append(_overloaded(
        "surface_color", "scene, shapes, mat, kind, row, position",
        "load3(mat, MAT_COLOR)",
        "\n".join(["    color = load3(mat, MAT_COLOR)",
                   "    texture = int(mat[MAT_TEXTURE])",
                   "    if texture >= 0:"] + lookups
                  + ["    return color"]),
        "The colour of the surface hit: its texture's at the hit (Scene.intersect), else the "
        "material's; the texture entries of ``scene`` are None in a scene without textures",
        absent_on="scene.types[%d]" % TEXELS))
    for light in LIGHTS:
        if light.ray_cast:
            parts.append(_direct(light))
        parts.append(_direct_path(light))
    parts.append("\n".join(
        ["@njit(cache=True, error_model=\"numpy\", inline=\"always\")",
         "def direct_path(lights, shapes, surface, brdf, stream, shadows, formula):",
         '    """PathTrace\'s light loop over every light kind: (radiance, shadow rays). ``surface``:',
         "    (position, normal, w_o); ``brdf``: (rho, rho_s, shininess); ``stream``: (the vertex's first",
         '    dimension, pixel, sample, seed)."""',
         "    zero = lit(0, brdf[0][0])",
         "    result = (zero, zero, zero)",
         "    n_shadow = 0"]
        + ["    sets = sampler_sets(lights[%d], lights[%d], lights[%d])" % (len(LIGHTS), len(LIGHTS) + 1, len(LIGHTS) + 2)]
        + ["    result, n = direct_path_%s(lights[%d], sets, shapes, surface, brdf, stream, shadows, formula, result)\n"
           "    n_shadow += n" % (light.name, j) for j, light in enumerate(LIGHTS)]
        + ["    return result, n_shadow"]))

    # One branch per BRDF function: shaders that share one (brdf_of) share its branch.
    brdf_of = {}
    for shader in SHADERS:
        if shader.brdf:
            brdf_of.setdefault(shader.brdf_of or shader.name, []).append(shader.id)
    brdf_lines = ["@njit(cache=True, error_model=\"numpy\", inline=\"always\")",
                  "def brdf(shader, mat, color, normal, w_o, w_i, cos_theta):",
                  '    """The BRDF term of the shader with id ``shader``."""']
    for name, ids in brdf_of.items():
        brdf_lines.append("    if %s:\n        return brdf_%s(mat, color, normal, w_o, w_i, cos_theta)"
                          % (" or ".join("shader == %d" % i for i in ids), name))
    brdf_lines.append("    return color")
    parts.append("\n".join(brdf_lines))

    def case(shader) -> str:
        guard = "bounces is not None and " if shader.continues else ""
        return "%sshader == %d" % (guard, shader.id)

    # The light loop is written once, for every shader with a BRDF (each supplies its term
    # through ``brdf``); such a shader that continues the path does so after it.
    light_calls = ["        sets = sampler_sets(lights[%d], lights[%d], lights[%d])" % (len(LIGHTS), len(LIGHTS) + 1, len(LIGHTS) + 2)]
    light_calls += ["        result, n = direct_%s(lights[%d], sets, shader, mat, color, surface_point, neg(r_d), shapes, shadows, formula, stream, result)\n"
                    "        n_shadow += n" % (light.name, j) for j, light in enumerate(LIGHTS) if light.ray_cast]
    lit_shaders = [shader for shader in SHADERS if shader.brdf and not shader.emits]
    shade_lines = ["@njit(cache=True, error_model=\"numpy\", inline=\"always\")",
                   "def shade(shader, mat, color, r_d, surface_point, lights, shapes, shadows, bounces, formula, stream):",
                   '    """The slide\'s ``switch (*hit).shader``: (radiance, has_hit, further rays,',
                   '    shadow rays), the further rays as continue_<name> gives them (rtfgu.kernels.shaders);',
                   '    ``color`` is the surface\'s (surface_color). A shader that continues the path exists',
                   '    only when ``bounces`` does; ``stream`` as for the light loop."""',
                   "    n_shadow = 0"]
    if lit_shaders:
        shade_lines.append("    if %s:  # %s" % (" or ".join("(%s)" % case(s) if s.continues else case(s)
                                                             for s in lit_shaders),
                                                 ", ".join(s.name for s in lit_shaders)))
        shade_lines.append("        result = surface(mat, color)")
        shade_lines += light_calls
        for shader in lit_shaders:
            if shader.continues:
                shade_lines.append("        if %s:  # %s" % (case(shader), shader.name))
                shade_lines.append("            return result, False, continue_%s(mat, r_d, surface_point[1]), n_shadow"
                                   % shader.name)
        shade_lines.append("        return result, True, ends(r_d), n_shadow")
    for shader in SHADERS:
        if shader.emits:
            shade_lines.append("    if shader == %d:  # %s" % (shader.id, shader.name))
            shade_lines.append("        return load3(mat, MAT_EMISSION), True, ends(r_d), n_shadow")
        elif shader.continues and not shader.brdf:
            shade_lines.append("    if %s:  # %s" % (case(shader), shader.name))
            shade_lines.append("        result = load3(mat, MAT_EMISSION)")
            shade_lines.append("        return result, False, continue_%s(mat, r_d, surface_point[1]), n_shadow"
                               % shader.name)
    shade_lines.append("    return color, True, ends(r_d), n_shadow")
    parts.append("\n".join(shade_lines))
    return "\n\n\n".join(parts) + "\n"


def cache_dir() -> Path:
    """A writable folder for the generated module and numba's cache: RTFGU_CACHE_DIR, else
    beside this file, else the user's cache folder."""
    for candidate in (os.environ.get("RTFGU_CACHE_DIR"), Path(__file__).resolve().parent / "__generated__",
                      Path.home() / ".cache" / "rtfgu", Path(tempfile.gettempdir()) / "rtfgu"):
        if not candidate:
            continue
        path = Path(candidate)
        try:
            path.mkdir(parents=True, exist_ok=True)
            (path / ".writable").touch()
            return path
        except OSError:
            continue
    raise OSError("rtfgu.kernels.dispatch: no writable folder for the generated kernels "
                  "(set RTFGU_CACHE_DIR)")


# ``from ..module import a, b as c`` or ``from ..module import (a, b,\n c)`` at a line's start.
_PACKAGE_IMPORT = re.compile(r"^[ \t]*from \.\.(?P<module>[\w.]*) import (?:\((?P<multi>[^)]*)\)|(?P<single>[^\n#]*))",
                             re.MULTILINE)


def package_imports(text: str) -> list:
    """(module, names) of each ``from ..module import names`` in the Python source ``text``
    (a kernel module's), module named from the package: "rtfgu.layout"."""
    found = []
    for match in _PACKAGE_IMPORT.finditer(text):
        names = re.sub(r"#[^\n]*", "", match["multi"] or match["single"]).split(",")
        found.append(("rtfgu" + ("." + match["module"] if match["module"] else ""),
                      tuple(sorted(n.split()[0] for n in names if n.strip()))))
    return found


def kernel_imports() -> list:
    """(module, names) of every ``from ..module import names`` in the kernel modules: what
    they take from the rest of the package (the layout's offsets, the registry's kinds, a
    tracer's depth, the BVH's node layout, the noise's tables), read from their source."""
    found = set()
    for path in sorted(Path(__file__).resolve().parent.glob("*.py")):
        for module, names in package_imports(path.read_text()):
            if module != "rtfgu.kernels" and not module.startswith("rtfgu.kernels."):
                found.add((module, names))
    return sorted(found)


def _hash_value(digest, value, files: set) -> None:
    """Add ``value`` to ``digest``: numbers, strings and arrays by what they hold, containers
    element by element; a module, class, function or other object goes into ``files`` as
    the source file of the module that defines it."""
    if value is None or isinstance(value, (bool, int, float, complex, str, bytes, np.generic)):
        digest.update(repr(value).encode())
    elif isinstance(value, np.ndarray):
        digest.update(("%s%s" % (value.dtype, value.shape)).encode())
        digest.update(np.ascontiguousarray(value).tobytes())
    elif isinstance(value, (tuple, list)):
        digest.update(b"(")
        for item in value:
            _hash_value(digest, item, files)
        digest.update(b")")
    elif isinstance(value, dict):
        for key in sorted(value, key=repr):
            _hash_value(digest, key, files)
            _hash_value(digest, value[key], files)
    else:
        module = value if isinstance(value, ModuleType) else sys.modules.get(
            getattr(value, "__module__", None) or type(value).__module__)
        if getattr(module, "__file__", None):
            files.add(Path(module.__file__))


def kernel_version() -> str:
    """A hash of every source the compiled kernels depend on: the kernel modules, the
    generated text, and the modules the kernels import from the rest of the package
    (kernel_imports) with the values of what they import. numba checks only the file of the
    function it caches, and it compiles a global's value into the code (a constant such as
    the wide BVH's ROWS or a tracer's depth), so a kernel compiled against an older
    registry, an older intersect.py or an older constant would be loaded from its cache; a
    cache folder per version cannot be."""
    digest = hashlib.sha256(source().encode())
    files = set(Path(__file__).resolve().parent.glob("*.py"))
    for module_name, names in kernel_imports():
        module = importlib.import_module(module_name)
        files.add(Path(module.__file__))
        for name in names:
            digest.update(("%s.%s" % (module_name, name)).encode())
            _hash_value(digest, getattr(module, name), files)
    package = Path(__file__).resolve().parent.parent
    for path in sorted(files):
        digest.update(str(path.relative_to(package) if package in path.parents else path.name).encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:16]


def use_versioned_cache() -> None:
    """Point numba's cache at a folder of this kernel version (unless the user chose one
    with NUMBA_CACHE_DIR). Called before any kernel is defined."""
    import numba

    if os.environ.get("NUMBA_CACHE_DIR"):
        return
    numba.config.CACHE_DIR = str(cache_dir() / ("numba-" + kernel_version()))


def _quiet_inlined_loops() -> None:
    """numba's SSA pass reports a pedantic NumbaIRAssumptionWarning ("variable ... is not in
    scope") for loop variables of an overload body inlined with inline="always", such as the
    light loop's; the compiled code is right (the parity tests compare it bit for bit with
    the lecture layer), so only those warnings are silenced."""
    from numba.core.errors import NumbaIRAssumptionWarning

    warnings.filterwarnings("ignore", message=r"variable '_typed_\w+__locals__",
                            category=NumbaIRAssumptionWarning)


def load():
    """The generated module, written once per distinct text and imported from its file."""
    text = source()
    digest = hashlib.sha256(text.encode()).hexdigest()[:16]
    name = "rtfgu_dispatch_" + digest
    if name in sys.modules:
        return sys.modules[name]
    path = cache_dir() / (name + ".py")
    if not path.is_file() or path.read_text() != text:
        tmp = path.with_suffix(".tmp%d" % os.getpid())
        tmp.write_text(text)
        os.replace(tmp, path)
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


use_versioned_cache()
cache_inline_typing()
compile_inline_bodies_once()
copy_inlined_scope_once()
untyped_ir_once()
skip_dead_code_after_inlining()
use_bitset_liveness()
optimize_kernels_once()
_quiet_inlined_loops()
_generated = load()
intersect_scene = _generated.intersect_scene
in_shadow = _generated.in_shadow
shape_normal = _generated.shape_normal
shade = _generated.shade
surface_color = _generated.surface_color
direct_path = _generated.direct_path
instance_t = _generated.instance_t
trace_packet = _generated.trace_packet
intersect_scene_before_eye = _generated.intersect_scene_before_eye
eye_scan = _generated.eye_scan
intersect_scene_after_eye = _generated.intersect_scene_after_eye
