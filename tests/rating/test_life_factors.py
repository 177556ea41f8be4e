"""Life factors Z_NT, Y_NT and the Palmgren–Miner sums.

Corner points: ISO 6336-2:2006, Table 2 (Z_NT) and ISO 6336-3:2006, Table 3 (Y_NT);
between them straight lines in log–log coordinates (the tables' own rule).
"""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic.rating import (
    RatingError,
    bending_curve,
    bending_damage,
    bending_life_factor,
    pitting_curve,
    pitting_damage,
    pitting_life_factor,
)


@pytest.mark.parametrize(("treatment", "permitted", "cycles", "expected"), [
    # ISO 6336-2:2006, Table 2, line 1 (some pitting permitted)
    ("Eh", True, 6e5, 1.6), ("Eh", True, 1e7, 1.3), ("Eh", True, 1e9, 1.0), ("Eh", True, 1e10, 0.85),
    # line 2 (no pitting)
    ("V", False, 1e5, 1.6), ("V", False, 5e7, 1.0), ("V", False, 1e10, 0.85),
    # lines 3 and 4
    ("NT", False, 1e5, 1.3), ("NT", False, 2e6, 1.0), ("NV(nitrocar)", False, 1e5, 1.1),
    ("GG", False, 2e6, 1.0), ("Eh", False, 1e3, 1.6),
])
def test_z_nt_table_points(treatment, permitted, cycles, expected):
    assert pitting_life_factor(cycles, treatment, pitting_permitted=permitted) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(("treatment", "cycles", "expected"), [
    # ISO 6336-3:2006, Table 3
    ("V", 1e4, 2.5), ("V", 3e6, 1.0), ("Eh", 1e3, 2.5), ("Eh", 3e6, 1.0), ("Eh", 1e10, 0.85),
    ("NT", 1e3, 1.6), ("St", 3e6, 1.0), ("NV(nitrocar)", 1e3, 1.1), ("Eh", 10.0, 2.5),
])
def test_y_nt_table_points(treatment, cycles, expected):
    assert bending_life_factor(cycles, treatment) == pytest.approx(expected, rel=1e-12)


def test_between_points_log_log_line():
    # Z_NT of Eh without pitting at 10^6: log-linear between (1e5, 1.6) and (5e7, 1.0)
    t = (6 - 5) / (math.log10(5e7) - 5)
    assert pitting_life_factor(1e6, "Eh") == pytest.approx(10 ** ((1 - t) * math.log10(1.6)), rel=1e-12)


def test_optimum_long_life_is_flat():
    assert pitting_life_factor(1e10, "Eh", long_life="optimum") == 1.0
    assert bending_curve("Eh", long_life="optimum").cycles_to_failure(0.95) == math.inf


@settings(max_examples=30, deadline=None)
@given(st.floats(min_value=4.0, max_value=11.0), st.sampled_from(["Eh", "V", "NT", "St"]))
def test_cycles_to_failure_inverts_the_curve(log_n, treatment):
    for curve in (pitting_curve(treatment), bending_curve(treatment)):
        n = 10 ** log_n
        if n <= curve.static_cycles:
            continue
        assert curve.cycles_to_failure(curve.factor(n)) == pytest.approx(n, rel=1e-9)


def test_miner_sum_is_linear_in_cycles():
    curve = pitting_curve("Eh")
    n = curve.cycles_to_failure(1.2)
    assert pitting_damage([(1200.0, n / 4), (1200.0, n / 4)], 1000.0, "Eh") == pytest.approx(0.5)
    assert bending_damage([(500.0, 1e3)], 200.0, "Eh") == pytest.approx(1.0)  # at the static factor 2.5
    assert bending_damage([(600.0, 1.0)], 200.0, "Eh") == math.inf   # 3 x: over the static strength
    assert pitting_damage([(0.0, 1e9), (900.0, 0.0)], 1000.0, "Eh") == 0.0


def test_bad_input_names_the_field():
    with pytest.raises(RatingError, match="treatment"):
        pitting_curve("XX")
    with pytest.raises(RatingError, match="load cycles"):
        pitting_life_factor(0.0, "Eh")
    with pytest.raises(RatingError, match="reference_stress"):
        pitting_damage([(1.0, 1.0)], 0.0, "Eh")
    with pytest.raises(RatingError, match="long_life"):
        bending_curve("Eh", long_life="best")


