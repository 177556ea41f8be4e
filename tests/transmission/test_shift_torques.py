"""Shift-element torques, verified by independent balances on the elements.

Hand derivations use only the torque relations of a simple set
(T_ring = −i0·η0^w·T_sun, T_carrier = −(T_sun + T_ring); Queitsch eq. 26,
Brandenberger eqs. 7/7') and torque balance of the shafts.  Tolerance 1e-9 relative.
"""

from __future__ import annotations

import pytest

from epicyclic.model.elements import Brake
from epicyclic.transmission.library import build


def test_8hp_first_gear_by_hand():
    """1st gear (A, B, C): P1 held (sun and ring braked) so R4 is held through C1; P2, P3 carry
    no torque (C3 open).  Clutch C carries the whole input torque into S4.  P4: sun drives
    (w = +1): T_r4 = (85/23)·η0·T_in.  P1 (no rolling, w = 0): its carrier reaction T_r4 splits
    into sun 1/(1 + 2) and ring 2/(1 + 2):  |T_A| = T_r4/3, |T_B| = 2 T_r4/3.
    """
    eta0 = 0.97
    g = build("zf_8hp70", eta0).analyze("1")
    t_r4 = 85 / 23 * eta0
    assert g.element_torques["C"] == pytest.approx(1.0, rel=1e-9)
    assert abs(g.element_torques["A"]) == pytest.approx(t_r4 / 3, rel=1e-9)
    assert abs(g.element_torques["B"]) == pytest.approx(2 * t_r4 / 3, rel=1e-9)
    assert g.set_status == {"P1": "locked", "P2": "idle", "P3": "idle", "P4": "rolling"}


def test_simpson_first_gear_band_torque_by_hand():
    """Ford C4, 1st gear (forward clutch + low/reverse band), lossless, k = 72/33:
    front set ring (input T_in) → sun torque T_in/k; the common sun passes it to the rear set;
    rear carrier (band) reacts (1 + k)·T_in/k = 1.4583 T_in; output 2 + 1/k = 2.4583 T_in."""
    k = 72 / 33
    g = build("simpson_c4").analyze("1")
    assert abs(g.element_torques["low_reverse"]) == pytest.approx((1 + k) / k, rel=1e-9)
    assert g.element_torques["forward"] == pytest.approx(1.0, rel=1e-9)


@pytest.mark.parametrize("key", ["simpson_c4", "ravigneaux_aod", "lepelletier_6hp26", "zf_8hp70"])
@pytest.mark.parametrize("eta0", [1.0, 0.97])
def test_brakes_balance_the_housing(key, eta0):
    """Whole-box balance: the torques of the engaged brakes (plus sets fixed to the housing)
    equal −(M_in + M_out), computed from input and output alone."""
    t = build(key, eta0)
    for gear in t.gears:
        g = t.analyze(gear)
        sol = g.drive
        m_in, m_out = sol.torque(t.input), sol.torque(t.output)
        on_housing = 0.0
        for e in t.train.elements:
            state = sol.elements[e.name]
            for port, shaft in state.ports.items():
                if shaft == "housing":
                    on_housing += state.torques[port]
        # torque balance of the housing shaft: its reaction equals the sum of port torques
        assert sol.torque("housing") == pytest.approx(on_housing, abs=1e-9 * abs(m_in))
        assert on_housing == pytest.approx(-(m_in + m_out), abs=1e-9 * abs(m_in) * 10)
        brakes = sum(g.element_torques[e.name] for e in t.train.elements
                     if isinstance(e, Brake) and e.name in g.element_torques)
        assert brakes * m_in == pytest.approx(-sum(
            sol.elements[e.name].torques["housing"] for e in t.train.elements
            if isinstance(e, Brake) and e.name in g.element_torques), rel=1e-9, abs=1e-9)


@pytest.mark.parametrize("gear", ["1", "2", "3", "4", "5", "7", "8", "R"])
def test_8hp_clutch_torque_balances_its_shaft(gear):
    """Element balance: a clutch's torque equals what the other elements on its second shaft take."""
    t = build("zf_8hp70", 0.98)
    g = t.analyze(gear)
    sol = g.drive
    for name, value in g.element_torques.items():
        element = t.train.element(name)
        if isinstance(element, Brake):
            continue
        shaft = element.second
        others = sum(state.torques[p] for n, state in sol.elements.items() if n != name
                     for p, s in state.ports.items() if s == shaft)
        external = sol.torque(shaft) if shaft in (t.input, t.output) else 0.0
        # shaft balance: external − Σ port torques = 0, the clutch's second port = −first
        assert -value * sol.torque(t.input) == pytest.approx(external - others, abs=1e-9 * abs(sol.torque(t.input)))


def test_slip_speeds_of_open_elements_8hp_first_gear():
    """1st gear: D open between C3 and the output; E between R2/S3 (1.5 n_in) and S4 (n_in)."""
    g = build("zf_8hp70").analyze("1")
    assert g.slip_speeds["E"] == pytest.approx(0.5, rel=1e-12)
    assert set(g.slip_speeds) == {"D", "E"}
