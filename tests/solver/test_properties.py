"""Invariants of the general solver over random trains and operating points (hypothesis).

* torque balance at every shaft: external torque = Σ port torques of the elements on it;
* power balance: Σ external power = total loss ≥ 0 (power positive into the train);
* 0 < η ≤ 1 where defined; η = 1 and loss = 0 when every η0 = 1;
* speeds satisfy the Willis equation of every set and the ratio of every stage;
* ideal trains are reversible: swapping drive and load keeps the ratio and η = 1.
"""

import math

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from epicyclic import (
    Brake,
    Clutch,
    EpicyclicError,
    GearStage,
    GearTrain,
    OperatingPoint,
    PlanetarySet,
    solve,
)

ratios = st.one_of(st.floats(-12.0, -1.2), st.floats(1.05, 6.0), st.floats(0.15, 0.9))
efficiencies = st.floats(0.5, 1.0)
speeds = st.floats(50.0, 6000.0).flatmap(lambda v: st.sampled_from([v, -v]))
torques = st.floats(0.1, 500.0)
members = ("sun", "ring", "carrier")


@st.composite
def single_set_trains(draw):
    """One set, one member held: drive one of the others, load the third."""
    i0, eta = draw(ratios), draw(efficiencies)
    held = draw(st.sampled_from(members))
    drive, load = draw(st.permutations([m for m in members if m != held]))
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", i0, eta), Brake("B", held)])
    return train, drive, load


@st.composite
def closed_trains(draw):
    """Brandenberger's Bild 10–12: a set whose two shafts are also joined by a fixed-axis stage."""
    i0, eta, eta_stage = draw(ratios), draw(efficiencies), draw(efficiencies)
    first, second = draw(st.permutations(members).map(lambda p: p[:2]))
    third = next(m for m in members if m not in (first, second))
    stage_ratio = draw(st.one_of(st.floats(-6.0, -0.2), st.floats(0.2, 6.0)))
    assume(abs(stage_ratio - 1.0) > 0.05)
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", i0, eta),
                       GearStage("G", first, second, stage_ratio, eta_stage)])
    drive, load = draw(st.permutations([first, third]))
    return train, drive, load


@st.composite
def compound_trains(draw):
    """Two sets: Simpson-like (suns joined, ring 1 = carrier 2), one brake, a clutch state."""
    i1, i2 = draw(st.floats(-6.0, -1.3)), draw(st.floats(-6.0, -1.3))
    e1, e2 = draw(efficiencies), draw(efficiencies)
    held = draw(st.sampled_from(["c1", "r2", "s"]))
    train = GearTrain([
        PlanetarySet("P1", "s", "out", "c1", i1, e1),
        PlanetarySet("P2", "s", "r2", "out", i2, e2),
        Brake("B", held),
    ])
    inputs = [x for x in ("s", "r2", "c1") if x != held]
    drive = draw(st.sampled_from(inputs))
    return train, drive, "out"


any_train = st.one_of(single_set_trains(), closed_trains(), compound_trains())


def solve_or_skip(train, op):
    try:
        return solve(train, op)
    except EpicyclicError:
        assume(False)  # e.g. a mode where drive and load stand still for this combination


