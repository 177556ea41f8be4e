"""Loss models through the general solver: zero losses change nothing, balances, batch = scalar, invariants."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic import Brake, EpicyclicError, GearStage, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.demo import brandenberger_1952
from epicyclic.geometry import BasicRack, SetGeometry, StageGeometry
from epicyclic.io import load_train_file
from epicyclic.losses import (
    ConstantFriction,
    DragTorque,
    ElementLosses,
    LossModelError,
    Lubricant,
    PlanetBearing,
    SchlenkFriction,
    efficiency_map,
    solve_batch_with_losses,
    solve_with_losses,
)
from epicyclic.solver.batch import solve_batch

EXAMPLES = __import__("pathlib").Path(__file__).resolve().parents[2] / "examples"


def test_zero_new_losses_change_nothing():
    # Brandenberger 1952, Bild 10: giving every element its own η0 as a factor, and no torques, must
    # reproduce the plain solve exactly (η' = 0.8494).
    train, op = brandenberger_1952()
    plain = solve(train, op)
    own = {e.name: {"mesh": e.stationary_efficiency if hasattr(e, "stationary_efficiency") else e.efficiency}
           for e in train.elements if hasattr(e, "ratio") or hasattr(e, "stationary_ratio")}
    same = solve(train, op, efficiencies=own, loss_torques={})
    assert same.efficiency == pytest.approx(plain.efficiency, rel=1e-14)
    for name, state in plain.elements.items():
        assert same.elements[name].torques == pytest.approx(dict(state.torques), rel=1e-13, abs=1e-12)
    assert round(plain.efficiency, 2) == 0.85
    # a model with no friction, bearing or drag leaves the element's η0 as it is
    models = {"planetary": ElementLosses(train.element("planetary"))}
    assert solve_with_losses(train, op, models).efficiency == pytest.approx(plain.efficiency, rel=1e-14)


def test_fzg_c40_as_a_gear_stage_through_the_solver():
    # The published FZG C40 point (GEARpie report C40: 215.5 N·m at 1800 1/min, P320 at 80 °C, μ = 0.0256,
    # P_VZP = 206.31 W with H_VL 0.1984) as a fixed-axis stage from a file-like model: the solver's loss of
    # the stage is the mesh loss μ H_V P (H_V 0.1986: +0.1 %).
    stage = GearStage.from_teeth("C40", "pinion", "wheel", [(16, 24, "external")])
    rack = BasicRack(4.5)
    geom = StageGeometry(stage, rack, [(0.1817, 0.1715)], face_width=40.0, tip_shortening=False)
    model = ElementLosses.for_stage(geom, friction=SchlenkFriction(Lubricant(49.85, 0.65), 0.355))
    op = OperatingPoint(speeds={"pinion": 1800.0}, torques={"pinion": 215.5}, drives=["pinion"], loads=["wheel"])
    sol = solve_with_losses(GearTrain([stage]), op, {"C40": model})
    p_in = 215.5 * 1800 * math.pi / 30
    assert sol.input_power == pytest.approx(p_in)
    assert sol.loss == pytest.approx(206.31 * 0.1986 / 0.1984 * p_in / 40623.2, rel=2e-3)
    assert sol.elements["C40"].loss_sources["mesh"] == pytest.approx(sol.loss)
    assert sol.efficiency == pytest.approx(1 - 0.0256 * 0.1986, abs=5e-5)


def test_sources_balance_the_power_and_batch_equals_scalar():
    f = load_train_file(EXAMPLES / "geometry_simple_set.toml")
    sol = f.solve()
    sources = sol.loss_sources
    assert set(sources) == {"mesh", "bearing", "drag"} and min(sources.values()) > 0
    assert sol.input_power - sol.output_power == pytest.approx(sum(sources.values()), rel=1e-9)
    assert sol.loss == pytest.approx(sum(sources.values()), rel=1e-12)
    speeds = np.array([[800.0, 2500.0], [4000.0, 6000.0]])
    torques = np.array([[15.0, 60.0], [120.0, 30.0]])
    batch = solve_batch_with_losses(f.train, f.losses, speeds={"in": speeds}, torques={"in": torques},
                                    drives=["in"], loads=["out"])
    for idx in np.ndindex(speeds.shape):
        one = solve_with_losses(f.train, OperatingPoint(speeds={"in": speeds[idx]}, torques={"in": torques[idx]},
                                                        drives=["in"], loads=["out"]), f.losses)
        assert batch.efficiency[idx] == pytest.approx(one.efficiency, abs=1e-12)
        for source, value in one.elements["P"].loss_sources.items():
            assert batch.loss_sources["P"][source][idx] == pytest.approx(value, rel=1e-9)


def test_given_losses_errors_name_the_problem():
    train, op = brandenberger_1952()
    with pytest.raises(Exception, match="no element 'Q'"):
        solve(train, op, efficiencies={"Q": {"mesh": 0.9}})
    with pytest.raises(Exception, match=r"must lie in \(0, 1\]"):
        solve(train, op, efficiencies={"planetary": {"mesh": 1.5}})
    with pytest.raises(Exception, match="'nowhere', which is not a shaft"):
        solve(train, op, loss_torques={"planetary": {"nowhere": 1.0}})
    with pytest.raises(LossModelError, match="no element 'X'"):
        solve_with_losses(train, op, {"X": ElementLosses(train.element("planetary"))})


def test_transmission_map_and_coast():
    f = load_train_file(EXAMPLES / "zf_8hp70_geometry.toml")
    drive = efficiency_map(f, [1000.0, 4000.0], [50.0, 300.0], gear="3")
    coast = efficiency_map(f, [1000.0, 4000.0], [50.0, 300.0], gear="3", direction="coast")
    assert drive.ratio == pytest.approx(2.1039, abs=5e-5)  # published 8HP 70 3rd gear
    assert np.all((drive.efficiency > 0.9) & (drive.efficiency < 1.0))
    assert np.all((coast.efficiency > 0.9) & (coast.efficiency < 1.0))
    # drag grows with speed, the mesh loss with torque
    assert np.all(np.diff(drive.losses["drag"], axis=1) > 0)
    assert np.all(np.diff(drive.losses["mesh"], axis=0) > 0)
    assert drive.to_csv().count("\n") == 5 and "loss_drag_W" in drive.to_csv()


SET = PlanetarySet.simple("P", sun="in", ring="ring", carrier="out", z_sun=30, z_planet=24, z_ring=78)
GEOMETRY = SetGeometry.create(SET, module=2.0, face_width=20.0)
TRAIN = GearTrain([SET, Brake("B", "ring")])


BEARING = PlanetBearing(16.0).efficiency(GEOMETRY)
MESHES = ElementLosses.for_set(GEOMETRY, friction=ConstantFriction(0.05)).meshes


def _solve(mu, drag, speed, torque, sign=1.0):
    model = ElementLosses(SET, MESHES, ConstantFriction(mu), BEARING, (DragTorque("carrier", drag),))
    drive, load = ("in", "out") if sign > 0 else ("out", "in")
    op = OperatingPoint(speeds={"in": speed}, torques={drive: torque}, drives=[drive], loads=[load])
    return solve_with_losses(TRAIN, op, {"P": model})


@settings(max_examples=25, deadline=None)
@given(st.floats(0.0, 0.12), st.floats(0.0, 0.12), st.lists(st.floats(0.0, 1e-4), min_size=1, max_size=3),
       st.floats(100.0, 6000.0), st.floats(5.0, 500.0), st.sampled_from([1.0, -1.0]))
def test_losses_positive_efficiency_below_one_and_rising_as_friction_falls(mu1, mu2, drag, speed, torque, sign):
    lo, hi = sorted((mu1, mu2))
    rough, smooth = _solve(hi, drag, speed, torque, sign), _solve(lo, drag, speed, torque, sign)
    for sol in (rough, smooth):
        assert all(v >= 0.0 for e in sol.elements.values() for v in e.loss_sources.values())
        assert sol.loss >= 0.0
        if sol.efficiency is not None:
            assert 0.0 < sol.efficiency <= 1.0
        assert sol.input_power - sol.output_power == pytest.approx(sol.loss, rel=1e-9, abs=1e-9)
    if rough.efficiency is not None and smooth.efficiency is not None:
        assert smooth.efficiency >= rough.efficiency - 1e-12


@settings(max_examples=20, deadline=None)
@given(st.lists(st.floats(1e-6, 1e-3), min_size=1, max_size=3), st.floats(100.0, 3000.0), st.floats(1.05, 3.0),
       st.floats(5.0, 300.0))
def test_drag_loss_grows_with_speed_through_the_solver(drag, speed, factor, torque):
    slow, fast = _solve(0.05, drag, speed, torque), _solve(0.05, drag, speed * factor, torque)
    assert fast.elements["P"].loss_sources["drag"] > slow.elements["P"].loss_sources["drag"] > 0


def test_batch_with_given_losses_matches_scalar_for_plain_trains():
    # the solver hook alone (no loss model): per-point efficiencies and a drag torque on the carrier
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", -2.0, 0.97), Brake("B", "ring")])
    speeds = np.array([500.0, 1500.0, 3000.0])
    etas = np.array([0.95, 0.97, 0.99])
    drag = -0.02 * np.sign(speeds / 3)
    batch = solve_batch(train, speeds={"sun": speeds}, torques={"sun": 10.0}, drives=["sun"], loads=["carrier"],
                        efficiencies={"P": {"mesh": etas}},
                        loss_torques={"P": {"carrier": drag, "housing": -drag}})
    for j in range(3):
        one = solve(train, OperatingPoint(speeds={"sun": speeds[j]}, torques={"sun": 10.0}, drives=["sun"],
                                          loads=["carrier"]),
                    efficiencies={"P": {"mesh": etas[j]}}, loss_torques={"P": {"carrier": drag[j],
                                                                                "housing": -drag[j]}})
        assert batch.efficiency[j] == pytest.approx(one.efficiency, abs=1e-13)
        # closed form: η = (1 − i0 η0)/(1 − i0) for the mesh, minus the drag power over the input
        p_in = 10.0 * speeds[j] * math.pi / 30
        drag_loss = 0.02 * speeds[j] / 3 * math.pi / 30
        mesh_only = (1 + 2 * etas[j]) / 3
        assert one.efficiency == pytest.approx(mesh_only - drag_loss / p_in, rel=1e-12)
        assert one.elements["P"].loss_sources["drag"] == pytest.approx(drag_loss, rel=1e-12)


def test_transmission_gears_use_the_files_loss_models():
    from epicyclic.transmission import Transmission
    from epicyclic.transmission.batch import solve_gears

    t = Transmission.from_file(EXAMPLES / "zf_8hp70_geometry.toml")
    assert set(t.losses) == {"P1", "P2", "P3", "P4"}
    result = t.analyze("3", input_speed=2000.0, input_torque=200.0)
    f = load_train_file(EXAMPLES / "zf_8hp70_geometry.toml")
    emap = efficiency_map(f, [2000.0], [200.0], gear="3")
    assert result.drive.efficiency == pytest.approx(float(emap.efficiency[0, 0]), abs=1e-12)
    batch = solve_gears(t, input_speed=[2000.0], input_torque=[200.0], gears=["3"])
    assert batch.efficiency("3")[0] == pytest.approx(result.drive.efficiency, abs=1e-12)
    assert 0.98 < result.drive.efficiency < 1.0


def test_efficiency_map_takes_units_and_is_read_only():
    # regressions: a pint array in rad/s was stripped of its unit (UnitStrippedWarning) and read as
    # 1/min, a silently wrong map; "1000 U/min" was a bare ValueError; map.efficiency[0, 0] = 5 and
    # map.losses["mesh"] = ... changed a frozen result
    import pint

    ureg = pint.UnitRegistry()
    f = load_train_file("examples/zf_8hp70_geometry.toml")
    plain = efficiency_map(f, [1000.0, 2000.0], [98.0665, 200.0], gear="3")
    rad_s = np.array([1000.0, 2000.0]) * np.pi / 30
    for speeds, torques in ((["1000 U/min", "2000 rpm"], ["10 kp*m", "200 N*m"]),
                            (rad_s * ureg("rad/s"), np.array([0.0980665, 0.2]) * ureg("kN*m"))):
        emap = efficiency_map(f, speeds, torques, gear="3")
        assert emap.speeds == pytest.approx(plain.speeds, rel=1e-12)
        assert emap.torques == pytest.approx([98.0665, 200.0], rel=1e-12)
        assert emap.efficiency == pytest.approx(plain.efficiency, rel=1e-12)
    with pytest.raises(EpicyclicError, match=r"efficiency_map: speeds\[1\]: '2 kW' is not a speed"):
        efficiency_map(f, ["1000 rpm", "2 kW"], [100.0], gear="3")
    with pytest.raises(ValueError, match="read-only"):
        plain.efficiency[0, 0] = 5.0
    with pytest.raises(TypeError):
        plain.losses["mesh"] = plain.loss
