"""Package conventions: one version everywhere, ``python -m epicyclic``, ``py.typed``, metadata."""

from __future__ import annotations

import re
import subprocess
import sys
import tomllib
from importlib import metadata
from pathlib import Path

import epicyclic

ROOT = Path(__file__).resolve().parents[1]


def test_version_is_single_sourced():
    # pyproject.toml reads the version from epicyclic.__version__ (dynamic), the installed
    # metadata carries it, and CHANGELOG.md has a section for it.
    assert re.fullmatch(r"\d+\.\d+\.\d+(?:[ab]\d+|rc\d+|\.dev\d+)?", epicyclic.__version__)
    assert metadata.version("epicyclic") == epicyclic.__version__
    pyproject = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    assert "version" in pyproject["project"]["dynamic"] and "version" not in pyproject["project"]
    assert pyproject["tool"]["setuptools"]["dynamic"]["version"] == {"attr": "epicyclic.__version__"}
    changelog = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    assert f"## [{epicyclic.__version__}]" in changelog
    assert "## [Unreleased]" in changelog


def test_python_dash_m_epicyclic_is_the_command():
    done = subprocess.run([sys.executable, "-m", "epicyclic", "--version"], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == f"epicyclic {epicyclic.__version__}"
    done = subprocess.run([sys.executable, "-m", "epicyclic", "modes", "--sun", "30", "--ring", "78"],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert "-2.6" in done.stdout  # i0 = -78/30


def test_package_ships_its_type_hints():
    # PEP 561: the marker file sits in the installed package and is listed as package data.
    assert (Path(epicyclic.__file__).parent / "py.typed").is_file()
    assert '"py.typed"' in (ROOT / "pyproject.toml").read_text(encoding="utf-8")


def test_metadata_names_authors_keywords_and_classifiers():
    meta = metadata.metadata("epicyclic")
    assert meta["Author"] or meta["Author-email"]
    assert "planetary gear" in meta["Keywords"]
    classifiers = meta.get_all("Classifier")
    assert "Typing :: Typed" in classifiers
    assert "Topic :: Scientific/Engineering" in classifiers
    assert any(c.startswith("Programming Language :: Python :: 3.11") for c in classifiers)
    assert meta["License-Expression"] == "MIT"
