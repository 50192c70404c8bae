# gyro: the two set-up commands of the README.
#   make demo   create .venv if needed, install gyro, solve every bundled problem
#   make test   the same set-up, then import layers, ruff, mypy and the test suite on
#               every core (pytest-xdist), but for the tests marked slow
#   make test-slow  the tests marked slow: the pages in Chromium, the package and docs
#               builds, the hooks' environments, the cold-start and import guards (fresh
#               interpreters), processes sent signals or given a broken HOME, the memory
#               guards of streaming (tracemalloc); CI (.ci/run)
#               runs make test, then make test-slow
#   make props  the property tests with long hypothesis budgets (EXAMPLES times the
#               default, default 10), on every core
#   make browser  the pages in Chromium with the contrast of every text (make test checks
#               one text of each style)
#   make handout  a solution sheet of every bundled problem, handout.pdf (needs pdflatex:
#               apt-get install texlive-latex-base texlive-latex-recommended
#               texlive-latex-extra poppler-utils; the test that compiles it skips without)
#   make fuzz   mutate the bundled problems for MINUTES (default 5), in-process
#   make examples  the example pages docs/examples/*.html (gyro solve --format html) and the
#               outputs stored in the example notebook docs/examples/gyro.ipynb
#   make docs   the documentation site: docs/ built into site/ by MkDocs in strict mode,
#               offline (any warning, a broken link or anchor, fails); open site/index.html
#   make dist   the sdist and wheel in dist/ (python -m build), checked by twine
#   make environment  pipes, signals, read-only HOME, FIFOs (docs/exit_codes.md): no root,
#               run in a temporary folder that is removed afterwards
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: demo test test-slow props browser check bench handout fuzz examples docs dist environment clean

MINUTES ?= 5
EXAMPLES ?= 10

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)

$(STAMP): $(BIN)/python pyproject.toml
	$(BIN)/python -m pip install --quiet --upgrade pip
	PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 $(BIN)/python -m pip install --quiet -e '.[dev]'
	$(BIN)/python -m compileall -q gyro_cli   # bytecode even where PYTHONDONTWRITEBYTECODE is set
	touch $(STAMP)

demo: $(STAMP)
	$(BIN)/gyro solve problems/*.yaml

# mypy (15 s on one core from a fresh clone) runs beside the tests rather than before them,
# its report printed after theirs; make test fails if either does. The tests run with plain
# asserts (rewriting the 3,800 asserts for pytest's messages cost each test process 6 s of
# its 12 s start); the tests that fail are run again, alone, with pytest's messages. The
# tests are compiled first (1.8 s of each test process's start where PYTHONDONTWRITEBYTECODE
# is set, as on the project's machine).
test: $(STAMP)
	$(BIN)/python -m compileall -q -j 0 tests fuzz   # each test process reads them compiled
	$(BIN)/lint-imports --no-cache
	$(BIN)/ruff check gyro_cli tests benchmarks fuzz
	@echo "$(BIN)/mypy gyro_cli  (beside the tests)"
	@$(BIN)/mypy gyro_cli > $(VENV)/mypy.log 2>&1 & typing=$$!; \
	  $(BIN)/python -m pytest -q -n auto --dist worksteal --assert=plain -m "not slow"; tests=$$?; \
	  if [ $$tests -ne 0 ]; then \
	    echo "make test: the failed tests again, with pytest's assertion messages"; \
	    $(BIN)/python -m pytest -q -m "not slow" --last-failed --last-failed-no-failures none; fi; \
	  wait $$typing; typed=$$?; cat $(VENV)/mypy.log; \
	  test $$tests -eq 0 -a $$typed -eq 0

# The tests make test leaves out (marked slow): each waits on another program (Chromium,
# pip and build, mkdocs, pre-commit, a notebook kernel), on fresh Python interpreters (the
# cold-start and import guards) or on a process it signals, or measures memory under
# tracemalloc (the streaming guards).
test-slow: $(STAMP)
	$(BIN)/python -m pytest -q -n auto --dist worksteal --assert=plain -m slow || \
	  { echo "make test-slow: the failed tests again, with pytest's assertion messages"; \
	    $(BIN)/python -m pytest -q -m slow --last-failed --last-failed-no-failures none; exit 1; }

props: $(STAMP)
	GYRO_EXAMPLES=$(EXAMPLES) $(BIN)/python -m pytest -q -n auto -m property

browser: $(STAMP)
	GYRO_BROWSER_SWEEP=1 $(BIN)/python -m pytest -q -n auto tests/test_browser.py tests/test_course_browser.py

check: $(STAMP)
	$(BIN)/lint-imports --no-cache
	$(BIN)/gyro check problems/

handout: $(STAMP)
	@command -v pdflatex >/dev/null || { echo "make handout needs pdflatex: apt-get install texlive-latex-base texlive-latex-recommended texlive-latex-extra poppler-utils"; exit 2; }
	$(BIN)/gyro solve --format latex --standalone problems/*.yaml > handout.tex
	pdflatex -interaction=nonstopmode -halt-on-error handout.tex > /dev/null
	@! grep -n "Overfull" handout.log
	@echo "handout.pdf written"
	$(BIN)/python -m pytest -q tests/test_handout.py

bench: $(STAMP)
	$(BIN)/python benchmarks/bench_solve.py
	$(BIN)/python benchmarks/bench_check.py
	$(BIN)/python benchmarks/bench_simulate.py
	$(BIN)/python benchmarks/bench_motion.py
	$(BIN)/python benchmarks/bench_animate.py
	$(BIN)/python benchmarks/bench_render.py --passes 5

examples: $(STAMP)
	$(BIN)/gyro solve --format html problems/11_3.yaml > docs/examples/11_3.html
	$(BIN)/gyro solve --format html problems/11_2_released_top.yaml > docs/examples/11_2_released_top.html
	env -u MPLBACKEND $(BIN)/python -c "import nbclient, nbformat; p = 'docs/examples/gyro.ipynb'; \
	  nb = nbformat.read(p, 4); nbclient.NotebookClient(nb, timeout=120, record_timing=False, \
	  resources={'metadata': {'path': 'docs/examples'}}).execute(); nbformat.write(nb, p)"

docs: $(STAMP)
	$(BIN)/mkdocs build --strict --site-dir site

dist: $(STAMP)
	rm -rf dist
	$(BIN)/python -m build --outdir dist .
	$(BIN)/twine check --strict dist/*

fuzz: $(STAMP)
	nice $(BIN)/python fuzz/fuzz.py --minutes $(MINUTES)

environment: $(STAMP)
	@tmp=$$(mktemp -d) && \
	TMPDIR=$$tmp GYRO_CACHE_DIR=$$tmp/cache $(BIN)/python -m pytest -q -p no:cacheprovider \
		--basetemp=$$tmp/pytest tests/test_environment.py; status=$$?; \
	rm -rf $$tmp; exit $$status

clean:
	rm -rf $(VENV) build dist site *.egg-info .pytest_cache handout.tex handout.aux handout.log handout.pdf
