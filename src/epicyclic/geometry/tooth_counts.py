"""Fitting conditions that tooth counts alone decide: coaxiality of standard gears and assembly.

A set without a ``geometry`` table still has its tooth counts; two conditions
need nothing more:

coaxiality of standard gears
    ``z_ring − z_sun − 2 z_planet = 0`` (simple; the stepped and double forms in
    :func:`~epicyclic.model.teeth.coaxial_mismatch`).  A set that misses it by a
    few teeth is built with profile shift: the check is then a *warning* that says
    how far the counts are off and that profile shift must close it; the
    geometry's working centre distances decide (:func:`~epicyclic.geometry.check_coaxiality`).
assembly of equally spaced planets
    ``(z_sun + z_ring)/N`` whole for a simple set (SDP/SI D785 eqs. 13-7, 13-8;
    :func:`~epicyclic.geometry.check_assembly`), independent of module and shifts.

References
----------
SDP/SI, *Elements of Metric Gear Technology* (D785), section 13, eqs. (13-5)–(13-8).
"""

from __future__ import annotations

from types import MappingProxyType

from ..model.planetary import PlanetarySet
from ..model.teeth import coaxial_mismatch, coaxial_note
from .checks import Check, CoaxialityCheck, FittingReport
from .errors import GeometryError, expect_type
from .fitting import check_assembly

__all__ = ["check_tooth_counts"]


def check_tooth_counts(planetary_set: PlanetarySet, planets: int | None = None, *, allow_unequal: bool = False,
                       module_ratio: float = 1.0) -> FittingReport:
    """Coaxiality of standard gears (a warning where profile shift must close it) and assembly, from tooth counts.

    Parameters
    ----------
    planetary_set : PlanetarySet
        A set built from tooth counts.
    planets : int, optional
        Number of planets (default the set's).
    allow_unequal : bool, default False
        Accept unequal planet spacing where equal spacing cannot be assembled.
    module_ratio : float, default 1.0
        m2/m1 of a stepped set.

    Returns
    -------
    FittingReport
        ``geometry`` None, ``name`` the set's; the checks ``coaxiality`` and ``assembly``.

    Raises
    ------
    GeometryError
        The set has no tooth counts.

    Examples
    --------
    A simple set whose counts miss z_ring = z_sun + 2 z_planet by three teeth:

    >>> p = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=20, z_planet=37, z_ring=97, planets=3)
    >>> report = check_tooth_counts(p)
    >>> report.passed, [c.severity for c in report.checks if not c.passed]
    (True, ['warning'])

    References
    ----------
    SDP/SI D785, eqs. (13-5)–(13-8).
    """
    expect_type(planetary_set, PlanetarySet, "check_tooth_counts", "planetary_set", "give a PlanetarySet")
    teeth = planetary_set.teeth
    if teeth is None:
        raise GeometryError(f"check_tooth_counts: set {planetary_set.name!r} has no tooth counts (built from a ratio).")
    mismatch = coaxial_mismatch(teeth, module_ratio)
    note = coaxial_note(teeth, module_ratio)
    if note is None:
        message = "standard gears are coaxial (tooth counts add up); no profile shift needed for coaxiality"
    else:
        message = note
    coaxial = CoaxialityCheck("coaxiality", note is None, message, "warning", MappingProxyType({}), mismatch / 2.0,
                              0.0, MappingProxyType({}))
    n = planetary_set.planets if planets is None else planets
    checks: tuple[Check, ...] = (coaxial, check_assembly(teeth, n, allow_unequal=allow_unequal))
    return FittingReport(None, checks, planetary_set.name)
