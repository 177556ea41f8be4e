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
    (["--min-dwell", "nan"], "min_dwell"),
    (["--mass", "-3"], "mass"),
])
def test_bad_options_are_exit_2(args, says):
    result = runner.invoke(app, ["cycle", FILE, "--cycle", WLTC, *args] if "--wheel-radius" in args
                           else ["cycle", FILE, "--cycle", WLTC, *CAR, *args])
    assert result.exit_code == 2, result.output
    assert says in " ".join(result.output.split())
