"""The general quasi-static solver: one mechanism for every gear train.

1. Kinematics: all speeds from the given ones (Willis row per set).
2. Ideal statics (η = 1): torques from the given torques/powers.
3. Loss directions w = sign(rolling power) from the ideal solution.
4. Lossy statics with η0^w; re-read w from the lossy solution.  When it
   agrees (w = 0 agrees with anything, since such an element carries no loss)
   the solution is consistent; otherwise try the lossy pattern, a few times.
5. Self-locking: a consistent lossy solution in which a load delivers power
   or a drive absorbs it, or no consistent pattern at all, means the train
   cannot move in the asked direction.  The threshold η0 where this starts is
   found per element by bisection.

References
----------
Brandenberger 1952, eqs. 1–10 and Bild 8–9 (the sign of the rolling power decides where η0 acts).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from types import MappingProxyType

import numpy as np

from ..errors import ContradictionError, EpicyclicError, OperatingPointError
from ..model.elements import HOUSING, Brake, Clutch, GearStage
from ..model.operating_point import OperatingPoint
from ..model.planetary import PlanetarySet
from ..model.train import GearTrain
from ..results.solution import RPM_TO_RAD_S, ElementState, SelfLocking, ShaftState, Solution
from .assembly import TrainMatrices, matrices
from .kinematics import degrees_of_freedom, solve_speeds
from .statics import TorqueSolver, torque_solver

__all__ = ["solve", "given_torques", "loss_pattern", "MAX_PATTERN_TRIES"]

#: How many loss-direction patterns are tried before declaring self-locking.
MAX_PATTERN_TRIES = 8
#: Rolling powers below this fraction of the largest port power count as zero.
ZERO_POWER = 1e-9


def _validate(train: GearTrain, op: OperatingPoint) -> None:
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
        if abs(omega) < 1e-12:
            raise OperatingPointError(
                f"operating point: powers[{shaft!r}] = {power:g} W is given, but shaft {shaft!r} "
                "stands still (speed 0), so the power fixes no torque; give torques[" + repr(shaft) + "] instead.",
                group="powers", shafts=[shaft],
            )
        result[shaft] = _with_role(op, shaft, power / omega, omega)
    for shaft, torque in op.torques.items():
        result[shaft] = _with_role(op, shaft, torque, speeds[shaft] * RPM_TO_RAD_S)
    return result


def _with_role(op: OperatingPoint, shaft: str, torque: float, omega: float) -> float:
    if omega == 0.0:
        return torque
    if shaft in op.drives:
        return abs(torque) * np.sign(omega)
    if shaft in op.loads:
        return -abs(torque) * np.sign(omega)
    return torque


def loss_pattern(mats: TrainMatrices, x: np.ndarray, speeds: np.ndarray) -> np.ndarray:
    """w = sign of the rolling power of every lever, 0 where it is negligible.

    ``x`` holds torques (columns of ``mats.torque_columns``, points along
    trailing axes) and ``speeds`` the speeds of all shafts in
    ``mats.train.shafts`` order.  Returns an int array (levers, ...).
    """
    index = {s: k for k, s in enumerate(mats.train.shafts)}
    rolling = []
    for lever in mats.levers:
        col = mats.torque_index[("port", lever.element.name, lever.ports[0])]
        a, _, c = (index[s] for s in lever.shafts)
        rolling.append(x[col] * (speeds[a] - speeds[c]) * RPM_TO_RAD_S)
    if not rolling:
        return np.zeros((0,) + np.shape(x)[1:], dtype=int)
    rolling = np.array(rolling)
    scale = _power_scale(mats, x, speeds)
    pattern = np.sign(rolling).astype(int)
    pattern[np.abs(rolling) <= ZERO_POWER * scale] = 0
    return pattern


def _power_scale(mats: TrainMatrices, x: np.ndarray, speeds: np.ndarray) -> np.ndarray:
    index = {s: k for k, s in enumerate(mats.train.shafts)}
    powers = [np.abs(x[col] * speeds[index[shaft]] * RPM_TO_RAD_S) for _, shaft, col in mats.port_shaft_columns]
    return np.max(np.array(powers), axis=0) if powers else np.ones(np.shape(x)[1:])


def _consistent(pattern: np.ndarray, observed: np.ndarray) -> bool:
    """w agrees with the re-read sign (observed 0, or w 0 with observed 0, agree)."""
    return bool(np.all((pattern == observed) | (observed == 0)))


def solve(train: GearTrain, operating_point: OperatingPoint, *, lossless: bool = False) -> Solution:
    """Solve a gear train at an operating point, with losses by power flow.

    Parameters
    ----------
    train : GearTrain
    operating_point : OperatingPoint
        Given speeds (1/min), torques (N·m) or powers (W), drives and loads.
    lossless : bool, default False
        Ignore all losses (η = 1 everywhere).

    Returns
    -------
    Solution
        With ``.ideal`` holding the lossless solution at the same point.

    Raises
    ------
    UnknownShaftError, UnderdeterminedError, ContradictionError, OperatingPointError

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
    speeds = solve_speeds(mats, op.speeds)
    speed_vector = np.array([speeds[s] for s in train.shafts])
    torques = given_torques(op, speeds)
    given = list(torques)
    values = np.array([torques[s] for s in given])

    ideal_solver = torque_solver(mats, given, None)
    x_ideal = ideal_solver.torques(values)
    ideal_solver.check(values, x_ideal)
    roles = _roles(train, op, mats, x_ideal, speeds)
    ideal_pattern = loss_pattern(mats, x_ideal, speed_vector)
    ideal = _build(train, op, mats, speeds, x_ideal, ideal_pattern, ideal_solver, roles, None, lossless=True)
    if lossless or all(lever.efficiency == 1.0 for lever in mats.levers):
        return replace(ideal, ideal=None) if lossless else replace(ideal, ideal=ideal)

    pattern = ideal_pattern
    tried: list[tuple[int, ...]] = []
    consistent = None
    first = None
    while len(tried) < MAX_PATTERN_TRIES and tuple(pattern) not in tried:
        tried.append(tuple(pattern))
        solver = torque_solver(mats, given, pattern)
        x = solver.torques(values)
        solver.check(values, x)
        if first is None:
            first = (solver, x, pattern)
        observed = loss_pattern(mats, x, speed_vector)
        if _consistent(pattern, observed):
            consistent = (solver, x, pattern)
            break
        pattern = np.where(observed == 0, pattern, observed)

    solver, x, pattern = consistent if consistent is not None else first
    solution = _build(train, op, mats, speeds, x, pattern, solver, roles, ideal)
    locked = _self_locking(solution, consistent is not None, mats, given, values, speed_vector, first)
    if locked is not None:
        solution = replace(solution, self_locking=locked, efficiency=None)
    return solution


