"""What to synthesise: target ratios, sets, shift elements and bounds (validated once, here).

A :class:`SynthesisSpec` is built from Python values (:meth:`SynthesisSpec.create`)
or a TOML file (:meth:`SynthesisSpec.from_file`)::

    title = "8-speed, ZF 8HP 70 ratios"
    [targets]
    forward = [4.6957, 3.1304, 2.1039, 1.6667, 1.2845, 1.0, 0.8392, 0.6667]
    reverse = [-3.2968]
    tolerance = 0.01            # relative, per ratio
    # or: spread = 7.0, gears = 8, first = 4.7, progression = 1.0 (Jante factor; 1 = geometric)
    [sets]
    simple = 4
    plus = 0
    [elements]
    brakes = 2
    clutches = 3
    engaged = 3                 # per gear (default: every feasible number)
    [bounds]
    stationary_ratio = [1.5, 4.0]   # |i0|
    sun = [17, 80]
    planet = [17, 80]
    planets = [3, 4, 5]
    [search]
    max_members_per_shaft = 2   # ties join pairs of members (default: no limit)
    free_input = true           # also a separate input shaft reached by clutches only
    input_members = ["sun", "ring", "carrier"]    # the input shaft holds one of these (default: any)
    output_members = ["sun", "ring", "carrier"]
    levels = 4                  # bisection levels of the screening (at most 16 // sets are used)
    stationary_efficiency = 0.98
    top = 20

Every problem raises :class:`SynthesisError` naming the key and the fix.

References
----------
Naunheimer, Bertsche, Ryborz, Novak (2011), *Automotive Transmissions*, 2nd ed.,
section 6.2 (overall ratio spread; geometric and progressive ("Jante") ratio
steps, φ_k = φ1 · φ2^(z−k)).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from math import comb
from pathlib import Path
from typing import Any

from ..errors import ModelError
from ..limits import (MAX_PLANETS, MAX_SYNTHESIS_ELEMENTS, MAX_SYNTHESIS_GEARS, MAX_SYNTHESIS_SETS, MAX_TEETH,
                      MIN_TEETH)

__all__ = ["SynthesisError", "SynthesisSpec", "progressive_ratios"]


class SynthesisError(ModelError):
    """A synthesis specification that cannot be searched (names the key and the fix)."""


def _number(value: Any, key: str, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise SynthesisError(f"{where}: {key} must be a finite number, got {value!r}.")
    return float(value)


def _count(value: Any, key: str, where: str, minimum: int = 0, maximum: int | None = None) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or value < minimum:
        raise SynthesisError(f"{where}: {key} must be a whole number >= {minimum}, got {value!r}.")
    if maximum is not None and value > maximum:
        raise SynthesisError(f"{where}: {key} must be at most {maximum}, got {value!r} (see docs/limits.md).")
    return value


def _pair(value: Any, key: str, where: str, integer: bool = False) -> tuple[float, float]:
    if not isinstance(value, Sequence) or isinstance(value, str) or len(value) != 2:
        raise SynthesisError(f"{where}: {key} must be a pair [low, high], got {value!r}.")
    lo, hi = (_count(v, key, where, MIN_TEETH, MAX_TEETH) if integer else _number(v, key, where) for v in value)
    if not lo <= hi:
        raise SynthesisError(f"{where}: {key} must have low <= high, got [{lo}, {hi}].")
    return lo, hi


def progressive_ratios(spread: float, gears: int, first: float, progression: float = 1.0) -> tuple[float, ...]:
    """Forward ratios from spread, number of gears, first ratio and the progression factor φ2.

    Steps φ_k = i_k / i_(k+1) = φ1 · φ2^(z − 1 − k) (k = 1 … z − 1); φ2 = 1 gives a
    geometric series, φ2 > 1 larger steps in the low gears (Naunheimer et al. 2011, eq. 6.9).

    >>> [round(r, 4) for r in progressive_ratios(4.0, 3, 4.0)]
    [4.0, 2.0, 1.0]
    """
    z = gears
    # product of steps = spread: φ1^(z-1) · φ2^((z-1)(z-2)/2) = spread
    phi1 = (spread / progression ** ((z - 1) * (z - 2) / 2)) ** (1.0 / (z - 1))
    out = [first]
    for k in range(1, z):
        out.append(out[-1] / (phi1 * progression ** (z - 1 - k)))
    return tuple(out)


@dataclass(frozen=True)
class SynthesisSpec:
    """A validated synthesis problem.

    Attributes
    ----------
    forward : tuple of float
        Forward targets, largest first (> 0).
    reverse : tuple of float
        Reverse targets (< 0), largest magnitude first.
    tolerance : float
        Relative tolerance per ratio, in (0, 0.2].
    simple, plus : int
        Number of simple (minus) and double-planet (plus) sets.
    brakes, clutches : int
    engaged : tuple of int
        Elements engaged per gear to search (each gives its own mechanisms).
    stationary_ratio : (float, float)
        Bounds of |i0|.
    sun, planet : (int, int)
        Tooth-count bounds.
    planets : tuple of int
    max_members_per_shaft : int or None
    free_input : bool
    input_members, output_members : tuple of str
        The input (output) shaft holds at least one of these members.
    levels : int
    stationary_efficiency : float
    top : int
    title : str
    """

    forward: tuple[float, ...]
    reverse: tuple[float, ...]
    tolerance: float = 0.01
    simple: int = 2
    plus: int = 0
    brakes: int = 2
    clutches: int = 2
    engaged: tuple[int, ...] = ()
    stationary_ratio: tuple[float, float] = (1.5, 4.0)
    sun: tuple[int, int] = (17, 80)
    planet: tuple[int, int] = (17, 80)
    planets: tuple[int, ...] = (3, 4, 5)
    max_members_per_shaft: int | None = None
    free_input: bool = True
    input_members: tuple[str, ...] = ("sun", "ring", "carrier")
    output_members: tuple[str, ...] = ("sun", "ring", "carrier")
    levels: int = 4
    stationary_efficiency: float = 0.98
    top: int = 20
    title: str = "synthesis"

    @property
    def kinds(self) -> tuple[str, ...]:
        return ("simple",) * self.simple + ("plus",) * self.plus

    @property
    def gears(self) -> int:
        return len(self.forward) + len(self.reverse)

    @classmethod
    def create(cls, targets: Any, sets: Any = 2, elements: Any = None, constraints: Mapping[str, Any] | None = None,
               where: str = "synthesize") -> SynthesisSpec:
        """Build and validate a spec from the arguments of :func:`~epicyclic.synthesis.synthesize`.

        Parameters
        ----------
        targets : sequence of float or mapping
            Ratios (negative ones are reverse gears), or a mapping with
            ``forward``/``reverse``/``tolerance`` or ``spread``/``gears``/``first``/``progression``.
        sets : int or mapping
            Number of simple sets, or ``{"simple": n, "plus": m}``.
        elements : mapping
            ``{"brakes": b, "clutches": c, "engaged": k}`` (``engaged`` optional).
        constraints : mapping, optional
            Keys ``tolerance``, ``stationary_ratio``, ``sun``, ``planet``, ``planets``,
            ``max_members_per_shaft``, ``free_input``, ``input_members``, ``output_members``, ``levels``,
            ``stationary_efficiency``, ``top``, ``title``.
        """
        kw: dict[str, Any] = {}
        tmap = dict(targets) if isinstance(targets, Mapping) else {"ratios": targets}
        unknown = set(tmap) - {"ratios", "forward", "reverse", "tolerance", "spread", "gears", "first", "progression"}
        if unknown:
            raise SynthesisError(f"{where}: unknown targets key(s) {', '.join(sorted(map(repr, unknown)))}; use "
                                 "forward, reverse, tolerance or spread, gears, first, progression.")
        if "spread" in tmap:
            for key in ("gears", "first"):
                if key not in tmap:
                    raise SynthesisError(f"{where}: targets.spread needs targets.{key} as well.")
            spread = _number(tmap["spread"], "targets.spread", where)
            first = _number(tmap["first"], "targets.first", where)
            gears = _count(tmap["gears"], "targets.gears", where, 2)
            prog = _number(tmap.get("progression", 1.0), "targets.progression", where)
            if spread <= 1 or first <= 0 or prog <= 0:
                raise SynthesisError(f"{where}: targets.spread must be > 1, first and progression > 0.")
            forward = list(progressive_ratios(spread, gears, first, prog))
            reverse = [_number(v, "targets.reverse", where) for v in tmap.get("reverse", [])]
        elif "ratios" in tmap:
            values = tmap["ratios"]
            if isinstance(values, (str, bytes)) or not isinstance(values, Sequence) or not values:
                raise SynthesisError(f"{where}: targets must be a non-empty list of ratios, got {values!r}.")
            nums = [_number(v, "targets", where) for v in values]
            if any(v == 0 for v in nums):
                raise SynthesisError(f"{where}: a target ratio of 0 is no gear; forward ratios must be > 0 and "
                                     "reverse ratios < 0.")
            forward, reverse = [v for v in nums if v > 0], [v for v in nums if v < 0]
        else:
            forward = [_number(v, "targets.forward", where) for v in tmap.get("forward", [])]
            reverse = [_number(v, "targets.reverse", where) for v in tmap.get("reverse", [])]
        if any(v <= 0 for v in forward) or any(v >= 0 for v in reverse):
            raise SynthesisError(f"{where}: forward ratios must be > 0 and reverse ratios < 0 (a ratio of 0 is no gear).")
        if not forward:
            raise SynthesisError(f"{where}: give at least one forward ratio (targets.forward).")
        kw["forward"] = tuple(sorted(forward, reverse=True))
        kw["reverse"] = tuple(sorted(reverse))
        cons = dict(constraints or {})
        if "tolerance" in tmap:
            cons.setdefault("tolerance", tmap["tolerance"])
        if isinstance(sets, Mapping):
            unknown = set(sets) - {"simple", "plus"}
            if unknown:
                raise SynthesisError(f"{where}: unknown sets key(s) {sorted(unknown)}; use simple and plus.")
            kw["simple"] = _count(sets.get("simple", 0), "sets.simple", where)
            kw["plus"] = _count(sets.get("plus", 0), "sets.plus", where)
        else:
            kw["simple"], kw["plus"] = _count(sets, "sets", where, 1), 0
        if not 1 <= kw["simple"] + kw["plus"] <= MAX_SYNTHESIS_SETS:
            raise SynthesisError(f"{where}: give 1 to {MAX_SYNTHESIS_SETS} planetary sets in all (sets.simple + "
                                 f"sets.plus), got {kw['simple'] + kw['plus']} (see docs/limits.md).")
        elements = dict(elements or {"brakes": 2, "clutches": 2})
        unknown = set(elements) - {"brakes", "clutches", "engaged"}
        if unknown:
            raise SynthesisError(f"{where}: unknown elements key(s) {sorted(unknown)}; use brakes, clutches, engaged.")
        kw["brakes"] = _count(elements.get("brakes", 0), "elements.brakes", where)
        kw["clutches"] = _count(elements.get("clutches", 0), "elements.clutches", where)
        total = kw["brakes"] + kw["clutches"]
        gears = len(kw["forward"]) + len(kw["reverse"])
        if total > MAX_SYNTHESIS_ELEMENTS:
            raise SynthesisError(f"{where}: at most {MAX_SYNTHESIS_ELEMENTS} shift elements (elements.brakes + "
                                 f"elements.clutches), got {total} (see docs/limits.md).")
        if gears > MAX_SYNTHESIS_GEARS:
            raise SynthesisError(f"{where}: at most {MAX_SYNTHESIS_GEARS} target ratios, got {gears} "
                                 "(see docs/limits.md).")
        if "engaged" in elements:
            engaged = elements["engaged"]
            engaged = (engaged,) if not isinstance(engaged, Sequence) else tuple(engaged)
            kw["engaged"] = tuple(_count(e, "elements.engaged", where, 1) for e in engaged)
        else:
            kw["engaged"] = tuple(k for k in range(1, total) if comb(total, k) >= gears)
        for k in kw["engaged"]:
            if k >= total or comb(total, k) < gears:
                raise SynthesisError(
                    f"{where}: {total} shift elements with {k} engaged per gear give {comb(total, k) if k < total else 0} "
                    f"combinations, fewer than the {gears} gears asked for; add elements (elements.brakes/clutches) "
                    "or change elements.engaged.")
        if not kw["engaged"]:
            raise SynthesisError(f"{where}: {total} shift elements cannot give {gears} gears; add brakes or clutches.")
        return cls._with_constraints(kw, cons, where)

    @classmethod
    def _with_constraints(cls, kw: dict[str, Any], cons: dict[str, Any], where: str) -> SynthesisSpec:
        allowed = {"tolerance", "stationary_ratio", "sun", "planet", "planets", "max_members_per_shaft",
                   "free_input", "input_members", "output_members", "levels", "stationary_efficiency", "top",
                   "title"}
        unknown = set(cons) - allowed
        if unknown:
            raise SynthesisError(f"{where}: unknown constraint(s) {', '.join(sorted(map(repr, unknown)))}; "
                                 f"allowed: {', '.join(sorted(allowed))}.")
        if "tolerance" in cons:
            kw["tolerance"] = _number(cons["tolerance"], "tolerance", where)
            if not 0 < kw["tolerance"] <= 0.2:
                raise SynthesisError(f"{where}: tolerance is relative (0.01 = 1 %) and must lie in (0, 0.2], "
                                     f"got {kw['tolerance']!r}.")
        if "stationary_ratio" in cons:
            lo, hi = _pair(cons["stationary_ratio"], "bounds.stationary_ratio", where)
            if lo <= 1.0:
                raise SynthesisError(f"{where}: bounds.stationary_ratio gives |i0|, which must exceed 1 "
                                     f"(ring larger than sun), got [{lo}, {hi}].")
            kw["stationary_ratio"] = (lo, hi)
        for key in ("sun", "planet"):
            if key in cons:
                kw[key] = _pair(cons[key], f"bounds.{key}", where, integer=True)
        if "planets" in cons:
            p = cons["planets"]
            p = (p,) if isinstance(p, int) else p
            if not isinstance(p, Sequence) or not p:
                raise SynthesisError(f"{where}: bounds.planets must be a list of planet numbers, got {p!r}.")
            kw["planets"] = tuple(_count(v, "bounds.planets", where, 1, MAX_PLANETS) for v in p)
        if cons.get("max_members_per_shaft") is not None:
            kw["max_members_per_shaft"] = _count(cons["max_members_per_shaft"], "search.max_members_per_shaft", where, 2)
        if "free_input" in cons:
            if not isinstance(cons["free_input"], bool):
                raise SynthesisError(f"{where}: search.free_input must be true or false, got {cons['free_input']!r}.")
            kw["free_input"] = cons["free_input"]
        for key in ("input_members", "output_members"):
            if key in cons:
                value = cons[key]
                value = [value] if isinstance(value, str) else value
                if not isinstance(value, Sequence) or not value or any(v not in ("sun", "ring", "carrier")
                                                                        for v in value):
                    raise SynthesisError(f"{where}: search.{key} must be a non-empty list of 'sun', 'ring', "
                                         f"'carrier', got {cons[key]!r}.")
                kw[key] = tuple(value)
        if "levels" in cons:
            kw["levels"] = _count(cons["levels"], "search.levels", where, 0)
            if kw["levels"] > 4:
                raise SynthesisError(f"{where}: search.levels must be at most 4, got {kw['levels']}.")
        if "stationary_efficiency" in cons:
            eta = _number(cons["stationary_efficiency"], "search.stationary_efficiency", where)
            if not 0 < eta <= 1:
                raise SynthesisError(f"{where}: search.stationary_efficiency must lie in (0, 1], got {eta!r}.")
            kw["stationary_efficiency"] = eta
        if "top" in cons:
            kw["top"] = _count(cons["top"], "search.top", where, 1)
        if "title" in cons:
            kw["title"] = str(cons["title"])
        return cls(**kw)

    @classmethod
    def from_file(cls, path: str | Path) -> SynthesisSpec:
        """Read a TOML specification (see the module docstring for the keys)."""
        from ..io.source import InputFileError, parse_toml, read_source

        path = Path(path)
        try:
            data = parse_toml(read_source(path), str(path))
        except InputFileError as exc:
            raise SynthesisError(str(exc)) from None
        unknown = set(data) - {"title", "targets", "sets", "elements", "bounds", "search"}
        if unknown:
            raise SynthesisError(f"{path}: unknown table(s)/key(s) {', '.join(sorted(map(repr, unknown)))}; "
                                 "use title, [targets], [sets], [elements], [bounds], [search].")
        for table in ("targets", "sets", "elements", "bounds", "search"):
            if table in data and not isinstance(data[table], Mapping):
                raise SynthesisError(f"{path}: {table} must be a table [{table}].")
        if "targets" not in data:
            raise SynthesisError(f"{path}: missing [targets] table (forward = [...], reverse = [...]).")
        cons = {**data.get("bounds", {}), **data.get("search", {})}
        if "title" in data:
            cons["title"] = data["title"]
        return cls.create(data["targets"], data.get("sets", {"simple": 2}), data.get("elements"), cons,
                          where=str(path))
