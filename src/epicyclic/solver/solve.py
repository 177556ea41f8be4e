"""The general quasi-static solver: one mechanism for every gear train.

1. Kinematics: all speeds from the given ones (Willis row per set).
2. Ideal statics (η = 1): torques from the given torques/powers.
3. Loss directions w = sign(rolling power) from the ideal solution.
4. Lossy statics with η0^w; re-read w from the lossy solution.  When it
   agrees (w = 0 agrees with anything, since such an element carries no loss)
   the solution is consistent; otherwise try the lossy pattern, a few times.
5. Self-locking (:mod:`epicyclic.solver.self_locking`): a consistent lossy
   solution in which no power reaches the loads, a load delivers power or a
   drive absorbs it (each beyond a margin), or no consistent pattern at all,
   means the train cannot move in the asked direction.

Every number passes the zero rule of :mod:`epicyclic.results.zero` once, in
:func:`epicyclic.solver.evaluate.evaluate`: held shafts, idle and locked
elements are exactly 0, and the efficiency is never computed from round-off
(no power flowing is "no efficiency", and it is never above 1).  The
circulating power is that of :mod:`epicyclic.results.circulation`.

References
----------
Brandenberger 1952, eqs. 1–10 and Bild 8–9 (the sign of the rolling power decides where η0 acts).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace
from functools import lru_cache
from types import MappingProxyType


from ..errors import (ContradictionError, EpicyclicError, ModelError, NearSingularError, NonFiniteResultError,
                      OperatingPointError, UnderdeterminedError)
from ..model.elements import HOUSING, Clutch
from ..model.operating_point import OperatingPoint
from ..model.planetary import PlanetarySet
from ..model.train import GearTrain
from ..results.circulation import circulation, indeterminate_circulation
from ..results.solution import RPM_TO_RAD_S, ElementState, SelfLocking, ShaftState, Solution
from ..results.zero import clean, scale_of
from .assembly import TrainMatrices, matrices
from .evaluate import Evaluation
from .given_losses import GivenLosses, given_losses, with_efficiencies
from .kinematics import degrees_of_freedom, solve_speeds
from .friction_state import describe, reversible_levers, wrong_way_at_designated
from .point import evaluate_point
from .self_locking import self_locking
from .statics import TorqueSolver, torque_solver

__all__ = ["solve", "given_torques", "MAX_PATTERN_TRIES"]

#: How many loss-direction patterns are tried before declaring self-locking.
MAX_PATTERN_TRIES = 8


def _validate(train: GearTrain, op: OperatingPoint) -> None:
    if not isinstance(train, GearTrain):
        raise ModelError(f"solve: the first argument must be a GearTrain, got {type(train).__name__}; "
                         "build it as GearTrain([elements]) or read a file with epicyclic.io.load_train_file(path).train.")
    if not isinstance(op, OperatingPoint):
        raise OperatingPointError(
            f"solve: the operating point must be an OperatingPoint, got {type(op).__name__}; "
            "build it as OperatingPoint(speeds={...}, torques={...}, drives=[...], loads=[...]).")
    for shaft in op.shaft_names():
        train.check_shaft(shaft)
    for group in ("drives", "loads", "connected"):
        if HOUSING in getattr(op, group):
            raise OperatingPointError(
                f"operating point: the housing cannot be one of the {group}; it only takes reactions.",
                group=group, shafts=[HOUSING],
            )
    for group in ("torques", "powers"):
        if HOUSING in getattr(op, group):
            raise OperatingPointError(
                f"operating point: {group}['housing'] cannot be given; the housing reaction is computed.",
                group=group, shafts=[HOUSING],
            )
    if op.speeds.get(HOUSING, 0.0) != 0.0:
        raise ContradictionError(
            f"operating point: speeds['housing'] = {op.speeds[HOUSING]:g} 1/min, but the housing "
            "is the frame and stands still; remove it (speeds are measured against the housing).",
            [HOUSING],
            "speed",
        )


def given_torques(op: OperatingPoint, speeds: Mapping[str, float]) -> dict[str, float]:
    """External torques (N·m) from the given torques and powers.

    A power P at a shaft turning at n gives M = P/ω with ω = n·π/30.  At a
    designated drive the power enters (M·ω > 0), at a load it leaves (M·ω < 0):
    for those, the magnitude is used and the role sets the sign.

    Raises
    ------
    OperatingPointError
        A power given at a shaft that stands still.
    """
    result: dict[str, float] = {}
    for shaft, power in op.powers.items():
        omega = speeds[shaft] * RPM_TO_RAD_S
        if omega == 0.0:
            raise OperatingPointError(
                f"operating point: powers[{shaft!r}] = {power:g} W is given, but shaft {shaft!r} "
                "stands still (speed 0), so the power fixes no torque; give torques[" + repr(shaft) + "] instead.",
                group="powers", shafts=[shaft],
            )
        torque = power / omega
        if not math.isfinite(torque):
            raise NonFiniteResultError(
                f"operating point: powers[{shaft!r}] = {power:g} W at {speeds[shaft]:g} 1/min needs a torque "
                "beyond the floating-point range (about 1.8e308 N·m); give a larger speed or a smaller power.",
                "torque", shaft,
            )
        result[shaft] = _with_role(op, shaft, torque, omega)
    for shaft, torque in op.torques.items():
        result[shaft] = _with_role(op, shaft, torque, speeds[shaft] * RPM_TO_RAD_S)
    return result


def _with_role(op: OperatingPoint, shaft: str, torque: float, omega: float) -> float:
    if omega == 0.0:
        return torque
    sign = 1.0 if omega > 0.0 else -1.0
    if shaft in op.drives:
        return abs(torque) * sign
    if shaft in op.loads:
        return -abs(torque) * sign
    return torque


def _consistent(pattern: tuple[int, ...], observed: list[int]) -> bool:
    """w agrees with the re-read sign (observed 0, or w 0 with observed 0, agree)."""
    return all(w == o or o == 0 for w, o in zip(pattern, observed))


def solve(train: GearTrain, operating_point: OperatingPoint, *, lossless: bool = False,
          efficiencies: Mapping[str, Mapping[str, float]] | None = None,
          loss_torques: Mapping[str, Mapping[str, float]] | None = None) -> Solution:
    """Solve a gear train at an operating point, with losses by power flow.

    Parameters
    ----------
    train : GearTrain
    operating_point : OperatingPoint
        Given speeds (1/min), torques (N·m) or powers (W), drives and loads.
    lossless : bool, default False
        Ignore all losses (η = 1 everywhere).
    efficiencies : mapping element → mapping source → float, optional
        Efficiency factors by source (e.g. ``{"P1": {"mesh": 0.985, "bearing": 0.999}}``)
        whose product replaces the element's η0 in the loss rule; the loss is
        reported split by source (:mod:`~epicyclic.solver.given_losses`).
    loss_torques : mapping element → mapping shaft → float, optional
        Loss torques of an element acting on shafts, N·m (drag, with its
        reactions); they enter the shafts' torque balances.

    Returns
    -------
    Solution
        With ``.ideal`` holding the lossless solution at the same point (built on first
        access) and each element's loss by source in ``loss_sources``.

    Raises
    ------
    UnknownShaftError, UnderdeterminedError, ContradictionError, OperatingPointError
    NearSingularError
        The train's equations are too close to singular for round-off not to decide the result.
    NonFiniteResultError
        A speed, torque or power overflows the floating-point range.

    References
    ----------
    Brandenberger 1952, eqs. 1–10.

    Examples
    --------
    Minus set, ring held, sun drives the carrier (Brandenberger's rule gives
    η = (1 − i0·η0)/(1 − i0)):

    >>> from epicyclic import GearTrain, PlanetarySet, Brake, OperatingPoint, solve
    >>> train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", -2.0, 0.97), Brake("B", "ring")])
    >>> op = OperatingPoint(speeds={"sun": 3000}, torques={"sun": 10}, drives=["sun"], loads=["carrier"])
    >>> sol = solve(train, op)
    >>> round(sol.efficiency, 6), round((1 + 2 * 0.97) / 3, 6)
    (0.98, 0.98)
    """
    op = operating_point
    _validate(train, op)
    mats = matrices(train, op.external_shafts)
    extra = None if lossless else given_losses(mats, efficiencies, loss_torques, 1)
    speeds = solve_speeds(mats, op.speeds)
    n = [speeds[s] for s in train.shafts]
    given_values = {s: float(v) for s, v in given_torques(op, speeds).items()}
    given = list(given_values)
    values = list(given_values.values())

    ideal_solver = torque_solver(mats, given, None)
    x_ideal = ideal_solver.point(values)
    ideal_solver.check(values, x_ideal)
    ideal_eval = evaluate_point(mats, n, x_ideal, None, given_values)
    ideal_column = _Column(ideal_eval)
    roles = _roles(train, op, mats, ideal_column)
    ideal_mats = mats
    ideal = _once(lambda: _build(train, op, ideal_mats, ideal_eval, ideal_solver, roles, None, lossless=True))
    if extra is not None:  # the given factors are the levers' η0
        mats = matrices(with_efficiencies(train, {lv.element.name: float(extra.efficiency[k, 0])
                                                  for k, lv in enumerate(mats.levers)}), op.external_shafts)
    dragged = extra.torques if extra is not None and extra.has_torques else None
    if lossless or (dragged is None and all(lever.efficiency == 1.0 for lever in mats.levers)):
        return replace(ideal(), ideal=None) if lossless else replace(ideal(), ideal=ideal())
    rows = None if dragged is None else extra.rows(mats)[:, 0]

    ideal_pattern = tuple(ideal_column.pattern)
    pattern = ideal_pattern
    tried: list[tuple[int, ...]] = []
    consistent: tuple[TorqueSolver, Evaluation] | None = None
    first: tuple[TorqueSolver, Evaluation] | None = None
    singular = False
    while len(tried) < MAX_PATTERN_TRIES and pattern not in tried:
        tried.append(pattern)
        try:
            solver = torque_solver(mats, given, pattern)
            x = solver.point(values, rows)
            solver.check(values, x, rows)
        except (UnderdeterminedError, NearSingularError, ContradictionError) as error:
            if not _at_limit(error, ideal_solver, mats, given, pattern):
                raise
            singular = True  # exactly (or within round-off) at the self-locking limit of this pattern
            break
        ev = evaluate_point(mats, n, x, pattern, given_values, shaft_torques=dragged)
        if first is None:
            first = (solver, ev)
        observed = _Column(ev).pattern
        if _consistent(pattern, observed):
            consistent = (solver, ev)
            break
        pattern = tuple(w if o == 0 else o for w, o in zip(pattern, observed))

    if consistent is None and first is None:  # no lossy solution at all: the lossless numbers are shown
        solution = replace(ideal(), ideal=ideal())
    else:
        solver, ev = consistent if consistent is not None else first
        other = None if consistent is None else (
            lambda: _other_friction_state(train, op, mats, solver, given, values, rows, n, given_values, dragged))
        solution = _build(train, op, mats, ev, solver, roles, ideal, extra=extra, other=other)
    locked = self_locking(solution, consistent is not None, mats, given, values, n, ideal_pattern,
                          singular=singular)
    if locked is not None and dragged is not None:
        locked = _no_load_cause(locked, solution, -math.fsum(float(t) * v for t, v in zip(dragged[:, 0], n)) * RPM_TO_RAD_S)
    if locked is not None:
        solution = solution.replace(self_locking=locked, efficiency=None)
    return solution


def _no_load_cause(locked: SelfLocking, solution: Solution, no_load: float) -> SelfLocking:
    """``locked``, or — where the no-load losses alone take at least the input power — what it really is.

    Such a point is no self-locking of the gearing (a larger input torque moves the train): the
    speed-dependent losses (drag, churning, pump, seals) exceed what the input gives.
    """
    if not no_load >= solution.input_power > 0.0:
        return locked
    return replace(locked, cause="no-load losses", thresholds=MappingProxyType({}), message=(
        f"no power reaches the load: the no-load (spin) losses, {no_load:.6g} W, exceed the input power, "
        f"{solution.input_power:.6g} W, at this point (not a self-locking of the gearing). Give a larger input "
        "torque, or check the oil temperature and the drag inputs."))


def _at_limit(error, ideal_solver: TorqueSolver, mats: TrainMatrices, given, pattern) -> bool:
    """Whether ``error`` of a loss pattern's equations means "at the self-locking limit".

    The lossless equations were determined; if those of a loss pattern leave a torque free
    (``UnderdeterminedError``), are too close to singular (``NearSingularError``) or, having lost
    rank, cannot take the given torques (``ContradictionError``), the losses alone made them
    singular: i0·η0^w (or a loop's product of such ratios) is 1, the torques of that pattern are
    unbounded, and no consistent solution with it exists (Brandenberger 1952, text to Bild 9:
    self-locking where the carrier torque M3' = 0 for a finite drive torque).
    """
    if isinstance(error, ContradictionError):
        lossy = mats.solvers.get(("torque", tuple(given), tuple(int(w) for w in pattern)))
        return lossy is not None and lossy.system.rank < ideal_solver.system.rank
    return True


def _other_friction_state(train, op, mats, solver: TorqueSolver, given, values, rows, n, given_values,
                          dragged) -> tuple[str, ...]:
    """A warning if another loss pattern, one element reversed, is consistent too (see friction_state)."""
    designated = [(k, "drive" if s in op.drives else "load") for k, s in enumerate(train.shafts)
                  if s in op.drives or s in op.loads]
    for k in reversible_levers(solver):
        other = tuple(-w if j == k else w for j, w in enumerate(solver.pattern))
        try:
            alternative = torque_solver(mats, given, other)
            x = alternative.point(values, rows)
            alternative.check(values, x, rows)
            col = _Column(evaluate_point(mats, n, x, other, given_values, shaft_torques=dragged))
        except EpicyclicError:  # singular or out of range: no state
            continue
        scale = max(abs(p) for p in col.powers)
        if _consistent(other, col.pattern) and not wrong_way_at_designated(col.powers, designated, scale):
            torques = {s: t for s, t in zip(train.shafts, col.torques) if s in mats.external}
            return (describe(mats, solver.pattern, other, torques),)
    return ()


def _once(make):
    """``make`` called on the first call only (a lighter :func:`functools.cache` for one value)."""
    made = []

    def value():
        if not made:
            made.append(make())
        return made[0]
    return value


def _roles(train: GearTrain, op: OperatingPoint, mats: TrainMatrices, ideal: _Column) -> dict[str, str]:
    """drive/load per shaft: as designated, else from the ideal power's sign."""
    roles: dict[str, str] = {}
    for k, shaft in enumerate(train.shafts):
        if shaft == HOUSING:
            roles[shaft] = "housing"
        elif shaft in op.drives:
            roles[shaft] = "drive"
        elif shaft in op.loads:
            roles[shaft] = "load"
        elif shaft in mats.external:
            power = ideal.powers[k]
            roles[shaft] = ("drive" if power > 0 else "load" if power < 0
                            else "held" if ideal.speeds[k] == 0 else "external")
        else:
            roles[shaft] = "internal"
    return roles


def _efficiency(drive_power: float, load_power: float, loss: float) -> float | None:
    """output/input; None when no power enters; never above 1 (round-off of a lossless path)."""
    if drive_power <= 0.0:
        return None
    efficiency = load_power / drive_power
    if loss == 0.0 and abs(efficiency - 1.0) <= 1e-9:
        return 1.0
    return min(efficiency, 1.0)


def _build(train, op, mats, ev: Evaluation, solver: TorqueSolver, roles, ideal, lossless=False,
           extra: GivenLosses | None = None, other=None) -> Solution:
    col = _Column(ev)
    shafts = {shaft: ShaftState(shaft, speed, torque, power, roles[shaft])
              for shaft, speed, torque, power in zip(train.shafts, col.speeds, col.torques, col.powers)}
    elements = {element.name: _element_state(element, layout, ev, col, lossless, extra)
                for element, layout in zip(train.elements, _element_layouts(mats))}

    drive_power = sum(s.power for s in shafts.values() if s.role == "drive") + 0.0
    load_power = -sum(s.power for s in shafts.values() if s.role == "load") + 0.0
    housing = {} if lossless or extra is None else {
        source: float(value[0]) for source, value in extra.drag_losses(HOUSING, ev.speeds).items()}
    loss = sum(e.loss for e in elements.values()) + sum(housing.values()) + 0.0
    efficiency = _efficiency(drive_power, load_power, loss)

    @_once
    def circ():  # made on first access, as are the warnings (they name the loops)
        if solver.indeterminate:
            return indeterminate_circulation(solver.indeterminate)
        flows = [(e.name, e.ports[p], power) for e in elements.values() for p, power in e.port_powers.items()]
        return circulation(flows, drive_power, train.shafts)

    return Solution(
        train=train,
        operating_point=op,
        shafts=MappingProxyType(shafts),
        elements=MappingProxyType(elements),
        input_power=drive_power,
        output_power=load_power,
        loss=loss,
        efficiency=efficiency,
        self_locking=None,
        circulation=circ,
        degrees_of_freedom=degrees_of_freedom(mats),
        housing_loss_sources=MappingProxyType(housing),
        warnings=lambda: tuple(_warnings(shafts, solver, circ(), drive_power, load_power)) + (other() if other else ()),
        ideal=ideal,
    )


class _Column:
    """The one point of an Evaluation as Python floats (read once, not entry by entry)."""

    speeds: list[float]
    torques: list[float]
    powers: list[float]
    x: list[float]
    relative: list[float]
    rolling: list[float]
    coupling: list[float]
    loss: list[float]
    pattern: list[int]
    direction: list[int]

    def __init__(self, ev: Evaluation):
        floats = getattr(ev, "floats", None) or {name: getattr(ev, name)[:, 0].tolist() for name in (
            "speeds", "torques", "powers", "x", "relative", "rolling", "coupling", "loss", "pattern", "direction")}
        self.__dict__.update(floats)  # speeds, torques, powers, x, relative, rolling, coupling, loss, pattern, direction


@dataclass(frozen=True)
class _ElementLayout:
    """Where an element's numbers sit in an Evaluation."""

    lever: int | None  # index among the levers (sets and stages), None for clutches and brakes
    ports: tuple[str, ...]
    shafts: tuple[str, ...]
    columns: tuple[int, ...]  # torque column of each port (engaged elements)
    rows: tuple[int, ...]  # speed row of each port's shaft
    efficiency: float  # the lever's η0 in these equations (given factors included)
    kind: str  # "planetary set", "gear stage", "clutch", "brake"
    port_map: Mapping[str, str]  # port → shaft, read-only, shared by every solution
    planet_factors: tuple[float, ...]  # of a set with tooth counts (Teeth.planet_factors)


@lru_cache(maxsize=64)
def _element_layouts(mats: TrainMatrices) -> tuple[_ElementLayout, ...]:
    idx = mats.torque_index
    row = {s: k for k, s in enumerate(mats.train.shafts)}
    lever_index = {lever.element.name: k for k, lever in enumerate(mats.levers)}
    out = []
    for element in mats.train.elements:
        k = lever_index.get(element.name)
        if k is not None:
            ports, shafts = mats.levers[k].ports, mats.levers[k].shafts
        else:
            ports = ("first", "second") if isinstance(element, Clutch) else ("shaft", "housing")
            shafts = element.shafts
        engaged = k is not None or element.engaged
        kind = ("planetary set" if isinstance(element, PlanetarySet) else "gear stage" if k is not None
                else "clutch" if isinstance(element, Clutch) else "brake")
        teeth = element.teeth if isinstance(element, PlanetarySet) else None
        out.append(_ElementLayout(k, ports, shafts,
                                  tuple(idx[("port", element.name, p)] for p in ports) if engaged else (),
                                  tuple(row[s] for s in shafts),
                                  mats.levers[k].efficiency if k is not None else 1.0,
                                  kind, MappingProxyType(dict(zip(ports, shafts))),
                                  () if teeth is None else teeth.planet_factors))
    return tuple(out)


def _warnings(shafts, solver, circ, drive_power, load_power) -> list[str]:
    warnings = []
    for s in shafts.values():
        if s.role in ("drive", "load") and s.speed == 0.0 and s.torque != 0.0:
            warnings.append(f"{s.name!r} is a {s.role} but the train holds it still (speed 0): it takes "
                            f"{abs(s.torque):.6g} N·m as a reaction torque, not power.")
    if drive_power == 0.0 and load_power == 0.0 and any(s.role in ("drive", "load") for s in shafts.values()):
        warnings.append("no power flows through the train at this operating point, so it has no efficiency.")
    if solver.indeterminate:
        warnings.append(
            "the internal torque split of " + ", ".join(repr(n) for n in solver.indeterminate)
            + " is statically indeterminate (redundant locking): the minimum-norm split is shown, and the "
            "circulating power and the largest element power are not defined."
        )
    if circ.loops:
        warnings.append("power circulates: " + circ.describe() + ".")
    return warnings


def _sources(element, extra: GivenLosses | None, ev: Evaluation, k: int | None, rolling: float, lossless: bool):
    """(loss, loss by source) of an element: its rolling loss split by source, plus its loss torques' loss."""
    if lossless:
        return rolling, {}
    parts = {"mesh": rolling} if k is not None else {}
    if extra is not None:
        if k is not None:
            parts = {source: float(v[0]) for source, v in extra.split(k, ev.loss[k]).items()}
        spin = 0.0
        for source, value in extra.drag_losses(element.name, ev.speeds).items():
            if float(value[0]):
                parts[source] = parts.get(source, 0.0) + float(value[0])
                spin += float(value[0])
        return rolling + spin, parts
    return rolling, parts


def _element_state(element, layout: _ElementLayout, ev: Evaluation, col: _Column, lossless,
                   extra: GivenLosses | None = None) -> ElementState:
    k = layout.lever
    ports = layout.port_map
    speeds = col.speeds
    port_speeds = dict(zip(layout.ports, [speeds[r] for r in layout.rows]))
    if k is not None:
        loss, sources = _sources(element, extra, ev, k, col.loss[k], lossless)
        torques = dict(zip(layout.ports, [col.x[c] for c in layout.columns]))
        w = col.direction[k]
        planets: tuple[float, ...] = ()
        relative: tuple[float, ...] = ()
        if layout.planet_factors:
            relative_speed, carrier = col.relative[k], speeds[layout.rows[2]]
            relative = tuple([f * relative_speed + 0.0 for f in layout.planet_factors])
            planets = tuple([clean(carrier + r, scale_of(carrier, r)) for r in relative])
        return ElementState(
            element.name,
            layout.kind,
            ports,
            MappingProxyType(torques),
            MappingProxyType(port_speeds),
            rolling_power=col.rolling[k],
            coupling_power=col.coupling[k],
            loss=loss,
            loss_sources=MappingProxyType(sources),
            loss_direction=w,
            efficiency_factor=1.0 if lossless or w == 0 else layout.efficiency ** w,
            planet_speeds=planets,
            planet_speeds_relative=relative,
        )
    # clutch or brake
    if element.engaged:
        torques = {p: col.x[c] for p, c in zip(layout.ports, layout.columns)}
    else:
        torques = {p: 0.0 for p in layout.ports}
    first, second = (port_speeds[p] for p in layout.ports)
    loss, sources = _sources(element, extra, ev, None, 0.0, lossless)
    return ElementState(
        element.name,
        layout.kind,
        ports,
        MappingProxyType(torques),
        MappingProxyType(port_speeds),
        engaged=element.engaged,
        slip_speed=clean(first - second, scale_of(first, second)),
        loss=loss,
        loss_sources=MappingProxyType(sources),
    )