def _roles(train, op, mats, x_ideal, speeds) -> dict[str, str]:
    """drive/load per shaft: as designated, else from the ideal power's sign."""
    roles: dict[str, str] = {}
    for shaft in train.shafts:
        if shaft == HOUSING:
            roles[shaft] = "housing"
        elif shaft in op.drives:
            roles[shaft] = "drive"
        elif shaft in op.loads:
            roles[shaft] = "load"
        elif shaft in mats.external:
            power = x_ideal[mats.external_column(shaft)] * speeds[shaft]
            roles[shaft] = "drive" if power > 0 else "load" if power < 0 else "held" if speeds[shaft] == 0 else "external"
        else:
            roles[shaft] = "internal"
    return roles


def _build(train, op, mats, speeds, x, pattern, solver: TorqueSolver, roles, ideal, lossless=False) -> Solution:
    shafts = {}
    for shaft in train.shafts:
        torque = float(x[mats.external_column(shaft)]) if shaft in mats.external else 0.0
        power = torque * speeds[shaft] * RPM_TO_RAD_S + 0.0  # no −0.0 at the housing
        shafts[shaft] = ShaftState(shaft, speeds[shaft], torque, power, roles[shaft])

    elements = {}
    lever_index = {lever.element.name: k for k, lever in enumerate(mats.levers)}
    for element in train.elements:
        elements[element.name] = _element_state(element, mats, x, speeds, pattern, lever_index, lossless)

    drive_power = sum(s.power for s in shafts.values() if s.role == "drive")
    load_power = -sum(s.power for s in shafts.values() if s.role == "load")
    loss = sum(e.loss for e in elements.values())
    efficiency = load_power / drive_power if drive_power > 0 else None
    if efficiency is not None and 1.0 < efficiency <= 1.0 + 1e-9:
        efficiency = 1.0  # round-off of a lossless path, never above 1
    port_power = max((abs(p) for e in elements.values() for p in e.port_powers.values()), default=0.0)
    circulating = port_power / drive_power if drive_power > 0 else 0.0
    warnings = []
    if solver.indeterminate:
        warnings.append(
            "the internal torque split of " + ", ".join(repr(n) for n in solver.indeterminate)
            + " is statically indeterminate (redundant locking); the minimum-norm split is shown."
        )
    if circulating > 1.0 + 1e-9:
        warnings.append(f"power circulates: the largest internal power is {circulating:.3g} × the input power.")
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
        circulating_power=circulating,
        degrees_of_freedom=degrees_of_freedom(mats),
        warnings=tuple(warnings),
        ideal=ideal,
    )