def check_invariants(sol):
    train = sol.train
    # torque balance at every shaft
    for shaft in train.shafts:
        on_elements = sum(
            t for e in sol.elements.values() for port, t in e.torques.items() if e.ports[port] == shaft
        )
        scale = max(1.0, max(abs(t) for e in sol.elements.values() for t in e.torques.values()))
        assert sol.shafts[shaft].torque == pytest.approx(on_elements, abs=1e-9 * scale)
    # power balance: Σ P = Σ losses
    total = sum(s.power for s in sol.shafts.values())
    scale = max(1.0, sol.input_power, max(abs(s.power) for s in sol.shafts.values()))
    assert total == pytest.approx(sol.loss, abs=1e-9 * scale)
    # Willis for every set, ratio for every stage
    for element in train.elements:
        n = {p: sol.elements[element.name].speeds[p] for p in sol.elements[element.name].ports}
        if isinstance(element, PlanetarySet):
            i0 = element.stationary_ratio
            residual = n["sun"] - i0 * n["ring"] - (1 - i0) * n["carrier"]
            assert residual == pytest.approx(0, abs=1e-9 * max(1.0, *map(abs, n.values())))
        elif isinstance(element, GearStage):
            assert n["first"] == pytest.approx(element.ratio * n["second"], rel=1e-9, abs=1e-9)
    if sol.self_locking is None:
        assert sol.loss >= -1e-9 * scale
        for e in sol.elements.values():
            assert e.loss >= -1e-9 * scale
        if sol.efficiency is not None:
            assert 0 < sol.efficiency <= 1.0
    else:
        assert sol.efficiency is None


@settings(max_examples=150, deadline=None)
@given(any_train, speeds, torques, st.booleans())
def test_invariants_hold(case, speed, torque, torque_at_load):
    train, drive, load = case
    given_at = load if torque_at_load else drive
    op = OperatingPoint(speeds={drive: speed}, torques={given_at: torque}, drives=[drive], loads=[load])
    sol = solve_or_skip(train, op)
    check_invariants(sol)
    check_invariants(sol.ideal)
    if sol.ideal.input_power > 0:  # a train may hold its load still: then no power flows (issue 13)
        assert sol.ideal.efficiency == pytest.approx(1.0, rel=1e-9)
    else:
        assert sol.ideal.efficiency is None and sol.ideal.output_power == 0.0
    assert sol.ideal.loss == pytest.approx(0.0, abs=1e-9 * max(1.0, sol.ideal.input_power))


@settings(max_examples=100, deadline=None)
@given(any_train, speeds, torques)
def test_lossless_trains_have_unit_efficiency_and_are_reversible(case, speed, torque):
    train, drive, load = case
    ideal = GearTrain(
        tuple(
            PlanetarySet(e.name, e.sun, e.ring, e.carrier, e.stationary_ratio, 1.0) if isinstance(e, PlanetarySet)
            else GearStage(e.name, e.first, e.second, e.ratio, 1.0) if isinstance(e, GearStage) else e
            for e in train.elements
        )
    )
    forward = solve_or_skip(ideal, OperatingPoint(speeds={drive: speed}, torques={drive: torque},
                                                  drives=[drive], loads=[load]))
    backward = solve_or_skip(ideal, OperatingPoint(speeds={drive: speed}, torques={load: abs(forward.torque(load))},
                                                   drives=[load], loads=[drive]))
    assert forward.efficiency == pytest.approx(1.0, rel=1e-9)
    assert backward.efficiency == pytest.approx(1.0, rel=1e-9)
    assert backward.speed(load) == pytest.approx(forward.speed(load), rel=1e-9)
    # reversed power flow: same magnitudes of torque, opposite roles
    assert abs(backward.torque(drive)) == pytest.approx(abs(forward.torque(drive)), rel=1e-9)
    assert not forward.is_self_locking and not backward.is_self_locking


@settings(max_examples=60, deadline=None)
@given(single_set_trains(), speeds, torques)
def test_efficiency_falls_with_stationary_efficiency(case, speed, torque):
    """A lossier set never gives a higher overall efficiency (Brandenberger's rule is monotone)."""
    train, drive, load = case
    planetary = train.element("P")
    assume(planetary.stationary_efficiency < 0.999)
    better = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", planetary.stationary_ratio,
                                     min(1.0, planetary.stationary_efficiency + 0.001)), train.element("B")])
    op = OperatingPoint(speeds={drive: speed}, torques={drive: torque}, drives=[drive], loads=[load])
    low, high = solve_or_skip(train, op), solve_or_skip(better, op)
    if low.efficiency is not None and high.efficiency is not None:
        assert low.efficiency <= high.efficiency + 1e-12
    if high.is_self_locking:
        assert low.is_self_locking
    assert math.isfinite(low.loss)
