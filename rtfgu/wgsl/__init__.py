"""The WGSL path: the scene as a WebGPU compute program written as the 02562 slides write it
(struct Ray, struct HitInfo, intersect_* with ptr<function, HitInfo>, shade's switch, the
path loop), assembled per scene from the .wgsl files of this package and run through wgpu."""
from .assemble import Program, assemble, pieces
from .device import INSTALL_HINT, NoAdapterError, adapter_description, get_device
from .runner import WGPUAccumulator, WGSLCompileError, compile_program, prepare, render_wgpu

__all__ = ["pieces", "Program", "assemble", "INSTALL_HINT", "NoAdapterError",
           "adapter_description", "get_device", "WGSLCompileError", "compile_program",
           "prepare", "render_wgpu", "WGPUAccumulator"]
