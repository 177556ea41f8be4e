"""A train over a duty cycle: energies by element and source, bearing lives, cycle efficiency.

:func:`analyse_duty_cycle` solves every load case of a :class:`~epicyclic.rating.DutyCycle`
with the elements' loss models, vectorised: the cases that run in the same gear
with the same kind of inputs (the same shafts given, the same drives and loads)
are one batch solve (:func:`~epicyclic.losses.solve_batch_with_losses`), however
many there are.  Per case it keeps

* the energy in, out and lost: E = P t with the case's hours t (per hour of the
  cycle for a cycle of shares without total hours), lost by element and source
  (``mesh``, ``bearing``, ``drag`` and whatever sources the loss models report);
* the bearing loads: the planets' bearing loads from the tooth forces (the vector
  sum of all meshes of a planet, also of one that several sets share:
  :func:`~epicyclic.geometry.share_planets`) at the planet's speed relative to the
  carrier, n_p − n_c = k (n_s − n_c); the central bearings' load (the net force of
  the planets on the member, zero for equally spaced planets, plus a given
  ``external_load``) at the member's speed relative to the housing.

and over the cycle the cycle efficiency η = Σ E_out / Σ E_in and each bearing's
life over the spectrum (:class:`~epicyclic.rating.duty_result.BearingLife`).

References
----------
ISO 281:2007, 5.3, 7.3 and clause 9; Palmgren 1924, Miner 1945 (life under variable load);
Queitsch part I, eqs. (23)–(26) (planet bearing load from the tooth forces);
Brandenberger 1952, eqs. 3', 7 (losses in the direction of the rolling power).
"""

from __future__ import annotations

import copy
from collections.abc import Mapping
from types import MappingProxyType
from typing import Any

import numpy as np

from ..errors import EpicyclicError
from ..geometry.forces import planetary_forces
from ..geometry.set_geometry import SetGeometry
from ..geometry.shared_planets import share_planets
from ..losses.solve import solve_batch_with_losses, solve_with_losses
from ..model.planetary import PlanetarySet
from ..model.train import GearTrain
from ..transmission.errors import UnknownGearError
from .bearing_life import BearingRating
from .bearing_loads import set_loads, solution_view, unit_forces
from .duty_cycle import DutyCycle, DutyCycleError
from .duty_result import BearingLife, CaseEnergy, DutyCycleResult

__all__ = ["BEARING_ROLES", "CENTRAL_ROLES", "analyse_duty_cycle"]

#: The central members of a set whose bearings turn relative to the housing.
CENTRAL_ROLES = ("sun", "ring", "carrier")
#: Bearing positions of a planetary set.
BEARING_ROLES = ("planet", *CENTRAL_ROLES)


def _signature(case) -> tuple:
    op = case.operating_point
    return (case.gear, tuple(sorted(op.speeds)), tuple(sorted(op.torques)), tuple(sorted(op.powers)),
            tuple(op.drives), tuple(op.loads), tuple(op.connected))


def _check_gears(duty: DutyCycle, schedule) -> None:
    for case in duty.cases:
        if case.gear is None:
            continue
        if schedule is None:
            raise DutyCycleError(f"duty cycle, case {case.name!r}: gear {case.gear!r} needs a [transmission] "
                                 "table with a schedule; remove 'gear' or add the schedule.")
        if case.gear not in schedule.schedule:
            raise UnknownGearError(case.gear, schedule.schedule)


