"""The shared scuffing factors against closed forms: continuity of the piecewise formulas, symmetry, Blok.

The coefficients themselves are checked against the printed values of a KISSsoft report in
``test_methods.py``; here the formulas' structure: every piecewise factor is continuous where its
ranges meet (ISO/TR 13989-2:2000 draws them as one curve), X_G is the same seen from either gear,
and X_G follows Blok's flash temperature |√v_1 − √v_2| / ρ_rel^¼ for internal gears too.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from epicyclic.geometry import BasicRack, GearGeometry, MeshGeometry
from epicyclic.rating import RatingError
from epicyclic.rating.contact_path import contact_path
from epicyclic.rating.errors import RatingWarning
from epicyclic.rating.scuffing import factors


@pytest.mark.parametrize(("e1", "e2", "moved"), [
    (1.0, 0.6, "e1"),     # ε_1 = 1 inside 1 ≤ ε_α < 2
    (0.6, 1.0, "e2"),     # ε_2 = 1
    (1.2, 0.8, "e1"),     # ε_α = 2, ε_1 ≥ ε_2
    (0.8, 1.2, "e2"),     # ε_α = 2, ε_1 < ε_2
    (0.7, 0.3, "e1"),     # ε_α = 1
    (0.45, 0.55, "e2"),   # ε_α = 1
])
def test_contact_ratio_factor_is_continuous_where_its_ranges_meet(e1, e2, moved):
    """X_ε on both sides of each border of its ranges agrees (ISO/TR 13989-2:2000 draws one curve)."""
    eps = 1e-9
    step = (eps, 0.0) if moved == "e1" else (0.0, eps)
    below = factors.contact_ratio_factor(e1 - step[0], e2 - step[1])
    above = factors.contact_ratio_factor(e1 + step[0], e2 + step[1])
    assert below == pytest.approx(above, abs=1e-7)
    far = factors.contact_ratio_factor(e1 + 1e3 * step[0], e2 + 1e3 * step[1])
    assert far != above  # the points straddle a border of a smooth, non-constant curve


def test_contact_ratio_factor_below_one_and_beyond_three():
    """ε_α < 1: (ε_1² + ε_2²)/(2 ε_α ε_1); ε_α ≥ 3 warns naming the clause."""
    assert factors.contact_ratio_factor(0.5, 0.3) == pytest.approx((0.25 + 0.09) / (2 * 0.8 * 0.5))
    with pytest.warns(RatingWarning, match="ISO/TS 6336-21"):
        factors.contact_ratio_factor(1.6, 1.5)
    with pytest.raises(RatingError, match="ε_1"):
        factors.contact_ratio_factor(0.0, 1.2)


def test_helical_and_approach_factors_are_continuous():
    """K_Bγ at ε_γ = 2 and 3.5, X_Q at ε_f/ε_a = 1.5 and 3."""
    assert factors.helical_load_factor(2.0 + 1e-12) == pytest.approx(1.0, abs=1e-5)
    assert factors.helical_load_factor(3.5 - 1e-12) == pytest.approx(1.3)
    assert factors.helical_load_factor(1.4) == 1.0 and factors.helical_load_factor(4.0) == 1.3
    assert factors.approach_factor(1.5 + 1e-12, 1.0) == pytest.approx(1.0)
    assert factors.approach_factor(3.0 - 1e-12, 1.0) == pytest.approx(0.6)


def test_tip_relief_factor_limits():
    """X_Ca with C_a = 0 and with C_a ≥ C_eff (taken as C_eff)."""
    assert factors.tip_relief_factor(0.0, 40.0, 0.8) == pytest.approx(1 + 0.06 * 0.8 + 0.02 * 0.64)
    full = 1 + 0.24 * 0.8 + 0.71 * 0.64
    assert factors.tip_relief_factor(40.0, 40.0, 0.8) == pytest.approx(full)
    assert factors.tip_relief_factor(90.0, 40.0, 0.8) == pytest.approx(full)


def test_geometry_factor_is_the_same_from_either_gear():
    """X_G(Γ; u) = X_G(−Γ/u; 1/u): the formula does not depend on which gear is called the pinion."""
    gam = np.linspace(-0.4, 0.5, 11)
    np.testing.assert_allclose(factors.geometry_factor(gam, 3.2), factors.geometry_factor(-gam / 3.2, 1 / 3.2),
                               rtol=1e-12)


def test_internal_geometry_factor_is_blok():
    """For a ring mesh X_G follows |√v_1 − √v_2| / ρ_rel^¼ of the path (Blok 1937) point by point."""
    rack = BasicRack(3.0)
    mesh = MeshGeometry(GearGeometry(39, rack, 0.1), GearGeometry(99, rack, -0.45, internal=True), "planet-ring")
    path = contact_path(mesh, 40.0)
    gam = np.linspace(path.points["A"], path.points["E"], 9)
    gam = gam[np.abs(gam) > 1e-6]
    v1, v2 = path.velocities(gam, 900.0)
    blok = np.abs(np.sqrt(v1) - np.sqrt(v2)) / path.relative_radius(gam) ** 0.25
    xg = factors.geometry_factor(gam, path.u, internal=True)
    np.testing.assert_allclose(xg / xg[0], blok / blok[0], rtol=1e-12)


def test_pitch_point_radius_is_the_relative_radius_at_c():
    """ρ_redC = u a sin α_wt / ((u ± 1)² cos β_b) equals the path's ρ_rel at Γ = 0 (external and internal)."""
    rack = BasicRack(3.0, helix_angle=12.0)
    for mesh in (MeshGeometry(GearGeometry(21, rack, 0.25), GearGeometry(39, rack, 0.1)),
                 MeshGeometry(GearGeometry(39, rack, 0.1), GearGeometry(99, rack, -0.45, internal=True))):
        path = contact_path(mesh, 40.0)
        rho = factors.pitch_point_radius(path.u, mesh.center_distance, path.alpha_wt, path.beta_b, mesh.internal)
        assert rho == pytest.approx(float(path.relative_radius(0.0)), rel=1e-9)


