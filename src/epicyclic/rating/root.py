"""Factors of the tooth-root stress and of the permissible root stress (ISO 6336-3, Method B).

=========  =================================================================  ==================
symbol     formula                                                            clause
=========  =================================================================  ==================
Y_β        2006: 1 − ε_β β/120° (ε_β ≤ 1, β ≤ 30° taken at the limits)         7.3, eq. (42)
           2019: (1 − ε_β β/120°) / cos³β
Y_B        1 for a solid gear or a rim s_R/h_t ≥ 1.2; 1.6 ln(2.242 h_t/s_R)   7.4
           for 0.5 < s_R/h_t < 1.2; internal: 1.15 ln(8.324 m_n/s_R) below
           s_R/m_n = 3.5
Y_DT       1 (accuracy grade > 4 or ε_αn ≤ 2.05); grade ≤ 4: 2.366 −          7.5
           0.666 ε_αn up to 2.5, 0.9 beyond
Y_ST       2.0 (stress correction factor of the reference test gear)          11
Y_δrelT    (1 + √(ρ' χ*)) / (1 + √(ρ' χ*_T)), χ* = (1 + 2 q_s)/5,              13.2, eq. (54)
           χ*_T = 1.2; ρ' the slip-layer thickness of the material
Y_RrelT    R_z < 16 µm … by material: 1.674 − 0.529 (R_z + 1)^0.1 (V, GGG,     14.2, eqs. (59)–(61)
           Eh, IF), 5.306 − 4.203 (R_z + 1)^0.01 (St), 4.299 − 3.259
           (R_z + 1)^0.0058 (GG, NT, NV) for 1 ≤ R_z < 40
Y_X        by material and m_n: 1 up to 5 mm, then linear to 0.85/0.8/0.7     15, Table 6
Y_M        1; 0.7 for an idler gear under fully reversed bending (a planet     ISO 6336-3:2019 Annex B,
           between sun and ring)                                              ISO 6336-5:2016, 5.4
=========  =================================================================  ==================

References
----------
ISO 6336-3:2006 and ISO 6336-3:2019, clauses 7, 11–15 and Annex B; ISO 6336-5:2016, 5.4
(reversed bending: 0.7 σ_Flim).
"""

from __future__ import annotations

import math

from .errors import warn_validity

__all__ = [
    "REVERSED_BENDING",
    "Y_ST",
    "deep_tooth_factor",
    "helix_factor",
    "relative_notch_sensitivity",
    "relative_surface_factor",
    "rim_factor",
    "size_factor",
    "slip_layer",
]

#: Y_ST, the stress correction factor of the reference test gear.
Y_ST = 2.0
#: Y_M of an idler gear (planet) under fully reversed bending.
REVERSED_BENDING = 0.7


def helix_factor(beta: float, eps_beta: float, edition: str) -> float:
    """Y_β; ``beta`` in rad, ε_β > 1 taken as 1, β > 30° as 30°.

    Parameters
    ----------
    beta : float
        Reference helix angle, rad.
    eps_beta : float
        Overlap ratio.
    edition : str
        ``"2006"`` or ``"2019"`` (2019 divides by cos³β).

    Returns
    -------
    float

    References
    ----------
    ISO 6336-3:2006, 7.3, eq. (42); ISO 6336-3:2019, 7.3.

    Examples
    --------
    >>> round(helix_factor(math.radians(15), 1.2, "2006"), 4), round(helix_factor(math.radians(15), 1.2, "2019"), 4)
    (0.875, 0.9709)
    """
    b = min(math.degrees(beta), 30.0)
    y = 1.0 - min(eps_beta, 1.0) * b / 120.0
    if edition == "2019":
        y /= math.cos(math.radians(b)) ** 3
    return y


def rim_factor(rim_thickness: float | None, tooth_height: float, module: float, internal: bool = False) -> float:
    """Y_B from the rim thickness s_R below the root (None: a solid gear, 1).

    Parameters
    ----------
    rim_thickness : float or None
        s_R, mm.
    tooth_height : float
        h_t, mm (external gears).
    module : float
        m_n, mm (internal gears).
    internal : bool, default False

    Returns
    -------
    float
        External: 1 for s_R/h_t ≥ 1.2, else 1.6 ln(2.242 h_t/s_R) (down to s_R/h_t = 0.5);
        internal: 1 for s_R/m_n ≥ 3.5, else 1.15 ln(8.324 m_n/s_R) (down to s_R/m_n = 1.75).

    References
    ----------
    ISO 6336-3:2006, 7.4, eqs. (43)–(44); below the lower limits a warning and the value there.

    Examples
    --------
    >>> rim_factor(None, 4.5, 2.0), round(rim_factor(3.0, 4.5, 2.0), 4), round(rim_factor(5.0, 4.5, 2.0, True), 4)
    (1.0, 1.9405, 1.3833)
    """
    if rim_thickness is None:
        return 1.0
    if internal:
        ratio = rim_thickness / module
        if ratio >= 3.5:
            return 1.0
        if ratio < 1.75:
            warn_validity(f"rim s_R/m_n = {ratio:.3g} of an internal gear is below 1.75, outside the method; "
                          "Y_B at 1.75 is used.", "ISO 6336-3:2006, 7.4")
            ratio = 1.75
        return 1.15 * math.log(8.324 / ratio)
    ratio = rim_thickness / tooth_height
    if ratio >= 1.2:
        return 1.0
    if ratio < 0.5:
        warn_validity(f"rim s_R/h_t = {ratio:.3g} is below 0.5, outside the method; Y_B at 0.5 is used.",
                      "ISO 6336-3:2006, 7.4")
        ratio = 0.5
    return 1.6 * math.log(2.242 / ratio)


