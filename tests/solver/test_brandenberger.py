"""Brandenberger 1952, "Die Berechnung des Reibungsverlustes und des Wirkungsgrades von
Umlaufrädergetrieben", Schweiz. Bauzeitung 70 (39), Beispiel zu Bild 10.

Units of the paper: U/min, PS, cm·kg (= kp·cm).  1 PS = 735.49875 W, 1 kp·cm = 0.0980665 N·m;
the paper's M = 71620·N/n cm·kg for N in PS is the same conversion to 4 digits.
"""

import math

import pytest

from epicyclic import solve
from epicyclic.demo import KP_CM, PS, brandenberger_1952

# Exact tooth ratios of the example: a/b·c/d = 50/24·30/42 and e/f·g/h = 40/44·20/64.
AC_BD = (50 / 24) * (30 / 42)
EG_FH = (40 / 44) * (20 / 64)
BD_AC = 1 / AC_BD
FH_EG = 1 / EG_FH


@pytest.fixture(scope="module")
def solution():
    train, op = brandenberger_1952()
    return solve(train, op)


def test_speeds_match_printed_digits(solution):
    # Paper, eqs. (5) and (6'): n1 = 2740, n3 = 5280 U/min for n2 = 1500 (printed to 4 digits).
    assert round(solution.speed("I"), -1) == 2740
    assert round(solution.speed("III"), -1) == 5280
    assert solution.speed("II") == 1500


def test_input_torque_efficiency_and_output_match_printed_digits(solution):
    # Paper: M_An' = 71620·3/1500 = 143.24 cm·kg; η' = 0.85; N1' = 2.55 PS.
    assert solution.torque("II") / KP_CM == pytest.approx(143.24, abs=0.005)
    assert round(solution.efficiency, 2) == 0.85
    assert round(solution.output_power / PS, 2) == 2.55
    # The loss-free output is the full 3 PS (paper: N1 = 3 PS).
    assert solution.ideal.output_power / PS == pytest.approx(3.0, rel=1e-12)


def test_efficiency_equals_the_papers_closed_form(solution):
    # Paper, formula for η' below eq. (10), evaluated exactly with η1η2 = η3η4 = 0.9 (= 0.8494).
    e12 = e34 = 0.9
    closed = (BD_AC + FH_EG * (1 - BD_AC)) / (BD_AC * e12 + FH_EG / e34 * (1 - BD_AC * e12))
    assert solution.efficiency == pytest.approx(closed, rel=1e-12)
    assert round(closed, 4) == 0.8494


def test_port_torques_equal_the_papers_equations(solution):
    # Paper eqs. (10'), (7'), (8) evaluated exactly: the solver must agree to round-off.
    m_an = solution.torque("II")
    e12 = e34 = 0.9
    for sol, e_p, e_s in ((solution, e12, e34), (solution.ideal, 1.0, 1.0)):
        m1 = m_an / (BD_AC * e_p + (1 - BD_AC * e_p) / (EG_FH * e_s))
        m2 = -m1 / AC_BD * e_p
        m3 = -(m1 + m2)
        torques = sol.elements["planetary"].torques
        assert abs(torques["sun"]) == pytest.approx(m1, rel=1e-12)
        assert abs(torques["ring"]) == pytest.approx(abs(m2), rel=1e-12)
        assert abs(torques["carrier"]) == pytest.approx(abs(m3), rel=1e-12)


@pytest.mark.parametrize(
    ("port", "with_friction", "printed"),
    [
        ("sun", True, 66.7), ("ring", True, 40.3), ("carrier", True, 26.4),
        ("sun", False, 78.2), ("ring", False, 52.5), ("carrier", False, 25.8),
    ],
)
def test_port_torques_against_printed_values(solution, port, with_friction, printed):
    """Magnitudes of the paper's M1', M2', M3' (with) and M1, M2, M3 (without friction), cm·kg.

    The paper computed with a slide rule and rounded ratios (1.49, 0.284); its own numbers are not
    mutually exact: M2 + M3 = −78.3 but M1 = 78.2, and M1·n1/71620 = 2.99 PS where it states 3 PS.
    Hand check of the loss-free M1 by power balance, which no rounding of the ratios can change:
    M1 = M_An·n2/n1 = 143.24·1500/2739.8 = 78.42 cm·kg (the paper prints 78.2).  Its eq. (10')
    with exact ratios gives M1' = 66.61 (paper 66.7).  Every printed torque is reproduced within
    the paper's slide-rule error (0.3 cm·kg, 0.4 %); M2' = 40.3 and the exact equations above
    agree to round-off.
    """
    sol = solution if with_friction else solution.ideal
    value = abs(sol.elements["planetary"].torques[port]) / KP_CM
    assert value == pytest.approx(printed, abs=0.3)


def test_signs_follow_the_papers_tables(solution):
    # Tabelle 2 (signs for Bild 8): I is the load, II and III act as drives on the planetary set;
    # relative to the carrier, I drives (M1'(n1 − n3) has the sign of a drive): w = +1.
    planetary = solution.elements["planetary"]
    assert solution.shafts["I"].role == "load" and solution.power("I") < 0
    assert planetary.loss_direction == +1
    assert planetary.torques["ring"] * planetary.speeds["ring"] > 0  # II feeds the set
    assert planetary.torques["carrier"] * planetary.speeds["carrier"] > 0  # III feeds the set
    # No power circulates in Bild 10 (the paper: circulation only in Bild 11 and 12).
    assert solution.circulation.power == 0.0 and solution.circulation.loops == ()
    assert solution.circulation.largest_element_ratio < 1.0


def test_loss_does_not_depend_on_speed_level():
    # Brandenberger, text to Bild 8: the loss rectangle is independent of the operating point A,
    # i.e. of a common speed added to all three systems (torques unchanged).
    from epicyclic import GearTrain, OperatingPoint, PlanetarySet

    train = GearTrain([PlanetarySet("P", "I", "II", "III", BD_AC, 0.9)])
    losses = []
    for common in (0.0, 1000.0, -3000.0):
        op = OperatingPoint(speeds={"I": 2740 + common, "III": 5280 + common}, torques={"I": -6.5},
                            drives=["II", "III"])
        losses.append(solve(train, op).loss)
    assert losses[1] == pytest.approx(losses[0], rel=1e-12)
    assert losses[2] == pytest.approx(losses[0], rel=1e-12)
    assert math.isfinite(losses[0]) and losses[0] > 0
