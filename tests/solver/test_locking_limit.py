"""A set exactly at (and round-off away from) its self-locking limit i0·η0^w = 1.

Closed form (Brandenberger 1952, eq. 7 and text to Bild 9; the same rule in Pennestrì &
Freudenstein 1993): with the loss direction w the lever rows are T_r = −i0·η0^w·T_s and
T_c = −(1 − i0·η0^w)·T_s, so a given carrier torque needs T_s = −T_c/(1 − i0·η0^w): at
i0·η0^w = 1 exactly that torque is unbounded, and next to it (1e-12 away) the formal efficiency is
of the order of the distance (4e-12), below the self-locking margin.  The verdict on both sides and
at the limit is therefore "self-locks", never an error: at i0 = η0 = 0.75 with the sun held and the
ring at 1000 1/min, w = −1 (the ring drives the sun relative to the carrier) and i0/η0 = 1.

The one-degree-of-freedom train at the same limit (ring held) is the textbook case: driving from the
sun with the carrier torque given (Brandenberger: "ins Schnelle getrieben ... η = b/d/a/c") the
drive torque is unbounded.  The numbers 0.75 are exact binary fractions, so i0/η0 = 1 exactly.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.solver.batch import solve_batch

LIMIT = 0.75


def _two_dof(eta, n_sun=0.0, n_ring=1000.0):
    train = GearTrain([PlanetarySet("P", "s", "r", "c", LIMIT, eta)])
    return train, OperatingPoint(speeds={"s": n_sun, "r": n_ring}, torques={"c": 1.0}, loads=["c"],
                                 connected=["s", "r"])


# exactly at the limit, one and a few units in the last place away, 1e-14 and 1e-12 away
OFFSETS = [0.0, 1.1e-16, -1.1e-16, 1e-15, -1e-15, 1e-14, -1e-14, 1e-12, -1e-12]


@pytest.mark.parametrize("offset", OFFSETS)
def test_two_dof_set_at_and_next_to_its_limit_self_locks(offset):
    train, point = _two_dof(LIMIT + offset)
    sol = solve(train, point)
    assert sol.is_self_locking and sol.efficiency is None
    assert "self-locks" in sol.self_locking.message
    assert sol.self_locking.thresholds["P"] == pytest.approx(LIMIT, rel=1e-9)
    formal = sol.self_locking.formal_efficiency
    assert formal is None or abs(formal) < 1e-9   # of the order of the distance from the limit
    assert all(math.isfinite(s.torque) and math.isfinite(s.power) for s in sol.shafts.values())


def test_exact_limit_says_so_and_shows_the_lossless_numbers():
    train, point = _two_dof(LIMIT)
    sol = solve(train, point)
    assert "exactly at its self-locking limit" in sol.self_locking.message
    assert "give a torque" not in sol.self_locking.message
    assert sol.self_locking.formal_efficiency is None   # unbounded torques: no formal ratio
    # no finite lossy state exists: the lossless one is shown (T_s = −T_c/(1 − i0) = −4 N·m)
    assert sol.torque("s") == pytest.approx(-4.0 * sol.torque("c"), rel=1e-12)
    assert sol.loss == 0.0
    assert sol.warnings == sol.ideal.warnings   # made, no error


@pytest.mark.parametrize("i0, eta", [(0.75, 0.75), (0.5, 0.5), (2.0, 0.5)])
def test_exact_limit_two_dof_agrees_with_the_closed_form(i0, eta):
    """Where a finite consistent state exists at the limit it is returned; where none, self-locking."""
    rng = np.random.default_rng(5)
    for n_sun, n_ring in rng.uniform(-3000.0, 3000.0, (40, 2)):
        n_carrier = (n_sun - i0 * n_ring) / (1.0 - i0)
        if abs(n_carrier) < 1.0 or abs(n_sun - n_carrier) < 1.0:
            continue
        t_carrier = -math.copysign(1.0, n_carrier)   # a load of 1 N·m at the carrier
        states = [w for w in (1, -1) if 1.0 - i0 * eta**w != 0.0
                  and -t_carrier / (1.0 - i0 * eta**w) * (n_sun - n_carrier) * w > 0]
        train = GearTrain([PlanetarySet("P", "s", "r", "c", i0, eta)])
        sol = solve(train, OperatingPoint(speeds={"s": n_sun, "r": n_ring}, torques={"c": 1.0}, loads=["c"],
                                          connected=["s", "r"]))
        if states:
            assert not sol.is_self_locking and sol.elements["P"].loss_direction == states[0]
        else:
            assert sol.is_self_locking


@pytest.mark.parametrize("offset", [0.0, 1e-14, 1e-12])
def test_one_dof_train_with_the_load_torque_given_at_the_limit_self_locks(offset):
    train = GearTrain([PlanetarySet("P", "s", "r", "c", LIMIT, LIMIT + offset), Brake("B", "r")])
    for given in ("s", "c"):   # drive torque given (bounded) or load torque given (unbounded drive torque)
        sol = solve(train, OperatingPoint(speeds={"s": 1000.0}, torques={given: 1.0}, drives=["s"], loads=["c"]))
        assert sol.is_self_locking, given
        assert "-0" not in sol.self_locking.message   # a formal efficiency of −0 reads 0
    # the other direction runs: η = (1 − i0/η0)… here carrier → sun with i0·η0 = 0.5625
    back = solve(train, OperatingPoint(speeds={"s": 1000.0}, torques={"c": 1.0}, drives=["c"], loads=["s"]))
    assert not back.is_self_locking


def test_a_set_at_its_limit_inside_a_larger_train():
    """The limit of one set in a two-set train (second set a plain reduction behind it)."""
    train = GearTrain([PlanetarySet("P", "s", "r", "c", LIMIT, LIMIT), Brake("B", "r"),
                       PlanetarySet("Q", "c", "h", "out", -2.0, 0.98), Brake("H", "h")])
    sol = solve(train, OperatingPoint(speeds={"s": 1000.0}, torques={"out": 1.0}, drives=["s"], loads=["out"]))
    assert sol.is_self_locking and "P: η0 < 0.75" in sol.self_locking.message


def test_batch_point_at_the_limit_self_locks_and_the_others_solve():
    eta = LIMIT
    train = GearTrain([PlanetarySet("P", "s", "r", "c", LIMIT, eta)])
    speeds = {"s": np.array([0.0, 0.0, 3000.0]), "r": np.array([1000.0, -1000.0, 1000.0])}
    res = solve_batch(train, speeds=speeds, torques={"c": 1.0}, loads=["c"], connected=["s", "r"])
    for k in range(3):
        sol = solve(train, OperatingPoint(speeds={s: float(v[k]) for s, v in speeds.items()}, torques={"c": 1.0},
                                          loads=["c"], connected=["s", "r"]))
        assert bool(res.self_locking[k]) == sol.is_self_locking
        for shaft in ("s", "r", "c"):
            assert res.torques[shaft][k] == pytest.approx(sol.torque(shaft), rel=1e-12, abs=1e-12)
    assert res.self_locking[:2].all() and np.isnan(res.efficiency[:2]).all()
    assert np.isfinite(res.loss).all()


def test_connected_shaft_is_not_called_the_load():
    """Item of wording: a shaft declared ``connected`` has its role from the lossless power flow."""
    train, point = _two_dof(LIMIT - 1e-12)
    message = solve(train, point).self_locking.message
    assert "'r' would have to absorb power although, without losses, it puts power in (a connected shaft)" in message
    assert "it is the load" not in message and "it is a drive" not in message
    # a designated load is called a load
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", 1.02, 0.95), Brake("B", "ring")])
    sol = solve(train, OperatingPoint(speeds={"sun": 1000.0}, torques={"sun": 10.0}, drives=["sun"], loads=["carrier"]))
    assert "'carrier' would have to deliver power although it is a load" in sol.self_locking.message
