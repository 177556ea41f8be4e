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
    hunting = false             # true: only hunting-tooth sets (no common factor sun/planet, planet/ring)
    [search]
    max_members_per_shaft = 2   # ties join pairs of members (default: no limit)
    free_input = true           # also a separate input shaft reached by clutches only
    input_members = ["sun", "ring", "carrier"]    # the input shaft holds one of these (default: any)
    output_members = ["sun", "ring", "carrier"]
    levels = 4                  # bisection levels of the screening (at most 16 // sets are used)
    stationary_efficiency = 0.98
    top = 20
    max_architectures = 1e10    # refuse a larger search before it starts (estimate printed first)
    time_limit = 3600           # s of wall time; the search stops there and says it is incomplete
    [ranking]                   # weights of the criteria (epicyclic.synthesis.ranking), 0 leaves one out
    circulating_power = 2.0
    double_shifts = 10.0
    [sizing]                    # module and face width of every set, ISO 6336 (epicyclic.synthesis.sizing)
    input_torque = 300.0        # N·m
    input_speed = 1000.0        # 1/min
    face_width_ratio = 0.5      # b / d_sun
    [rating]                    # rating inputs of the sizing (defaults: epicyclic.synthesis.sizing.RATING_DEFAULTS)
    material = "18CrNiMo7-6"
    flank_roughness = 3.0       # R_z, µm
    root_roughness = 10.0
    viscosity_40 = 100.0        # mm²/s
    life = 20000.0              # h
    S_Hmin = 1.0
    S_Fmin = 1.4
    application_factor = 1.0
    [teeth]                     # tooth choice per candidate (epicyclic.synthesis.teeth)
    ratio_error = 1.0           # weight of the largest ratio error, per tolerance
    ring_balance = 1.0          # weight of largest/smallest ring diameter − 1, per 0.25

Every problem raises :class:`SynthesisError` naming the file (or ``synthesize``
for the Python call), the key and the fix, as every file error does:
``spec.toml: [bounds], key 'sun': ...`` or ``synthesize: key 'constraints.sun': ...``.

References
----------
Naunheimer, Bertsche, Ryborz, Novak (2011), *Automotive Transmissions*, 2nd ed.,
section 6.2 (overall ratio spread; geometric and progressive ("Jante") ratio
steps, φ_k = φ1 · φ2^(z−k)).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from math import comb
from pathlib import Path
from typing import Any

from ..errors import ModelError
from ..text import short
from ..limits import (MAX_PLANETS, MAX_SYNTHESIS_ARCHITECTURES, MAX_SYNTHESIS_ELEMENTS, MAX_SYNTHESIS_GEARS,
                      MAX_SYNTHESIS_SETS, MAX_SYNTHESIS_TOP, MAX_TEETH, MIN_TEETH)
from .progression import progression_range, progressive_ratios  # re-exported: the spec's ratio series

__all__ = ["SynthesisError", "SynthesisSpec", "progression_range", "progressive_ratios"]


class SynthesisError(ModelError):
    """A synthesis specification that cannot be searched (names the file or call, the key and the fix)."""


@dataclass(frozen=True)
class _Place:
    """Where a specification's values came from, to name them in messages as every file error does.

    ``source`` is the file (its keys live in tables ``[targets]``, ``[sets]``,
    ``[elements]``, ``[bounds]``, ``[search]``; ``tables`` says which table each
    constraint came from) or the Python call (``synthesize``: keys
    ``targets.forward``, ``constraints.sun``, ...).

    >>> _Place("s.toml", {"sun": "bounds"}).key("constraints", "sun")
    "[bounds], key 'sun'"
    >>> _Place("synthesize").key("constraints", "sun")
    "key 'constraints.sun'"
    """

    source: str
    tables: Mapping[str, str] | None = None  # None: the Python call

    def key(self, group: str, name: str | None = None) -> str:
        from ..io.reader import at_key

        if self.tables is None:
            return f"key {group + '.' + name if name else group!r}"
        table = self.tables.get(name or "", "search") if group == "constraints" else group
        return at_key(f"[{table}]", name) if name else f"[{table}]"

    def error(self, group: str, name: str | None, message: str) -> SynthesisError:
        """``"<source>: <key>: <message>"`` (``s.toml: [bounds], key 'sun': ...``)."""
        where = self.key(group, name)
        exc = SynthesisError(f"{self.source}: {where}: {message}")
        exc.source, exc.where = self.source, where
        return exc