def _check_bearings(bearings, geometry, train: GearTrain) -> None:
    sets = {e.name for e in train.elements if isinstance(e, PlanetarySet)}
    for element, roles in bearings.items():
        if element not in sets:
            raise DutyCycleError(f"bearings: the train has no planetary set {element!r}; bearing ratings belong to "
                                 f"the sets {', '.join(map(repr, sorted(sets))) or '(none)'}.")
        if not isinstance(geometry.get(element), SetGeometry):
            raise DutyCycleError(f"bearings of {element!r}: the bearing loads come from the tooth forces; add a "
                                 "'geometry' table (module, ...) to the set.")
        for role, rating in roles.items():
            if role not in BEARING_ROLES:
                raise DutyCycleError(f"bearings of {element!r}: unknown position {role!r}; expected one of "
                                     f"{', '.join(BEARING_ROLES)}.")
            if not isinstance(rating, BearingRating):
                raise DutyCycleError(f"bearings of {element!r}.{role}: expected a BearingRating, got "
                                     f"{type(rating).__name__}.")


def _solve_groups(train, duty, schedule, losses, spin=None):
    """Batch solutions by group and, per case, (group key, index in the group)."""
    groups: dict[tuple, list[int]] = {}
    for k, case in enumerate(duty.cases):
        groups.setdefault(_signature(case), []).append(k)
    solved = {}
    where = [None] * len(duty)
    for key, members in groups.items():
        cases = [duty.cases[k] for k in members]
        first = cases[0].operating_point
        train_g = schedule.train_in_gear(train, cases[0].gear) if cases[0].gear is not None else train
        arrays = {group: {shaft: np.array([getattr(c.operating_point, group)[shaft] for c in cases])
                          for shaft in getattr(first, group)} for group in ("speeds", "torques", "powers")}
        models = {name: m for name, m in losses.items() if name in {e.name for e in train_g.elements}}
        # spin losses (clutch drag, pump, churning, seals) where the loss package has them: by gear and input
        extra = {} if spin is None else {"spin": spin, "gear": cases[0].gear,
                                         "input": getattr(schedule, "input", None)}
        try:
            batch = solve_batch_with_losses(train_g, models, drives=first.drives, loads=first.loads, **arrays,
                                            **extra)
        except EpicyclicError as exc:
            raise _case_error(exc, duty, members, train_g, models, extra) from None
        solved[key] = (train_g, batch)
        for j, k in enumerate(members):
            where[k] = (key, j)
    return solved, where


def _case_error(exc: EpicyclicError, duty: DutyCycle, members, train_g, models, extra) -> EpicyclicError:
    """The error of the first case of a group that fails alone (scalar solve), naming the case.

    The error keeps its class and fields; ``duty_case`` is the case's index (the file reader
    locates it at its ``[[duty_cycle.case]]`` table).
    """
    failed, index = exc, members[0]
    for k in members:
        try:
            solve_with_losses(train_g, duty.cases[k].operating_point, models, **extra)
        except EpicyclicError as alone:
            failed, index = alone, k
            break
    new = copy.copy(failed)
    new.args = (f"duty cycle, case {duty.cases[index].name!r}: {failed}",)
    new.duty_case = index  # type: ignore[attr-defined]
    return new


def _planet_speed(geometry: SetGeometry, body_gear: str, n_sun, n_carrier):
    pset = geometry.planetary_set
    k = pset.teeth.planet_factors  # type: ignore[union-attr]
    factor = k[geometry.planet_gear_names.index(body_gear)] if pset.teeth.kind == "double" else k[0]  # type: ignore[union-attr]
    return np.abs(factor * (n_sun - n_carrier))


