"""Losses given to the general solver: efficiency factors by source and loss torques on shafts."""

from __future__ import annotations

import math

import numpy as np
import pytest

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.errors import EfficiencyError, ModelError
from epicyclic.solver.batch import solve_batch
from epicyclic.solver.given_losses import with_efficiencies

#: A minus set with two drives and the carrier as load: no element has a port at the housing.
FREE = GearTrain([PlanetarySet("P", "s", "r", "c", -2.0, 0.97)])
FREE_OP = OperatingPoint(speeds={"s": 3000.0, "r": 500.0}, torques={"s": 10.0}, drives=["s", "r"], loads=["c"])
#: Ring held: sun drives the carrier (Brandenberger's rule: η = (1 − i0·η0)/(1 − i0)).
HELD = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", -2.0, 1.0), Brake("B", "ring")])
HELD_OP = OperatingPoint(speeds={"sun": 3000.0}, torques={"sun": 10.0}, drives=["sun"], loads=["carrier"])


def test_factors_multiply_into_eta0_and_split_the_loss_by_their_logarithms():
    # Brandenberger 1952, eq. 7: minus set, ring held, η = (1 − i0·η0)/(1 − i0) with η0 = 0.98·0.99.
    sol = solve(HELD, HELD_OP, efficiencies={"P": {"mesh": 0.98, "bearing": 0.99}})
    eta0 = 0.98 * 0.99
    assert sol.efficiency == pytest.approx((1 + 2 * eta0) / 3, rel=1e-14)
    parts = sol.elements["P"].loss_sources
    assert parts["mesh"] / parts["bearing"] == pytest.approx(math.log(0.98) / math.log(0.99), rel=1e-12)
    assert parts["mesh"] + parts["bearing"] == pytest.approx(sol.loss, rel=1e-14)
    assert sol.train is HELD  # the solution describes the train as given


def test_a_loss_torque_enters_the_torque_balance_and_its_reaction_the_housing():
    # Drag of 0.5 N·m on the carrier, reacted by the housing, where no element has a port.
    plain = solve(FREE, FREE_OP)
    sol = solve(FREE, FREE_OP, loss_torques={"P": {"c": -0.5, "housing": 0.5}})
    omega_c = sol.shafts["c"].speed * math.pi / 30
    assert sol.elements["P"].loss_sources["drag"] == pytest.approx(0.5 * omega_c, rel=1e-14)
    assert sol.shafts["housing"].torque == -0.5
    assert sol.input_power - sol.output_power == pytest.approx(sol.loss, rel=1e-12)
    assert sol.loss == pytest.approx(plain.loss + 0.5 * omega_c, rel=1e-12)
    # the drives keep their speeds and the given sun torque; the load takes 0.5 N·m less
    assert sol.shafts["s"].torque == 10.0
    assert sol.shafts["c"].torque == pytest.approx(plain.shafts["c"].torque + 0.5, rel=1e-14)


def test_batch_takes_per_point_factors_and_torques():
    speeds = np.array([500.0, 3000.0, 6000.0])
    mesh = np.array([0.99, 0.95, 0.9])
    drag = np.array([-0.1, -0.3, -0.6])
    batch = solve_batch(HELD, speeds={"sun": speeds}, torques={"sun": 10.0}, drives=["sun"], loads=["carrier"],
                        efficiencies={"P": {"mesh": mesh}}, loss_torques={"P": {"carrier": drag,
                                                                               "housing": -drag}})
    for k in range(3):
        op = OperatingPoint(speeds={"sun": speeds[k]}, torques={"sun": 10.0}, drives=["sun"], loads=["carrier"])
        one = solve(HELD, op, efficiencies={"P": {"mesh": mesh[k]}},
                    loss_torques={"P": {"carrier": drag[k], "housing": -drag[k]}})
        assert batch.efficiency[k] == pytest.approx(one.efficiency, abs=1e-14)
        for source, value in one.elements["P"].loss_sources.items():
            assert batch.loss_sources["P"][source][k] == pytest.approx(value, rel=1e-12)


def test_without_given_losses_the_element_eta0_is_the_mesh_source():
    sol = solve(FREE, FREE_OP)
    assert sol.elements["P"].loss_sources == {"mesh": sol.elements["P"].loss}
    assert solve(FREE, FREE_OP, efficiencies={}, loss_torques={}).efficiency == sol.efficiency


def test_with_efficiencies_replaces_only_what_changes():
    assert with_efficiencies(HELD, {"P": 1.0}) is HELD
    other = with_efficiencies(HELD, {"P": 0.9, "B": 0.5})
    assert other.element("P").stationary_efficiency == 0.9 and other.element("B") is HELD.element("B")


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"efficiencies": {"Q": {"mesh": 0.9}}}, ModelError, "no element 'Q'"),
        ({"efficiencies": {"B": {"mesh": 0.9}}}, ModelError, "'B' is a clutch or brake"),
        ({"efficiencies": {"P": {"mesh": 0.0}}}, EfficiencyError, r"mesh efficiency of 'P' must lie in \(0, 1\]"),
        ({"efficiencies": {"P": {"mesh": float("nan")}}}, EfficiencyError, r"must lie in \(0, 1\]"),
        ({"loss_torques": {"P": {"moon": 1.0}}}, ModelError, "'moon', which is not a shaft"),
        ({"loss_torques": {"P": {"carrier": float("inf")}}}, ModelError, "must be finite"),
    ],
)
def test_bad_given_losses_name_the_element_and_value(kwargs, error, match):
    with pytest.raises(error, match=match):
        solve(HELD, HELD_OP, **kwargs)