def _number(value: Any, place: _Place, group: str, name: str | None) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise place.error(group, name, f"expected a finite number, got {short(value)}.")
    return float(value)


def _count(value: Any, place: _Place, group: str, name: str | None, minimum: int = 0,
           maximum: int | None = None) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or value < minimum:
        raise place.error(group, name, f"expected a whole number >= {minimum}, got {short(value)}.")
    if maximum is not None and value > maximum:
        raise place.error(group, name, f"expected at most {maximum}, got {value!r} (see docs/limits.md).")
    return value


def _pair(value: Any, place: _Place, name: str, integer: bool = False) -> tuple[float, float]:
    if not isinstance(value, Sequence) or isinstance(value, str) or len(value) != 2:
        raise place.error("constraints", name, f"expected a pair [low, high], got {short(value)}.")
    lo, hi = (_count(v, place, "constraints", name, MIN_TEETH, MAX_TEETH) if integer
              else _number(v, place, "constraints", name) for v in value)
    if not lo <= hi:
        raise place.error("constraints", name, f"expected low <= high, got [{lo}, {hi}].")
    return lo, hi


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
    hunting : bool
        Only hunting-tooth simple sets.
    max_members_per_shaft : int or None
    free_input : bool
    input_members, output_members : tuple of str
        The input (output) shaft holds at least one of these members.
    levels : int
    stationary_efficiency : float
    top : int
    max_architectures : int
        Bound on the architectures screened; a larger search is refused before it starts.
    time_limit : float or None
        Wall-time bound, s: the search stops there and its result says it is incomplete.
    weights : tuple of (str, float)
        Ranking weights given (the others keep the defaults of :data:`~epicyclic.synthesis.ranking.CRITERIA`).
    module : float
        Module of every set, mm, for the ring diameters of the ranking where no set is sized.
    input_torque, input_speed, face_width_ratio : float
        N·m, 1/min and b/d_sun of the ISO 6336 sizing of every set (:mod:`~epicyclic.synthesis.sizing`).
    rating : tuple of (str, value)
        Rating inputs of the sizing given (the others: :data:`~epicyclic.synthesis.sizing.RATING_DEFAULTS`).
    tooth_weights : tuple of (str, float)
        Weights of the tooth choice given (the others: :data:`~epicyclic.synthesis.teeth.TOOTH_WEIGHTS`).
    title : str
    source : str
        The file read, or ``synthesize`` (the Python call): first in the messages of the search.
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
    hunting: bool = False
    max_members_per_shaft: int | None = None
    free_input: bool = True
    input_members: tuple[str, ...] = ("sun", "ring", "carrier")
    output_members: tuple[str, ...] = ("sun", "ring", "carrier")
    levels: int = 4
    stationary_efficiency: float = 0.98
    top: int = 20
    max_architectures: int = MAX_SYNTHESIS_ARCHITECTURES
    time_limit: float | None = None
    weights: tuple[tuple[str, float], ...] = ()
    module: float = 2.0
    input_torque: float = 300.0
    input_speed: float = 1000.0
    face_width_ratio: float = 0.5
    rating: tuple[tuple[str, Any], ...] = ()
    tooth_weights: tuple[tuple[str, float], ...] = ()
    title: str = "synthesis"
    source: str = field(default="synthesize", compare=False)

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
        where : str, default "synthesize"
            Where the values came from, for messages: the Python call, or a file (then
            keys are named by their tables, ``[bounds], key 'sun'``).

        Returns
        -------
        SynthesisSpec

        Raises
        ------
        SynthesisError
            An unknown key, a value of the wrong type or out of range, or fewer
            combinations of shift elements than gears; the message names the key.
        """
        place = where if isinstance(where, _Place) else _Place(where)
        kw: dict[str, Any] = {}
        listed = not isinstance(targets, Mapping)
        tmap = {"ratios": targets} if listed else dict(targets)
        unknown = set(tmap) - {"ratios", "forward", "reverse", "tolerance", "spread", "gears", "first", "progression"}
        if unknown:
            raise place.error("targets", None, f"unknown key(s) {', '.join(sorted(map(short, unknown)))}; use "
                                               "forward, reverse, tolerance or spread, gears, first, progression.")
        if "spread" in tmap:
            for key in ("gears", "first"):
                if key not in tmap:
                    raise place.error("targets", key, "missing: a spread of ratios needs the number of gears and "
                                                      "the first ratio (gears = 8, first = 4.7).")
            # the number of gears is checked against the limit before any ratio is built
            gears = _count(tmap["gears"], place, "targets", "gears", 2, MAX_SYNTHESIS_GEARS)
            spread = _number(tmap["spread"], place, "targets", "spread")
            first = _number(tmap["first"], place, "targets", "first")
            prog = _number(tmap.get("progression", 1.0), place, "targets", "progression")
            for key, value, low in (("spread", spread, "> 1"), ("first", first, "> 0"), ("progression", prog, "> 0")):
                if not (value > 1 if key == "spread" else value > 0):
                    raise place.error("targets", key, f"expected a number {low}, got {value!r}.")
            low_p, high_p = progression_range(spread, gears)
            if not low_p < prog < high_p:
                raise place.error("targets", "progression",
                                  f"with spread {spread:g} and {gears} gears the progression must lie in "
                                  f"({low_p:.6g}, {high_p:.6g}), or a ratio step would be <= 1 (the ratios would "
                                  f"not fall); got {prog!r} (1 is a geometric series).")
            forward = list(progressive_ratios(spread, gears, first, prog))
            if not all(math.isfinite(v) and v >= 1e-6 for v in forward) or forward[0] > 1e6:
                raise place.error("targets", "first", f"first ratio {first:g} with spread {spread:g} gives ratios "
                                                      "outside 1e-6 ... 1e6; give a first ratio such as 4.7.")
            reverse = [_number(v, place, "targets", "reverse") for v in _list(tmap.get("reverse", []), place,
                                                                               "reverse")]
        elif "ratios" in tmap:
            values = tmap["ratios"]
            if isinstance(values, (str, bytes)) or not isinstance(values, Sequence) or not values:
                raise place.error("targets", None, f"expected a non-empty list of ratios, got {short(values)}.")
            _list(values, place, None)
            nums = [_number(v, place, "targets", None) for v in values]
            if any(v == 0 for v in nums):
                raise place.error("targets", None, "a target ratio of 0 is no gear; forward ratios must be > 0 and "
                                                   "reverse ratios < 0.")
            forward, reverse = [v for v in nums if v > 0], [v for v in nums if v < 0]
        else:
            forward = [_number(v, place, "targets", "forward") for v in _list(tmap.get("forward", []), place,
                                                                               "forward")]
            reverse = [_number(v, place, "targets", "reverse") for v in _list(tmap.get("reverse", []), place,
                                                                               "reverse")]
        for key, bad, rule in (("forward", [v for v in forward if v <= 0], "> 0"),
                               ("reverse", [v for v in reverse if v >= 0], "< 0")):
            if bad:
                raise place.error("targets", None if listed else key,
                                  f"{key} ratios must be {rule} (a ratio of 0 is no gear), got {bad[0]!r}.")
        if not forward:
            raise place.error("targets", None if listed else "forward", "give at least one forward ratio.")
        kw["forward"] = tuple(sorted(forward, reverse=True))
        kw["reverse"] = tuple(sorted(reverse))
        cons = dict(constraints or {})
        if "tolerance" in tmap:
            cons.setdefault("tolerance", tmap["tolerance"])
        if isinstance(sets, Mapping):
            unknown = set(sets) - {"simple", "plus"}
            if unknown:
                raise place.error("sets", None, f"unknown key(s) {', '.join(sorted(map(short, unknown)))}; use "
                                                "simple and plus.")
            kw["simple"] = _count(sets.get("simple", 0), place, "sets", "simple")
            kw["plus"] = _count(sets.get("plus", 0), place, "sets", "plus")
        else:
            kw["simple"], kw["plus"] = _count(sets, place, "sets", None, 1), 0
        if not 1 <= kw["simple"] + kw["plus"] <= MAX_SYNTHESIS_SETS:
            raise place.error("sets", None, f"give 1 to {MAX_SYNTHESIS_SETS} planetary sets in all (simple + plus), "
                                            f"got {kw['simple'] + kw['plus']} (see docs/limits.md).")
        elements = dict(elements or {"brakes": 2, "clutches": 2})
        unknown = set(elements) - {"brakes", "clutches", "engaged"}
        if unknown:
            raise place.error("elements", None, f"unknown key(s) {', '.join(sorted(map(short, unknown)))}; use "
                                                "brakes, clutches, engaged.")
        kw["brakes"] = _count(elements.get("brakes", 0), place, "elements", "brakes")
        kw["clutches"] = _count(elements.get("clutches", 0), place, "elements", "clutches")
        total = kw["brakes"] + kw["clutches"]
        gears = len(kw["forward"]) + len(kw["reverse"])
        if total > MAX_SYNTHESIS_ELEMENTS:
            raise place.error("elements", None, f"at most {MAX_SYNTHESIS_ELEMENTS} shift elements (brakes + "
                                                f"clutches), got {total} (see docs/limits.md).")
        if gears > MAX_SYNTHESIS_GEARS:
            raise place.error("targets", None, f"at most {MAX_SYNTHESIS_GEARS} target ratios, got {gears} "
                                               "(see docs/limits.md).")
        if "engaged" in elements:
            engaged = elements["engaged"]
            if isinstance(engaged, (str, bytes)) or (isinstance(engaged, Sequence) and not 0 < len(engaged) <= total):
                raise place.error("elements", "engaged", f"expected a number or a list of 1 to {max(total, 1)} "
                                                         f"numbers, got {short(engaged)}.")
            engaged = (engaged,) if not isinstance(engaged, Sequence) else tuple(engaged)
            kw["engaged"] = tuple(_count(e, place, "elements", "engaged", 1) for e in engaged)
            repeated = sorted({e for e in kw["engaged"] if kw["engaged"].count(e) > 1})
            if repeated:
                raise place.error("elements", "engaged", f"{repeated[0]} is listed twice; each number engaged per "
                                                         "gear is searched once, so give it once.")
        else:
            kw["engaged"] = tuple(k for k in range(1, total) if comb(total, k) >= gears)
        for k in kw["engaged"]:
            if k >= total or comb(total, k) < gears:
                raise place.error(
                    "elements", "engaged",
                    f"{total} shift elements with {k} engaged per gear give {comb(total, k) if k < total else 0} "
                    f"combinations, fewer than the {gears} gears asked for; add brakes or clutches, or change "
                    "the number engaged.")
        if not kw["engaged"]:
            raise place.error("elements", None, f"{total} shift elements cannot give {gears} gears; add brakes or "
                                                "clutches.")
        return cls._with_constraints(kw, cons, place)

    @classmethod
    def _with_constraints(cls, kw: dict[str, Any], cons: dict[str, Any], place: _Place) -> SynthesisSpec:
        allowed = {"tolerance", "stationary_ratio", "sun", "planet", "planets", "hunting", "max_members_per_shaft",
                   "free_input", "input_members", "output_members", "levels", "stationary_efficiency", "top",
                   "max_architectures", "time_limit", "weights", "module", "input_torque", "input_speed",
                   "face_width_ratio", "rating", "tooth_weights", "title"}
        for old in ("allowable_stress", "face_width_factor"):
            if old in cons:
                raise place.error("constraints", old, "the Lewis pre-dimensioning was replaced by the ISO 6336 sizing; "
                                                      "give face_width_ratio (b/d_sun) and the rating inputs "
                                                      "([rating] material, flank_roughness, ...) instead.")
        unknown = set(cons) - allowed
        if unknown:
            name = sorted(unknown)[0]
            raise place.error("constraints", name, f"unknown constraint; allowed: {', '.join(sorted(allowed))}.")

        def bad(name: str, message: str) -> SynthesisError:
            return place.error("constraints", name, message)

        if "tolerance" in cons:
            kw["tolerance"] = _number(cons["tolerance"], place, "constraints", "tolerance")
            if not 0 < kw["tolerance"] <= 0.2:
                raise bad("tolerance", f"the tolerance is relative (0.01 = 1 %) and must lie in (0, 0.2], "
                                       f"got {kw['tolerance']!r}.")
        if "stationary_ratio" in cons:
            lo, hi = _pair(cons["stationary_ratio"], place, "stationary_ratio")
            if lo <= 1.0:
                raise bad("stationary_ratio", f"the bounds of |i0| must exceed 1 (ring larger than sun), "
                                              f"got [{lo}, {hi}].")
            kw["stationary_ratio"] = (lo, hi)
        for key in ("sun", "planet"):
            if key in cons:
                kw[key] = _pair(cons[key], place, key, integer=True)
        if "planets" in cons:
            p = cons["planets"]
            p = (p,) if isinstance(p, int) else p
            if isinstance(p, (str, bytes)) or not isinstance(p, Sequence) or not 0 < len(p) <= MAX_PLANETS:
                raise bad("planets", f"expected a list of 1 to {MAX_PLANETS} planet numbers, got {short(p)}.")
            kw["planets"] = tuple(sorted({_count(v, place, "constraints", "planets", 1, MAX_PLANETS) for v in p}))
        if cons.get("max_members_per_shaft") is not None:
            kw["max_members_per_shaft"] = _count(cons["max_members_per_shaft"], place, "constraints",
                                                 "max_members_per_shaft", 2)
        if "hunting" in cons:
            if not isinstance(cons["hunting"], bool):
                raise bad("hunting", f"expected true or false, got {short(cons['hunting'])}.")
            kw["hunting"] = cons["hunting"]
        if "free_input" in cons:
            if not isinstance(cons["free_input"], bool):
                raise bad("free_input", f"expected true or false, got {short(cons['free_input'])}.")
            kw["free_input"] = cons["free_input"]
        for key in ("input_members", "output_members"):
            if key in cons:
                value = cons[key]
                value = [value] if isinstance(value, str) else value
                if not isinstance(value, Sequence) or not value or any(v not in ("sun", "ring", "carrier")
                                                                        for v in value):
                    raise bad(key, f"expected a non-empty list of 'sun', 'ring', 'carrier', got {short(cons[key])}.")
                kw[key] = tuple(value)
        if "levels" in cons:
            kw["levels"] = _count(cons["levels"], place, "constraints", "levels", 0, 4)
        if "stationary_efficiency" in cons:
            eta = _number(cons["stationary_efficiency"], place, "constraints", "stationary_efficiency")
            if not 0 < eta <= 1:
                raise bad("stationary_efficiency", f"expected an efficiency in (0, 1], got {eta!r}.")
            kw["stationary_efficiency"] = eta
        if "top" in cons:
            kw["top"] = _count(cons["top"], place, "constraints", "top", 1, MAX_SYNTHESIS_TOP)
        if "max_architectures" in cons:
            value = cons["max_architectures"]
            if isinstance(value, float) and value.is_integer():
                value = int(value)
            kw["max_architectures"] = _count(value, place, "constraints", "max_architectures", 1, 10**15)
        if cons.get("time_limit") is not None:
            limit = _number(cons["time_limit"], place, "constraints", "time_limit")
            if not 0 < limit <= 30 * 86400:
                raise bad("time_limit", f"expected seconds in (0, 2592000] (30 days), got {limit!r}.")
            kw["time_limit"] = limit
        if "weights" in cons:
            from .ranking import check_weights

            given = cons["weights"]
            if not isinstance(given, Mapping):
                raise bad("weights", f"expected a table of criterion = weight, got {short(given)}.")
            check_weights(given, lambda name, message: bad(name if place.tables is not None else f"weights.{name}",
                                                           message))
            kw["weights"] = tuple((str(k), float(v)) for k, v in given.items())
        if "module" in cons:
            module = _number(cons["module"], place, "constraints", "module")
            if not 0.1 <= module <= 50:
                raise bad("module", f"expected a module in mm within [0.1, 50], got {module!r}.")
            kw["module"] = module
        for key, low, high, unit in (("input_torque", 1e-3, 1e6, "N·m"), ("input_speed", 1.0, 1e5, "1/min"),
                                     ("face_width_ratio", 0.05, 2.0, "(b/d_sun)")):
            if key in cons:
                value = _number(cons[key], place, "constraints", key)
                if not low <= value <= high:
                    raise bad(key, f"expected {low:g} … {high:g} {unit}, got {value!r}.")
                kw[key] = value
        if "rating" in cons:
            from .sizing import check_rating

            kw["rating"] = check_rating(cons["rating"], lambda name, message: bad(
                name if place.tables is not None or name == "rating" else f"rating.{name}", message))
        if "tooth_weights" in cons:
            from .teeth import check_tooth_weights

            given = cons["tooth_weights"]
            if not isinstance(given, Mapping):
                raise bad("tooth_weights", f"expected a table of criterion = weight, got {short(given)}.")
            kw["tooth_weights"] = tuple(check_tooth_weights(
                given, lambda name, message: bad(name if place.tables is not None else f"tooth_weights.{name}",
                                                 message)).items())
        if "title" in cons:
            kw["title"] = str(cons["title"])
        return cls(**kw, source=place.source)

    @classmethod
    def from_file(cls, path: str | Path) -> SynthesisSpec:
        """Read a TOML specification (see the module docstring for the keys).

        Raises
        ------
        SynthesisError
            A bad file or value; the message names the file, the table and the key
            (``spec.toml: [bounds], key 'sun': ...``).
        """
        from ..io.source import InputFileError, read_source

        path = Path(path)
        try:
            text = read_source(path)
        except InputFileError as exc:
            raise SynthesisError(str(exc)) from None
        return cls.from_text(text, str(path))

    @classmethod
    def from_text(cls, text: str, source: str = "spec.toml") -> SynthesisSpec:
        """Read a TOML specification from its text (the keys of :meth:`from_file`; the page reads it so).

        Parameters
        ----------
        text : str
            The TOML text.
        source : str, default "spec.toml"
            What the messages call it, in place of a file name.

        Raises
        ------
        SynthesisError
            Bad TOML or a bad value, named by ``source``, table and key.
        """
        from ..io.source import InputFileError, parse_toml

        try:
            data = parse_toml(text, source)
        except InputFileError as exc:
            raise SynthesisError(str(exc)) from None
        path = source
        tables_known = ("targets", "sets", "elements", "bounds", "search", "ranking", "sizing", "rating", "teeth")
        unknown = set(data) - {"title", *tables_known}
        if unknown:
            raise SynthesisError(f"{path}: unknown table(s)/key(s) {', '.join(sorted(map(short, unknown)))}; "
                                 "use title, [targets], [sets], [elements], [bounds], [search], [ranking], [sizing], "
                                 "[rating], [teeth].")
        for table in tables_known:
            if table in data and not isinstance(data[table], Mapping):
                raise SynthesisError(f"{path}: key {table!r}: expected a table [{table}], got {short(data[table])}.")
        if "targets" not in data:
            raise SynthesisError(f"{path}: missing [targets] table (forward = [...], reverse = [...]).")
        bounds, search, ranking = data.get("bounds", {}), data.get("search", {}), dict(data.get("ranking", {}))
        cons = {**bounds, **search}
        tables = {"tolerance": "targets", **{k: "bounds" for k in bounds}, **{k: "search" for k in search}}
        if "module" in ranking:
            cons["module"] = ranking.pop("module")
        if ranking:
            cons["weights"] = ranking
        tables.update({k: "ranking" for k in ("module", "weights", *ranking)})
        sizing = data.get("sizing", {})
        for key, value in sizing.items():
            if key not in ("input_torque", "input_speed", "face_width_ratio", "allowable_stress", "face_width_factor"):
                raise SynthesisError(f"{path}: [sizing], key {key!r}: unknown; use input_torque, input_speed, "
                                     "face_width_ratio.")
            cons[key] = value
            tables[key] = "sizing"
        for table, key in (("rating", "rating"), ("teeth", "tooth_weights")):
            if table in data:
                cons[key] = data[table]
                tables.update({key: table, **{str(k): table for k in data[table]}})
        if "title" in data:
            cons["title"] = data["title"]
        return cls.create(data["targets"], data.get("sets", {"simple": 2}), data.get("elements"), cons,
                          where=_Place(str(path), tables))  # type: ignore[arg-type]


def _list(value: Any, place: _Place, name: str) -> Sequence[Any]:
    """A list of target ratios (``[targets]`` forward or reverse)."""
    if isinstance(value, (str, bytes)) or not isinstance(value, Sequence):
        raise place.error("targets", name, f"expected a list of ratios, got {short(value)}.")
    if len(value) > MAX_SYNTHESIS_GEARS:  # before any value is read
        raise place.error("targets", name, f"at most {MAX_SYNTHESIS_GEARS} target ratios, got {len(value)} "
                                           "(see docs/limits.md).")
    return value
