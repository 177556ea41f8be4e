"""Fitting conditions of a planetary set: do the planets fit, assemble and mesh?

Each check returns a frozen result with ``passed``, the numbers behind it and a
message that names the condition, says by how much it fails and what to
change.  :func:`check_fitting` runs them all and returns a
:class:`FittingReport`.

Conditions
----------
coaxiality
    The sun mesh and the ring mesh must have the same operating centre
    distance (simple and stepped sets); for standard gears of a simple set
    ``z_r = z_s + 2 z_p``.  A double-planet set closes a triangle
    ``|a_1 − a_2| < a_12 < a_1 + a_2``.  (SDP/SI D785 eqs. 13-5, 13-6.)
assembly
    Planets can sit at carrier angles that are multiples of
    ``φ_min = 360° g / D`` (Queitsch: φ_min), with ``D = |z_r + z_s|`` for a
    simple set, ``|z_r − z_s|`` for a double-planet set and
    ``D = |z_s z_c ± z_r z_b|`` with ``g = gcd(z_b, z_c)`` for a stepped set
    (b meshes the sun, c the ring).  Equal spacing of N planets needs
    ``D/(g N)`` whole (SDP/SI D785 eqs. 13-7, 13-8); otherwise the nearest
    possible unequal spacing is reported.  Mesh phasing follows from
    ``z mod N`` (in-phase 0, sequential ±1, counter-phase otherwise;
    Drivetrain Hub, *Planetary Gears*).
neighbours
    Adjacent planets' tip circles keep a clearance:
    ``2 a sin(π/N) − d_a > c_min`` (SDP/SI D785 eq. 13-10); the largest N
    that fits is reported.
undercut
    ``x ≥ x_min = h_a* − z sin²α_t / (2 cos β)``, i.e. ``z ≥ z_g = 2 h_a* cos β / sin²α_t``
    (Queitsch: Grenzzähnezahl z_g; ≈ 17 for 20°, practical limit 5/6 z_g ≈ 14).
internal interference
    Involute, trochoid and trimming interference of each internal mesh
    (SDP/SI D785 section 5.2), reported as warnings.
contact ratio, tip thickness, backlash
    ε_γ ≥ 1 (continuous contact), s_an ≥ 0.2 m_n (a warning below 0.4 m_n) and
    j_bn ≥ 0 at the centre distance as built (:mod:`epicyclic.geometry.working`):
    a design that cannot run never passes.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from types import MappingProxyType
from typing import Literal

from .checks import (
    AssemblyCheck,
    Check,
    CoaxialityCheck,
    FittingReport,
    InterferenceCheck,
    NeighbourCheck,
    UndercutCheck,
)
from .errors import GeometryError, expect_type, finite_number
from .gear import MeshGeometry
from .coaxiality import check_coaxiality, coaxiality_tolerance
from .involute import inv
from .set_geometry import SetGeometry, gear_label
from .undercut import check_undercut, min_profile_shift, undercut_limit
from .working import check_backlash, check_contact_ratio, check_tip_thickness

__all__ = [
    "Check",
    "CoaxialityCheck",
    "AssemblyCheck",
    "NeighbourCheck",
    "UndercutCheck",
    "InterferenceCheck",
    "FittingReport",
    "check_coaxiality",
    "coaxiality_tolerance",
    "check_assembly",
    "check_neighbours",
    "check_undercut",
    "check_interference",
    "check_fitting",
    "assembly_ticks",
    "mesh_phasing",
    "max_planets",
    "undercut_limit",
    "min_profile_shift",
]

#: Numerical margin (mm) below which a clearance counts as contact.
_EPS_MM = 1e-9


# ---------------------------------------------------------------------- assembly
def assembly_ticks(teeth) -> int:
    """Number T of possible planet positions on the circle (φ_min = 360°/T).

    For a simple set ``T = z_s + z_r``; double-planet ``T = |z_r − z_s|``;
    stepped ``T = |σ_r z_s z_c − σ_s z_r z_b| / gcd(z_b, z_c)`` with σ = +1 for an
    internal and −1 for an external central gear (so ``z_s z_c + z_r z_b`` for
    sun and ring, ``|z_s z_c − z_r z_b|`` for two suns or two rings).

    Derivation: turning a planet copy by ψ relative to the carrier turns central
    gear j by σ_j ψ z_pj/z_j; a copy at carrier angle φ meshes iff
    φ − σ_j ψ z_pj/z_j is a whole tooth pitch of both central gears for some ψ,
    i.e. φ is a multiple of 360° g/D.

    >>> from epicyclic.model import Teeth
    >>> assembly_ticks(Teeth("simple", 17, 49, (16,)))
    66

    References
    ----------
    SDP/SI D785, eqs. (13-7) and (13-8); Queitsch, φ_min (minimaler Drehwinkelabstand
    zweier Planetenräder).
    """
    zs, zr, zp = teeth.sun, teeth.ring, teeth.planet
    if teeth.kind == "simple":
        return zs + zr
    if teeth.kind == "double":
        return abs(zr - zs)
    zb, zc = zp
    sigma_s = 1 if getattr(teeth, "sun_internal", False) else -1
    sigma_r = 1 if teeth.ring_internal else -1
    d = abs(sigma_r * zs * zc - sigma_s * zr * zb)
    return d // math.gcd(zb, zc)


def mesh_phasing(teeth: int, angles: Sequence[float]) -> str:
    """Phasing of the meshes of one central gear with planets at ``angles`` (degrees).

    From the first-harmonic sums of the mesh excitations: the force sum and the
    torque sum of the N meshes over one tooth period.

    Parameters
    ----------
    teeth : int
        Tooth count of the central gear.
    angles : sequence of float
        Angular positions of the planets, degrees.

    Returns
    -------
    str
        ``"in-phase"`` (all meshes together: torque ripple, no net force),
        ``"sequential"`` (net force, no torque ripple), ``"counter-phase"`` (neither)
        or ``"mixed"``.

    Examples
    --------
    >>> mesh_phasing(48, [0, 90, 180, 270]), mesh_phasing(51, [0, 90, 180, 270])
    ('in-phase', 'sequential')

    References
    ----------
    Drivetrain Hub, *Geometry / Planetary Gears* (notebooks-gears, Chapter 4):
    phase φ_i = 2π (θ_i z/2π mod 1); k_φ = z mod N.
    """
    n = len(angles)
    fx = fy = torque = 0j
    for theta in angles:
        q = (math.radians(theta) * teeth / (2 * math.pi)) % 1.0
        signal = complex(math.cos(2 * math.pi * q), math.sin(2 * math.pi * q))
        fx += math.cos(math.radians(theta)) * signal
        fy += math.sin(math.radians(theta)) * signal
        torque += signal
    f_sum = (abs(fx) + abs(fy)) / (n / 2)
    t_sum = abs(torque) / n
    f_zero, t_zero = f_sum < 1e-6, t_sum < 1e-6
    if f_zero and abs(t_sum - 1) < 1e-6:
        return "in-phase"
    if f_zero and t_zero:
        return "counter-phase"
    if abs(f_sum - 2) < 1e-6 and t_zero:
        return "sequential"
    return "mixed"


def check_assembly(geometry_or_teeth, planets: int, *, allow_unequal: bool = False) -> AssemblyCheck:
    """Whether ``planets`` planets can be assembled equally spaced, and where they would sit otherwise.

    Parameters
    ----------
    geometry_or_teeth : SetGeometry or Teeth
    planets : int
    allow_unequal : bool, default False
        Pass with unequal (nearest possible) spacing when equal spacing is impossible.

    References
    ----------
    SDP/SI D785, eqs. (13-7), (13-8); Drivetrain Hub, *Planetary Gears* (tick angle, phasing).
    """
    teeth = geometry_or_teeth.planetary_set.teeth if isinstance(geometry_or_teeth, SetGeometry) else geometry_or_teeth
    if isinstance(planets, bool) or not isinstance(planets, int) or planets < 1:
        raise GeometryError(f"check_assembly: planets must be a whole number >= 1, got {planets!r}.")
    ticks = assembly_ticks(teeth)
    equal = ticks % planets == 0
    if equal:
        positions = [i * ticks // planets for i in range(planets)]
    else:
        positions = [math.floor(i * ticks / planets + 0.5) for i in range(planets)]
    angles = tuple(360.0 * p / ticks for p in positions) if ticks else tuple(0.0 for _ in range(planets))
    deviation = max(abs(a - 360.0 * i / planets) for i, a in enumerate(angles))
    distinct = ticks >= planets and len(set(positions)) == planets
    phasing = {"sun": mesh_phasing(teeth.sun, angles), "ring": mesh_phasing(teeth.ring, angles)} if distinct else {}
    min_angle = 360.0 / ticks if ticks else 360.0
    formula = {"simple": "(z_sun + z_ring)", "double": "(z_ring - z_sun)", "stepped": "D/gcd(z_b, z_c)"}[teeth.kind]
    if equal:
        message = (
            f"{planets} planets equally spaced at {360.0 / planets:g}°: {formula}/N = {ticks}/{planets} = "
            f"{ticks // planets} (phi_min = {min_angle:.3f}°); phasing {gear_label(teeth, 'sun')} {phasing.get('sun')}, "
            f"{gear_label(teeth, 'ring')} {phasing.get('ring')}"
        )
        passed = True
    else:
        good = [n for n in range(2, 13) if ticks % n == 0]
        where = ", ".join(f"{a:.2f}°" for a in angles)
        message = (
            f"{planets} planets cannot be equally spaced: {formula}/N = {ticks}/{planets} = {ticks / planets:.3f} "
            f"is not whole (phi_min = {min_angle:.3f}°). "
            + (f"Nearest possible positions {where} (up to {deviation:.2f}° off equal spacing). " if distinct
               else "Not even unequal spacing places them. ")
            + f"Use N in {good or 'none up to 12'} or change z_ring by a tooth or two."
        )
        passed = allow_unequal and distinct
    severity = "warning" if (not equal and passed) else "error"
    return AssemblyCheck("assembly", passed, message, severity, planets, ticks, min_angle, equal, angles,
                         deviation, MappingProxyType(phasing))


# ---------------------------------------------------------------------- neighbours
def max_planets(tip_diameter: float, center_distance: float, min_clearance: float = 0.0) -> int:
    """Largest number of equally spaced planets whose tip circles keep ``min_clearance`` (mm).

    Contact (zero clearance) counts as interference: ``2 a sin(π/N) − d_a > c_min``.

    Parameters
    ----------
    tip_diameter : float
        Planet tip diameter d_a, mm (> 0).
    center_distance : float
        Radius of the planet axes (the sun–planet centre distance a), mm (> 0).
    min_clearance : float, default 0
        Least gap between neighbouring tip circles, mm.

    Returns
    -------
    int
        N_max ≥ 1 (at most 1000).

    Raises
    ------
    GeometryError
        ``tip_diameter`` or ``center_distance`` ≤ 0.

    Examples
    --------
    Drivetrain Hub, *Planetary Gears*, standard example: d_a ≈ d_w2 = 34.667 mm at
    a = 34.667 mm gives "Number of planets, max = 5":

    >>> max_planets(104 / 3, 104 / 3)
    5

    References
    ----------
    SDP/SI D785, eq. (13-10) d_ab < 2 a_x sin θ; Drivetrain Hub l = 2a sin(π/N) > d_a2.
    """
    tip_diameter = finite_number(tip_diameter, "max_planets", "tip_diameter", minimum=0.0, above=True, unit="mm")
    center_distance = finite_number(center_distance, "max_planets", "center_distance", minimum=0.0, above=True,
                                    unit="mm")
    min_clearance = finite_number(min_clearance, "max_planets", "min_clearance", unit="mm")
    n = 1
    while n < 1000 and 2 * center_distance * math.sin(math.pi / (n + 1)) - tip_diameter - min_clearance > _EPS_MM:
        n += 1
    return n


def _planet_circles(geometry: SetGeometry, angles: Sequence[float]) -> list[tuple[int, int, float, float, float]]:
    """(body, plane, x, y, tip radius) of every planet gear for carrier angles in degrees."""
    circles = []
    g = geometry.gears
    names = geometry.planet_gear_names
    if geometry.kind == "double":
        a1, a12, a2 = (m.center_distance for m in geometry.meshes)
        cos_g = (a1 * a1 + a2 * a2 - a12 * a12) / (2 * a1 * a2)
        gamma = math.acos(max(-1.0, min(1.0, cos_g)))
    for body, theta in enumerate(angles):
        t = math.radians(theta)
        if geometry.kind == "double":
            circles.append((body, 0, a1 * math.cos(t), a1 * math.sin(t), g[names[0]].tip_diameter / 2))
            circles.append((body, 0, a2 * math.cos(t + gamma), a2 * math.sin(t + gamma), g[names[1]].tip_diameter / 2))
        else:
            a = geometry.carrier_radius
            for plane, name in enumerate(names):
                circles.append((body, plane, a * math.cos(t), a * math.sin(t), g[name].tip_diameter / 2))
    return circles


def _min_clearance(geometry: SetGeometry, angles: Sequence[float]) -> float:
    circles = _planet_circles(geometry, angles)
    best = math.inf
    for i, (b1, p1, x1, y1, r1) in enumerate(circles):
        for b2, p2, x2, y2, r2 in circles[i + 1:]:
            if b1 != b2 and p1 == p2:
                best = min(best, math.hypot(x2 - x1, y2 - y1) - r1 - r2)
    if geometry.kind == "double":
        g, names = geometry.gears, geometry.planet_gear_names
        a1, _, a2 = (m.center_distance for m in geometry.meshes)
        best = min(best, a2 - g[names[1]].tip_diameter / 2 - g["sun"].tip_diameter / 2)
        best = min(best, g["ring"].tip_diameter / 2 - a1 - g[names[0]].tip_diameter / 2)
    return best


def check_neighbours(
    geometry: SetGeometry, planets: int, angles: Sequence[float] | None = None, min_clearance: float = 0.0
) -> NeighbourCheck:
    """Neighbour condition: planet tip circles keep at least ``min_clearance`` mm.

    Parameters
    ----------
    geometry : SetGeometry
    planets : int
    angles : sequence of float, optional
        Carrier angles of the planets in degrees (default: equally spaced).
    min_clearance : float, default 0
        Required clearance between tip circles, mm (contact always fails).

    References
    ----------
    SDP/SI D785, eqs. (13-9) z_b + 2 < (z_a + z_b) sin(180°/N) and (13-10).
    """
    if isinstance(planets, bool) or not isinstance(planets, int) or planets < 1:
        raise GeometryError(f"check_neighbours: planets must be a whole number >= 1, got {planets!r}.")
    if isinstance(min_clearance, bool) or not isinstance(min_clearance, (int, float)) \
            or not math.isfinite(min_clearance) or min_clearance < 0:
        raise GeometryError(f"check_neighbours: min_clearance must be a finite number of mm >= 0, got {min_clearance!r}.")
    if angles is None:
        angles = [360.0 * i / planets for i in range(planets)]
    elif len(angles) != planets:
        raise GeometryError(f"check_neighbours: {planets} planets need {planets} angles, got {len(angles)}.")
    clearance = _min_clearance(geometry, angles)
    if not math.isfinite(clearance):  # one planet: no neighbour to clear
        n_max = 1
        while n_max < 200 and _min_clearance(geometry, [360.0 * i / (n_max + 1) for i in range(n_max + 1)]) \
                - min_clearance > _EPS_MM:
            n_max += 1
        message = f"one planet: no neighbour to clear; at most {n_max} fit"
        return NeighbourCheck("neighbours", True, message, "error", planets, clearance, min_clearance, n_max)
    n_max = 1
    while n_max < 200 and _min_clearance(geometry, [360.0 * i / (n_max + 1) for i in range(n_max + 1)]) - min_clearance > _EPS_MM:
        n_max += 1
    passed = clearance - min_clearance > _EPS_MM
    if passed:
        message = (
            f"{planets} planets fit: smallest tip clearance {clearance:.3f} mm "
            f"(required > {min_clearance:g} mm); at most {n_max} fit"
        )
    else:
        how = f"tip circles overlap by {-clearance:.3f} mm" if clearance < 0 else (
            f"tip clearance {clearance:.3f} mm is not more than the required {min_clearance:g} mm")
        message = f"{planets} planets do not fit: {how}; at most {n_max} fit (use fewer planets or smaller planets)"
    return NeighbourCheck("neighbours", passed, message, "error", planets, clearance, min_clearance, n_max)


# ---------------------------------------------------------------------- undercut
def _interference_margins(mesh: MeshGeometry) -> tuple[float, float, float]:
    """(involute, trochoid, trimming) margins of an internal mesh, rad or ratio; ≥ 0 is free."""
    p, ring = mesh.gear1, mesh.gear2
    z1, z2 = p.teeth, ring.teeth
    ra1, ra2 = p.tip_diameter / 2, ring.tip_diameter / 2
    rb1, rb2 = p.base_diameter / 2, ring.base_diameter / 2
    a, aw = mesh.center_distance, mesh.alpha_wt
    if ra2 <= rb2:
        return (-math.inf, -math.inf, -math.inf)
    aa1, aa2 = math.acos(rb1 / ra1), math.acos(rb2 / ra2)
    involute = z1 / z2 - (1 - math.tan(aa2) / math.tan(aw))
    c1 = (ra2 * ra2 - ra1 * ra1 - a * a) / (2 * a * ra1)
    c2 = (a * a + ra2 * ra2 - ra1 * ra1) / (2 * a * ra2)
    if abs(c1) <= 1 and abs(c2) <= 1:
        th1 = math.acos(c1) + inv(aa1) - inv(aw)
        th2 = math.acos(c2)
        trochoid = th1 * z1 / z2 + inv(aw) - inv(aa2) - th2
    else:
        trochoid = -math.inf  # tip circles do not intersect as the formula assumes
    s1 = (1 - (math.cos(aa1) / math.cos(aa2)) ** 2) / (1 - (z1 / z2) ** 2)
    s2 = ((math.cos(aa2) / math.cos(aa1)) ** 2 - 1) / ((z2 / z1) ** 2 - 1)
    if 0 <= s1 <= 1 and 0 <= s2 <= 1:
        t1, t2 = math.asin(math.sqrt(s1)), math.asin(math.sqrt(s2))
        trimming = t1 + inv(aa1) - inv(aw) - (z2 / z1) * (t2 + inv(aa2) - inv(aw))
    else:
        trimming = math.inf if s2 < 0 else -math.inf
    return involute, trochoid, trimming


#: What each kind of internal-gear interference means (SDP/SI D785 section 5.2).
_WHY_INTERFERENCE = {
    "involute": "the ring's tips reach inside the planet's base circle, too few planet teeth for this ring",
    "trochoid": "the planet's tips touch the ring's tips as they leave the mesh, z_ring - z_planet too small",
    "trimming": "the planet cannot be moved in radially to assemble, z_ring - z_planet too small",
}


def check_interference(geometry: SetGeometry) -> tuple[InterferenceCheck, ...]:
    """Involute, trochoid and trimming interference of each internal mesh (warnings).

    References
    ----------
    SDP/SI D785 section 5.2 (KHK): involute z1/z2 ≥ 1 − tan α_a2/tan α_w;
    trochoid θ1 z1/z2 + inv α_w − inv α_a2 ≥ θ2; trimming
    θ1 + inv α_a1 − inv α_w ≥ (z2/z1)(θ2 + inv α_a2 − inv α_w).
    """
    out = []
    for mesh in geometry.meshes:
        if not mesh.internal:
            continue
        inv_m, tro_m, trim_m = _interference_margins(mesh)
        bad = [name for name, m in (("involute", inv_m), ("trochoid", tro_m), ("trimming", trim_m)) if m < 0]
        z1, z2 = mesh.gear1.teeth, mesh.gear2.teeth
        ring = geometry.gear_label(next(g for g in geometry.mesh_gears(mesh) if geometry.gears[g].internal))
        if not bad:
            message = f"{mesh.name}: no involute, trochoid or trimming interference (z2 - z1 = {z2 - z1})"
        else:
            fixes = ["more planet teeth"] if "involute" in bad else []
            fixes += ["increase z_ring - z_planet"] if {"trochoid", "trimming"} & set(bad) else []
            message = (
                f"{mesh.name}: {', '.join(bad)} interference (margins: involute {inv_m:+.4f}, trochoid "
                f"{tro_m:+.4f} rad, trimming {trim_m:+.4f} rad); {'; '.join(_WHY_INTERFERENCE[b] for b in bad)} "
                f"(planet {z1}, ring {z2} teeth): {', '.join(fixes)}, enlarge the ring's tip circle (x_{ring} more "
                f"negative in the ISO 21771 sign) or shorten the ring's addendum"
            )
        out.append(InterferenceCheck("interference", not bad, message, "warning", mesh.name, inv_m, tro_m, trim_m))
    return tuple(out)


def check_fitting(
    geometry: SetGeometry,
    planets: int | None = None,
    *,
    allow_unequal: bool = False,
    min_clearance: float = 0.0,
    undercut: Literal["theoretical", "practical"] = "theoretical",
    tolerance: float | None = None,
) -> FittingReport:
    """Run every fitting condition (number of planets from the set unless given).

    Parameters
    ----------
    geometry : SetGeometry
        The set's gears (:meth:`SetGeometry.create`).
    planets : int, optional
        Number of planets; default the set's.
    allow_unequal : bool, default False
        Accept unequal planet spacing where equal spacing cannot be assembled.
    min_clearance : float, default 0
        Smallest tip clearance between neighbouring planets, mm.
    undercut : {"theoretical", "practical"}
        Undercut limit z_min = 2/sin²α (theoretical) or 5/6 of it (practical).
    tolerance : float, optional
        Allowed difference of the centre distances for coaxiality, mm; default the
        geometry's ``center_distance_tolerance`` or :func:`coaxiality_tolerance`
        (scaled with the module and the digits of the shifts).

    Returns
    -------
    FittingReport
        Every check with its numbers, ``passed``, ``table()``, ``raise_if_failed()``.

    Raises
    ------
    GeometryError
        ``geometry`` is no SetGeometry, or ``planets`` is no whole number ≥ 1.

    References
    ----------
    SDP/SI, *Elements of Metric Gear Technology* (D785), section 13 (coaxial, assembly and
    neighbouring conditions); ISO 21771 (undercut, interference).

    Examples
    --------
    >>> from epicyclic import PlanetarySet
    >>> p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78, planets=4)
    >>> report = check_fitting(SetGeometry.create(p, module=2))
    >>> report.passed, [c.condition for c in report.checks][:3]
    (True, ['coaxiality', 'assembly', 'neighbours'])
    """
    expect_type(geometry, SetGeometry, "check_fitting", "geometry", "make one with SetGeometry.create(set, module=...)")
    n = geometry.planetary_set.planets if planets is None else planets
    assembly = check_assembly(geometry, n, allow_unequal=allow_unequal)
    angles = assembly.angles if (assembly.passed and not assembly.equally_spaced) else None
    checks: list[Check] = [
        check_coaxiality(geometry, tolerance),
        assembly,
        check_neighbours(geometry, n, angles, min_clearance),
        *check_undercut(geometry, undercut),
        *check_interference(geometry),
        *check_contact_ratio(geometry.meshes, geometry.mesh_face_widths()),
        *check_tip_thickness(geometry.gears, geometry.gear_label),
        *check_backlash(geometry.meshes),
    ]
    return FittingReport(geometry, tuple(checks))
