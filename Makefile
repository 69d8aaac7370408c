# Quick start:  make demo       (results and figures under runs/demo)
#               make test       (the whole test suite, on every core)
#               make test-fast  (the tests not marked slow: about a minute, every package)
PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: demo test test-fast bench venv clean browser test-py313

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

# the LMGC90 engine (extra 'lmgc90') without the GUI stack its package declares: the solver run
# imports only its compiled module (45 MB instead of ~1.1 GB; docs/engines.md#11-lmgc90)
$(STAMP): $(BIN)/python pyproject.toml
	$(BIN)/python -m pip install --quiet -e '.[all,test]'
	$(BIN)/python -m pip install --quiet --no-deps 'compas_lmgc90>=0.1.11,<0.2'
	touch $(STAMP)

venv: $(STAMP)

demo: $(STAMP)
	$(BIN)/archdem campaign --quick --out runs/demo

# one pytest worker per core (pytest-xdist); worksteal hands a finished worker the queued tests of a
# busy one, so the minutes-long campaign tests do not leave a core idle at the end
XDIST := -n auto --dist worksteal

test: $(STAMP) browser
	$(BIN)/python -m pytest -q $(XDIST)

test-fast: $(STAMP)
	$(BIN)/python -m pytest -q $(XDIST) -m "not slow"

# The report test renders the campaign report in headless Chromium (Debian's package);
# installed here when possible, otherwise that one test is skipped with the reason.
browser:
	@if ! command -v chromium >/dev/null 2>&1; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then \
	    echo "installing Debian's chromium for the report browser test"; \
	    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium >/dev/null) \
	      || echo "chromium could not be installed: the browser test will be skipped"; \
	  else echo "no chromium and no root apt-get: the browser test will be skipped"; fi; \
	fi

bench: $(STAMP)
	$(BIN)/python benchmarks/run_all.py

clean:
	rm -rf $(VENV) build *.egg-info

# Python 3.13 on Debian 13, as root (.ci/debian13: a debootstrapped root, made once then reused):
# the tests of PY313_TESTS there, then the quick campaign's catalogue, tilt, shake and map tables
# of one specimen on 3.13 and on this venv's Python, compared cell by cell (.ci/same_tables.py).
PY313_TESTS  ?= tests/specimens tests/analytic tests/dem/core tests/dem/campaign tests/dem/cli \
                tests/dem/experiments/tilt/test_run.py tests/test_readme.py
SAME_NUMBERS ?= --quick --specimens Sh02-Sd020 --steps catalogue,tilt,shake,map
SAME_DIR     := runs/same-numbers

test-py313: $(STAMP)
	.ci/debian13 python -m pytest -q -p no:cacheprovider $(PY313_TESTS)
	rm -rf $(SAME_DIR)
	.ci/debian13 archdem campaign $(SAME_NUMBERS) --out $(SAME_DIR)/py313
	nice -n 5 $(BIN)/archdem campaign $(SAME_NUMBERS) --out $(SAME_DIR)/host
	$(BIN)/python .ci/same_tables.py $(SAME_DIR)/host $(SAME_DIR)/py313
