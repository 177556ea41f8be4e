"""Tooth form factor Y_F and stress correction factor Y_S (ISO 6336-3, Method B).

External gears: the critical section is where the 30° tangent touches the root
fillet that the basic rack (dedendum h_fP, tip radius ρ_fP, protuberance
residual s_pr) generates in the virtual spur gear of z_n teeth.  The angle ϑ
comes from the fixed-point iteration of ISO 6336-3 eq. (18)::

    E = π m_n/4 − h_fP tan α_n + s_pr / cos α_n − (1 − sin α_n) ρ_fP / cos α_n     (14)
    G = ρ_fP/m_n − h_fP/m_n + x                                                     (16)
    H = 2/z_n (π/2 − E/m_n) − π/3                                                   (17)
    ϑ = 2G/z_n tan ϑ − H                           (iterated from ϑ = π/6)          (18)
    s_Fn/m_n = z_n sin(π/3 − ϑ) + √3 (G / cos ϑ − ρ_fP/m_n)                         (12)
    ρ_F/m_n = ρ_fP/m_n + 2G² / (cos ϑ (z_n cos²ϑ − 2G))                             (13)

and the load acts at the outer point of single pair tooth contact of the
virtual gear (d_en, α_en, γ_e, α_Fen, eqs. (19)–(27)); then::

    Y_F = 6 (h_Fe/m_n) cos α_Fen / ((s_Fn/m_n)² cos α_n)                            (11)
    Y_S = (1.2 + 0.13 L) q_s^(1 / (1.21 + 2.3/L)),  L = s_Fn/h_Fe,  q_s = s_Fn/(2ρ_F) (41)

Internal gears (ISO 6336-3, 6.3): the tooth is approximated by a rack-shaped
tooth (z_n → ∞) whose dedendum is the depth of the root circle below the datum
line: from the pinion-type cutter (z_0, x_0, addendum h_a0*, tip radius ρ_a0*)
that cuts it, or — the fallback — from the basic rack (h_fP, ρ_fP).  The 30°
tangent on the fillet of radius ρ_fP gives::

    s_Fn = 2 (π m_n/4 + (h_fP − ρ_fP) tan α_n + ρ_fP/cos α_n − ρ_fP cos 30°)
    h_Fe = e − ρ_fP (1 − sin 30°) − (π m_n/4 + (h_fP − e) tan α_n) tan α_n,  ρ_F = ρ_fP

with e the radial distance of the load point (outer point of single contact,
toward the ring's tip) from the root circle, and α_Fen = α_n.  The fillet radius
of the ring is taken as the tool's tip radius (the cutter's curvature, which
widens it, is neglected: a conservative Y_S).

References
----------
ISO 6336-3:2006, clause 6, eqs. (11)–(27) and 6.3 (internal gears); clause 7,
eq. (41) (Y_S, valid for 1 ≤ q_s < 8); the same in ISO 6336-3:2019.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..geometry.errors import GeometryError
from ..geometry.tooth_generation import PinionCutter
from .errors import RatingError, warn_validity

__all__ = ["Cutter", "ToothForm", "external_tooth_form", "internal_tooth_form", "stress_correction"]


@dataclass(frozen=True)
class Cutter(PinionCutter):
    """A pinion-type cutter (shaper cutter) that cuts an internal gear: the ``cutter`` key.

    The :class:`~epicyclic.geometry.tooth_generation.PinionCutter` with the addendum 1.25 of an
    ISO 53 cutter by default, and :class:`RatingError` for bad values.

    Parameters
    ----------
    teeth : int
        z_0 (≥ 8).
    profile_shift : float, default 0
        x_0.
    addendum : float, default 1.25
        h_a0* (cutter addendum / m_n; 1.25 cuts the ISO 53 root).
    tip_radius : float, default 0.25
        ρ_a0* (cutter tip radius / m_n).

    References
    ----------
    ISO 6336-3:2006, 6.3 (internal gears cut by a pinion-type cutter).
    """

    addendum: float | None = 1.25

    def __post_init__(self) -> None:
        try:
            super().__post_init__()
        except GeometryError as exc:
            raise RatingError(str(exc).replace("PinionCutter:", "cutter:")) from None


@dataclass(frozen=True)
class ToothForm:
    """The critical section and the factors of one gear's tooth (lengths in mm).

    Attributes
    ----------
    Y_F, Y_S : float
        Tooth form and stress correction factor.
    s_Fn, h_Fe, rho_F : float
        Chord of the critical section, bending moment arm, root fillet radius there, mm.
    alpha_Fen : float
        Load direction angle at the outer point of single contact, rad.
    q_s, L : float
        Notch parameter s_Fn/(2ρ_F) and s_Fn/h_Fe.
    theta : float
        ϑ of eq. (18), rad (0 for the rack approximation of internal gears).
    method : str
        ``"30° tangent"``, ``"rack (basic rack)"`` or ``"rack (pinion-type cutter)"``.
    """

    Y_F: float
    Y_S: float
    s_Fn: float
    h_Fe: float
    rho_F: float
    alpha_Fen: float
    q_s: float
    L: float
    theta: float
    method: str

    def to_dict(self) -> dict[str, Any]:
        """Plain data (mm, degrees)."""
        return {"Y_F": self.Y_F, "Y_S": self.Y_S, "s_Fn": self.s_Fn, "h_Fe": self.h_Fe, "rho_F": self.rho_F,
                "alpha_Fen": math.degrees(self.alpha_Fen), "q_s": self.q_s, "L": self.L,
                "theta": math.degrees(self.theta), "method": self.method}


def _inv(angle: float) -> float:
    return math.tan(angle) - angle


def stress_correction(s_Fn: float, h_Fe: float, rho_F: float, clause: str = "ISO 6336-3:2019, 7.2") -> float:
    """Y_S = (1.2 + 0.13 L) q_s^(1/(1.21 + 2.3/L)) with L = s_Fn/h_Fe, q_s = s_Fn/(2 ρ_F).

    Parameters
    ----------
    s_Fn, h_Fe, rho_F : float
        Critical section chord, bending arm and fillet radius, mm.
    clause : str
        Named in the warning when q_s leaves 1 ≤ q_s < 8.

    Returns
    -------
    float

    References
    ----------
    ISO 6336-3:2006, eq. (41) (range of validity 1 ≤ q_s < 8).

    Examples
    --------
    >>> round(stress_correction(8.0, 6.0, 1.2), 4)
    2.0698
    """
    q_s = s_Fn / (2.0 * rho_F)
    L = s_Fn / h_Fe
    if not 1.0 <= q_s < 8.0:
        warn_validity(f"notch parameter q_s = {q_s:.3f} lies outside 1 <= q_s < 8 where Y_S is defined; "
                      "Y_S is computed with the formula anyway (the fillet is sharper or wider than the tests).",
                      clause)
    return (1.2 + 0.13 * L) * q_s ** (1.0 / (1.21 + 2.3 / L))


def external_tooth_form(teeth: int, profile_shift: float, module: float, pressure_angle: float, helix_angle: float,
                        tip_diameter: float, contact_ratio: float, *, dedendum: float = 1.25,
                        tip_radius: float = 0.25, protuberance: float = 0.0) -> ToothForm:
    """Y_F, Y_S of an external gear by the 30° tangent method (ISO 6336-3, Method B).

    Parameters
    ----------
    teeth : int
        z.
    profile_shift : float
        x.
    module : float
        m_n, mm.
    pressure_angle, helix_angle : float
        α_n and β, rad.
    tip_diameter : float
        d_a, mm (as made, with tip shortening).
    contact_ratio : float
        ε_α of the mesh (transverse).
    dedendum, tip_radius : float
        h_fP* and ρ_fP* of the basic rack that cuts the gear (ISO 53:1998 A: 1.25, 0.38; B: 1.25, 0.3;
        C: 1.25, 0.25; D: 1.4, 0.39).
    protuberance : float, default 0
        Residual undercut s_pr of a protuberance tool, mm.

    Returns
    -------
    ToothForm

    Raises
    ------
    RatingError
        The iteration for ϑ does not converge (a tooth the method cannot describe).

    References
    ----------
    ISO 6336-3:2006, eqs. (11)–(27); ISO 6336-3:2019, 6.2.

    Examples
    --------
    z = 19, x = 0.5, m_n = 4, ISO 53 rack with ρ_fP* = 0.25 (critical section as in
    the independent DIN 3990 implementation hanslhansl/din3990, tests/test_1.py:
    s_Fn = 8.7487 mm (here 8.7492: 6e-5 apart), ρ_F = 1.3161 mm, ϑ = 48.10°):

    >>> f = external_tooth_form(19, 0.5, 4.0, math.radians(20), 0.0, 88.0, 1.5363)
    >>> round(f.s_Fn, 4), round(f.rho_F, 4), round(math.degrees(f.theta), 2)
    (8.7492, 1.3161, 48.1)
    """
    m, an, beta = module, pressure_angle, helix_angle
    h_fP, rho_fP = dedendum * m, tip_radius * m
    beta_b = math.asin(math.sin(beta) * math.cos(an))
    z_n = teeth / (math.cos(beta_b) ** 2 * math.cos(beta))
    E = math.pi / 4 * m - h_fP * math.tan(an) + protuberance / math.cos(an) - (1 - math.sin(an)) * rho_fP / math.cos(an)
    G = rho_fP / m - h_fP / m + profile_shift
    H = 2.0 / z_n * (math.pi / 2 - E / m) - math.pi / 3
    theta = math.pi / 6
    for _ in range(200):
        new = 2.0 * G / z_n * math.tan(theta) - H
        if abs(new - theta) < 1e-12:
            theta = new
            break
        theta = new
    else:
        raise RatingError(f"tooth form (ISO 6336-3, eq. 18): the 30° tangent iteration does not converge for z = "
                          f"{teeth}, x = {profile_shift:g}; check the tooth count and the basic rack.")
    s_Fn = m * (z_n * math.sin(math.pi / 3 - theta) + math.sqrt(3) * (G / math.cos(theta) - rho_fP / m))
    rho_F = m * (rho_fP / m + 2 * G * G / (math.cos(theta) * (z_n * math.cos(theta) ** 2 - 2 * G)))
    # load at the outer point of single pair tooth contact of the virtual gear, eqs. (19)-(27)
    d = teeth * m / math.cos(beta)
    d_n = m * z_n
    d_bn = d_n * math.cos(an)
    d_an = d_n + tip_diameter - d
    eps_an = contact_ratio / math.cos(beta_b) ** 2
    p_bn = math.pi * m * math.cos(an)
    roll = math.sqrt(max(0.0, (d_an / 2) ** 2 - (d_bn / 2) ** 2)) - p_bn * (eps_an - 1.0)
    d_en = 2.0 * math.sqrt(roll * roll + (d_bn / 2) ** 2)
    alpha_en = math.acos(min(1.0, d_bn / d_en))
    gamma_e = (math.pi / 2 + 2 * profile_shift * math.tan(an)) / z_n + _inv(an) - _inv(alpha_en)
    alpha_Fen = alpha_en - gamma_e
    h_Fe = 0.5 * m * ((math.cos(gamma_e) - math.sin(gamma_e) * math.tan(alpha_Fen)) * d_en / m
                      - z_n * math.cos(math.pi / 3 - theta) - G / math.cos(theta) + rho_fP / m)
    if not (s_Fn > 0 and h_Fe > 0 and rho_F > 0):
        raise RatingError(f"tooth form (ISO 6336-3, 6.2): no critical section for z = {teeth}, x = {profile_shift:g} "
                          f"(s_Fn = {s_Fn:.3g}, h_Fe = {h_Fe:.3g} mm); the tooth is undercut or pointed.")
    Y_F = 6.0 * (h_Fe / m) * math.cos(alpha_Fen) / ((s_Fn / m) ** 2 * math.cos(an))
    Y_S = stress_correction(s_Fn, h_Fe, rho_F, "ISO 6336-3, eq. (41)")
    return ToothForm(Y_F, Y_S, s_Fn, h_Fe, rho_F, alpha_Fen, s_Fn / (2 * rho_F), s_Fn / h_Fe, theta, "30° tangent")


def internal_tooth_form(teeth: int, profile_shift: float, module: float, pressure_angle: float, helix_angle: float,
                        tip_diameter: float, contact_ratio: float, *, dedendum: float = 1.25,
                        tip_radius: float = 0.25, cutter: Cutter | None = None) -> ToothForm:
    """Y_F, Y_S of an internal gear (rack-shaped tooth, ISO 6336-3, 6.3).

    Parameters
    ----------
    teeth : int
        z (positive; the gear is internal).
    profile_shift : float
        x in the ISO 21771 sign, as :class:`~epicyclic.geometry.GearGeometry` holds it (a negative x
        enlarges an internal gear's tip and root circles).
    module : float
        m_n, mm.
    pressure_angle, helix_angle : float
        α_n and β, rad.
    tip_diameter : float
        d_a (the inner circle of the tips), mm.
    contact_ratio : float
        ε_α of the mesh.
    dedendum, tip_radius : float
        h_fP*, ρ_fP* of the basic rack: the fallback where no cutter is given.
    cutter : Cutter, optional
        The pinion-type cutter: its addendum, shift and tip radius give the root depth
        and fillet radius.

    Returns
    -------
    ToothForm

    Raises
    ------
    RatingError
        The cutter's tooth count is not below the gear's, no critical section.

    References
    ----------
    ISO 6336-3:2006, 6.3 (internal gears); ISO 21771:2007 (cutting centre distance).

    Examples
    --------
    >>> f = internal_tooth_form(96, 0.0, 1.5, math.radians(20), 0.0, 141.0, 1.7)
    >>> round(f.s_Fn / 1.5, 4), f.method
    (2.3978, 'rack (basic rack)')
    """
    m, an, beta = module, pressure_angle, helix_angle
    x = -profile_shift  # the internal-gear equations below are written in the KHK sign: x_KHK = -x_ISO
    mt = m / math.cos(beta)
    d = teeth * mt
    alpha_t = math.atan(math.tan(an) / math.cos(beta))
    if cutter is None:
        h_fP, rho_fP, method = dedendum * m, tip_radius * m, "rack (basic rack)"
    else:
        if cutter.teeth >= teeth:
            raise RatingError(f"cutter: z0 = {cutter.teeth} must be smaller than the internal gear's z = {teeth}.")
        inv_w0 = _inv(alpha_t) + 2 * math.tan(an) * (x - cutter.profile_shift) / (teeth - cutter.teeth)
        alpha_w0 = _solve_inv(inv_w0)
        a0 = mt * (teeth - cutter.teeth) / 2 * math.cos(alpha_t) / math.cos(alpha_w0)
        d_a0 = cutter.teeth * mt + 2 * m * (cutter.addendum + cutter.profile_shift)
        root = 2 * a0 + d_a0
        h_fP = (root - d) / 2 - x * m
        rho_fP, method = cutter.tip_radius * m, "rack (pinion-type cutter)"
    beta_b = math.asin(math.sin(beta) * math.cos(an))
    z_n = teeth / (math.cos(beta_b) ** 2 * math.cos(beta))
    d_n = m * z_n
    d_bn = d_n * math.cos(an)
    d_an = d_n - (d - tip_diameter)
    eps_an = contact_ratio / math.cos(beta_b) ** 2
    roll = math.sqrt(max(0.0, (d_an / 2) ** 2 - (d_bn / 2) ** 2)) + math.pi * m * math.cos(an) * (eps_an - 1.0)
    r_en = math.sqrt(roll * roll + (d_bn / 2) ** 2)
    depth = (r_en - d_n / 2) - x * m          # of the load point below the datum line
    e = h_fP - depth                                       # load point above the root circle
    s_Fn = 2 * (math.pi * m / 4 + (h_fP - rho_fP) * math.tan(an) + rho_fP / math.cos(an)
                - rho_fP * math.cos(math.pi / 6))
    h_Fe = e - rho_fP * (1 - math.sin(math.pi / 6)) - (math.pi * m / 4 + (h_fP - e) * math.tan(an)) * math.tan(an)
    rho_F = rho_fP if rho_fP > 0 else 1e-3 * m
    if not (s_Fn > 0 and h_Fe > 0):
        raise RatingError(f"tooth form (ISO 6336-3, 6.3): no critical section for the internal gear z = {teeth} "
                          f"(s_Fn = {s_Fn:.3g}, h_Fe = {h_Fe:.3g} mm); check tip diameter and tool.")
    Y_F = 6.0 * (h_Fe / m) / (s_Fn / m) ** 2
    Y_S = stress_correction(s_Fn, h_Fe, rho_F, "ISO 6336-3, 6.3 and eq. (41)")
    return ToothForm(Y_F, Y_S, s_Fn, h_Fe, rho_F, an, s_Fn / (2 * rho_F), s_Fn / h_Fe, 0.0, method)


def _solve_inv(value: float) -> float:
    """The angle α with inv α = value (Newton), rad."""
    if value <= 0:
        raise RatingError("cutter: the profile shifts of gear and cutter give no cutting pressure angle.")
    a = (3 * value) ** (1 / 3)
    for _ in range(60):
        step = (_inv(a) - value) / math.tan(a) ** 2
        a -= step
        if abs(step) < 1e-15:
            break
    return a
