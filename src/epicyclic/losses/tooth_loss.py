"""The tooth loss factor H_V of a gear mesh and the mesh efficiency η = 1 − μ H_V.

The mean power lost by sliding in a mesh is ``P_V = μ_m H_V P`` (P the power
through the mesh, μ_m the mean coefficient of friction).  The tooth loss factor
H_V is the integral of the sliding speed times the normal load along the path of
contact, divided by the pitch-line speed and the nominal load.  With the load
shared equally by two tooth pairs in double contact and carried by one pair in
single contact, it has Ohlendorf's closed form

.. math::

    H_V = \\frac{\\pi (u + 1)}{z_1\\,u\\,\\cos\\beta_b}
          \\left(1 - \\varepsilon_\\alpha + \\varepsilon_1^2 + \\varepsilon_2^2\\right)

with the gear ratio u = z_2/z_1 (negative for an internal gear 2), the base helix
angle β_b and the addendum contact ratios ε_1, ε_2 (the parts of the path of
contact on the addenda of gear 1 and gear 2, in base pitches; ε_α = ε_1 + ε_2).
For an internal mesh (u < 0) the factor (u + 1)/u = 1 − z_1/|z_2| makes H_V
smaller: the flanks roll with less sliding.

References
----------
Ohlendorf, H.: *Verlustleistung und Erwärmung von Stirnrädern*, Diss. TH München (1958)
(the closed form above), as used in ISO/TR 14179-2:2001 and by
Fernandes, Marques, Martins, Seabra: *Influence of gear loss factor on the power loss
prediction*, Mechanical Sciences 6 (2015) 81–88, eq. (2);
Wimmer, A.: *Lastverluste von Stirnradverzahnungen*, Diss. TU München (2006)
(H_V as the path integral, :func:`tooth_loss_factor_numerical`).
"""

from __future__ import annotations

import math

import numpy as np

from ..geometry.gear import MeshGeometry
from .errors import LossModelError

__all__ = ["addendum_contact_ratios", "tooth_loss_factor", "tooth_loss_factor_method", "tooth_loss_factor_numerical",
           "mesh_efficiency",
           "base_helix_angle", "sliding_integral"]


def base_helix_angle(mesh: MeshGeometry) -> float:
    """β_b with sin β_b = sin β cos α_n, rad (ISO 21771)."""
    rack = mesh.rack
    return math.asin(math.sin(rack.beta) * math.cos(rack.alpha_n))


def addendum_contact_ratios(mesh: MeshGeometry) -> tuple[float, float]:
    """(ε_1, ε_2): the path of contact on the addendum of gear 1 and of gear 2, in transverse base pitches.

    External mesh: g_i = √(r_ai² − r_bi²) − r_wi sin α_wt.  Internal gear 2 (its
    addendum lies inside its pitch circle): g_2 = r_w2 sin α_wt − √(r_a2² − r_b2²).

    Examples
    --------
    FZG type C gear (z = 16/24, m = 4.5, x = 0.1817/0.1715, a = 91.5 mm): ε_α = 1.46.

    >>> from epicyclic.geometry import BasicRack, GearGeometry, MeshGeometry
    >>> rack = BasicRack(4.5)
    >>> c = MeshGeometry(GearGeometry(16, rack, 0.1817), GearGeometry(24, rack, 0.1715))
    >>> round(sum(addendum_contact_ratios(c)), 2)
    1.46

    References
    ----------
    ISO 21771:2007 (path of contact g_α = g_f + g_a, ε_α = g_α/p_bt).
    """
    g1, g2 = mesh.gear1, mesh.gear2
    alpha = mesh.alpha_wt
    r_w1, r_w2 = (d / 2.0 for d in mesh.operating_pitch_diameters)
    p_bt = math.pi * mesh.rack.transverse_module * math.cos(mesh.rack.alpha_t)
    path1 = math.sqrt(max(0.0, (g1.tip_diameter / 2) ** 2 - (g1.base_diameter / 2) ** 2)) - r_w1 * math.sin(alpha)
    root2 = math.sqrt(max(0.0, (g2.tip_diameter / 2) ** 2 - (g2.base_diameter / 2) ** 2))
    path2 = r_w2 * math.sin(alpha) - root2 if mesh.internal else root2 - r_w2 * math.sin(alpha)
    return path1 / p_bt, path2 / p_bt


def _signed_ratio(mesh: MeshGeometry) -> float:
    z1, z2 = mesh.gear1.teeth, mesh.gear2.teeth
    return -z2 / z1 if mesh.internal else z2 / z1


def _pairs_in_contact(xi, eps: float):
    """Tooth pairs in contact at path position ξ (base pitches from A): #{k ∈ Z: 0 ≤ ξ + k ≤ ε}."""
    return np.floor(eps - xi) + np.floor(xi) + 1.0


