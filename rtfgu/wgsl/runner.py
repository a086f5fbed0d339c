"""Run an assembled WGSL program as a compute shader through wgpu (wgpu-py).

The scene arrays of rtfgu.layout go into GPU buffers; the image comes back from a storage
buffer tile by tile, one dispatch (and one submit) per tile, so that no single dispatch runs
long enough to trip a driver's watchdog. Compiled pipelines are cached per process by
their WGSL text, so a moved camera or light only rewrites buffers ("pass data from CPU to
GPU to enable interaction", 02562 week 1).

The scene arrays go into uniform buffers unless ``scene_buffer="storage"``; an array too
large for a uniform binding (64 KiB) goes to storage either way. docs/wgsl_buffers.md has
the measurements behind that default. rtfgu/wgsl/harness.py runs other compute programs
(the hard cases, the grading checks) on the same device and cache.
"""
from __future__ import annotations

import re
import time

import numpy as np

from ..layout import compile_sampler, compile_scene
from ..options import check_finite_image, pixel_sampler
from . import structs
from .assemble import GENERATED, assemble, check_formula
from .device import get_device

DEFAULT_SCENE_BUFFER = "uniform"

# Pixels per tile side; 8x8 workgroups.
TILE = 128
WORKGROUP = 8
# A path-traced render adds its samples in dispatches of at most this many per pixel. On
# Mesa's llvmpipe, one dispatch that traced 48 or more paths per pixel of the Cornell box
# lost part of their light (the image 12 % darker at 64; every batch up to 32 matched the
# numba path to float32 rounding); batches of 8 keep well below that.
PATH_SAMPLES_PER_DISPATCH = 8


class WGSLCompileError(RuntimeError):
    """The WGSL did not compile; names the file, line and function it points at."""

    def __init__(self, message, file=None, line=None, column=None, function=None, text=None):
        super().__init__(message)
        self.file = file
        self.line = line
        self.column = column
        self.function = function
        self.text = text


def _compile_error(program, error, stage) -> WGSLCompileError:
    raw = str(error)
    m = re.search(r"wgsl:(\d+):(\d+)", raw)
    if not m:
        return WGSLCompileError("WGSL %s failed (no line reported):\n%s" % (stage, raw))
    line, column = int(m.group(1)), int(m.group(2))
    lines = program.source.splitlines()
    file, file_line, function = program.origin(line) if 0 < line <= len(lines) else (None, None, None)
    text = lines[line - 1] if 0 < line <= len(lines) else ""
    where = ("rtfgu/wgsl/%s" % file if file and file != GENERATED else (file or "?"))
    # naga's own sentence ("... parsing error: ...") rather than wgpu's "Validation Error".
    summary = next((s.strip() for s in raw.splitlines() if "error:" in s.lower()),
                   raw.strip().splitlines()[-1] if raw.strip() else "")
    message = "%s:%s:%d%s: %s\n    %s\n(line %d of the assembled program)\n%s" % (
        where, file_line, column, " in fn %s" % function if function else "", summary,
        text.strip(), line, raw)
    return WGSLCompileError(message, where, file_line, column, function, text)


# Process-wide cache: WGSL text -> CompiledProgram. COMPILES counts real compilations.
_PIPELINES = {}
COMPILES = 0


