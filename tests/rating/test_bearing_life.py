"""ISO 281:2007 bearing life: published examples, closed forms and the a_ISO equations' own properties."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic.errors import ModelError
from epicyclic.rating.bearing_life import (
    A_ISO_LIMIT,
    BearingLifeError,
    BearingRating,
    basic_rating_life,
    equivalent_load,
    life_modification_factor,
    rating_life_hours,
    reference_viscosity,
    reliability_factor,
    spectrum_life,
)


def test_skf_calculation_example_1():
    # SKF, Rolling bearings (catalogue 10000, 2013), "Selecting bearing size", Calculation example 1: a 6309
    # deep groove ball bearing, C = 55.3 kN, constant radial load F_r = P = 10 kN, 3000 r/min:
    # L10 = (55.3/10)^3 = 169 million revolutions, L10h = 10^6/(60*3000) * 169 = 940 operating hours.
    life = float(basic_rating_life(55.3e3, 10e3, 3.0))
    assert round(life) == 169
    assert round(float(rating_life_hours(life, 3000.0)), -1) == 940
    rating = BearingRating("deep groove ball", 55.3e3)
    assert rating.life_exponent == 3.0 and rating.kind == "ball"


@pytest.mark.parametrize("kind, exponent", [("cylindrical roller", 10 / 3), ("needle roller", 10 / 3),
                                            ("tapered roller", 10 / 3), ("deep groove ball", 3.0)])
def test_life_exponent_by_type(kind, exponent):
    # ISO 281:2007, 5.3 and 7.3: p = 3 for ball bearings, 10/3 for roller bearings
    assert BearingRating(kind, 1e4).life_exponent == pytest.approx(exponent)


@settings(max_examples=30, deadline=None)
@given(c=st.floats(1e3, 1e6), p=st.floats(10.0, 1e5), factor=st.floats(1.01, 10.0),
       exponent=st.sampled_from([3.0, 10 / 3]))
def test_life_scales_as_load_to_the_minus_p(c, p, factor, exponent):
    # closed form: L10 ∝ P^-p, and (C/P)^p = 1 at P = C
    ratio = basic_rating_life(c, p, exponent) / basic_rating_life(c, p * factor, exponent)
    assert float(ratio) == pytest.approx(factor ** exponent, rel=1e-12)
    assert float(basic_rating_life(c, c, exponent)) == pytest.approx(1.0)


def test_no_load_or_no_rotation_is_an_infinite_life():
    assert math.isinf(float(basic_rating_life(1e4, 0.0, 3.0)))
    assert math.isinf(float(rating_life_hours(100.0, 0.0)))


def test_reference_viscosity_iso_281_eq_13():
    # ISO 281:2007, 9.3.3: nu1 = 45000 n^-0.83 dm^-0.5 below 1000 r/min, 4500 n^-0.5 dm^-0.5 from 1000
    assert float(reference_viscosity(3000.0, 72.5)) == pytest.approx(4500 / math.sqrt(3000 * 72.5), rel=1e-12)
    assert float(reference_viscosity(500.0, 100.0)) == pytest.approx(45000 * 500 ** -0.83 / 10.0, rel=1e-12)
    # the two branches meet within 3 % at 1000 r/min (Figure 7 is one curve)
    low, high = reference_viscosity([999.999, 1000.0], 50.0)
    assert high == pytest.approx(low, rel=0.03)


@pytest.mark.parametrize("kind", ["ball", "roller"])
@pytest.mark.parametrize("edge", [0.4, 1.0])
def test_a_iso_bands_join_continuously(kind, edge):
    # ISO 281:2007, 9.3 (radial ball and roller bearings): the constants of the three kappa bands make a_ISO continuous at 0.4 and 1
    # (a check on the transcribed constants: 2.2649/0.4^0.054381 = 2.38062 and 1.9987/0.4^0.19087 = 2.38069,
    # equal to the standard's 5 digits; the exponent -9.3 magnifies that rounding to < 1e-3 in a_ISO)
    below, above = life_modification_factor([edge * (1 - 1e-12), edge], 0.3, kind)
    assert below == pytest.approx(above, rel=1e-3)


@pytest.mark.parametrize("kind", ["ball", "roller"])
def test_a_iso_limits(kind):
    # without fatigue-load margin a_ISO = 0.1 at every kappa; a_ISO <= 50; kappa above 4 counts as 4
    assert life_modification_factor([0.1, 1.0, 4.0], 0.0, kind) == pytest.approx([0.1, 0.1, 0.1])
    assert float(life_modification_factor(4.0, 5.0, kind)) == A_ISO_LIMIT
    assert float(life_modification_factor(10.0, 0.2, kind)) == float(life_modification_factor(4.0, 0.2, kind))


def test_a_iso_closed_form_values():
    # eq. 8 and 9 evaluated by hand: ball, kappa = 1, e_C C_u/P = 0.1:
    # 0.1 [1 - (2.5671 - 1.9987)^0.83 0.1^(1/3)]^-9.3; roller, kappa = 2, ratio 0.2:
    # 0.1 [1 - (1.5859 - 1.2348/2^0.071739) 0.2^0.4]^-9.185
    ball = 0.1 * (1 - (2.5671 - 1.9987) ** 0.83 * 0.1 ** (1 / 3)) ** -9.3
    roller = 0.1 * (1 - (1.5859 - 1.2348 / 2 ** 0.071739) * 0.2 ** 0.4) ** -9.185
    assert float(life_modification_factor(1.0, 0.1, "ball")) == pytest.approx(ball, rel=1e-12)
    assert float(life_modification_factor(2.0, 0.2, "roller")) == pytest.approx(roller, rel=1e-12)


@settings(max_examples=40, deadline=None)
@given(k1=st.floats(0.1, 4.0), k2=st.floats(0.1, 4.0), r1=st.floats(0.0, 1.0), r2=st.floats(0.0, 1.0),
       kind=st.sampled_from(["ball", "roller"]))
def test_a_iso_grows_with_kappa_and_load_margin(k1, k2, r1, r2, kind):
    lo_k, hi_k = sorted((k1, k2))
    lo_r, hi_r = sorted((r1, r2))
    a = life_modification_factor([lo_k, hi_k, lo_k], [lo_r, lo_r, hi_r], kind)
    assert a[1] >= a[0] * (1 - 1e-12) and a[2] >= a[0] * (1 - 1e-12)
    assert np.all((a >= 0.1 - 1e-12) & (a <= A_ISO_LIMIT))


def test_kappa_below_the_standard_is_refused():
    with pytest.raises(BearingLifeError, match="at least 0.1"):
        life_modification_factor(0.05, 0.2, "roller")


def test_reliability_factor_table_12():
    # ISO 281:2007, Table 12
    assert reliability_factor(90) == 1.0 and reliability_factor(95) == 0.64 and reliability_factor(99) == 0.25
    with pytest.raises(BearingLifeError, match="Table 12"):
        reliability_factor(93)


@settings(max_examples=30, deadline=None)
@given(loads=st.lists(st.floats(100.0, 5e4), min_size=1, max_size=6),
       data=st.data(), exponent=st.sampled_from([3.0, 10 / 3]))
def test_equivalent_load_and_spectrum_life_agree(loads, data, exponent):
    # Palmgren-Miner (SKF, Rolling bearings 2013, variable operating conditions): L_h from P_eq and the mean speed equals 1/Σ(q_i/L_h,i)
    n = len(loads)
    speeds = data.draw(st.lists(st.floats(10.0, 1e4), min_size=n, max_size=n))
    weights = data.draw(st.lists(st.floats(0.01, 1.0), min_size=n, max_size=n))
    q = np.array(weights) / sum(weights)
    c = 1e5
    per_case = rating_life_hours(basic_rating_life(c, loads, exponent), speeds)
    p_eq = equivalent_load(loads, speeds, q, exponent)
    hours = 1e6 * float(basic_rating_life(c, p_eq, exponent)) / (60 * float(np.sum(q * np.array(speeds))))
    assert spectrum_life(per_case, q) == pytest.approx(hours, rel=1e-9)
    assert min(loads) * (1 - 1e-12) <= p_eq <= max(loads) * (1 + 1e-12)


def test_rating_inputs_are_checked():
    with pytest.raises(BearingLifeError, match="unknown type 'roller'"):
        BearingRating("roller", 1e4)
    with pytest.raises(BearingLifeError, match="dynamic_load_rating C must be a positive"):
        BearingRating("needle roller", -1.0)
    with pytest.raises(BearingLifeError, match="pitch_diameter, viscosity, contamination missing"):
        BearingRating("needle roller", 1e4, fatigue_load_limit=1e3)
    with pytest.raises(BearingLifeError, match="contamination e_C must lie in"):
        BearingRating("needle roller", 1e4, 1e3, 20.0, 10.0, 1.5)
    assert issubclass(BearingLifeError, ModelError) and issubclass(BearingLifeError, ValueError)


def test_modified_life_factor_of_a_rating():
    # a_1 a_ISO at one point by hand: roller, d_m 20 mm, 2000 r/min -> nu1 = 4500/sqrt(40000) = 22.5 mm²/s,
    # nu = 45 -> kappa = 2; e_C C_u/P = 0.5 * 2000/5000 = 0.2; reliability 99 % -> a_1 = 0.25
    b = BearingRating("cylindrical roller", 5e4, 2000.0, 20.0, 45.0, 0.5, reliability=99)
    expected = 0.25 * float(life_modification_factor(2.0, 0.2, "roller"))
    assert float(b.life_factor(5000.0, 2000.0)) == pytest.approx(expected, rel=1e-12)
    assert float(BearingRating("cylindrical roller", 5e4).life_factor(5000.0, 2000.0)) == 1.0
