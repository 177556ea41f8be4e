"""The spin-loss models one by one: oil (ASTM D341), clutch drag, pump, seals, churning, windage, thermal."""

from __future__ import annotations

import math

import numpy as np
import pytest

from epicyclic.losses import (ChurningGear, ClutchDrag, Housing, LossModelError, Oil, OilPump, ShaftSeal,
                              WindageGear, steady_temperature)
from epicyclic.losses.churning import GRAVITY
from epicyclic.losses.thermal import STEFAN_BOLTZMANN

RPM = math.pi / 30.0


# ---------------------------------------------------------------------- oil
def test_walther_passes_through_the_two_data_sheet_points():
    oil = Oil(46.0, 6.8)
    assert oil.kinematic_viscosity(40.0) == pytest.approx(46.0, rel=1e-12)
    assert oil.kinematic_viscosity(100.0) == pytest.approx(6.8, rel=1e-12)


def test_walther_against_a_third_published_point():
    # Shell Tellus S2 M 46 data sheet: ν = 580 mm²/s at 0 °C, 46 at 40 °C, 6.8 at 100 °C (VI 98).
    # ASTM D341 from the 40/100 °C points predicts the 0 °C value within 1 % (the chart's accuracy).
    assert Oil(46.0, 6.8).kinematic_viscosity(0.0) == pytest.approx(580.0, rel=0.01)


def test_walther_independent_closed_form():
    # ASTM D341 eq. (1): log log (ν + 0.7) = A − B log T, solved by hand for 29.5 / 6.0 mm²/s at 80 °C
    z = [math.log10(math.log10(v + 0.7)) for v in (29.5, 6.0)]
    t = [math.log10(273.15 + c) for c in (40.0, 100.0)]
    b = (z[0] - z[1]) / (t[1] - t[0])
    nu = 10 ** (10 ** (z[0] + b * t[0] - b * math.log10(353.15))) - 0.7
    assert Oil(29.5, 6.0).kinematic_viscosity(80.0) == pytest.approx(nu, rel=1e-12)


def test_density_and_dynamic_viscosity():
    oil = Oil(29.5, 6.0, density=850.0, expansion=6.5e-4)
    assert oil.density_at(15.0) == pytest.approx(850.0)
    assert oil.density_at(95.0) == pytest.approx(850.0 * (1 - 6.5e-4 * 80.0))
    assert oil.dynamic_viscosity(80.0) == pytest.approx(oil.kinematic_viscosity(80.0) * oil.density_at(80.0) / 1e3)


@pytest.mark.parametrize("args, match", [((6.0, 29.5), "must exceed viscosity_100"), ((30.0, 1.5), ">= 2 mm"),
                                         ((-1.0, 6.0), "viscosity_40"), ((30.0, 6.0, 100.0), "density")])
def test_bad_oil(args, match):
    with pytest.raises(LossModelError, match=match):
        Oil(*args)


def test_temperature_outside_the_range_is_refused():
    with pytest.raises(LossModelError, match="temperature must lie in"):
        Oil(30.0, 6.0).kinematic_viscosity(250.0)


# ---------------------------------------------------------------------- clutch drag
def _drag(**kw):
    return ClutchDrag("C", **{"gaps": 8, "inner_radius": 65.0, "outer_radius": 80.0, "clearance": 0.2, **kw})


def test_full_film_is_newtons_couette_torque():
    # T = N π η ω (r_o⁴ − r_i⁴) / (2h) (Yuan et al. 2007, eq. 5 with r_e = r_o)
    eta, n = 10.0, 1500.0
    expected = 8 * math.pi * eta * 1e-3 * n * RPM * (0.080 ** 4 - 0.065 ** 4) / (2 * 0.2e-3)
    assert float(_drag().torque(n, eta, 850.0)) == pytest.approx(expected, rel=1e-12)
    assert float(_drag(groove_factor=0.6).torque(n, eta, 850.0)) == pytest.approx(0.6 * expected, rel=1e-12)


