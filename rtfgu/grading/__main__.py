"""python -m rtfgu.grading: generate the assignments, grade submissions, build the bundle.

Errors in what the user typed (unknown assignment, missing folder) exit with code 2 and a
message naming the parameter.
"""
from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from .assignments import ASSIGNMENTS, get_assignment


def _cmd_render(a, folder, out, width, height) -> int:
    """Render the assignment's images with the student's files; 1 if any render failed (0,
    with a message, for an assignment without images)."""
    import numpy as np

    from ..image import write_png
    from .sandbox import choose_isolation, hidden_from_sandbox_user, prepare, run_child, work_folder

    if not a.images:
        print("%s has no images to render: its tests are `make check A=%s`" % (a.id, a.short))
        return 0
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    failed = 0
    isolation = choose_isolation()
    with hidden_from_sandbox_user(isolation), work_folder("rtfgu-render-") as tmp:
        ws = prepare(a, folder, tmp / "work")
        for note in ws.notes + list(ws.broken.values()):
            print("note:", note)
        for name in a.images:
            child = run_child(ws, tmp / "scratch" / name, ["render", name, width or 0, height or 0],
                              isolation=isolation, time_limit=3600, memory_mb=4096,
                              output_limit=16 * 1024 * 1024)
            if child.status != "ok" or "error" in child.data:
                print("%s: failed: %s" % (name, child.detail or child.data.get("error")))
                failed += 1
                continue
            path = out / (name + ".png")
            write_png(np.asarray(child.data["image"]), path)
            print(path)
    if failed:
        print("%d of %d images failed to render" % (failed, len(a.images)))
    return 1 if failed else 0


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m rtfgu.grading", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("list", help="the assignments")
    p = sub.add_parser("generate", help="write the student tree (assignments/)")
    p.add_argument("--out", default="assignments")
    p.add_argument("--check", action="store_true", help="only compare; exit 1 if the folder differs")
    p = sub.add_parser("solution", help="write the solved student files of an assignment")
    p.add_argument("assignment")
    p.add_argument("out")
    p = sub.add_parser("stubs", help="write the student files (stubs) of an assignment")
    p.add_argument("assignment")
    p.add_argument("out")
    p = sub.add_parser("references", help="regenerate the reference observations from the solution")
    p.add_argument("assignments", nargs="*")

    def grading_options(p):
        p.add_argument("--time-limit", type=float, default=None, help="seconds per test")
        p.add_argument("--memory-mb", type=int, default=1024, help="memory per test, MB")
        p.add_argument("--require-sandbox", action="store_true",
                       help="refuse to grade unless student code runs in bubblewrap")

    p = sub.add_parser("grade", help="grade one submission (a folder or a zip)")
    p.add_argument("assignment")
    p.add_argument("submission")
    p.add_argument("--out", default=None, help="folder for results.json, summary.txt and diffs/")
    p.add_argument("--format", default="gradescope", choices=("gradescope", "prairielearn"))
    p.add_argument("--visible-only", action="store_true")
    grading_options(p)
    p = sub.add_parser("check", help="the visible tests on a student's files")
    p.add_argument("assignment")
    p.add_argument("folder", nargs="?", default=None, help="default assignments/<id>")
    p.add_argument("--out", default=None)
    grading_options(p)
    p = sub.add_parser("render", help="render the assignment's images with a student's files")
    p.add_argument("assignment")
    p.add_argument("folder", nargs="?", default=None)
    p.add_argument("--out", default=None, help="default renders/<aNN>")
    p.add_argument("--width", type=int, default=None)
    p.add_argument("--height", type=int, default=None)
    p = sub.add_parser("grade-all", help="grade a class: one folder (or zip) per student")
    p.add_argument("assignment")
    p.add_argument("submissions")
    p.add_argument("--out", required=True)
    p.add_argument("--processes", type=int, default=None, help="default: all cores")
    grading_options(p)
    p = sub.add_parser("release", help="write a student repository (no solution in it) into OUT")
    p.add_argument("out")
    p.add_argument("--reveal", default="", help="assignments whose solutions the release carries, e.g. a01,a02")
    p.add_argument("--no-gaps", action="store_true",
                   help="do not run the visible tests to find those students cannot pass in this release")
    p = sub.add_parser("autograder-zip", help="build the Gradescope autograder bundle")
    p.add_argument("assignment")
    p.add_argument("--out", default=None, help="default dist/autograder-<id>.zip")

    args = parser.parse_args(argv)
    try:
        if args.command == "list":
            for a in ASSIGNMENTS.values():
                print("%-40s %s" % (a.id, a.title))
        elif args.command == "generate":
            from .generate import compare_tree, write_tree

            if args.check:
                problems = compare_tree(args.out)
                for line in problems:
                    print(line)
                return 1 if problems else 0
            for path in write_tree(args.out):
                print(path)
        elif args.command in ("solution", "stubs"):
            from .generate import solution_files, student_files, write_files

            a = get_assignment(args.assignment)
            if args.command == "solution":
                # The solved files are the writer's alone (folders 0700, files 0600, made so
                # from the start): a sandbox user running a student's code must not read them.
                out = Path(args.out)
                mask = os.umask(0o077)
                try:
                    written = write_files(solution_files(a), out)
                finally:
                    os.umask(mask)
                for path in written:
                    os.chmod(path, 0o600)
                    for folder in path.parents:
                        os.chmod(folder, 0o700)
                        if folder == out:
                            break
            else:
                written = write_files(student_files(a), args.out)
            for path in written:
                print(path)
        elif args.command == "references":
            from .grader import compute_references
            from .mistakes import write_known

            for name in args.assignments or list(ASSIGNMENTS):
                a = get_assignment(name)
                for path in compute_references(a):
                    print(path)
                known = write_known(a)
                if known is not None:
                    print(known)
        elif args.command in ("grade", "check"):
            from .grader import grade

            a = get_assignment(args.assignment)
            if args.command == "grade":
                submission, visible_only, fmt = args.submission, args.visible_only, args.format
            else:
                submission = args.folder or str(Path("assignments") / a.id)
                visible_only, fmt = True, "gradescope"
            if not Path(submission).exists():
                parser.exit(2, "error: submission %s does not exist\n" % submission)
            log = (lambda line: print(line, flush=True)) if args.command == "check" else None
            out = args.out
            if args.command == "check" and out is None:
                out = str(Path("check-results") / a.short)
            result = grade(a, submission, out, fmt_name=fmt, visible_only=visible_only,
                           time_limit=args.time_limit, memory_mb=args.memory_mb, log=log,
                           require_sandbox=args.require_sandbox)
            print(result.summary())
            if args.command == "check":
                return 0 if result.score >= result.max_score - 1e-9 else 1
        elif args.command == "render":
            a = get_assignment(args.assignment)
            folder = args.folder or str(Path("assignments") / a.id)
            return _cmd_render(a, folder, args.out or str(Path("renders") / a.short), args.width, args.height)
        elif args.command == "grade-all":
            from .gradebook import grade_all

            a = get_assignment(args.assignment)
            if not Path(args.submissions).is_dir():
                parser.exit(2, "error: submissions folder %s does not exist\n" % args.submissions)
            path = grade_all(a, args.submissions, args.out, processes=args.processes,
                             time_limit=args.time_limit, memory_mb=args.memory_mb,
                             require_sandbox=args.require_sandbox,
                             log=lambda line: print(line, flush=True))
            print(path)
        elif args.command == "release":
            from .release import write_release

            reveal = tuple(r.strip() for r in args.reveal.split(",") if r.strip())
            for name in reveal:
                get_assignment(name)
            if Path(args.out).exists() and any(Path(args.out).iterdir()):
                parser.exit(2, "error: %s is not empty\n" % args.out)
            written = write_release(args.out, reveal)
            print("wrote a student release (%d files, revealed: %s) into %s"
                  % (len(written), ", ".join(reveal) or "none", args.out))
            if not args.no_gaps:
                from .release_gaps import release_gaps, report

                print("checking which visible tests students can pass in it with each assignment's own code "
                      "(--no-gaps skips this)", flush=True)
                for line in report(release_gaps(reveal)):
                    print(line)
        elif args.command == "autograder-zip":
            from .autograder import build_zip

            a = get_assignment(args.assignment)
            print(build_zip(a, args.out or str(Path("dist") / ("autograder-%s.zip" % a.id))))
    except ValueError as error:
        parser.exit(2, "error: %s\n" % error)
    return 0


if __name__ == "__main__":
    sys.exit(main())