def sliding_integral(eps1: float, eps2: float) -> float:
    """∫_A^E |ξ − ξ_C| / (pairs in contact) dξ over the path of contact (base pitches), exact.

    The load is shared equally by the tooth pairs in contact (Ohlendorf's
    assumption, extended to any contact ratio); the integrand is linear between
    the points where a pair enters or leaves contact and the pitch point C, so
    the trapezoid rule over those points is exact.  Equals
    (1 − ε_α + ε_1² + ε_2²)/2 when the pitch point lies in single contact
    (ε_1, ε_2 ≤ 1 ≤ ε_α).
    """
    eps = eps1 + eps2  # ξ_C = ε_2 may lie outside [0, ε] (path beside the pitch point)
    breaks = {0.0, eps, eps2}
    k = 1.0
    while k < eps:
        breaks.update({k, eps - k})
        k += 1.0
    points = sorted(b for b in breaks if 0.0 <= b <= eps)
    total = 0.0
    for left, right in zip(points[:-1], points[1:]):
        count = float(_pairs_in_contact(0.5 * (left + right), eps))
        total += 0.5 * (abs(left - eps2) + abs(right - eps2)) * (right - left) / max(count, 1.0)
    return total


def tooth_loss_factor(mesh: MeshGeometry) -> float:
    """Ohlendorf's tooth loss factor H_V of a mesh (dimensionless).

    Ohlendorf's closed form holds while the pitch point lies in single contact
    (ε_1, ε_2 ≤ 1), and is the published convention also for ε_α < 1 (helical
    gears).  Otherwise H_V is the exact integral of the same load sharing over the
    actual path of contact (:func:`sliding_integral`), which joins the closed form
    continuously: where the pitch point lies in double contact (internal meshes with
    ε_2 > 1, a long path on the ring's addendum), and where the path of contact lies
    beside the pitch point (ε_1 < 0 or ε_2 < 0: e.g. an internal mesh whose ring tip
    lies outside the operating pitch circle, so the ring's addendum never meets the
    planet's flank before the pitch point) — the sliding speed then keeps one sign
    along the path.  :func:`tooth_loss_factor_method` says which applies.

    Parameters
    ----------
    mesh : MeshGeometry
        External or internal pair (gear 2 may be internal).

    Returns
    -------
    float
        H_V ≥ 0.

    Raises
    ------
    LossModelError
        No path of contact at all (ε_α ≤ 0: the tips do not reach across the line of action).

    Examples
    --------
    FZG type C gear: H_V = 0.1986 (GEARpie, Fernandes 2023, report C40, "Gear Loss Factor HV, Ohlendorf"):

    >>> from epicyclic.geometry import BasicRack, GearGeometry, MeshGeometry
    >>> rack = BasicRack(4.5)
    >>> round(tooth_loss_factor(MeshGeometry(GearGeometry(16, rack, 0.1817), GearGeometry(24, rack, 0.1715))), 4)
    0.1986

    References
    ----------
    Ohlendorf 1958; Fernandes et al. 2015, Mech. Sci. 6, eqs. (1)–(2); Wimmer 2006 (H_V as the path integral).
    """
    eps1, eps2 = addendum_contact_ratios(mesh)
    if eps1 + eps2 <= 0.0:
        raise LossModelError(
            f"mesh {mesh.name or '(unnamed)'}: there is no path of contact (addendum contact ratios {eps1:.4f}, "
            f"{eps2:.4f}, eps_alpha = {eps1 + eps2:.4f} <= 0): the tips do not reach across the line of action. "
            "Check the profile shifts and tip diameters."
        )
    u = _signed_ratio(mesh)
    z1 = mesh.gear1.teeth
    factor = math.pi * (u + 1.0) / (z1 * u * math.cos(base_helix_angle(mesh)))
    if 0.0 <= eps1 <= 1.0 and 0.0 <= eps2 <= 1.0:
        return factor * (1.0 - (eps1 + eps2) + eps1 ** 2 + eps2 ** 2)
    return factor * 2.0 * sliding_integral(eps1, eps2)


def tooth_loss_factor_method(mesh: MeshGeometry) -> str:
    """Which form of H_V :func:`tooth_loss_factor` uses for this mesh, in words.

    Parameters
    ----------
    mesh : MeshGeometry
        The mesh.

    Returns
    -------
    str
        ``"Ohlendorf closed form"``, ``"path integral (pitch point in double contact)"`` or
        ``"path integral (path of contact beside the pitch point)"``.

    References
    ----------
    Ohlendorf 1958; Wimmer 2006.
    """
    eps1, eps2 = addendum_contact_ratios(mesh)
    if eps1 < 0.0 or eps2 < 0.0:
        return "path integral (path of contact beside the pitch point)"
    if eps1 > 1.0 or eps2 > 1.0:
        return "path integral (pitch point in double contact)"
    return "Ohlendorf closed form"


