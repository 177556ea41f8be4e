"""Factors of the scuffing rating shared by the flash and the integral temperature method.

Every function takes numbers or numpy arrays (one value per load case) and returns the
same.  Internal gears follow the standards' sign convention through the absolute values
written out here: u = |z2|/z1 and a = |a_w| with the ring's concave flank (ρ_2 = ρ_C1 (u + Γ)).

=================  =================================================================================
factor             formula
=================  =================================================================================
X_M                thermo-elastic factor E_r^¼ √1000 / B_M  (E_r = 2/((1−ν1²)/E1 + (1−ν2²)/E2), B_M in
                   N/(mm s^½ K); 50.06 K N^-¾ s^½ m^-½ mm for steel with B_M = 13.78)
X_αβ               angle factor 1.22 sin^¼ α_wt cos^¼ α_n cos^¼ β / (cos^½ α_t cos^½ α_wt)
X_G(Γ), X_BE       geometry factor 0.51 √(u ± 1) |√(1 + Γ) − √(1 ∓ Γ/u)| / ((1 + Γ)(u ∓ Γ))^¼
                   (upper sign external); X_BE = X_G(Γ_E) / X_αβ at the tip of the pinion
K_Bγ               helical load factor: 1 (ε_γ ≤ 2), 1 + 0.2 √((ε_γ − 2)(5 − ε_γ)) (2 < ε_γ < 3.5), 1.3
X_ε                contact ratio factor from the addendum contact ratios ε_1, ε_2 (six cases, ε_α < 3)
X_Ca               tip relief factor 1 + (0.06 + 0.18 C_a/C_eff) ε_max + (0.02 + 0.69 C_a/C_eff) ε_max²,
                   C_eff = K_A F_t / (b c_γα), C_a ≤ C_eff
X_Q                approach factor: 1 (ε_f/ε_a ≤ 1.5), 1.4 − 4/15 ε_f/ε_a (< 3), 0.6
μ_mC               mean coefficient of friction 0.045 (w_Bt K_Bγ / (v_ΣC ρ_redC))^0.2 η_oil^-0.05 X_R X_L,
                   X_R = 2.2 (R_a / ρ_redC)^¼, v_ΣC = 2 v_w sin α_wt (v_w at d_w1), ρ_redC = u a sin α_wt/((u ± 1)² cos β_b)
T_1T               3.726 S_FZG², the pinion torque of the FZG A/8.3/90 load stage (ISO 14635-1)
=================  =================================================================================

The coefficients were checked against a published KISSsoft report of a helical gear pair
(ISO/TR 13989:2000; see ``tests/rating/scuffing``): K_Bγ, X_αβ, X_BE, X_ε, X_Ca, C_eff, X_M and
μ_mC agree with its printed digits.

References
----------
ISO/TS 6336-21:2017 (integral temperature method), ISO/TR 13989-2:2000 (its predecessor, and
DIN 3990-4:1987 before it): K_Bγ, X_ε, X_BE, X_αβ, X_Ca, X_Q, μ_mC, X_R, X_L; ISO/TS
6336-20:2017 and ISO/TR 13989-1:2000 (flash temperature method): X_M, X_G, B_M; ISO
14635-1:2000 (FZG A/8.3/90 test, load stages).  The standards' texts were not reachable to this
package: the formulas follow their published structure and are tested against the report's
printed values and against closed forms.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import RatingError, warn_validity
from ..micropitting import helical_load_factor  # K_Bγ, shared with micropitting (ISO/TR 15144-1)

__all__ = [
    "FZG_TORQUES",
    "MAX_LOAD_STAGE",
    "LUBRICANT_FACTORS",
    "angle_factor",
    "approach_factor",
    "contact_ratio_factor",
    "effective_tip_relief",
    "fzg_torque",
    "geometry_factor",
    "helical_load_factor",
    "mean_friction",
    "pitch_point_radius",
    "thermo_elastic_factor",
    "tip_relief_factor",
]

#: Pinion torque T_1T (N·m) of the FZG A/8.3/90 load stages 1 … 12 as the test rig applies it
#: (ISO 14635-1:2000, Table 2); the methods take T_1T = 3.726 S_FZG² (:func:`fzg_torque`).
FZG_TORQUES = (3.3, 13.7, 35.3, 60.8, 94.1, 135.3, 183.4, 239.3, 302.0, 372.6, 450.1, 534.5)
#: The highest load stage accepted (12 is the test's last; 13, 14 extrapolate, as reports print them).
MAX_LOAD_STAGE = 14

#: Lubricant factor X_L by oil type (ISO/TR 13989-2:2000, Table 1; ISO/TS 6336-21:2017).
LUBRICANT_FACTORS = {
    "mineral": 1.0,
    "polyalphaolefin": 0.8,
    "polyglycol": 0.7,              # non-water-soluble polyglycol
    "water-soluble polyglycol": 0.6,
    "traction": 1.5,
    "phosphate ester": 1.3,
}

_ROOT_1000 = math.sqrt(1000.0)  # v in m/s, lengths in mm: √(m/s) = √1000 √(mm/s)


def thermo_elastic_factor(e1: float, nu1: float, e2: float, nu2: float, contact_coefficient: float) -> float:
    """X_M = E_r^¼ / B_M, K·N^-¾·s^½·m^-½·mm (for steel with B_M = 13.78: 50.06).

    Parameters
    ----------
    e1, e2 : float
        Young's moduli, N/mm².
    nu1, nu2 : float
        Poisson's ratios.
    contact_coefficient : float
        Thermal contact coefficient B_M = √(λ_M ρ_M c_M), N/(mm s^½ K), the same for both gears.

    Returns
    -------
    float

    References
    ----------
    ISO/TR 13989-1:2000, clause 5 (X_M, B_M); ISO/TS 6336-20:2017.
    """
    e_r = 2.0 / ((1.0 - nu1 ** 2) / e1 + (1.0 - nu2 ** 2) / e2)
    return e_r ** 0.25 * _ROOT_1000 / contact_coefficient


def angle_factor(alpha_n: float, alpha_t: float, alpha_wt: float, beta: float) -> float:
    """X_αβ = 1.22 sin^¼ α_wt cos^¼ α_n cos^¼ β / (cos^½ α_t cos^½ α_wt) (angles in rad).

    References
    ----------
    ISO/TR 13989-2:2000 and ISO/TR 13989-1:2000 (angle factor); ISO/TS 6336-21:2017.
    """
    return (1.22 * math.sin(alpha_wt) ** 0.25 * math.cos(alpha_n) ** 0.25 * math.cos(beta) ** 0.25
            / (math.cos(alpha_t) ** 0.5 * math.cos(alpha_wt) ** 0.5))


def geometry_factor(gamma, u: float, internal: bool = False):
    """X_G(Γ) / X_αβ: 0.51 √(u ± 1) |√(1 + Γ) − √(1 ∓ Γ/u)| / ((1 + Γ)(u ∓ Γ))^¼.

    At the pinion's tip (Γ = Γ_E) it is the geometry factor X_BE of the integral method.

    Parameters
    ----------
    gamma : float or array_like
        Γ of the point (0 at the pitch point).
    u : float
        |z2| / z1.
    internal : bool, default False
        Gear 2 is a ring (its flank concave).

    Returns
    -------
    float or ndarray

    References
    ----------
    ISO/TR 13989-1:2000 (X_G); ISO/TR 13989-2:2000 and ISO/TS 6336-21:2017 (X_BE).
    """
    g = np.asarray(gamma, dtype=float)
    s = -1.0 if internal else 1.0
    value = (0.51 * math.sqrt(u + s) * np.abs(np.sqrt(1.0 + g) - np.sqrt(1.0 - s * g / u))
             / ((1.0 + g) * (u - s * g)) ** 0.25)
    return float(value) if value.ndim == 0 else value


def pitch_point_radius(u: float, center_distance: float, alpha_wt: float, beta_b: float,
                       internal: bool = False) -> float:
    """ρ_redC, the relative radius of curvature at the pitch point in the normal section, mm.

    References
    ----------
    ISO/TR 13989-2:2000 and ISO/TS 6336-21:2017 (ρ_redC = u a sin α_wt / ((1 + u)² cos β_b)).
    """
    s = -1.0 if internal else 1.0
    return u * center_distance * math.sin(alpha_wt) / ((u + s) ** 2 * math.cos(beta_b))


def contact_ratio_factor(eps_1: float, eps_2: float, clause: str = "ISO/TS 6336-21:2017") -> float:
    """X_ε from the addendum contact ratios ε_1 (pinion tip) and ε_2 (wheel tip).

    Parameters
    ----------
    eps_1, eps_2 : float
        ε_1 = (ρ_E1 − ρ_C1)/p_bt, ε_2 = (ρ_C1 − ρ_A1)/p_bt.
    clause : str
        Named in the warning for ε_α ≥ 3.

    Returns
    -------
    float

    References
    ----------
    ISO/TR 13989-2:2000 (contact ratio factor, six ranges of ε_α, ε_1, ε_2); DIN 3990-4:1987.
    """
    e1, e2 = float(eps_1), float(eps_2)
    ea = e1 + e2
    if e1 <= 0.0:
        raise RatingError(f"scuffing: the pinion's addendum contact ratio ε_1 = {e1:.4f} must be > 0 "
                          "(its tip does not pass the pitch point); the integral method needs ε_1 > 0.")
    if ea < 1.0:
        poly = e1 ** 2 + e2 ** 2
    elif ea < 2.0:
        if e1 < 1.0 and e2 < 1.0:
            poly = 0.70 * (e1 ** 2 + e2 ** 2) - 0.22 * ea + 0.52 - 0.60 * e1 * e2
        elif e1 >= 1.0:
            poly = 0.18 * e1 ** 2 + 0.70 * e2 ** 2 + 0.82 * e1 - 0.52 * e2 - 0.30 * e1 * e2
        else:
            poly = 0.70 * e1 ** 2 + 0.18 * e2 ** 2 - 0.52 * e1 + 0.82 * e2 - 0.30 * e1 * e2
    else:
        if ea >= 3.0:
            warn_validity(f"ε_α = {ea:.3f} ≥ 3 lies beyond the contact ratio factor's ranges; the 2 ≤ ε_α < 3 "
                          "formula is used", clause)
        if e1 >= e2:
            poly = 0.44 * e1 ** 2 + 0.59 * e2 ** 2 + 0.30 * e1 - 0.30 * e2 - 0.15 * e1 * e2
        else:
            poly = 0.59 * e1 ** 2 + 0.44 * e2 ** 2 - 0.30 * e1 + 0.30 * e2 - 0.15 * e1 * e2
    return poly / (2.0 * ea * e1)


def effective_tip_relief(application_factor: float, tangential_force, face_width: float, mesh_stiffness):
    """C_eff = K_A F_t / (b c_γα), µm: the tip relief that just takes the load off the tip.

    References
    ----------
    ISO/TR 13989-2:2000 and ISO/TS 6336-21:2017 (C_eff); ISO/TR 13989-1:2000.
    """
    return application_factor * np.asarray(tangential_force, dtype=float) / (face_width * np.asarray(mesh_stiffness))


def tip_relief_factor(tip_relief: float, effective, eps_max: float):
    """X_Ca = 1 + (0.06 + 0.18 C_a/C_eff) ε_max + (0.02 + 0.69 C_a/C_eff) ε_max², C_a ≤ C_eff.

    Parameters
    ----------
    tip_relief : float
        C_a, µm (the running-in value C_ay without a designed relief).
    effective : float or array_like
        C_eff, µm.
    eps_max : float
        The larger addendum contact ratio, max(ε_1, ε_2).

    References
    ----------
    ISO/TR 13989-2:2000 and ISO/TS 6336-21:2017 (tip relief factor).
    """
    c_eff = np.asarray(effective, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(c_eff > 0, np.minimum(tip_relief / np.where(c_eff > 0, c_eff, 1.0), 1.0), 1.0)
    return 1.0 + (0.06 + 0.18 * ratio) * eps_max + (0.02 + 0.69 * ratio) * eps_max ** 2


def approach_factor(eps_driven_tip: float, eps_driving_tip: float) -> float:
    """X_Q from the ratio of the approach (driven gear's tip) to the recess (driving gear's tip) contact.

    References
    ----------
    ISO/TR 13989-2:2000 and ISO/TS 6336-21:2017 (meshing factor X_Q).
    """
    ratio = eps_driven_tip / eps_driving_tip
    if ratio <= 1.5:
        return 1.0
    if ratio < 3.0:
        return 1.40 - 4.0 / 15.0 * ratio
    return 0.60


def mean_friction(line_load, sum_velocity, radius: float, viscosity, roughness: float, lubricant_factor: float):
    """μ_mC = 0.045 (w_Bt K_Bγ / (v_ΣC ρ_redC))^0.2 η_oil^-0.05 X_R X_L, X_R = 2.2 (R_a/ρ_redC)^¼.

    Parameters
    ----------
    line_load : float or array_like
        w_Bt K_Bγ, N/mm.
    sum_velocity : float or array_like
        v_ΣC = 2 v_w sin α_wt, the sum of the flanks' velocities at the pitch point, m/s.
    radius : float
        ρ_redC, mm.
    viscosity : float or array_like
        η_oil at the oil temperature, mPa·s.
    roughness : float
        R_a, the mean of both flanks, µm.
    lubricant_factor : float
        X_L.

    References
    ----------
    ISO/TR 13989-2:2000 and ISO/TS 6336-21:2017 (mean coefficient of friction).
    """
    w = np.asarray(line_load, dtype=float)
    v = np.asarray(sum_velocity, dtype=float)
    x_r = 2.2 * (roughness / radius) ** 0.25
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(v > 0, w / (np.where(v > 0, v, 1.0) * radius), 0.0)
    return 0.045 * ratio ** 0.2 * np.asarray(viscosity, dtype=float) ** -0.05 * x_r * lubricant_factor


def fzg_torque(load_stage: int) -> float:
    """T_1T = 3.726 S_FZG², the pinion torque of the FZG A/8.3/90 test at load stage S_FZG, N·m.

    The test's load stages are 1 … 12 (ISO 14635-1; the formula lies within 0.9 % of its table from
    stage 6 on); 13 and 14, which reports print for oils that pass stage 12, extrapolate it (a
    warning where the stage is used).

    Raises
    ------
    RatingError
        A stage that is not a whole number 1 … 14.

    References
    ----------
    ISO/TR 13989-2:2000 and ISO/TS 6336-21:2017 (T_1T of the test); ISO 14635-1:2000, Table 2.
    """
    if isinstance(load_stage, bool) or not isinstance(load_stage, int) or not 1 <= load_stage <= MAX_LOAD_STAGE:
        raise RatingError(f"scuffing.load_stage must be a whole FZG A/8.3/90 load stage 1 ... 12 (ISO 14635-1; 13 "
                          f"and 14 extrapolate), got {load_stage!r}; an oil that passes stage 12 is rated with 12 "
                          "(on the safe side), or give integral_scuffing_temperature / scuffing_temperature from its "
                          "own test.")
    return 3.726 * load_stage ** 2
