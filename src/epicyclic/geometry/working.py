"""Working geometry as built: tooth and tip thickness, overlap and total contact ratio, backlash — and their checks.

Tooth thickness (transverse, at a diameter d_y; x_E the generating shift with the
thickness allowance, ISO 21771)::

    s_t   = m_t (π/2 + 2 x_E tan α_n)                       at the reference circle
    s_yt  = d_y (s_t/d + inv α_t − inv α_yt)                  external gear
    s_yt  = d_y (s_t/d − inv α_t + inv α_yt)                  internal gear (x ISO)
    s_yn  = s_yt cos β_y,  tan β_y = tan β · d_y/d,  cos α_yt = d_b/d_y

The tip thickness is s_y at d_a.  Reviews ask for s_an ≥ 0.2 m_n (0.4 m_n for
case-hardened gears, whose tips would harden through): below 0.2 m_n the check is
an error (a pointed tooth at s_an ≤ 0), below 0.4 m_n a warning.

Contact ratios: ε_β = b sin β / (π m_n) (b the mesh's face width), ε_γ = ε_α + ε_β.
A mesh runs with continuous contact only when ε_γ ≥ 1; a spur mesh or a helical
mesh without a face width is judged by ε_α.  Backlash: :attr:`MeshGeometry.backlash`.

References
----------
ISO 21771:2007 (tooth thickness s_t, s_y; ε_β = b sin β/(π m_n); ε_γ = ε_α + ε_β;
x_E and j_bn, eqs. 62–63); Niemann/Winter, *Maschinenelemente* Bd. II (s_a ≥ 0.2 m,
0.4 m for case-hardened gears); DIN 3960:1987.
"""

from __future__ import annotations

import math

from .checks import BacklashCheck, ContactRatioCheck, FittingReport, TipThicknessCheck
from .contact import overlap_ratio
from .gear import GearGeometry, MeshGeometry
from .involute import inv, inv_inverse

__all__ = ["tooth_thickness", "tip_thickness", "pointed_tip_diameter", "overlap_ratio", "check_tip_thickness",
           "check_contact_ratio", "check_backlash", "TIP_THICKNESS_ERROR", "TIP_THICKNESS_WARNING", "check_stage"]

#: s_an / m_n below which the tip thickness is an error, and below which a warning.
TIP_THICKNESS_ERROR = 0.2
TIP_THICKNESS_WARNING = 0.4


def tooth_thickness(gear: GearGeometry, diameter: float) -> float:
    """Normal tooth thickness s_yn of a gear at a diameter, mm (negative beyond the pointed tip).

    Parameters
    ----------
    gear : GearGeometry
        External or internal gear; its generating shift x_E (with the thickness allowance) is used.
    diameter : float
        d_y ≥ d_b, mm (a smaller one is taken at the base circle).

    Returns
    -------
    float
        s_yn, mm.

    Examples
    --------
    At the reference circle of an unshifted gear the tooth is half a pitch thick:

    >>> from epicyclic.geometry.gear import BasicRack
    >>> g = GearGeometry(20, BasicRack(2.0))
    >>> round(tooth_thickness(g, g.reference_diameter), 6) == round(math.pi, 6)
    True

    References
    ----------
    ISO 21771:2007, s_t = m_t (π/2 + 2 x tan α_n), s_y = d_y (s/d ± (inv α_t − inv α_y)).
    """
    rack = gear.rack
    d, d_b = gear.reference_diameter, gear.base_diameter
    d_y = max(diameter, d_b)
    s_t = rack.transverse_module * (math.pi / 2.0 + 2.0 * gear.generating_profile_shift * math.tan(rack.alpha_n))
    alpha_y = math.acos(min(1.0, d_b / d_y))
    if gear.internal:
        s_yt = d_y * (s_t / d - inv(rack.alpha_t) + inv(alpha_y))
    else:
        s_yt = d_y * (s_t / d + inv(rack.alpha_t) - inv(alpha_y))
    beta_y = math.atan(math.tan(rack.beta) * d_y / d)
    return s_yt * math.cos(beta_y)


def tip_thickness(gear: GearGeometry) -> float:
    """Normal tooth thickness at the tip circle s_an, mm (≤ 0: a pointed tooth).

    Parameters
    ----------
    gear : GearGeometry
        The gear (tip shortening and allowance included).

    Returns
    -------
    float
        s_an, mm.

    References
    ----------
    ISO 21771:2007 (s_y at d_y = d_a).
    """
    return tooth_thickness(gear, gear.tip_diameter)


