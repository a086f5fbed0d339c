"""A class of 20 mixed a03 submissions graded by ``grade-all``, as an instructor runs it
(docs/course.md, "Grading a class"): the wall time and the gradebook, whose ``error``
column must say the cause of every submission that could not be judged.

The class: 8 solutions, 7 planted bugs (tests/submissions), two endless loops (Triangle.normal_at
and, at its first line, Sphere.intersect_p), a syntax error, an exception at import and a
submission that hoards memory and prints megabytes. Each isolation mode runs in its own
process (benchmarks/grading_time.py's modes), all cores.

    python benchmarks/grading_class.py [--modes bwrap,user] [--time-limit 10]
"""
from __future__ import annotations

import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))

from grading_time import MODES  # noqa: E402

PLANTED = ("a03_discriminant_sign", "a03_missing_tmin", "a03_sphere_a_is_one", "a03_unnormalised_normal",
           "a03_triangle_gamma_sign", "a03_triangle_swapped_edges", "a03_triangle_open_edges")
DEF = "    def intersect_p(self, ray: Ray) -> bool:\n"


def write_class(folder: Path) -> None:
    from planted import apply_replacements, make_submission
    from rtfgu.grading.generate import solution_files, write_files

    solved = solution_files("a03")
    for i in range(8):
        write_files(solved, folder / ("solution_%d" % i))
    for name in PLANTED:
        make_submission(name, folder / name)
    make_submission("a03_infinite_loop", folder / "loop_triangle_normal")
    write_files(apply_replacements(solved, [("shapes/sphere.py", DEF, DEF + "        while True:\n            pass\n")],
                                   "loop"), folder / "loop_sphere_intersect")
    write_files(dict(solved, **{"shapes/plane.py": solved["shapes/plane.py"].replace("def intersect_p(self, ray: Ray)",
                                                                                    "def intersect_p(self, ray: Ray", 1)}),
                folder / "syntax_error")
    write_files(dict(solved, **{"shapes/sphere.py": solved["shapes/sphere.py"] + "\nraise RuntimeError('boom')\n"}),
                folder / "raises_at_import")
    make_submission("a03_misbehaving", folder / "misbehaving")


def worker(time_limit: float) -> None:
    from rtfgu.grading.gradebook import grade_all

    with tempfile.TemporaryDirectory() as tmp:
        write_class(Path(tmp) / "class")
        start = time.perf_counter()
        path = grade_all("a03", Path(tmp) / "class", Path(tmp) / "out", time_limit=time_limit)
        seconds = time.perf_counter() - start
        rows = list(csv.DictReader(open(path)))
    print(json.dumps({"seconds": seconds, "rows": rows}))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--modes", default="bwrap,user")
    parser.add_argument("--time-limit", type=float, default=10.0)
    parser.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        worker(args.time_limit)
        return
    print("%d cores, load average %.2f %.2f %.2f before" % ((os.cpu_count(),) + os.getloadavg()))
    for mode in args.modes.split(","):
        out = subprocess.run([sys.executable, __file__, "--worker", "--time-limit", str(args.time_limit)],
                             env=dict(os.environ, **MODES[mode]), check=True, capture_output=True, text=True)
        data = json.loads(out.stdout.splitlines()[-1])
        print("\n%s: %d submissions graded in %.1f s (time limit %g s per test)\n"
              % (mode, len(data["rows"]), data["seconds"], args.time_limit))
        print("| student | score | error |")
        print("|---|---:|---|")
        for row in sorted(data["rows"], key=lambda r: r["student"]):
            print("| %s | %s | %s |" % (row["student"], row["score"], row["error"] or ""))


if __name__ == "__main__":
    main()