def analyse_duty_cycle(train: GearTrain, duty: DutyCycle, *, schedule=None,
                       losses: Mapping[str, Any] | None = None, geometry: Mapping[str, Any] | None = None,
                       bearings: Mapping[str, Mapping[str, BearingRating]] | None = None,
                       rating=None, spin=None, title: str = "") -> DutyCycleResult:
    """Energies, losses by source, cycle efficiency and bearing lives of ``train`` over ``duty``.

    Parameters
    ----------
    train : GearTrain
        The train (for cases with a gear: as the schedule's gears are made from it).
    duty : DutyCycle
        The load cases.
    schedule : epicyclic.io.toml_format.Transmission, optional
        The shift schedule (``TrainFile.transmission``); needed by cases that name a gear.
    losses : mapping element → ElementLosses, optional
        Loss models (``TrainFile.losses``); elements without one keep their η0.
    geometry : mapping element → SetGeometry, optional
        Gear geometry (``TrainFile.geometry``), needed for the bearing loads.
    bearings : mapping element → mapping position → BearingRating, optional
        Bearing ratings by set and position (``planet``, ``sun``, ``ring``, ``carrier``).
    rating : RatingSpec, optional
        Tooth rating inputs (``TrainFile.rating``): with them, the flank and root damage sums of
        every gear (:mod:`~epicyclic.rating.duty_damage`); a cycle of shares then runs for
        ``rating.life`` hours.
    spin : SpinLosses, optional
        Load-independent spin losses (``TrainFile.spin`` where the loss package has them), passed to
        :func:`~epicyclic.losses.solve_batch_with_losses` with each case's gear; their sources join
        the energy lost by source.
    title : str, optional
        For the report.

    Returns
    -------
    DutyCycleResult

    Raises
    ------
    UnknownGearError
        A case names a gear the schedule does not have.
    DutyCycleError
        A case names a gear without a schedule, a case self-locks, bearings of a set without
        geometry or of an unknown position.

    References
    ----------
    ISO 281:2007, 5.3 and 7.3; Queitsch part I, eqs. (23)–(26); Brandenberger 1952, eq. 7.

    Examples
    --------
    >>> from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet
    >>> from epicyclic.rating import DutyCycle
    >>> p = PlanetarySet.simple("P", sun="in", ring="r", carrier="out", z_sun=30, z_planet=24, z_ring=78,
    ...                         stationary_efficiency=0.97)
    >>> train = GearTrain([p, Brake("B", "r")])
    >>> ops = [OperatingPoint(speeds={"in": n}, torques={"in": t}, drives=["in"], loads=["out"])
    ...        for n, t in ((3000, 100), (1000, 300))]
    >>> res = analyse_duty_cycle(train, DutyCycle.from_operating_points(ops, hours=[10.0, 10.0]))

    Both cases have η = (1 + 2.6 η0)/3.6 (ring held, sun drives), so the cycle has it too:

    >>> round(res.cycle_efficiency, 6), round((1 + 2.6 * 0.97) / 3.6, 6)
    (0.978333, 0.978333)
    """
    losses = dict(losses or {})
    geometry = dict(geometry or {})
    bearings = {k: dict(v) for k, v in (bearings or {}).items()}
    if not isinstance(duty, DutyCycle):
        raise DutyCycleError(f"analyse_duty_cycle: duty must be a DutyCycle, got {type(duty).__name__}.")
    _check_gears(duty, schedule)
    _check_bearings(bearings, geometry, train)
    solved, where = _solve_groups(train, duty, schedule, losses, spin)
    count = len(duty)
    per_hour = duty.hours is None
    hours = duty.shares if per_hour else duty.hours

    def column(pick) -> np.ndarray:
        return np.array([float(pick(solved[key][1], j)) for key, j in where])  # type: ignore[misc]

    for k, (key, j) in enumerate(where):  # type: ignore[misc]
        if bool(solved[key][1].self_locking.reshape(-1)[j]):
            raise DutyCycleError(f"duty cycle, case {duty.cases[k].name!r}: the train self-locks at this operating "
                                 "point (no power reaches the load); check the drives and loads of the case.")
    p_in = column(lambda s, j: s.input_power.reshape(-1)[j])
    p_out = column(lambda s, j: s.output_power.reshape(-1)[j])
    sources: dict[str, dict[str, np.ndarray]] = {}
    for k, (key, j) in enumerate(where):  # type: ignore[misc]
        batch = solved[key][1]
        for element, parts in batch.loss_sources.items():
            for source, value in parts.items():
                sources.setdefault(element, {}).setdefault(source, np.zeros(count))[k] = float(
                    np.asarray(value).reshape(-1)[j])
    for parts in sources.values():  # a loss of round-off size (1e-9 of the power in) is no loss: shown as 0
        for source, value in parts.items():
            parts[source] = np.where(np.abs(value) <= 1e-9 * np.abs(p_in), 0.0, value)
    energy = CaseEnergy(
        input=p_in * hours / 1000.0, output=np.abs(p_out) * hours / 1000.0,
        lost=MappingProxyType({e: MappingProxyType({s: v * hours / 1000.0 for s, v in parts.items()})
                               for e, parts in sources.items()}),
    )
    lives = _bearing_lives(duty, solved, where, geometry, bearings, _oil_state(duty, solved, where, spin)) \
        if bearings else ()
    damage: tuple = ()
    if rating is not None:
        if not geometry:
            raise DutyCycleError("duty cycle: the tooth damage sums need the gear geometry; add 'geometry' tables.")
        from .duty_damage import gear_damages

        members: dict[tuple, list[int]] = {}
        for k, (key, _) in enumerate(where):  # type: ignore[misc]
            members.setdefault(key, []).append(k)
        case_hours = duty.hours if duty.hours is not None else duty.shares * rating.life
        damage = gear_damages([(solved[key][1], m) for key, m in members.items()], count, case_hours, geometry,
                              rating)
    required = duty.total_hours if duty.total_hours is not None else (rating.life if rating is not None else None)
    return DutyCycleResult(duty, energy, lives, per_hour=per_hour, title=title or train.name, damage=damage,
                           required_life=required)


