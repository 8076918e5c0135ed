# bearingload: every target creates its own environment (.venv) from pyproject.toml.
# The package is installed editable in compat mode (a path entry, no import hook) and compiled
# to bytecode once, so a terminal calculation starts fast even where PYTHONDONTWRITEBYTECODE is set.
# The install builds the compiled core (bearingload/models/_core.pyx, with Cython from PyPI, in
# place); a change of a kernel source or of the build makes the next target build it again.
PY ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
CORE := setup.py bearingload/models/_core.pyx bearingload/models/_core.pxd \
	bearingload/models/_radial.pxi bearingload/_elliptic.pyx bearingload/_elliptic.pxd

.PHONY: run test lint tables golden docs bench checked core clean

$(STAMP): pyproject.toml $(CORE)
	test -x $(BIN)/python || $(PY) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test,plot]' --config-settings editable_mode=compat \
		|| $(BIN)/python -m pip install --quiet -e '.[test,plot]'  # a setuptools without compat mode
	$(BIN)/python -m compileall -q bearingload
	touch $(STAMP)

## make run: set up, regenerate tables/, print a worked example (bearing 306 of Kuzmenko 2010)
run: $(STAMP)
	$(BIN)/bearingload tables update tables
	$(BIN)/bearingload solve --balls 8 --load 300kgf --stiffness 4700kgf/mm^1.5 --clearance 20um
	$(BIN)/bearingload table k --z-max 12

## make test: set up, lint (ruff, mypy), run the whole test suite
test: $(STAMP) lint
	$(BIN)/python -m pytest

lint: $(STAMP)
	$(BIN)/ruff check bearingload tests benchmarks
	$(BIN)/ruff format --check bearingload tests benchmarks
	$(BIN)/mypy bearingload

## make tables: rewrite every file of tables/ whose text differs from its command in
## tables/manifest.toml (bearingload tables update --exact), the example folder examples/tables
## and the errata block of docs/errata.md
tables: $(STAMP)
	$(BIN)/bearingload tables update --exact tables
	$(BIN)/bearingload tables update --exact examples/tables
	$(BIN)/python -m bearingload.reports.committed docs/errata.md

## make golden: rewrite the stored CLI outputs (tests/golden/), the console examples of README.md
## and docs/, and the command-line reference docs/cli.md (from every command's --help)
golden: $(STAMP)
	$(BIN)/python -m tests.golden_outputs

## make docs: everything generated in README.md and docs/ (make tables, then make golden)
docs: tables golden

## make bench: vectorised solver against a per-case scipy brentq loop, one call against scipy root
## (hybr) and the Hertz contact against brentq on the ellipticity equation, ring_forces against a
## per-evaluation Python loop, bearingload batch on 10^5 csv cases against the brentq loop, the
## start-up of solve and table k against python -c 'import numpy': ratios,
## each in one run; the work-precision report (times of this run) and the full stability grid
bench: $(STAMP)
	$(BIN)/python -m compileall -q bearingload
	$(BIN)/python benchmarks/bench_solver.py
	$(BIN)/python benchmarks/bench_scalar.py
	$(BIN)/python benchmarks/bench_methods.py
	$(BIN)/python benchmarks/bench_forces.py
	$(BIN)/python benchmarks/bench_combined.py
	$(BIN)/python benchmarks/bench_angular.py
	$(BIN)/python benchmarks/bench_pair.py
	$(BIN)/python benchmarks/bench_speed.py
	$(BIN)/python benchmarks/bench_combined_sweep.py
	$(BIN)/python benchmarks/bench_batch.py
	$(BIN)/python benchmarks/bench_startup.py
	$(BIN)/bearingload accuracy
	$(BIN)/bearingload stability --size full

## make checked: the compiled core rebuilt with bounds checks, AddressSanitizer and
## UndefinedBehaviorSanitizer (for the campaigns: see docs/architecture.md); make core undoes it
checked: $(STAMP)
	BEARINGLOAD_CHECKED=1 $(BIN)/python -m pip install --quiet -e . --no-deps \
		--config-settings editable_mode=compat

core: $(STAMP)
	$(BIN)/python -m pip install --quiet -e . --no-deps --config-settings editable_mode=compat

clean:
	rm -rf $(VENV) build *.egg-info .pytest_cache .mypy_cache .ruff_cache .hypothesis
	rm -f bearingload/models/_core.c bearingload/models/_core.*.so bearingload/_elliptic.c \
		bearingload/_elliptic.*.so
