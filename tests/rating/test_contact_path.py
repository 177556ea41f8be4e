"""The path of contact (epicyclic.rating.contact_path) against closed forms.

The texts of ISO/TS 6336-22:2018 and ISO/TS 6336-20:2017 were not reachable when this was written, so no
printed example of the standards is reproduced here; the tests check the path against independent closed
forms: ε_α of ISO 21771 (MeshGeometry.contact_ratio), the tip circles at A and E, the nominal contact stress
σ_H0 = Z_H Z_E √(F_t/(d1 b) (u ± 1)/u) of ISO 6336-2:2019 eq. (2) (spur, Z_ε = Z_β = 1) at the pitch point,
the kinematics of two involutes rolling on their base circles (v_g = (ω1 ± ω2)·|CY|), and the balance of
the load sharing factor X(Γ) + X(Γ + p_bt) = 1 in the double contact zones.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from epicyclic.geometry.gear import BasicRack, GearGeometry, MeshGeometry
from epicyclic.rating import RatingError, RatingWarning, flank
from epicyclic.rating.contact_path import POINTS, contact_path

RACK = BasicRack(4.0)
EXTERNAL = MeshGeometry(GearGeometry(20, RACK, 0.2), GearGeometry(40, RACK, 0.1), "pair")
INTERNAL = MeshGeometry(GearGeometry(20, RACK, 0.2), GearGeometry(70, RACK, 0.1, internal=True), "planet-ring")
HELICAL_RACK = BasicRack(4.0, helix_angle=15.0)
HELICAL = MeshGeometry(GearGeometry(20, HELICAL_RACK, 0.2), GearGeometry(40, HELICAL_RACK, 0.1), "helical")


@pytest.mark.parametrize("mesh", [EXTERNAL, INTERNAL, HELICAL])
def test_points_contact_ratio_and_tip_circles(mesh):
    path = contact_path(mesh, 30.0)
    assert path.eps_alpha == pytest.approx(mesh.contact_ratio, rel=1e-12)
    assert list(path.points) == list(POINTS)
    values = [path.points[k] for k in POINTS if k != "C"]
    assert values == sorted(values)
    d1, d2 = path.diameters([path.points["A"], path.points["E"]])
    assert d2[0] == pytest.approx(mesh.gear2.tip_diameter, rel=1e-12)     # A: tip of gear 2
    assert d1[1] == pytest.approx(mesh.gear1.tip_diameter, rel=1e-12)     # E: tip of gear 1
    assert path.g_of(path.points["E"]) - path.g_of(path.points["A"]) == pytest.approx(path.length)
    assert path.g_of(path.points["D"]) - path.g_of(path.points["A"]) == pytest.approx(path.base_pitch)
    assert float(path.gamma_of(path.g_of(0.3))) == pytest.approx(0.3)
    d1c, d2c = path.diameters(0.0)
    assert (float(d1c), float(d2c)) == pytest.approx(mesh.operating_pitch_diameters, rel=1e-12)


@pytest.mark.parametrize("mesh", [EXTERNAL, INTERNAL])
def test_pressure_at_pitch_point_is_iso_6336_2_nominal_stress(mesh):
    """p_H(C)/√X(C) = σ_H0 of ISO 6336-2:2019, eq. (2) with Z_ε = Z_β = 1 (spur): the same Hertz line contact."""
    b, ft, ze = 30.0, 12000.0, 189.8
    path = contact_path(mesh, b)
    state = path.state([0.0], 1500.0, ft, ze)
    u = mesh.gear2.teeth / mesh.gear1.teeth
    zh = flank.zone_factor(mesh.rack.alpha_t, mesh.alpha_wt, 0.0)
    ratio = (u - 1) / u if mesh.internal else (u + 1) / u
    sigma_h0 = zh * ze * math.sqrt(ft / (mesh.gear1.reference_diameter * b) * ratio)
    assert float(state.p_H[0] / np.sqrt(state.X[0])) == pytest.approx(sigma_h0, rel=1e-12)


@pytest.mark.parametrize("mesh", [EXTERNAL, INTERNAL])
def test_velocities_of_rolling_involutes(mesh):
    path = contact_path(mesh, 30.0)
    n1 = 1200.0
    gamma = path.gammas(11)
    state = path.state(gamma, n1, 1000.0, 189.8)
    w1 = 2 * math.pi * n1 / 60
    w2 = w1 / path.u
    cy = np.abs(gamma) * path.rho_c1 / 1000.0                    # |CY|, m
    expected = (w1 - w2 if mesh.internal else w1 + w2) * cy
    assert state.v_slide == pytest.approx(expected, abs=1e-12)
    assert state.v_r1 == pytest.approx(w1 * path.rb1 * np.tan(np.arccos(2 * path.rb1 / state.d_y1)) / 1000)
    c = int(np.argmin(np.abs(gamma)))
    assert state.zeta1[c] == pytest.approx(0.0, abs=1e-12) and state.zeta2[c] == pytest.approx(0.0, abs=1e-12)
    assert np.all(state.zeta1[gamma < 0] < 0) and np.all(state.zeta1[gamma > 0] > 0)
    assert state.v_sum == pytest.approx(state.v_r1 + state.v_r2)


@pytest.mark.parametrize("relief", ["none", "pinion", "wheel", "both"])
def test_load_sharing_balances_in_double_contact(relief):
    path = contact_path(EXTERNAL, 30.0, tip_relief=relief)
    p = path.points
    entering = np.linspace(p["A"], p["B"], 9)[1:-1]                  # open: X jumps at B and D
    partner = path.gamma_of(path.g_of(entering) + path.base_pitch)   # the pair one base pitch ahead
    total = path.load_sharing(entering) + path.load_sharing(partner)
    assert total == pytest.approx(np.ones_like(total), abs=1e-12)
    assert path.load_sharing(np.linspace(p["B"], p["D"], 5)) == pytest.approx(np.ones(5))
    x_a, x_e = path.load_sharing([p["A"], p["E"]])
    assert x_a == pytest.approx(0.0 if relief in ("wheel", "both") else 1 / 3)
    assert x_e == pytest.approx(0.0 if relief in ("pinion", "both") else 1 / 3)


def test_load_sharing_accuracy_grade_and_helical():
    coarse = contact_path(EXTERNAL, 30.0, accuracy_grade=10)
    assert float(coarse.load_sharing(coarse.points["A"])) == pytest.approx(8 / 15)        # (Q − 2)/15
    wide = contact_path(HELICAL, 60.0)
    assert wide.eps_beta > 1
    assert float(wide.load_sharing(0.0)) == pytest.approx(1 / wide.eps_alpha)
    assert float(wide.load_sharing(wide.points["A"])) == pytest.approx(1.3 / wide.eps_alpha)  # X_but = 1.3
    flat = contact_path(HELICAL, 60.0, buttressing=False)
    assert float(flat.load_sharing(flat.points["A"])) == pytest.approx(1 / flat.eps_alpha)
    narrow = contact_path(HELICAL, 20.0)
    eb = narrow.eps_beta
    assert 0 < eb < 1
    assert float(narrow.load_sharing(0.0)) == pytest.approx((1 - eb) + eb / narrow.eps_alpha)


def test_vectorised_over_load_cases():
    path = contact_path(EXTERNAL, 30.0)
    gamma = path.gammas(20)
    many = path.state(gamma, [1000.0, 2000.0, 3000.0], [1e4, 2e4, 3e4], 189.8, load_factor=[1.0, 1.1, 1.2])
    assert many.p_H.shape == (3, gamma.size) and many.v_sum.shape == (3, gamma.size)
    one = path.state(gamma, 2000.0, 2e4, 189.8, load_factor=1.1)
    assert many.p_H[1] == pytest.approx(one.p_H) and many.v_slide[1] == pytest.approx(one.v_slide)


def test_bad_input_named():
    short = MeshGeometry(GearGeometry(20, RACK, 0.0, tip_shortening=0.6), GearGeometry(40, RACK, 0.0, tip_shortening=0.6))
    with pytest.raises(RatingError, match="ε_α = .* < 1"):
        contact_path(short, 20.0)
    with pytest.raises(RatingError, match="tip_relief"):
        contact_path(EXTERNAL, 20.0, tip_relief="long")
    with pytest.raises(RatingError, match="face width"):
        contact_path(EXTERNAL, -1.0)
    with pytest.raises(RatingError, match="number of points"):
        contact_path(EXTERNAL, 20.0).gammas(1)
    with pytest.raises(RatingError, match="tangential force"):
        contact_path(EXTERNAL, 20.0).state([0.0], 100.0, float("nan"), 189.8)


def test_high_contact_ratio_spur_warns():
    rack = BasicRack(2.0, addendum=1.4, dedendum=1.65)
    mesh = MeshGeometry(GearGeometry(60, rack), GearGeometry(90, rack))
    assert mesh.contact_ratio > 2
    with pytest.warns(RatingWarning, match="ISO/TS 6336-22:2018, 6.3"):
        path = contact_path(mesh, 20.0)
    assert float(path.load_sharing(0.0)) == pytest.approx(0.5)


@settings(max_examples=40, deadline=None)
@given(torque=st.floats(1.0, 5000.0), factor=st.floats(1.01, 3.0), z1=st.integers(17, 40),
       ratio=st.floats(1.0, 4.0), internal=st.booleans())
def test_pressure_positive_finite_and_monotone_in_load(torque, factor, z1, ratio, internal):
    z2 = max(z1 + 30, round(3 * z1 * ratio)) if internal else round(z1 * ratio)
    mesh = MeshGeometry(GearGeometry(z1, RACK, 0.3), GearGeometry(z2, RACK, -0.3 if internal else 0.0, internal=internal))
    path = contact_path(mesh, 25.0)
    ft = 2000.0 * torque / mesh.gear1.reference_diameter
    low = path.state(path.gammas(15), 1000.0, ft, 189.8).p_H
    high = path.state(path.gammas(15), 1000.0, ft * factor, 189.8).p_H
    assert np.all(np.isfinite(low)) and np.all(low > 0)
    assert np.all(high > low)


def test_the_tip_of_gear_1_below_the_base_circle_of_gear_2_is_interference():
    """ρ_E ≥ a_w sin α_wt puts the contact below gear 2's base circle (its flank radius ρ_2 < 0): an error."""
    rack = BasicRack(3.0)
    with pytest.raises(RatingError, match="below the base circle of gear 2"):
        contact_path(MeshGeometry(GearGeometry(10, rack, 0.8), GearGeometry(12, rack, -0.6)), 20.0)


def test_a_vanishing_helix_angle_gives_the_spur_load_sharing():
    """β → 0 (hypothesis found 2e-309°): X_but = 1, X_Γ finite and equal to the spur pair's."""
    spur = contact_path(MeshGeometry(GearGeometry(14, BasicRack(3.0)), GearGeometry(17, BasicRack(3.0))), 30.0)
    rack = BasicRack(3.0, helix_angle=2.2e-309)
    tiny = contact_path(MeshGeometry(GearGeometry(14, rack), GearGeometry(17, rack)), 30.0)
    gam = spur.gammas(11)
    np.testing.assert_allclose(tiny.load_sharing(gam), spur.load_sharing(gam), rtol=1e-12)