def _shared_sets(train_g, present, geometry) -> set[str]:
    """The sets of ``present`` that share a planet body with another (a geometric property: one check)."""
    view = solution_view(train_g, {s: {"sun": 1.0, "ring": 1.0, "carrier": 0.0} for s in present})
    forces = share_planets({s: planetary_forces(view, s, geometry[s]) for s in present},
                           {s: geometry[s] for s in present})
    return {s for s in present if any(b.shared_with for b in forces[s].bodies)}


def _case_by_case(train_g, batch, members, shared, geometry):
    """Bodies' (gear, index, force, axial, shared_with) and central forces of the sets that share planets,
    one :func:`planetary_forces` per case (their loads are not of the separable form of bearing_loads)."""
    out: dict[str, list] = {s: [] for s in shared}
    for j in range(len(members)):
        view = solution_view(train_g, {s: {p: float(batch.port_torques[(s, p)].reshape(-1)[j])
                                           for p in ("sun", "ring", "carrier")} for s in shared})
        forces = share_planets({s: planetary_forces(view, s, geometry[s]) for s in shared},
                               {s: geometry[s] for s in shared})
        for s in shared:
            out[s].append(forces[s])
    return out


def _oil_state(duty, solved, where, spin) -> tuple[np.ndarray | None, np.ndarray | None]:
    """(oil temperature °C, ν mm²/s) per case from the spin losses' oil: the thermal balance's temperature of
    each case, else the given one; (None, None) without an oil or a temperature."""
    oil = getattr(spin, "oil", None)
    if oil is None:
        return None, None
    t = np.full(len(duty), np.nan)
    for k, (key, j) in enumerate(where):  # type: ignore[misc]
        temps = getattr(solved[key][1], "oil_temperature", None)
        if temps is not None:
            t[k] = float(np.asarray(temps).reshape(-1)[j])
        elif spin.temperature is not None:
            t[k] = float(spin.temperature)
    if not np.all(np.isfinite(t)):
        return None, None
    return t, np.asarray(oil.kinematic_viscosity(t), dtype=float)


