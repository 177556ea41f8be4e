"""``epicyclic gears`` and ``epicyclic explore`` on the library's TOML files."""

from __future__ import annotations

import json
from pathlib import Path

from typer.testing import CliRunner

from epicyclic.cli.main import app

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
runner = CliRunner()


def test_gears_table_8hp():
    result = runner.invoke(app, ["gears", str(EXAMPLES / "zf_8hp70_8speed.toml")])
    assert result.exit_code == 0, result.output
    assert "4.6957" in result.output and "-3.2968" in result.output and "spread 7.043" in result.output


def test_gears_json_and_detail(tmp_path):
    result = runner.invoke(app, ["gears", str(EXAMPLES / "simpson_c4_3speed.toml"), "--format", "json"])
    assert result.exit_code == 0
    data = json.loads(result.output)
    assert [g["gear"] for g in data["gears"]] == ["1", "2", "3", "R"]
    result = runner.invoke(app, ["gears", str(EXAMPLES / "simpson_c4_3speed.toml"), "--detail"])
    assert "open, slip" in result.output
    out = tmp_path / "g.html"
    result = runner.invoke(app, ["gears", str(EXAMPLES / "simpson_c4_3speed.toml"), "-f", "html", "-o", str(out)])
    assert result.exit_code == 0 and "<table>" in out.read_text()
    result = runner.invoke(app, ["gears", str(EXAMPLES / "simpson_c4_3speed.toml"), "-f", "markdown"])
    assert "| gear |" in result.output


def test_explore_command():
    result = runner.invoke(app, ["explore", str(EXAMPLES / "ravigneaux_ford_aod_4speed.toml")])
    assert result.exit_code == 0
    assert "7 drives (5 distinct ratios)" in result.output
    result = runner.invoke(app, ["explore", str(EXAMPLES / "ravigneaux_ford_aod_4speed.toml"), "-f", "json"])
    assert len(json.loads(result.output)["combinations"]) == 7


def test_gears_without_transmission_table_is_bad_input():
    result = runner.invoke(app, ["gears", str(EXAMPLES / "toyota_prius_power_split.toml")])
    assert result.exit_code == 2
    assert "no [transmission] table" in " ".join(result.output.split())


def test_a_point_given_by_an_option_that_no_gear_carries_names_the_option():
    # issue 30: `gears --torque 1e12` blamed "[transmission], key 'schedule.1'" of the file, not the option
    from typer.testing import CliRunner

    from epicyclic.cli.main import app

    result = CliRunner().invoke(app, ["gears", "examples/zf_8hp70_geometry.toml", "--torque", "1e12"])
    assert result.exit_code == 2, result.output
    text = " ".join(result.output.split())
    assert text.startswith("error: --torque: in gear 1 at input") and "1e+12 N*m (from --torque)" in text
    assert "schedule.1" not in text
