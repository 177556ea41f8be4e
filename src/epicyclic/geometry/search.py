"""Tooth-count search for a simple planetary set (vectorised with numpy).

All (z_sun, z_planet, z_ring, N) within bounds, standard gears
(``z_ring = z_sun + 2 z_planet``, x = 0), whose two-shaft ratio in the chosen
mode lies within a relative tolerance of the target and that pass every
fitting condition of :mod:`epicyclic.geometry.fitting` (equal-spacing
assembly, neighbour clearance, undercut, and optionally internal-gear
interference).  Distinct sets first (one set of each family: the counts
divided by their common factor), then the repeats (scaled copies such as
21/21/63 … 40/40/120, the same counts with other numbers of planets); within
each by ratio error, then the hunting-tooth property (gcd(z_sun, z_planet) =
gcd(z_planet, z_ring) = 1: every tooth meets every tooth of its mate), size
(z_ring), z_sun and N.

:func:`search_teeth_loops` is the straightforward reference: nested Python
loops that build a :class:`~epicyclic.geometry.set_geometry.SetGeometry` for
every candidate within the ratio tolerance and ask
:func:`~epicyclic.geometry.fitting.check_fitting`.  Both return the same
candidates (``benchmarks/bench_tooth_search.py``).

References
----------
Willis equation n_s − i0 n_r − (1 − i0) n_c = 0 with i0 = −z_r/z_s (Queitsch eqs. 4, 12);
SDP/SI D785 eqs. (13-5), (13-7), (13-9); Drivetrain Hub, *Planetary Gears*
(target ratio with ± deviation, candidate table; hunting teeth: no common factor of a mesh's tooth counts).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, Literal

import numpy as np

from ..model.planetary import PlanetarySet
from ._render import html_table, text_table
from .errors import GeometryError, finite_number
from .fitting import check_fitting
from .gear import BasicRack
from .involute import inv
from .set_geometry import SetGeometry
from .undercut import undercut_limit

__all__ = ["Candidate", "ToothSearch", "search_teeth", "search_teeth_loops", "two_shaft_ratio"]

_SHAFTS = ("sun", "ring", "carrier")


def two_shaft_ratio(i0, held: str, driver: str, driven: str):
    """Speed ratio n_driver/n_driven with shaft ``held`` at rest (floats or arrays).

    From the Willis equation n_sun − i0 n_ring − (1 − i0) n_carrier = 0 with the
    held shaft's speed zero.

    Parameters
    ----------
    i0 : float or numpy.ndarray
        Stationary ratio (n_sun − n_carrier)/(n_ring − n_carrier); −z_ring/z_sun for a simple set.
    held, driver, driven : {"sun", "ring", "carrier"}
        The three shafts, each once.

    Returns
    -------
    float or numpy.ndarray
        n_driver/n_driven.

    Raises
    ------
    GeometryError
        ``held``, ``driver`` and ``driven`` are not ``sun``, ``ring``, ``carrier`` in some order.

    References
    ----------
    tec-science, "Willis-Gleichung"; Queitsch, Tafel 1 (1 − s, 1/(1 − s), 1/s, ... with s = i0).

    Examples
    --------
    >>> two_shaft_ratio(-78 / 30, "ring", "sun", "carrier")
    3.6
    """
    if {held, driver, driven} != set(_SHAFTS):
        raise GeometryError(
            f"two_shaft_ratio: held, driver and driven must be 'sun', 'ring', 'carrier' in some order, "
            f"got held={held!r}, driver={driver!r}, driven={driven!r}."
        )
    coeff = {"sun": 1.0, "ring": -i0, "carrier": -(1.0 - i0)}
    return -coeff[driven] / coeff[driver]


@dataclass(frozen=True)
class Candidate:
    """One tooth-count solution."""

    z_sun: int
    z_planet: int
    z_ring: int
    planets: int
    ratio: float
    error: float
    hunting: bool
    clearance: float

    def planetary_set(self, name: str = "P", sun: str = "sun", ring: str = "ring", carrier: str = "carrier",
                      stationary_efficiency: float | None = None) -> PlanetarySet:
        """The candidate as a model :class:`~epicyclic.model.PlanetarySet` (a simple set).

        Parameters
        ----------
        name : str, default "P"
            Element name.
        sun, ring, carrier : str, default "sun", "ring", "carrier"
            The shafts the set joins.
        stationary_efficiency : float, optional
            η0 in (0, 1]; default 1 (lossless).

        Returns
        -------
        PlanetarySet
            With the candidate's tooth counts and number of planets.

        Raises
        ------
        EfficiencyError
            ``stationary_efficiency`` outside (0, 1].

        Examples
        --------
        >>> best = search_teeth(4.0, tolerance=0.0, z_sun=(14, 30), z_planet=(14, 30), planets=(3,)).candidates[0]
        >>> best.planetary_set("P", ring="housing", sun="in", carrier="out").stationary_ratio
        -3.0
        """
        return PlanetarySet.simple(name, sun=sun, ring=ring, carrier=carrier, z_sun=self.z_sun,
                                   z_planet=self.z_planet, z_ring=self.z_ring, planets=self.planets,
                                   stationary_efficiency=stationary_efficiency)

    def key(self) -> tuple[int, int, int, int]:
        """The candidate's design as ``(z_sun, z_planet, z_ring, planets)``."""
        return (self.z_sun, self.z_planet, self.z_ring, self.planets)


