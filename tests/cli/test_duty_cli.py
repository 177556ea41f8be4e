"""``epicyclic duty FILE``: formats, JSON with units and without NaN/Infinity, exit codes."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "zf_8hp70_geometry.toml"
runner = CliRunner()


def test_table_of_the_example():
    result = runner.invoke(app, ["duty", str(EXAMPLE)])
    assert result.exit_code == 0, result.output
    assert "mixed driving, 12 cases" in result.output and "bearing rating life" in result.output
    assert "cycle" in result.output and "lost mesh" in result.output


def test_json_is_strict_and_carries_units():
    result = runner.invoke(app, ["duty", str(EXAMPLE), "--format", "json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.output, parse_constant=lambda c: (_ for _ in ()).throw(ValueError(c)))
    cycle = data["cycle"]
    assert cycle["energy_in"]["unit"] == "kWh" and 0.95 < cycle["efficiency"] < 1.0
    total_lost = sum(v["value"] for v in cycle["energy_lost"].values())
    assert cycle["energy_in"]["value"] - cycle["energy_out"]["value"] == pytest.approx(total_lost, rel=1e-9)
    planet = data["bearings"][0]
    assert planet["L10h"]["unit"] == "h" and planet["rating"]["C"] == {"value": 11500.0, "unit": "N"}
    assert planet["Lnmh"]["unit"] == "h"  # P1 has the modified-life inputs


def test_markdown_and_html(tmp_path):
    md = runner.invoke(app, ["duty", str(EXAMPLE), "-f", "markdown"])
    assert md.exit_code == 0 and md.output.startswith("# Duty cycle:") and "| case |" in md.output
    out = tmp_path / "duty.html"
    page = runner.invoke(app, ["duty", str(EXAMPLE), "-f", "html", "-o", str(out)])
    assert page.exit_code == 0 and "<table" in out.read_text()


def test_bad_input_exits_2_with_one_line(tmp_path):
    plain = Path(__file__).resolve().parents[2] / "examples" / "wolfrom_drive.toml"
    result = runner.invoke(app, ["duty", str(plain)])
    assert result.exit_code == 2 and "has no [duty_cycle] table" in result.output
    bad = tmp_path / "bad.toml"
    bad.write_text(EXAMPLE.read_text().replace('gear = "R"\nshare = 0.02', 'gear = "9"\nshare = 0.02'))
    result = runner.invoke(app, ["duty", str(bad)])
    assert result.exit_code == 2 and "no gear '9'" in result.output and "Traceback" not in result.output
    result = runner.invoke(app, ["duty", str(EXAMPLE), "--set", "duty_cycle.hours=-1"])
    assert result.exit_code == 2 and "total hours > 0" in result.output


def test_rated_example_gives_damage_sums_and_modified_lives():
    rated = Path(__file__).resolve().parents[2] / "examples" / "rating" / "simple_set_duty_cycle.toml"
    result = runner.invoke(app, ["duty", str(rated), "-f", "json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert {(d["mesh"], d["gear"]) for d in data["damage"]} == {
        ("sun-planet", "sun"), ("sun-planet", "planet"), ("planet-ring", "planet"), ("planet-ring", "ring")}
    assert all(0 <= d["D_H"] < 1 and 0 <= d["D_F"] < 1 for d in data["damage"])  # the design lasts the cycle
    planet = data["bearings"][0]
    assert planet["Lnmh"]["value"] > planet["L10h"]["value"]  # clean oil, kappa > 1: a_ISO > 1
    assert 0.98 < data["cycle"]["efficiency"] < 1.0
