# The README's two commands: `make demo` and `make test`.
# Both create a local virtual environment (.venv) with Python 3.11 on first use.
PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV   ?= .venv
PY      = $(VENV)/bin/python
STAMP   = $(VENV)/.installed

.PHONY: demo test bench docs docs-serve gallery clean chromium

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[test]'
	$(PY) -m compileall -q src  # bytecode, as pip writes it for an installed package (PYTHONDONTWRITEBYTECODE may be set)
	touch $(STAMP)

demo: $(STAMP)
	$(VENV)/bin/epicyclic analyze examples/brandenberger_1952.toml
	$(VENV)/bin/epicyclic analyze examples/brandenberger_1952.toml --format html --out out/brandenberger_1952.html

test: $(STAMP) chromium
	$(PY) -m pytest -q src tests

# The documentation site (mkdocs.yml) into site/; warnings are errors (strict).
docs: $(STAMP)
	NO_MKDOCS_2_WARNING=1 DISABLE_MKDOCS_2_WARNING=true $(VENV)/bin/mkdocs build --strict

# The built site on http://127.0.0.1:8001/ (it also opens from the file system: site/index.html).
docs-serve: docs
	$(PY) -m http.server --bind 127.0.0.1 --directory site 8001

# Every example × every kind of picture into docs/gallery/ and docs/gallery.md; the figures of docs/plotting.md.
gallery: $(STAMP)
	$(PY) docs/gallery/make_gallery.py
	$(PY) docs/figures/make_figures.py
	$(PY) docs/figures/make_screenshots.py

# The browser tests (tests/web/test_browser.py) drive Debian's chromium through chromium-driver:
# install both when missing (CI runs on a fresh Debian machine as root); nothing to do when present.
chromium:
	@if [ -x /usr/bin/chromium ] && [ -x /usr/bin/chromedriver ]; then :; \
	elif command -v apt-get >/dev/null 2>&1; then \
	  SUDO=$$([ "$$(id -u)" = 0 ] || echo sudo); \
	  echo "installing chromium and chromium-driver for the browser tests (apt-get)"; \
	  $$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq chromium chromium-driver; \
	else echo "chromium and chromium-driver are missing and there is no apt-get: browser tests will be skipped" >&2; fi

bench: $(STAMP)
	for b in benchmarks/bench_*.py; do $(PY) $$b || exit 1; done

clean:
	rm -rf $(VENV) build site *.egg-info src/*.egg-info .pytest_cache .hypothesis
