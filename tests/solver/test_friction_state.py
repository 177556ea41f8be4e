"""Non-unique friction state: two loss-direction patterns both consistent (Coulomb friction).

Closed form: one set, no shaft held, two speeds and the carrier torque given (the torque rule of
the gear pair entity, Brandenberger 1952, eq. 7; Pennestrì & Freudenstein 1993; coded in
tests/solver/test_two_dof_closed_form.py::closed_form).  Inside the band η0 < i0 < 1/η0 both
w = +1 and w = −1 may agree with their own rolling power; the quasi-static equations then do not
decide the state (the indeterminate case of dry friction, Champneys & Várkonyi 2016).  `solve`
must warn, `solve_batch` must flag the point in ``ambiguous``, exactly where the closed form finds
two states — over the same kind of 3000-point scan the validation engineer classified (2895 one
state, 54 none, 51 two with i0 spread over (−8, 6); here the band is sampled more densely).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.solver.batch import solve_batch

from .test_two_dof_closed_form import closed_form

NOT_UNIQUE = "the friction state is not unique"


def _scan(count=3000, seed=2):
    rng = np.random.default_rng(seed)
    i0 = np.concatenate([rng.uniform(-8.0, -0.2, count // 4), rng.uniform(0.2, 0.9, count // 4),
                         rng.uniform(1.1, 6.0, count // 4), rng.uniform(0.85, 1.18, count - 3 * (count // 4))])
    eta0 = rng.uniform(0.6, 0.999, count)
    n_sun, n_ring = rng.uniform(-3000.0, 3000.0, (2, count))
    n_carrier = (n_sun - i0 * n_ring) / (1.0 - i0)
    keep = ((np.abs(n_carrier) > 1.0) & (np.abs(n_sun - n_carrier) > 1.0)
            & (np.minimum(np.abs(1.0 - i0 * eta0), np.abs(1.0 - i0 / eta0)) > 1e-3))
    return [(float(a), float(e), float(s), float(r)) for a, e, s, r in zip(i0[keep], eta0[keep], n_sun[keep], n_ring[keep])]


def test_scan_classification_scalar():
    """Every point (the carrier a drive and a load in turn): a warning exactly where two states agree."""
    counts = {0: 0, 1: 0, 2: 0}
    for j, (i0, eta0, n_sun, n_ring) in enumerate(_scan(1500)):
        role = ("drive", "load")[j % 2]
        t_carrier = 10.0 * math.copysign(1.0, (n_sun - i0 * n_ring) / (1.0 - i0)) * (1.0 if role == "drive" else -1.0)
        states = len(closed_form(i0, eta0, n_sun, n_ring, t_carrier))
        counts[states] += 1
        train = GearTrain([PlanetarySet("P", "s", "r", "c", i0, eta0)])
        roles = {"drives": ["c"]} if role == "drive" else {"loads": ["c"]}
        sol = solve(train, OperatingPoint(speeds={"s": n_sun, "r": n_ring}, torques={"c": 10.0},
                                          connected=["s", "r"], **roles))
        assert any(NOT_UNIQUE in w for w in sol.warnings) == (states == 2)
        assert sol.is_self_locking == (states == 0)
    assert counts[2] > 20 and counts[0] > 20, counts   # the band is sampled


def test_batch_ambiguous_matches_the_closed_form():
    n_sun, n_ring = np.random.default_rng(4).uniform(-3000.0, 3000.0, (2, 300))
    for role in ("drive", "load"):
        counts = {0: 0, 1: 0, 2: 0}
        for i0 in (0.88, 0.93, 0.97, 1.02, 1.05, 1.1, -2.0, 0.5, 3.0):
            for eta0 in (0.9, 0.95, 0.96):
                train = GearTrain([PlanetarySet("P", "s", "r", "c", i0, eta0)])
                roles = {"drives": ["c"]} if role == "drive" else {"loads": ["c"]}
                res = solve_batch(train, speeds={"s": n_sun, "r": n_ring}, torques={"c": 10.0},
                                  connected=["s", "r"], **roles)
                for k in range(n_sun.size):
                    n_carrier = (n_sun[k] - i0 * n_ring[k]) / (1.0 - i0)
                    if abs(n_carrier) <= 1.0 or abs(n_sun[k] - n_carrier) <= 1.0:
                        continue
                    t_carrier = 10.0 * math.copysign(1.0, n_carrier) * (1.0 if role == "drive" else -1.0)
                    states = len(closed_form(i0, eta0, n_sun[k], n_ring[k], t_carrier))
                    counts[states] += 1
                    assert bool(res.ambiguous[k]) == (states == 2), (i0, eta0, k)
                    assert bool(res.self_locking[k]) == (states == 0), (i0, eta0, k)
        assert counts[2] > 10 and counts[0] > 10 and counts[1] > 100, counts
    assert res.ambiguous.shape == res.efficiency.shape


def test_per_point_efficiencies_agree_with_solve():
    """Batch with its own η0 per point (the Woodbury form of the reversal test) = solve point by point."""
    rng = np.random.default_rng(11)
    n_sun, n_ring = rng.uniform(-3000.0, 3000.0, (2, 150))
    factor = rng.uniform(0.9, 0.99, 150)
    train = GearTrain([PlanetarySet("P", "s", "r", "c", 1.03, 0.97)])
    res = solve_batch(train, speeds={"s": n_sun, "r": n_ring}, torques={"c": 10.0}, drives=["c"],
                      connected=["s", "r"], efficiencies={"P": {"mesh": factor}})
    flagged = 0
    for k in range(150):
        sol = solve(train, OperatingPoint(speeds={"s": n_sun[k], "r": n_ring[k]}, torques={"c": 10.0}, drives=["c"],
                                          connected=["s", "r"]), efficiencies={"P": {"mesh": factor[k]}})
        warned = any(NOT_UNIQUE in w for w in sol.warnings)
        assert warned == bool(res.ambiguous[k])
        flagged += warned
    assert 0 < flagged < 150
    assert "with a friction state that is not unique" in repr(res)


def test_a_state_against_the_designated_roles_is_not_an_alternative():
    """Plus set i0 = 1.02, η0 = 0.95, ring held, carrier → sun (η = (1 − i0)/(1 − i0/η0) = 0.2714,
    Brandenberger's rule): with the carrier torque given, w = +1 also agrees with its rolling power,
    but there the sun — the designated load — would deliver power: the self-locked state, no warning."""
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", 1.02, 0.95), Brake("B", "ring")])
    sol = solve(train, OperatingPoint(speeds={"sun": 1000.0}, torques={"carrier": 10.0}, drives=["carrier"],
                                      loads=["sun"]))
    assert sol.efficiency == pytest.approx((1 - 1.02) / (1 - 1.02 / 0.95), rel=1e-12)
    assert not any(NOT_UNIQUE in w for w in sol.warnings)
    res = solve_batch(train, speeds={"sun": np.array([1000.0])}, torques={"carrier": 10.0}, drives=["carrier"],
                      loads=["sun"])
    assert not res.ambiguous.any()


def test_the_warning_names_both_states_and_stays_deferred():
    train = GearTrain([PlanetarySet("P", "s", "r", "c", 1.02, 0.95)])
    sol = solve(train, OperatingPoint(speeds={"s": 1000.0, "r": 990.0}, torques={"c": 10.0}, loads=["c"],
                                      connected=["s", "r"]))
    assert callable(sol.__dict__["_warnings"])   # made on first access only
    (warning,) = [w for w in sol.warnings if NOT_UNIQUE in w]
    assert "P: -1 (shown) and P: +1" in warning
    # the other state's sun torque is the closed form's other root
    n_carrier = (1000.0 - 1.02 * 990.0) / (1 - 1.02)
    roots = [t for t, _ in closed_form(1.02, 0.95, 1000.0, 990.0, -10.0 * math.copysign(1.0, n_carrier))]
    other = [t for t in roots if t != pytest.approx(sol.torque("s"), rel=1e-9)]
    assert len(roots) == 2 and f"s {other[0]:.6g} N·m" in warning


def test_a_reversal_exactly_at_the_locking_limit_is_no_second_state_in_solve_and_batch():
    """Found by tests/solver/test_edges_hypothesis.py: a plus set with i0 = η0 = 0.625 in a loop with a
    stage. Reversing the set's w gives i0/η0 = 1: c = 1 − i0·η0^−w is 0 exactly (Brandenberger 1952, text
    to Bild 9: the self-locking limit), computed as −4.4e-16 by the Sherman–Morrison ratio. The batch
    took that round-off as c < 0 and flagged the point ambiguous while solve did not warn; the reversed
    pattern's equations are singular there, so no second state exists and neither may say so."""
    from epicyclic import GearStage

    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", 0.625, 0.625),
                       GearStage("G", "sun", "ring", 0.75, 0.75)])
    op = OperatingPoint(speeds={"sun": 10.0}, torques={"carrier": 1.0}, drives=["sun"], loads=["carrier"])
    solution = solve(train, op)
    assert not any("friction state is not unique" in w for w in solution.warnings)
    batch = solve_batch(train, speeds={"sun": np.array([10.0])}, torques={"carrier": np.array([1.0])},
                        drives=["sun"], loads=["carrier"])
    assert not batch.ambiguous[0]
