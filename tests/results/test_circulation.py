"""Circulating power (Blindleistung): power around a closed loop beyond the input power.

Brandenberger 1952, text to Bild 10–12: the set of the Beispiel (a/b·c/d = 50/24·30/42) is brought
to the same speeds ("Stelle A", n1 = 2740, n2 = 1500, n3 = 5280 U/min) by joining two of its systems
with a gear stage: II and III in Bild 10, I and III in Bild 11, I and II in Bild 12.  With the signs of
his Tabelle 2 (I is the output, II and III drive the set) he states that in Bild 11 and 12 — not in
Bild 10 — power circulates in the stage ("zirkulieren im Vorgelege Leistungen, die gegen aussen im
An- und Abtrieb nicht zur Geltung kommen"): in Bild 11 part of the output at I must drive III, in
Bild 12 it must drive II.

Closed forms from the paper's eqs. (2), (7) and (8): the set's torques are M2' = −M1'·(bd/ac)·η and
M3' = −M1'·(1 − (bd/ac)·η) with η = η1η2 (w = +1, Bild 8).  The power that goes round is the power the
stage feeds into the set, and the input enters at the set's other member, so
  Bild 11: P_circ/P_in = |M3'·n3| / |M2'·n2| = (1 − η·bd/ac)/(η·bd/ac) · n3/n2,
  Bild 12: P_circ/P_in = |M2'·n2| / |M3'·n3| = (η·bd/ac)/(1 − η·bd/ac) · n2/n3.
Tolerance 1e-12 relative: the solver computes the same products in floating point.
"""

import pytest

from epicyclic import Clutch, GearStage, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.demo import PS, brandenberger_1952
from epicyclic.results.circulation import circulation

BD_AC = 1 / ((50 / 24) * (30 / 42))
FH_EG = 1 / ((40 / 44) * (20 / 64))
N2 = 1500.0
N3 = N2 * FH_EG  # eq. (5)
N1 = N2 * BD_AC + N2 * FH_EG * (1 - BD_AC)  # eq. (6')


def _set(eta):
    return PlanetarySet.stepped("planetary", sun="I", ring="II", carrier="III", z_sun=50, z_planet_sun=24,
                                z_planet_ring=30, z_ring=42, ring_internal=False, stationary_efficiency=eta)


def bild_11(eta):
    train = GearTrain([_set(eta), GearStage("stage", "III", "I", N3 / N1, eta)], name="Bild 11")
    return solve(train, OperatingPoint(speeds={"II": N2}, powers={"II": 3 * PS}, drives=["II"], loads=["I"]))


def bild_12(eta):
    train = GearTrain([_set(eta), GearStage("stage", "II", "I", N2 / N1, eta)], name="Bild 12")
    return solve(train, OperatingPoint(speeds={"III": N3}, powers={"III": 3 * PS}, drives=["III"], loads=["I"]))


@pytest.mark.parametrize("eta", [1.0, 0.9])
def test_bild_11_circulates_through_the_stage_as_the_closed_form_says(eta):
    sol = bild_11(eta)
    assert sol.speed("I") == pytest.approx(N1, rel=1e-12) and sol.speed("III") == pytest.approx(N3, rel=1e-12)
    (loop,) = sol.circulation.loops
    # the power leaves the set at I, passes the stage to III and re-enters the set ("im Vorgelege")
    assert loop.path == ("I", "stage", "III", "planetary")
    closed = (1 - eta * BD_AC) / (eta * BD_AC) * N3 / N2
    assert loop.ratio == pytest.approx(closed, rel=1e-12)
    assert sol.circulation.ratio == pytest.approx(closed, rel=1e-12)
    assert loop.power == pytest.approx(closed * 3 * PS, rel=1e-12)
    # the set's port at I carries the output plus what goes round (and the stage's loss)
    port_i = -sol.elements["planetary"].port_powers["sun"]
    assert port_i == pytest.approx(sol.output_power + sol.elements["stage"].loss + loop.power, rel=1e-12)
    assert sol.circulation.largest_element_ratio == pytest.approx(port_i / sol.input_power, rel=1e-12)


@pytest.mark.parametrize("eta", [1.0, 0.9])
def test_bild_12_circulates_through_the_stage_as_the_closed_form_says(eta):
    sol = bild_12(eta)
    (loop,) = sol.circulation.loops
    assert loop.path == ("I", "stage", "II", "planetary")
    closed = (eta * BD_AC) / (1 - eta * BD_AC) * N2 / N3
    assert loop.ratio == pytest.approx(closed, rel=1e-12)
    assert any("power circulates" in w for w in sol.warnings)


