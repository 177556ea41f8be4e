"""Factors of the contact stress and of the permissible contact stress (ISO 6336-2, Method B).

======  ==========================================================================  ===========
symbol  formula                                                                     clause
======  ==========================================================================  ===========
Z_H     √(2 cos β_b cos α_wt / (cos² α_t sin α_wt))                                 6.1, eq. (9)
Z_E     √(1 / (π ((1 − ν1²)/E1 + (1 − ν2²)/E2)))                                    7, eq. (10)
Z_ε     ε_β < 1: √((4 − ε_α)/3 (1 − ε_β) + ε_β/ε_α); ε_β ≥ 1: √(1/ε_α)              8, eq. (13)
Z_β     1 / √cos β                                                                  9, eq. (14)
Z_B     M1 = √(ρ_C1 ρ_C2 / (ρ_B1 ρ_B2)) at the inner point B of single contact;     6.2, eq. (5)
        spur max(1, M1), ε_β ≥ 1: 1, between: M1 − ε_β (M1 − 1)
Z_D     the same at D for gear 2; 1 for an internal gear                            6.2
Z_L     C_ZL + 4 (1 − C_ZL) / (1.2 + 134/ν_40)², C_ZL = 0.08 (σ_Hlim − 850)/350 + 0.83  11, eq. (24)
Z_v     C_Zv + 2 (1 − C_Zv) / √(0.8 + 32/v), C_Zv = C_ZL + 0.02                     11, eq. (26)
Z_R     (3 / R_z10)^C_ZR, R_z10 = R_z (10/ρ_red)^(1/3), C_ZR = 0.12 + (1000 − σ_Hlim)/5000  11, eq. (28)
Z_W     hard pinion on a through-hardened wheel: 1.2 − (HB − 130)/1700 (130 … 470 HB)  12, eq. (31)
Z_X     1 (size factor of pitting)                                                  13
======  ==========================================================================  ===========

(C_ZL, C_ZR between σ_Hlim 850 and 1200 N/mm², constant outside; ρ_B, ρ_C radii of
curvature along the line of action, for an internal gear ρ2 = ρ1 + a_w sin α_wt.)
The same in the 2006 and 2019 editions.

References
----------
ISO 6336-2:2006 and ISO 6336-2:2019, clauses 6–13.
"""

from __future__ import annotations

import math

import numpy as np

from .errors import warn_validity

__all__ = [
    "contact_ratio_factor",
    "elasticity_factor",
    "helix_factor",
    "lubricant_factor",
    "pitch_curvature",
    "roughness_factor",
    "single_pair_factors",
    "speed_factor",
    "work_hardening_factor",
    "zone_factor",
]


def zone_factor(alpha_t: float, alpha_wt: float, beta_b: float) -> float:
    """Z_H (ISO 6336-2, eq. (9)); angles in rad.

    Parameters
    ----------
    alpha_t, alpha_wt, beta_b : float
        Transverse pressure angle, operating transverse pressure angle, base helix angle, rad.

    Returns
    -------
    float

    References
    ----------
    ISO 6336-2:2006, 6.1, eq. (9).

    Examples
    --------
    Unshifted spur pair (α_wt = α_t = 20°): Z_H = √(2/(cos 20° sin 20°)) = 2.4946.

    >>> round(zone_factor(math.radians(20), math.radians(20), 0.0), 4)
    2.4946
    """
    return math.sqrt(2 * math.cos(beta_b) * math.cos(alpha_wt) / (math.cos(alpha_t) ** 2 * math.sin(alpha_wt)))


def elasticity_factor(E1: float, nu1: float, E2: float, nu2: float) -> float:
    """Z_E in √(N/mm²) (ISO 6336-2, eq. (10)).

    Parameters
    ----------
    E1, E2 : float
        Moduli of elasticity, N/mm².
    nu1, nu2 : float
        Poisson's ratios.

    Returns
    -------
    float

    References
    ----------
    ISO 6336-2:2006, clause 7, eq. (10) (steel on steel: 189.8).

    Examples
    --------
    >>> round(elasticity_factor(206000, 0.3, 206000, 0.3), 1)
    189.8
    """
    return math.sqrt(1.0 / (math.pi * ((1 - nu1 ** 2) / E1 + (1 - nu2 ** 2) / E2)))


