# release: solves a01 a02 a03 a04 a05 a07 a08 a09 a10 a11 a12 a13
"""The numba path: the lecture layer's renderer as jitted kernels over the flat layout.

``render_numba(scene, width, height, precision)`` compiles the scene (rtfgu.layout, which
validates it), groups its arrays per kind (``kernel_arguments``) and runs the kernel on all
cores; numba compiles one kernel per combination of kinds present. The kernel modules
follow the slides: camera.gen_ray, intersect.intersect_<kind>, lights.sample_point_light,
shaders (the BRDF terms and continuations), dispatch (intersect_scene, in_shadow, the light
loop and shade, generated from rtfgu.registry), render.trace / render_kernel.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import dispatch  # noqa: F401  (first: it points numba's cache at this kernel version)
from ..layout import CAMERA_WIDTH, PINHOLE, PINHOLE_EYE, compile_sampler
from ..layout_cache import kept_layout
from ..registry import LIGHTS, SHADER_BY_ID, SHAPES
from ..options import DEFAULT_FORMULAS, check_finite_image, pixel_sampler
from ..tracers.whitted import MAX_DEPTH
from .culling import cone_table
from .dispatch import FORMULAS
from .intersect import sphere_eye_terms
from .render import (COUNTS, NOT_FINITE, PRIMARY, SECONDARY, SHADOW, STACK_FIELDS, TILE, mean_image, mesh_arrays,
                     render_kernel, scene_tuple, shape_arrays)
from .threads import run_in_threads

__all__ = ["render_numba", "NumbaAccumulator", "RayCounts", "DEFAULT_SPHERE_FORMULA"]

# The formula of a numba render unless one is asked for (decided in rtfgu.renderer).
DEFAULT_SPHERE_FORMULA = DEFAULT_FORMULAS["numba"]


def sphere_formula_id(formula) -> int:
    """The formula id (rtfgu.kernels.dispatch.FORMULAS) of "slide" / "robust" (None: the
    default)."""
    if formula is None:
        formula = DEFAULT_SPHERE_FORMULA
    if formula not in FORMULAS:
        raise ValueError("formula must be one of %s, got %r" % (", ".join(FORMULAS), formula))
    return FORMULAS.index(formula)


@dataclass
class RayCounts:
    primary: int
    shadow: int
    secondary: int

    @property
    def total(self) -> int:
        return self.primary + self.shadow + self.secondary


def _coprime_stride(n: int) -> int:
    """A stride near n / golden ratio with gcd(stride, n) = 1, so k -> k * stride mod n
    visits every tile once and neighbouring k land far apart."""
    stride = max(1, int(n * 0.6180339887))
    while math.gcd(stride, n) != 1:
        stride += 1
    return stride


def own_sets(flat, sampler=None):
    """The last three entries of the kernels' ``lights``: the sets of the samplers lights and
    BRDFs have of their own, samples and orders, both None where none has one, and 1 where
    the render's FlatSampler ``sampler`` is a Sobol, else None (the 2D draws' choice,
    rtfgu.kernels.sampling.sampler_sets)."""
    sobol = 1 if sampler is not None and sampler.kind == "sobol" else None
    return flat.own_samples, flat.own_shuffled, sobol


def hit_phases(cast, packets) -> tuple:
    """How the ray-cast tracer (``cast``; None: none) finds its hits, four flags each 1 or
    None (render.render_tile): (one_by_one: the primary hits found ray by ray before the
    pixels' colours, where no shader continues a path and there are no packets; given: the
    primary hits given to trace, which then compiles no intersection, where no shader
    continues a path; given_first: the packets' hits given at depth 0 and every deeper hit
    searched; search: every hit searched by trace, where a shader continues a path without
    packets)."""
    if cast is None:
        return None, None, None, None
    ends = cast[0] is None
    flag = lambda condition: 1 if condition else None
    return (flag(ends and packets is None), flag(ends), flag(not ends and packets is not None),
            flag(not ends and packets is None))


def kernel_arguments(flat, width: int, height: int, formula=None, sampler=None, seed: int = 0,
                     samples=(0, 1)):
    """The render_kernel arguments for a FlatScene (rtfgu.kernels.render says how they are
    grouped), with None for every kind the scene lacks, up to ``sampler``, then the stride
    of the tiles' order (the first of render_kernel's ``share``; render_tiles); and the
    number of tiles.
    ``sampler``: a FlatSampler (rtfgu.layout.compile_sampler) or None; ``samples``: the
    range of sample indices to add."""
    formula_id = sphere_formula_id(formula)
    shapes = shape_arrays(flat)
    lights = tuple(flat.lights[k.name] if len(flat.lights[k.name]) else None for k in LIGHTS) + own_sets(flat, sampler)
    camera = np.ascontiguousarray(flat.camera.reshape(CAMERA_WIDTH))
    camera64 = camera.astype(np.float64)
    eye = None
    for kind in SHAPES:
        table = flat.table(kind.name)
        in_bvh = flat.mesh is not None and flat.mesh.spheres
        if kind.from_eye and len(table) and flat.camera_kind == PINHOLE and not in_bvh:
            # Every primary ray starts at the eye: o - center and c per row once per frame,
            # and a cone per row for the per-tile culling.
            terms = np.zeros((len(table), 4), dtype=flat.dtype)
            sphere_eye_terms(camera[PINHOLE_EYE:PINHOLE_EYE + 3].copy(), table, terms)
            eye = (terms, cone_table(camera64, table))
    continues = any(SHADER_BY_ID[s].continues for s in flat.shaders.tolist())
    tiles = ((width + TILE - 1) // TILE) * ((height + TILE - 1) // TILE)
    stacks = np.empty((tiles, MAX_DEPTH, STACK_FIELDS), dtype=flat.dtype) if "two_rays" in flat.features else None
    cast, path = (MAX_DEPTH if continues else None, flat.area_lighting, stacks), None
    if flat.max_depth:
        cast, path = None, (flat.max_depth, flat.lights_at_every_vertex)
    # A pinhole's primary rays through the scene's wide BVH in packets (render.hits_in_packets),
    # for the ray-cast tracer, in both precisions (docs/bvh.md, "Packets").
    packets = 1 if (cast is not None and flat.camera_kind == PINHOLE and not flat.show_ray_direction
                    and flat.mesh is not None and flat.mesh.scene_tree
                    and mesh_arrays(flat)[3].ndim == 3) else None
    scene = scene_tuple(flat)
    phases = hit_phases(cast, packets)
    settings = (flat.shadows, flat.show_ray_direction, formula_id, int(seed), int(samples[0]),
                int(samples[1]))
    if sampler is not None and sampler.kind == "sobol":
        sampler = (sampler.num_samples,)
    elif sampler is not None:
        sampler = (sampler.samples, sampler.shuffled, sampler.num_samples, sampler.num_sets)
    return ((width, height), (flat.camera_kind, camera, camera64), shapes, lights, scene, eye,
            settings, (cast, path, packets, phases), sampler, _coprime_stride(tiles)), tiles


def render_tiles(args: tuple, tiles: int, sums: np.ndarray, counts: np.ndarray) -> None:
    """render_kernel over all ``tiles`` tiles of kernel_arguments' ``args``, adding to ``sums``
    and filling ``counts`` (tiles, COUNTS), on numba's thread count of threads
    (rtfgu.kernels.threads)."""
    run_in_threads(render_kernel, args[:-1], (sums, counts), tiles, args[-1])


def sums_dtype(flat, sampler) -> np.dtype:
    """The dtype of the sums a render of ``flat`` with ``sampler`` (None: one sample at each
    pixel's centre) adds its samples to: float64 for one sample, in either precision (the sum
    of one sample is the sample, and a float32 value is exactly a float64 one, so those sums
    are the image itself, with no second array), else the scene's own (the passes of a
    progressive render add in it)."""
    return np.dtype(np.float64) if sampler is None or sampler.num_samples == 1 else flat.dtype


class NumbaAccumulator:
    """A numba render in passes: each call adds a range of samples to every pixel's sum
    and returns the mean image so far (rtfgu.renderer.render_passes)."""

    def __init__(self, scene, width: int, height: int, precision: str = "float64",
                 formula: str | None = None, sampler=None, seed: int = 0):
        sphere_formula_id(formula)  # a bad formula is refused before the scene is compiled
        self.flat = kept_layout(scene, precision)   # compile_scene's, kept while the scene is unchanged
        self.sampler = compile_sampler(sampler, precision)
        self.size = (width, height)
        self.formula = formula
        self.seed = seed
        # Not zeroed: the kernel writes the sums of a range that starts at sample 0.
        self.sums = np.empty((height, width, 3), dtype=sums_dtype(self.flat, sampler))
        self.started = False
        self.counts = np.zeros(3, dtype=np.int64)

    def add(self, samples) -> np.ndarray:
        """The kernel alone: adds the samples samples[0] <= s < samples[1] of every pixel to
        the sums (written over from sample 0) and returns its counts (tiles, COUNTS)."""
        if self.sums is None:
            raise ValueError("NumbaAccumulator: its last pass has given its sums away as the image")
        if samples[0] > 0 and not self.started:
            self.sums[...] = 0
        self.started = True
        width, height = self.size
        args, tiles = kernel_arguments(self.flat, width, height, self.formula, self.sampler,
                                       self.seed, samples)
        counts = np.zeros((tiles, COUNTS), dtype=np.int64)
        render_tiles(args, tiles, self.sums, counts)
        self.counts += counts[:, :NOT_FINITE].sum(axis=0)
        return counts

    def __call__(self, samples, progress=None, last=False) -> np.ndarray:
        """The float64 image so far (``add``, then the mean), refused (check_finite_image)
        where not finite. With ``last`` (no pass follows), float64 sums become the image,
        divided in place (of one sample, only checked, by the kernel's count: v / 1 is v): a
        render then holds one image-sized array, not two, and the accumulator none (a call
        after it is refused)."""
        counts = self.add(samples)
        height = self.size[1]
        if progress is not None:
            progress(height, height)
        sums = self.sums
        if last and sums.dtype == np.float64:
            image, self.sums = sums, None
        else:
            image = np.empty(sums.shape)
        if image is sums and samples[1] == 1:
            bad = counts[:, NOT_FINITE].sum()   # the sum of one sample is its mean
        else:
            bad = mean_image(sums, sums.dtype.type(samples[1]), image)
        if bad:
            check_finite_image(image, "numba")
        return image

    @property
    def ray_counts(self) -> RayCounts:
        return RayCounts(int(self.counts[PRIMARY]), int(self.counts[SHADOW]), int(self.counts[SECONDARY]))


def render_numba(scene, width: int, height: int, precision: str = "float64",
                 with_counts: bool = False, formula: str | None = None, spp: int | None = None,
                 seed: int = 0):
    """Render on the numba path in one pass; a (height, width, 3) float64 array, row 0 at
    the top. With ``with_counts`` also the RayCounts of the render. ``formula``: the sphere
    test, "slide" (lecture 01) or "robust" (Ray Tracing Gems ch. 7); None is
    DEFAULT_SPHERE_FORMULA. ``spp``, ``seed``: as rtfgu.render."""
    sampler = pixel_sampler(scene, spp)
    accumulate = NumbaAccumulator(scene, width, height, precision, formula, sampler, seed)
    image = accumulate((0, 1 if sampler is None else sampler.num_samples), last=True)
    if with_counts:
        return image, accumulate.ray_counts
    return image
