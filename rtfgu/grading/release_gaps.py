"""Which visible tests a student cannot pass in a release by the assignment's own code alone.

A test runs more than its assignment's functions: a09's furnace renders with a03's shapes and
a04's Matte; a06's image needs WGSL pieces that a release carries only once an earlier
assignment is revealed (rtfgu.grading.release). In a release those are stubs or absent, so the
student sees the test fail until they have written the earlier assignments, while the grader
runs it with their solutions. ``release_gaps(reveal)`` finds these tests by running them: for
each assignment the release does not reveal, the release's own package with that assignment's
solution written in, the visible tests run by the student checker (rtfgu.grading.local); a
test that stops at another assignment's stub gets that assignment's solution too and runs
again, until it passes or stops at a missing file. ``make release`` prints what it finds.
"""
from __future__ import annotations

import re
import shutil
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from .assignments import ASSIGNMENTS, get_assignment
from .local import OTHER_STUB as STUB, check

LEFT_OUT = re.compile(r"rtfgu/([\w/]+\.(?:py|wgsl)) is not part of this release")


@dataclass
class Gap:
    assignment: str           # the assignment's short id
    test: str                 # the test's number, e.g. "9.4"
    points: float
    needs: list = field(default_factory=list)     # other assignments whose functions it runs
    left_out: list = field(default_factory=list)  # files of the package the release leaves out
    failure: str = ""         # the message, when it fails even with those written

    def describe(self) -> str:
        why = []
        if self.needs:
            why.append("runs %s" % ", ".join(self.needs))
        if self.left_out:
            why.append("needs %s, left out of this release until %s %s revealed" % (
                ", ".join("rtfgu/" + f for f, _ in self.left_out),
                ", ".join(sorted({a for _, owners in self.left_out for a in owners})),
                "is" if len({a for _, o in self.left_out for a in o}) == 1 else "are"))
        if self.failure:
            why.append("fails with the solution: " + self.failure[:200])
        return "%s (%g points): %s" % (self.test, self.points, "; ".join(why))


def _solve(root: Path, numbers: set) -> None:
    """Write the files of the assignments numbered ``numbers`` into the release at ``root``,
    with exactly those assignments' blocks solved (and the release's revealed ones): what a
    student who has written them has. Twins are not added: the release keeps what it carries."""
    from .generate import source_text, transform

    files = {f for a in ASSIGNMENTS.values() if a.number in numbers for f in a.files}
    for relpath in sorted(files):
        target = root / "rtfgu" / relpath
        target.write_text(transform(source_text(relpath), relpath, None, revealed=numbers))


def release_gaps(reveal=(), assignments=None, log=None) -> list:
    """The Gaps of a release revealing ``reveal``, for ``assignments`` (default: every
    assignment it does not reveal)."""
    from .checks import checks_for
    from .release import revealed_numbers, solves, write_release

    revealed = revealed_numbers(reveal)
    chosen = [get_assignment(a) for a in assignments] if assignments is not None else \
        [a for a in ASSIGNMENTS.values() if a.number not in revealed]
    gaps = []
    with tempfile.TemporaryDirectory(prefix="rtfgu-release-gaps-") as tmp:
        pristine = Path(tmp) / "release"
        write_release(pristine, reveal)
        for a in chosen:
            if log:
                log("running %s's visible tests in the release with %s written" % (a.short, a.short))
            root = Path(tmp) / a.short
            shutil.copytree(pristine, root)
            _solve(root, revealed | {a.number})
            result = check(a, root)
            for test in result.tests:
                if test.score >= test.max_score:
                    continue
                c = next(c for c in checks_for(a.id) if c.number == test.number)
                gap, output = Gap(a.short, test.number, test.max_score), test.output
                for _ in range(len(ASSIGNMENTS)):
                    stub, left_out = STUB.search(output), LEFT_OUT.search(output)
                    if stub and stub.group(1) != a.short and stub.group(1) not in gap.needs:
                        gap.needs.append(stub.group(1))
                        _solve(root, revealed | {a.number} | {get_assignment(n).number for n in gap.needs})
                    elif left_out:
                        relpath = left_out.group(1)
                        text = (Path(__file__).resolve().parent.parent / relpath).read_text()
                        owners = sorted("a%02d" % n for n in solves(text) - revealed)
                        gap.left_out.append((relpath, owners))
                        break
                    else:
                        gap.failure = output.strip().splitlines()[0] if output.strip() else "no message"
                        break
                    again = check(a, root, only=(c.slug,)).tests[0]
                    if again.score >= again.max_score:
                        break
                    output = again.output
                gap.needs.sort()
                gaps.append(gap)
                _solve(root, revealed | {a.number})      # the next test starts from the assignment alone
    return gaps


def report(gaps, reveal=()) -> list:
    """The lines ``make release`` prints: per assignment, its tests a student cannot pass with
    that assignment's code alone, and why."""
    from .checks import checks_for

    lines = []
    for short in sorted({g.assignment for g in gaps}):
        mine = [g for g in gaps if g.assignment == short]
        visible = [c for c in checks_for(short) if c.visibility == "visible"]
        lines.append("warning: %s: %d of its %d visible tests (%g of %g points) cannot pass in this release with "
                     "%s's code alone; they pass once the student has written what they run (the grader runs "
                     "them with the solutions):" % (short, len(mine), len(visible), sum(g.points for g in mine),
                                                    sum(c.weight for c in visible), short))
        lines += ["  " + g.describe() for g in mine]
    return lines
