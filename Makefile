# Two commands on a fresh machine with Python 3.11 and make:
#   make run   - set up .venv and run the main job (sdt benchmark on the embedded default)
#   make test  - set up .venv with dev extras and run the whole test suite
PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: run test doccheck lint bench clean browser

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

# the sensor catalogue is a second distribution (plugins/sensors-catalog), installed beside.
# pip's output goes to $(LOG): an editable install prints setuptools' banners ("Please be
# careful with folders in your working directory...") that are noise on every `make run`.
# A failed install prints the whole log; a finished one still prints pip's ERROR lines.
LOG := $(VENV)/install.log
$(STAMP): pyproject.toml plugins/sensors-catalog/pyproject.toml | $(BIN)/python
	@echo "installing sdt-framework into $(VENV) (pip's output: $(LOG))"
	@$(BIN)/python -m pip install --quiet -e ".[dev]" -e plugins/sensors-catalog >$(LOG) 2>&1 \
		|| { cat $(LOG) >&2; echo "pip install failed (its output above, also in $(LOG))" >&2; exit 1; }
	@grep '^ERROR' $(LOG) >&2 || true
	@touch $(STAMP)

run: $(STAMP)
	$(BIN)/sdt benchmark

# both cores: one pytest-xdist worker each; a file stays on one worker, so its module
# fixtures (small benchmarks, results folders) are built once
test: $(STAMP) browser
	$(BIN)/python -m pytest -q -n 2 --dist loadfile

# the slow documented commands (full benchmarks, sweeps, calibrations) of README.md and docs/*.md
doccheck: $(STAMP)
	$(BIN)/python -m tools.doccheck --mode slow

# best effort, CI only: headless Chromium for the report's browser test (skipped without it)
browser:
	@if [ -n "$$CI" ] && ! command -v chromium >/dev/null && [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
		apt-get update -qq && apt-get install -y -qq chromium >/dev/null || echo "chromium not installed: browser test will be skipped"; \
	fi

bench: $(STAMP)
	for script in benchmarks/bench_*.py; do $(BIN)/python $$script || exit 1; done

lint: $(STAMP)
	$(BIN)/ruff check .
	$(BIN)/ruff format --check .

clean:
	rm -rf $(VENV) build *.egg-info
