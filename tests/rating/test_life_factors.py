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
