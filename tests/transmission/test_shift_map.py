"""Shift map and best gear (issue 20): closed forms against one gear at a time, invariants, hostile input.

The best gear must be the argmin of the per-gear loss, computed here independently: every gear solved
alone at each point with the point solver (``solve_with_losses``, not the batch the map uses), and the
carrying condition applied by hand.  The envelope is at least every carrying gear's efficiency; the
saving against a schedule is never negative.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from epicyclic import OperatingPoint
from epicyclic.errors import EpicyclicError, ModelError
from epicyclic.limits import LimitError
from epicyclic.losses import solve_with_losses
from epicyclic.transmission import Transmission
from epicyclic.transmission.gear_points import CarryLimits, solve_gear_points
from epicyclic.transmission.shift_map import best_gear_index, forward_gears, shift_map
from epicyclic.transmission.shift_schedule import ShiftSchedule

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
GEOMETRY = EXAMPLES / "zf_8hp70_geometry.toml"


@pytest.fixture(scope="module")
def transmission():
    return Transmission.from_file(GEOMETRY)


@pytest.fixture(scope="module")
def small_map(transmission):
    limits = CarryLimits((800.0, 6000.0), 450.0)
    return shift_map(transmission, np.linspace(100.0, 6000.0, 9), np.linspace(50.0, 2000.0, 7), limits=limits)


def test_forward_gears_first_gear_first(transmission):
    assert forward_gears(transmission) == ("1", "2", "3", "4", "5", "6", "7", "8")


def test_best_gear_is_the_argmin_of_the_loss_one_gear_at_a_time(transmission, small_map):
    t, m = transmission, small_map
    for i in (0, 3, 6):
        for j in (1, 4, 8):
            n_out, t_out = m.output_speeds[j], m.output_torques[i]
            losses = {}
            for gear in m.gears:
                op = OperatingPoint(speeds={t.output: n_out}, torques={t.output: t_out}, drives=[t.input],
                                    loads=[t.output])
                sol = solve_with_losses(t.gear_train(gear), op, t.losses)
                n_in, m_in = abs(sol.speed(t.input)), abs(sol.torque(t.input))
                if 800.0 <= n_in <= 6000.0 and m_in <= 450.0 and not sol.self_locking:
                    losses[gear] = sol.input_power - sol.output_power
            expected = min(losses, key=losses.get) if losses else ""
            assert m.best_gear_names()[i, j] == expected
            if losses:
                assert m.best_loss[i, j] == pytest.approx(losses[expected], rel=1e-9)


def test_the_envelope_is_the_best_gears_efficiency(small_map):
    m = small_map
    carried = m.best >= 0
    assert carried.any() and (~carried).any()  # the limits leave some points to no gear
    assert np.all(np.isnan(m.envelope[~carried]))
    power = m.output_power
    # η = P_out / (P_out + P_V) of the least loss
    assert np.allclose(m.envelope[carried], (power / (power + m.best_loss))[carried], rtol=1e-9)


def test_no_gear_beyond_the_engine_speed_range(transmission):
    m = shift_map(transmission, [5000.0], [100.0], limits=CarryLimits((800.0, 6000.0)))
    # only gears whose input speed 5000 i stays within 6000: i <= 1.2 → gears 6, 7, 8
    assert m.best_gear_names()[0, 0] in {"6", "7", "8"}
    assert not m.carries[:5, 0, 0].any() and m.carries[5:, 0, 0].all()


def test_a_capacity_takes_a_gear_out(transmission):
    free = shift_map(transmission, [300.0], [800.0])
    gear = free.best_gear_names()[0, 0]
    element = max(transmission.schedule[gear], key=lambda e: abs(
        solve_gear_points(transmission, gear, 300.0, 800.0).element_torques[e]))
    torque = abs(float(solve_gear_points(transmission, gear, 300.0, 800.0).element_torques[element]))
    capped = shift_map(transmission, [300.0], [800.0], limits=CarryLimits(capacities={element: 0.5 * torque}))
    assert capped.best_gear_names()[0, 0] != gear


@settings(max_examples=8, deadline=None)
@given(st.floats(200.0, 5000.0), st.floats(20.0, 2000.0), st.floats(900.0, 3000.0))
def test_envelope_is_at_least_every_carrying_gears_efficiency(speed, torque, engine_top):
    t = Transmission.from_file(GEOMETRY)
    m = shift_map(t, [speed, speed * 1.1], [torque, torque * 1.2], limits=CarryLimits((700.0, engine_top)))
    for k in range(len(m.gears)):
        where = m.carries[k] & np.isfinite(m.efficiency[k])
        assert np.all(m.envelope[where] >= m.efficiency[k][where] - 1e-12)
        assert np.all(m.best_loss[where] <= m.loss[k][where] + 1e-9)
    assert np.all(m.best_loss[m.best >= 0] >= 0)


def test_the_saving_against_a_schedule_is_never_negative(transmission):
    schedule = ShiftSchedule(("1", "2", "3", "4", "5", "6", "7", "8"), [0.0, 2000.0],
                             [[300, 600], [450, 900], [700, 1300], [900, 1700], [1200, 2200], [1500, 2800],
                              [1800, 3400]])
    m = shift_map(transmission, np.linspace(100.0, 4000.0, 8), np.linspace(50.0, 1500.0, 6), schedule=schedule,
                  limits=CarryLimits(max_input_torque=450.0))
    saved = m.saved[np.isfinite(m.saved)]
    assert saved.size and np.all(saved >= -1e-9)
    s = m.summary()
    assert s["saved_mean_W"] == pytest.approx(float(saved.mean()))
    # where the schedule's gear is the best gear, nothing is saved
    same = (m.scheduled == m.best) & (m.best >= 0)
    assert np.allclose(m.saved[same], 0.0)


def test_best_gear_index_ties_and_no_gear():
    loss = np.array([[1.0, 5.0, 2.0], [1.0, 3.0, 9.0]])
    carries = np.array([[True, True, False], [True, True, False]])
    assert best_gear_index(loss, carries).tolist() == [0, 1, -1]


def test_renders_table_json_csv_and_picture(tmp_path, small_map):
    import json

    m = small_map
    assert "best gear (least loss)" in m.table() and "800..6000 1/min" in m.table()
    data = json.loads(m.to_json())
    assert data["best_gear"][0][1] == (m.best_gear_names()[0, 1] or None)
    assert m.to_csv().count("\n") == 1 + m.best.size
    assert "<ShiftMap" in repr(m)
    import matplotlib

    matplotlib.use("Agg")
    for suffix in (".png", ".svg"):
        assert m.save(tmp_path / f"map{suffix}").stat().st_size > 1000
    with pytest.raises(ModelError, match="cannot write"):
        m.save(tmp_path / "map.txt")


@pytest.mark.parametrize("kwargs, error, says", [
    ({"gears": ["9"]}, ModelError, "no gear '9'"),
    ({"limits": CarryLimits(capacities={"Z": 10.0})}, ModelError, "no shift element 'Z'"),
])
def test_bad_arguments(transmission, kwargs, error, says):
    with pytest.raises(error, match=says):
        shift_map(transmission, [1000.0], [100.0], **kwargs)


def test_bad_axes_and_the_point_limit(transmission):
    with pytest.raises(ModelError, match="output_speeds"):
        shift_map(transmission, [0.0, 100.0], [100.0])
    with pytest.raises(EpicyclicError, match="output_torques"):  # a UnitError: not a finite torque
        shift_map(transmission, [100.0], [np.nan])
    with pytest.raises(LimitError, match="grid points"):
        shift_map(transmission, np.arange(1.0, 1002.0), np.arange(1.0, 1002.0))


@pytest.mark.parametrize("args, says", [
    (((800.0, 600.0),), "lowest < highest"), (((800.0, 6000.0), -1.0), "max_input_torque"),
    (((800.0, 6000.0), None, {"B": 0.0}), "capacity of 'B'"), (("fast",), "pair"),
])
def test_carry_limits_refuse(args, says):
    with pytest.raises(ModelError, match=says):
        CarryLimits(*args)


def test_schedule_gear_by_upshift_lines():
    # closed form: upshift 1-2 at 300 (T=0) … 600 1/min (T=400), linear between
    s = ShiftSchedule(["1", "2", "3"], [0.0, 400.0], [[300.0, 600.0], [600.0, 1200.0]])
    assert s.gear_index([449.0, 451.0], [200.0, 200.0]).tolist() == [0, 1]  # line at 450 for T = 200
    assert s.gear_index([599.0], [1e6]).tolist() == [0]  # beyond the table the last row holds


@pytest.mark.parametrize("args, says", [
    ((["1"], [0.0], [[]]), "two or more"),
    ((["1", "2"], [0.0, 0.0], [[1.0, 2.0]]), "increasing"),
    ((["1", "2", "3"], [0.0, 1.0], [[500.0, 500.0], [400.0, 600.0]]), "lies below"),
    ((["1", "2"], [0.0, 1.0], [[500.0, -1.0]]), "> 0"),
    ((["1", "2"], [0.0, 1.0], [[500.0]]), "shape"),
])
def test_schedule_refuses(args, says):
    with pytest.raises(ModelError, match=says):
        ShiftSchedule(*args)