def test_film_flow_is_yuans_eq_9():
    # Q = π ρ ω² h³ (r_o² − r_i²) / (40 η ln(r_o/r_i)), m³/s → l/min
    rho, eta, n = 850.0, 10.0, 1000.0
    q = math.pi * rho * (n * RPM) ** 2 * 0.2e-3 ** 3 * (0.08 ** 2 - 0.065 ** 2) / (40 * 1e-2 * math.log(80 / 65))
    assert float(_drag().film_flow(n, eta, rho)) == pytest.approx(q * 6e4, rel=1e-12)


def test_drag_rises_linearly_peaks_where_the_supply_runs_short_and_falls():
    drag = _drag(supply=2.0, mist=False)  # the film alone (Yuan et al. 2007); the mist: test_clutch_drag_mist.py
    peak = drag.peak_slip(10.0, 850.0)
    assert float(drag.film_flow(peak, 10.0, 850.0)) == pytest.approx(2.0 / 8, rel=1e-9)
    below = drag.torque(np.array([0.25, 0.5, 1.0]) * peak, 10.0, 850.0)
    assert below / below[0] == pytest.approx([1.0, 2.0, 4.0], rel=1e-9)  # full film: ∝ ω
    after = drag.torque(np.array([1.0, 1.05, 1.1]) * peak, 10.0, 850.0)
    assert after[0] > after[1] > after[2] >= 0.0  # aeration: the film shrinks
    radius = drag.film_radius(1.05 * peak, 10.0, 850.0)
    assert float(drag.film_flow(1.05 * peak, 10.0, 850.0, radius)) == pytest.approx(2.0 / 8, rel=1e-9)


def test_drag_needs_no_sign_and_is_zero_at_zero_slip():
    drag = _drag(supply=1.0)
    assert drag.torque(-700.0, 8.0, 850.0) == pytest.approx(drag.torque(700.0, 8.0, 850.0))
    assert float(drag.torque(0.0, 8.0, 850.0)) == 0.0


@pytest.mark.parametrize("kw, match", [({"gaps": 0}, "gaps"), ({"outer_radius": 60.0}, "outer_radius must exceed"),
                                       ({"clearance": 10.0}, "no thin film"), ({"groove_factor": 1.5}, "groove"),
                                       ({"supply": -1.0}, "supply")])
def test_bad_clutch_drag(kw, match):
    with pytest.raises(LossModelError, match=match):
        _drag(**kw)


# ---------------------------------------------------------------------- pump
def test_pump_torque_and_power_are_the_hydraulic_closed_form():
    # M = V Δp / (2π η_hm) (Will & Gebhardt 2011, §5.1): 20 cm³, 10 bar, 0.85
    pump = OilPump(20.0, 10.0, 0.85)
    assert pump.torque() == pytest.approx(20e-6 * 10e5 / (2 * math.pi * 0.85))
    # P = V n Δp / η_hm: 20e-6 m³ · 2000/60 1/s · 1e6 Pa / 0.85
    assert float(pump.loss(2000.0)) == pytest.approx(20e-6 * 2000 / 60 * 1e6 / 0.85)


def test_pump_pressure_by_gear():
    pump = OilPump(14.0, {"1": 9.0, "R": 12.0}, default_pressure=6.0)
    assert (pump.pressure_in("1"), pump.pressure_in("R"), pump.pressure_in("5")) == (9.0, 12.0, 6.0)
    with pytest.raises(LossModelError, match="no line pressure for gear '5'"):
        OilPump(14.0, {"1": 9.0}).pressure_in("5")


# ---------------------------------------------------------------------- seals
def test_seal_is_the_simrit_formula_of_iso_tr_14179_2():
    # ISO/TR 14179-2 (after Simrit): P = 7.69e-6 d² n W → 50 mm at 3000 1/min: 57.675 W
    seal = ShaftSeal("out", 50.0, count=2)
    assert float(seal.loss(3000.0)) == pytest.approx(2 * 57.675)
    assert seal.torque() * 3000.0 * RPM == pytest.approx(2 * 57.675)


# ---------------------------------------------------------------------- churning
def test_submerged_area_of_a_half_dipped_gear():
    # h = R: θ = π/2, S_m = R² π (both half faces) + π R b (half the rim)
    gear = ChurningGear("out", 72.0, 24.0, 72.0, 1.5)
    assert gear.submerged_area == pytest.approx(0.072 ** 2 * math.pi + math.pi * 0.072 * 0.024)


