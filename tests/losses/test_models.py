"""Loss models of sets and stages: meshes, planet bearings, drag; invariants with hypothesis."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic import Brake, GearStage, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.geometry import BasicRack, SetGeometry, StageGeometry, planetary_forces
from epicyclic.losses import (
    ConstantFriction,
    DragTorque,
    ElementLosses,
    LossModelError,
    Lubricant,
    PlanetBearing,
    SchlenkFriction,
    set_meshes,
    stage_meshes,
    tooth_loss_factor,
)

SIMPLE = PlanetarySet.simple("P", sun="in", ring="ring", carrier="out", z_sun=30, z_planet=24, z_ring=78)


def geometry(pset=SIMPLE, module=2.0, width=20.0, **kw):
    return SetGeometry.create(pset, module=module, face_width=width, **kw)


def test_set_meshes_load_and_speed_from_the_set_state():
    g = geometry()
    sun, ring = set_meshes(g)
    # sun mesh: F_bt = 1000 T_sun / (N r_b,sun); ring mesh: 1000 T_ring / (N r_b,ring) (Queitsch eqs. 23-25)
    assert sun.force_factor == pytest.approx(1000 / (3 * g.gears["sun"].base_diameter / 2))
    assert ring.force_factor == pytest.approx(1000 / (3 * g.gears["ring"].base_diameter / 2))
    # pitch-line speed relative to the carrier: |n_sun - n_c| ω r_w,sun = |n_p,rel| r_w,planet in both meshes
    r_w_sun = g.meshes[0].operating_pitch_diameters[0] / 2
    assert sun.speed_factor == pytest.approx(math.pi / 30 * r_w_sun / 1000)
    assert ring.speed_factor == pytest.approx(sun.speed_factor, rel=1e-12)
    # lossless: the same base-circle force at both meshes (the planet is balanced)
    t_sun, t_ring = 100.0, 260.0
    assert sun.force_factor * t_sun == pytest.approx(ring.force_factor * t_ring, rel=1e-12)
    assert (sun.loss_factor, ring.loss_factor) == (tooth_loss_factor(g.meshes[0]), tooth_loss_factor(g.meshes[1]))


def test_double_and_stepped_and_wolfrom_meshes():
    double = PlanetarySet.double_planet("D", sun="s", ring="r", carrier="c", z_sun=30, z_planet_sun=15,
                                        z_planet_ring=16, z_ring=78)
    meshes = set_meshes(geometry(double))
    assert [m.force_port for m in meshes] == ["sun", "ring", "ring"] and len(meshes) == 3
    wolfrom = PlanetarySet.two_rings("W", first="a", second="b", carrier="c", z_first=81, z_planet_first=27,
                                     z_planet_second=24, z_second=78)
    w = set_meshes(geometry(wolfrom))
    # both meshes internal: the planet turns at (z_first/z_p1)|n_a - n_c|; r_w of the planet gear in each mesh
    g = geometry(wolfrom)
    assert w[0].speed_factor == pytest.approx(math.pi / 30 * 81 / 27 * g.meshes[0].operating_pitch_diameters[0] / 2
                                              / 1000)
    assert all(m.mesh.internal for m in w)


def test_stage_meshes_carry_the_torque_through_the_chain():
    stage = GearStage.from_teeth("G", "a", "b", [(40, 44, "external"), (20, 64, "external")])
    g = StageGeometry(stage, BasicRack(2.0), face_width=20.0)
    first, second = stage_meshes(g)
    # mesh 2 is driven by the layshaft: torque × 44/40, speed × 40/44
    assert second.force_factor == pytest.approx(1000 * 44 / 40 / (g.meshes[1].gear1.base_diameter / 2))
    assert second.speed_factor == pytest.approx(math.pi / 30 * 40 / 44 * g.meshes[1].operating_pitch_diameters[0] / 2
                                                / 1000)
    assert first.force_factor == pytest.approx(1000 / (g.meshes[0].gear1.base_diameter / 2))
    internal = GearStage.from_teeth("I", "a", "b", [(80, 20, "internal")])  # the driving gear is the ring
    gi = StageGeometry(internal, BasicRack(2.0), face_width=20.0)
    assert not gi.driving_is_gear1(0) and gi.meshes[0].gear2.internal


def test_bearing_efficiency_from_the_tooth_forces():
    # the bearing loss is 0.5 μ d Σ F_b |ω_p - ω_c|, F_b from planetary_forces: check against a solved point
    g = geometry()
    bearing = PlanetBearing(16.0, "needle roller")
    eta_b = bearing.efficiency(g)
    sol = solve(GearTrain([SIMPLE, Brake("B", "ring")]),
                OperatingPoint(speeds={"in": 3000.0}, torques={"in": 100.0}, drives=["in"], loads=["out"]))
    forces = planetary_forces(sol, "P", g, load_sharing=1.0)
    omega_p = abs(sol.elements["P"].planet_speeds_relative[0]) * math.pi / 30
    loss = sum(0.5 * 0.0020 * 16.0 * b.bearing_load / 1000 * omega_p for b in forces.bodies)
    rolling = abs(sol.elements["P"].rolling_power)
    assert 1 - eta_b == pytest.approx(loss / rolling, rel=1e-12)
    assert PlanetBearing(16.0, 0.0011).coefficient == 0.0011
    with pytest.raises(LossModelError, match="unknown bearing type 'ball'"):
        PlanetBearing(16.0, "ball")
    with pytest.raises(LossModelError, match="bore must be a positive diameter"):
        PlanetBearing(0.0)


def test_element_losses_split_and_drag_torques():
    g = geometry()
    model = ElementLosses.for_set(g, friction=ConstantFriction(0.05), bearing=PlanetBearing(16.0),
                                  drag=[DragTorque("carrier", (0.1, 1e-4)), DragTorque("sun", (0.0, 1e-5),
                                                                                          relative_to="carrier")])
    speeds = {"sun": np.array([3000.0]), "ring": np.array([0.0]), "carrier": np.array([833.3])}
    torques = {"sun": np.array([100.0]), "ring": np.array([260.0]), "carrier": np.array([-360.0])}
    state = model.evaluate(speeds, torques)
    h = [m.loss_factor for m in model.meshes]
    assert state.factors["mesh"][0] == pytest.approx((1 - 0.05 * h[0]) * (1 - 0.05 * h[1]))
    assert state.factors["bearing"][0] == pytest.approx(PlanetBearing(16.0).efficiency(g))
    # carrier drag: 0.1 + 1e-4·833.3 N·m against the carrier; sun drag relative to the carrier
    carrier_drag = 0.1 + 1e-4 * 833.3
    sun_drag = 1e-5 * (3000 - 833.3)
    assert state.torques["out"][0] == pytest.approx(-carrier_drag + sun_drag)
    assert state.torques["in"][0] == pytest.approx(-sun_drag)
    assert state.torques["housing"][0] == pytest.approx(carrier_drag)
    assert sum(v[0] for v in state.torques.values()) == pytest.approx(0.0, abs=1e-12)  # reactions balance
    expected = (carrier_drag * 833.3 + sun_drag * (3000 - 833.3)) * math.pi / 30
    assert state.drag_loss[0] == pytest.approx(expected)
    # without a friction model the element's own η0 is the mesh factor
    plain = ElementLosses(PlanetarySet("Q", "a", "b", "c", -2.0, 0.97), drag=[DragTorque("carrier", (0.1,))])
    assert plain.evaluate({"sun": 1.0, "ring": 0.0, "carrier": 1 / 3}, {"sun": 1.0, "ring": 2.0, "carrier": -3.0}
                          ).factors["mesh"] == pytest.approx(0.97)
    with pytest.raises(LossModelError, match="'planet', which is not a member"):
        ElementLosses(SIMPLE, drag=[DragTorque("planet", (0.1,))])
    with pytest.raises(LossModelError, match="needs the meshes"):
        ElementLosses(SIMPLE, friction=ConstantFriction(0.05))


@settings(max_examples=80, deadline=None)
@given(st.floats(0.0, 0.15), st.floats(0.0, 0.15), st.floats(-6000.0, 6000.0), st.floats(0.1, 2000.0))
def test_mesh_efficiency_in_0_1_and_rises_as_friction_falls(mu_low, mu_high, speed, torque):
    lo, hi = sorted((mu_low, mu_high))
    g = geometry()
    speeds = {"sun": np.array([speed]), "ring": np.array([0.0]), "carrier": np.array([speed / 3.6])}
    torques = {"sun": np.array([torque]), "ring": np.array([2.6 * torque]), "carrier": np.array([-3.6 * torque])}
    eta_lo = ElementLosses.for_set(g, friction=ConstantFriction(lo)).evaluate(speeds, torques).efficiency[0]
    eta_hi = ElementLosses.for_set(g, friction=ConstantFriction(hi)).evaluate(speeds, torques).efficiency[0]
    assert 0 < eta_hi <= eta_lo <= 1
    if lo == 0.0:
        assert eta_lo == 1.0  # μ → 0: no mesh loss


@settings(max_examples=80, deadline=None)
@given(st.lists(st.floats(0.0, 1e-3), min_size=1, max_size=4), st.floats(0.0, 8000.0), st.floats(0.0, 8000.0))
def test_drag_loss_is_positive_and_grows_with_speed(coefficients, n1, n2):
    drag = DragTorque("carrier", coefficients)
    lo, hi = sorted((n1, n2))
    assert 0.0 <= drag.loss(lo) <= drag.loss(hi)
    assert drag.loss(-hi) == pytest.approx(drag.loss(hi))  # opposes either direction of rotation


@settings(max_examples=40, deadline=None)
@given(st.floats(1.0, 2000.0), st.floats(10.0, 6000.0), st.floats(1.0, 200.0), st.floats(0.1, 2.0))
def test_schlenk_set_efficiency_is_below_one(torque, speed, viscosity, roughness):
    g = geometry()
    model = ElementLosses.for_set(g, friction=SchlenkFriction(Lubricant(viscosity), roughness))
    speeds = {"sun": np.array([speed]), "ring": np.array([0.0]), "carrier": np.array([speed / 3.6])}
    torques = {"sun": np.array([torque]), "ring": np.array([2.6 * torque]), "carrier": np.array([-3.6 * torque])}
    eta = model.evaluate(speeds, torques).efficiency[0]
    assert 0.9 < eta < 1.0


def test_a_load_beyond_the_friction_correlation_is_an_error_not_a_negative_efficiency():
    # Schlenk's μ grows as (load per face width)^0.2: at 1e12 N·m on a 20 mm set μ·H_V passes 1.
    sun, _ = set_meshes(geometry())
    friction = SchlenkFriction(Lubricant(30.0), 0.4)
    eta, mu = sun.efficiency(friction, np.array([100.0]), np.array([2000.0]))
    assert 0.98 < eta[0] < 1.0 and 0.01 < mu[0] < 0.1
    with pytest.raises(LossModelError, match=r"mesh sun-planet: the coefficient of friction .* leaves no efficiency"):
        sun.efficiency(friction, np.array([100.0, 1e300]), np.array([2000.0, 2000.0]))
    with pytest.raises(LossModelError, match="leaves no efficiency"):  # a NaN load is never an efficiency
        sun.efficiency(friction, np.array([np.nan]), np.array([2000.0]))
