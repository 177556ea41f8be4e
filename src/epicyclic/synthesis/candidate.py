"""One synthesised transmission: architecture, tooth counts, schedule, figures of merit, files.

A :class:`Candidate` is plain data (it travels between Dask workers).  It
becomes a :class:`~epicyclic.transmission.Transmission` (:meth:`Candidate.transmission`)
and a train file that ``epicyclic analyze`` and ``epicyclic gears`` read
(:meth:`Candidate.toml`).  Its figures of merit come from the project's own
solver (:func:`evaluate`): efficiency in drive per gear with losses by the
direction of rolling power, the largest shift-element torque, the largest
planet speed relative to its carrier, and the shift sequence.

References
----------
Brandenberger 1952, eqs. 7–10 (efficiency by the direction of power flow);
tec-science, "Willis-Gleichung" (planet speed n_P z_P = n_T (z_P + z_S) − n_S z_S);
Naunheimer et al. 2011, section 6.2 (ratio steps).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from .kinematics import element_shafts
from .mechanisms import Mechanism
from .sizing import RATING_DEFAULTS, SetSize, rating_spec, size_sets
from .teeth import SetTeeth

__all__ = ["Candidate", "evaluate", "gear_names"]


def gear_names(forward: int, reverse: int) -> list[str]:
    """``["1", …, "n", "R"]`` (``"R1"``, ``"R2"`` … for several reverse gears)."""
    rev = ["R"] if reverse == 1 else [f"R{k + 1}" for k in range(reverse)]
    return [str(k + 1) for k in range(forward)] + rev


@dataclass(frozen=True)
class Candidate:
    """A transmission found by the synthesis.

    Attributes
    ----------
    mechanism : Mechanism
    input, output : int
        Shaft numbers.
    elements : tuple of int
        Shift-element numbers (brakes, then clutches).
    schedule : tuple of tuple of int
        Engaged element numbers per gear (forward gears first, then reverse).
    teeth : tuple of SetTeeth
    ratios, targets : tuple of float
        Gear ratios with these tooth counts, and the targets, per gear.
    metrics : dict
        Filled by :func:`evaluate` (see :attr:`HEADER`).
    sizes : tuple of SetSize or None
        Module and face width per set from :func:`evaluate` (None: a plus set, no tooth geometry).
    input_torque, input_speed : float
        N·m and 1/min at the operating point of the train file (the point the sets are sized for).
    rating : tuple of (str, value)
        The rating inputs the sets were sized with (:data:`~epicyclic.synthesis.sizing.RATING_KEYS`);
        the train file's ``[rating]`` table.
    """

    mechanism: Mechanism
    input: int
    output: int
    elements: tuple[int, ...]
    schedule: tuple[tuple[int, ...], ...]
    teeth: tuple[SetTeeth, ...]
    ratios: tuple[float, ...]
    targets: tuple[float, ...]
    forward: int
    stationary_efficiency: float = 0.98
    metrics: dict[str, Any] = field(default_factory=dict, compare=False)
    sizes: tuple[SetSize | None, ...] = field(default=(), compare=False)
    input_torque: float = field(default=100.0, compare=False)
    input_speed: float = field(default=1000.0, compare=False)
    rating: tuple[tuple[str, Any], ...] = field(default=(), compare=False)

    # ------------------------------------------------------------------ names
    def shaft_name(self, shaft: int) -> str:
        """A shaft's name in the candidate's files and tables: ``in``, ``out``, or its members.

        Members are named by set (from 1) and letter: ``s1_c2`` joins sun 1 and carrier 2;
        a shaft with no member is ``x<number>``.

        Parameters
        ----------
        shaft : int
            The shaft's number in the mechanism.

        Returns
        -------
        str
        """
        if shaft == self.input:
            return "in"
        if shaft == self.output:
            return "out"
        members = self.mechanism.shaft_members(shaft)
        return "_".join(f"{p[0]}{k + 1}" for k, p in members) or f"x{shaft}"

    def element_name(self, element: int) -> str:
        """A shift element's name: ``B1``, ``B2``, ... for brakes, ``K1``, ``K2``, ... for clutches.

        Numbered in the order of the candidate's elements.

        Parameters
        ----------
        element : int
            The element's number in the mechanism's list of possible elements (one of
            :attr:`elements`).

        Returns
        -------
        str

        Raises
        ------
        ValueError
            ``element`` is not one of the candidate's elements.
        """
        shafts = element_shafts(self.mechanism.shafts)
        brakes = [e for e in self.elements if len(shafts[e]) == 1]
        clutches = [e for e in self.elements if len(shafts[e]) == 2]
        return f"B{brakes.index(element) + 1}" if element in brakes else f"K{clutches.index(element) + 1}"

    @property
    def gears(self) -> list[str]:
        return gear_names(self.forward, len(self.schedule) - self.forward)

    @property
    def named_schedule(self) -> dict[str, tuple[str, ...]]:
        return {g: tuple(sorted(self.element_name(e) for e in combo)) for g, combo in zip(self.gears, self.schedule)}

    def _canonical(self, with_teeth: bool) -> tuple:
        from .mechanisms import set_permutations

        shafts = element_shafts(self.mechanism.shafts)
        best = None
        for perm in set_permutations(self.mechanism.kinds):
            seq = [self.mechanism.members[3 * perm[j] + q] for j in range(self.mechanism.sets) for q in range(3)]
            number: dict[int, int] = {}
            for s in seq:
                number.setdefault(s, len(number))
            if self.mechanism.free_input:
                number.setdefault(self.mechanism.member_shafts, len(number))
            elems = tuple(sorted(tuple(sorted(number[s] for s in shafts[e])) for e in self.elements))
            teeth = tuple((self.teeth[perm[j]].z_sun, self.teeth[perm[j]].z_ring) for j in range(len(perm))) \
                if with_teeth else ()
            k = (self.mechanism.kinds, tuple(number[s] for s in seq), number[self.input], number[self.output], elems,
                 teeth)
            best = k if best is None or k < best else best
        return best

    @property
    def key(self) -> tuple:
        """Canonical form of architecture and tooth counts (sets permuted within kinds); equal keys are isomorphic."""
        return self._canonical(True)

    @property
    def architecture_key(self) -> tuple:
        """Canonical form of the architecture alone (ties, input, output, shift elements)."""
        return self._canonical(False)

    @classmethod
    def from_transmission(cls, transmission, stationary_efficiency: float = 0.98) -> Candidate:
        """The candidate that describes an existing :class:`~epicyclic.transmission.Transmission`.

        Lets a published transmission (e.g. from :mod:`epicyclic.transmission.library`)
        be compared with synthesised ones (:attr:`architecture_key`).  Sets
        without simple tooth counts get |i0| as a fraction with a denominator of
        at most 100 (z_sun, z_ring).

        Parameters
        ----------
        transmission : Transmission
            Planetary sets, clutches and brakes only; no set member on the housing;
            the output on a set member.
        stationary_efficiency : float, default 0.98
            η0 of every set for the candidate's efficiency metrics.

        Returns
        -------
        Candidate
            Gears ordered as a synthesis orders them: forward by falling ratio, then
            reverse.

        Raises
        ------
        SynthesisError
            A transmission outside the synthesis space (a gear stage, a member tied to
            the housing, an output that is no set member).
        """
        from fractions import Fraction

        from ..model import Brake, Clutch
        from ..model.elements import HOUSING
        from .spec import SynthesisError

        train = transmission.train
        # simple sets first, then plus sets: the order of SynthesisSpec.kinds
        sets = sorted(train.planetary_sets, key=lambda p: p.stationary_ratio > 0)
        if len(sets) != len(train.elements) - len(train.shift_elements):
            raise SynthesisError("from_transmission: only planetary sets, clutches and brakes can be described.")
        number: dict[str, int] = {}
        members = []
        if any(HOUSING in (p.sun, p.ring, p.carrier) for p in sets):
            raise SynthesisError("from_transmission: a set member tied to the housing is outside the synthesis "
                                 "space (members are joined to each other; the housing only through brakes).")
        for p in sets:
            for shaft in (p.sun, p.ring, p.carrier):
                members.append(number.setdefault(shaft, len(number)))
        free = transmission.input not in number
        if free:
            number[transmission.input] = len(number)
        if transmission.output not in number:
            raise SynthesisError("from_transmission: the output must be a member of a planetary set.")
        kinds = tuple("simple" if p.stationary_ratio < 0 else "plus" for p in sets)
        mech = Mechanism(kinds, tuple(members), free)
        index = {s: e for e, s in enumerate(element_shafts(mech.shafts))}
        elements, by_name = [], {}
        for e in train.shift_elements:
            if isinstance(e, Brake):
                key: tuple[int, ...] = (number[e.shaft],)
            elif isinstance(e, Clutch):
                key = tuple(sorted((number[e.first], number[e.second])))
            else:  # pragma: no cover - GearTrain has no other shift elements
                continue
            elements.append(index[key])
            by_name[e.name] = index[key]
        teeth = []
        for p in sets:
            if p.teeth is not None and p.teeth.kind == "simple":
                teeth.append(SetTeeth("simple", p.teeth.sun, p.teeth.ring, p.teeth.planet[0], p.planets))
            else:
                f = Fraction(abs(p.stationary_ratio)).limit_denominator(100)
                teeth.append(SetTeeth("simple" if p.stationary_ratio < 0 else "plus", f.denominator, f.numerator,
                                      None, p.planets))
        ratios = transmission.ratios
        forward = [g for g in transmission.gears if ratios[g] > 0]
        reverse = [g for g in transmission.gears if ratios[g] < 0]
        order = sorted(forward, key=lambda g: -ratios[g]) + sorted(reverse, key=lambda g: ratios[g])
        schedule = tuple(tuple(sorted(by_name[n] for n in transmission.schedule[g])) for g in order)
        values = tuple(ratios[g] for g in order)
        return cls(mech, number[transmission.input], number[transmission.output], tuple(sorted(elements)), schedule,
                   tuple(teeth), values, values, len(forward), stationary_efficiency)

    def describe(self) -> str:
        """Architecture in words: ties, input, output, brakes and clutches."""
        shafts = element_shafts(self.mechanism.shafts)
        parts = []
        for e in self.elements:
            s = shafts[e]
            parts.append(f"{self.element_name(e)}: {self.shaft_name(s[0])}" +
                         (f"–{self.shaft_name(s[1])}" if len(s) == 2 else " held"))
        return (f"ties {self.mechanism.describe()}; in = {self.shaft_name(self.input)} "
                f"({_members(self.mechanism, self.input)}), out = {_members(self.mechanism, self.output)}; "
                + "; ".join(sorted(parts)))

    # ------------------------------------------------------------------ model
    def train(self, name: str = "synthesised transmission"):
        """The :class:`~epicyclic.GearTrain` (all shift elements open)."""
        from ..model import Brake, Clutch, GearTrain, PlanetarySet

        elements: list = []
        for k, t in enumerate(self.teeth):
            s, r, c = (self.shaft_name(x) for x in self.mechanism.set_shafts(k))
            if t.z_planet is not None:
                elements.append(PlanetarySet.simple(f"P{k + 1}", sun=s, ring=r, carrier=c, z_sun=t.z_sun,
                                                    z_planet=t.z_planet, z_ring=t.z_ring, planets=t.planets,
                                                    stationary_efficiency=self.stationary_efficiency))
            else:
                elements.append(PlanetarySet(f"P{k + 1}", s, r, c, t.stationary_ratio, self.stationary_efficiency,
                                             t.planets))
        shafts = element_shafts(self.mechanism.shafts)
        for e in sorted(self.elements, key=self.element_name):
            s = shafts[e]
            if len(s) == 1:
                elements.append(Brake(self.element_name(e), self.shaft_name(s[0])))
            else:
                elements.append(Clutch(self.element_name(e), self.shaft_name(s[0]), self.shaft_name(s[1])))
        return GearTrain(elements, name=name)

    def transmission(self, name: str = "synthesised transmission"):
        """The :class:`~epicyclic.transmission.Transmission` with this schedule."""
        from ..transmission import Transmission

        return Transmission(self.train(name), self.named_schedule, "in", "out", name=name)

    def toml(self, title: str = "synthesised transmission") -> str:
        """A train file (TOML) with a ``[transmission]`` table; ``epicyclic gears`` reads it."""
        import json

        # the title as a TOML basic string (JSON's escapes are TOML's), on one line in the comment
        lines = [f"# {''.join(c if c.isprintable() else ' ' for c in title)}", f"# Architecture: {self.describe()}",
                 "# Ratios: " + ", ".join(f"{g}: {r:.4f} (target {t:.4f})"
                                          for g, r, t in zip(self.gears, self.ratios, self.targets)),
                 "# Written by epicyclic synthesize.", "", "title = " + json.dumps(title, ensure_ascii=False).replace("\x7f", "\\u007f")]
        for k, t in enumerate(self.teeth):
            s, r, c = (self.shaft_name(x) for x in self.mechanism.set_shafts(k))
            lines += ["", "[[planetary]]", f'name = "P{k + 1}"', f'sun = "{s}"', f'ring = "{r}"', f'carrier = "{c}"']
            if t.z_planet is not None:
                lines.append(f"teeth = {{ sun = {t.z_sun}, planet = {t.z_planet}, ring = {t.z_ring} }}")
                lines.append(f"planets = {t.planets}")
            else:
                sign = "-" if t.kind == "simple" else ""
                lines.append(f'stationary_ratio = "{sign}{t.z_ring}/{t.z_sun}"')
            lines.append(f"stationary_efficiency = {self.stationary_efficiency}")
            size = self.sizes[k] if k < len(self.sizes) else None
            if size is not None:
                lines += [f"# ISO 6336 sizing: smallest ISO 54 module meeting S_Hmin and S_Fmin in every gear (set by "
                          f"gear {size.gear}; lowest S_H {size.safety_pitting:.2f}, S_F {size.safety_bending:.2f}; "
                          "epicyclic.synthesis.sizing)",
                          "[planetary.geometry]", f"module = {size.module}", f"face_width = {size.face_width!r}"]
        shafts = element_shafts(self.mechanism.shafts)
        for e in sorted(self.elements, key=self.element_name):
            s = shafts[e]
            if len(s) == 2:
                lines += ["", "[[clutch]]", f'name = "{self.element_name(e)}"', f'first = "{self.shaft_name(s[0])}"',
                          f'second = "{self.shaft_name(s[1])}"', "engaged = false"]
            else:
                lines += ["", "[[brake]]", f'name = "{self.element_name(e)}"', f'shaft = "{self.shaft_name(s[0])}"',
                          "engaged = false"]
        if self.rating:
            lines += ["", "# the rating inputs the sets were sized with (epicyclic rate reads them)", "[rating]"]
            lines += [f"{k} = {_toml_value(v)}" for k, v in self.rating if k != "viscosity_40"]
            lines += ["[rating.lubricant]", f"viscosity_40 = {_toml_value(dict(self.rating)['viscosity_40'])}"]
        lines += ["", f"# first gear at {self.input_speed:g} 1/min and {self.input_torque:g} N·m on the input "
                  "(epicyclic analyze solves it)", "[operating_point]", f'gear = "{self.gears[0]}"',
                  f"speeds = {{ in = {float(self.input_speed)} }}", f"torques = {{ in = {float(self.input_torque)} }}",
                  'drives = ["in"]', 'loads = ["out"]']
        lines += ["", "[transmission]", 'input = "in"', 'output = "out"', "", "[transmission.schedule]"]
        for gear, engaged in self.named_schedule.items():
            lines.append(f'"{gear}" = [' + ", ".join(f'"{n}"' for n in engaged) + "]")
        return "\n".join(lines) + "\n"

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data: architecture, ties, input/output, named schedule, ratios, targets, teeth, metrics.

        Returns
        -------
        dict
            ``architecture``, ``ties``, ``input``, ``output``, ``schedule`` (gear → element
            names), ``ratios`` and ``targets`` (gear → n_in/n_out), ``teeth`` and ``sizes`` (module,
            face width in mm, sizing gear, sun torque in N·m, lowest S_H and S_F, per set), ``input_torque``
            (N·m), ``rating`` (the inputs sized with) and the ranking metrics (errors, efficiencies, element torque, planet speed, double shifts).
        """
        return {"architecture": self.describe(), "ties": self.mechanism.describe(),
                "input": self.shaft_name(self.input), "output": self.shaft_name(self.output),
                "schedule": {g: list(v) for g, v in self.named_schedule.items()},
                "ratios": dict(zip(self.gears, self.ratios)), "targets": dict(zip(self.gears, self.targets)),
                "teeth": [t.to_dict() for t in self.teeth],
                "sizes": [None if z is None else z.to_dict() for z in self.sizes], "input_torque": self.input_torque,
                "rating": dict(self.rating), **self.metrics}


