"""``epicyclic shiftmap FILE``: outputs and exit codes."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
FILE = str(EXAMPLES / "zf_8hp70_geometry.toml")
SCHEDULE = str(EXAMPLES / "schedules" / "zf_8hp70_upshift.csv")
SMALL = ["--speed", "200..4000:6", "--torque", "50..1500:5"]
runner = CliRunner()


def test_table_states_the_limits_and_the_saving():
    result = runner.invoke(app, ["shiftmap", FILE, *SMALL, "--max-input-torque", "450", "--schedule", SCHEDULE])
    assert result.exit_code == 0, result.output
    assert "input speed 800..6000 1/min, input torque <= 450 N*m" in result.output
    assert "loss saved by the best gear" in result.output


def test_json_and_files(tmp_path):
    result = runner.invoke(app, ["shiftmap", FILE, *SMALL, "-f", "json", "--engine-speed", "1000..5000 rpm"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.output)
    assert data["limits"]["input_speed_rpm"] == [1000.0, 5000.0] and len(data["best_gear"]) == 5
    for suffix in (".png", ".svg", ".csv", ".json"):
        out = tmp_path / f"m{suffix}"
        result = runner.invoke(app, ["shiftmap", FILE, *SMALL, "--schedule", SCHEDULE, "-o", str(out)])
        assert result.exit_code == 0, result.output
        assert out.stat().st_size > 100


@pytest.mark.parametrize("args, says", [
    (["--capacity", "Q=100"], "no shift element 'Q'"),
    (["--capacity", "B"], "NAME=TORQUE"),
    (["--max-input-torque", "3 m"], "--max-input-torque"),
    (["--engine-speed", "6000..800"], "--engine-speed"),
    (["--gears", "1,9"], "no gear '9'"),
    (["--schedule", "missing.csv"], "no such file"),
    (["-o", "map.txt"], "--out"),
    (["--speed", "1..100000:2000", "--torque", "1..10:1000"], "exceed the limit"),
])
def test_bad_input_is_exit_2(args, says):
    result = runner.invoke(app, ["shiftmap", FILE, *SMALL[:0], *args])
    assert result.exit_code == 2, result.output
    assert says in " ".join(result.output.split())
