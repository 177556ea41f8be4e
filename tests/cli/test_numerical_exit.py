"""Numerical limits reach the command line as bad input: exit 2, one line, the quantity named."""

from __future__ import annotations

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app

runner = CliRunner()

TRAIN = """
[[planetary]]
name = "P"
sun = "sun"
ring = "ring"
carrier = "carrier"
stationary_ratio = -2
stationary_efficiency = {eta}

[[brake]]
name = "B"
shaft = "ring"

[operating_point]
speeds = {{ {speed} }}
torques = {{ {torque} }}
drives = ["{drive}"]
loads = ["{load}"]
"""


@pytest.mark.parametrize(("values", "expected"), [
    ({"eta": "5e-324", "speed": "carrier = 1000", "torque": "carrier = 10", "drive": "carrier", "load": "sun"},
     "stationary efficiency 5e-324 is too small"),
    ({"eta": "0.97", "speed": "carrier = 1e308", "torque": "sun = 10", "drive": "sun", "load": "carrier"},
     "speed of shaft 'sun' is not a finite number: it overflows"),
])
def test_out_of_range_is_exit_2_with_the_quantity(tmp_path, values, expected):
    path = tmp_path / "t.toml"
    path.write_text(TRAIN.format(**values), encoding="utf-8")
    result = runner.invoke(app, ["analyze", str(path)])
    assert result.exit_code == 2, result.output
    assert expected in result.output and "Traceback" not in result.output
    assert len(result.output.strip().splitlines()) == 1


def test_held_load_is_reported_not_given_an_efficiency(tmp_path):
    # Issue 13: a load the train holds still takes a reaction torque, not power: exit 0, no efficiency.
    path = tmp_path / "t.toml"
    path.write_text("""
[[brake]]
name = "B0"
shaft = "x2"
[[planetary]]
name = "P0"
sun = "x2"
ring = "x0"
carrier = "x1"
stationary_ratio = 1.09375
stationary_efficiency = 0.5
[[gear]]
name = "G1"
first = "x2"
second = "x3"
ratio = 0.7561
efficiency = 0.7561
[operating_point]
speeds = { x0 = 1338.2 }
torques = { x3 = 564.16 }
drives = ["x0"]
loads = ["x3"]
""", encoding="utf-8")
    result = runner.invoke(app, ["analyze", str(path)])
    assert result.exit_code == 0, result.output
    assert "holds it still" in result.output and "1.213" not in result.output
