# release: solves a03 a04 a05
"""The pixel loop on all cores: the lecture's render loop (lecture 01 "Rendering a Scene")
and the 02562 path loop (``main_fs``), in tiles that the threads claim as they go
(rtfgu.kernels.threads).

Every pixel is computed on its own from the same inputs, so the image is the same bit for
bit for any number of threads. The scene arrives grouped (rtfgu.kernels.kernel_arguments):

    camera    (camera kind, camera row, the camera row in float64 for the tile culling)
    shapes    table, index per registered shape kind; lights: a table per light kind; None
              for a kind the scene lacks (rtfgu.kernels.dispatch)
    scene     (materials, shaders, background, texels, a table per texture kind,
              environment, material_of): the distinct materials' rows and shader ids, each
              shape's row among them last (rtfgu.layout.FlatScene); the texture entries None
              in a scene without textures, the environment None without an EnvironmentLight
              (scene_tuple)
    eye       None, or (per-frame terms, culling cones) of the from-eye shape kind
    settings  (shadows, show_ray_direction, formula id, seed, first sample, end sample)
    tracer    (cast, path, packets, phases), cast or path None: ``cast`` the ray-cast loop's
              (bounces, sampled, stacks), bounces None when no shader continues a path (that
              code then compiles to nothing), else MAX_DEPTH; sampled: AreaLighting's area
              lights; stacks: (tiles, MAX_DEPTH, STACK_FIELDS) rays waiting, a stack per tile,
              or None where no material sends a second ray (trace); ``path`` PathTrace's
              (max_depth, lights at every vertex: False for GlobalTrace)
              (rtfgu.kernels.path_trace); ``packets`` 1 where a pinhole's primary rays go
              through the scene's wide BVH in packets (hits_in_packets), else None;
              ``phases`` how the ray-cast tracer finds its hits (kernel_arguments' hit_phases)
    sampler   None (one sample at each pixel's centre), or the FlatSampler's
              (samples, shuffled, num_samples, num_sets) (rtfgu.kernels.sampling)

render_tile takes ``cast`` and ``path`` as arguments of their own: numba removes a branch on
``argument is not None`` before it types a function whose argument is None, so render_tile
compiles only the scene's tracer, inlined, and types it once.

``image`` holds each pixel's sum of samples: a render adds samples first <= s < end to
it, in order, so passes that split the samples sum to the same bits as one render.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit, types
from numba.extending import overload

from ..accelerators.wide_bvh import FACE_COLUMNS, ROWS, WIDTH
from ..layout import MESH_KIND, PINHOLE, THIN_LENS, offset
from ..materials.material import BASE_COLOR
from ..registry import INSTANCED, SHAPE_IDS, SHAPES, TEXTURES
from ..sampling.random import LENS_SET, PIXEL_SET, VERTEX_DIMENSIONS
from ..ray import SPAWN_EPSILON
from .camera import gen_ray, thin_lens_ray
from .culling import tile_candidates
from .dispatch import (MESH_SLOTS, eye_scan, intersect_scene, intersect_scene_after_eye, intersect_scene_before_eye,
                       shade, shape_normal, slots, surface_color, trace_packet)
from .dispatch_support import as_python
from .float3 import add, lit, mul, scale
from .environment import ENVIRONMENT, MATERIAL_OF, background_radiance
from .path_trace import trace_path
from .wide_bvh import WIDE, on_the_stack
from .packet import PACKET, lanes_of as packet_lanes
from .sampling import concentric_map, pixel_sample
from .threads import claim, fetch_add, finish, run_in_threads

# Tiles of TILE x TILE pixels are the unit of parallel work.
TILE = 16

packet_rays = on_the_stack(3 * PACKET, "A packet's origins or directions, three values a ray.")

# counts columns: rays cast per tile, by kind; then 1 where a value of the tile's sums is
# not finite after the range's last sample, else 0 (a render of one sample refuses its image
# by it, with no pass over the image of its own).
PRIMARY = 0
SHADOW = 1
SECONDARY = 2
NOT_FINITE = 3
COUNTS = 4

# A row of record_bounce: [origin (3), direction (3), t, scene index, kind, shader,
# normal (3), colour added (3)].
RECORD_FIELDS = 16


def shape_arrays(flat, empty: bool = False) -> tuple:
    """The kernels' ``shapes``: table, index per row kind, the FlatMesh's arrays and the BVH
    (rtfgu.kernels.dispatch.MESH_SLOTS) for a mesh kind, None for every kind the scene lacks.

    With ``empty`` (the pixel debugger's: one kernel for every scene of a precision), every
    entry is an array that changes nothing where the scene lacks it. A kind the scene lacks
    is its empty table and index; the spheres or instances the BVH holds have an empty index
    (the loops over a kind's rows run over its index: their rows are reached through the
    tree); a scene without a tree of its own has empty_tree's (the tree of a scene whose
    meshes are all instances' starts at a mesh's root); a mesh without vertex normals or
    (u, v) has zero ones (a zero normal is the flat one, rtfgu.kernels.mesh.normal_mesh; a
    (u, v) of third column 0 the barycentrics, texcoord_mesh); the instances' mesh slots hold
    the scene's mesh, which no instance then names, or empty_tree's."""
    shapes = ()
    mesh = mesh_arrays(flat, empty) if flat.mesh is not None else None
    absent = empty_tree(flat.dtype) if empty else (None,) * len(MESH_SLOTS)
    for kind in SHAPES:
        if kind.bvh:   # the scene's own tree; absent where its meshes are all instances'
            shapes += mesh if mesh is not None and flat.mesh.scene_tree else absent
        elif kind.instance and (flat.count(kind.name) or empty):
            # The instance table and index, then the instanced table of each kind an instance
            # may hold (None for a kind none holds), then the mesh arrays with the trees of
            # the meshes instances hold (absent where none holds one).
            # The index is None where the BVH holds the instances (no loop of their own; the
            # debugger's is empty).
            in_bvh = flat.mesh is not None and flat.mesh.instances
            index = flat.index(kind.name)
            if in_bvh:
                index = np.zeros(0, dtype=index.dtype) if empty else None
            held = "instanced_mesh" in flat.features or (empty and mesh is not None)
            shapes += (instance_table(flat, kind.name), index) + tuple(
                flat.instanced[k.name] if len(flat.instanced[k.name]) or empty else None for k in INSTANCED) \
                + (mesh if held else absent)
        elif flat.count(kind.name) == 0:
            shapes += ((flat.table(kind.name), flat.index(kind.name)) if empty else (None, None)) \
                + (None,) * (slots(kind) - 2)
        elif kind.name == "sphere" and flat.mesh is not None and flat.mesh.spheres:
            # The BVH holds the spheres: no loop of their own (scan and any_hit are absent
            # without an index, and loop over none with an empty one), their table kept for
            # the BVH, their normals and (u, v).
            index = flat.index(kind.name)
            shapes += (flat.table(kind.name), np.zeros(0, dtype=index.dtype) if empty else None)
        else:
            shapes += (flat.table(kind.name), flat.index(kind.name))
    return shapes


def numba_tree(mesh):
    """The wide tree (rtfgu.accelerators.wide_bvh) the numba path traverses for a FlatMesh:
    its bottom nodes made blocks (with_blocks), in float32 with copies of their faces'
    corners, in float64 without (their test gathers the corners through the faces)."""
    return mesh.bvh.wide_with_blocks(mesh.tree_roots, mesh.vertices, mesh.faces)


def mesh_arrays(flat, empty: bool = False) -> tuple:
    """The FlatMesh's arrays in MESH_SLOTS order, with the tree the numba path traverses: the
    wide one (numba_tree) where the CPU has vector units (rtfgu.kernels.wide_bvh.WIDE), else
    the binary one. With ``empty`` (shape_arrays), zero normals and (u, v) for a mesh
    without them, in place of None."""
    mesh = flat.mesh
    nodes = numba_tree(mesh).nodes if WIDE else mesh.bvh.nodes
    normals, uvs = mesh.normals, mesh.uvs
    if empty:
        normals = np.zeros_like(mesh.vertices) if normals is None else normals
        uvs = np.zeros_like(mesh.vertices) if uvs is None else uvs
    return mesh.vertices, mesh.faces, normals, nodes, nodes.view(np.int32), uvs


def empty_tree(dtype) -> tuple:
    """mesh_arrays of a mesh of no face (shape_arrays with ``empty``): vertices, faces,
    normals and (u, v) of no row, and a tree of one node whose boxes are empty (lo = +inf,
    hi = -inf), which no ray enters, so a traversal of it returns the hit it was given; the
    wide node (rtfgu.accelerators.wide_bvh) where the CPU has vector units, else the binary
    one (rtfgu.accelerators.flat_bvh: lo at columns 0-2, hi at 4-6)."""
    if WIDE:
        nodes = np.zeros((1, ROWS, WIDTH), dtype=np.float32)
        nodes[0, :3], nodes[0, 3:6] = np.inf, -np.inf
    else:
        nodes = np.zeros((1, 8), dtype=np.float32)
        nodes[0, :3], nodes[0, 4:7] = np.inf, -np.inf
    none = np.zeros((0, 3), dtype=dtype)
    return none, np.zeros((0, FACE_COLUMNS), dtype=np.int32), none.copy(), nodes, nodes.view(np.int32), none.copy()


def instance_table(flat, kind: str) -> np.ndarray:
    """The instance table as the numba path reads it: an instance of a Mesh names its mesh's
    root in the tree that mesh_arrays gives (the layout names the binary table's)."""
    table = flat.table(kind)
    if "instanced_mesh" not in flat.features or not WIDE:
        return table
    mesh = flat.mesh
    wide_roots = dict(zip(mesh.tree_roots, numba_tree(mesh).roots))
    column, kind_column = offset("Instance", "object_row"), offset("Instance", "object_kind")
    table = table.copy()
    of_mesh = table[:, kind_column] == SHAPE_IDS[MESH_KIND.name]
    table[of_mesh, column] = [wide_roots[int(r)] for r in table[of_mesh, column]]
    return table


def scene_tuple(flat, empty: bool = False) -> tuple:
    """The kernels' ``scene``: materials, shaders, background, then the texels and a table
    per texture kind (rtfgu.registry.TEXTURES), all None when the scene has no texture, the
    environment's image (ENVIRONMENT) or None, and each shape's material row (MATERIAL_OF).
    With ``empty`` (the pixel debugger's, as shape_arrays), no None: a texture kind the scene
    lacks is its empty table (no material names it), no environment an empty image (the
    background, rtfgu.kernels.environment.background_radiance)."""
    if "textures" not in flat.features and not empty:
        textures = (None,) * (1 + len(TEXTURES))
    else:
        textures = (flat.texels,) + tuple(flat.textures[k.name] if len(flat.textures[k.name]) or empty else None
                                          for k in TEXTURES)
    environment = flat.environment
    if environment is None and empty:
        environment = np.zeros((0, 0, 3), dtype=flat.dtype)
    return (flat.materials, flat.shaders, flat.background) + textures + (environment, flat.material_of)


@njit(cache=True, error_model="numpy")
def eye_candidates(eye, camera, tile_box, size, candidates):
    """The rows of the from-eye kind that the tile's primary rays can hit (culling), and
    their number; -1 without a pinhole eye or such a kind."""
    if eye is None:
        return -1
    x0, x1, y0, y1 = tile_box
    return tile_candidates(camera[2], eye[1], x0, x1, y0, y1, size[0], size[1], candidates)


@njit(cache=True, error_model="numpy")
def from_eye_rows(eye):
    return 0 if eye is None else eye[0].shape[0]


def eye_terms(eye):
    """The per-frame terms of the from-eye kind, or None (typed by the overload below)."""
    return as_python(_typed_eye_terms, eye)


@overload(eye_terms, inline="always")
def _typed_eye_terms(eye):
    if isinstance(eye, types.NoneType):
        return lambda eye: None
    return lambda eye: eye[0]


def record_bounce(record, i, ray, hit, shader, normal, color):
    """Bounce ``i`` of a path into ``record`` for the pixel debugger (rtfgu.kernels.debug
    reads it); nothing at all when ``record`` is None, as in a render (typed by the
    overload below)."""
    return as_python(_typed_record_bounce, record, i, ray, hit, shader, normal, color)


@overload(record_bounce, inline="always")
def _typed_record_bounce(record, i, ray, hit, shader, normal, color):
    if isinstance(record, types.NoneType):
        return lambda record, i, ray, hit, shader, normal, color: None

    def write(record, i, ray, hit, shader, normal, color):
        row = record[i]
        row[0], row[1], row[2] = ray[0]
        row[3], row[4], row[5] = ray[1]
        row[6], row[7], row[8], row[9] = hit[0], hit[1], hit[2], shader
        row[10], row[11], row[12] = normal
        row[13], row[14], row[15] = color
    return write


# How ``trace`` finds the hit of its ray at depth i: one of these three, handed to it by its
# caller as ``hit_of``. numba inlines a function handed to an inlined function as it inlines
# one called by name, before it types the kernel, so the kernel holds the intersection only
# where the function chosen has it (an overload choosing among them by type would have
# numba type intersect_scene once more on its own: 15 % of a kernel's compile, measured).
@njit(cache=True, error_model="numpy", inline="always")
def search_hit(primary, i, shapes, eye_rows, origin, direction, tmin, tmax, formula):
    """The nearest hit (t, scene index, kind, row) of the scene's intersect_scene (a primary
    ray, i = 0, tests the from-eye kind's culled candidates); ``primary`` is not read."""
    return intersect_scene(shapes, eye_rows[0], eye_rows[1], eye_rows[2] if i == 0 else -1,
                           origin, direction, tmin, tmax, formula)


@njit(cache=True, error_model="numpy", inline="always")
def given_hit(primary, i, shapes, eye_rows, origin, direction, tmin, tmax, formula):
    """``primary``, the primary ray's hit found before (render_tile's second phase), where no
    shader continues a path: no intersection code is compiled in trace at all."""
    return primary


@njit(cache=True, error_model="numpy", inline="always")
def given_first_hit(primary, i, shapes, eye_rows, origin, direction, tmin, tmax, formula):
    """``primary`` at depth 0 (found before, in packets), search_hit's at every other depth."""
    if i == 0:
        return primary
    return intersect_scene(shapes, eye_rows[0], eye_rows[1], -1, origin, direction, tmin, tmax, formula)


# A row of a tile's stack of rays (push_ray): origin (3), direction (3), weight (3), depth.
STACK_FIELDS = 10


def push_ray(stack, pending, origin, direction, weight, depth):
    """Put a second ray (a Transparent's reflection) on ``stack`` above its ``pending`` rows
    and return their new number; nothing where its weight is 0, and nothing at all without a
    stack, in a scene no material of which sends two rays (typed by the overload below)."""
    return as_python(_typed_push_ray, stack, pending, origin, direction, weight, depth)


@overload(push_ray, inline="always")
def _typed_push_ray(stack, pending, origin, direction, weight, depth):
    if isinstance(stack, types.NoneType):
        return lambda stack, pending, origin, direction, weight, depth: pending

    def push(stack, pending, origin, direction, weight, depth):
        zero = lit(0, weight[0])
        if (weight[0] == zero and weight[1] == zero and weight[2] == zero) or pending >= stack.shape[0]:
            return pending
        row = stack[pending]
        row[0], row[1], row[2] = origin
        row[3], row[4], row[5] = direction
        row[6], row[7], row[8] = weight
        row[9] = depth
        return pending + 1
    return push


def pop_ray(stack, pending, weight):
    """The ray on top of ``stack``: (origin, direction, weight, depth); ``weight`` only gives
    the type of a stack that is None, which is never popped (typed by the overload below)."""
    return as_python(_typed_pop_ray, stack, pending, weight)


@overload(pop_ray, inline="always")
def _typed_pop_ray(stack, pending, weight):
    if isinstance(stack, types.NoneType):
        return lambda stack, pending, weight: (weight, weight, weight, 0)

    def pop(stack, pending, weight):
        row = stack[pending - 1]
        return (row[0], row[1], row[2]), (row[3], row[4], row[5]), (row[6], row[7], row[8]), int(row[9])
    return pop


def tile_stack(cast, k):
    """Tile ``k``'s stack of rays from the ray-cast tracer's ``cast`` (bounces, sampled,
    stacks), or None where there are none (typed by the overload below)."""
    return as_python(_typed_tile_stack, cast, k)


@overload(tile_stack, inline="always")
def _typed_tile_stack(cast, k):
    if isinstance(cast, types.NoneType):
        return lambda cast, k: None
    return lambda cast, k: row_of(cast[2], k)


def row_of(stacks, k):
    """``stacks[k]``, or None where ``stacks`` is None (typed by the overload below)."""
    return as_python(_typed_row_of, stacks, k)


@overload(row_of, inline="always")
def _typed_row_of(stacks, k):
    if isinstance(stacks, types.NoneType):
        return lambda stacks, k: None
    return lambda stacks, k: stacks[k]


@njit(cache=True, error_model="numpy", inline="always")
def trace(ray, shapes, lights, scene, eye_rows, settings, bounces, stream, hit_of, stack=None, record=None,
          primary=None):
    """The 02562 path loop (rtfgu.renderer.trace) as Whitted's tracer (Suffern ch. 24):
    shade each hit until a shader ends the path or the ray leaves the scene (background), at
    most ``bounces`` (MAX_DEPTH) rays deep, each hit's radiance weighted by the product of
    the factors of the rays that led to it (kr cr of a mirror, kt of a refraction: 1 in the
    02562 shaders, so their sums are what they were bit for bit). A second ray (a
    Transparent's reflection) waits on ``stack`` (its rows, STACK_FIELDS each; None in a
    scene without one) and is followed when the first path ends: the lecture layer's
    recursion in another order, so a scene with weights other than 1 equals it to rounding.
    Primary rays from a pinhole eye test the from-eye kind's ``candidates[:n_candidates]``
    with its per-frame ``terms``, ``eye_rows`` = (terms, candidates, n_candidates)
    (n_candidates -1: no such eye). ``record``: None, or an
    array that receives every bounce of the first path (record_bounce). ``stream``: (pixel,
    sample, seed, whether area lights are sampled: AreaLighting), the numbers a ray at depth
    i draws being the stream's path_dimension(i, k). ``hit_of``: search_hit, given_hit or
    given_first_hit, how the hit at each depth is found; ``primary``: None, or the primary
    ray's nearest hit, found before (render_tile's second phase), for given_hit and
    given_first_hit. Returns (radiance, shadow rays, secondary rays)."""
    origin, direction, tmin, tmax = ray
    materials, shaders, background = scene[0], scene[1], scene[2]
    shadows, formula = settings[0], settings[2]
    zero = lit(0, tmin)
    one = lit(1, zero)
    result = (zero, zero, zero)
    weight = (one, one, one)
    n_shadow = 0
    n_secondary = 0
    depth = 1 if bounces is None else bounces
    first = 0
    pending = 0
    while True:
        for i in range(first, depth):
            if i > 0:
                n_secondary += 1
            t, idx, kind, row = hit_of(primary, i, shapes, eye_rows, origin, direction, tmin, tmax, formula)
            if idx < 0:
                seen = background_radiance(scene[ENVIRONMENT], background, direction)
                result = add(result, mul(weight, seen))
                record_bounce(record, i, (origin, direction), (t, idx, kind), -1, direction, seen)
                break
            # HitInfo: position = ray(t) = o + d t, the normal of the shape hit, its material.
            position = add(origin, scale(direction, t))
            m = scene[MATERIAL_OF][idx]
            shader = shaders[m]
            if shader == BASE_COLOR:
                normal = position  # base_color reads no normal: a flat-colour scene skips normal_at
            else:
                normal = shape_normal(shapes, kind, row, position, direction)
            mat = materials[m]
            surface = surface_color(scene, shapes, mat, kind, row, position)
            color, has_hit, further, shadow_rays = shade(
                shader, mat, surface, direction, (position, normal), lights, shapes, shadows,
                bounces, formula, (2 + i * VERTEX_DIMENSIONS, stream[0], stream[1], stream[2], stream[3]))
            result = add(result, mul(weight, color))
            record_bounce(record, i, (origin, direction), (t, idx, kind), shader, normal, color)
            n_shadow += shadow_rays
            if has_hit:
                break
            # The lecture's _continue_path: a new ray with a fresh tmax; a second ray waits.
            new_direction, factor, second, second_factor = further
            if i + 1 < depth:
                pending = push_ray(stack, pending, position, second, mul(weight, second_factor), i + 1)
            weight = mul(weight, factor)
            origin = position
            direction = new_direction
            tmin = lit(SPAWN_EPSILON, zero)
            tmax = lit(math.inf, zero)
        if pending == 0:
            break
        origin, direction, weight, first = pop_ray(stack, pending, weight)
        pending -= 1
        tmin = lit(SPAWN_EPSILON, zero)
        tmax = lit(math.inf, zero)
    return result, n_shadow, n_secondary


@njit(cache=True, error_model="numpy", inline="always")
def screen_point(sampler, pixel, s, seed, ix, iy, width, height, one):
    """Sample ``s`` of pixel (ix, iy) (``pixel`` its index, row 0 at the top) on the view
    plane: (sx, sy) in [-1, 1]^2, the sampler's point in the pixel (the centre without one)."""
    spx, spy = pixel_sample(sampler, pixel, s, PIXEL_SET, seed, one)
    return (lit(2, one) * (lit(ix, one) + spx) / lit(width, one) - one,
            lit(2, one) * (lit(iy, one) + spy) / lit(height, one) - one)


# A packet: the PACKET_SIDE x PACKET_SIDE pixels of a block of a tile (rtfgu.kernels.packet).
PACKET_SIDE = 4
assert PACKET_SIDE * PACKET_SIDE == PACKET and TILE % PACKET_SIDE == 0


# A tile's primary rays (render_tile's first phase): origin (3), direction (3), tmin, tmax,
# stored a field at a time (field f of ray c at f * TILE_RAYS + c), so that a loop over the
# rays reads each field with unit stride (dispatch's eye_scan, vectorised by LLVM).
RAY_FIELDS = 8
TILE_RAYS = TILE * TILE
tile_rays = on_the_stack(RAY_FIELDS * TILE_RAYS, "A tile's primary rays, field after field.")
tile_values = on_the_stack(TILE_RAYS, "A value per pixel of a tile.")
tile_hits = on_the_stack(3 * TILE_RAYS, "The scene indices, then kinds of a tile's primary hits, then room for "
                         "eye_scan (int32: eight to a vector there).")
tile_rows = on_the_stack(TILE_RAYS, "The rows of a tile's primary hits.")


@njit(cache=True, error_model="numpy", inline="always")
def fill_rays(tile, camera_kind, camera_row, sampler, s, seed, rays):
    """Sample ``s``'s primary ray of every pixel of ``tile`` into ``rays``, row after row from
    (x0, y0), field after field (RAY_FIELDS; ThinLens.gen_ray with the lens's sample, else the
    camera's gen_ray)."""
    x0, x1, y0, y1, width, height = tile
    one = lit(1, camera_row[0])
    c = 0
    for iy in range(y0, y1):
        for ix in range(x0, x1):
            pixel = (height - 1 - iy) * width + ix
            sx, sy = screen_point(sampler, pixel, s, seed, ix, iy, width, height, one)
            if camera_kind == THIN_LENS:
                lens = concentric_map(*pixel_sample(sampler, pixel, s, LENS_SET, seed, one))
                origin, direction, tmin, tmax = thin_lens_ray(camera_row, sx, sy, lens)
            else:
                origin, direction, tmin, tmax = gen_ray(camera_kind, camera_row, sx, sy)
            rays[c], rays[TILE_RAYS + c], rays[2 * TILE_RAYS + c] = origin
            rays[3 * TILE_RAYS + c], rays[4 * TILE_RAYS + c], rays[5 * TILE_RAYS + c] = direction
            rays[6 * TILE_RAYS + c] = tmin
            rays[7 * TILE_RAYS + c] = tmax
            c += 1


@njit(cache=True, error_model="numpy", inline="always")
def camera_rays(tile, camera_kind, camera_row, sampler, s, seed, rays):
    """render_tile's first phase: fill_rays with the camera's kind chosen once per tile, a
    pinhole's loop compiled with its kind known (a literal), so that gen_ray's choice of kind
    leaves the loop (a choice per pixel cost a flat-colour render of the 64 spheres a fifth
    to a quarter of its time)."""
    if camera_kind == PINHOLE:
        fill_rays(tile, PINHOLE, camera_row, sampler, s, seed, rays)
    else:
        fill_rays(tile, camera_kind, camera_row, sampler, s, seed, rays)


@njit(cache=True, error_model="numpy", inline="always")
def ray_at(rays, c):
    """Ray ``c`` of a tile's ``rays``: (origin, direction, tmin, tmax)."""
    n = TILE_RAYS
    return ((rays[c], rays[n + c], rays[2 * n + c]), (rays[3 * n + c], rays[4 * n + c], rays[5 * n + c]),
            rays[6 * n + c], rays[7 * n + c])


@njit(cache=True, error_model="numpy", inline="always")
def keep_hit(ts, hits, c, hit):
    """Store ``hit`` (t, scene index, kind, row) as pixel ``c``'s primary hit (``hits``: the
    tile's (tile_hits, tile_rows))."""
    ts[c] = hit[0]
    hits[0][c] = np.int32(hit[1])
    hits[0][TILE_RAYS + c] = np.int32(hit[2])
    hits[1][c] = hit[3]


@njit(cache=True, error_model="numpy", inline="always")
def hits_one_by_one(tile, shapes, eye_rows, rays, ts, hits, formula):
    """render_tile's second phase where no shader continues a path: the nearest hit of each
    of the tile's primary ``rays`` into ``ts`` and ``hits`` (keep_hit), so that trace, given
    it (given_hit), compiles no intersection of its own. Each ray meets the shapes in
    intersect_scene's order and gets its hit bit for bit, in three loops: the kinds before the
    from-eye kind ray by ray, the from-eye kind's candidates for all the rays at once
    (eye_scan: 8 rays an instruction), the rest ray by ray."""
    x0, x1, y0, y1 = tile[0], tile[1], tile[2], tile[3]
    terms, candidates, n_candidates = eye_rows
    count = (x1 - x0) * (y1 - y0)
    for c in range(count):
        origin, direction, tmin, tmax = ray_at(rays, c)
        keep_hit(ts, hits, c, intersect_scene_before_eye(shapes, origin, direction, tmin, (tmax, -1, -1, -1),
                                                         formula))
    eye_scan(shapes, terms, candidates, n_candidates, rays, count, TILE_RAYS, ts, hits[0], hits[1], formula)
    for c in range(count):
        origin, direction, tmin, tmax = ray_at(rays, c)
        keep_hit(ts, hits, c, intersect_scene_after_eye(shapes, terms, candidates, n_candidates, origin, direction,
                                                        tmin, hit_at(ts, hits, c), formula))


@njit(cache=True, error_model="numpy", inline="always")
def hits_in_packets(tile, shapes, eye_rows, rays, ts, hits, formula):
    """render_tile's second phase where the rays go in packets: the rays of each PACKET_SIDE
    x PACKET_SIDE block of the tile through the scene's wide BVH as one packet
    (trace_packet), then each ray's hit completed with the shapes outside the BVH
    (intersect_scene given the BVH's hit), into ``ts`` and ``hits`` (keep_hit). Every ray
    gets the hit its own intersect_scene gives (rtfgu.kernels.packet), so the image is the
    same bit for bit."""
    x0, x1, y0, y1 = tile[0], tile[1], tile[2], tile[3]
    one = lit(1, rays[0])
    zero = lit(0, one)
    inf = lit(math.inf, one)
    origins = packet_rays(one)
    directions = packet_rays(one)
    t = packet_lanes(one)
    best = packet_lanes(np.int64)
    kind = packet_lanes(np.int64)
    row = packet_lanes(np.int64)
    for by in range(y0, y1, PACKET_SIDE):
        for bx in range(x0, x1, PACKET_SIDE):
            # An int64 from the start: a literal 0 would have numba compile the packet's
            # traversal once more, for a count of Literal[int](0) that no call passes.
            count = np.int64(0)
            for iy in range(by, min(by + PACKET_SIDE, y1)):
                for ix in range(bx, min(bx + PACKET_SIDE, x1)):
                    k = (iy - y0) * (x1 - x0) + ix - x0
                    for a in range(3):
                        origins[3 * count + a] = rays[a * TILE_RAYS + k]
                        directions[3 * count + a] = rays[(3 + a) * TILE_RAYS + k]
                    t[count] = inf
                    best[count] = -1
                    kind[count] = -1
                    row[count] = -1
                    count += 1
            trace_packet(shapes, origins, directions, count, zero, t, best, kind, row, formula)
            count = 0
            for iy in range(by, min(by + PACKET_SIDE, y1)):
                for ix in range(bx, min(bx + PACKET_SIDE, x1)):
                    c = (iy - y0) * (x1 - x0) + ix - x0
                    origin, direction, tmin, tmax = ray_at(rays, c)
                    keep_hit(ts, hits, c, intersect_scene(shapes, eye_rows[0], eye_rows[1], eye_rows[2], origin,
                                                          direction, tmin, tmax, formula,
                                                          (t[count], best[count], kind[count], row[count])))
                    count += 1


@njit(cache=True, error_model="numpy", inline="always")
def hit_at(ts, hits, c):
    """Pixel ``c``'s primary hit (t, scene index, kind, row), as keep_hit stored it."""
    return ts[c], np.int64(hits[0][c]), np.int64(hits[0][TILE_RAYS + c]), hits[1][c]


@njit(cache=True, error_model="numpy", _nrt=False)
def render_tile(view, world, eye_rows, settings, cast, path, packets, buffers, one_by_one, given, given_first,
                search):
    """Add the samples of the pixels x0 <= ix < x1, y0 <= iy < y1 (``view`` = (tile,
    camera, sampler), ``tile`` = (x0, x1, y0, y1, width, height)) of the scene ``world`` =
    (shapes, lights, scene) to the image (the lecture's render loop,
    rtfgu.renderer.render_reference), each traced by the ray-cast ``trace`` (``cast``) or
    by PathTrace (``path``): (primary, shadow, secondary) rays cast, and 1 where a value of
    the tile's sums is not finite after sample end - 1, else 0. ``eye_rows`` is (terms,
    candidates, n_candidates): ``candidates[:n_candidates]`` are the from-eye kind's rows
    the tile's primary rays can hit, with their per-frame ``terms`` (None and -1 without a
    pinhole eye). ``buffers`` = (stack, image): the tile's rays waiting (trace), None where
    none can, and the image.
    ``packets``: None, or 1 where a pinhole's primary rays go through the scene's wide BVH in
    packets (hits_in_packets; rtfgu.kernels.kernel_arguments decides). ``one_by_one``,
    ``given``, ``given_first``, ``search``: 1 or None, how the ray-cast tracer finds its hits
    (kernel_arguments' ``hit_phases``); numba removes a branch on ``argument is not None``
    where the argument is None, so a kernel holds only the code its phases use.

    A sample of the tile is made in three phases, each a loop of its own over the tile's
    pixels: their primary rays (camera_rays); the rays' nearest hits, for the ray-cast
    tracer where the rays go in packets (hits_in_packets) or no shader continues a path
    (hits_one_by_one); then each pixel's colour (trace, given the hit where it was found
    before: given_hit, given_first_hit; else search_hit; trace_path). Where a shader
    continues the path without packets, trace finds every hit itself, so intersect_scene,
    the largest part of a kernel, is compiled once, not twice.
    A loop that only intersects keeps the shaders' code, chosen per pixel, out of the
    intersection's loop (a loop with both measured 1.15x slower on the 64 spheres). Every
    pixel adds its samples in the same order, and every ray is computed by the same
    functions from the same numbers, so the image is the same bit for bit as a loop that
    does it all pixel by pixel.

    Compiled without numba's reference counting (``_nrt=False``): it allocates nothing, and
    the scene arrays it reads, unpacked from their tuples for every pixel, would otherwise
    cost an atomic increment and decrement each per pixel, twice the time of the pixel."""
    tile, camera, sampler = view
    shapes, lights, scene = world
    x0, x1, y0, y1, width, height = tile
    stack, image = buffers
    camera_kind, camera_row = camera[0], camera[1]
    show_ray_direction, seed, first, end, formula = settings[1], settings[3], settings[4], settings[5], settings[2]
    n_shadow = 0
    n_secondary = 0
    # v - v is +0 for a finite v and NaN for an infinite or NaN one, and NaN stays NaN in a
    # sum: one NaN test a tile, where a test a value cost 5-10 % of a frame of flat colours.
    poison = lit(0, image[0, 0, 0])
    one = lit(1, camera_row[0])
    rays = tile_rays(one)
    ts = tile_values(one)
    hits = (tile_hits(np.int32), tile_rows(np.int64))
    zero = lit(0, one)
    for s in range(first, end):
        camera_rays(tile, camera_kind, camera_row, sampler, s, seed, rays)
        if not show_ray_direction:
            if packets is not None:
                hits_in_packets(tile, shapes, eye_rows, rays, ts, hits, formula)
            if one_by_one is not None:
                hits_one_by_one(tile, shapes, eye_rows, rays, ts, hits, formula)
        c = 0
        for iy in range(y0, y1):
            for ix in range(x0, x1):
                ray = ray_at(rays, c)
                if show_ray_direction:
                    half = lit(0.5, one)
                    color = add(scale(ray[1], half), (half, half, half))
                else:
                    pixel = (height - 1 - iy) * width + ix
                    # Exactly one of these stays in a compiled kernel (the module docstring).
                    if cast is not None:
                        stream = (pixel, s, seed, cast[1])
                    if given is not None:
                        color, shadow_rays, secondary_rays = trace(
                            ray, shapes, lights, scene, eye_rows, settings, cast[0], stream, given_hit, stack, None,
                            hit_at(ts, hits, c))
                    if given_first is not None:
                        color, shadow_rays, secondary_rays = trace(
                            ray, shapes, lights, scene, eye_rows, settings, cast[0], stream, given_first_hit, stack,
                            None, hit_at(ts, hits, c))
                    if search is not None:
                        color, shadow_rays, secondary_rays = trace(
                            ray, shapes, lights, scene, eye_rows, settings, cast[0], stream, search_hit, stack)
                    if path is not None:
                        color, shadow_rays, secondary_rays = trace_path(ray, shapes, lights, scene,
                                                                        eye_rows[0], eye_rows[1], eye_rows[2],
                                                                        settings, path, pixel, s)
                    n_shadow += shadow_rays
                    n_secondary += secondary_rays
                out = image[height - 1 - iy, ix]
                if s == 0:
                    # A render's first sample starts its sums, as 0 + v would (v + 0 is
                    # that, -0 made +0): the image need not be zeroed nor read before.
                    out[0] = color[0] + zero
                    out[1] = color[1] + zero
                    out[2] = color[2] + zero
                else:
                    out[0] += color[0]
                    out[1] += color[1]
                    out[2] += color[2]
                if s == end - 1:
                    poison += (out[0] - out[0]) + (out[1] - out[1]) + (out[2] - out[2])
                c += 1
    return (x1 - x0) * (y1 - y0) * (end - first), n_shadow, n_secondary, 0 if poison == poison else 1


@njit(cache=True, error_model="numpy", nogil=True)
def render_kernel(size, camera, shapes, lights, scene, eye, settings, tracer, sampler, share,
                  image, counts):
    """Add the samples settings[4] <= s < settings[5] of the tiles this thread claims to
    ``image`` (height, width, 3), row 0 at the top (samples from 0 are written over what it
    held), and fill their rows of ``counts`` (tiles, COUNTS); ``size`` is (width, height).
    ``share`` = (stride, counter, run): the thread claims the next ``run`` k from
    ``counter`` (threads.claim) until k reaches the number of tiles, the k-th tile being the
    image's tile k * stride mod n_tiles (the stride is coprime with n_tiles), and counts
    each run done once its pixels are written (threads.finish). The threads
    that run this at once (rtfgu.kernels.threads, compiled with ``nogil`` for them) render
    every tile once between them. For a pinhole camera with a from-eye shape kind, ``eye``
    holds its per-frame terms and culling cones, so each tile tests only the rows its
    primary rays can hit; otherwise it is None."""
    width, height = size
    tile_stride, counter, run = share
    tiles_x = (width + TILE - 1) // TILE
    tiles_y = (height + TILE - 1) // TILE
    n_tiles = tiles_x * tiles_y
    candidates = np.empty(from_eye_rows(eye), dtype=np.int64)
    terms = eye_terms(eye)
    cast, path, packets, phases = tracer
    first = claim(counter, run)
    while first < n_tiles:
        for k in range(first, min(first + run, n_tiles)):
            tile = (k * tile_stride) % n_tiles
            x0 = (tile % tiles_x) * TILE
            y0 = (tile // tiles_x) * TILE
            box = (x0, min(x0 + TILE, width), y0, min(y0 + TILE, height))
            n_candidates = eye_candidates(eye, camera, box, size, candidates)
            n_primary, n_shadow, n_secondary, n_not_finite = render_tile(
                (box + size, camera, sampler), (shapes, lights, scene), (terms, candidates, n_candidates),
                settings, cast, path, packets, (tile_stack(cast, tile), image), phases[0], phases[1], phases[2],
                phases[3])
            counts[tile, PRIMARY] = n_primary
            counts[tile, SHADOW] = n_shadow
            counts[tile, SECONDARY] = n_secondary
            counts[tile, NOT_FINITE] = n_not_finite
        finish(counter, min(first + run, n_tiles) - first)
        first = claim(counter, run)


# mean_image: an image of fewer values is made by the calling thread alone (a 73 x 73 image has
# 15987).
MEAN_ALONE = 1 << 14


@njit(cache=True, nogil=True)
def mean_rows(sums, n, share, out, bad):
    """mean_image's rows this thread claims: ``share`` = (1, counter, run), each claim the next
    ``run`` rows (rtfgu.kernels.threads), ``out`` = ``sums`` / ``n`` there, the division in the
    sums' own precision; the count of its values that are not finite added to bad[0] before
    the rows are counted done."""
    _, counter, run = share
    rows = sums.shape[0]
    first = claim(counter, run)
    while first < rows:
        last = min(first + run, rows)
        count = 0
        for y in range(first, last):
            for x in range(sums.shape[1]):
                for c in range(sums.shape[2]):
                    value = sums[y, x, c] / n
                    out[y, x, c] = value
                    if not math.isfinite(value):
                        count += 1
        if count:
            fetch_add(bad, 0, count)
        finish(counter, last - first)
        first = claim(counter, run)


def mean_image(sums, n, out) -> int:
    """Write the image of the samples so far, ``out`` (float64) = ``sums`` / ``n``, the
    division in the sums' own precision (``n`` of their type); returns how many of its values
    are not finite (rtfgu.renderer refuses them). Its rows are shared by the render's threads
    as the tiles are (run_in_threads): a thread that starts late finds them done, where a
    parallel loop would wait for it, milliseconds on a busy machine (docs/bvh.md, "A small
    mesh's build on a busy machine"). An image of fewer than MEAN_ALONE values is made by the
    calling thread alone: handing rows to another thread costs more than they do."""
    bad = np.zeros(1, dtype=np.int64)
    run_in_threads(mean_rows, (sums, n), (out, bad), sums.shape[0], 1, 1 if sums.size < MEAN_ALONE else None)
    return int(bad[0])
