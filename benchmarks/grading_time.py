"""Grading time per submission in each isolation mode (docs/grading_sandbox.md, "Time per
submission").

Each mode runs in a process of its own, as root: the solution of each assignment is graded
once to warm up (the runtime copy, the namespace probe and the ``.pyc`` files of the
site-packages exist afterwards), then ``--rounds`` times; the median is reported with the
score, so a time never stands without what was graded.

    python benchmarks/grading_time.py [a01 a09 ...] [--rounds 3] [--modes bwrap,user,user-ns]

Modes: ``bwrap`` (bubblewrap), ``user`` (the fallback without namespaces: Gradescope's
container, RTFGU_BWRAP=none RTFGU_FALLBACK_NAMESPACES=0), ``user-ns`` (the fallback with its
mount, network and IPC namespaces, RTFGU_BWRAP=none).
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time

MODES = {
    "bwrap": {},
    "user": {"RTFGU_BWRAP": "none", "RTFGU_FALLBACK_NAMESPACES": "0"},
    "user-ns": {"RTFGU_BWRAP": "none"},
}


def worker(assignments, rounds) -> None:
    from rtfgu.grading.grader import grade

    rows = []
    for name in assignments:
        warm = grade(name, None)
        times = []
        for _ in range(rounds):
            start = time.perf_counter()
            result = grade(name, None)
            times.append(time.perf_counter() - start)
        rows.append({"assignment": name, "tests": len(result.tests), "isolation": warm.isolation,
                     "score": sum(t.score for t in result.tests),
                     "max_score": sum(t.max_score for t in result.tests),
                     "median_s": statistics.median(times), "times": times})
    print(json.dumps(rows))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("assignments", nargs="*", default=["a%02d" % n for n in range(1, 10)])
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--modes", default=",".join(MODES))
    parser.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        worker(args.assignments, args.rounds)
        return
    results = {}
    for mode in args.modes.split(","):
        env = dict(os.environ, **MODES[mode])
        out = subprocess.run([sys.executable, __file__, "--worker", "--rounds", str(args.rounds),
                              *args.assignments], env=env, check=True, capture_output=True, text=True)
        results[mode] = {row["assignment"]: row for row in json.loads(out.stdout.splitlines()[-1])}
    modes = list(results)
    print("load average before the last mode: %.2f %.2f %.2f" % os.getloadavg())
    print("| assignment | tests | " + " | ".join("%s (%s)" % (m, next(iter(results[m].values()))["isolation"])
                                                 for m in modes) + " | score |")
    print("|---|---:|" + "---:|" * len(modes) + "---:|")
    for name in args.assignments:
        first = results[modes[0]][name]
        scores = {"%g/%g" % (results[m][name]["score"], results[m][name]["max_score"]) for m in modes}
        print("| %s | %d | %s | %s |" % (name, first["tests"],
                                        " | ".join("%.2f s" % results[m][name]["median_s"] for m in modes),
                                        ", ".join(sorted(scores))))


if __name__ == "__main__":
    main()
