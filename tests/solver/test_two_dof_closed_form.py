"""Two-degree-of-freedom operation of one set, with losses, against an independent closed form.

No shaft is held: two speeds are given and one torque; the other two torques are reactions.  The
closed form is the torque rule of the "gear pair entity" with the loss set by the direction of the
rolling power (Brandenberger 1952, eq. 7; the same rule in Pennestrì & Freudenstein 1993, J. Mech.
Des. 115, 645, and del Castillo 2002, Mech. Mach. Theory 37, 197): with
i0 = (n_s − n_c)/(n_r − n_c) and the sun's rolling power P_w = T_s·(n_s − n_c),

    T_r = −i0 · η0^w · T_s,  w = sign(P_w)     (the ring gets η0 times the sun's rolling power
                                                when the sun drives in the carrier frame, and
                                                1/η0 times it when the ring drives),
    T_c = −(T_s + T_r).

Given T_c this is T_s = −T_c / (1 − i0·η0^w), and w must agree with the sign of the rolling power
it produces.  Outside the band η0 < i0 < 1/η0 exactly one w agrees and the solver must return
it; inside the band (a plus set close to i0 = 1) none or both may agree: with none the train
self-locks and the solver must say so (Brandenberger 1952, text to Bild 9).  The code below is
written from the formulas, not from the solver.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from epicyclic import GearTrain, OperatingPoint, PlanetarySet, solve


def closed_form(i0: float, eta0: float, n_sun: float, n_ring: float, t_carrier: float):
    """Every self-consistent (T_sun, T_ring) for a given carrier torque (see the module docstring)."""
    n_carrier = (n_sun - i0 * n_ring) / (1.0 - i0)
    found = []
    for w in (1, -1):
        t_sun = -t_carrier / (1.0 - i0 * eta0**w)
        rolling = t_sun * (n_sun - n_carrier)
        if rolling * w > 0:
            found.append((t_sun, -t_sun - t_carrier))
    return found


def _solve(i0, eta0, n_sun, n_ring, torque, role):
    train = GearTrain([PlanetarySet("P", "s", "r", "c", i0, eta0)])
    point = OperatingPoint(speeds={"s": n_sun, "r": n_ring}, torques={"c": torque},
                           drives=["c"] if role == "drive" else [], loads=["c"] if role == "load" else [],
                           connected=["s", "r"])
    return solve(train, point)


ratios = st.one_of(st.floats(-8.0, -0.2), st.floats(0.2, 0.9), st.floats(1.1, 6.0))
speeds = st.floats(-3000.0, 3000.0)


@settings(max_examples=150, deadline=None)
@given(i0=ratios, eta0=st.floats(0.6, 0.999), n_sun=speeds, n_ring=speeds,
       torque=st.floats(1.0, 500.0), role=st.sampled_from(["drive", "load"]))
def test_two_input_set_matches_the_gear_pair_entity_formulas(i0, eta0, n_sun, n_ring, torque, role):
    n_carrier = (n_sun - i0 * n_ring) / (1.0 - i0)
    assume(abs(n_carrier) > 1.0 and abs(n_sun - n_carrier) > 1.0)
    assume(min(abs(1.0 - i0 * eta0), abs(1.0 - i0 / eta0)) > 1e-3)   # not at the locking boundary
    # the given magnitude sits at the carrier; its role fixes the sign (power in at a drive)
    t_carrier = torque * math.copysign(1.0, n_carrier) * (1.0 if role == "drive" else -1.0)
    expected = closed_form(i0, eta0, n_sun, n_ring, t_carrier)
    sol = _solve(i0, eta0, n_sun, n_ring, torque, role)
    if len(expected) == 1:
        (t_sun, t_ring), = expected
        assert sol.torque("s") == pytest.approx(t_sun, rel=1e-9, abs=1e-9)
        assert sol.torque("r") == pytest.approx(t_ring, rel=1e-9, abs=1e-9)
        assert sol.torque("c") == pytest.approx(t_carrier, rel=1e-12)
        assert not sol.is_self_locking
        assert not any("not unique" in w for w in sol.warnings)
    elif not expected:
        assert eta0 < i0 < 1.0 / eta0   # only a plus set close to 1 can lock
        assert sol.is_self_locking
    else:   # two friction states agree (inside the band): the solver returns one of them and says so
        assert eta0 < i0 < 1.0 / eta0
        assert any(sol.torque("s") == pytest.approx(t, rel=1e-9) for t, _ in expected)
        assert any("the friction state is not unique" in w for w in sol.warnings)


@pytest.mark.parametrize("i0, n_sun, n_ring, role, w", [
    # minus set, both central members drive, carrier is the load: the faster one in the carrier frame
    (-78 / 30, 3000.0, 1200.0, "load", 1),     # sun drives the ring relative to the carrier
    (-78 / 30, 500.0, 1500.0, "load", -1),     # ring drives the sun relative to the carrier
    # plus set (i0 = +2.4, Ravigneaux forward path), carrier drives
    (72 / 30, 2000.0, 600.0, "drive", -1),
    (72 / 30, 1700.0, 1000.0, "drive", 1),
])
def test_named_two_dof_cases(i0, n_sun, n_ring, role, w):
    """A hand check per regime: the expected loss direction is written down, not computed."""
    eta0 = 0.97
    n_carrier = (n_sun - i0 * n_ring) / (1.0 - i0)
    t_carrier = 100.0 * math.copysign(1.0, n_carrier) * (1.0 if role == "drive" else -1.0)
    (t_sun, t_ring), = closed_form(i0, eta0, n_sun, n_ring, t_carrier)
    sol = _solve(i0, eta0, n_sun, n_ring, 100.0, role)
    assert sol.elements["P"].loss_direction == w
    assert sol.torque("s") == pytest.approx(t_sun, rel=1e-12)
    assert sol.torque("r") == pytest.approx(t_ring, rel=1e-12)
    # power balance: the loss is η0-dependent and positive
    loss = sum(sol.power(x) for x in ("s", "r", "c"))
    assert loss == pytest.approx(sol.loss, rel=1e-9) and loss > 0