def deep_tooth_factor(eps_alpha_n: float, grade: int) -> float:
    """Y_DT (1 unless accuracy grade ≤ 4 and ε_αn > 2.05).

    Parameters
    ----------
    eps_alpha_n : float
        Virtual contact ratio ε_αn.
    grade : int
        ISO 1328-1 accuracy grade.

    Returns
    -------
    float

    References
    ----------
    ISO 6336-3:2006, 7.5, eqs. (45)–(47).
    """
    if grade > 4 or eps_alpha_n <= 2.05:
        return 1.0
    if eps_alpha_n <= 2.5:
        return -0.666 * eps_alpha_n + 2.366
    return 0.9


def slip_layer(treatment: str, yield_strength: float) -> float:
    """Slip-layer thickness ρ' of a material, mm.

    Parameters
    ----------
    treatment : str
        ISO 6336-5 symbol.
    yield_strength : float
        σ_0.2 (V, GTS, GGG) or σ_S (St), N/mm².

    Returns
    -------
    float

    References
    ----------
    ISO 6336-3:2006, 13.2, Table 4 (St σ_S = 300/400: 0.0833/0.0445; V σ_0.2 = 500/600/800/1000:
    0.0281/0.0194/0.0064/0.0014; Eh, IF: 0.0030; NT, NV: 0.1993; GGG perl.: 0.1005; GG: 0.31).
    """
    if treatment in ("Eh", "IF"):
        return 0.0030
    if treatment in ("NT", "NV", "NV(nitrocar)"):
        return 0.1993
    if treatment == "GGG(perl)":
        return 0.1005
    if treatment in ("GG", "GGG(ferr)"):
        return 0.3124
    if treatment in ("St", "St(cast)"):
        return float(_interp(yield_strength, (300.0, 400.0), (0.0833, 0.0445)))
    return float(_interp(yield_strength, (500.0, 600.0, 800.0, 1000.0), (0.0281, 0.0194, 0.0064, 0.0014)))


def _interp(x: float, xs, ys) -> float:
    if x <= xs[0]:
        return ys[0]
    for x0, x1, y0, y1 in zip(xs, xs[1:], ys, ys[1:]):
        if x <= x1:
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    return ys[-1]


def relative_notch_sensitivity(q_s: float, treatment: str, yield_strength: float) -> float:
    """Y_δrelT = (1 + √(ρ' χ*)) / (1 + √(1.2 ρ')), χ* = (1 + 2 q_s)/5.

    Parameters
    ----------
    q_s : float
        Notch parameter of the gear's critical section.
    treatment : str
        ISO 6336-5 symbol.
    yield_strength : float
        N/mm².

    Returns
    -------
    float

    References
    ----------
    ISO 6336-3:2006, 13.2, eqs. (54)–(55) (χ*_T for q_sT = 2.5).

    Examples
    --------
    >>> round(relative_notch_sensitivity(2.5, "Eh", 850.0), 6)  # the reference gear: 1
    1.0
    """
    rho = slip_layer(treatment, yield_strength)
    chi = (1.0 + 2.0 * q_s) / 5.0
    return (1.0 + math.sqrt(rho * chi)) / (1.0 + math.sqrt(rho * 1.2))


def relative_surface_factor(rz: float, treatment: str) -> float:
    """Y_RrelT from the root roughness R_z in µm.

    Parameters
    ----------
    rz : float
        Mean peak-to-valley roughness of the root fillet, µm.
    treatment : str
        ISO 6336-5 symbol.

    Returns
    -------
    float

    References
    ----------
    ISO 6336-3:2006, 14.2, eqs. (59)–(64) (R_z < 1 µm: 1.120, 1.070, 1.025).

    Examples
    --------
    >>> round(relative_surface_factor(10.0, "Eh"), 4)  # the test gear's R_z = 10 µm: about 1
    1.0017
    """
    if rz >= 40.0:
        warn_validity(f"root roughness R_z = {rz:g} µm is outside 1 <= R_z < 40 µm; the value at 40 µm is used.",
                      "ISO 6336-3:2006, 14.2")
        rz = 40.0 - 1e-9
    if treatment in ("V", "V(cast)", "GGG(perl)", "GTS", "Eh", "IF"):
        return 1.120 if rz < 1.0 else 1.674 - 0.529 * (rz + 1.0) ** 0.1
    if treatment in ("St", "St(cast)"):
        return 1.070 if rz < 1.0 else 5.306 - 4.203 * (rz + 1.0) ** 0.01
    return 1.025 if rz < 1.0 else 4.299 - 3.259 * (rz + 1.0) ** 0.0058


def size_factor(module: float, treatment: str) -> float:
    """Y_X by material and normal module (mm).

    Parameters
    ----------
    module : float
        m_n, mm.
    treatment : str
        ISO 6336-5 symbol.

    Returns
    -------
    float

    References
    ----------
    ISO 6336-3:2006, clause 15, Table 6 (method B).

    Examples
    --------
    >>> size_factor(4.0, "Eh"), round(size_factor(10.0, "Eh"), 3), round(size_factor(10.0, "V"), 3)
    (1.0, 0.95, 0.97)
    """
    if module <= 5.0:
        return 1.0
    if treatment in ("St", "St(cast)", "V", "V(cast)", "GGG(perl)", "GGG(ferr)", "GTS"):
        return 1.03 - 0.006 * module if module < 30.0 else 0.85
    if treatment in ("Eh", "IF", "NT", "NV", "NV(nitrocar)"):
        return 1.05 - 0.01 * module if module < 25.0 else 0.8
    return 1.075 - 0.015 * module if module < 25.0 else 0.7