def pointed_tip_diameter(gear: GearGeometry) -> float:
    """The diameter at which an external gear's tooth comes to a point (s_y = 0), mm.

    inv α_y = s_t/d + inv α_t, d_y = d_b / cos α_y (ISO 21771).

    Parameters
    ----------
    gear : GearGeometry
        An external gear.

    Returns
    -------
    float
        d_y of the pointed tooth, mm.

    References
    ----------
    ISO 21771:2007 (tooth thickness s_y = 0).
    """
    rack = gear.rack
    s_t = rack.transverse_module * (math.pi / 2.0 + 2.0 * gear.generating_profile_shift * math.tan(rack.alpha_n))
    alpha = inv_inverse(s_t / gear.reference_diameter + inv(rack.alpha_t))
    return gear.base_diameter / math.cos(alpha)


def check_tip_thickness(gears, label=lambda name: name, error: float = TIP_THICKNESS_ERROR,
                        warning: float = TIP_THICKNESS_WARNING) -> tuple[TipThicknessCheck, ...]:
    """Tip thickness of every gear: an error below ``error`` m_n (pointed at ≤ 0), a warning below ``warning`` m_n.

    Parameters
    ----------
    gears : mapping name → GearGeometry
        The gears (:attr:`SetGeometry.gears`, or a stage's).
    label : callable, optional
        A gear's name as the user says it.
    error, warning : float
        The limits as multiples of m_n (0.2 and 0.4).

    Returns
    -------
    tuple of TipThicknessCheck

    References
    ----------
    ISO 21771:2007; Niemann/Winter Bd. II (s_a ≥ 0.2 m, case-hardened 0.4 m).
    """
    out = []
    for key, gear in gears.items():
        name = label(key)
        m = gear.rack.module
        s_a = tip_thickness(gear)
        ratio = s_a / m
        numbers = f"{name}: s_an = {s_a:.3f} mm = {ratio:.3f} m_n at d_a = {gear.tip_diameter:.3f} mm"
        if ratio >= warning:
            out.append(TipThicknessCheck("tip thickness", True, f"{numbers} (>= {warning:g} m_n)", "warning", name,
                                         s_a, m, error, warning))
            continue
        fix = "lower its profile shift or shorten its tip (tip_shortening)"
        if ratio <= 0.0:
            message = f"{name} has pointed teeth: {numbers}; {fix}"
        elif ratio < error:
            message = f"{name}: tip too thin, {numbers} < {error:g} m_n; {fix}"
        else:
            message = (f"{numbers} < {warning:g} m_n: enough for through-hardened gears, too thin for case-hardened "
                       f"ones; {fix} if the gear is case-hardened")
        severity = "error" if ratio < error else "warning"
        out.append(TipThicknessCheck("tip thickness", False, message, severity, name, s_a, m, error, warning))
    return tuple(out)


def check_contact_ratio(meshes, face_widths=None) -> tuple[ContactRatioCheck, ...]:
    """Continuous contact of every mesh: ε_γ ≥ 1 (ε_α for spur meshes or without face width) — an error otherwise.

    Parameters
    ----------
    meshes : sequence of MeshGeometry
        The meshes.
    face_widths : sequence of float or None, optional
        The face width of each mesh, mm (None where unknown).

    Returns
    -------
    tuple of ContactRatioCheck

    References
    ----------
    ISO 21771:2007 (ε_α, ε_β, ε_γ).
    """
    widths = list(face_widths) if face_widths is not None else [None] * len(meshes)
    out = []
    for mesh, width in zip(meshes, widths):
        eps_a = mesh.contact_ratio
        helical = mesh.rack.helix_angle > 0.0
        eps_b = overlap_ratio(mesh, width) if width is not None else (0.0 if not helical else None)
        total = eps_a + (eps_b or 0.0)
        judged = total if eps_b is not None else eps_a
        numbers = f"eps_alpha = {eps_a:.3f}" + (f", eps_beta = {eps_b:.3f}, eps_gamma = {total:.3f}"
                                                if helical and eps_b is not None else "")
        if judged >= 1.0:
            warn = helical and eps_a < 1.0
            message = f"{mesh.name}: {numbers}" + (
                " (eps_alpha < 1: continuous only through the overlap, check the profile)" if warn else
                " (continuous contact)")
            out.append(ContactRatioCheck("contact ratio", not warn, message, "warning", mesh.name, eps_a, eps_b,
                                         total))
            continue
        if eps_a <= 0.0:
            why = "the tips do not reach across the line of action: no contact at all"
        else:
            why = "no continuous contact (eps < 1): the mesh cannot run smoothly"
        missing = " (eps_beta unknown: give face_width)" if helical and eps_b is None else ""
        message = (f"{mesh.name}: {numbers}{missing}; {why}; raise the tip diameters (less tip shortening, other "
                   "shifts), more teeth (smaller module) or, helical, a wider face")
        out.append(ContactRatioCheck("contact ratio", False, message, "error", mesh.name, eps_a, eps_b, total))
    return tuple(out)


