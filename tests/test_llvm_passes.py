"""rtfgu.kernels.llvm_passes: rtfgu's functions skip numba's first run of LLVM's function
pipeline (the module pipeline optimises them), every other function keeps it, and a
function compiled so computes what it did."""
from __future__ import annotations

import math

import pytest
from numba import njit
from numba.core import codegen

import rtfgu.kernels  # noqa: F401  (installs it, as a render does)
from rtfgu.kernels import llvm_passes

SOURCE = '''
def probe(n, x):
    total = 0.0
    for k in range(n):
        if k % 3 == 0:
            total += math.sqrt(x + k)
        else:
            total -= x / (k + 1.0)
    return total
'''


def probe_in(module_name):
    """The probe function, defined as if in module ``module_name`` (numba names a compiled
    function after its module)."""
    namespace = {"__name__": module_name, "math": math}
    exec(SOURCE, namespace)
    return namespace["probe"]


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


@pytest.mark.parametrize("module_name, skipped", [("rtfgu.kernels.probe", True),
                                                   ("a_students_module", False)])
def test_only_rtfgus_functions_skip_the_function_pipeline(function_pipeline_runs, module_name, skipped):
    probe = probe_in(module_name)
    compiled = njit(probe)
    for n, x in ((0, 1.0), (7, 2.5), (40, 0.25)):
        assert compiled(n, x) == probe(n, x)
    own = [name for name in function_pipeline_runs if "probe" in name]
    if skipped:
        assert own == []
    else:
        assert own, "numba's function pipeline ran on no function of the probe"


def test_what_counts_as_rtfgus_module():
    class Function:
        def __init__(self, name, declaration=False):
            self.name, self.is_declaration = name, declaration

    class Module:
        def __init__(self, *functions):
            self.functions = functions
    assert llvm_passes.is_rtfgu_module(Module(Function("_ZN5rtfgu7kernels6render11render_tileB3v12E")))
    assert llvm_passes.is_rtfgu_module(Module(Function("_ZN31rtfgu_dispatch_0123456789abcdef5shadeE")))
    # A module that only declares one of rtfgu's functions (calls it) is not rtfgu's.
    assert not llvm_passes.is_rtfgu_module(Module(Function("_ZN5rtfgu7kernels4mesh12mesh_closestE", True),
                                                  Function("_ZN8__main__3fooE")))
    assert not llvm_passes.is_rtfgu_module(Module(Function("_ZN5numba2np8arrayobj4fillE")))