class CompiledProgram:
    """A compiled pipeline with its scene buffers and bind group."""

    def __init__(self, program):
        import wgpu

        global COMPILES
        self.program = program
        _, device = get_device()
        self.device = device
        start = time.perf_counter()
        try:
            module = device.create_shader_module(label="rtfgu", code=program.source)
        except Exception as error:
            raise _compile_error(program, error, "compilation") from None
        storage = wgpu.BufferBindingType.read_only_storage
        scene_entries = [{"binding": 0, "visibility": wgpu.ShaderStage.COMPUTE,
                          "buffer": {"type": wgpu.BufferBindingType.uniform}}]
        for b in program.bindings:
            kind = wgpu.BufferBindingType.uniform if b.kind == "uniform" else storage
            scene_entries.append({"binding": b.number, "visibility": wgpu.ShaderStage.COMPUTE,
                                  "buffer": {"type": kind}})
        self.scene_layout = device.create_bind_group_layout(entries=scene_entries)
        self.image_layout = device.create_bind_group_layout(entries=[
            {"binding": 0, "visibility": wgpu.ShaderStage.COMPUTE,
             "buffer": {"type": wgpu.BufferBindingType.storage}}])
        layout = device.create_pipeline_layout(bind_group_layouts=[self.scene_layout,
                                                                   self.image_layout])
        try:
            self.pipeline = device.create_compute_pipeline(
                layout=layout, compute={"module": module, "entry_point": "main"})
        except Exception as error:
            raise _compile_error(program, error, "pipeline creation") from None
        self.compile_seconds = time.perf_counter() - start
        COMPILES += 1

        self.uniforms = device.create_buffer(size=structs.UNIFORMS_SIZE,
                                             usage=wgpu.BufferUsage.UNIFORM | wgpu.BufferUsage.COPY_DST)
        self.buffers = {}
        entries = [{"binding": 0, "resource": {"buffer": self.uniforms}}]
        for b in program.bindings:
            usage = (wgpu.BufferUsage.UNIFORM if b.kind == "uniform" else wgpu.BufferUsage.STORAGE)
            buffer = device.create_buffer(size=b.size, usage=usage | wgpu.BufferUsage.COPY_DST)
            self.buffers[b.name] = buffer
            entries.append({"binding": b.number, "resource": {"buffer": buffer}})
        self.scene_group = device.create_bind_group(layout=self.scene_layout, entries=entries)
        self._image = None  # (pixels, buffer, bind group)
        self.background = np.zeros(3, dtype=np.float32)

    def upload(self, flat) -> None:
        """Write the scene's numbers (camera, shapes, materials, lights) to the buffers."""
        for b in self.program.bindings:
            data = b.pack(flat)
            if len(data) != b.size:
                raise ValueError("Scene: %s has %d bytes, the compiled program expects %d "
                                 "(the scene's shape or light counts changed: assemble again)"
                                 % (b.name, len(data), b.size))
            self.device.queue.write_buffer(self.buffers[b.name], 0, data)
        self.background = np.asarray(flat.background[:3], dtype=np.float32)

    def _image_buffer(self, pixels):
        import wgpu

        if self._image is None or self._image[0] < pixels:
            buffer = self.device.create_buffer(size=16 * pixels, usage=wgpu.BufferUsage.STORAGE
                                               | wgpu.BufferUsage.COPY_SRC | wgpu.BufferUsage.COPY_DST)
            group = self.device.create_bind_group(layout=self.image_layout, entries=[
                {"binding": 0, "resource": {"buffer": buffer}}])
            self._image = (pixels, buffer, group)
        return self._image

    def render(self, width: int, height: int, tile: int = TILE, progress=None, seed: int = 0,
               samples=(0, 1)) -> np.ndarray:
        """Add samples ``samples[0] <= s < samples[1]`` of every pixel to the sums on the
        device (zeroed when samples[0] is 0) and return the sums, (height, width, 3)
        float32, row 0 at the top; ``progress(rows_done, height)`` after each band of tiles."""
        tile = int(tile)
        if tile < 1:
            raise ValueError("tile must be >= 1, got %r" % (tile,))
        _, buffer, group = self._image_buffer(width * height)
        queue = self.device.queue
        if samples[0] == 0:
            queue.write_buffer(buffer, 0, bytes(16 * width * height))
        for origin, size in tiles(width, height, tile):
            for batch in sample_batches(self.program, samples):
                queue.write_buffer(self.uniforms, 0, structs.uniforms(
                    self.background, seed, width, height, origin, size, batch))
                encoder = self.device.create_command_encoder()
                compute = encoder.begin_compute_pass()
                compute.set_pipeline(self.pipeline)
                compute.set_bind_group(0, self.scene_group)
                compute.set_bind_group(1, group)
                compute.dispatch_workgroups(*workgroups(size), 1)
                compute.end()
                queue.submit([encoder.finish()])
            if progress is not None and origin[0] + size[0] == width:
                progress(origin[1] + size[1], height)
        data = np.frombuffer(queue.read_buffer(buffer, 0, 16 * width * height), dtype=np.float32)
        return data.reshape(height, width, 4)[:, :, :3].copy()


