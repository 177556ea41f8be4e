"""All gears × many operating points: agrees with the per-point solver."""

from __future__ import annotations

import json

import numpy as np
import pytest

from epicyclic.errors import ModelError
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