def tooth_loss_factor_numerical(mesh: MeshGeometry, points: int = 400_000) -> float:
    """H_V of a spur mesh as the path integral (Wimmer's definition) on a fine grid — an independent check.

    .. math:: H_V = \\frac{1}{p_{bt}} \\int_A^E \\frac{F(x)}{F_{bt}} \\frac{v_g(x)}{v_{tb}}\\,dx

    with the sliding speed v_g = |x − x_C| |ω_1 ± ω_2| (+ external, − internal),
    v_tb = ω_1 r_b1 and the load F/F_bt shared equally by the pairs in contact
    (midpoint rule on ``points`` intervals; error of order 1/points at the
    steps of the load sharing).

    Parameters
    ----------
    mesh : MeshGeometry
        A spur mesh (helix angle 0) with contact ratio ε_α ≥ 1.
    points : int, default 400000
        Intervals of the midpoint rule on the path of contact.

    Returns
    -------
    float
        H_V.

    Raises
    ------
    LossModelError
        A helical mesh, or ε_α < 1.

    References
    ----------
    Wimmer 2006; Fernandes et al. 2015, Mech. Sci. 6, eq. (1).
    """
    if mesh.rack.helix_angle != 0.0:
        raise LossModelError("tooth_loss_factor_numerical: spur meshes only (helix_angle = 0).")
    eps1, eps2 = addendum_contact_ratios(mesh)
    eps = eps1 + eps2
    if eps < 1.0:
        raise LossModelError(f"tooth_loss_factor_numerical: needs eps_alpha >= 1 (spur), got {eps:.4f}.")
    p_bt = math.pi * mesh.rack.transverse_module * math.cos(mesh.rack.alpha_t)
    r_b1 = mesh.gear1.base_diameter / 2
    z1, z2 = mesh.gear1.teeth, mesh.gear2.teeth
    omega_ratio = 1.0 - z1 / z2 if mesh.internal else 1.0 + z1 / z2  # |ω1 ± ω2| / ω1
    h = eps / points
    xi = (np.arange(points) + 0.5) * h  # midpoints, base pitches from A (A on gear 2's addendum side)
    integrand = np.abs(xi - eps2) / _pairs_in_contact(xi, eps)
    return float(integrand.sum() * h) * p_bt * omega_ratio / r_b1


def mesh_efficiency(friction, loss_factor):
    """η = 1 − μ H_V (floats or arrays).

    Parameters
    ----------
    friction : float or numpy.ndarray
        Mean coefficient of friction μ.
    loss_factor : float
        Ohlendorf's tooth loss factor H_V (:func:`tooth_loss_factor`).

    Returns
    -------
    float or numpy.ndarray
        The mesh efficiency.

    Raises
    ------
    LossModelError
        μ or H_V negative, not finite or not a number, μ ≥ 1, or μ H_V ≥ 1 (no efficiency left).

    References
    ----------
    Ohlendorf 1958; Fernandes et al. 2015, Mech. Sci. 6, eq. (1).

    Examples
    --------
    >>> round(mesh_efficiency(0.0256, 0.1986), 5)
    0.99492
    """
    mu = _checked_array(friction, "friction (mu)", "mesh_efficiency")
    h_v = _checked_array(loss_factor, "loss_factor (H_V)", "mesh_efficiency")
    if np.any(mu >= 1.0):
        raise LossModelError(f"mesh_efficiency: friction (mu) must be below 1 (gear meshes run at 0.02…0.1), got "
                             f"{float(np.max(mu))!r}.")
    loss = mu * h_v
    if np.any(loss >= 1.0):
        raise LossModelError(
            f"mesh_efficiency: friction (mu) × loss_factor (H_V) = {float(np.max(loss))!r} leaves no efficiency "
            "(mu·H_V >= 1); H_V of real meshes lies within 0.05…0.5 — check both arguments."
        )
    return 1.0 - loss if isinstance(friction, np.ndarray) or isinstance(loss_factor, np.ndarray) \
        else float(1.0 - loss)


def _checked_array(value, name: str, owner: str) -> np.ndarray:
    """``value`` as a float array of finite numbers ≥ 0, else LossModelError naming ``name``."""
    if isinstance(value, (bool, str, bytes)):
        raise LossModelError(f"{owner}: {name} must be a number, got {value!r}.")
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise LossModelError(f"{owner}: {name} must be a number or an array of numbers, got {value!r:.80}.") from None
    if not np.all(np.isfinite(array)) or np.any(array < 0):
        bad = array[~(np.isfinite(array) & (array >= 0))].ravel()[0]
        raise LossModelError(f"{owner}: {name} must be finite and >= 0, got {float(bad)!r}.")
    return array
