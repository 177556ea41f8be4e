"""A drawable set for a planetary set given by its stationary ratio alone (labelled "schematic").

Every transmission of the library, and every differential, is given by i0
without tooth counts.  To draw it (speed plan, animation) a set is chosen
whose tooth counts reproduce i0 exactly where small whole numbers can:

* a minus set with |i0| ≥ 1.5 (or ≤ 1/1.5): a simple sun–planet–ring set,
  ``z_ring/z_sun = |i0|`` (Queitsch eq. 4); below 1 the port called "sun" is
  the internal gear;
* a plus set with i0 ≥ 1.8 (or ≤ 1/1.8): a double-planet set,
  ``z_ring/z_sun = i0``, where small tooth counts give i0 exactly;
* otherwise a stepped planet (Brandenberger's a/b·c/d): an internal ring for
  a minus set, ``i0 = −(z_d z_b)/(z_a z_c)``, two external central gears for a
  plus set, ``i0 = (z_d z_b)/(z_a z_c)``; the planet gears are coaxial:
  ``z_a + z_b = z_d ∓ z_c`` with one module.  For |i0| < 1 the set is drawn
  with its "sun" port as the second central gear (ratio 1/|i0|).

Among the candidates with 10 to 180 teeth the smallest drawable one is
taken (planets clear of each other and of the central gears with the set's
planet count).  A figure that draws such a set says "schematic".

References
----------
Queitsch, eq. 4 (i0 = −z_ring/z_sun); Brandenberger 1952, eq. 1 and Bild 1
(stepped planet, n2 − n3 = (n1 − n3)(a/b)(c/d)).
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache
from types import MappingProxyType

import numpy as np

from ..model.planetary import PlanetarySet, Teeth

__all__ = ["DrawnSet", "drawn_set", "schematic_teeth"]

_MIN, _MAX = 10, 180


@dataclass(frozen=True)
class DrawnSet:
    """The tooth counts a set is drawn with.

    Attributes
    ----------
    teeth : Teeth
        Real tooth counts, or schematic ones reproducing i0.
    roles : mapping drawn gear → port
        ``{"sun": "sun", "ring": "ring"}``, or swapped where the set's "sun"
        port is drawn as the larger (internal) gear.
    schematic : bool
        The tooth counts were chosen for the drawing (the set has none).
    exact : bool
        They reproduce i0 to 1e-9 (else the nearest drawable set is shown).
    """

    teeth: Teeth
    roles: Mapping[str, str]
    schematic: bool
    exact: bool = True

    @property
    def swapped(self) -> bool:
        return self.roles["sun"] != "sun"

    def planet_speeds(self, speeds: Mapping[str, float]) -> tuple[float, ...]:
        """Speeds of the drawn planet gears (1/min) from the port speeds ``sun``, ``ring``, ``carrier``.

        tec-science, "Willis-Gleichung": n_P z_P = n_T (z_P + z_S) − n_S z_S, with
        the drawn sun (the port in ``roles["sun"]``).
        """
        sun, carrier = speeds[self.roles["sun"]], speeds["carrier"]
        return tuple(carrier + k * (sun - carrier) for k in self.teeth.planet_factors)


def _ratio(i0: float) -> Fraction:
    return Fraction(i0).limit_denominator(240)


def _multiples(k: Fraction, smallest: int) -> Iterator[tuple[int, int]]:
    """(z_sun, z_ring) = m·(denominator, numerator) of ``k``, z_sun ≥ ``smallest``, z_ring ≤ the maximum."""
    m = 1
    while k.numerator * m <= _MAX:
        if k.denominator * m >= smallest:
            yield k.denominator * m, k.numerator * m
        m += 1


def _simple(k: Fraction, planets: int) -> Teeth | None:
    """Smallest simple set with z_ring/z_sun = k, else the one of 14…40 sun teeth nearest to k."""
    def drawable(zs: int, zr: int) -> Teeth | None:
        zp = (zr - zs) // 2  # an odd difference: a profile-shifted planet, as in the Prius 30/23/78
        if zr <= _MAX and zp >= 8 and (zs + zp) * math.sin(math.pi / planets) > zp + 2.5:
            return Teeth("simple", zs, zr, (zp,))
        return None

    for zs, zr in _multiples(k, 14):
        if (teeth := drawable(zs, zr)) is not None:
            return teeth
    near = sorted(range(14, 41), key=lambda zs: abs(round(float(k) * zs) / zs - float(k)))
    return next((t for zs in near if (t := drawable(zs, round(float(k) * zs))) is not None), None)


def _double(k: Fraction, planets: int) -> Teeth | None:
    for zs, zr in _multiples(k, 12):
        for zp in range(8, zr):
            a1, a2 = (zs + zp) / 2, (zr - zp) / 2
            if not (a2 - a1 > 2.5 and a1 + zp / 2 + 2 < zr / 2 - 1 and a1 + a2 > zp):
                continue
            cos_d = (a1 ** 2 + a2 ** 2 - zp ** 2) / (2 * a1 * a2)
            if abs(cos_d) <= 1 and 2 * math.acos(cos_d) < 2 * math.pi / planets * 0.85:
                return Teeth("double", zs, zr, (zp, zp))
    return None


def _stepped(internal: bool, target: float, k: Fraction, planets: int) -> tuple[Teeth, bool] | None:
    """Smallest stepped set with (z_d z_b)/(z_a z_c) = target ≥ 1 (= k exactly if possible, else nearest)."""
    z = np.arange(_MIN, 101)
    za, zb, zc = np.meshgrid(z, z, z, indexing="ij")
    zd = za + zb + zc if internal else za + zb - zc
    ok = (zd >= _MIN) & (zd <= _MAX) & (zb != zc)
    if internal:
        ok &= zd - zc >= za + 6  # the ring clears the sun-side step
    else:
        ok &= zd != za
    ok &= zd * zb >= za * zc  # target ≥ 1: the drawn sun is the faster central gear with the carrier held
    a = (za + zb) / 2
    ok &= 2 * a * np.sin(np.pi / planets) > np.maximum(zb, zc) + 2.5  # neighbouring planets clear
    exact = ok & (zd * zb * k.denominator == k.numerator * za * zc)
    pick = exact if exact.any() else ok
    if not pick.any():
        return None
    error = np.abs(zd * zb / (za * zc) - target) if not exact.any() else 0.0
    size = za + zb + zc + zd
    score = np.where(pick, size + 1e6 * error, np.inf)
    idx = np.unravel_index(int(np.argmin(score)), score.shape)
    teeth = Teeth("stepped", int(za[idx]), int(zd[idx]), (int(zb[idx]), int(zc[idx])), internal)
    return teeth, bool(exact.any())


@lru_cache(maxsize=256)
def schematic_teeth(i0: float, planets: int = 3) -> tuple[Teeth, Mapping[str, str], bool]:
    """(teeth, roles, exact) of the drawable set for ``i0`` (see the module text).

    Examples
    --------
    >>> t, roles, exact = schematic_teeth(-96 / 48)
    >>> t, exact
    (Teeth(kind='simple', sun=16, ring=32, planet=(8,), ring_internal=True, sun_internal=False), True)
    >>> t, roles, exact = schematic_teeth(72 / 30)
    >>> t.kind, t.stationary_ratio == 72 / 30
    ('double', True)
    >>> t, roles, exact = schematic_teeth(-1.0)
    >>> t.kind, round(t.stationary_ratio, 12), exact
    ('stepped', -1.0, True)
    """
    planets = max(int(planets), 2)
    magnitude = abs(i0)
    swapped = magnitude < 1
    k = _ratio(1 / magnitude if swapped else magnitude)
    roles = MappingProxyType({"sun": "ring", "ring": "sun"} if swapped else {"sun": "sun", "ring": "ring"})
    target = 1 / magnitude if swapped else magnitude  # ≥ 1: the drawn ratio
    teeth = None
    if i0 < 0 and k >= Fraction(3, 2):
        teeth = _simple(k, planets)
    elif i0 > 0 and k >= Fraction(9, 5):
        teeth = _double(k, planets)
    if teeth is not None:
        exact = abs(teeth.ring / teeth.sun - target) <= 1e-9 * target
        # a simple set's drawing is made exact by its ring radius; a double planet must be exact itself
        if exact or teeth.kind == "simple":
            return teeth, roles, exact
    found = _stepped(i0 < 0, target, k, planets)
    if found is None:  # pragma: no cover - the grid always holds a drawable stepped set
        raise ValueError(f"no drawable set for i0 = {i0!r}")
    teeth, exact = found
    return teeth, roles, exact and abs(abs(teeth.stationary_ratio) - target) <= 1e-9 * target


def drawn_set(pset: PlanetarySet) -> DrawnSet:
    """The tooth counts ``pset`` is drawn with: its own, or a schematic set reproducing its i0."""
    if pset.teeth is not None:
        return DrawnSet(pset.teeth, MappingProxyType({"sun": "sun", "ring": "ring"}), False)
    teeth, roles, exact = schematic_teeth(pset.stationary_ratio, pset.planets)
    return DrawnSet(teeth, roles, True, exact)
