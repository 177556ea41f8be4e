"""ScuffingRating as two failure modes, and the section they give ``epicyclic rate`` in every format."""

from __future__ import annotations

import json
from pathlib import Path

from typer.testing import CliRunner

from epicyclic.cli.main import app

EXAMPLE = str(Path(__file__).resolve().parents[3] / "examples" / "rating" / "helical_stage_scuffing.toml")
runner = CliRunner()


def test_every_format_has_both_methods():
    text = runner.invoke(app, ["rate", EXAMPLE])
    assert text.exit_code == 0, text.output
    assert "Failure modes beyond pitting and root" in text.output
    assert "Scuffing, integral temperature method" in text.output and "Scuffing, flash temperature method" in text.output
    assert "ϑ_intS" in text.output and "ISO/TS 6336-21:2017" in text.output and "ISO 14635-1" in text.output
    data = json.loads(runner.invoke(app, ["rate", EXAMPLE, "-f", "json"]).output)
    modes = data["ratings"][0]["meshes"][0]["modes"]
    integral, flash = modes["scuffing_integral"], modes["scuffing_flash"]
    assert integral["safety"] == "S_intS" and integral["minimum"] == 1.8 and integral["ok"]
    assert {"S_SL", "theta_int", "theta_M", "theta_flaint", "X_epsilon"} <= set(integral["factors"])
    assert flash["safety"] == "S_B" and flash["factors"]["theta_Bmax"]["unit"] == "°C"
    assert len(flash["profile"]["gamma"]) == len(flash["profile"]["theta_B"])
    assert data["inputs"]["scuffing"]["load_stage"] == 12
    markdown = runner.invoke(app, ["rate", EXAMPLE, "-f", "markdown"]).output
    assert "Scuffing, flash temperature method" in markdown and "| S_B |" in markdown
    page = runner.invoke(app, ["rate", EXAMPLE, "-f", "html"]).output
    assert "Scuffing, integral temperature method" in page and page.rstrip().endswith("</html>")


def test_below_the_minimum_is_marked_and_named():
    """S_Smin above the safety: ``!`` in text, red in HTML, the mesh named on stderr."""
    args = ["rate", EXAMPLE, "--set", "rating.scuffing.S_Smin=5.0"]
    text = runner.invoke(app, args)
    assert text.exit_code == 0, text.output
    assert " !" in text.output and "below minimum safety: S3 mesh 1 (24/95)" in text.output
    page = runner.invoke(app, [*args, "-f", "html"]).output
    assert "class='below'" in page


def test_a_bad_key_exits_2_naming_it():
    result = runner.invoke(app, ["rate", EXAMPLE, "--set", "rating.scuffing.load_stage=15"])
    assert result.exit_code == 2 and "load_stage" in result.output
