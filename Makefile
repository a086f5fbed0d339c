# rtfgu: two commands on a fresh machine, `make render` and `make test`.
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed

.PHONY: render html test venv clean bench montage assignments check grade grade-all autograder-zip release

# Create the virtual environment and install the package (editable) with its test extras.
# The stamp depends on setup.cfg, so a second run reinstalls nothing unless it changed.
# pip's and setuptools' chatter goes to .venv/install.log, shown only if the install fails.
$(STAMP): setup.cfg pyproject.toml
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	@echo "installing rtfgu and what it needs into $(VENV) (log: $(VENV)/install.log)"
	@{ $(PY) -m pip install --quiet --upgrade pip && $(PY) -m pip install --quiet -e '.[test]'; } \
	  > $(VENV)/install.log 2>&1 || { cat $(VENV)/install.log; exit 1; }
	touch $(STAMP)

# bubblewrap isolates the grader's student code (rtfgu/grading/sandbox.py). Where it is not
# installed (Debian package bubblewrap) and apt-get can download it, its binary is unpacked
# into .venv/sandbox; without it the grader falls back to weaker isolation and says so.
SANDBOX_STAMP := $(VENV)/.sandbox
$(SANDBOX_STAMP): $(STAMP)
	@if command -v bwrap >/dev/null 2>&1; then echo "bubblewrap: $$(command -v bwrap)"; \
	elif command -v apt-get >/dev/null 2>&1 && command -v dpkg-deb >/dev/null 2>&1; then \
	  rm -rf $(VENV)/sandbox-download && mkdir -p $(VENV)/sandbox-download && \
	  (cd $(VENV)/sandbox-download && { apt-get download bubblewrap >/dev/null 2>&1 || \
	    { test "$$(id -u)" = 0 && apt-get update -qq >/dev/null 2>&1 && apt-get download bubblewrap >/dev/null 2>&1; }; }) && \
	  dpkg-deb -x $(VENV)/sandbox-download/bubblewrap_*.deb $(VENV)/sandbox && \
	  echo "bubblewrap: $(VENV)/sandbox/usr/bin/bwrap" || \
	  echo "bubblewrap could not be downloaded (Debian package bubblewrap): the grader will use a weaker sandbox"; \
	  rm -rf $(VENV)/sandbox-download; \
	else echo "bubblewrap not found (Debian package bubblewrap): the grader will use a weaker sandbox"; fi
	touch $(SANDBOX_STAMP)

venv: $(STAMP) $(SANDBOX_STAMP)

render: $(STAMP) $(SANDBOX_STAMP)
	$(if $(A),$(PY) -m rtfgu.grading render $(A) $(if $(W),--width $(W)) $(if $(H),--height $(H)),$(PY) -m rtfgu render-all --backend numba --out renders)

# Every homework scene as a self-contained WebGPU page (rtfgu/browser): open html/index.html
# in a browser with WebGPU.
html: $(STAMP)
	$(PY) -m rtfgu export-html-all --out html

# The benchmark (not a test): prints the table and writes docs/bench.md and its plot.
# The bench extra (matplotlib) is installed once, through its own stamp.
BENCH_STAMP := $(VENV)/.installed-bench
$(BENCH_STAMP): $(STAMP) setup.cfg
	$(PY) -m pip install --quiet -e '.[test,bench]'
	touch $(BENCH_STAMP)

bench: $(BENCH_STAMP)
	$(PY) benchmarks/bench.py $(BENCH_ARGS)

# The contact sheet shown in the README.
montage: $(STAMP)
	$(PY) -m rtfgu.montage docs/homework_renders.png docs/samplers.png

# One pytest worker per core (pytest-xdist): most of a cold run is numba compiling kernels,
# one process at a time; a test file stays on one worker, in its order (files that compile
# the same kernels share one: SAME_WORKER in tests/conftest.py).
test: $(STAMP) $(SANDBOX_STAMP)
	$(PY) -m pytest -n auto --dist loadfile --durations=15

clean:
	rm -rf $(VENV) renders html

# Assignments and the autograder (rtfgu/grading). A is an assignment id (a03 or
# a03_intersections); `make render A=a03` renders that assignment's images with the
# student's files in assignments/.
assignments: $(STAMP)
	$(PY) -m rtfgu.grading generate --out assignments

check: $(STAMP) $(SANDBOX_STAMP)
	$(PY) -m rtfgu.grading check $(A)

grade: $(STAMP) $(SANDBOX_STAMP)
	$(PY) -m rtfgu.grading grade $(A) $(SUBMISSION) --out $(or $(OUT),grading-results/$(A)/$(notdir $(patsubst %/,%,$(SUBMISSION))))

grade-all: $(STAMP) $(SANDBOX_STAMP)
	$(PY) -m rtfgu.grading grade-all $(A) $(SUBMISSIONS) --out $(or $(OUT),grading-results/$(A))

autograder-zip: $(STAMP) $(SANDBOX_STAMP)
	$(PY) -m rtfgu.grading autograder-zip $(A)

# A student repository without any solution: `make release OUT=DIR [REVEAL=a01,a02]`.
release: $(STAMP)
	$(PY) -m rtfgu.grading release $(OUT) $(if $(REVEAL),--reveal $(REVEAL))