def _members(mech: Mechanism, shaft: int) -> str:
    members = mech.shaft_members(shaft)
    return "+".join(f"{p}{k + 1}" for k, p in members) or "separate shaft"


def _toml_value(value: Any) -> str:
    """A rating input as TOML: a quoted string or a number."""
    return f'"{value}"' if isinstance(value, str) else repr(float(value))


def evaluate(candidate: Candidate, input_torque: float | None = None, rating: Any = (),
             face_width_ratio: float = 0.5, input_speed: float = 1000.0) -> Candidate:
    """Fill the figures of merit with the project's solver (drive and coast, losses by power flow).

    Metrics (all per input speed, torque or power):

    * ``efficiency`` per gear in drive, ``efficiency_mean`` over forward gears,
      ``efficiency_min`` (None where a gear self-locks);
    * ``element_torque_max``: largest torque on an engaged clutch or brake, × T_in;
    * ``element_capacity``: sum over the elements of each one's largest torque, × T_in;
    * ``slip_speed_max``: largest slip of an open element in a forward gear, × n_in;
    * ``circulating_power_max``: largest power circulating in a loop, any gear, × P_in
      (``circulation_indeterminate``: gears where the torque split is statically indeterminate);
    * ``planet_speed_max``: largest |n_planet − n_carrier|, × n_in;
    * ``double_shifts``: consecutive forward gears that change more than one element;
    * ``step_irregularity``: largest change of log step between neighbouring steps;
    * ``shafts``: number of shafts (fewer is simpler); ``ratio_error``: largest |r/target − 1|.

    With ``input_torque`` (N·m) every simple set is also sized by ISO 6336 in every gear at
    ``input_speed`` (:func:`~epicyclic.synthesis.sizing.size_sets`): the candidate's ``sizes``.

    Parameters
    ----------
    candidate : Candidate
    input_torque : float, optional
        N·m at the sizing point; None leaves the sets unsized.
    rating : mapping or sequence of (key, value), optional
        Rating inputs over :data:`~epicyclic.synthesis.sizing.RATING_DEFAULTS`.
    face_width_ratio : float, default 0.5
        b / d_sun.
    input_speed : float, default 1000
        1/min at the sizing point.

    Returns
    -------
    Candidate
        With ``metrics`` (and ``sizes``) filled.

    Raises
    ------
    RatingError
        A set that no module up to 50 mm can carry.

    References
    ----------
    ISO 6336-2:2019 and -3:2019 (via :func:`~epicyclic.rating.sizing.smallest_module`).
    """
    t = candidate.transmission()
    analysis = t.analyze_all(input_speed=input_speed, input_torque=input_torque or 100.0)
    eff = {g.gear: g.efficiency_drive for g in analysis.gears}
    torque = max((abs(v) for g in analysis.gears for v in g.element_torques.values()), default=0.0)
    capacity: dict[str, float] = {}  # each element's largest torque over the gears
    for g in analysis.gears:
        for name, v in g.element_torques.items():
            capacity[name] = max(capacity.get(name, 0.0), abs(v))
    forward_gears = analysis.gears[:candidate.forward]
    slip = max((abs(v) for g in forward_gears for v in g.slip_speeds.values()), default=0.0)
    circulating = [g.circulating_power_ratio for g in analysis.gears]
    indeterminate = [g.gear for g, c in zip(analysis.gears, circulating) if c is None]
    planet = 0.0
    sets = [e for e in t.train.planetary_sets]
    for g in analysis.gears:
        speeds = g.drive
        n_in = speeds.speed("in")
        for s in sets:
            if s.teeth is None:
                continue
            rel = speeds.speed(s.sun) - speeds.speed(s.carrier)
            for f in s.teeth.planet_factors:
                planet = max(planet, abs(f * rel / n_in))
    schedule = candidate.schedule[:candidate.forward]
    doubles = sum(len(set(a) ^ set(b)) > 2 for a, b in zip(schedule, schedule[1:]))
    fwd = np.array(candidate.ratios[:candidate.forward])
    steps = np.log(fwd[:-1] / fwd[1:]) if fwd.size > 1 else np.array([])
    irregular = float(np.max(np.abs(np.diff(steps)))) if steps.size > 1 else 0.0
    forward_eff = [eff[g] for g in candidate.gears[:candidate.forward]]
    defined = [e for e in forward_eff if e is not None]
    metrics = {
        "efficiency": eff,
        "efficiency_mean": float(np.mean(defined)) if defined else None,
        "efficiency_min": float(min(defined)) if len(defined) == len(forward_eff) else None,
        "element_torque_max": float(torque),
        "element_capacity": float(sum(capacity.values())),
        "slip_speed_max": float(slip),
        "circulating_power_max": float(max((c for c in circulating if c is not None), default=0.0)),
        "circulation_indeterminate": indeterminate,
        "planet_speed_max": float(planet),
        "double_shifts": int(doubles),
        "step_irregularity": irregular,
        "shafts": candidate.mechanism.shafts,
        "ratio_error": float(max(abs(r / g - 1) for r, g in zip(candidate.ratios, candidate.targets))),
    }
    sizes: tuple[SetSize | None, ...] = ()
    values = tuple(dict(rating).items())
    if input_torque is not None:
        full = tuple({**RATING_DEFAULTS, **dict(values)}.items())
        solutions = {g.gear: g.drive for g in analysis.gears}
        names = [None if tooth.z_planet is None else f"P{k + 1}" for k, tooth in enumerate(candidate.teeth)]
        sizes = size_sets(solutions, names, rating_spec(full), face_width_ratio, input_torque)
        metrics["modules"] = [None if z is None else z.module for z in sizes]
        values = full
    return replace(candidate, metrics=metrics, sizes=sizes, rating=values if input_torque is not None else (),
                   input_torque=candidate.input_torque if input_torque is None else float(input_torque),
                   input_speed=float(input_speed))