def test_bild_10_has_no_circulating_power_but_its_largest_element_power_is_kept():
    # Bild 10 (the Beispiel): II and III both drive the set, nothing goes round.  The old figure
    # "largest port power / input" (0.8494 here, the same number as the efficiency) is kept under
    # its own name.
    sol = solve(*brandenberger_1952())
    assert sol.circulation.loops == () and sol.circulation.power == 0.0 and sol.circulation.ratio == 0.0
    assert sol.circulation.largest_element_ratio == pytest.approx(sol.efficiency, rel=1e-12)
    assert "circulating power  none" in sol.table()


@pytest.mark.parametrize(("i0", "k"), [(-2.5, -0.5), (-2.5, 0.5), (-2.5, 0.2), (1.6, 2.0), (-4.0, 3.0)])
def test_lossless_closed_set_splits_or_circulates_as_the_closed_form_says(i0, k):
    # Any set (s, r, c) whose carrier is joined to its sun by a stage n_c = k·n_s, driven at s, loaded
    # at r, lossless.  Brandenberger eq. (1): ω_r = (ω_s − (1 − i0)·ω_c)/i0; eqs. (2), (3'): T_r = −i0·T_s,
    # T_c = (i0 − 1)·T_s.  The input at s splits into the set's sun branch and the stage branch, which
    # carries the carrier's port power p_c = T_c·ω_c; x = p_c/P_in = (i0 − 1)·k / (1 − (1 − i0)·k).
    # 0 ≤ x ≤ 1: power division, nothing circulates; x > 1: the stage carries x·P_in and the sun
    # branch returns (x − 1)·P_in (round s → G → c → P); x < 0: the stage returns |x|·P_in (round
    # s → P → c → G).  This is Müller's distinction of Leistungsteilung and Blindleistung.
    train = GearTrain([PlanetarySet("P", "s", "r", "c", i0, 1.0), GearStage("G", "c", "s", k, 1.0)])
    sol = solve(train, OperatingPoint(speeds={"s": 1000.0}, torques={"s": 10.0}, drives=["s"], loads=["r"]))
    x = (i0 - 1) * k / (1 - (1 - i0) * k)
    assert sol.efficiency == 1.0 and sol.loss == 0.0
    if 0 <= x <= 1:
        assert sol.circulation.loops == () and sol.circulation.power == 0.0
        return
    (loop,) = sol.circulation.loops
    assert loop.ratio == pytest.approx(x - 1 if x > 1 else -x, rel=1e-12)
    assert loop.path == (("s", "G", "c", "P") if x > 1 else ("s", "P", "c", "G"))
    assert sol.circulation.largest_element_ratio == pytest.approx(max(abs(x), abs(1 - x)), rel=1e-12)


def test_parallel_clutches_make_the_circulation_indeterminate():
    # Two engaged clutches between the same shafts: the rigid-body equations leave their torque
    # split open, so neither the circulating nor the largest element power is defined.
    train = GearTrain([PlanetarySet("P", "a", "ring", "b", -2.0, 0.98), Clutch("C1", "a", "x"), Clutch("C2", "a", "x"),
                       GearStage("G", "ring", "x", 1.5, 0.98)])
    sol = solve(train, OperatingPoint(speeds={"x": 1000.0}, torques={"x": 10.0}, drives=["x"], loads=["b"]))
    circ = sol.circulation
    assert circ.indeterminate == ("C1", "C2") and not circ.determinate
    assert circ.power is None and circ.ratio is None and circ.largest_element_power is None
    assert "not defined" in sol.table() and sol.to_dict()["circulation"]["power"] is None
    assert any("statically indeterminate" in w for w in sol.warnings)


def test_two_loops_are_reported_separately_largest_first():
    # A network of port powers (W) with two independent loops through shaft "in": 300 W round
    # in → A → u → B → in, 100 W round in → A → v → C → in; 1000 W input leaves at "out".
    flows = [("A", "in", 1400.0), ("A", "out", -1000.0), ("A", "u", -300.0), ("A", "v", -100.0),
             ("B", "u", 300.0), ("B", "in", -300.0), ("C", "v", 100.0), ("C", "in", -100.0)]
    circ = circulation(flows, 1000.0, ["in", "out", "u", "v"])
    assert [(loop.path, loop.power) for loop in circ.loops] == [
        (("in", "A", "u", "B"), 300.0), (("in", "A", "v", "C"), 100.0)]
    assert circ.power == 400.0 and circ.ratio == 0.4
    assert circ.largest_element_power == 1400.0 and circ.largest_element_ratio == 1.4


def test_no_input_power_gives_no_ratios():
    circ = circulation([("A", "x", 5.0), ("A", "y", -5.0)], 0.0)
    assert circ.loops == () and circ.ratio is None and circ.largest_element_ratio is None
