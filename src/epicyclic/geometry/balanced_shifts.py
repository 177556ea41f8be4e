"""Profile shifts that make a simple set coaxial, buildable and balanced in specific sliding.

For a simple set (sun z_s, planet z_p, ring z_r) both meshes must run at one working centre
distance a_w.  Per unit module a_w fixes the two shift sums (ISO 21771:2007,
inv α_wt = inv α_t + 2 tan α_n Σx / z_Σ):

.. math:: x_s + x_p = \\Sigma_{ext}(a_w), \\qquad -x_r - x_p = \\Sigma_{int}(a_w)

(the ring's x_r in the ISO 21771 sign, −x_r in the KHK sign of the internal pair's sum), leaving
a_w and the planet's x_p free.
:func:`balanced_shifts` searches a stated grid of the two — a_w/m_n over the span of the two
meshes' reference centre distances (widened by :data:`SPAN` on each side), x_p over
:data:`PLANET_SHIFTS` — and keeps, among the sets that pass every error-level fitting condition
of :func:`~epicyclic.geometry.check_fitting` (coaxiality, assembly, neighbours, undercut, tip
thickness, ε_α; the one path ``epicyclic fit`` uses), the one whose sun–planet mesh has equal
specific sliding at the roots of sun and planet (Niemann & Winter; ISO/TR 4467:1982) — to
:data:`BALANCE_STEP`, and among those the lowest sliding; sets whose ε_α lies below
:data:`PREFERRED_CONTACT_RATIO` only where no other passes:

.. math:: \\zeta_1 = 1 - \\frac{\\rho_2}{\\rho_1}\\frac{z_1}{z_2}\\;(\\text{root of gear 1}), \\qquad
          \\zeta_2 = 1 - \\frac{\\rho_1}{\\rho_2}\\frac{z_2}{z_1}\\;(\\text{root of gear 2})

with ρ the involutes' radii of curvature where the mating tip meets the root
(ρ = √(r_a² − r_b²) at a tip, the rest of T_1T_2 = a_w sin α_wt at the other flank).  The
geometry scales with the module, so the shifts hold for every module.

References
----------
ISO 21771:2007, 5.2 (inv α_wt, a_w) and 7 (specific sliding); ISO/TR 4467:1982 (balanced
specific sliding); Niemann, G.; Winter, H.: Maschinenelemente II, 2nd ed., Springer 1989, 21.2;
SDP/SI D785, section 13 (coaxial planetary sets).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import GeometryError
from .fitting import check_fitting
from .involute import profile_shift_sum
from .set_geometry import SetGeometry

__all__ = ["PLANET_SHIFTS", "SPAN", "ShiftChoice", "balanced_shifts", "root_sliding"]

#: The grid of the planet's profile shift x_p searched (ISO 21771 sign).
PLANET_SHIFTS = tuple(round(-0.6 + 0.05 * k, 2) for k in range(37))  # -0.6 ... +1.2
#: a_w / m_n is searched from the smaller to the larger reference centre distance, widened by this (per module).
SPAN = 0.5
#: Points of the a_w / m_n grid.
CENTER_STEPS = 41
#: Sliding differences within one step count as balanced alike; among them the lowest sliding wins.
BALANCE_STEP = 0.05
#: Sets with a smaller ε_α (still >= 1, the hard condition) are taken only where no other passes: a design
#: choice of this search (smooth running), not a limit of a standard.
PREFERRED_CONTACT_RATIO = 1.2


@dataclass(frozen=True)
class ShiftChoice:
    """The profile shifts found, with the sliding they balance and the bound searched.

    Attributes
    ----------
    x_sun, x_planet, x_ring : float
        Profile-shift coefficients (the ring's in the ISO 21771 sign).
    center_distance : float
        a_w / m_n, the working centre distance per unit module.
    sliding : (float, float)
        Specific sliding at the roots of sun and planet in the sun–planet mesh.
    tried, passed : int
        Candidates of the grid, and how many pass every fitting condition.
    bound : str
        The grid searched, in words.
    """

    x_sun: float
    x_planet: float
    x_ring: float
    center_distance: float
    sliding: tuple[float, float]
    tried: int
    passed: int
    bound: str

    def to_dict(self) -> dict:
        """Plain data (shifts, a_w/m_n, sliding, counts, bound)."""
        return {"x_sun": self.x_sun, "x_planet": self.x_planet, "x_ring": self.x_ring,
                "center_distance_per_module": self.center_distance, "sliding": list(self.sliding),
                "tried": self.tried, "passed": self.passed, "bound": self.bound}


def root_sliding(mesh) -> tuple[float, float]:
    """(ζ at the root of gear 1, ζ at the root of gear 2) of an external mesh (−inf: contact below a base circle).

    Parameters
    ----------
    mesh : MeshGeometry

    Returns
    -------
    tuple of float

    References
    ----------
    ISO 21771:2007, 7; Niemann & Winter, Maschinenelemente II (1989), 21.2.
    """
    g1, g2 = mesh.gear1, mesh.gear2
    rb1, rb2 = g1.base_diameter / 2.0, g2.base_diameter / 2.0
    rho_a1 = math.sqrt(max((g1.tip_diameter / 2.0) ** 2 - rb1 ** 2, 0.0))
    rho_a2 = math.sqrt(max((g2.tip_diameter / 2.0) ** 2 - rb2 ** 2, 0.0))
    length = mesh.center_distance * math.sin(mesh.alpha_wt)
    rho_1a, rho_2e = length - rho_a2, length - rho_a1
    if rho_1a <= 0.0 or rho_2e <= 0.0:
        return -math.inf, -math.inf
    z1, z2 = g1.teeth, g2.teeth
    return 1.0 - rho_a2 / rho_1a * z1 / z2, 1.0 - rho_a1 / rho_2e * z2 / z1


def balanced_shifts(planetary_set, *, pressure_angle: float = 20.0, helix_angle: float = 0.0,
                    addendum: float = 1.0, dedendum: float = 1.25) -> ShiftChoice:
    """Profile shifts of a simple set: coaxial, every fitting condition met, specific sliding balanced.

    Parameters
    ----------
    planetary_set : PlanetarySet
        A simple set with tooth counts.
    pressure_angle, helix_angle : float
        α_n and β of the basic rack, degrees.
    addendum, dedendum : float
        h_a* and h_f* of the basic rack.

    Returns
    -------
    ShiftChoice

    Raises
    ------
    GeometryError
        Not a simple set, or no point of the grid passes the fitting conditions (the message gives
        the grid and the conditions that failed most often).

    References
    ----------
    ISO 21771:2007; ISO/TR 4467:1982; SDP/SI D785, section 13.

    Examples
    --------
    >>> from epicyclic import PlanetarySet
    >>> p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=19, z_planet=17, z_ring=56, planets=3)
    >>> c = balanced_shifts(p)
    >>> abs(c.sliding[0] - c.sliding[1]) < 0.5, c.passed > 0
    (True, True)
    """
    teeth = getattr(planetary_set, "teeth", None)
    if teeth is None or teeth.kind != "simple":
        raise GeometryError(f"balanced_shifts: {getattr(planetary_set, 'name', planetary_set)!r} is not a simple "
                            "set with tooth counts (give its profile shifts).")
    zs, zp, zr = teeth.sun, teeth.planet[0], teeth.ring
    beta = math.radians(helix_angle)
    alpha = math.radians(pressure_angle)
    a_ext, a_int = (zs + zp) / (2.0 * math.cos(beta)), (zr - zp) / (2.0 * math.cos(beta))
    low, high = min(a_ext, a_int) - SPAN, max(a_ext, a_int) + SPAN
    centers = np.linspace(low, high, CENTER_STEPS)
    bound = (f"a_w/m_n {low:.4g} ... {high:.4g} ({CENTER_STEPS} points) x x_planet {PLANET_SHIFTS[0]:+g} ... "
             f"{PLANET_SHIFTS[-1]:+g} (step 0.05)")
    best, passed, tried = None, 0, 0
    failures: dict[str, int] = {}
    for a_w in centers:
        try:
            s_ext = profile_shift_sum(float(a_w), zs + zp, 1.0, alpha, beta)
            s_int = profile_shift_sum(float(a_w), zr - zp, 1.0, alpha, beta)
        except ValueError:
            continue
        for x_p in PLANET_SHIFTS:
            tried += 1
            x_s, x_r = s_ext - x_p, -(s_int + x_p)  # profile_shift_sum: x_ring - x_planet in the KHK sign
            try:
                shape = SetGeometry.create(planetary_set, 1.0, pressure_angle=pressure_angle,
                                           helix_angle=helix_angle, addendum=addendum, dedendum=dedendum,
                                           x_sun=x_s, x_planet=x_p, x_ring=x_r)
            except GeometryError:
                continue
            report = check_fitting(shape)
            if not report.passed:
                for c in report.failures:
                    failures[c.condition] = failures.get(c.condition, 0) + 1
                continue
            z1, z2 = root_sliding(shape.sun_mesh)
            if not (math.isfinite(z1) and math.isfinite(z2)):  # contact below a base circle: not a working mesh
                failures["contact below a base circle"] = failures.get("contact below a base circle", 0) + 1
                continue
            passed += 1
            eps = min(m.contact_ratio for m in shape.meshes)
            key = (eps < PREFERRED_CONTACT_RATIO, round(abs(z1 - z2) / BALANCE_STEP), max(abs(z1), abs(z2)))
            if best is None or key < best[0]:
                best = (key, x_s, x_p, x_r, float(a_w), (z1, z2))
    if best is None:
        most = ", ".join(f"{k} ({n})" for k, n in sorted(failures.items(), key=lambda kv: -kv[1]))
        raise GeometryError(f"balanced_shifts: no profile shifts of the grid {bound} give a set "
                            f"{planetary_set.name!r} ({zs}/{zp}/{zr}) that can be built; failing: {most or 'none'}.")
    _, x_s, x_p, x_r, a_w, sliding = best
    return ShiftChoice(round(x_s, 6), x_p, round(x_r, 6), round(a_w, 6), (round(sliding[0], 6), round(sliding[1], 6)),
                       tried, passed, bound)