@dataclass(frozen=True)
class ToothSearch:
    """Ranked result of a tooth-count search."""

    target: float
    mode: tuple[str, str, str]
    tolerance: float
    module: float
    candidates: tuple[Candidate, ...]
    #: Smallest and largest ratio of the tooth ranges in this mode, before the fitting checks (None: not known).
    reachable: tuple[float, float] | None = field(default=None, compare=False)
    #: How many (z_sun, z_planet, N) of the ranges meet the ratio before the fitting checks (None: not known).
    matched: int | None = field(default=None, compare=False)

    def __len__(self) -> int:
        return len(self.candidates)

    @property
    def best(self) -> Candidate | None:
        return self.candidates[0] if self.candidates else None

    _HEAD = ["z_sun", "z_planet", "z_ring", "N", "ratio", "error [%]", "hunting", "clearance [mm]"]

    def _rows(self, limit: int) -> list[list[object]]:
        return [[c.z_sun, c.z_planet, c.z_ring, c.planets, c.ratio, 100 * c.error, c.hunting,
                 c.clearance if math.isfinite(c.clearance) else "no neighbour"]
                for c in self.candidates[:limit]]

    def table(self, limit: int = 20) -> str:
        """The best candidates as a plain-text table, with a line saying why none was found if so.

        Columns: tooth counts, number of planets N, ratio, deviation from the target
        in %, whether the counts are hunting (no common factor of sun/planet and
        planet/ring) and the neighbour clearance of the planet tips in mm.

        Parameters
        ----------
        limit : int, default 20
            Most rows shown (the candidates are ranked: distinct sets, then repeats;
            each by smallest error, hunting teeth, smallest ring, sun, planets).

        Returns
        -------
        str
        """
        held, driver, driven = self.mode
        title = (f"{len(self)} tooth-count sets for {driver} -> {driven} ({held} held) = {self.target:g} "
                 f"± {100 * self.tolerance:g} %, m = {self.module:g} mm (first {min(limit, len(self))})")
        return text_table(self._HEAD, self._rows(limit), title=title) + self._why_none()

    def _why_none(self) -> str:
        """For an empty result: whether the ratio is out of reach of the tooth ranges or no set fits."""
        if self.candidates or self.reachable is None:
            return ""
        if self.matched:
            sets = "1 tooth-count set meets" if self.matched == 1 else f"{self.matched} tooth-count sets meet"
            return (f"\nnone found: {sets} the ratio, but none passes assembly at equal "
                    "spacing, neighbour clearance, undercut and interference; widen the tolerance or the tooth "
                    "ranges, or try other numbers of planets.")
        held, driver, driven = self.mode
        low, high = self.reachable
        return (f"\nnone found: no tooth counts of these ranges come within ± {100 * self.tolerance:g} % of "
                f"{self.target:g}; with the {held} held, {driver} -> {driven} ranges over {low:.4g} … {high:.4g} "
                "here; change the target, the tolerance, the mode or the ranges.")

    def _repr_html_(self) -> str:
        return html_table(self._HEAD, self._rows(50), title=f"tooth-count search, target {self.target:g}")

    def to_csv(self) -> str:
        """Every candidate as comma-separated values with a header line (error in %, clearance in mm)."""
        head = "z_sun,z_planet,z_ring,planets,ratio,error_percent,hunting,clearance_mm"
        lines = [f"{c.z_sun},{c.z_planet},{c.z_ring},{c.planets},{c.ratio!r},{100 * c.error!r},"
                 f"{str(c.hunting).lower()},{repr(c.clearance) if math.isfinite(c.clearance) else ''}"
                 for c in self.candidates]
        return "\n".join([head, *lines]) + "\n"

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data: the target, mode, tolerance, module and every candidate.

        Returns
        -------
        dict
            ``target``, ``mode`` (``{held, driver, driven}``), ``tolerance`` (relative),
            ``module`` (mm) and ``candidates`` (each with the fields of :class:`Candidate`;
            clearance in mm, null with ``clearance_note`` for one planet, which has no neighbour),
            in rank order.
        """
        rows = []
        for c in self.candidates:
            row = c.__dict__.copy()
            if not math.isfinite(row["clearance"]):  # JSON has no Infinity
                row["clearance"] = None
                row["clearance_note"] = "one planet: no neighbour, the clearance is unbounded"
            rows.append(row)
        return {"target": self.target, "mode": dict(zip(("held", "driver", "driven"), self.mode)),
                "tolerance": self.tolerance, "module": self.module, "candidates": rows}

    def __repr__(self) -> str:
        best = self.best
        top = f", best {best.key()} ratio {best.ratio:.5g}" if best else ""
        return f"ToothSearch(target={self.target:g}, mode={self.mode}, {len(self)} candidates{top})"


def _validate(target, tolerance, bounds: dict[str, tuple[int, int]], planets, min_clearance=0.0) -> tuple[int, ...]:
    if isinstance(target, bool) or not isinstance(target, (int, float)) or not math.isfinite(target) or target == 0:
        raise GeometryError(f"search_teeth: target_ratio must be a finite non-zero number, got {target!r}.")
    if isinstance(tolerance, bool) or not isinstance(tolerance, (int, float)) or not 0 <= tolerance < 1:
        raise GeometryError(
            f"search_teeth: tolerance is a relative deviation in [0, 1) (0.01 = 1 %), got {tolerance!r}."
        )
    for name, (lo, hi) in bounds.items():
        if not (isinstance(lo, int) and isinstance(hi, int)) or lo < 3 or hi < lo:
            raise GeometryError(f"search_teeth: {name} must be (low, high) whole numbers with 3 <= low <= high, "
                                f"got ({lo!r}, {hi!r}).")
    counts = tuple(planets)
    finite_number(min_clearance, "search_teeth", "min_clearance", unit="mm")
    if not counts or any(isinstance(n, bool) or not isinstance(n, int) or n < 1 for n in counts):
        raise GeometryError(f"search_teeth: planets must be whole numbers >= 1, got {planets!r}.")
    return counts


def _interference_free(z1, z2, rack: BasicRack):
    """Vectorised KHK involute/trochoid/trimming conditions for standard internal pairs (x = 0)."""
    m, alpha, ha = rack.module, rack.alpha_t, rack.addendum
    mt = rack.transverse_module
    ra1, ra2 = (mt * z1 + 2 * m * ha) / 2, (mt * z2 - 2 * m * ha) / 2
    rb1, rb2 = mt * z1 * math.cos(alpha) / 2, mt * z2 * math.cos(alpha) / 2
    a = mt * (z2 - z1) / 2
    with np.errstate(invalid="ignore", divide="ignore"):
        ok = ra2 > rb2
        aa1 = np.arccos(np.clip(rb1 / ra1, -1, 1))
        aa2 = np.arccos(np.clip(rb2 / ra2, -1, 1))
        involute = z1 / z2 - (1 - np.tan(aa2) / math.tan(alpha))
        c1 = (ra2 ** 2 - ra1 ** 2 - a ** 2) / (2 * a * ra1)
        c2 = (a ** 2 + ra2 ** 2 - ra1 ** 2) / (2 * a * ra2)
        c_ok = (np.abs(c1) <= 1) & (np.abs(c2) <= 1)
        th1 = np.arccos(np.clip(c1, -1, 1)) + inv(aa1) - inv(alpha)
        th2 = np.arccos(np.clip(c2, -1, 1))
        trochoid = np.where(c_ok, th1 * z1 / z2 + inv(alpha) - inv(aa2) - th2, -np.inf)
        s1 = (1 - (np.cos(aa1) / np.cos(aa2)) ** 2) / (1 - (z1 / z2) ** 2)
        s2 = ((np.cos(aa2) / np.cos(aa1)) ** 2 - 1) / ((z2 / z1) ** 2 - 1)
        s_ok = (s1 >= 0) & (s1 <= 1) & (s2 >= 0) & (s2 <= 1)
        t1, t2 = np.arcsin(np.sqrt(np.clip(s1, 0, 1))), np.arcsin(np.sqrt(np.clip(s2, 0, 1)))
        trim = np.where(s_ok, t1 + inv(aa1) - inv(alpha) - (z2 / z1) * (t2 + inv(aa2) - inv(alpha)),
                        np.where(s2 < 0, np.inf, -np.inf))
    return ok & (involute >= 0) & (trochoid >= 0) & (trim >= 0)


def _rank(cands: list[Candidate]) -> tuple[Candidate, ...]:
    """Distinct sets first, then the repeats; each in order of ratio error, hunting teeth, size (z_ring), z_sun, N.

    A set's family is its tooth counts divided by their common factor (21/21/63 and 40/40/120 are one family,
    1/1/3 scaled); its repeats are the family's other members and the same counts with other numbers of
    planets.  So a target that only scaled copies meet exactly (ratio 4: z_s = z_p) lists the smallest exact
    set once and then the hunting sets near the target, before twenty copies of one.
    """
    ordered = sorted(cands, key=lambda c: (round(c.error, 12), not c.hunting, c.z_ring, c.z_sun, c.planets))
    seen: set[tuple[int, int]] = set()
    distinct: list[Candidate] = []
    repeats: list[Candidate] = []
    for c in ordered:
        common = math.gcd(c.z_sun, c.z_planet)
        family = (c.z_sun // common, c.z_planet // common)
        (repeats if family in seen else distinct).append(c)
        seen.add(family)
    return tuple(distinct + repeats)


def search_teeth(
    target_ratio: float,
    *,
    held: Literal["sun", "ring", "carrier"] = "ring",
    driver: Literal["sun", "ring", "carrier"] = "sun",
    driven: Literal["sun", "ring", "carrier"] = "carrier",
    tolerance: float = 0.01,
    z_sun: tuple[int, int] = (12, 80),
    z_planet: tuple[int, int] = (12, 80),
    z_ring: tuple[int, int] | None = None,
    planets: Sequence[int] = (3, 4, 5),
    module: float = 1.0,
    pressure_angle: float = 20.0,
    addendum: float = 1.0,
    min_clearance: float = 0.0,
    undercut: Literal["theoretical", "practical"] = "theoretical",
    interference: bool = True,
) -> ToothSearch:
    """Every simple set within bounds that meets the target ratio and fits, ranked.

    Parameters
    ----------
    target_ratio : float
        n_driver / n_driven in the mode (``held`` shaft at rest).
    held, driver, driven : {"sun", "ring", "carrier"}
        The mode (default: ring held, sun drives carrier).
    tolerance : float, default 0.01
        Allowed relative deviation |ratio/target − 1|.
    z_sun, z_planet, z_ring : (int, int)
        Inclusive bounds (z_ring optional).
    planets : sequence of int
        Numbers of planets to try.
    module, pressure_angle, addendum : float
        Basic rack (mm, degrees); the module scales the clearance.
    min_clearance : float, default 0
        Neighbour clearance between planet tips, mm.
    undercut : {"theoretical", "practical"}
    interference : bool, default True
        Also reject internal-gear interference (KHK conditions).

    Examples
    --------
    >>> res = search_teeth(4.0, tolerance=0.0, z_sun=(14, 30), z_planet=(14, 30), planets=(3, 4))
    >>> [c.key() for c in res.candidates[:2]]
    [(21, 21, 63, 3), (21, 21, 63, 4)]
    """
    counts = _validate(target_ratio, tolerance, {"z_sun": z_sun, "z_planet": z_planet,
                                                 **({"z_ring": z_ring} if z_ring else {})}, planets, min_clearance)
    two_shaft_ratio(-2.0, held, driver, driven)  # validates the mode
    rack = BasicRack(module, pressure_angle, 0.0, addendum)
    zs, zp, n = np.meshgrid(np.arange(z_sun[0], z_sun[1] + 1), np.arange(z_planet[0], z_planet[1] + 1),
                            np.array(counts), indexing="ij")
    zs, zp, n = zs.ravel(), zp.ravel(), n.ravel()
    zr = zs + 2 * zp
    ratio = two_shaft_ratio(-zr / zs, held, driver, driven)
    error = np.abs(ratio / target_ratio - 1.0)
    keep = error <= tolerance + 1e-12
    in_range = np.ones_like(keep) if not z_ring else (zr >= z_ring[0]) & (zr <= z_ring[1])
    keep &= in_range
    reachable = (float(ratio[in_range].min()), float(ratio[in_range].max())) if in_range.any() else None
    matched = int(np.count_nonzero(keep))
    keep &= (zs + zr) % n == 0
    a = module * (zs + zp) / 2.0
    da = module * (zp + 2 * addendum)
    clearance = np.where(n > 1, 2 * a * np.sin(np.pi / n) - da, np.inf)
    keep &= clearance - min_clearance > 1e-9
    z_lim = undercut_limit(pressure_angle, addendum) * (5 / 6 if undercut == "practical" else 1)
    keep &= (addendum * (z_lim - zs) / z_lim <= 1e-9) & (addendum * (z_lim - zp) / z_lim <= 1e-9)
    idx = np.nonzero(keep)[0]
    if interference and idx.size:
        idx = idx[_interference_free(zp[idx].astype(float), zr[idx].astype(float), rack)]
    hunting = (np.gcd(zs[idx], zp[idx]) == 1) & (np.gcd(zp[idx], zr[idx]) == 1)
    cands = [Candidate(int(zs[i]), int(zp[i]), int(zr[i]), int(n[i]), float(ratio[i]), float(error[i]), bool(h),
                       float(clearance[i])) for i, h in zip(idx, hunting)]
    return ToothSearch(float(target_ratio), (held, driver, driven), float(tolerance), float(module), _rank(cands),
                       reachable, matched)


def search_teeth_loops(
    target_ratio: float,
    *,
    held: str = "ring",
    driver: str = "sun",
    driven: str = "carrier",
    tolerance: float = 0.01,
    z_sun: tuple[int, int] = (12, 80),
    z_planet: tuple[int, int] = (12, 80),
    z_ring: tuple[int, int] | None = None,
    planets: Sequence[int] = (3, 4, 5),
    module: float = 1.0,
    pressure_angle: float = 20.0,
    addendum: float = 1.0,
    min_clearance: float = 0.0,
    undercut: Literal["theoretical", "practical"] = "theoretical",
    interference: bool = True,
) -> ToothSearch:
    """Reference implementation of :func:`search_teeth`: nested loops and :func:`check_fitting` per candidate.

    Slow; for tests and the benchmark (``benchmarks/``).  It takes the same
    arguments and returns the same candidates as :func:`search_teeth`.

    Parameters
    ----------
    target_ratio : float
        n_driver / n_driven in the mode (``held`` shaft at rest).
    held, driver, driven : {"sun", "ring", "carrier"}
        The mode (default: ring held, sun drives carrier).
    tolerance : float, default 0.01
        Allowed relative deviation |ratio/target − 1|.
    z_sun, z_planet : (int, int), default (12, 80)
        Inclusive bounds of the tooth counts.
    z_ring : (int, int), optional
        Inclusive bounds of the ring (z_ring = z_sun + 2 z_planet).
    planets : sequence of int, default (3, 4, 5)
        Numbers of planets to try.
    module : float, default 1.0
        Module, mm.
    pressure_angle : float, default 20
        Pressure angle, degrees.
    addendum : float, default 1.0
        Addendum factor h_a*.
    min_clearance : float, default 0
        Neighbour clearance between planet tips, mm.
    undercut : {"theoretical", "practical"}, default "theoretical"
        Undercut limit (:func:`min_profile_shift`).
    interference : bool, default True
        Also reject internal-gear interference.

    Returns
    -------
    ToothSearch

    Raises
    ------
    GeometryError
        A target that is not a finite non-zero number, bounds that are not whole
        numbers ≥ 3 in order, planets < 1, or an unknown mode.
    """
    counts = _validate(target_ratio, tolerance, {"z_sun": z_sun, "z_planet": z_planet,
                                                 **({"z_ring": z_ring} if z_ring else {})}, planets, min_clearance)
    cands = []
    for s in range(z_sun[0], z_sun[1] + 1):
        for p in range(z_planet[0], z_planet[1] + 1):
            r = s + 2 * p
            if z_ring and not z_ring[0] <= r <= z_ring[1]:
                continue
            ratio = two_shaft_ratio(-r / s, held, driver, driven)
            error = abs(ratio / target_ratio - 1.0)
            if error > tolerance + 1e-12:
                continue
            for n in counts:
                pset = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=s, z_planet=p, z_ring=r,
                                           planets=n)
                geom = SetGeometry.create(pset, module, pressure_angle=pressure_angle, addendum=addendum)
                report = check_fitting(geom, min_clearance=min_clearance, undercut=undercut)
                ok = report.passed and (not interference or all(c.passed for c in report.checks))
                if ok:
                    clearance = next(c.clearance for c in report.checks if c.condition == "neighbours")
                    hunting = math.gcd(s, p) == 1 and math.gcd(p, r) == 1
                    cands.append(Candidate(s, p, r, n, ratio, error, hunting, clearance))
    return ToothSearch(float(target_ratio), (held, driver, driven), float(tolerance), float(module), _rank(cands))