def contact_ratio_factor(eps_alpha: float, eps_beta: float) -> float:
    """Z_ε (ISO 6336-2, eq. (13)).

    Parameters
    ----------
    eps_alpha, eps_beta : float
        Transverse contact ratio and overlap ratio.

    Returns
    -------
    float

    References
    ----------
    ISO 6336-2:2006, clause 8, eqs. (11)–(13).

    Examples
    --------
    >>> round(contact_ratio_factor(1.5363235945832296, 0.0), 6)  # √((4 − ε_α)/3)
    0.906215
    """
    if eps_beta >= 1.0:
        return math.sqrt(1.0 / eps_alpha)
    return math.sqrt((4.0 - eps_alpha) / 3.0 * (1.0 - eps_beta) + eps_beta / eps_alpha)


def helix_factor(beta: float) -> float:
    """Z_β = 1/√cos β (ISO 6336-2, eq. (14)), β in rad.

    Parameters
    ----------
    beta : float
        Reference helix angle, rad.

    Returns
    -------
    float

    References
    ----------
    ISO 6336-2:2006, clause 9, eq. (14).
    """
    return 1.0 / math.sqrt(math.cos(beta))


def pitch_curvature(base_radius1: float, base_radius2: float, alpha_wt: float, internal: bool) -> tuple[float, float]:
    """(ρ_C1, ρ_C2): radii of curvature at the pitch point, mm (ρ = r_b tan α_wt).

    Parameters
    ----------
    base_radius1, base_radius2 : float
        r_b1, r_b2, mm.
    alpha_wt : float
        Operating transverse pressure angle, rad.
    internal : bool
        Gear 2 internal (returned positive; the relative curvature takes the difference).

    Returns
    -------
    tuple of float

    References
    ----------
    ISO 6336-2:2006, 11.4 (ρ_red at the pitch point).
    """
    return base_radius1 * math.tan(alpha_wt), base_radius2 * math.tan(alpha_wt)


def single_pair_factors(tip_radius1: float, base_radius1: float, teeth1: int, tip_radius2: float, base_radius2: float,
                        teeth2: int, alpha_wt: float, center_distance: float, eps_alpha: float, eps_beta: float,
                        internal: bool) -> tuple[float, float]:
    """(Z_B, Z_D): contact stress at the inner points of single pair contact over that at the pitch point.

    Parameters
    ----------
    tip_radius1, base_radius1 : float
        r_a1, r_b1 of gear 1, mm.
    teeth1 : int
        z1.
    tip_radius2, base_radius2 : float
        r_a2, r_b2 of gear 2 (inner tip radius for an internal gear), mm.
    teeth2 : int
        z2.
    alpha_wt : float
        rad.
    center_distance : float
        a_w, mm.
    eps_alpha, eps_beta : float
        Transverse contact ratio, overlap ratio.
    internal : bool
        Gear 2 internal: Z_D = 1.

    Returns
    -------
    tuple of float

    References
    ----------
    ISO 6336-2:2006, 6.2, eqs. (5)–(8).

    Examples
    --------
    z = 19/104, x = 0.5/0.15, m = 4 (M1 = 1.00555 in the independent DIN 3990 implementation
    hanslhansl/din3990, tests/test_1.py):

    >>> r_b1, r_b2 = 71.41663917972905 / 2, 390.9121302469379 / 2
    >>> zb, zd = single_pair_factors(44.0, r_b1, 19, 212.6, r_b2, 104, math.radians(21.531902292465457),
    ...                              248.506843355171, 1.5363235945832296, 0.0, False)
    >>> round(zb, 5), zd
    (1.00555, 1.0)
    """
    pitch = 2 * math.pi * base_radius1 / teeth1  # p_bt
    rho_a1 = math.sqrt(max(0.0, tip_radius1 ** 2 - base_radius1 ** 2))
    rho_a2 = math.sqrt(max(0.0, tip_radius2 ** 2 - base_radius2 ** 2))
    line = center_distance * math.sin(alpha_wt)
    c1, c2 = pitch_curvature(base_radius1, base_radius2, alpha_wt, internal)

    def gear2(rho1: float) -> float:
        return rho1 + line if internal else line - rho1

    b1 = rho_a1 - pitch                     # inner point of single contact of gear 2 ... B: E − p_bt
    m1 = math.sqrt(c1 * c2 / (b1 * gear2(b1))) if b1 > 0 and gear2(b1) > 0 else 1.0
    if internal:
        m2 = 1.0                             # Z_D = 1 for an internal gear
    else:
        d2 = rho_a2 - pitch                  # D seen from gear 2
        m2 = math.sqrt(c1 * c2 / (d2 * (line - d2))) if d2 > 0 and line - d2 > 0 else 1.0

    def blend(m: float) -> float:
        if eps_beta >= 1.0:
            return 1.0
        return max(1.0, m - eps_beta * (m - 1.0))

    return blend(m1), 1.0 if internal else blend(m2)


