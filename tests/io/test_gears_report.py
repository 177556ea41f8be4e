"""``epicyclic gears -f html``: one self-contained page with the detail, every gear's lever and the speed chart."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import matplotlib
from typer.testing import CliRunner

from epicyclic.cli.main import app

matplotlib.use("Agg")

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_gears_html_is_one_self_contained_page(tmp_path):
    out = tmp_path / "gears.html"
    result = CliRunner().invoke(app, ["gears", str(EXAMPLES / "simpson_c4_3speed.toml"), "-f", "html", "-o", str(out)])
    assert result.exit_code == 0, result.output
    page = out.read_text()
    assert page.startswith("<!DOCTYPE html>") and "<style>" in page
    assert not re.search(r"<script|<link|\bsrc=|\bhref=|url\(|@import", page)  # nothing outside the file
    # the summary, the speed chart, then per gear its detail and its lever diagram
    assert "Every gear of the schedule" in page and "Speed chart" in page
    for gear in ("1", "2", "3", "R"):
        assert f"Gear {gear} (" in page and f"Lever diagram, gear {gear}" in page
    assert "high_reverse" in page and "× n_in" in page and "× T_in" in page
    svgs = re.findall(r"<svg.*?</svg>", page, flags=re.S)
    assert len(svgs) == 1 + 4  # the chart and one lever per gear
    for svg in svgs:
        ET.fromstring(svg)
    assert "−0.0000" not in page and "-0.0000" not in page  # round-off never shown as a signed zero


def test_gears_html_uses_the_file_units(tmp_path):
    # the reduced levers of a file with [units] speak its units, as the analyze report's tables do
    text = (EXAMPLES / "zf_8hp70_8speed.toml").read_text()
    train = tmp_path / "8hp.toml"
    train.write_text(text.replace("[[planetary]]", '[units]\nspeed = "U/min"\n\n[[planetary]]', 1))
    out = tmp_path / "gears.html"
    result = CliRunner().invoke(app, ["gears", str(train), "-f", "html", "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert "U/min" in out.read_text()
