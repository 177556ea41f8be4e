"""Two-shaft and three-shaft operation of a single set, against closed forms and published formulas."""

import math

import pytest

from epicyclic import Brake, Clutch, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.analysis import three_shaft_speeds, two_shaft_modes
from epicyclic.analysis.modes import QUEITSCH_TAFEL_1

# Queitsch, Tafel 1: the seven ratios i = n_an/n_ab in terms of s = i0.
TAFEL_1 = {
    "I": lambda s: 1 / (1 - s),
    "II": lambda s: -s / (1 - s),
    "III": lambda s: 1 / s,
    "IV": lambda s: (1 - s) / (-s),
    "V": lambda s: s,
    "VI": lambda s: 1 - s,
    "VII": lambda s: 1.0,
}


@pytest.mark.parametrize("s", [-78 / 30, -2.0, -11.0, -1.5, 1.02, 0.672, 2.5])
@pytest.mark.parametrize("label", list(TAFEL_1))
def test_queitsch_tafel_1_ratios(s, label):
    # Queitsch, "Grundlagen der Umlaufrädergetriebe" (I), Tafel 1; tolerance: round-off (1e-12).
    assert two_shaft_modes(s)[label].ratio == pytest.approx(TAFEL_1[label](s), rel=1e-12)


def test_tafel_1_labels_are_the_papers_columns():
    # Queitsch Tafel 1, row "0 =": the member held in columns I … VI (VII: two members joined).
    held = {label: held for label, _, _, held, _ in QUEITSCH_TAFEL_1}
    assert held == {"I": "ring", "II": "sun", "III": "carrier", "IV": "sun", "V": "carrier",
                    "VI": "ring", "VII": None}


# tec-science, "Willis-Gleichung": z_S = 30, z_H = 78 (any simple set); the formulas of the article:
ZS, ZP, ZH = 30, 24, 78


@pytest.mark.parametrize(
    ("held", "drive", "load", "expected"),
    [
        ("sun", "ring", "carrier", 1 + ZS / ZH),     # "Festgestelltes Sonnenrad": i_S = 1 + z_S/z_H
        ("ring", "sun", "carrier", 1 + ZH / ZS),     # "Festgestelltes Hohlrad":   i_H = 1 + z_H/z_S
        ("carrier", "sun", "ring", -ZH / ZS),        # "Festgestellter Steg":      i_0 = −z_H/z_S
    ],
)
def test_willis_article_ratios(held, drive, load, expected):
    train = GearTrain([
        PlanetarySet.simple("P", sun="sun", ring="ring", carrier="carrier", z_sun=ZS, z_planet=ZP, z_ring=ZH),
        Brake("B", held),
    ])
    sol = solve(train, OperatingPoint(speeds={drive: 1000}, torques={drive: 5}, drives=[drive], loads=[load]))
    assert sol.speed(drive) / sol.speed(load) == pytest.approx(expected, rel=1e-12)
    assert sol.efficiency == pytest.approx(1.0, rel=1e-12)


def test_willis_article_direct_drive():
    # Two members joined: the whole set turns as a block, ratio 1, no rolling, no loss.
    train = GearTrain([
        PlanetarySet.simple("P", sun="sun", ring="ring", carrier="carrier", z_sun=ZS, z_planet=ZP, z_ring=ZH,
                            stationary_efficiency=0.9),
        Clutch("C", "sun", "carrier"),
    ])
    sol = solve(train, OperatingPoint(speeds={"sun": 1000}, torques={"sun": 5}, drives=["sun"], loads=["ring"]))
    assert sol.speed("ring") == pytest.approx(1000, rel=1e-12)
    assert sol.efficiency == pytest.approx(1.0, rel=1e-12)
    assert sol.elements["P"].loss == pytest.approx(0.0, abs=1e-9)
    assert sol.elements["P"].planet_speeds_relative == pytest.approx((0.0,), abs=1e-9)


@pytest.mark.parametrize(("n_sun", "n_carrier"), [(1000, 0), (1000, 300), (-500, 800), (0, 1200)])
def test_willis_article_planet_speed(n_sun, n_carrier):
    # tec-science, "Willis-Gleichung", Grundgleichung: n_P·z_P = n_T·(z_P + z_S) − n_S·z_S.
    s = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=ZS, z_planet=ZP, z_ring=ZH)
    speeds = three_shaft_speeds(s, sun=n_sun, carrier=n_carrier)
    assert speeds["planet"] * ZP == pytest.approx(n_carrier * (ZP + ZS) - n_sun * ZS, abs=1e-9)
    # and the ring from the planetary equation: n_H·z_H = n_T·(z_H + z_S) − z_S·n_S
    assert speeds["ring"] * ZH == pytest.approx(n_carrier * (ZH + ZS) - ZS * n_sun, abs=1e-9)


def test_three_shaft_speeds_queitsch_eq_12():
    # Queitsch eq. (12): (1 − s)·n51 + s·n41 − n21 = 0.
    s = -2.6
    result = three_shaft_speeds(PlanetarySet("P", "a", "b", "c", s), ring=400, carrier=-250)
    assert (1 - s) * result["carrier"] + s * result["ring"] - result["sun"] == pytest.approx(0, abs=1e-9)
    assert "planet" not in result  # no tooth counts, no planet speed


def test_three_shaft_speeds_needs_two():
    with pytest.raises(ValueError, match="exactly two of sun, ring, carrier"):
        three_shaft_speeds(PlanetarySet("P", "a", "b", "c", -2.0), sun=100)


