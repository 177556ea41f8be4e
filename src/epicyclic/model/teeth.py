"""Tooth counts of a planetary set and the checks that make them a set.

Every arrangement of two central gears and planets is one of three kinds:

* ``simple``: sun (external) – planet – ring (internal);
* ``double``: sun – planet 1 – planet 2 – ring (a plus set);
* ``stepped``: a planet with two gears on one shaft; gear b meshes the first
  central gear, gear c the second.  Each central gear may be external (a sun)
  or internal (a ring): sun + ring (the usual stepped set), two suns
  (Brandenberger's a/b·c/d) or two rings (the Wolfrom or 3K set).

The sign of i0 is the product of the mesh signs (an external mesh reverses the
direction of rotation relative to the carrier, an internal mesh keeps it).

Coaxiality: the planet axes of both meshes lie on one circle.  With the
modules m1 (first mesh) and m2 (second mesh) and standard centre distances
a = m (z_gear ± z_planet)/2 (+ external, − internal central gear), standard
(unshifted) gears need ``m1 (z1 ± z_b) = m2 (z2 ± z_c)``.  Industrial sets often
miss this by a few teeth (``z_ring − z_sun − 2 z_planet = ±3`` and more) and are
made coaxial by profile shift: the working centre distances of the shifted
meshes decide (:func:`~epicyclic.geometry.check_coaxiality`).  Without geometry
the counts are accepted up to :data:`MAX_COAXIAL_MISMATCH_TEETH` (a difference of
the standard centre distances of three modules, more than the centre-distance
modifications y ≈ ±1.5 of two meshes can close) and
:func:`coaxial_mismatch` says how far they are off.

References
----------
Brandenberger 1952, eq. 1 and Bild 1–2 (stepped planets, two suns);
tec-science, "Willis-Gleichung" (i0 = −z_H/z_S);
SDP/SI, *Elements of Metric Gear Technology* (D785), eqs. (13-5), (13-6) (coaxial condition).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from ..errors import ToothCountError
from ..limits import MAX_TEETH, MIN_TEETH

__all__ = ["Teeth", "COAXIAL_TOLERANCE_TEETH", "MAX_COAXIAL_MISMATCH_TEETH", "TWO_CENTRAL_NAMES", "check_teeth",
           "check_stepped", "check_double", "coaxial_mismatch", "coaxial_note"]

#: Largest mismatch |z_ring - z_sun - 2 z_planet| (in teeth of the first mesh's module) accepted from tooth
#: counts alone: the standard centre distances then differ by three modules, which two meshes' centre-distance
#: modifications (|y| up to about 1.5 each) can still close; the geometry's working centre distances decide.
MAX_COAXIAL_MISMATCH_TEETH = 6

#: Former name of :data:`MAX_COAXIAL_MISMATCH_TEETH` (kept for callers of earlier versions).
COAXIAL_TOLERANCE_TEETH = MAX_COAXIAL_MISMATCH_TEETH

#: Names of the gears (and central ports) of a set with two suns or two rings, as its file's
#: ``teeth`` table says them (``kind = "two_rings"`` / ``"two_suns"``), by the solver's names.
TWO_CENTRAL_NAMES = {"sun": "first", "planet_sun": "planet_first", "planet_ring": "planet_second", "ring": "second"}


def check_teeth(value: object, field_name: str, owner: str) -> int:
    """Return ``value`` as int if it is a whole number of teeth in MIN_TEETH … MAX_TEETH, else raise."""
    if isinstance(value, bool) or not isinstance(value, int):
        if isinstance(value, float) and value.is_integer():
            value = int(value)
        else:
            raise ToothCountError(f"{owner}: {field_name} must be a whole number of teeth, got {value!r:.40}.")
    if value < MIN_TEETH:
        raise ToothCountError(
            f"{owner}: {field_name} must be at least {MIN_TEETH} teeth, got {value}."
        )
    if value > MAX_TEETH:
        raise ToothCountError(
            f"{owner}: {field_name} must be at most {MAX_TEETH} teeth, got {value:.4g} (see docs/limits.md)."
        )
    return value


@dataclass(frozen=True)
class Teeth:
    """Tooth counts of a planetary set.

    Parameters
    ----------
    kind : {"simple", "double", "stepped"}
        ``simple``: sun–planet–ring.  ``double``: sun meshes planet 1, planet 1
        meshes planet 2, planet 2 meshes the ring (a plus set).  ``stepped``: a
        planet with two gears on one shaft, the first meshing the first central
        gear (``sun``), the second meshing the second central gear (``ring``).
    sun, ring : int
        Teeth of the first and second central gear.
    planet : tuple of int
        Planet teeth: ``(z_p,)`` for a simple set, ``(z_p1, z_p2)`` otherwise,
        the first meshing the sun.
    ring_internal : bool, default True
        Whether the second central gear is internal (a ring).  Only a stepped
        set may have an external second central gear.
    sun_internal : bool, default False
        Whether the first central gear is internal (a ring, as in the Wolfrom
        set).  Only a stepped set may have an internal first central gear.

    Examples
    --------
    A Wolfrom (3K) set, two rings and a stepped planet: a plus set

    >>> round(Teeth("stepped", 81, 78, (27, 24), sun_internal=True).stationary_ratio, 6)
    1.083333
    """

    kind: Literal["simple", "double", "stepped"]
    sun: int
    ring: int
    planet: tuple[int, ...]
    ring_internal: bool = True
    sun_internal: bool = False

    @property
    def stationary_ratio(self) -> float:
        """i0 from the tooth counts (sign from the meshes).

        >>> Teeth("simple", 30, 78, (24,)).stationary_ratio
        -2.6
        """
        s, r, p = self.sun, self.ring, self.planet
        if self.kind == "simple":
            return -r / s
        if self.kind == "double":
            return r / s
        sign = (1.0 if self.sun_internal else -1.0) * (1.0 if self.ring_internal else -1.0)
        return sign * (r * p[0]) / (s * p[1])

    @property
    def planet_factors(self) -> tuple[float, ...]:
        """Factors k with n_planet - n_carrier = k (n_sun - n_carrier), per planet gear.

        An external mesh with the first central gear reverses the planet's
        relative rotation (k < 0), an internal one keeps it (k > 0).

        References
        ----------
        tec-science, "Willis-Gleichung", Grundgleichung: n_P z_P = n_T (z_P + z_S) - n_S z_S.
        """
        s, p = self.sun, self.planet
        if self.kind == "simple":
            return (-s / p[0],)
        if self.kind == "double":
            return (-s / p[0], s / p[1])
        return ((s if self.sun_internal else -s) / p[0],)  # both steps turn together

    @property
    def arrangement(self) -> str:
        """A word for the arrangement: simple, double, stepped, two suns or two rings."""
        if self.kind != "stepped":
            return self.kind
        if self.sun_internal == self.ring_internal:
            return "two rings" if self.sun_internal else "two suns"
        return "stepped"

    def label(self, name: str) -> str:
        """A gear's or port's name as a user of this arrangement says it.

        A set with two rings or two suns (:attr:`arrangement`) calls its central gears
        ``first`` and ``second`` and its planet gears ``planet_first`` and
        ``planet_second``, the keys of its file's ``teeth`` table; every other set keeps
        the solver's names (``sun``, ``ring``, ``planet``, ...).  The solver itself always
        says ``sun``/``ring``/``carrier``; reports, meshes, forces and plots use this label.

        Parameters
        ----------
        name : str
            The solver's name of a port (``sun``, ``ring``, ``carrier``) or gear
            (``planet_sun``, ``planet_ring``, ...).

        Returns
        -------
        str
            The name in this arrangement; ``name`` itself where nothing differs.

        Examples
        --------
        >>> wolfrom = Teeth("stepped", 81, 78, (27, 24), sun_internal=True)
        >>> [wolfrom.label(p) for p in ("sun", "ring", "carrier", "planet_sun")]
        ['first', 'second', 'carrier', 'planet_first']
        >>> Teeth("simple", 30, 78, (24,)).label("sun")
        'sun'
        """
        if self.arrangement in ("two rings", "two suns"):
            return TWO_CENTRAL_NAMES.get(name, name)
        return name


def _center(z_gear: int, z_planet: int, internal: bool) -> int:
    """Twice the standard centre distance in modules: z_gear ± z_planet."""
    return z_gear - z_planet if internal else z_gear + z_planet


def check_stepped(teeth: Teeth, owner: str, module_ratio: float | None = 1.0, names: tuple[str, ...] = ()) -> None:
    """Raise ToothCountError if a stepped set cannot be built from its tooth counts.

    Parameters
    ----------
    teeth : Teeth
        ``kind == "stepped"``.
    owner : str
        Prefix of messages, e.g. ``"planetary set 'P'"``.
    module_ratio : float or None, default 1.0
        m2/m1, the module of the second central gear's mesh over that of the
        first.  ``None`` skips the coaxiality check (modules unknown).
    names : tuple of str
        Field names of (first central, planet b, planet c, second central) for messages.
    """
    zs, zr = teeth.sun, teeth.ring
    zb, zc = teeth.planet
    ns, nb, nc, nr = names or ("z_sun", "z_planet_sun", "z_planet_ring", "z_ring")
    for internal, z_gear, z_planet, gear_name, planet_name in (
        (teeth.sun_internal, zs, zb, ns, nb), (teeth.ring_internal, zr, zc, nr, nc)
    ):
        if internal and z_gear <= z_planet:
            raise ToothCountError(
                f"{owner}: an internal gear must have more teeth than the planet gear meshing it, "
                f"got {gear_name}={z_gear}, {planet_name}={z_planet}."
            )
    if teeth.sun_internal and teeth.ring_internal and zs * zc == zr * zb:
        raise ToothCountError(
            f"{owner}: with two rings, {ns}·{nc} = {zs}·{zc} equals {nr}·{nb} = {zr}·{zb}, so i0 = 1 and the "
            f"set is locked; change a tooth count (a Wolfrom set needs {ns}/{nb} ≠ {nr}/{nc})."
        )
    if not teeth.sun_internal and not teeth.ring_internal and zs * zc == zr * zb:
        raise ToothCountError(
            f"{owner}: with two suns, {ns}·{nc} = {zs}·{zc} equals {nr}·{nb} = {zr}·{zb}, so i0 = 1 and the "
            "set is locked; change a tooth count."
        )
    if module_ratio is None:
        return
    if isinstance(module_ratio, bool) or not isinstance(module_ratio, (int, float)) \
            or not math.isfinite(module_ratio) or module_ratio <= 0:
        raise ToothCountError(f"{owner}: module_ratio must be a positive number m2/m1, got {module_ratio!r}.")
    first = _center(zs, zb, teeth.sun_internal)
    second = _center(zr, zc, teeth.ring_internal)
    mismatch = first - module_ratio * second
    allowed = MAX_COAXIAL_MISMATCH_TEETH * max(1.0, module_ratio)
    if abs(mismatch) > allowed + 1e-9:
        sign1 = "-" if teeth.sun_internal else "+"
        sign2 = "-" if teeth.ring_internal else "+"
        exact = first / second
        raise ToothCountError(
            f"{owner}: the stepped planet cannot be coaxial: {ns} {sign1} {nb} = {zs} {sign1} {zb} = {first} "
            f"but (m2/m1)·({nr} {sign2} {nc}) = {module_ratio:g}·({zr} {sign2} {zc}) = "
            f"{module_ratio * second:g}, a mismatch of {abs(mismatch):g} teeth (at most {allowed:g} with "
            f"profile shift). Change the tooth counts, or give the module ratio m2/m1 of the two meshes "
            f"(module_ratio = {exact:.6g} makes them coaxial)."
        )


def check_double(teeth: Teeth, owner: str) -> None:
    """Raise ToothCountError if the double planets cannot close their triangle.

    Planet 1's axis lies at a1 = (z_sun + z_p1)/2, planet 2's at a2 = (z_ring − z_p2)/2
    (modules), their centre distance is a12 = (z_p1 + z_p2)/2; the triangle needs
    |a1 − a2| < a12 < a1 + a2, here allowed to miss by up to three modules (profile shift must close it;
    the geometry's working centre distances decide).

    References
    ----------
    SDP/SI D785, section 13 (planetary arrangement of double planets).
    """
    zs, zr = teeth.sun, teeth.ring
    z1, z2 = teeth.planet
    if zr <= z2:
        raise ToothCountError(
            f"{owner}: the ring must have more teeth than planet 2 meshing it, got z_ring={zr}, z_planet_ring={z2}."
        )
    a1, a2, a12 = (zs + z1) / 2, (zr - z2) / 2, (z1 + z2) / 2
    low, high = abs(a1 - a2), a1 + a2
    if a12 <= low - MAX_COAXIAL_MISMATCH_TEETH / 2 or a12 >= high + MAX_COAXIAL_MISMATCH_TEETH / 2:
        raise ToothCountError(
            f"{owner}: the double planets cannot be placed: planet 1's axis lies at (z_sun + z_planet_sun)/2 = "
            f"{a1:g}, planet 2's at (z_ring - z_planet_ring)/2 = {a2:g} modules, so their centre distance "
            f"(z_planet_sun + z_planet_ring)/2 = {a12:g} must lie between {low:g} and {high:g}; "
            "change the planet tooth counts."
        )


def coaxial_mismatch(teeth: Teeth, module_ratio: float = 1.0) -> float:
    """How far the tooth counts are from coaxial standard gears, in teeth of the first mesh's module.

    Simple set: ``z_ring − z_sun − 2 z_planet``; stepped: ``(z1 ± z_b) − (m2/m1)(z2 ± z_c)``;
    double: the distance (in teeth, twice modules) by which the planet–planet centre distance
    misses the open interval ``(|a1 − a2|, a1 + a2)``, 0 inside.  Twice the difference of the
    standard centre distances in modules; profile shift must close it.

    Parameters
    ----------
    teeth : Teeth
        The set's tooth counts.
    module_ratio : float, default 1.0
        m2/m1 of a stepped set.

    Returns
    -------
    float
        0 for standard coaxial counts.

    Examples
    --------
    >>> coaxial_mismatch(Teeth("simple", 21, 108, (43,)))
    1.0

    References
    ----------
    SDP/SI D785, eqs. (13-5), (13-6) (coaxial condition of standard gears).
    """
    if teeth.kind == "simple":
        return float(teeth.ring - teeth.sun - 2 * teeth.planet[0])
    if teeth.kind == "double":
        a1 = (teeth.sun + teeth.planet[0]) / 2
        a2 = (teeth.ring - teeth.planet[1]) / 2
        a12 = (teeth.planet[0] + teeth.planet[1]) / 2
        low, high = abs(a1 - a2), a1 + a2
        return 2.0 * (a12 - high if a12 >= high else (a12 - low if a12 <= low else 0.0))
    first = _center(teeth.sun, teeth.planet[0], teeth.sun_internal)
    second = _center(teeth.ring, teeth.planet[1], teeth.ring_internal)
    return float(first - module_ratio * second)


def coaxial_note(teeth: Teeth, module_ratio: float = 1.0) -> str | None:
    """A sentence on how far the counts are off coaxial standard gears and that profile shift must close it.

    None when standard gears are coaxial.

    Parameters
    ----------
    teeth : Teeth
        The set's tooth counts.
    module_ratio : float, default 1.0
        m2/m1 of a stepped set.

    Returns
    -------
    str or None

    Examples
    --------
    >>> print(coaxial_note(Teeth("simple", 20, 97, (37,))))
    z_ring - z_sun - 2 z_planet = 97 - 20 - 2*37 = +3: standard gears are not coaxial (their centre distances differ by 1.5 modules); profile shift must close it: give a geometry table (module, profile_shift) and the working centre distances decide
    """
    mismatch = coaxial_mismatch(teeth, module_ratio)
    if abs(mismatch) < 1e-9:
        return None
    if teeth.kind == "simple":
        what = (f"z_ring - z_sun - 2 z_planet = {teeth.ring} - {teeth.sun} - 2*{teeth.planet[0]} = "
                f"{mismatch:+g}")
    elif teeth.kind == "double":
        what = f"the double planets miss their triangle by {abs(mismatch) / 2:g} modules"
    else:
        what = f"the stepped planet's two meshes differ by {mismatch:+g} teeth (m2/m1 = {module_ratio:g})"
    modules = abs(mismatch) / 2
    return (f"{what}: standard gears are not coaxial (their centre distances differ by {modules:g} "
            f"module{'' if modules == 1 else 's'}); profile shift must close it: give a geometry table (module, "
            "profile_shift) and the working centre distances decide")
