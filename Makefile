# rtfgu: two commands on a fresh machine, `make render` and `make test`.
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed

.PHONY: render test venv clean bench montage assignments check grade grade-all autograder-zip

# Create the virtual environment and install the package (editable) with its test extras.
# The stamp depends on setup.cfg, so a second run reinstalls nothing unless it changed.
$(STAMP): setup.cfg pyproject.toml
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[test]'
	touch $(STAMP)

venv: $(STAMP)

render: $(STAMP)
	$(if $(A),$(PY) -m rtfgu.grading render $(A),$(PY) -m rtfgu render-all --backend numba --out renders)

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
	$(PY) -m rtfgu.montage docs/homework_renders.png

test: $(STAMP)
	$(PY) -m pytest

clean:
	rm -rf $(VENV) renders

# Assignments and the autograder (rtfgu/grading). A is an assignment id (a03 or
# a03_intersections); `make render A=a03` renders that assignment's images with the
# student's files in assignments/.
assignments: $(STAMP)
	$(PY) -m rtfgu.grading generate --out assignments

check: $(STAMP)
	$(PY) -m rtfgu.grading check $(A)

grade: $(STAMP)
	$(PY) -m rtfgu.grading grade $(A) $(SUBMISSION) --out $(or $(OUT),grading-results/$(A)/$(notdir $(patsubst %/,%,$(SUBMISSION))))

grade-all: $(STAMP)
	$(PY) -m rtfgu.grading grade-all $(A) $(SUBMISSIONS) --out $(or $(OUT),grading-results/$(A))

autograder-zip: $(STAMP)
	$(PY) -m rtfgu.grading autograder-zip $(A)
