"""``epicyclic datasheet`` and ``epicyclic rate --datasheet`` (issue 31): the data sheet in every format."""

from __future__ import annotations

import json
from pathlib import Path

from typer.testing import CliRunner

from epicyclic.cli.main import app

ROOT = Path(__file__).resolve().parents[2]
RATED = ROOT / "examples" / "rating" / "simple_set.toml"


def test_datasheet_formats():
    runner = CliRunner()
    table = runner.invoke(app, ["datasheet", str(RATED), "--thickness-tolerance", "0.04", "--accuracy-grade", "7"])
    assert table.exit_code == 0, table.output
    assert "W_k" in table.output and "flank tolerances" in table.output and "ISO 1328-1:2013" in table.output
    data = json.loads(runner.invoke(app, ["datasheet", str(RATED), "-f", "json"]).output)
    sun = data["datasheets"][0]["gears"][0]
    assert sun["span"]["teeth_spanned"] >= 2 and sun["pins"]["measured"] == "over balls"
    html = runner.invoke(app, ["datasheet", str(RATED), "-f", "html"]).output
    assert html.startswith("<!DOCTYPE html>") and "<table>" in html
    assert runner.invoke(app, ["datasheet", str(RATED), "-f", "markdown"]).output.startswith("# data sheet")


def test_rate_with_datasheet_uses_the_rating_accuracy_grade():
    runner = CliRunner()
    done = runner.invoke(app, ["rate", str(RATED), "--datasheet", "-f", "json"])
    assert done.exit_code == 0, done.output
    data = json.loads(done.stdout)
    grade = data["inputs"]["accuracy_grade"]
    assert data["datasheets"][0]["gears"][0]["accuracy"]["grade"] == grade
    text = runner.invoke(app, ["rate", str(RATED), "--datasheet"]).output
    assert "S_H" in text and "data sheet of" in text
