"""The Gradescope autograder bundle: ``setup.sh`` and ``run_autograder`` at the zip root, the
package (with the grader's reference files) beside them.

Gradescope unpacks the zip into /autograder/source, runs setup.sh once per image, and runs
run_autograder in a fresh container per submission, with the student's upload in
/autograder/submission; results go to /autograder/results/results.json. The root and the
Python are taken from AUTOGRADER_ROOT and AUTOGRADER_PYTHON if set, so the same bundle runs
in a test folder laid out the same way.
"""
from __future__ import annotations

import os
import zipfile
from pathlib import Path

from .generate import PACKAGE_DIR

SETUP_SH = """#!/usr/bin/env bash
# Gradescope runs this once when it builds the autograder image (Ubuntu). bubblewrap is the
# sandbox student code runs in (rtfgu/grading/sandbox.py); where the container forbids the
# namespaces it needs, the grader falls back to a weaker isolation and says which in the result.
set -euo pipefail
apt-get update
apt-get install -y python3 python3-pip python3-venv bubblewrap%(packages)s
python3 -m venv /autograder/venv
/autograder/venv/bin/pip install 'numpy>=1.24' 'Pillow>=10'%(extra)s
"""

# What wgpu needs to find Mesa's software adapter (llvmpipe through lavapipe or EGL).
MESA_PACKAGES = ("libgl1-mesa-dri", "libegl1", "mesa-vulkan-drivers")

RUN_AUTOGRADER = """#!/usr/bin/env bash
# Gradescope runs this once per submission. AUTOGRADER_ROOT and AUTOGRADER_PYTHON override
# the grader machine's layout (/autograder/{source,submission,results}) for local runs.
set -uo pipefail
ROOT="${AUTOGRADER_ROOT:-/autograder}"
PY="${AUTOGRADER_PYTHON:-$ROOT/venv/bin/python}"
test -x "$PY" || PY=python3
mkdir -p "$ROOT/results"
cd "$ROOT/source"
if command -v bwrap >/dev/null 2>&1; then
    echo "bubblewrap: $(command -v bwrap) (used where this container allows user namespaces)"
else
    echo "bubblewrap is not installed (Debian package bubblewrap): a weaker isolation is used"
fi
# The grade command prints which isolation ran ("student code ran isolated by: ...") and
# records it in results.json (extra_data.isolation).
PYTHONPATH="$ROOT/source" "$PY" -m rtfgu.grading grade %(assignment)s "$ROOT/submission" \\
    --out "$ROOT/results" --time-limit "${AUTOGRADER_TIME_LIMIT:-%(time_limit)g}"
status=$?
if [ ! -s "$ROOT/results/results.json" ]; then
    # The grader itself failed: tell the student and staff rather than leave no result.
    printf '{"score": 0, "execution_time": 0, "output": "The autograder failed (exit %%s); please tell the course staff.", "tests": []}\\n' "$status" > "$ROOT/results/results.json"
fi
exit 0
"""


def _package_files():
    for path in sorted(PACKAGE_DIR.rglob("*")):
        if path.is_file() and "__pycache__" not in path.parts and not path.name.endswith((".pyc", ".nbi", ".nbc")):
            yield path, "rtfgu/" + path.relative_to(PACKAGE_DIR).as_posix()


def build_zip(assignment, out) -> Path:
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    wgsl = assignment.language == "wgsl"
    extra = " 'wgpu>=0.19'" if wgsl else ""
    packages = "".join(" " + name for name in MESA_PACKAGES) if wgsl else ""

    def add_script(z, name, text):
        info = zipfile.ZipInfo(name, date_time=(2024, 1, 1, 0, 0, 0))
        info.external_attr = 0o755 << 16
        z.writestr(info, text)

    # The bundle holds the solutions and the references: its writer's alone (0600 from the
    # start), so that no sandbox user running a student's code can read it.
    fd = os.open(out, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
    os.fchmod(fd, 0o600)
    with os.fdopen(fd, "wb") as f, zipfile.ZipFile(f, "w", zipfile.ZIP_DEFLATED) as z:
        add_script(z, "setup.sh", SETUP_SH % {"extra": extra, "packages": packages})
        add_script(z, "run_autograder", RUN_AUTOGRADER % {"assignment": assignment.id,
                                                          "time_limit": assignment.time_limit})
        for path, name in _package_files():
            z.write(path, name)
    return out
