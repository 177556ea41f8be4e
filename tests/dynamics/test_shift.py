"""Shifts of the ZF 8HP 70 (examples/zf_8hp70_8speed.toml): steady states equal the static solution of
``gears``, the energy balance closes, bad input gets a clear answer.

No published shift simulation of the 8HP with its inputs (pressures, inertias, clutch data) was reachable
(searched: lever-analogy shift analyses, textbook 4-/6-speed shift examples); the checks are the closed
forms of tests/dynamics/test_integrate.py, the static solution (Brandenberger 1952, eq. 7 per set) and the
energy balance.
"""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic import OperatingPoint
from epicyclic.dynamics import (
    DynamicsError,
    Engine,
    FrictionCapacity,
    HeldSpeed,
    Inertias,
    PressureProfile,
    TorqueTrace,
    VehicleLoad,
    WetElement,
)
from epicyclic.dynamics.shift import (
    DynamicsSpec,
    ShiftController,
    simulate_launch,
    simulate_shift,
)
from epicyclic.transmission import Transmission, Vehicle

EXAMPLE = "examples/zf_8hp70_8speed.toml"
RPM = math.pi / 30


@pytest.fixture(scope="module")
def hp8():
    return Transmission.from_file(EXAMPLE)


def _spec(t, load=None, drive=None, **kw):
    shafts = {s: 0.01 for s in t.train.moving_shafts}
    shafts["in"] = 0.05
    cap = FrictionCapacity(piston_area=0.012, faces=8, mean_radius=0.08, friction=((0, 0.13), (100, 0.12), (1000, 0.11)),
                           return_spring=1500.0, friction_area=8 * math.pi * (0.09 ** 2 - 0.07 ** 2), heat_capacity=2000.0)
    return DynamicsSpec(Inertias(shafts), {n: WetElement(n, cap) for n in "ABCDE"},
                        drive or TorqueTrace(((0.0, 200.0),)), load or HeldSpeed(), input_speed=2500.0, **kw)


def _static(t, gear, n_in, torque):
    return t.solve(gear, OperatingPoint(speeds={"in": n_in}, torques={"in": torque}, drives=["in"], loads=["out"]))


