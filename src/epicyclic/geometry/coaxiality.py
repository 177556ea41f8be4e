"""Coaxiality of a planetary set: its meshes' working centre distances put the planet axes on one circle.

The working centre distances of the shifted meshes decide, not a tooth-count
rule: a set whose counts miss z_ring = z_sun + 2 z_planet by a few teeth is
coaxial when its profile shifts make both meshes run at one centre distance.

Tolerance
---------
A built design prints its shifts to a few decimals; the centre distances they give
then differ by the effect of that rounding, which grows with the module.  The
default tolerance is therefore

.. math:: \\Delta a_{tol} = \\max\\left(1\\,\\mu m,\\; \\delta \\sum_{\\text{gears}}
          \\left|\\frac{\\partial a_w}{\\partial x}\\right|\\right),\\qquad
          \\frac{\\partial a_w}{\\partial \\Sigma x} = \\frac{2 a_w \\tan\\alpha_n}{z_\\Sigma \\tan\\alpha_{wt}}

with δ = ½·10⁻ᵈ, d the decimals the shifts are written with (at least 4), summed
over the two gears of each of the two meshes.  The derivative follows from
inv α_wt = inv α_t + 2 tan α_n Σx/z_Σ and a_w = a cos α_t / cos α_wt.  A design
can instead carry its housing's centre-distance allowance: a number of mm or an
ISO 286 js field (DIN 3964, :mod:`~epicyclic.geometry.tolerances`).  A failing
check proposes the ring's profile shift rounded to the digits the user gave
(more only where those digits cannot reach the tolerance).

References
----------
SDP/SI D785, eqs. (13-5), (13-6) (coaxial condition); ISO 21771:2007 (inv α_wt, a_w);
DIN 3964:1980 and ISO 286-1:2010 (centre-distance allowances).
"""

from __future__ import annotations

import math
from dataclasses import replace
from types import MappingProxyType

from .checks import CoaxialityCheck
from .errors import GeometryError
from .gear import MeshGeometry
from .involute import profile_shift_sum
from .set_geometry import SetGeometry
from .tolerances import center_distance_allowance

__all__ = ["check_coaxiality", "coaxiality_tolerance", "shift_decimals", "ABSOLUTE_TOLERANCE_MM"]

#: Smallest coaxiality tolerance, mm (1 µm).
ABSOLUTE_TOLERANCE_MM = 1e-3


def shift_decimals(values) -> int:
    """Decimals the profile shifts are written with (the most of any non-zero one), at least 4.

    >>> shift_decimals([0.438, 0.0426, 0.0]), shift_decimals([0.12345])
    (4, 5)
    """
    most = 4
    for x in values:
        if isinstance(x, float) and x != 0.0 and math.isfinite(x):
            text = repr(x)
            if "e" in text:
                most = max(most, -int(text.split("e")[1]) + len(text.split("e")[0].split(".")[-1]))
            elif "." in text:
                most = max(most, len(text.split(".")[1]))
    return min(most, 12)


def _sensitivity(mesh: MeshGeometry) -> float:
    """|∂a_w/∂Σx| = 2 a_w tan α_n / (z_Σ tan α_wt), mm per unit of profile-shift sum."""
    return 2.0 * mesh.center_distance * math.tan(mesh.rack.alpha_n) / (mesh._z_sum * math.tan(mesh.alpha_wt))


def _given_shifts(geometry: SetGeometry) -> list[float]:
    return [geometry.x_sun, geometry.x_ring, *geometry.x_planet]  # type: ignore[misc]


def coaxiality_tolerance(geometry: SetGeometry) -> tuple[float, str]:
    """The coaxiality tolerance of a set, mm, and a phrase saying where it comes from.

    The geometry's ``center_distance_tolerance`` where given (mm, or a js field of the
    sun mesh's centre distance); else the effect of the shifts' last printed digit,
    at least 1 µm (module docstring).

    Parameters
    ----------
    geometry : SetGeometry
        The set.

    Returns
    -------
    tuple of (float, str)
        (tolerance in mm, basis).

    Examples
    --------
    >>> from epicyclic import PlanetarySet
    >>> p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=21, z_planet=43, z_ring=108)
    >>> tol, why = coaxiality_tolerance(SetGeometry.create(p, module=20, x_sun=0.438, x_planet=0.0426))
    >>> round(tol, 5), why
    (0.00384, 'the effect of shifts written to 4 decimals at m_n = 20 mm')

    References
    ----------
    ISO 21771:2007 (inv α_wt, a_w); DIN 3964:1980; ISO 286-1:2010.
    """
    given = getattr(geometry, "center_distance_tolerance", None)
    if isinstance(given, str):
        a = geometry.sun_mesh.center_distance
        return center_distance_allowance(given, a), f"DIN 3964 field {given} of a = {a:.1f} mm"
    if given is not None:
        return float(given), "the given centre-distance tolerance"
    if geometry.kind == "double":
        return ABSOLUTE_TOLERANCE_MM, "the 1 µm floor"
    decimals = shift_decimals(_given_shifts(geometry))
    delta = 0.5 * 10.0 ** -decimals
    effect = delta * 2.0 * (_sensitivity(geometry.sun_mesh) + _sensitivity(geometry.ring_mesh))
    if effect <= ABSOLUTE_TOLERANCE_MM:
        return ABSOLUTE_TOLERANCE_MM, "the 1 µm floor"
    return effect, f"the effect of shifts written to {decimals} decimals at m_n = {geometry.rack.module:g} mm"