def _bearing_lives(duty, solved, where, geometry, bearings, oil=(None, None)) -> tuple[BearingLife, ...]:
    count = len(duty)
    sets = [name for name in geometry if isinstance(geometry[name], SetGeometry)]
    radial: dict[tuple[str, str], np.ndarray] = {}
    axial: dict[tuple[str, str], np.ndarray] = {}
    speeds: dict[tuple[str, str], np.ndarray] = {}
    order: list[tuple[str, str, str]] = []  # (set, position label, role)
    claimed: dict[tuple, str] = {}

    def slot(s: str, label: str, role: str) -> tuple[str, str]:
        key = (s, label)
        if key not in radial:
            radial[key], axial[key], speeds[key] = np.zeros(count), np.zeros(count), np.zeros(count)
            order.append((s, label, role))
        return key

    units: dict[str, dict] = {}  # the unit-torque forces of each set: geometry only, the same in every gear
    sharing: dict[frozenset, set[str]] = {}
    members: dict[tuple, list[int]] = {}
    for k, (key, _) in enumerate(where):
        members.setdefault(key, []).append(k)
    for key, cases in members.items():
        train_g, batch = solved[key]
        names = {e.name for e in train_g.elements}
        present = [s for s in sets if s in names]
        if frozenset(present) not in sharing:
            sharing[frozenset(present)] = _shared_sets(train_g, present, geometry) if len(present) > 1 else set()
        shared = sharing[frozenset(present)]
        by_case = _case_by_case(train_g, batch, cases, shared, geometry) if shared else {}
        idx = np.array(cases)
        n = {shaft: np.asarray(v).reshape(-1) for shaft, v in batch.speeds.items()}
        for s in present:
            ratings = bearings.get(s, {})
            if not ratings:
                continue
            pset = geometry[s].planetary_set
            if s in by_case:
                forces = by_case[s]
                bodies = [(b.gear, b.index, b.shared_with) for b in forces[0].bodies]
                force = np.array([[f.bodies[b].bearing_force for f in forces] for b in range(len(bodies))])
                thrust = np.array([[f.bodies[b].bearing_axial for f in forces] for b in range(len(bodies))])
                central = {r: np.array([f.central_forces[r] for f in forces]) for r in CENTRAL_ROLES}
            else:
                if s not in units:
                    units[s] = unit_forces(train_g, s, geometry[s])
                loads = set_loads(train_g, s, geometry[s], batch.port_torques[(s, "sun")].reshape(-1),
                                  batch.port_torques[(s, "ring")].reshape(-1), units=units[s])
                bodies = [(g, i, ()) for g, i in zip(loads.gears, loads.indices)]
                force, thrust, central = loads.bearing, loads.axial, loads.central
            if "planet" in ratings:
                for b, (gear, index, shared_with) in enumerate(bodies):
                    owner = claimed.setdefault((tuple(sorted({s, *shared_with})), index, "" if shared_with else gear), s)
                    if owner != s:
                        continue  # a shared planet's bearing is rated once, by the first set with a rating
                    label = f"planet {index + 1}" + (f" ({gear})" if pset.teeth.kind == "double" else "")
                    at = slot(s, label, "planet")
                    radial[at][idx] = np.hypot(force[b][:, 0], force[b][:, 1])
                    axial[at][idx] = thrust[b]
                    speeds[at][idx] = _planet_speed(geometry[s], gear, n[pset.sun], n[pset.carrier])
            for role in CENTRAL_ROLES:
                if role in ratings:
                    at = slot(s, role, role)
                    radial[at][idx] = np.hypot(central[role][:, 0], central[role][:, 1]) + ratings[role].external_load
                    speeds[at][idx] = np.abs(n[getattr(pset, role)])
    def from_oil(rating) -> dict:
        if not rating.modified or oil[1] is None:
            return {}
        if rating.viscosity is None:
            return {"temperature": oil[0], "viscosity": oil[1]}
        return {"temperature": oil[0], "oil_viscosity": oil[1]}  # typed by hand: compared in the notes

    return tuple(BearingLife(s, label, role, bearings[s][role], radial[(s, label)], axial[(s, label)],
                             speeds[(s, label)], duty.shares, **from_oil(bearings[s][role])) for s, label, role in order)