def test_thermo_elastic_factor_of_steel():
    """X_M = E_r^¼ √1000 / B_M: 50 K·N^-¾·s^½·m^-½·mm for steel (ISO/TR 13989-1: "X_M = 50 for steel")."""
    assert factors.thermo_elastic_factor(206000, 0.3, 206000, 0.3, 13.78) == pytest.approx(50.0, abs=0.1)


def test_mean_friction_falls_with_viscosity_and_rises_with_roughness():
    """μ_mC ∝ η^-0.05 and R_a^¼ (closed form)."""
    a = factors.mean_friction(1000.0, 10.0, 30.0, 20.0, 0.5, 1.0)
    assert factors.mean_friction(1000.0, 10.0, 30.0, 40.0, 0.5, 1.0) == pytest.approx(a * 2 ** -0.05)
    assert factors.mean_friction(1000.0, 10.0, 30.0, 20.0, 1.0, 1.0) == pytest.approx(a * 2 ** 0.25)
    assert float(factors.mean_friction(1000.0, 0.0, 30.0, 20.0, 0.5, 1.0)) == 0.0


@pytest.mark.parametrize("stage", [0, 15, 2.5, True])
def test_fzg_stage_outside_the_test(stage):
    """Stages 1 … 12 of ISO 14635-1 (13, 14 extrapolate): anything else is an error naming the key and 12."""
    with pytest.raises(RatingError, match="load_stage.*12"):
        factors.fzg_torque(stage)


def test_fzg_torque_formula_and_the_test_table():
    """T_1T = 3.726 S² lies within 0.9 % of the torques of ISO 14635-1, Table 2, from stage 6 on (exact at 10)."""
    assert factors.fzg_torque(12) == pytest.approx(3.726 * 144)
    for stage in range(6, 13):
        assert factors.fzg_torque(stage) == pytest.approx(factors.FZG_TORQUES[stage - 1], rel=0.009)
    assert factors.fzg_torque(10) == pytest.approx(372.6)


def test_angle_factor_of_a_spur_pair():
    """X_αβ = 1.22 sin^¼ α / cos^¾ α at α_wt = α_n = 20°, β = 0 (standard spur pair)."""
    a = math.radians(20.0)
    assert factors.angle_factor(a, a, a, 0.0) == pytest.approx(1.22 * math.sin(a) ** 0.25 / math.cos(a) ** 0.75)
