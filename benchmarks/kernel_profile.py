"""Where a numba render's time goes, by function and by instruction: renders a scene of
benchmarks/scenes.py again and again with a symbol map of the compiled kernels for Linux
``perf`` (which cannot name code that numba compiles at run time).

    perf record -F 4999 -o perf.data python benchmarks/kernel_profile.py random_spheres_64
    perf report -i perf.data --sort dso,sym

The kernels are compiled afresh (an empty numba cache of its own), so that their object
code is at hand: each is written to OUT/<function>.o, whose ``objdump -d`` offsets are the
report's offsets from the symbol. The map is /tmp/perf-<pid>.map (perf's convention for
code made at run time).
"""
from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path


def symbols(library, path: Path) -> list:
    """(address, size, name) of every function of a compiled numba library, its object code
    written to ``path``."""
    path.write_bytes(library._compiled_object)
    listing = subprocess.run(["nm", "-S", "--defined-only", str(path)], capture_output=True, text=True,
                             check=True).stdout
    out = []
    for line in listing.splitlines():
        parts = line.split()
        if len(parts) == 4 and parts[2] in "tT":
            address = library.get_pointer_to_function(parts[3])
            if address:
                out.append((address, int(parts[1], 16), parts[3]))
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene", help="a function of benchmarks/scenes.py")
    parser.add_argument("--size", type=int, default=1024)
    parser.add_argument("--precision", default="float32", choices=("float32", "float64"))
    parser.add_argument("--calls", type=int, default=200)
    parser.add_argument("--out", default="kernel_profile", help="folder for the object files")
    args = parser.parse_args(argv)
    # Before numba is imported: compiled here, not loaded from a cache without object code.
    os.environ["NUMBA_CACHE_DIR"] = tempfile.mkdtemp(prefix="rtfgu-profile-")
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    import scenes
    from rtfgu.kernels import NumbaAccumulator
    from rtfgu.kernels.render import mean_rows, render_kernel, render_tile

    scene = getattr(scenes, args.scene)()
    accumulate = NumbaAccumulator(scene, args.size, args.size, args.precision)
    accumulate((0, 1))
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for dispatcher in (render_kernel, render_tile, mean_rows):
        for n, result in enumerate(dispatcher.overloads.values()):
            name = "%s_%d" % (dispatcher.py_func.__name__, n)
            rows += [(a, s, "%s:%s" % (name, symbol)) for a, s, symbol in symbols(result.library, out / (name + ".o"))]
    Path("/tmp/perf-%d.map" % os.getpid()).write_text("".join("%x %x %s\n" % row for row in rows))
    start = time.perf_counter()
    for _ in range(args.calls):
        accumulate.add((0, 1))
    print("%d calls, %.2f ms a call; object code in %s/" % (args.calls, (time.perf_counter() - start) / args.calls * 1e3,
                                                          out))


if __name__ == "__main__":
    main()