def _backlash_free_distance(mesh: MeshGeometry) -> float | None:
    """The centre distance at which the gears as cut (generating shifts x_E) mesh without backlash, mm."""
    from dataclasses import replace

    from .errors import GeometryError

    g1, g2 = mesh.gear1, mesh.gear2
    try:
        cut = MeshGeometry(replace(g1, profile_shift=g1.generating_profile_shift, thickness_allowance=0.0),
                           replace(g2, profile_shift=g2.generating_profile_shift, thickness_allowance=0.0))
    except GeometryError:
        return None
    return cut.center_distance


def check_backlash(meshes) -> tuple[BacklashCheck, ...]:
    """Backlash of every mesh at its centre distance: an error when the teeth jam (j_bn < 0).

    Parameters
    ----------
    meshes : sequence of MeshGeometry
        The meshes.

    Returns
    -------
    tuple of BacklashCheck

    References
    ----------
    ISO 21771:2007, eqs. (62), (63).
    """
    out = []
    for mesh in meshes:
        j = mesh.backlash
        given = mesh.working_center_distance is not None
        at = f"a_w = {mesh.center_distance:.4f} mm" + (" (given)" if given else "")
        if j >= -1e-9:
            message = f"{mesh.name}: normal backlash j_bn = {max(j, 0.0) * 1000:.1f} µm at {at}" + (
                "" if given or j > 1e-9 else " (backlash-free: give thickness_allowance or center_distance)")
            out.append(BacklashCheck("backlash", True, message, "error", mesh.name, max(j, 0.0),
                                     mesh.center_distance, given))
        else:
            free = _backlash_free_distance(mesh)
            where = f" (backlash-free at a_w = {free:.4f} mm)" if free is not None else ""
            message = (f"{mesh.name}: the teeth jam at {at}: j_bn = {j * 1000:.1f} µm < 0; the shifts and thickness "
                       f"allowances do not fit this centre distance{where}: move it, change the profile shifts or "
                       "thin the teeth (thickness_allowance)")
            out.append(BacklashCheck("backlash", False, message, "error", mesh.name, j, mesh.center_distance, given))
    return tuple(out)


def check_stage(geometry) -> FittingReport:
    """What a fixed-axis stage must meet to run: continuous contact, tip thickness and backlash of every mesh.

    An idler gear (:attr:`StageGeometry.idlers`) is checked once.

    Parameters
    ----------
    geometry : StageGeometry
        The stage's meshes.

    Returns
    -------
    FittingReport
        ``geometry`` the stage's; checks ``contact ratio``, ``tip thickness``, ``backlash``.

    References
    ----------
    ISO 21771:2007; Niemann/Winter Bd. II (tip thickness).
    """
    gears = {}
    for k, (mesh, (z1, z2, _kind)) in enumerate(zip(geometry.meshes, geometry.stage.meshes)):
        driving, driven = (mesh.gear1, mesh.gear2) if geometry.driving_is_gear1(k) else (mesh.gear2, mesh.gear1)
        if k not in geometry.idlers:  # mesh k's driving gear is mesh k-1's idler (1-based k)
            gears[f"mesh {k + 1} driving (z = {z1})"] = driving
        gears[f"mesh {k + 1} driven (z = {z2})" + (" idler" if k + 1 in geometry.idlers else "")] = driven
    checks = (*check_contact_ratio(geometry.meshes, geometry.mesh_face_widths()), *check_tip_thickness(gears),
              *check_backlash(geometry.meshes))
    return FittingReport(geometry, checks)
