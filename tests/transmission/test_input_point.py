"""``gears`` at a stated input point (issue 20): options, else the file's [operating_point], else the default.

With the geometry-based loss models of ``zf_8hp70_geometry.toml`` the efficiency of a gear depends on
the point (Schlenk's μ on load and speed, ISO/TR 14179-2), so the point used must be the one stated,
and the same in the command line's table, its JSON and the page's gear table.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic import OperatingPoint
from epicyclic.cli.main import app
from epicyclic.errors import ModelError
from epicyclic.io import load_train_file
from epicyclic.transmission import InputPoint, Transmission, input_point
from epicyclic.transmission.input_point import DEFAULT_INPUT_SPEED, DEFAULT_INPUT_TORQUE
from epicyclic.units import UnitError, Units

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
GEOMETRY = EXAMPLES / "zf_8hp70_geometry.toml"  # [operating_point]: in at 2000 1/min, 200 N·m
runner = CliRunner()


def test_the_point_comes_from_the_options_then_the_file_then_the_default():
    op = OperatingPoint(speeds={"in": 2000.0}, torques={"in": 200.0}, drives=["in"], loads=["out"])
    p = input_point("in", op)
    assert (p.speed, p.torque, p.speed_source, p.torque_source) == (2000.0, 200.0, "[operating_point]",
                                                                     "[operating_point]")
    p = input_point("in", op, speed="3000 U/min")
    assert (p.speed, p.torque, p.speed_source) == (3000.0, 200.0, "--speed")
    p = input_point("in", None)
    assert (p.speed, p.torque, p.is_default) == (DEFAULT_INPUT_SPEED, DEFAULT_INPUT_TORQUE, True)
    assert "default point" in p.describe()
    # an operating point at another shaft gives nothing for the input
    p = input_point("in", OperatingPoint(speeds={"x": 5.0}, torques={"x": 1.0}, drives=["x"], loads=["y"]))
    assert p.is_default


def test_a_power_at_the_input_gives_the_torque():
    # T = P / ω: 10 kW at 3000 1/min is 31.831 N·m
    op = OperatingPoint(speeds={"in": 3000.0}, powers={"in": 10_000.0}, drives=["in"], loads=["out"])
    assert input_point("in", op).torque == pytest.approx(10_000.0 / (3000.0 * math.pi / 30.0), rel=1e-12)


def test_plain_option_numbers_are_in_the_files_units():
    p = input_point("in", None, speed="100", torque="2", units=Units(speed="rad/s", torque="kp*m"))
    assert p.speed == pytest.approx(100 * 30 / math.pi) and p.torque == pytest.approx(2 * 9.80665)
    assert p.describe() == "input 100 rad/s (from --speed), 2 kp*m (from --torque)"


@pytest.mark.parametrize("kwargs, error, says", [
    ({"torque": "-5"}, ModelError, "--torque"), ({"torque": "0 N*m"}, ModelError, "--torque"),
    ({"speed": "0"}, ModelError, "--speed"), ({"speed": "3 m"}, UnitError, "--speed"),
    ({"torque": "nan"}, UnitError, "--torque"),
])
def test_bad_options_name_the_option(kwargs, error, says):
    with pytest.raises(error, match=says):
        input_point("in", None, **kwargs)


def test_input_point_refuses_non_finite_values():
    with pytest.raises(ModelError, match="speed"):
        InputPoint(math.inf, 1.0)
    with pytest.raises(ModelError, match="torque"):
        InputPoint(1000.0, -1.0)


def test_gears_uses_the_files_operating_point_and_states_it():
    result = runner.invoke(app, ["gears", str(GEOMETRY), "-f", "json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.output)
    assert data["operating_point"]["input_speed_rpm"] == 2000.0
    assert data["operating_point"]["input_torque_Nm"] == 200.0
    assert data["operating_point"]["speed_source"] == "[operating_point]"
    t = Transmission.from_file(GEOMETRY)
    at_file = t.analyze("1", input_speed=2000.0, input_torque=200.0).efficiency_drive
    hidden = t.analyze("1", input_speed=1000.0, input_torque=100.0).efficiency_drive
    assert at_file != pytest.approx(hidden, abs=1e-6)  # the point matters with loss models
    assert data["gears"][0]["efficiency_drive"] == pytest.approx(at_file, rel=1e-12)


def test_gears_options_override_the_file_in_every_format():
    args = ["gears", str(GEOMETRY), "--speed", "4000 1/min", "--torque", "50"]
    text = runner.invoke(app, args).output
    assert "analysed at input 4000 1/min (from --speed), 50 N*m (from --torque)" in text
    data = json.loads(runner.invoke(app, args + ["-f", "json"]).output)
    t = Transmission.from_file(GEOMETRY)
    assert data["gears"][1]["efficiency_drive"] == pytest.approx(
        t.analyze("2", input_speed=4000.0, input_torque=50.0).efficiency_drive, rel=1e-12)
    assert "analysed at input 4000" in runner.invoke(app, args + ["-f", "markdown"]).output
    assert "analysed at input 4000" in runner.invoke(app, args + ["-f", "html"]).output


def test_gears_without_operating_point_states_the_default():
    text = runner.invoke(app, ["gears", str(EXAMPLES / "simpson_c4_3speed.toml")]).output
    assert "input 1000 1/min, 100 N*m (the default point: give --speed/--torque or an [operating_point])" in text


@pytest.mark.parametrize("option, value", [("--torque", "-1"), ("--torque", "3 m"), ("--speed", "fast")])
def test_gears_bad_point_is_exit_2_naming_the_option(option, value):
    result = runner.invoke(app, ["gears", str(GEOMETRY), option, value])
    assert result.exit_code == 2 and option in result.output


def test_the_pages_gear_table_uses_the_same_point_and_losses():
    from epicyclic.web.summary import gear_table
    from epicyclic.web.views import _transmission

    f = load_train_file(GEOMETRY)
    table = gear_table(lambda: _transmission(f), None, str(GEOMETRY), f.operating_point)
    assert table["error"] is None
    assert "analysed at input 2000 1/min, 200 N*m (from [operating_point])" in table["footer"]
    cli = json.loads(runner.invoke(app, ["gears", str(GEOMETRY), "-f", "json"]).output)
    assert [g.efficiency_drive for g in table["analysis"].gears] == pytest.approx(
        [g["efficiency_drive"] for g in cli["gears"]], rel=1e-12)
