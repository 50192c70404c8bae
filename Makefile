# gyro: the two set-up commands of the README.
#   make demo   create .venv if needed, install gyro, solve every bundled problem
#   make test   the same set-up, then the test suite
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: demo test check bench clean

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)

$(STAMP): $(BIN)/python pyproject.toml
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[dev]'
	touch $(STAMP)

demo: $(STAMP)
	$(BIN)/gyro solve problems/*.yaml

test: $(STAMP)
	$(BIN)/lint-imports --no-cache
	$(BIN)/python -m pytest -q

check: $(STAMP)
	$(BIN)/lint-imports --no-cache
	$(BIN)/gyro check problems/

bench: $(STAMP)
	$(BIN)/python benchmarks/bench_solve.py
	$(BIN)/python benchmarks/bench_check.py
	$(BIN)/python benchmarks/bench_simulate.py
	$(BIN)/python benchmarks/bench_motion.py

clean:
	rm -rf $(VENV) build *.egg-info .pytest_cache
