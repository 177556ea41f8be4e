"""The documentation site builds with warnings as errors, and its generated pages are complete."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def site(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("site")
    env = {**os.environ, "NO_MKDOCS_2_WARNING": "1", "DISABLE_MKDOCS_2_WARNING": "true"}
    done = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "--site-dir", str(out)],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, f"mkdocs build --strict failed:\n{done.stdout[-4000:]}\n{done.stderr[-4000:]}"
    assert "WARNING" not in done.stderr, done.stderr[-4000:]
    return out


def page(site: Path, name: str) -> str:
    return (site / name / "index.html").read_text(encoding="utf-8")


def test_cli_reference_is_generated_from_every_command(site):
    from typer.main import get_command

    from epicyclic.cli.main import app

    text = page(site, "reference/cli")
    for command in get_command(app).commands:  # type: ignore[attr-defined]
        assert f"epicyclic {command}" in text, f"command {command!r} missing from the CLI reference"
    assert "--format" in text and "--version" in text


def test_api_reference_renders_the_docstrings(site):
    text = page(site, "reference/api/epicyclic.solver")
    assert "Brandenberger" in text and "Parameters" in text
    model = page(site, "reference/api/epicyclic.model")
    assert "PlanetarySet" in model and "stationary_ratio" in model
    assert ":func:`" not in model and ":class:`" not in model  # roles rewritten (docs/griffe_rst.py)


def test_validation_page_lists_every_case_with_what_we_get(site):
    from published_cases import groups

    text = page(site, "validation")
    everything = groups()
    for group in everything:
        assert group.title.split(":")[0].replace("'", "&#39;")[:30] in text.replace("&rsquo;", "'") or \
            group.title[:20] in text
    assert f"{sum(len(g.cases) for g in everything)} cases" in text


def test_existing_pages_are_site_pages(site):
    for name in ("theory", "file-format", "performance", "plotting", "geometry", "transmissions", "changelog"):
        assert (site / name / "index.html").is_file(), name
    assert "Keep a Changelog" in page(site, "changelog")
