# rtfgu: two commands on a fresh machine, `make render` and `make test`.
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed

.PHONY: render test venv clean bench

# Create the virtual environment and install the package (editable) with its test extras.
# The stamp depends on setup.cfg, so a second run reinstalls nothing unless it changed.
$(STAMP): setup.cfg pyproject.toml
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[test]'
	touch $(STAMP)

venv: $(STAMP)

render: $(STAMP)
	$(PY) -m rtfgu render-all --backend numba --out renders

# The benchmark (not a test): prints the table and writes docs/bench.md.
bench: $(STAMP)
	$(PY) -m pip install --quiet -e '.[test,bench]'
	$(PY) benchmarks/bench.py

test: $(STAMP)
	$(PY) -m pytest

clean:
	rm -rf $(VENV) renders