def test_churning_is_changenet_velex_low_reynolds_fit():
    # Changenet & Velex 2007, eqs. (4)-(5), recomputed by hand for a 144 mm gear, b = 24 mm, h = 36 mm,
    # V0 = 1.5 l at 500 1/min and ν = 60 mm²/s: Re_c = ω R b / ν = 1508 < 6000 (first regime)
    r, b, h, v0, n, nu, rho = 0.072, 0.024, 0.036, 1.5e-3, 500.0, 60e-6, 870.0
    w = n * RPM
    assert w * r * b / nu < 6000
    cm = 1.366 * (h / (2 * r)) ** 0.45 * (v0 / (2 * r) ** 3) ** 0.1 * (w ** 2 * r / GRAVITY) ** -0.6 \
        * (w * r ** 2 / nu) ** -0.21
    theta = math.acos(1 - h / r)
    s_m = r ** 2 * (2 * theta - math.sin(2 * theta)) + 2 * theta * r * b
    expected = 0.5 * rho * w ** 2 * s_m * r ** 3 * cm
    gear = ChurningGear("out", 72.0, 24.0, 36.0, 1.5)
    assert float(gear.torque(n, 60.0, rho)) == pytest.approx(expected, rel=1e-12)


def test_churning_high_reynolds_fit_and_speed_exponent():
    gear = ChurningGear("out", 72.0, 24.0, 36.0, 1.5)
    # Re_c > 9000 (3000 1/min, 10 mm²/s): C_m = 3.644 (h/D)^0.1 (V0/D³)^-0.35 Fr^-0.88 (b/D)^0.85
    r, d = 0.072, 0.144
    w = 3000.0 * RPM
    cm = 3.644 * 0.25 ** 0.1 * (1.5e-3 / d ** 3) ** -0.35 * (w ** 2 * r / GRAVITY) ** -0.88 * (0.024 / d) ** 0.85
    assert float(gear.coefficient(3000.0, 10.0)) == pytest.approx(cm, rel=1e-12)
    # first regime: T ∝ ω² Fr^-0.6 Re^-0.21 ∝ ω^0.59
    low = gear.torque(np.array([200.0, 400.0]), 300.0, 870.0)
    assert low[1] / low[0] == pytest.approx(2 ** 0.59, rel=1e-9)


def test_churning_immersion_deeper_than_the_gear_is_refused():
    with pytest.raises(LossModelError, match="deeper than the gear"):
        ChurningGear("out", 50.0, 20.0, 120.0, 1.0)


# ---------------------------------------------------------------------- windage
def test_windage_laminar_is_cochrans_free_disc():
    # Schlichting & Gersten 2000, §5.2.4: C_M = 3.87 / √Re (both faces), T = ½ C_M ρ ω² R⁵
    gear = WindageGear("in", 50.0, 0.0 + 1e-9)
    w = 1000.0 * RPM
    re = w * 0.05 ** 2 / 15.1e-6
    assert re < 3e5
    assert float(gear.torque(1000.0)) == pytest.approx(0.5 * 3.87 / math.sqrt(re) * 1.204 * w ** 2 * 0.05 ** 5,
                                                       rel=1e-6)


def test_windage_turbulent_and_rim_factor():
    # turbulent free disc: C_M = 0.146 Re^-0.2 (von Kármán; Theodorsen & Regier 1944); rim (1 + 2.3 b/R), Dawson
    gear = WindageGear("in", 150.0, 30.0)
    w = 8000.0 * RPM
    re = w * 0.15 ** 2 / 15.1e-6
    assert re > 3e5
    expected = 0.5 * 0.146 * re ** -0.2 * 1.204 * w ** 2 * 0.15 ** 5 * (1 + 2.3 * 30 / 150)
    assert float(gear.torque(8000.0)) == pytest.approx(expected, rel=1e-12)


