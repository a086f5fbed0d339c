"""The WebGPU adapter and device, requested once per process.

A real GPU when there is one; otherwise the software adapter Mesa provides on Linux:
llvmpipe through OpenGL (Debian: libgl1-mesa-dri with libegl1) or lavapipe through
Vulkan (Debian: mesa-vulkan-drivers). With no adapter at all ``NoAdapterError`` says
which package to install, so that no caller ever sees a black image instead.
"""
from __future__ import annotations

INSTALL_HINT = ("install a GPU driver, or Mesa's software adapter: on Debian/Ubuntu "
                "`apt-get install libgl1-mesa-dri libegl1` (llvmpipe through OpenGL) or "
                "`apt-get install mesa-vulkan-drivers` (lavapipe through Vulkan)")


class NoAdapterError(RuntimeError):
    """No WebGPU adapter (or no wgpu) on this machine."""


_DEVICE = None


def _pick(adapters):
    # A real GPU first (discrete before integrated), the CPU adapter only as a fallback.
    rank = {"DiscreteGPU": 0, "IntegratedGPU": 1, "VirtualGPU": 2, "Unknown": 3, "CPU": 4}
    return min(adapters, key=lambda a: rank.get(a.info.get("adapter_type", "Unknown"), 3))


def _runtime_dir() -> None:
    """Give the process an XDG_RUNTIME_DIR where it has none (a container, a CI job, ssh
    without a login session): Mesa's Vulkan driver asks libwayland for a display, which
    prints "error: XDG_RUNTIME_DIR is invalid or not set in the environment." once per
    probe otherwise, alarming and meaningless for an off-screen render. The folder is the
    process's own (mode 0700, as the XDG Base Directory specification requires), empty, so
    no display is found there either."""
    import os
    import stat
    import tempfile

    current = os.environ.get("XDG_RUNTIME_DIR")
    if current:
        try:
            info = os.stat(current)
            if stat.S_ISDIR(info.st_mode) and info.st_uid == os.getuid() and not info.st_mode & 0o077:
                return
        except OSError:
            pass
    import atexit

    folder = tempfile.mkdtemp(prefix="rtfgu-runtime-")
    atexit.register(lambda: os.path.isdir(folder) and not os.listdir(folder) and os.rmdir(folder))
    os.environ["XDG_RUNTIME_DIR"] = folder


def get_device():
    """(adapter, device), created on the first call and cached for the process."""
    global _DEVICE
    if _DEVICE is not None:
        return _DEVICE
    _runtime_dir()
    try:
        import wgpu
    except Exception as error:  # ImportError, or wgpu-native's library failing to load
        raise NoAdapterError("the wgpu backend needs the Python package wgpu (pip install wgpu): "
                             "%s" % error) from error
    try:
        adapters = list(wgpu.gpu.enumerate_adapters_sync())
    except Exception as error:
        raise NoAdapterError("no WebGPU adapter: %s (%s)" % (INSTALL_HINT, error)) from error
    if not adapters:
        raise NoAdapterError("no WebGPU adapter: " + INSTALL_HINT)
    adapter = _pick(adapters)
    device = adapter.request_device_sync(required_limits={})
    _DEVICE = (adapter, device)
    return _DEVICE


def adapter_description() -> str:
    """e.g. 'llvmpipe (LLVM 15.0.6, 256 bits) (CPU) via OpenGL'."""
    adapter, _ = get_device()
    info = adapter.info
    return "%s (%s) via %s" % (info.get("device", "?"), info.get("adapter_type", "?"),
                               info.get("backend_type", "?"))