def tiles(width: int, height: int, tile: int = TILE) -> list:
    """((column, row) of the top-left pixel, (width, height)) of every tile of the image,
    row by row from the top: one dispatch (per batch of samples) each."""
    return [((col0, row0), (min(tile, width - col0), min(tile, height - row0)))
            for row0 in range(0, height, tile) for col0 in range(0, width, tile)]


def sample_batches(program, samples) -> list:
    """The ranges (first, end) of samples that one dispatch adds, in order: all of
    ``samples`` at once, or PATH_SAMPLES_PER_DISPATCH at a time for a path tracer."""
    first, end = samples
    batch = PATH_SAMPLES_PER_DISPATCH if "path_trace" in program.features else end - first
    return [(s, min(s + batch, end)) for s in range(first, end, max(batch, 1))]


def workgroups(size) -> tuple:
    """The workgroups (x, y) that cover a tile of ``size`` pixels."""
    return -(-size[0] // WORKGROUP), -(-size[1] // WORKGROUP)


def compile_program(program) -> CompiledProgram:
    """The compiled pipeline for ``program``, from the process cache when the WGSL text is
    one already compiled."""
    compiled = _PIPELINES.get(program.source)
    if compiled is None:
        compiled = CompiledProgram(program)
        _PIPELINES[program.source] = compiled
    return compiled


def prepare(scene, scene_buffer: str = DEFAULT_SCENE_BUFFER, overrides=None,
            formula: str | None = None, sampler=None) -> CompiledProgram:
    """Lay out ``scene`` in float32, assemble and compile (or reuse) its program, upload it.
    ``formula``: the sphere test, "slide" or "robust" (None: the assembler's default);
    ``sampler``: the render's Sampler, or None for one sample at each pixel's centre."""
    flat, program = assemble_scene(scene, scene_buffer, overrides, formula, sampler)
    compiled = compile_program(program)
    compiled.upload(flat)
    return compiled


def assemble_scene(scene, scene_buffer: str = DEFAULT_SCENE_BUFFER, overrides=None,
                   formula: str | None = None, sampler=None) -> tuple:
    """(FlatScene in float32 with its sampler, the Program assembled for it): what
    ``prepare`` compiles and rtfgu.browser puts in a web page."""
    check_formula(formula)  # a bad formula is refused before the scene is compiled
    flat = compile_scene(scene, "float32")
    flat.sampler = compile_sampler(sampler, "float32")
    return flat, assemble(flat, scene_buffer, overrides, formula)


class WGPUAccumulator:
    """A WGSL render in passes: each call adds a range of samples to every pixel's sum on
    the device and returns the mean image so far (rtfgu.renderer.render_passes)."""

    def __init__(self, scene, width: int, height: int, formula: str | None = None, sampler=None,
                 seed: int = 0, scene_buffer: str = DEFAULT_SCENE_BUFFER, tile: int = TILE):
        self.compiled = prepare(scene, scene_buffer, formula=formula, sampler=sampler)
        self.size = (width, height)
        self.seed = seed
        self.tile = tile

    def __call__(self, samples, progress=None, last=False) -> np.ndarray:
        """The float64 image so far, refused (check_finite_image) where not finite; a new
        array on every call, ``last`` or not (rtfgu.kernels.NumbaAccumulator's ``last``)."""
        width, height = self.size
        sums = self.compiled.render(width, height, self.tile, progress, self.seed, samples)
        image = (sums / np.float32(samples[1])).astype(np.float64)
        check_finite_image(image, "wgpu")
        return image


def render_wgpu(scene, width: int, height: int, progress=None,
                scene_buffer: str = DEFAULT_SCENE_BUFFER, tile: int = TILE,
                formula: str | None = None, spp: int | None = None, seed: int = 0) -> np.ndarray:
    """The WGSL path in one pass: (height, width, 3) float64, before gamma; ``spp``,
    ``seed`` as rtfgu.render."""
    sampler = pixel_sampler(scene, spp)
    accumulate = WGPUAccumulator(scene, width, height, formula, sampler, seed, scene_buffer, tile)
    samples = (0, 1 if sampler is None else sampler.num_samples)
    return accumulate(samples, progress)
