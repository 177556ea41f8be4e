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
    return (site / f"{name}.html").read_text(encoding="utf-8")


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
        assert (site / f"{name}.html").is_file(), name
    assert "Keep a Changelog" in page(site, "changelog")


def test_the_site_loads_nothing_from_elsewhere(site):
    """Offline: no script, style sheet or font from a CDN on any page (KaTeX is vendored, fonts are the system's)."""
    import re

    external = re.compile(r"""<(?:script|link|img)\b[^>]*\b(?:src|href)=["'](?:https?:)?//""", re.IGNORECASE)
    pages = list(site.rglob("*.html"))
    assert len(pages) > 20
    for path in pages:
        text = re.sub(r'<link rel="canonical"[^>]*>', "", path.read_text(encoding="utf-8"))  # an address, no load
        found = external.findall(text)
        assert not found, f"{path.relative_to(site)} loads from elsewhere: {found[:3]}"
    for css in site.rglob("*.css"):
        assert "fonts.googleapis" not in css.read_text(encoding="utf-8"), css
    assert (site / "vendor" / "katex" / "katex.min.js").is_file()
    assert "katex.min.js" in page(site, "theory")


def test_the_site_opens_from_the_file_system(site):
    """Pages are name.html and link to name.html (no directory index a file:// browser cannot open);
    the search index is inlined by the offline plugin."""
    import re

    text = page(site, "index")
    links = re.findall(r'href="([^"#:]+)"', text)
    local = [link for link in links if not link.startswith(("//", "mailto"))]
    assert local and all(not link.endswith("/") for link in local), [x for x in local if x.endswith("/")][:5]
    assert (site / "search" / "search_index.js").is_file()


def test_theory_and_losses_are_typeset_math_and_no_navigation_file_is_a_page(site):
    theory = page(site, "theory")
    assert theory.count('class="arithmatex"') >= 15
    assert r"\eta_0" in theory
    assert not (site / "reference" / "api" / "SUMMARY.html").exists()
    losses = page(site, "losses")
    assert losses.count('class="arithmatex"') >= 9 and r"H_V = \frac" in losses  # Ohlendorf's H_V and the rest


def test_tutorials_show_the_output_of_their_commands(site):
    """docs/hooks.py runs every shell block of a tutorial at build time and shows what it printed."""
    brandenberger = page(site, "tutorials/brandenberger")
    assert "Output (run when this page was built)" in brandenberger
    assert "0.8494" in brandenberger  # the efficiency, as `epicyclic analyze` prints it
    for name in ("single-set", "transmission", "geometry"):
        assert "Output (run when this page was built)" in page(site, f"tutorials/{name}"), name


def test_the_home_page_gives_the_install_and_the_two_commands(site):
    import re

    home = re.sub(r"<[^>]+>", "", page(site, "index"))  # the words of the page, highlighting spans taken out
    for text in ("pip install", "make demo", "make test"):
        assert text in home, text
