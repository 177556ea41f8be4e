# The README's two commands: `make demo` and `make test`.
# Both create a local virtual environment (.venv) with Python 3.11 on first use.
PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV   ?= .venv
PY      = $(VENV)/bin/python
STAMP   = $(VENV)/.installed

.PHONY: demo test bench gallery clean

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[test]'
	touch $(STAMP)

demo: $(STAMP)
	$(VENV)/bin/epicyclic analyze examples/brandenberger_1952.toml
	$(VENV)/bin/epicyclic analyze examples/brandenberger_1952.toml --format html --out out/brandenberger_1952.html

test: $(STAMP)
	$(PY) -m pytest -q src tests

# Every example × every kind of picture into docs/gallery/ and docs/gallery.md; the figures of docs/plotting.md.
gallery: $(STAMP)
	$(PY) docs/gallery/make_gallery.py
	$(PY) docs/figures/make_figures.py

bench: $(STAMP)
	for b in benchmarks/bench_*.py; do $(PY) $$b || exit 1; done

clean:
	rm -rf $(VENV) build *.egg-info src/*.egg-info .pytest_cache .hypothesis
