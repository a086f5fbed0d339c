"""Shared test configuration.

``--update-reference-images`` is the only way the committed images in
``tests/reference_images/`` are rewritten: without it an image test compares and fails,
it never regenerates silently.
"""
from __future__ import annotations

from pathlib import Path

import pytest

TESTS_DIR = Path(__file__).resolve().parent
REFERENCE_IMAGES_DIR = TESTS_DIR / "reference_images"
# Where a failing image test writes what it rendered and a diff (git-ignored).
OUTPUT_DIR = TESTS_DIR / "output"


def pytest_addoption(parser):
    parser.addoption(
        "--update-reference-images",
        action="store_true",
        default=False,
        help="rewrite tests/reference_images/*.png from the current renderer instead of comparing",
    )


@pytest.fixture
def update_reference_images(request) -> bool:
    return request.config.getoption("--update-reference-images")


@pytest.fixture
def reference_images_dir() -> Path:
    return REFERENCE_IMAGES_DIR


@pytest.fixture
def output_dir() -> Path:
    """Where a failing image test writes its images; created only when something is written."""
    return OUTPUT_DIR


# Every path a scene can be rendered on: (label, backend, precision).
PATHS = (("reference", "reference", "float64"), ("numba-float64", "numba", "float64"),
         ("numba-float32", "numba", "float32"), ("wgpu-float32", "wgpu", "float32"))


class RenderPath:
    """One path as a contract test sees it: ``trace(scene, rays, formula=None)`` runs the
    given rays (origin, direction, tmin, tmax) through ``scene`` on this path in one call
    (with the path's default formula where None) and returns each ray's bounces
    (rtfgu.debug.trace_rays); ``label`` names it in a failure."""

    def __init__(self, label, backend, precision):
        self.label, self.backend, self.precision = label, backend, precision

    @property
    def reference(self) -> "RenderPath":
        """The lecture layer, which defines the right answer for every path."""
        return RenderPath(*PATHS[0])

    def trace(self, scene, rays, formula=None):
        from rtfgu.debug import trace_rays

        return trace_rays(scene, rays, self.backend, self.precision, formula)

    def __repr__(self):
        return self.label


def _available(label, backend, precision) -> RenderPath:
    """The path, or a skip naming the package to install where WGSL has no adapter."""
    if backend == "wgpu":
        from rtfgu.wgsl.device import NoAdapterError, get_device

        try:
            get_device()
        except NoAdapterError as error:
            pytest.skip(str(error))
    return RenderPath(label, backend, precision)


@pytest.fixture(params=PATHS, ids=[label for label, _, _ in PATHS])
def path(request) -> RenderPath:
    """Each path in turn; the WGSL one is skipped only where no adapter exists, with the
    package to install in the reason (rtfgu.wgsl.device)."""
    return _available(*request.param)


@pytest.fixture(params=PATHS[1:], ids=[label for label, _, _ in PATHS[1:]])
def fast_path(request) -> RenderPath:
    """Each path but the lecture layer, for images too large for pure Python (thousands of
    samples per pixel); numba float64 stands in for the lecture layer there, which it
    equals within 1e-9 (tests/test_numba_parity.py). WGSL skipped as in ``path``."""
    return _available(*request.param)


# Test files whose numba tests compile the same kernels (the image and solid textures: the same
# debugger kernel in both precisions) run on one pytest-xdist worker, one after the other, so
# the second loads from numba's cache what the first compiled; on two workers at once, each
# compiled it (docs/compile_time.md, "Kernels compiled twice"). Every other file is its own
# scope, as under --dist loadfile.
SAME_WORKER = {"test_textures.py": "textures", "test_solid_textures.py": "textures"}

try:
    from xdist.scheduler import LoadFileScheduling
except ImportError:  # pytest without pytest-xdist: one process, nothing to share out
    LoadFileScheduling = None

if LoadFileScheduling is not None:
    class SharedKernelScheduling(LoadFileScheduling):
        """--dist loadfile, except that the files SAME_WORKER maps to one name are one scope."""

        def _split_scope(self, nodeid: str) -> str:
            file = super()._split_scope(nodeid)
            return SAME_WORKER.get(file.rsplit("/", 1)[-1], file)

    @pytest.hookimpl(optionalhook=True)  # pytest -p no:xdist: no such hook
    def pytest_xdist_make_scheduler(config, log):
        if config.getvalue("dist") == "loadfile":
            return SharedKernelScheduling(config, log)
        return None
