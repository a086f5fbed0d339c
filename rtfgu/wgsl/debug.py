"""Run the pixel debugger's WGSL program (debug_main.wgsl in place of main.wgsl) and read
its records: one pixel's path, or a batch of given rays in one dispatch. The program is
assembled and compiled as a render's is (rtfgu/wgsl/assemble.py, runner.compile_program),
so a scene with the same counts and kinds reuses the compiled pipeline.
"""
from __future__ import annotations

import numpy as np

from .. import layout
from ..layout import compile_scene
from ..tracers.whitted import MAX_DEPTH
from . import structs
from .assemble import assemble, check_formula
from .runner import compile_program

ENTRY = "debug_main.wgsl"
# vec4f per path: two of input, four per bounce (debug_main.wgsl).
STRIDE = 2 + 4 * MAX_DEPTH
WORKGROUP = 64


def wgpu_records(scene, formula=None, pixel=None, rays=None) -> np.ndarray:
    """(paths, MAX_DEPTH, 4, 4) float32 records of debug_main.wgsl: of ``pixel`` (x, y,
    width, height) with row y = 0 at the top, or of every row of ``rays`` ((n, 8): origin,
    direction, tmin, tmax; an infinite tmax goes in as rtfgu.layout.FAR)."""
    import wgpu

    check_formula(formula)
    flat = compile_scene(scene, "float32")
    compiled = compile_program(assemble(flat, formula=formula, entry=ENTRY))
    compiled.upload(flat)
    data = np.zeros((1, STRIDE, 4), dtype=np.float32)
    if pixel is None:
        given = np.asarray(rays, dtype=np.float64).reshape(-1, 8)
        given = np.where(np.isinf(given), np.sign(given) * layout.FAR, given)
        data = np.zeros((len(given), STRIDE, 4), dtype=np.float32)
        data[:, 0] = given[:, [0, 1, 2, 6]]
        data[:, 1] = given[:, [3, 4, 5, 7]]
        uniforms = structs.uniforms(compiled.background, 0, 1, 1, (0, 0), (len(given), 0))
    else:
        x, y, width, height = pixel
        uniforms = structs.uniforms(compiled.background, 0, width, height, (x, y), (1, 1))
    device = compiled.device
    buffer = device.create_buffer(size=data.nbytes, usage=wgpu.BufferUsage.STORAGE
                                  | wgpu.BufferUsage.COPY_SRC | wgpu.BufferUsage.COPY_DST)
    group = device.create_bind_group(layout=compiled.image_layout, entries=[
        {"binding": 0, "resource": {"buffer": buffer}}])
    device.queue.write_buffer(buffer, 0, data.tobytes())
    device.queue.write_buffer(compiled.uniforms, 0, uniforms)
    encoder = device.create_command_encoder()
    compute = encoder.begin_compute_pass()
    compute.set_pipeline(compiled.pipeline)
    compute.set_bind_group(0, compiled.scene_group)
    compute.set_bind_group(1, group)
    compute.dispatch_workgroups(-(-len(data) // WORKGROUP), 1, 1)
    compute.end()
    device.queue.submit([encoder.finish()])
    out = np.frombuffer(device.queue.read_buffer(buffer, 0, data.nbytes), dtype=np.float32)
    return out.reshape(len(data), STRIDE, 4)[:, 2:].reshape(len(data), MAX_DEPTH, 4, 4).copy()
