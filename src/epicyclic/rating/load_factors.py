"""Load factors of ISO 6336-1: K_v (method B), K_Hβ/K_Fβ (given or method C), K_Hα/K_Fα; mesh stiffness.

All functions take the tangential force and speed as numbers or numpy arrays (one
value per load case) and return the same shape: a duty cycle is rated in one call.

* Mesh stiffness (ISO 6336-1, 9.3): c' = c'_th C_M C_R C_B cos β with
  1/c'_th = q' = C1 + C2/z_n1 + C3/z_n2 + C4 x1 + C5 x1/z_n1 + C6 x2 + C7 x2/z_n2 + C8 x1² + C9 x2²
  (z_n2 → ∞ for internal gears), reduced by (K_A F_t/b)/100 below 100 N/mm;
  c_γα = c' (0.75 ε_α + 0.25), c_γβ = 0.85 c_γα.
* K_v, method B (ISO 6336-1, 6.3): resonance speed n_E1 = 30000/(π z1) √(c_γα/m_red),
  N = n1/n_E1; subcritical N ≤ N_S: K_v = N K + 1, K = C_v1 B_p + C_v2 B_f + C_v3 B_k; main
  resonance N_S < N ≤ 1.15: K_v = C_v1 B_p + C_v2 B_f + C_v4 B_k + 1; supercritical N ≥ 1.5:
  K_v = C_v5 B_p + C_v6 B_f + C_v7; between 1.15 and 1.5 linear.  m_red per unit face
  width: external pair m1* m2*/(m1* + m2*), m* = π/8 ρ d_m⁴/d_b²; planet–ring (internal) m_P*;
  sun–planet of a set with p planets m_P* m_S*/(p m_P* + m_S*).
* K_Hβ, method C (ISO 6336-1, 7.6): F_βy = F_βx − y_β; K_Hβ = 1 + F_βy c_γβ/(2 F_m/b) where
  that is ≤ 1 (else √(2 F_βy c_γβ/(F_m/b))), F_m = F_t K_A K_v; K_Fβ = K_Hβ^N_F,
  N_F = (b/h)²/(1 + b/h + (b/h)²).
* K_Hα, K_Fα, method B (ISO 6336-1, 8.3): F_tH = F_t K_A K_v K_Hβ; for ε_γ ≤ 2
  K_Hα = ε_γ/2 (0.9 + 0.4 c_γα (f_pb − y_α)/(F_tH/b)), otherwise
  0.9 + 0.4 √(2(ε_γ − 1)/ε_γ) c_γα (f_pb − y_α)/(F_tH/b); limited to 1 … ε_γ/(ε_α Z_ε²)
  (K_Fα up to ε_γ/(0.25 ε_α + 0.75), the ε_γ/(ε_α Y_ε) of eq. (76)).
* Pitch, profile and helix deviations from the accuracy grade by ISO 1328-1:1995 or :2013
  (:mod:`epicyclic.geometry.accuracy`, the tolerances as the edition rounds them); f_pb = f_pt cos α_t.

References
----------
ISO 6336-1:2006 and :2019, clauses 6.3 (K_v method B, eqs. (13)–(29)), 7.6 (method C),
8.3 (K_Hα, K_Fα method B), 9.3 (c', c_γ); ISO 1328-1:1995, clause 6; ISO 1328-1:2013, 5.2.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import EpicyclicError
from ..geometry.accuracy import flank_tolerances
from .errors import RatingError

__all__ = [
    "basic_rack_factor",
    "deviations",
    "dynamic_factor",
    "face_load_factors",
    "mesh_stiffness",
    "reduced_mass",
    "single_stiffness",
    "transverse_load_factors",
]

_Q = (0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182)


def deviations(grade: int, diameter: float, module: float, face_width: float,
               edition: str = "2013") -> dict[str, float]:
    """Single pitch, profile form and helix slope tolerances of accuracy grade ``grade``, µm.

    The tolerances of :func:`epicyclic.geometry.accuracy.flank_tolerances` (rounded by the
    edition's rule, as the standard tabulates them): the one path from an accuracy grade to the
    deviations the load factors take.

    Parameters
    ----------
    grade : int
        ISO 1328-1 accuracy grade (1995: 0 … 12) or flank tolerance class (2013: 1 … 11).
    diameter : float
        Reference diameter d, mm.
    module : float
        m_n, mm.
    face_width : float
        b, mm.
    edition : {"1995", "2013"}, default "2013"
        ISO 1328-1 edition.

    Returns
    -------
    dict
        ``f_pt``, ``f_falpha``, ``f_Hbeta`` (µm).

    Raises
    ------
    RatingError
        A grade outside the edition's range, an unknown edition, a size outside its ranges.

    References
    ----------
    ISO 1328-1:2013, 5.2, eqs. (5), (8), (10); ISO 1328-1:1995, clause 6 and Annex B.

    Examples
    --------
    >>> deviations(5, 100.0, 2.0, 20.0)
    {'f_pt': 6.0, 'f_falpha': 6.0, 'f_Hbeta': 6.0}
    >>> deviations(5, 100.0, 2.0, 20.0, "1995")
    {'f_pt': 5.5, 'f_falpha': 4.5, 'f_Hbeta': 5.5}
    """
    try:
        t = flank_tolerances(grade, diameter, module, face_width, edition)
    except EpicyclicError as exc:
        raise RatingError(f"rating.accuracy_grade: {exc}") from None
    return {"f_pt": t.f_pt, "f_falpha": t.f_falpha, "f_Hbeta": t.f_Hbeta}


def basic_rack_factor(dedendum: float, pressure_angle_deg: float) -> float:
    """C_B = [1 + 0.5 (1.2 − h_fP/m_n)] [1 − 0.02 (20° − α_n)] (ISO 6336-1, eq. (79)).

    Parameters
    ----------
    dedendum : float
        h_fP/m_n of the basic rack.
    pressure_angle_deg : float
        α_n, degrees.

    Returns
    -------
    float

    References
    ----------
    ISO 6336-1:2006, 9.3.1, eq. (79).

    Examples
    --------
    >>> round(basic_rack_factor(1.25, 20.0), 3)
    0.975
    """
    return (1 + 0.5 * (1.2 - dedendum)) * (1 - 0.02 * (20.0 - pressure_angle_deg))


def single_stiffness(z_n1: float, z_n2: float, x1: float, x2: float, beta: float, *, dedendum: float = 1.25,
                     pressure_angle_deg: float = 20.0, internal: bool = False, gear_blank: float = 0.8) -> float:
    """Single stiffness c' at K_A F_t/b ≥ 100 N/mm, N/(mm µm).

    Parameters
    ----------
    z_n1, z_n2 : float
        Virtual tooth numbers (z_n2 ignored for an internal gear: → ∞).
    x1, x2 : float
        Profile shifts.
    beta : float
        Helix angle, rad.
    dedendum : float
        h_fP* for C_B.
    pressure_angle_deg : float
        α_n for C_B.
    internal : bool
        Gear 2 is internal.
    gear_blank : float, default 0.8
        C_M (0.8 for solid discs).

    Returns
    -------
    float

    References
    ----------
    ISO 6336-1:2006, 9.3.1, eqs. (70)–(79), Table 8 (C1 … C9); C_R = 1 (solid blanks).

    Examples
    --------
    >>> round(single_stiffness(19, 104, 0.5, 0.15, 0.0), 3)
    14.892
    """
    c1, c2, c3, c4, c5, c6, c7, c8, c9 = _Q
    inv2 = 0.0 if internal else 1.0 / z_n2
    q = c1 + c2 / z_n1 + c3 * inv2 + c4 * x1 + c5 * x1 / z_n1 + c6 * x2 + c7 * x2 * inv2 + c8 * x1 ** 2 + c9 * x2 ** 2
    return (1.0 / q) * gear_blank * basic_rack_factor(dedendum, pressure_angle_deg) * math.cos(beta)


def mesh_stiffness(c_prime: float, contact_ratio: float, line_load):
    """(c', c_γα, c_γβ) for the line load K_A F_t/b (N/mm), reduced below 100 N/mm.

    Parameters
    ----------
    c_prime : float
        :func:`single_stiffness`, N/(mm µm).
    contact_ratio : float
        ε_α.
    line_load : float or ndarray
        K_A F_t / b, N/mm.

    Returns
    -------
    tuple of float or ndarray

    References
    ----------
    ISO 6336-1:2006, 9.3.1 (eq. 70, low loads) and 9.3.2 (c_γα = c'(0.75 ε_α + 0.25), c_γβ = 0.85 c_γα).
    """
    scale = np.clip(np.asarray(line_load, dtype=float) / 100.0, 1e-9, 1.0)  # no zero stiffness at zero load
    c = c_prime * scale
    c_ga = c * (0.75 * contact_ratio + 0.25)
    return c, c_ga, 0.85 * c_ga


def reduced_mass(d_m1: float, d_b1: float, d_m2: float, d_b2: float, density1: float, density2: float, *,
                 internal: bool = False, planets: int = 0, gear1_is_planet: bool = True) -> float:
    """m_red per unit face width, kg/mm (ISO 6336-1, 6.5.9 for planetary meshes).

    Parameters
    ----------
    d_m1, d_b1, d_m2, d_b2 : float
        Mean diameters (d_a + d_f)/2 and base diameters, mm.
    density1, density2 : float
        kg/mm³.
    internal : bool
        Gear 2 is an internal ring: m_red = m1* (the ring's mass taken as infinite).
    planets : int
        Number of planets p where gear 2 is a sun meshing p planets (0 otherwise).
    gear1_is_planet : bool
        Gear 1 is the planet of a planetary mesh (with ``planets``).

    Returns
    -------
    float

    References
    ----------
    ISO 6336-1:2006, 6.5.9, eqs. (30)–(34): m* = π/8 ρ d_m⁴/d_b².
    """
    m1 = math.pi / 8 * density1 * d_m1 ** 4 / d_b1 ** 2
    if internal:
        return m1
    m2 = math.pi / 8 * density2 * d_m2 ** 4 / d_b2 ** 2
    if planets > 1:  # sun-planet: the sun vibrates against p planets
        planet, sun = (m1, m2) if gear1_is_planet else (m2, m1)
        return planet * sun / (planets * planet + sun)
    return m1 * m2 / (m1 + m2)


def _cv(eps_gamma: float) -> tuple[float, ...]:
    if eps_gamma <= 2.0:
        c2, c3, c4, c6 = 0.34, 0.23, 0.90, 0.47
    else:
        c2 = 0.57 / (eps_gamma - 0.3)
        c3 = 0.096 / (eps_gamma - 1.56)
        c4 = (0.57 - 0.05 * eps_gamma) / (eps_gamma - 1.44)
        c6 = 0.12 / (eps_gamma - 1.74)
    if eps_gamma <= 1.0:
        c7 = 0.75
    elif eps_gamma <= 1.5:
        c7 = 0.125 * math.sin(math.pi * (eps_gamma - 1.0)) + 0.875
    else:
        c7 = 1.0
    return 0.32, c2, c3, c4, 0.47, c6, c7


def running_in_tip_relief(sigma_hlim1: float, sigma_hlim2: float) -> float:
    """C_ay, the tip relief that running-in produces, of a pair: the mean of both gears', µm.

    Parameters
    ----------
    sigma_hlim1, sigma_hlim2 : float
        σ_Hlim of the two gears, N/mm².

    Returns
    -------
    float
        ½ Σ [(σ_Hlim/97 − 18.45)²/18 + 1.5], µm: the C_a of B_k for gears without a designed
        tip relief.

    References
    ----------
    ISO 6336-1:2006, 6.3 (B_k, C_ay).

    Examples
    --------
    Case-carburised (1500 N/mm²) and through-hardened (700 N/mm²) gears: 2.0 and 8.5 µm:

    >>> round(running_in_tip_relief(1500, 1500), 3), round(running_in_tip_relief(700, 700), 2)
    (1.995, 8.51)
    """
    return 0.5 * sum((s / 97.0 - 18.45) ** 2 / 18.0 + 1.5 for s in (sigma_hlim1, sigma_hlim2))


def dynamic_factor(speed, teeth1: int, c_gamma_alpha, c_prime, reduced_mass_: float, line_load, f_pb_eff: float,
                   f_f_eff: float, eps_gamma: float, tip_relief: float = 0.0):
    """K_v by method B and the resonance ratio N (scalars or arrays over load cases).

    Parameters
    ----------
    speed : float or ndarray
        Pinion speed n1 (relative to the carrier in a planetary set), 1/min (sign ignored).
    teeth1 : int
        z1.
    c_gamma_alpha, c_prime : float or ndarray
        Mesh stiffness and single stiffness, N/(mm µm).
    reduced_mass_ : float
        m_red, kg/mm.
    line_load : float or ndarray
        K_A F_t / b, N/mm.
    f_pb_eff, f_f_eff : float or ndarray
        Effective base pitch and profile form deviations after running-in, µm.
    eps_gamma : float
        Total contact ratio ε_γ.
    tip_relief : float, default 0
        C_a, µm.

    Returns
    -------
    tuple
        (K_v, N, n_E1).

    References
    ----------
    ISO 6336-1:2006, 6.3, eqs. (13)–(29) (N_S = 0.85, or 0.5 + 0.35 √(K_A F_t/(100 b)) below 100 N/mm).

    Examples
    --------
    K_v → 1 as the speed → 0:

    >>> k, n, _ = dynamic_factor(1e-6, 20, 15.0, 14.0, 0.01, 300.0, 8.0, 6.0, 1.6)
    >>> round(float(k), 9)
    1.0
    """
    n1 = np.abs(np.asarray(speed, dtype=float))
    w = np.maximum(np.asarray(line_load, dtype=float), 1e-9)
    n_e1 = 30000.0 / (math.pi * teeth1) * np.sqrt(np.asarray(c_gamma_alpha, dtype=float) / reduced_mass_)
    ratio = n1 / n_e1
    b_p = np.asarray(c_prime, dtype=float) * f_pb_eff / w
    b_f = np.asarray(c_prime, dtype=float) * f_f_eff / w
    b_k = np.abs(1.0 - np.asarray(c_prime, dtype=float) * tip_relief / w)
    cv1, cv2, cv3, cv4, cv5, cv6, cv7 = _cv(eps_gamma)
    n_s = np.where(w < 100.0, 0.5 + 0.35 * np.sqrt(w / 100.0), 0.85)
    sub = ratio * (cv1 * b_p + cv2 * b_f + cv3 * b_k) + 1.0
    main = cv1 * b_p + cv2 * b_f + cv4 * b_k + 1.0
    sup = cv5 * b_p + cv6 * b_f + cv7
    inter = sup + (main - sup) / 0.35 * (1.5 - ratio)
    k_v = np.where(ratio <= n_s, sub, np.where(ratio <= 1.15, main, np.where(ratio < 1.5, inter, sup)))
    return k_v, ratio, n_e1


def face_load_factors(k_hbeta_given, force_per_width, c_gamma_beta, misalignment: float, running_in: float,
                      face_width: float, tooth_height: float):
    """(K_Hβ, K_Fβ): K_Hβ given, or by method C from the misalignment F_βx.

    Parameters
    ----------
    k_hbeta_given : float or None
        A given K_Hβ (≥ 1), or None for method C.
    force_per_width : float or ndarray
        F_m/b = F_t K_A K_v / b, N/mm.
    c_gamma_beta : float or ndarray
        N/(mm µm).
    misalignment : float or ndarray
        Initial equivalent misalignment F_βx, µm.
    running_in : float or ndarray
        y_β, µm (≤ F_βx).
    face_width, tooth_height : float
        b and h = (d_a − d_f)/2 of the gear with the smaller b/h, mm (b/h below 3 taken as 3).

    Returns
    -------
    tuple of float or ndarray

    References
    ----------
    ISO 6336-1:2006, 7.6 (method C, eqs. (41)–(44)) and 7.7 (K_Fβ, eq. (45)).
    """
    w = np.maximum(np.asarray(force_per_width, dtype=float), 1e-9)
    if k_hbeta_given is not None:
        k_h = np.broadcast_to(np.asarray(float(k_hbeta_given)), w.shape) * 1.0
    else:
        f_by = np.maximum(0.0, np.asarray(misalignment, dtype=float) - np.asarray(running_in, dtype=float))
        ratio = f_by * np.asarray(c_gamma_beta, dtype=float) / (2.0 * w)
        k_h = np.where(ratio <= 1.0, 1.0 + ratio, np.sqrt(2.0 * ratio))
    bh = max(face_width / tooth_height, 3.0)
    n_f = bh * bh / (1.0 + bh + bh * bh)
    return k_h, k_h ** n_f


def transverse_load_factors(force_per_width, c_gamma_alpha, f_pb_eff: float, eps_alpha: float, eps_gamma: float,
                            z_eps: float, edition: str):
    """(K_Hα, K_Fα) by method B, limited to 1 … ε_γ/(ε_α Z_ε²) (K_Fα: 1 … ε_γ/(ε_α Y_ε)).

    Parameters
    ----------
    force_per_width : float or ndarray
        F_tH/b = F_t K_A K_v K_Hβ / b, N/mm.
    c_gamma_alpha : float or ndarray
        N/(mm µm).
    f_pb_eff : float or ndarray
        f_pb − y_α, µm.
    eps_alpha, eps_gamma : float
        Transverse and total contact ratio.
    z_eps : float
        Z_ε.
    edition : str
        ``"2006"`` or ``"2019"`` (the same here: the limit of K_Fα is kept in both).

    Returns
    -------
    tuple of float or ndarray

    References
    ----------
    ISO 6336-1:2006, 8.3.2, eqs. (73)–(76) (Y_ε = 0.25 + 0.75/ε_α in the K_Fα limit);
    ISO 6336-1:2019, 8.3.
    """
    w = np.maximum(np.asarray(force_per_width, dtype=float), 1e-9)
    term = np.asarray(c_gamma_alpha, dtype=float) * f_pb_eff / w
    if eps_gamma <= 2.0:
        k = eps_gamma / 2.0 * (0.9 + 0.4 * term)
    else:
        k = 0.9 + 0.4 * math.sqrt(2.0 * (eps_gamma - 1.0) / eps_gamma) * term
    k_h = np.clip(k, 1.0, eps_gamma / (eps_alpha * z_eps ** 2))
    y_eps = 0.25 + 0.75 / eps_alpha
    k_f = np.clip(k, 1.0, eps_gamma / (eps_alpha * y_eps))
    del edition
    return k_h, k_f

