"""``epicyclic cycle FILE --cycle CSV``: outputs and exit codes (hostile CSVs name the line and column)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
FILE = str(EXAMPLES / "zf_8hp70_spin_losses.toml")
WLTC = str(EXAMPLES / "cycles" / "wltc_class3b.csv")
CAR = ["--mass", "1800", "--wheel-radius", "0.33", "--axle-ratio", "2.8", "--drag-area", "0.7"]
runner = CliRunner()


def test_wltc_table_and_json(tmp_path):
    result = runner.invoke(app, ["cycle", FILE, "--cycle", WLTC, *CAR, "--max-input-torque", "500"])
    assert result.exit_code == 0, result.output
    assert "cycle efficiency" in result.output and "pump" in result.output
    result = runner.invoke(app, ["cycle", FILE, "--cycle", WLTC, *CAR, "-f", "json"])
    data = json.loads(result.output)
    assert data["energy_in_J"] == pytest.approx(data["energy_out_J"] + data["energy_lost_J"], rel=1e-9)
    out = tmp_path / "rows.csv"
    result = runner.invoke(app, ["cycle", FILE, "--cycle", WLTC, *CAR, "-o", str(out)])
    assert result.exit_code == 0 and out.read_text().count("\n") == 1802


def test_schedule_rule(tmp_path):
    result = runner.invoke(app, ["cycle", FILE, "--cycle", WLTC, *CAR, "--schedule",
                                 str(EXAMPLES / "schedules" / "zf_8hp70_upshift.csv")])
    assert result.exit_code == 0, result.output
    assert "upshift lines of zf_8hp70_upshift.csv" in result.output


@pytest.mark.parametrize("text, says", [
    ("", "the file is empty"),
    ("time,output_speed,output_torque\n0,5,1\n1,nan,1\n", "line 3, column 'output_speed': expected a finite number"),
    ("time,output_torque\n0,1\n", "missing column 'output_speed' or 'vehicle_speed'"),
    ("time [furlong],output_speed,output_torque\n0,5,1\n1,5,1\n", "column 'time': unknown unit 'furlong'"),
    ("time,output_speed [kg],output_torque\n0,5,1\n1,5,1\n", "column 'output_speed'"),
    ("time,output_speed,output_torque\n0,5,1\n0,6,1\n", "line 3, column 'time'"),
    ("time,output_speed,output_torque,gear\n0,5,1,1\n1,5,1,X\n", "line 3, column 'gear': no gear 'X'"),
])
def test_hostile_cycle_files_are_exit_2(tmp_path, text, says):
    path = tmp_path / "c.csv"
    path.write_text(text)
    result = runner.invoke(app, ["cycle", FILE, "--cycle", str(path)])
    assert result.exit_code == 2, result.output
    assert says in " ".join(result.output.split())


@pytest.mark.parametrize("args, says", [
    (["--wheel-radius", "0.3"], "--wheel-radius and --axle-ratio go together"),
    (["--gear-rule", "fast"], "--gear-rule"),
    (["--gear-rule", "given"], "no 'gear' column"),
    (["-o", "x.png"], "--out"),
    (["--gear-rule", "best", "--schedule", str(EXAMPLES / "schedules" / "zf_8hp70_upshift.csv")],
     "--schedule is read by --gear-rule schedule only"),
    # issue 30: the vehicle and gear-rule options named the train file and a field ("mass"), not the option
    (["--min-dwell", "nan"], "error: --min-dwell must be a finite number"),
    (["--hysteresis", "-1"], "error: --hysteresis must be"),
    (["--mass", "-3"], "error: --mass (kg) must be a number in (0, 1e+06]"),
    (["--mass", "3 parsec"], "error: --mass: unknown mass unit 'parsec'"),
    (["--axle-ratio", "0"], "error: --axle-ratio must be a number in [0.1, 50]"),
    (["--air-density", "-1 kg/m^3"], "error: --air-density (kg/m^3) must be"),
])
def test_bad_options_are_exit_2(args, says):
    result = runner.invoke(app, ["cycle", FILE, "--cycle", WLTC, *args] if "--wheel-radius" in args
                           else ["cycle", FILE, "--cycle", WLTC, *CAR, *args])
    assert result.exit_code == 2, result.output
    assert says in " ".join(result.output.split())
    if says.startswith("error: --"):
        assert FILE not in result.output  # an option's value, not the train file


def test_vehicle_options_take_units():
    # issue 30: `cycle --mass "1800 kg"` was refused as "not a valid float"; every quantity option takes units
    plain = runner.invoke(app, ["cycle", FILE, "--cycle", WLTC, *CAR, "-q", "-f", "json"])
    units = runner.invoke(app, ["cycle", FILE, "--cycle", WLTC, "--mass", "1.8 t", "--wheel-radius", "330 mm",
                                "--axle-ratio", "2.8", "--drag-area", "0.7 m^2", "-q", "-f", "json"])
    assert plain.exit_code == 0 and units.exit_code == 0, units.output
    assert json.loads(units.stdout) == json.loads(plain.stdout)