# Closed forms for a minus set (i0 < 0), from Brandenberger's rule worked by hand:
# the efficiency applies in the direction of the rolling power (power relative to the carrier).
# Also in H. W. Müller, "Die Umlaufgetriebe", 2nd ed. 1998, Tab. 4.1 (η of the six modes).
def closed_forms(i0, e):
    return {
        ("sun", "carrier"): (1 - i0 * e) / (1 - i0),          # ring held (Brandenberger 1952, eq. 7)
        ("carrier", "sun"): (1 - i0) / (1 - i0 / e),          # ring held, reversed
        ("ring", "carrier"): (i0 - e) / (i0 - 1),             # sun held: ring drives rel. carrier
        ("carrier", "ring"): (i0 - 1) / (i0 - 1 / e),         # sun held, reversed
        ("sun", "ring"): e,                                    # carrier held: stationary gear
        ("ring", "sun"): e,
    }


@pytest.mark.parametrize("i0", [-1.5, -2.0, -78 / 30, -5.0, -11.0])
@pytest.mark.parametrize("e", [0.99, 0.97, 0.9, 0.6])
def test_six_modes_of_a_minus_set_against_closed_forms(i0, e):
    table = two_shaft_modes(i0, e)
    forms = closed_forms(i0, e)
    for mode in table:
        if mode.held is None:
            assert mode.efficiency == pytest.approx(1.0, rel=1e-12)
            assert mode.reverse_efficiency == pytest.approx(1.0, rel=1e-12)
            continue
        assert mode.efficiency == pytest.approx(forms[(mode.input, mode.output)], rel=1e-12)
        assert mode.reverse_efficiency == pytest.approx(forms[(mode.output, mode.input)], rel=1e-12)


def test_plus_set_self_locks_from_sun_to_carrier():
    # Closed form of Brandenberger 1952's rule: plus set i0 = 1.02, η0 = 0.95, ring held.
    # carrier → sun (reduction 1:50): η = (1 − i0)/(1 − i0/η0) = 0.2714;
    # sun → carrier (step-up): formal η = (1 − i0·η0)/(1 − i0) = −1.55 → self-locking from η0 < 1/i0.
    table = two_shaft_modes(1.02, 0.95)
    mode = table["I"]  # carrier → sun, ring held
    assert mode.ratio == pytest.approx(-50)
    assert round(mode.efficiency, 4) == 0.2714
    assert mode.reverse_efficiency is None and mode.reverse_self_locking
    assert mode.reverse_threshold == pytest.approx(1 / 1.02, rel=1e-6)


def test_self_locking_solution_reports_formal_efficiency_not_negative():
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", 1.02, 0.95), Brake("B", "ring")])
    for given in ("sun", "carrier"):  # either the drive's or the load's torque given
        op = OperatingPoint(speeds={"sun": 1000}, torques={given: 3.0}, drives=["sun"], loads=["carrier"])
        sol = solve(train, op)
        assert sol.efficiency is None and sol.is_self_locking
        assert sol.self_locking.formal_efficiency == pytest.approx((1 - 1.02 * 0.95) / (1 - 1.02), rel=1e-9)
        # bisection on a matrix that turns singular at the threshold: 1e-6 is what it resolves
        assert sol.self_locking.thresholds["P"] == pytest.approx(1 / 1.02, rel=1e-6)
        assert "self-locks" in sol.self_locking.message and "0.980392" in sol.self_locking.message


def test_plus_set_above_threshold_does_not_self_lock():
    # η0 = 0.99 > 1/1.02: sun → carrier works, η = (1 − i0·η0)/(1 − i0) = 0.49.
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", 1.02, 0.99), Brake("B", "ring")])
    sol = solve(train, OperatingPoint(speeds={"sun": 1000}, torques={"sun": 3.0}, drives=["sun"], loads=["carrier"]))
    assert sol.efficiency == pytest.approx((1 - 1.02 * 0.99) / (1 - 1.02), rel=1e-12)


def test_mode_table_renders():
    table = two_shaft_modes(1.02, 0.95)
    text = table.table()
    assert "Tafel 1" in text and "self-locking (η0 < 0.9804)" in text
    assert "<table>" in table._repr_html_()
    assert table.to_dict()["modes"][0]["label"] == "I"


def test_exactly_at_the_self_locking_limit_is_self_locking():
    # Regression (found by hypothesis): plus set i0 = 0.5, sun held, ring → carrier at η0 = 0.5.
    # Closed form η = (i0 − η0)/(i0 − 1) = 0: no power reaches the load, so the train self-locks
    # (Brandenberger 1952, text to Bild 9: formal efficiency ≤ 0) — never an efficiency of −0.0000.
    train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", 0.5, 0.5), Brake("B", "sun")])
    sol = solve(train, OperatingPoint(speeds={"ring": 50}, torques={"ring": 1}, drives=["ring"], loads=["carrier"]))
    assert sol.efficiency is None and sol.is_self_locking
    assert "self-locking limit" in sol.self_locking.message


def test_three_shaft_speeds_take_units():
    # regression: sun="1000 U/min" was a bare ValueError (float('1000 U/min')); a file takes it
    import pint

    from epicyclic.units import UnitError

    s = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78)
    plain = three_shaft_speeds(s, sun=1000, carrier=300)
    assert three_shaft_speeds(s, sun="1000 U/min", carrier=pint.UnitRegistry().Quantity(300, "rpm")) == plain
    in_rad_s = three_shaft_speeds(s, sun=f"{1000 * math.pi / 30!r} rad/s", carrier=300)
    assert in_rad_s == pytest.approx(plain, rel=1e-12)
    with pytest.raises(UnitError, match="three_shaft_speeds: sun: '3 kW' is not a speed"):
        three_shaft_speeds(s, sun="3 kW", carrier=300)