def check_coaxiality(geometry: SetGeometry, tolerance: float | None = None) -> CoaxialityCheck:
    """Coaxiality of the set: both meshes' planet axes on one circle (centre distances in mm).

    A set with one planet per mesh chain (simple, stepped, two suns/rings) is coaxial
    when the sun-side and ring-side meshes run at the same operating centre distance;
    a double-planet set when the three centre distances close a triangle.  A failing
    check suggests the ring's profile shift that would make it coaxial, rounded to the
    digits the shifts were given with.

    Parameters
    ----------
    geometry : SetGeometry
        The set's gears and meshes.
    tolerance : float, optional
        Largest accepted difference of the centre distances, mm; default
        :func:`coaxiality_tolerance`.

    Returns
    -------
    CoaxialityCheck
        ``passed``, a message with the numbers and the fix, the centre distances
        (mm) and the suggested ``x_ring`` (in the convention the shifts were given in).

    References
    ----------
    SDP/SI D785, eqs. (13-5) z_c = z_a + 2 z_b and (13-6) a_x1 = a_x2.
    """
    basis = "given"
    if tolerance is None:
        tolerance, basis = coaxiality_tolerance(geometry)
    meshes = {m.name: m.center_distance for m in geometry.meshes}
    if geometry.kind == "double":
        a1, a12, a2 = (m.center_distance for m in geometry.meshes)
        low, high = abs(a1 - a2), a1 + a2
        diff = max(0.0, low - a12, a12 - high)
        passed = diff == 0.0 and a12 > low + tolerance and a12 < high - tolerance
        if passed:
            gamma = math.degrees(math.acos((a1 * a1 + a2 * a2 - a12 * a12) / (2 * a1 * a2)))
            message = (
                f"planet1 axis at r = {a1:.3f} mm, planet2 axis at r = {a2:.3f} mm, {gamma:.2f}° apart; "
                f"the planet1-planet2 centre distance {a12:.3f} mm closes the triangle"
            )
        else:
            message = (
                f"double planets cannot be placed: planet1-planet2 centre distance {a12:.3f} mm must lie "
                f"strictly between |a1 - a2| = {low:.3f} mm and a1 + a2 = {high:.3f} mm; change the planet "
                "tooth counts or the ring/sun tooth counts"
            )
        return CoaxialityCheck("coaxiality", passed, message, "error", MappingProxyType(meshes), diff, tolerance,
                               MappingProxyType({}))
    sun_mesh, ring_mesh = geometry.sun_mesh, geometry.ring_mesh
    a_s, a_r = sun_mesh.center_distance, ring_mesh.center_distance
    diff = a_r - a_s
    suggestion: dict[str, float] = {}
    within = f"within {tolerance * 1000:.2f} µm ({basis})"
    if abs(diff) <= tolerance:
        message = (f"{sun_mesh.name} and {ring_mesh.name} both run at a_w = {a_s:.4f} mm (difference {diff:+.4f} mm, "
                   f"{within})")
        return CoaxialityCheck("coaxiality", True, message, "error", MappingProxyType(meshes), diff, tolerance,
                               MappingProxyType(suggestion))
    decimals = shift_decimals(_given_shifts(geometry))
    proposed = _ring_shift(geometry, a_s, tolerance, decimals)
    if proposed is not None:
        suggestion["x_ring"] = proposed
    ring_label = geometry.gear_label("ring")
    sign = f", {geometry.internal_shift_convention.upper()} sign" if ring_mesh.gear2.internal else ""
    hint = (f"set x_{ring_label} = {suggestion['x_ring']:.{decimals}f} (other shifts kept{sign}; it meets the "
            f"tolerance at the digits given)" if suggestion else "change the tooth counts")
    if geometry.kind == "simple":
        teeth = geometry.planetary_set.teeth
        zs, zp, zr = teeth.sun, teeth.planet[0], teeth.ring  # type: ignore[union-attr]
        hint += f"; for standard gears z_ring = z_sun + 2 z_planet = {zs + 2 * zp} (given {zr})"
    message = (
        f"not coaxial: {sun_mesh.name} a_w = {a_s:.4f} mm but {ring_mesh.name} a_w = {a_r:.4f} mm "
        f"(differ by {abs(diff):.4f} mm, not {within}); {hint}"
    )
    return CoaxialityCheck("coaxiality", False, message, "error", MappingProxyType(meshes), diff, tolerance,
                           MappingProxyType(suggestion))


def _ring_shift(geometry: SetGeometry, target: float, tolerance: float, decimals: int) -> float | None:
    """The ring's shift (as the user writes it) that puts the ring mesh at ``target``, rounded to ``decimals``.

    More decimals only where the rounded value misses the tolerance; None where no shift reaches it.
    """
    ring_mesh = geometry.ring_mesh
    planet, ring = ring_mesh.gear1, ring_mesh.gear2
    rack = ring_mesh.rack
    z_sum = ring.teeth - planet.teeth if ring.internal else ring.teeth + planet.teeth
    try:
        needed = profile_shift_sum(target, z_sum, rack.module, rack.alpha_n, rack.beta)
    except ValueError:
        return None
    # ISO sign of an internal ring: x2 = −(needed + x1) (needed is the KHK-form x2 − x1)
    iso = -(needed + planet.profile_shift) if ring.internal else needed - planet.profile_shift
    khk = ring.internal and geometry.internal_shift_convention == "khk"
    for digits in range(decimals, 13):
        x_iso = round(iso, digits)
        try:
            mesh = MeshGeometry(planet, replace(ring, profile_shift=x_iso), ring_mesh.name)
        except GeometryError:  # a shift out of range gives no suggestion
            return None
        if abs(mesh.center_distance - target) <= tolerance:
            return -x_iso if khk else x_iso
    return -iso if khk else iso
