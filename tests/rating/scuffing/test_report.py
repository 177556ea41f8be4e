"""The scuffing section of ``epicyclic rate``: text, JSON, Markdown, HTML; marking below the minimum."""

from __future__ import annotations

import json
from pathlib import Path

from typer.testing import CliRunner

from epicyclic.cli.main import app

EXAMPLE = str(Path(__file__).resolve().parents[3] / "examples" / "rating" / "helical_stage_scuffing.toml")
runner = CliRunner()


def test_every_format_has_the_section():
    text = runner.invoke(app, ["rate", EXAMPLE])
    assert text.exit_code == 0, text.output
    assert "Scuffing: integral temperature and flash temperature methods" in text.output
    assert "theta_intS" in text.output and "ISO/TS 6336-21:2017" in text.output and "ISO 14635-1" in text.output
    data = json.loads(runner.invoke(app, ["rate", EXAMPLE, "-f", "json"]).output)
    (s,) = data["ratings"][0]["scuffing"]
    assert {"S_intS", "S_SL", "S_B", "integral", "flash", "path", "ok"} <= set(s)
    assert s["integral"]["theta_int"]["unit"] == "°C" and s["flash"]["S_B"]["clause"] == "ISO/TS 6336-20:2017"
    assert len(s["path"]["gamma"]) == len(s["path"]["theta_B"]) and data["inputs"]["scuffing"]["load_stage"] == 12
    markdown = runner.invoke(app, ["rate", EXAMPLE, "-f", "markdown"]).output
    assert "## Scuffing" in markdown and "| safety factor for scuffing (flash temperature) | S_B |" in markdown
    page = runner.invoke(app, ["rate", EXAMPLE, "-f", "html"]).output
    assert "<section class='scuffing'>" in page and page.rstrip().endswith("</html>")


def test_below_the_minimum_is_marked_and_named():
    """S_Smin above the safety: ``!`` in text, red in HTML, named on stderr."""
    args = ["rate", EXAMPLE, "--set", "rating.scuffing.S_Smin=5.0"]
    text = runner.invoke(app, args)
    assert text.exit_code == 0, text.output
    assert "BELOW its minimum safety" in text.output and " !" in text.output
    assert "below minimum scuffing safety: S3 mesh 1 (24/95) (S_intS" in text.output
    page = runner.invoke(app, [*args, "-f", "html"]).output
    assert "class='below'" in page


def test_a_bad_key_exits_2_naming_it():
    result = runner.invoke(app, ["rate", EXAMPLE, "--set", "rating.scuffing.load_stage=14"])
    assert result.exit_code == 2 and "load_stage" in result.output
