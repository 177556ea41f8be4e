"""The map's axes in the file's units: `io/ranges.py` (`epicyclic map --speed/--torque`, the page's map form).

Unit factors: 1 rad/s = 30/π 1/min (exact, SI); 1 kp = 9.80665 N (standard gravity, 3rd CGPM 1901).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from epicyclic.errors import ModelError
from epicyclic.io.ranges import MAP_DEFAULTS, default_axis, map_grid, parse_axis
from epicyclic.units import UnitError, Units


def test_numbers_without_a_unit_are_in_the_files_unit():
    assert parse_axis("100..200:3", "--speed", "rad/s", "speed") == pytest.approx(
        [100 * 30 / math.pi, 150 * 30 / math.pi, 200 * 30 / math.pi], rel=1e-12)
    assert parse_axis("2..4:2", "--torque", "kp*m", "torque") == pytest.approx([2 * 9.80665, 4 * 9.80665], rel=1e-12)


def test_a_unit_after_the_range_overrides_the_files():
    assert parse_axis("1000..2000:2 rpm", "--speed", "rad/s", "speed") == pytest.approx([1000.0, 2000.0])
    assert parse_axis("1500 1/min", "--speed", "rad/s", "speed") == pytest.approx([1500.0])
    assert parse_axis("10..20:2N*m", "--torque", "kp*m", "torque") == pytest.approx([10.0, 20.0])


def test_without_a_quantity_the_numbers_come_back_as_written():
    assert parse_axis("10..50:5", "--torque", "N*m").tolist() == [10.0, 20.0, 30.0, 40.0, 50.0]


@pytest.mark.parametrize("text, error, fragment", [
    ("100..600:10 N*m", UnitError, "--speed: 'N*m' is not a speed"),
    ("100..600:10 furlongs", UnitError, "--speed"),
    ("100..600:many", ModelError, "the count after ':' must be a whole number"),
    ("600..100:10 rpm", ModelError, "expected 0 < A <= B in A..B:N (rpm)"),
])
def test_bad_axes_name_the_option(text, error, fragment):
    with pytest.raises(error, match=None) as info:
        parse_axis(text, "--speed", "rad/s", "speed")
    assert fragment in str(info.value)


def test_defaults_are_the_same_physical_range_in_every_unit():
    speeds, torques = map_grid(None, None, units=Units(speed="rad/s", torque="kp*m"))
    assert speeds == pytest.approx(np.linspace(500, 6000, 50)) and torques == pytest.approx(np.linspace(10, 500, 50))
    assert MAP_DEFAULTS == {"speed": (500.0, 6000.0, 50), "torque": (10.0, 500.0, 50)}
    # written in the file's units, read back in them: the same axis (6 digits)
    text = default_axis("speed", "rad/s")
    assert text == "52.3599..628.319:50"
    assert parse_axis(text, "--speed", "rad/s", "speed") == pytest.approx(speeds, rel=1e-5)
    assert default_axis("torque", "kp*m") == "1.01972..50.9858:50"
    assert default_axis("speed", "1/min") == "500..6000:50" and default_axis("torque", "N*m") == "10..500:50"


def test_the_grid_reads_both_axes_in_the_files_units():
    speeds, torques = map_grid("10..20:2", "1..2:2", units=Units(speed="rad/s", torque="kp*m"))
    assert speeds == pytest.approx([10 * 30 / math.pi, 20 * 30 / math.pi])
    assert torques == pytest.approx([9.80665, 2 * 9.80665])
