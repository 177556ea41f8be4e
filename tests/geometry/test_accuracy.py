"""ISO 1328-1 flank tolerances of both editions (epicyclic.geometry.accuracy).

Published values: ISO 1328-1:1995, Table 1 (±f_pt) and Table 2 (F_p), the row 5 ≤ d ≤ 20 mm,
0.5 ≤ m_n ≤ 2 mm, grades 0 … 12 (the tables are the grade-5 formulas at the geometric means of the
ranges times √2^(Q−5), rounded by clause 6).  ISO 1328-1:2013 prints no tables; its eqs. (5)–(12)
are checked as closed forms at the gear's own d, m_n, b, and the two editions against each other.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from epicyclic.geometry.accuracy import (
    EDITIONS,
    base_pitch_deviation,
    flank_tolerances,
    round_tolerance,
    step_factor,
)
from epicyclic.geometry.errors import GeometryError

# ISO 1328-1:1995, Table 1 and Table 2, 5 <= d <= 20 mm, 0.5 <= m <= 2 mm, grades 0 ... 12 (µm)
TABLE_1_F_PT = (0.8, 1.2, 1.7, 2.3, 3.3, 4.7, 6.5, 9.5, 13.0, 19.0, 26.0, 37.0, 53.0)
TABLE_2_F_P = (2.0, 2.8, 4.0, 5.5, 8.0, 11.0, 16.0, 23.0, 32.0, 45.0, 64.0, 90.0, 127.0)


@pytest.mark.parametrize("grade", range(13))
def test_1995_tables_row_d_5_20_m_05_2(grade):
    t = flank_tolerances(grade, 12.0, 1.0, 10.0, "1995")
    assert t.f_pt == TABLE_1_F_PT[grade]
    assert t.F_p == TABLE_2_F_P[grade]


def test_1995_takes_the_geometric_mean_of_the_range():
    # every d of 50 < d <= 125 mm gives the same tolerance; 125 itself belongs to the lower range
    values = {flank_tolerances(6, d, 3.0, 20.0, "1995").unrounded["f_pt"] for d in (50.001, 80.0, 125.0)}
    assert len(values) == 1
    mean_d, mean_m = math.sqrt(50 * 125), math.sqrt(2 * 3.5)
    expected = (0.3 * (mean_m + 0.4 * math.sqrt(mean_d)) + 4) * math.sqrt(2)
    assert values.pop() == pytest.approx(expected, rel=1e-12)
    assert flank_tolerances(6, 125.001, 3.0, 20.0, "1995").unrounded["f_pt"] > expected


def test_2013_closed_forms_and_totals_from_unrounded_parts():
    d, m, b, step = 120.0, 3.0, 30.0, math.sqrt(2)  # class 6
    t = flank_tolerances(6, d, m, b, "2013")
    raw = t.unrounded
    assert raw["f_pt"] == pytest.approx((0.001 * d + 0.4 * m + 5) * step)
    assert raw["F_p"] == pytest.approx((0.002 * d + 0.55 * math.sqrt(d) + 0.7 * m + 12) * step)
    assert raw["f_falpha"] == pytest.approx((0.55 * m + 5) * step)
    assert raw["f_Halpha"] == pytest.approx((0.4 * m + 0.001 * d + 4) * step)
    assert raw["F_alpha"] == pytest.approx(math.hypot(raw["f_falpha"], raw["f_Halpha"]))
    assert raw["f_Hbeta"] == pytest.approx((0.05 * math.sqrt(d) + 0.35 * math.sqrt(b) + 4) * step)
    assert raw["f_fbeta"] == pytest.approx((0.07 * math.sqrt(d) + 0.45 * math.sqrt(b) + 4) * step)
    assert raw["F_beta"] == pytest.approx(math.hypot(raw["f_Hbeta"], raw["f_fbeta"]))
    assert raw["F_r"] == pytest.approx(0.9 * raw["F_p"])
    assert (t.f_pt, t.F_p) == (9.0, 29.0)  # 8.94 -> 0.5 µm steps, 28.80 -> whole µm


def test_the_editions_differ():
    # the 2013 profile form tolerance no longer depends on d, the 1995 one does
    a, b = (flank_tolerances(6, d, 4.0, 40.0, "2013").unrounded["f_falpha"] for d in (60.0, 900.0))
    assert a == b
    a, b = (flank_tolerances(6, d, 4.0, 40.0, "1995").unrounded["f_falpha"] for d in (60.0, 900.0))
    assert b > a
    assert flank_tolerances(6, 200.0, 4.0, 40.0, "1995").f_pt != flank_tolerances(6, 200.0, 4.0, 40.0, "2013").f_pt


def test_rounding_rule():
    assert [round_tolerance(v) for v in (12.49, 10.5, 10.0, 7.3, 7.2, 5.0, 4.96, 4.94, 0.84)] == [
        12.0, 11.0, 10.0, 7.5, 7.0, 5.0, 5.0, 4.9, 0.8]


def test_base_pitch_and_step():
    assert base_pitch_deviation(10.0, math.radians(20)) == pytest.approx(10 * math.cos(math.radians(20)))
    assert step_factor(9) == pytest.approx(4.0) and step_factor(3, "1995") == pytest.approx(0.5)


@pytest.mark.parametrize(("args", "match"), [
    ((6, 100.0, 2.0, 20.0, "1997"), "edition must be one of '1995', '2013'"),
    ((0, 100.0, 2.0, 20.0, "2013"), "1 ... 11"),
    ((13, 100.0, 2.0, 20.0, "1995"), "0 ... 12"),
    ((6.0, 100.0, 2.0, 20.0, "2013"), "whole number"),
    ((6, 100.0, 80.0, 20.0, "2013"), "normal module 80 mm lies outside the scope"),
    ((6, 12000.0, 2.0, 20.0, "1995"), "reference diameter 12000 mm lies outside"),
    ((6, 100.0, -2.0, 20.0, "2013"), "normal module must be a positive"),
])
def test_bad_input_names_the_value_and_the_range(args, match):
    with pytest.raises(GeometryError, match=match):
        flank_tolerances(*args)


@given(st.sampled_from(sorted(EDITIONS)), st.integers(1, 10), st.floats(6, 9000), st.floats(0.6, 60), st.floats(5, 900))
def test_tolerances_grow_with_the_grade(edition, grade, d, m, b):
    low, high = flank_tolerances(grade, d, m, b, edition), flank_tolerances(grade + 1, d, m, b, edition)
    for symbol, value in low.unrounded.items():
        assert high.unrounded[symbol] == pytest.approx(value * math.sqrt(2), rel=1e-12)
        assert getattr(high, symbol) >= getattr(low, symbol) > 0


# KISSsoft calculation report of the NREL 5 MW gearbox, stage 1 (gfsReboucas/Drivetrain, @NREL_5MW/stage_01.rtf,
# section 7 "Gear accuracy, according to ISO 1328-1:1995, ISO 1328-2:1997"): m_n = 45 mm, b = 491 mm, grade 6,
# sun d = 855 mm, planet 765 mm, ring 2520 mm; printed tolerances in µm.
NREL_PRINTED = {
    855.0: {"f_pt": 33, "f_falpha": 33, "f_Halpha": 27, "F_alpha": 42, "f_fbeta": 21, "f_Hbeta": 21, "F_beta": 30,
            "F_p": 81, "F_r": 65},
    765.0: {"f_pt": 33, "f_falpha": 33, "f_Halpha": 27, "F_alpha": 42, "f_fbeta": 21, "f_Hbeta": 21, "F_beta": 30,
            "F_p": 81, "F_r": 65},
    2520.0: {"f_pt": 38, "f_falpha": 40, "f_Halpha": 32, "F_alpha": 51, "f_fbeta": 24, "f_Hbeta": 24, "F_beta": 34,
             "F_p": 132, "F_r": 105},
}


@pytest.mark.parametrize("diameter", sorted(NREL_PRINTED))
def test_1995_kisssoft_report_nrel_5mw_stage_1(diameter):
    t = flank_tolerances(6, diameter, 45.0, 491.0, "1995")
    for symbol, printed in NREL_PRINTED[diameter].items():
        assert getattr(t, symbol) == printed, symbol
    # the report's base pitch deviations 31.00 and 35.70 µm: f_pt cos 20°
    printed_f_pb = 31.0 if diameter < 1000 else 35.7
    assert base_pitch_deviation(t.f_pt, math.radians(20)) == pytest.approx(printed_f_pb, abs=0.05)
