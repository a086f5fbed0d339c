"""rtfgu.kernels.llvm_passes: the kernels skip numba's first run of LLVM's function pipeline
(the module pipeline optimises them), every other function keeps it, rtfgu's own small
functions included, and a function compiled so computes what it did."""
from __future__ import annotations

import math

import pytest
from numba import njit
from numba.core import codegen

import rtfgu.kernels  # noqa: F401  (installs it, as a render does)
from rtfgu.kernels import llvm_passes

SOURCE = '''
def NAME(n, x):
    total = 0.0
    for k in range(n):
        if k % 3 == 0:
            total += math.sqrt(x + k)
        else:
            total -= x / (k + 1.0)
    return total
'''


def probe_in(module_name, name):
    """The probe function, named ``name``, defined as if in module ``module_name`` (numba
    names a compiled function after its module and its name)."""
    namespace = {"__name__": module_name, "math": math}
    exec(SOURCE.replace("NAME", name), namespace)
    return namespace[name]


@pytest.fixture
def function_pipeline_runs(monkeypatch):
    """The names of the functions numba's function pipeline runs on, from here on."""
    names = []
    make = codegen.JITCPUCodegen._function_pass_manager

    def recording(self, **kwargs):
        fpm, pb = make(self, **kwargs)

        class Recorder:
            def run(self, function, builder):
                names.append(function.name)
                return fpm.run(function, builder)
        return Recorder(), pb
    monkeypatch.setattr(codegen.JITCPUCodegen, "_function_pass_manager", recording)
    return names


def test_it_is_installed():
    optimize = codegen.CPUCodeLibrary._optimize_functions
    assert getattr(optimize, "_rtfgu_once", False)
    assert optimize.numba_optimize_functions is not optimize


@pytest.mark.parametrize("module_name, name, skipped", [
    ("rtfgu.kernels.render", "render_tile", True),          # as a kernel is named
    ("rtfgu.kernels.debug", "trace_records", True),
    ("rtfgu.kernels.mesh", "mesh_closest", False),           # one of rtfgu's small functions
    ("a_students_module", "render_tile", False)])
def test_only_the_kernels_skip_the_function_pipeline(function_pipeline_runs, module_name, name, skipped):
    probe = probe_in(module_name, name)
    compiled = njit(probe)
    for n, x in ((0, 1.0), (7, 2.5), (40, 0.25)):
        assert compiled(n, x) == probe(n, x)
    own = [f for f in function_pipeline_runs if name in f]
    if skipped:
        assert own == []
    else:
        assert own, "numba's function pipeline ran on no function of the probe"


def test_the_kernels_named_are_the_kernels():
    from rtfgu.kernels import debug, render

    functions = {name: getattr(render, name, None) or getattr(debug, name, None) for name in llvm_passes.KERNELS}
    assert all(hasattr(f, "py_func") for f in functions.values()), functions
    assert {f.py_func.__module__ for f in functions.values()} <= {"rtfgu.kernels.render", "rtfgu.kernels.debug"}


def test_what_counts_as_a_kernels_module():
    class Function:
        def __init__(self, name, declaration=False):
            self.name, self.is_declaration = name, declaration

    class Module:
        def __init__(self, *functions):
            self.functions = functions
    assert llvm_passes.is_kernel_module(Module(Function("_ZN5rtfgu7kernels6render11render_tileB3v12E")))
    assert llvm_passes.is_kernel_module(Module(Function("_ZN5rtfgu7kernels6render13render_kernelB3v10E")))
    assert llvm_passes.is_kernel_module(Module(Function("_ZN5rtfgu7kernels5debug13trace_recordsB3v2E")))
    # A module that only declares a kernel (calls it) is not the kernel's: the parallel
    # loop's body, which calls render_tile.
    assert not llvm_passes.is_kernel_module(Module(
        Function("_ZN5rtfgu7kernels6render11render_tileB3v12E", True),
        Function("_ZN13_3cdynamic_3e36__numba_parfor_gufunc_0x7f52227cdf50B4v145E")))
    assert not llvm_passes.is_kernel_module(Module(Function("_ZN5rtfgu7kernels4mesh12mesh_closestB3v7E")))
    assert not llvm_passes.is_kernel_module(Module(Function("_ZN31rtfgu_dispatch_0123456789abcdef5shadeE")))
    assert not llvm_passes.is_kernel_module(Module(Function("_ZN8__main__11render_tileE")))
    assert not llvm_passes.is_kernel_module(Module(Function("_ZN5numba2np8arrayobj4fillE")))
