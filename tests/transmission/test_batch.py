"""All gears × many operating points: agrees with the per-point solver."""

from __future__ import annotations

import json

import numpy as np
import pytest

from epicyclic.errors import EpicyclicError, ModelError
from epicyclic.transmission.batch import solve_gears
from epicyclic.transmission.library import build


@pytest.mark.parametrize("direction", ["drive", "coast"])
def test_batch_matches_per_gear_analysis(direction):
    t = build("zf_8hp70", 0.97)
    rng = np.random.default_rng(1)
    n = rng.uniform(500, 6000, 50)
    m = rng.uniform(10, 700, 50)
    res = solve_gears(t, input_speed=n, input_torque=m, direction=direction)
    for gear in t.gears:
        g = t.analyze(gear, input_speed=float(n[7]), input_torque=float(m[7]))
        expected = g.efficiency_drive if direction == "drive" else g.efficiency_coast
        assert res.efficiency(gear)[7] == pytest.approx(expected, rel=1e-10)
        assert np.allclose(res.efficiency(gear), expected, rtol=1e-10)  # level-independent
    assert res.points == 50 and "η mean" in res.table()
    json.dumps(res.to_dict())
    assert "<table>" in res._repr_html_() and repr(res).startswith("<TransmissionBatch")


def test_batch_direction_error():
    with pytest.raises(ModelError, match="direction must be 'drive' or 'coast'"):
        solve_gears(build("simpson_c4"), input_speed=[1.0], input_torque=[1.0], direction="reverse")


def test_solve_gears_takes_units_and_keeps_the_shape():
    # regression: a pint array in rad/s lost its unit (UnitStrippedWarning, read as 1/min) and
    # "1000 U/min" was a bare ValueError
    import pint

    ureg = pint.UnitRegistry()
    t = build("simpson_c4", stationary_efficiency=0.97)
    plain = solve_gears(t, input_speed=[[1000.0, 2000.0]], input_torque=98.0665)
    rad_s = np.array([[1000.0, 2000.0]]) * np.pi / 30 * ureg("rad/s")
    for speed, torque in ((rad_s, "10 kp*m"), ([["1000 U/min", "2000 rpm"]], 0.0980665 * ureg("kN*m"))):
        res = solve_gears(t, input_speed=speed, input_torque=torque)
        assert res.solutions["1"].speeds["in"].shape == (1, 2)
        assert res.solutions["1"].speeds["in"] == pytest.approx(plain.solutions["1"].speeds["in"], rel=1e-12)
        assert res.efficiency("1") == pytest.approx(plain.efficiency("1"), rel=1e-12)
    with pytest.raises(EpicyclicError, match=r"solve_gears: input_speed\[1\]: '3 kW' is not a speed"):
        solve_gears(t, input_speed=["1 rpm", "3 kW"], input_torque=1.0)