def _relative(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


@pytest.mark.parametrize("old, new", [("2", "3"), ("3", "4"), ("5", "6")])
def test_steady_states_equal_the_static_solution(hp8, old, new):
    result = simulate_shift(hp8, _spec(hp8), old, new)
    assert result.completed, result.status
    tr = result.traces
    for j, gear in ((0, old), (-1, new)):
        static = _static(hp8, gear, float(tr.speeds["in"][j]), 200.0)
        for name in hp8.schedule[gear]:
            assert _relative(tr.elements[name].torque[j], static.elements[name].torques["first" if name in "CDE"
                                                                                         else "shaft"]) < 1e-9
        for name in ("P1", "P2", "P3", "P4"):
            expected = static.elements[name].torques["sun"]
            if expected != 0.0:
                assert _relative(tr.set_torques[name][j], expected) < 1e-9
            else:
                assert abs(tr.set_torques[name][j]) < 1e-9
        assert _relative(tr.output_torque[j], -static.shafts["out"].torque) < 1e-9
        for shaft in hp8.train.moving_shafts:
            expected = static.shafts[shaft].speed
            assert abs(tr.speeds[shaft][j] - expected) <= 1e-9 * max(abs(expected), 2500.0)
    assert result.balance.relative_residual < 1e-6


def test_upshift_with_a_vehicle_and_engine(hp8):
    engine = Engine(((800, 250.0), (2000, 350.0), (5000, 330.0), (6500, 250.0)), throttle=0.5)
    spec = _spec(hp8, load=VehicleLoad(Vehicle(0.33, 2.8, mass=1800.0, drag_area=0.7)), drive=engine)
    result = simulate_shift(hp8, spec, "2", "3")
    assert result.completed and result.shift_time > 0 and result.inertia_phase > 0 and result.torque_phase > 0
    assert result.balance.relative_residual < 1e-6
    c = result.elements["C"]
    assert c.energy > 0 and c.peak_power > 0 and c.temperature_rise == pytest.approx(c.energy / 2000.0)
    assert result.traces.vehicle_acceleration is not None
    speed = result.traces.speeds["in"]
    assert speed[-1] == pytest.approx(result.traces.speeds["out"][-1] * hp8.ratio("3"), rel=1e-9)
    data = result.to_dict()
    assert data["completed"] and "traces" in data
    result.to_json()  # no NaN or infinity
    assert result.to_csv().splitlines()[0].startswith("time [s],n_")


def test_throttle_scales_the_engine(hp8):
    engine = Engine(((800, 250.0), (6500, 250.0)))
    spec = _spec(hp8, drive=engine)
    low = simulate_shift(hp8, spec, "2", "3", throttle=0.2)
    high = simulate_shift(hp8, spec, "2", "3", throttle=0.8)
    assert high.traces.input_torque[0] == pytest.approx(4 * low.traces.input_torque[0])
    assert high.elements["C"].energy > low.elements["C"].energy


def test_a_shift_the_schedule_does_not_allow(hp8):
    with pytest.raises(DynamicsError, match="clutch-to-clutch.*from '2' to '1', '3'"):
        simulate_shift(hp8, _spec(hp8), "2", "5")
    with pytest.raises(DynamicsError, match="both gear"):
        simulate_shift(hp8, _spec(hp8), "2", "2")


def test_an_element_without_capacity(hp8):
    spec = _spec(hp8)
    spec = DynamicsSpec(spec.inertias, {k: v for k, v in spec.elements.items() if k != "C"}, spec.drive, spec.load)
    with pytest.raises(DynamicsError, match="element 'C' has no capacity.*\\[clutch.capacity\\]"):
        simulate_shift(hp8, spec, "2", "3")


def test_a_profile_that_never_completes_is_stated(hp8):
    spec = _spec(hp8, pressures={"C": PressureProfile.constant(0.0, "C")}, duration=0.6)
    result = simulate_shift(hp8, spec, "2", "3")
    assert not result.completed and result.shift_time is None
    assert "not completed within the simulated 0.6 s" in result.status
    assert any(w.startswith("flare") for w in result.warnings)
    assert result.balance.relative_residual < 1e-6


def test_launch_from_standstill(hp8):
    engine = Engine(((800, 250.0), (2000, 350.0), (6500, 250.0)), throttle=0.4)
    spec = _spec(hp8, load=VehicleLoad(Vehicle(0.33, 2.8, mass=1800.0)), drive=engine, duration=1.5)
    spec = DynamicsSpec(spec.inertias, spec.elements, spec.drive, spec.load, input_speed=1500.0, duration=1.5)
    result = simulate_launch(hp8, spec)
    assert result.kind == "launch" and result.completed, result.status
    assert result.balance.relative_residual < 1e-6
    assert abs(result.traces.speeds["out"][0]) < 1e-9 and result.traces.speeds["out"][-1] > 0


def test_launch_needs_a_moving_output(hp8):
    with pytest.raises(DynamicsError, match="cannot be held"):
        simulate_launch(hp8, _spec(hp8))


@settings(max_examples=6, deadline=None)
@given(st.lists(st.tuples(st.floats(0.1, 0.9), st.floats(0.0, 15e5)), min_size=1, max_size=4),
       st.lists(st.tuples(st.floats(0.1, 0.9), st.floats(0.0, 15e5)), min_size=1, max_size=4))
def test_random_pressure_profiles_keep_the_energy_balance(hp8, on, off):
    profile = [(0.0, 0.0)] + sorted(on)
    release = [(0.0, 15e5)] + sorted(off)
    spec = _spec(hp8, pressures={"C": PressureProfile(tuple(profile), "C"), "A": PressureProfile(tuple(release), "A")},
                 duration=0.8)
    result = simulate_shift(hp8, spec, "2", "3")
    assert result.balance.relative_residual < 1e-6
    assert all(e.energy >= -1e-6 * result.balance.scale for e in result.elements.values())


@pytest.mark.parametrize("fast, slow", [(0.05, 0.3), (0.1, 0.2)])
def test_a_slower_torque_phase_never_raises_the_peak_clutch_power(hp8, fast, slow):
    peaks = []
    for ramp in (fast, slow):
        result = simulate_shift(hp8, _spec(hp8, controller=ShiftController(torque_phase=ramp), duration=1.2), "2", "3")
        assert result.completed
        peaks.append(max(e.peak_power for e in result.elements.values()))
    assert peaks[1] <= peaks[0] * (1 + 1e-9)


def test_a_tie_up_is_warned(hp8):
    # the on-coming element at line pressure at once while the off-going one still holds at line pressure
    spec = _spec(hp8, pressures={"C": PressureProfile(((0.0, 0.0), (0.1, 0.0), (0.11, 15e5)), "C"),
                                 "A": PressureProfile(((0.0, 15e5), (0.3, 15e5), (0.31, 0.0)), "A")})
    result = simulate_shift(hp8, spec, "2", "3")
    assert any(w.startswith("tie-up") and "'A'" in w for w in result.warnings), result.warnings
    assert result.balance.relative_residual < 1e-6


def test_a_common_element_beyond_its_capacity_is_warned(hp8):
    spec = _spec(hp8, pressures={"B": PressureProfile(((0.0, 15e5), (0.2, 15e5), (0.25, 1.6e5)), "B")})
    result = simulate_shift(hp8, spec, "2", "3")
    assert any(w.startswith("capacity exceeded: 'B'") for w in result.warnings), result.warnings
    assert result.balance.relative_residual < 1e-6


@pytest.mark.parametrize("old, new", [("1", "2"), ("3", "4"), ("4", "5"), ("5", "6"), ("6", "7"), ("7", "8"),
                                      ("4", "3")])
def test_every_single_swap_shift_of_the_example_completes_and_balances(old, new):
    from epicyclic.io import load_train_file
    from epicyclic.io.dynamics_format import dynamics_spec

    path = "examples/dynamics/zf_8hp70_shift.toml"
    t = Transmission.from_train_file(load_train_file(path))
    result = simulate_shift(t, dynamics_spec(open(path, encoding="utf-8").read(), path, t), old, new)
    assert result.completed, result.status
    assert result.balance.relative_residual < 1e-6
    assert not [w for w in result.warnings if w.startswith(("tie-up", "capacity"))], result.warnings
    final = result.traces.speeds["in"][-1] / result.traces.speeds["out"][-1]
    assert final == pytest.approx(t.ratio(new), rel=1e-9)
