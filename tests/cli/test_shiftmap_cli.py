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


def test_the_map_defaults_to_the_files_rated_range_and_warns_beyond_it():
    # issue 30: shiftmap mapped 2 300 N*m at 9 000 1/min (about 1.2 MW) for an 8HP70 with no input-torque limit,
    # and took --engine-speed 800..60000 without comment
    from typer.testing import CliRunner

    from epicyclic.cli.main import app

    runner = CliRunner()
    plain = runner.invoke(app, ["shiftmap", "examples/zf_8hp70_spin_losses.toml", "--speed", "50..9000:8",
                                "--torque", "10..2300:6"])
    assert plain.exit_code == 0, plain.output
    assert "input torque <= 500 N*m" in plain.stdout  # the stated default limit
    rated = ["--set", "transmission.input_speed_range=[800, 6500]", "--set", "transmission.max_input_torque=700"]
    result = runner.invoke(app, ["shiftmap", "examples/zf_8hp70_spin_losses.toml", "--speed", "50..9000:8",
                                 "--torque", "10..2300:6", *rated])
    assert result.exit_code == 0 and "input speed 800..6500 1/min, input torque <= 700 N*m" in result.stdout
    beyond = runner.invoke(app, ["shiftmap", "examples/zf_8hp70_spin_losses.toml", "--speed", "50..9000:8",
                                 "--torque", "10..2300:6", *rated, "--engine-speed", "800..7000",
                                 "--max-input-torque", "800"])
    assert beyond.exit_code == 0
    assert "warning: --engine-speed 800..7000 1/min is outside the file's rated input_speed_range" in beyond.stderr
    assert "warning: --max-input-torque 800 N*m exceeds the file's rated max_input_torque 700 N*m" in beyond.stderr
    wild = runner.invoke(app, ["shiftmap", "examples/zf_8hp70_spin_losses.toml", "--speed", "50..9000:8",
                               "--torque", "10..2300:6", "--engine-speed", "800..60000"])
    assert wild.exit_code == 0 and "beyond any road vehicle's engine or motor" in wild.stderr