def _c_zl(sigma_hlim: float) -> float:
    s = min(max(sigma_hlim, 850.0), 1200.0)
    return 0.08 * (s - 850.0) / 350.0 + 0.83


def lubricant_factor(viscosity_40: float, sigma_hlim: float) -> float:
    """Z_L from the kinematic viscosity at 40 °C, mm²/s (ISO 6336-2, eq. (24)).

    Parameters
    ----------
    viscosity_40 : float
        ν_40, mm²/s.
    sigma_hlim : float
        The lower σ_Hlim of the pair, N/mm².

    Returns
    -------
    float

    References
    ----------
    ISO 6336-2:2006, 11.2, eqs. (24)–(25).

    Examples
    --------
    >>> round(lubricant_factor(100.0, 1500.0), 4)  # 0.91 + 0.36/(1.2 + 1.34)²
    0.9658
    """
    if not 10.0 <= viscosity_40 <= 1500.0:
        warn_validity(f"viscosity_40 = {viscosity_40:g} mm^2/s lies outside the 10 ... 1500 mm^2/s of Figure 11; "
                      "Z_L is computed from the formula.", "ISO 6336-2:2006, 11.2")
    c = _c_zl(sigma_hlim)
    return c + 4.0 * (1.0 - c) / (1.2 + 134.0 / viscosity_40) ** 2


def speed_factor(velocity, sigma_hlim: float):
    """Z_v from the pitch line velocity v in m/s (ISO 6336-2, eq. (26)), scalar or array.

    Parameters
    ----------
    velocity : float or ndarray
        v, m/s (a value below 0.01 m/s is taken as 0.01).
    sigma_hlim : float
        N/mm².

    Returns
    -------
    float or ndarray

    References
    ----------
    ISO 6336-2:2006, 11.3, eqs. (26)–(27).

    Examples
    --------
    >>> round(float(speed_factor(10.0, 1500.0)), 4)  # 0.93 + 0.14/√4
    1.0
    """
    c = _c_zl(sigma_hlim) + 0.02
    v = np.maximum(np.abs(np.asarray(velocity, dtype=float)), 0.01)
    return c + 2.0 * (1.0 - c) / np.sqrt(0.8 + 32.0 / v)


def roughness_factor(rz1: float, rz2: float, rho_c1: float, rho_c2: float, internal: bool, sigma_hlim: float) -> float:
    """Z_R from the flank roughness R_z (µm) and the relative curvature at the pitch point.

    Parameters
    ----------
    rz1, rz2 : float
        Mean peak-to-valley roughness R_z of the flanks, µm.
    rho_c1, rho_c2 : float
        Radii of curvature at the pitch point, mm.
    internal : bool
        Gear 2 internal: ρ_red = ρ1 ρ2/(ρ2 − ρ1).
    sigma_hlim : float
        N/mm².

    Returns
    -------
    float

    References
    ----------
    ISO 6336-2:2006, 11.4, eqs. (28)–(30).

    Examples
    --------
    >>> round(roughness_factor(3.0, 3.0, 10.0, 100.0, False, 1500.0), 4)  # ρ_red 9.09 mm: R_z10 = 3.097
    0.9975
    """
    rz = (rz1 + rz2) / 2.0
    rho_red = rho_c1 * rho_c2 / (rho_c2 - rho_c1 if internal else rho_c1 + rho_c2)
    rz10 = rz * (10.0 / rho_red) ** (1.0 / 3.0)
    s = min(max(sigma_hlim, 850.0), 1200.0)
    c = 0.12 + (1000.0 - s) / 5000.0
    return (3.0 / rz10) ** c


def work_hardening_factor(hard, soft) -> float:
    """Z_W of the softer, through-hardened wheel run against a surface-hardened pinion (1 otherwise).

    Parameters
    ----------
    hard, soft : Material
        The two materials (either order).

    Returns
    -------
    float

    References
    ----------
    ISO 6336-2:2006, clause 12, eq. (31) (HB 130 … 470; outside, the end value and a warning); the
    hardness in HB, converted from HV or HRC by ASTM E140-12b, Table 1.
    """
    pair = sorted((hard, soft), key=lambda m: not m.surface_hardened)
    if not (pair[0].surface_hardened and not pair[1].surface_hardened):
        return 1.0
    hb = pair[1].hardness_in("HB")
    if not 130.0 <= hb <= 470.0:
        warn_validity(f"hardness {hb:g} HB of the through-hardened gear lies outside 130 ... 470 HB; "
                      "the end value is used for Z_W.", "ISO 6336-2:2006, clause 12")
        hb = min(max(hb, 130.0), 470.0)
    return 1.2 - (hb - 130.0) / 1700.0