def _element_state(element, mats, x, speeds, pattern, lever_index, lossless) -> ElementState:
    idx = mats.torque_index
    if isinstance(element, (PlanetarySet, GearStage)):
        lever = mats.levers[lever_index[element.name]]
        ports = dict(zip(lever.ports, lever.shafts))
        torques = {p: float(x[idx[("port", element.name, p)]]) for p in lever.ports}
        port_speeds = {p: speeds[s] for p, s in ports.items()}
        a, b, c = lever.ports
        w = int(pattern[lever_index[element.name]])  # direction of rolling power (0: none)
        rolling = torques[a] * (port_speeds[a] - port_speeds[c]) * RPM_TO_RAD_S
        coupling = torques[a] * port_speeds[c] * RPM_TO_RAD_S + 0.0
        loss = sum(torques[p] * port_speeds[p] for p in lever.ports) * RPM_TO_RAD_S
        planets: tuple[float, ...] = ()
        relative: tuple[float, ...] = ()
        if isinstance(element, PlanetarySet) and element.teeth is not None:
            relative = tuple(k * (port_speeds[a] - port_speeds[c]) for k in element.teeth.planet_factors)
            planets = tuple(port_speeds[c] + r for r in relative)
        return ElementState(
            element.name,
            "planetary set" if isinstance(element, PlanetarySet) else "gear stage",
            MappingProxyType(ports),
            MappingProxyType(torques),
            MappingProxyType(port_speeds),
            rolling_power=rolling,
            coupling_power=coupling,
            loss=max(loss, 0.0) if abs(loss) <= 1e-9 * max(1.0, abs(rolling)) else loss,
            loss_direction=w,
            efficiency_factor=1.0 if lossless else lever.efficiency ** w,
            planet_speeds=planets,
            planet_speeds_relative=relative,
        )
    # clutch or brake
    port_names = ("first", "second") if isinstance(element, Clutch) else ("shaft", "housing")
    ports = dict(zip(port_names, element.shafts))
    port_speeds = {p: speeds[s] for p, s in ports.items()}
    if element.engaged:
        torques = {p: float(x[idx[("port", element.name, p)]]) for p in port_names}
    else:
        torques = {p: 0.0 for p in port_names}
    return ElementState(
        element.name,
        "clutch" if isinstance(element, Clutch) else "brake",
        MappingProxyType(ports),
        MappingProxyType(torques),
        MappingProxyType(port_speeds),
        engaged=element.engaged,
        slip_speed=port_speeds[port_names[0]] - port_speeds[port_names[1]],
    )


