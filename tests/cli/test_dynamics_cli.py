"""``epicyclic shift`` and ``epicyclic launch`` on the 8HP example with its transient inputs."""

import json

from typer.testing import CliRunner

from epicyclic.cli.main import app

EXAMPLE = "examples/dynamics/zf_8hp70_shift.toml"


def test_shift_table_json_csv_and_picture(tmp_path):
    runner = CliRunner()
    table = runner.invoke(app, ["shift", EXAMPLE, "--from", "2", "--to", "3", "--throttle", "50%"])
    assert table.exit_code == 0, table.stderr
    assert "shift completed" in table.stdout and "inertia phase" in table.stdout
    out = runner.invoke(app, ["shift", EXAMPLE, "--from", "2", "--to", "3", "-f", "json"])
    data = json.loads(out.stdout)
    assert data["completed"] and data["energy_balance_J"]["residual"] is not None
    assert len(data["traces"]["time [s]"]) == 1001
    picture = tmp_path / "shift.png"
    csv = runner.invoke(app, ["shift", EXAMPLE, "--from", "3", "--to", "2", "-f", "csv", "--plot", str(picture)])
    assert csv.exit_code == 0, csv.stderr
    assert csv.stdout.splitlines()[0].startswith("time [s],")
    assert picture.stat().st_size > 10_000


def test_launch_states_its_assumptions():
    result = CliRunner().invoke(app, ["launch", EXAMPLE, "--set", "dynamics.duration=2.0",
                                      "--set", "dynamics.input_speed=1200"])
    assert result.exit_code == 0, result.stderr
    assert "launch completed" in result.stdout and "assumed: launch: 'B'" in result.stdout