# ---------------------------------------------------------------------------------------------
# Beyond 10^10 cycles: ISO 6336-2/-3:2006 end their curves at 10^10 (Table 2 / Table 3: the factor
# at N_L = 10^10 is the last value, 0.85 or 1.0 for optimum material, lubrication and manufacture),
# the 2019 editions continue the last line into the long-life region.
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("curve", [lambda e, **k: pitting_curve("Eh", edition=e, **k),
                                   lambda e, **k: pitting_curve("V", pitting_permitted=True, edition=e, **k),
                                   lambda e, **k: bending_curve("Eh", edition=e, **k),
                                   lambda e, **k: bending_curve("NT", edition=e, **k)])
def test_beyond_1e10_the_2006_edition_holds_and_2019_falls_on(curve):
    old, new = curve("2006"), curve("2019")
    for n in (1e10, 3e10, 1e12, 1e15):
        assert old.factor(n) == pytest.approx(0.85, rel=1e-12)
    assert new.factor(1e10) == pytest.approx(0.85, rel=1e-12)
    assert new.factor(1e11) < 0.85 and new.factor(1e12) < new.factor(1e11)
    # below 10^10 the editions agree
    for n in (1e4, 1e7, 5e9):
        assert old.factor(n) == new.factor(n)
    # a stress ratio under 0.85 never fails by the 2006 curve
    assert old.cycles_to_failure(0.84) == math.inf and new.cycles_to_failure(0.84) > 1e10
    assert "2006" in old.clause and "2019" in new.clause


@pytest.mark.parametrize("edition", ["2006", "2019"])
def test_optimum_conditions_are_flat_beyond_the_reference_in_both_editions(edition):
    curve = pitting_curve("Eh", long_life="optimum", edition=edition)
    assert [curve.factor(n) for n in (5e7, 1e10, 1e13)] == pytest.approx([1.0, 1.0, 1.0])
    assert bending_curve("V", long_life="optimum", edition=edition).factor(1e14) == pytest.approx(1.0)


@settings(max_examples=50, deadline=None)
@given(st.sampled_from(["Eh", "V", "NT", "NV(nitrocar)", "GG", "St"]), st.sampled_from(["2006", "2019"]),
       st.booleans(), st.floats(0.0, 16.0), st.floats(0.0, 4.0))
def test_life_factors_never_rise_with_the_cycles(treatment, edition, optimum, log_n, step):
    long_life = "optimum" if optimum else "standard"
    for curve in (pitting_curve(treatment, long_life=long_life, edition=edition),
                  bending_curve(treatment, long_life=long_life, edition=edition)):
        assert curve.factor(10 ** (log_n + step)) <= curve.factor(10 ** log_n) * (1 + 1e-12)


def test_unknown_edition_names_the_accepted():
    with pytest.raises(RatingError, match="expected one of 2006, 2019"):
        pitting_curve("Eh", edition="2003")


@pytest.mark.parametrize("standard", ["2006", "2019"])
def test_a_rating_past_1e10_cycles_takes_its_editions_curve(standard):
    from epicyclic.geometry import BasicRack, GearGeometry, MeshGeometry
    from epicyclic.rating import MeshInput, RatingSpec, rate_mesh

    pair = MeshGeometry(GearGeometry(19, BasicRack(4.0), 0.5), GearGeometry(104, BasicRack(4.0), 0.15))
    spec = RatingSpec(material="18CrNiMo7-6", flank_roughness=3.0, root_roughness=10.0, viscosity_40=100.0,
                      K_Hbeta=1.2, life=200000.0, standard=standard)
    rating = rate_mesh(MeshInput("pair", pair.with_tip_shortening(), 40.0, ("pinion", "wheel"), spec), 300.0, 3000.0)
    pinion = rating.gears[0]
    assert pinion["N_L"] == pytest.approx(60 * 200000 * 3000)  # 3.6e10
    if standard == "2006":
        assert pinion["Z_NT"] == pytest.approx(0.85) and pinion["Y_NT"] == pytest.approx(0.85)
    else:
        assert pinion["Z_NT"] < 0.85 and pinion["Y_NT"] < 0.85