def _self_locking(solution: Solution, consistent: bool, mats, given, values, speed_vector, first) -> SelfLocking | None:
    """Detect self-locking and find each lossy element's threshold η0."""
    scale = max(solution.input_power, solution.output_power, 1e-300)
    wrong = [
        s.name for s in solution.shafts.values()
        if (s.role == "load" and s.power > 1e-9 * scale) or (s.role == "drive" and s.power < -1e-9 * scale)
    ]
    transmits = solution.efficiency is None or solution.efficiency > 1e-12
    if consistent and not wrong and transmits:
        return None
    formal = _formal_efficiency(mats, given, values, speed_vector, first[2], solution)
    thresholds = _thresholds(mats, given, values, speed_vector, first[2], solution)
    if wrong:
        reason = (
            "with losses, " + ", ".join(repr(s) for s in wrong)
            + " would have to deliver power although it is the load" if any(
                solution.shafts[s].role == "load" for s in wrong) else
            "with losses, " + ", ".join(repr(s) for s in wrong) + " would have to absorb power although it is the drive"
        )
    elif not consistent:
        reason = "no loss-direction pattern is consistent with the given load"
    else:
        reason = "with losses, no power reaches the load (the train is exactly at its self-locking limit)"
    where = ", ".join(f"{name}: η0 < {eta:.6g}" for name, eta in thresholds.items())
    message = (
        f"the train self-locks in this direction of power flow: {reason}"
        + (f" (formal efficiency {formal:.4g})" if formal is not None else "")
        + (f"; self-locking starts at {where}" if where else "")
        + ". Drive it from the other side, or raise the efficiency."
    )
    return SelfLocking(message, formal, MappingProxyType(thresholds))


def _formal_efficiency(mats, given, values, speed_vector, pattern, solution, etas=None) -> float | None:
    """Efficiency from the loss rule with the ideal pattern (may be ≤ 0)."""
    if etas is not None:
        levers = tuple(replace(lv, efficiency=etas.get(lv.element.name, lv.efficiency)) for lv in mats.levers)
        mats = _with_levers(mats, levers)
    solver = torque_solver(mats, given, pattern)
    x = solver.torques(values)
    powers = {
        s: x[mats.external_column(s)] * speed_vector[k] * RPM_TO_RAD_S
        for k, s in enumerate(mats.train.shafts) if s in mats.external
    }
    drive = sum(p for s, p in powers.items() if solution.shafts[s].role == "drive")
    load = -sum(p for s, p in powers.items() if solution.shafts[s].role == "load")
    if drive == 0.0 and load == 0.0:
        return None
    # The ratio is invariant to which side's torque is given, as long as both are finite.
    if drive == 0.0:
        return -np.inf if load < 0 else np.inf
    return float(load / drive)


def _with_levers(mats: TrainMatrices, levers) -> TrainMatrices:
    clone = TrainMatrices(mats.train, mats.external)
    clone.__dict__["_parts"] = (levers, mats.links)
    return clone


def _thresholds(mats, given, values, speed_vector, pattern, solution) -> dict[str, float]:
    """Per lossy element: the η0 at which the formal efficiency crosses zero."""
    out: dict[str, float] = {}
    for k, lever in enumerate(mats.levers):
        if lever.efficiency == 1.0 or pattern[k] == 0:
            continue

        def efficiency(eta: float) -> float:
            try:
                value = _formal_efficiency(mats, given, values, speed_vector, pattern, solution,
                                           {lever.element.name: eta})
            except EpicyclicError:  # singular exactly at the threshold
                return 0.0
            return -np.inf if value is None else value

        hi = 1.0
        if efficiency(hi) <= 0:
            continue
        lo = lever.efficiency
        if efficiency(lo) > 0:
            continue
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            if efficiency(mid) > 0:
                hi = mid
            else:
                lo = mid
        out[lever.element.name] = 0.5 * (lo + hi)
    return out
