"""Run a compute program over arrays: the one WGSL harness of the hard cases, the grading
checks and any test that calls WGSL functions directly, next to the render's runner.

    program = batch_program(["ray.wgsl", "hitinfo.wgsl", "intersect_sphere.wgsl",
                             "hardcase_main.wgsl"], features={"sphere", "slide"},
                            constants={"SHAPE_WIDTH": 4})
    out = run_batch(program, [zero, rays, shapes], count)      # (count, 1, 4) float32

A program is assembled as the render's is (rtfgu/wgsl/assemble.py): the generated
constants of rtfgu.layout, then the named pieces of this package in the order given, each
cut to ``features`` by its ``// #if`` lines, with every line's origin kept, so a compile
error names file:line in fn (``WGSLCompileError``). ``overrides`` puts a text in place of a
piece, or adds a piece that is not a file here (a student's own intersect_sphere.wgsl).

The program's entry point is ``main`` with ``@workgroup_size(64)``; it reads the inputs at
``@group(0) @binding(0 .. k-1)`` (``var<storage, read>``) and writes ``array<vec4f>``, of
``count * vec4s`` elements, at ``@binding(k)`` (``var<storage, read_write>``). Compiled
programs share the render's device (``get_device``) and process cache (runner._PIPELINES).
"""
from __future__ import annotations

import numpy as np

from . import structs
from .assemble import GENERATED, Program, read_piece, select_lines
from .device import get_device
from .runner import _PIPELINES, WGSLCompileError, _compile_error  # noqa: F401 (WGSLCompileError: what a failing compile raises)

WORKGROUP = 64


def batch_program(pieces, features=(), constants=None, overrides=None) -> Program:
    """The compute program of ``pieces`` (file names in rtfgu/wgsl), cut to ``features``;
    ``constants``: {name: unsigned integer} declared after the layout's constants."""
    overrides = dict(overrides or {})
    features = frozenset(features)
    header = [structs.constants_wgsl()]
    header += ["const %s = %du;" % item for item in sorted((constants or {}).items())]
    lines, origin = [], []
    for number, line in enumerate("\n".join(header).splitlines(), start=1):
        lines.append(line)
        origin.append((GENERATED, number))
    for name in pieces:
        text = overrides[name] if name in overrides else read_piece(name)
        lines.append("// ---- rtfgu/wgsl/%s" % name)
        origin.append((name, 0))
        for number, line in select_lines(text, features, name):
            lines.append(line)
            origin.append((name, number))
    return Program("\n".join(lines) + "\n", origin, [], features, list(pieces))


class BatchPipeline:
    """A compiled batch program; one pipeline per number of input buffers."""

    def __init__(self, program: Program):
        _, self.device = get_device()
        self.program = program
        try:
            self.module = self.device.create_shader_module(label="rtfgu batch", code=program.source)
        except Exception as error:
            raise _compile_error(program, error, "compilation") from None
        self._pipelines = {}

    def pipeline(self, inputs: int):
        import wgpu

        if inputs not in self._pipelines:
            kinds = [wgpu.BufferBindingType.read_only_storage] * inputs + [wgpu.BufferBindingType.storage]
            layout = self.device.create_bind_group_layout(entries=[
                {"binding": b, "visibility": wgpu.ShaderStage.COMPUTE, "buffer": {"type": kind}}
                for b, kind in enumerate(kinds)])
            try:
                pipeline = self.device.create_compute_pipeline(
                    layout=self.device.create_pipeline_layout(bind_group_layouts=[layout]),
                    compute={"module": self.module, "entry_point": "main"})
            except Exception as error:
                raise _compile_error(self.program, error, "pipeline creation") from None
            self._pipelines[inputs] = (layout, pipeline)
        return self._pipelines[inputs]

    def run(self, inputs, count: int, vec4s: int = 1) -> np.ndarray:
        import wgpu

        layout, pipeline = self.pipeline(len(inputs))
        usage = wgpu.BufferUsage
        buffers = []
        for data in inputs:
            raw = np.ascontiguousarray(data).tobytes()
            raw += bytes(-len(raw) % 16 if raw else 16)  # whole vec4s; a binding is never empty
            buffers.append(self.device.create_buffer_with_data(data=raw, usage=usage.STORAGE))
        size = 16 * vec4s * count
        output = self.device.create_buffer(size=max(size, 16), usage=usage.STORAGE | usage.COPY_SRC)
        buffers.append(output)
        group = self.device.create_bind_group(layout=layout, entries=[
            {"binding": b, "resource": {"buffer": buffer, "offset": 0, "size": buffer.size}}
            for b, buffer in enumerate(buffers)])
        encoder = self.device.create_command_encoder()
        compute = encoder.begin_compute_pass()
        compute.set_pipeline(pipeline)
        compute.set_bind_group(0, group)
        compute.dispatch_workgroups(max(1, -(-count // WORKGROUP)), 1, 1)
        compute.end()
        self.device.queue.submit([encoder.finish()])
        data = np.frombuffer(self.device.queue.read_buffer(output), dtype=np.float32)
        return data[:4 * vec4s * count].reshape(count, vec4s, 4)


def compile_batch(program: Program) -> BatchPipeline:
    """The compiled ``program``, from the process cache when its text was compiled before."""
    key = ("batch", program.source)
    if key not in _PIPELINES:
        _PIPELINES[key] = BatchPipeline(program)
    return _PIPELINES[key]


def run_batch(program: Program, inputs, count: int, vec4s: int = 1) -> np.ndarray:
    """Run ``program`` over ``count`` items: ``inputs`` (numpy arrays, in binding order)
    in, ``vec4s`` vec4f per item out, as a (count, vec4s, 4) float32 array."""
    return compile_batch(program).run(inputs, count, vec4s)