# ---------------------------------------------------------------------- thermal
def test_housing_heat_paths():
    h = Housing(1.2, ambient=20.0, heat_transfer=8.0, emissivity=0.9, cooler=50.0, coolant=30.0)
    t = 90.0
    expected = 1.2 * (8.0 * 70.0 + 0.9 * STEFAN_BOLTZMANN * (363.15 ** 4 - 293.15 ** 4)) + 50.0 * 60.0
    assert float(h.dissipated(t)) == pytest.approx(expected)
    # McAdams: natural convection 1.32 (Δϑ / L)^0.25
    assert float(Housing(1.0, height=0.4).convection(60.0)) == pytest.approx(1.32 * (40.0 / 0.4) ** 0.25)


def test_steady_temperature_of_a_linear_housing():
    # h A Δϑ = P with radiation negligible: 300 W on 1 m² at 10 W/(m² K) → Δϑ = 30 K
    housing = Housing(1.0, ambient=20.0, heat_transfer=10.0, emissivity=1e-12)
    t = steady_temperature(housing, lambda temperature: np.full(np.shape(temperature), 300.0), (3,))
    assert t == pytest.approx([50.0] * 3, abs=1e-6)


def test_no_steady_state_is_a_clear_error():
    with pytest.raises(LossModelError, match="exceed what the housing sheds"):
        steady_temperature(Housing(0.1), lambda t: np.full(np.shape(t), 1e5), (1,))


def test_walther_line_from_a_table():
    # two points: the line through them; Tellus S2 M 46's three data-sheet points (0/40/100 °C): within 0.5 %
    assert Oil.from_table([(40.0, 46.0), (100.0, 6.8)]).viscosity_40 == pytest.approx(46.0, rel=1e-12)
    fitted = Oil.from_table([(0.0, 580.0), (40.0, 46.0), (100.0, 6.8)])
    assert fitted.kinematic_viscosity(40.0) == pytest.approx(46.0, rel=0.005)
    assert fitted.kinematic_viscosity(0.0) == pytest.approx(580.0, rel=0.005)
    with pytest.raises(LossModelError, match="two different temperatures"):
        Oil.from_table([(40.0, 46.0)])
    with pytest.raises(LossModelError, match="fall with temperature"):
        Oil.from_table([(40.0, 6.0), (100.0, 46.0)])


from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


@settings(max_examples=40, deadline=None)
@given(gaps=st.integers(1, 30), inner=st.floats(20.0, 150.0), width=st.floats(2.0, 60.0),
       clearance=st.floats(0.05, 0.5), supply=st.one_of(st.none(), st.floats(0.0, 20.0)),
       slip=st.floats(-9000.0, 9000.0), viscosity=st.floats(1.0, 500.0), density=st.floats(700.0, 1000.0))
def test_drag_is_finite_non_negative_and_at_most_the_full_film(gaps, inner, width, clearance, supply, slip, viscosity,
                                                                density):
    outer = inner + width
    drag = ClutchDrag("C", gaps, inner, outer, min(clearance, 0.04 * outer), supply)
    full = ClutchDrag("C", gaps, inner, outer, min(clearance, 0.04 * outer))
    t = float(drag.torque(slip, viscosity, density))
    assert math.isfinite(t) and 0.0 <= t <= float(full.torque(slip, viscosity, density)) * (1 + 1e-12)
    assert float(drag.loss(slip, viscosity, density)) >= 0.0
    r_e = float(drag.film_radius(slip, viscosity, density))
    assert inner <= r_e <= outer


@settings(max_examples=40, deadline=None)
@given(speed=st.floats(-8000.0, 8000.0), nu=st.floats(2.0, 1000.0), radius=st.floats(20.0, 200.0),
       immersion=st.floats(0.01, 1.0))
def test_churning_windage_seals_pump_never_gain_power(speed, nu, radius, immersion):
    gear = ChurningGear("s", radius, 20.0, immersion * 2 * radius, 3.0)
    for loss in (gear.loss(speed, nu, 860.0), WindageGear("s", radius, 20.0).loss(speed),
                 ShaftSeal("s", 40.0).loss(speed), OilPump(15.0, 8.0).loss(speed)):
        assert math.isfinite(float(loss)) and float(loss) >= 0.0
