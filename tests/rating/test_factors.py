"""The single factors of ISO 6336-1/-2/-3/-5 against closed forms and an independent implementation.

"din3990" marks values printed by the independent implementation hanslhansl/din3990,
tests/test_1.py (pair z = 19/104, m_n = 4, x = 0.5/0.15, a_w = 248.5068 mm, spur).
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic.rating import (
    RatingError,
    RatingWarning,
    flank,
    load_factors,
    material,
    root,
)
from epicyclic.rating.materials import allowable_stress_numbers

A_WT = math.radians(21.531902292465457)  # din3990


def test_zone_factor_din3990_and_closed_form():
    assert flank.zone_factor(math.radians(20), A_WT, 0.0) == pytest.approx(2.3959406670899934, rel=1e-12)
    a = math.radians(20)
    assert flank.zone_factor(a, a, 0.0) == pytest.approx(math.sqrt(2 / (math.cos(a) * math.sin(a))))


def test_elasticity_and_contact_ratio_factors():
    assert flank.elasticity_factor(206000, 0.3, 206000, 0.3) == pytest.approx(189.81, abs=0.01)  # ISO: 189.8
    assert flank.contact_ratio_factor(1.5363235945832296, 0.0) == pytest.approx(0.906214912960638, rel=1e-12)
    assert flank.contact_ratio_factor(1.5, 1.2) == pytest.approx(math.sqrt(1 / 1.5))
    assert flank.helix_factor(math.radians(15)) == pytest.approx(1 / math.sqrt(math.cos(math.radians(15))))


def test_single_pair_factor_din3990():
    zb, zd = flank.single_pair_factors(44.0, 71.41663917972905 / 2, 19, 212.6, 390.9121302469379 / 2, 104, A_WT,
                                       248.506843355171, 1.5363235945832296, 0.0, False)
    assert zb == pytest.approx(1.00554704549864, rel=1e-9)     # din3990: M_1 = Z_B
    assert zd == 1.0                                           # M_2 = 0.8836 < 1
    zb_h, _ = flank.single_pair_factors(44.0, 35.7, 19, 212.6, 195.5, 104, A_WT, 248.5, 1.54, 1.0, False)
    assert zb_h == 1.0                                         # ε_β ≥ 1


def test_lubrication_factors_closed_forms():
    # C_ZL = 0.91 above 1200 N/mm²: Z_L = 0.91 + 4·0.09/(1.2 + 134/ν40)²; C_ZL = 0.83 below 850
    assert flank.lubricant_factor(100.0, 1500) == pytest.approx(0.91 + 0.36 / (1.2 + 1.34) ** 2)
    assert flank.lubricant_factor(100.0, 600) == pytest.approx(0.83 + 0.68 / (1.2 + 1.34) ** 2)
    assert float(flank.speed_factor(10.0, 1500)) == pytest.approx(0.93 + 0.14 / math.sqrt(0.8 + 3.2))
    rho_red = 10 * 100 / 110
    assert flank.roughness_factor(3, 3, 10, 100, False, 1500) == pytest.approx(
        (3 / (3 * (10 / rho_red) ** (1 / 3))) ** 0.08)
    with pytest.warns(RatingWarning, match="ISO 6336-2:2006, 11.2"):
        flank.lubricant_factor(5.0, 1500)


def test_work_hardening_factor():
    hard, soft = material("18CrNiMo7-6"), material("C45", hardness=190)
    assert flank.work_hardening_factor(hard, soft) == pytest.approx(1.2 - 60 / 1700)
    assert flank.work_hardening_factor(hard, hard) == 1.0


def test_root_factors():
    b = math.radians(15)
    assert root.helix_factor(b, 1.2, "2006") == pytest.approx(1 - 15 / 120)
    assert root.helix_factor(b, 1.2, "2019") == pytest.approx((1 - 15 / 120) / math.cos(b) ** 3)
    assert root.helix_factor(math.radians(40), 0.5, "2006") == pytest.approx(1 - 0.5 * 30 / 120)  # β capped at 30°
    assert root.relative_notch_sensitivity(2.5, "V", 600) == pytest.approx(1.0)   # the reference test gear
    assert root.relative_notch_sensitivity(4.0, "Eh", 850) > 1.0
    assert root.relative_surface_factor(0.5, "Eh") == 1.120
    assert root.relative_surface_factor(10.0, "Eh") == pytest.approx(1.674 - 0.529 * 11 ** 0.1)
    assert root.size_factor(10, "Eh") == pytest.approx(0.95) and root.size_factor(40, "V") == 0.85
    assert root.deep_tooth_factor(2.3, 4) == pytest.approx(-0.666 * 2.3 + 2.366)
    assert root.deep_tooth_factor(2.3, 6) == 1.0 and root.rim_factor(None, 4.5, 2.0) == 1.0
    assert root.rim_factor(4.5, 4.5, 2.0) == pytest.approx(1.6 * math.log(2.242))      # s_R/h_t = 1
    assert root.rim_factor(5.4, 4.5, 2.0) == 1.0 and root.rim_factor(7.0, 4.5, 2.0, internal=True) == 1.0
    assert root.rim_factor(5.0, 4.5, 2.0, internal=True) == pytest.approx(1.15 * math.log(8.324 / 2.5))
    with pytest.warns(RatingWarning, match="ISO 6336-3:2006, 7.4"):
        assert root.rim_factor(2.0, 4.5, 2.0, internal=True) == pytest.approx(1.15 * math.log(8.324 / 1.75))


def test_stiffness_and_deviations():
    # ISO 6336-1, 9.3: c' ≈ 14 N/(mm µm) for solid standard spur gears
    q = 0.04723 + 0.15551 / 20 + 0.25791 / 40                  # ISO 6336-1, eq. (71), x = 0
    c = load_factors.single_stiffness(20, 40, 0.0, 0.0, 0.0)
    assert c == pytest.approx(1 / q * 0.8 * 0.975)              # C_M = 0.8, C_B(h_fP* = 1.25) = 0.975
    assert 12.0 < c < 16.0 and 12.0 < load_factors.single_stiffness(40, 80, 0.0, 0.0, 0.0) < 16.0
    dev = load_factors.deviations(6, 100.0, 2.0, 20.0)
    assert dev["f_pt"] == 8.5  # ISO 1328-1:2013, (0.1 + 0.8 + 5) √2 = 8.34 µm rounded to 0.5 µm (5.2.3)
    assert load_factors.deviations(6, 100.0, 2.0, 20.0, "1995")["f_pt"] == 7.5  # ISO 1328-1:1995, Table 1
    with pytest.raises(RatingError, match="accuracy_grade"):
        load_factors.deviations(13, 100.0, 2.0, 20.0)


@settings(max_examples=25, deadline=None)
@given(st.floats(1e-6, 1e-2), st.floats(50.0, 3000.0), st.integers(12, 80))
def test_dynamic_factor_tends_to_one_at_rest(speed, line_load, z1):
    k, _, _ = load_factors.dynamic_factor(speed, z1, 18.0, 14.0, 0.02, line_load, 8.0, 6.0, 1.6)
    assert float(k) == pytest.approx(1.0, abs=1e-4) and float(k) >= 1.0


def test_dynamic_factor_regions():
    # ISO 6336-1, 6.3: subcritical N K + 1, main resonance, linear between 1.15 and 1.5, supercritical
    speeds = np.linspace(1.0, 60000.0, 4001)
    k, n, _ = load_factors.dynamic_factor(speeds, 20, 18.0, 14.0, 0.005, 300.0, 8.0, 6.0, 1.6)
    b_p, b_f = 14.0 * 8.0 / 300.0, 14.0 * 6.0 / 300.0
    sub = n <= 0.85
    assert np.allclose(k[sub], n[sub] * (0.32 * b_p + 0.34 * b_f + 0.23) + 1.0)
    main = (n > 0.85) & (n <= 1.15)
    assert np.allclose(k[main], 0.32 * b_p + 0.34 * b_f + 0.90 + 1.0)
    sup = n >= 1.5
    assert np.allclose(k[sup], 0.47 * b_p + 0.47 * b_f + 1.0)
    between = (n > 1.15) & (n < 1.5)
    assert np.all((k[between] <= k[main][0] + 1e-12) & (k[between] >= k[sup][0] - 1e-12))


def test_transverse_and_face_factors():
    kh, kf = load_factors.transverse_load_factors(np.array([50.0, 5000.0]), 20.0, 5.0, 1.6, 1.6, 0.9, "2006")
    assert kh[1] == 1.0 and kh[0] == pytest.approx(min(1.6 / (1.6 * 0.81), 0.8 * (0.9 + 0.4 * 20 * 5 / 50)))
    assert kf[0] <= 1.6 / (1.6 * (0.25 + 0.75 / 1.6)) + 1e-12
    given_h, given_f = load_factors.face_load_factors(1.3, 200.0, 17.0, 10.0, 1.0, 40.0, 4.5)
    assert float(given_h) == 1.3 and 1.0 < float(given_f) < 1.3
    c_h, _ = load_factors.face_load_factors(None, 200.0, 17.0, 10.0, 1.5, 40.0, 4.5)
    assert float(c_h) == pytest.approx(1 + 8.5 * 17 / 400)      # F_βy c_γβ/(2 F_m/b) ≤ 1


@pytest.mark.parametrize(("treatment", "hardness", "quality", "expected"), [
    # ISO 6336-5:2016 Table 1 lines; ME lines agree with the transcription in waa552/fyp-website data.js
    ("St", 190, "ME", (1.520 * 190 + 250, 0.386 * 190 + 147)),
    ("St(cast)", 180, "ME", (1.143 * 180 + 237, 0.254 * 180 + 137)),
    ("V", 300, "ME", (2.213 * 300 + 260, 0.358 * 300 + 231)),
    ("Eh", 700, "ME", (1650, 525)), ("NT", 750, "ME", (1450, 468)), ("NV", 550, "ME", (1217, 432)),
    ("Eh", 700, "MQ", (1500, 425)), ("Eh", 700, "ML", (1300, 312)),
])
def test_allowable_stress_numbers(treatment, hardness, quality, expected):
    assert allowable_stress_numbers(treatment, hardness, quality) == pytest.approx(expected)


def test_material_errors_and_range_warning():
    with pytest.raises(RatingError, match="unknown material 'X'"):
        material("X")
    with pytest.warns(RatingWarning, match="ISO 6336-5:2016, Table 1"):
        assert allowable_stress_numbers("V", 500, "MQ") == allowable_stress_numbers("V", 390, "MQ")
    with pytest.raises(RatingError, match="no ISO 6336-5 line for treatment 'GG'"):
        allowable_stress_numbers("GG", 200, "ML")
