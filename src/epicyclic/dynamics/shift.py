"""Shifts and launches of a transmission: the inputs, a simple shift controller, and the run.

:class:`DynamicsSpec` gathers what a transient needs beyond the gear train: inertias, the wet
clutch and brake models (and freewheels), the drive and the load, the line pressure, the shift
controller's timing, the simulated time (a bound, stated) and the output step.

The controller (:class:`ShiftController`) programs a clutch-to-clutch shift open-loop:

* at the command time the on-coming element is filled to its kiss point (the pressure that just
  balances its return spring: no torque) and held there for ``fill_time``;
* torque phase: its pressure ramps over ``torque_phase`` to the pressure whose capacity equals
  the torque it carries in the new gear at the state before the shift, while the off-going
  element's pressure ramps from line pressure to zero;
* inertia phase: its pressure is the one that brings the slip to zero in ``inertia_phase``
  seconds, computed from the train's equations at the start of the shift (the slip's
  deceleration is affine in the element's torque: two evaluations give it);
* then it ramps to line pressure over ``boost_time``.

References
----------
Naunheimer, H., Bertsche, B., Ryborz, J., Novak, W.: *Automotive Transmissions*, 2nd ed., Springer
2011, §10.3 (power-shift phases and their pressure programme).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import Any

import numpy as np

from .drive import Engine, HeldSpeed
from .equations import Mode, TrainDynamics
from .errors import DynamicsError
from .figures import collect
from .friction import Freewheel, WetElement
from .inertia import Inertias
from .integrate import MAX_DURATION, integrate, project
from .pressure import PressureProfile
from .results import ShiftResult

__all__ = ["DynamicsSpec", "ShiftController", "simulate_shift", "simulate_launch", "shift_elements",
           "DEFAULT_LINE_PRESSURE"]

#: Line pressure, Pa (15 bar; automatic transmissions work with about 5 ... 25 bar), stated default.
DEFAULT_LINE_PRESSURE = 15e5
RPM = math.pi / 30.0


def _seconds(value: object, name: str, low: float = 0.0, high: float = MAX_DURATION) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or not low <= value <= high:
        raise DynamicsError(f"dynamics: {name} must be a time in [{low:g}, {high:g}] s, got {value!r:.40}.")
    return float(value)


@dataclass(frozen=True)
class ShiftController:
    """Timing of the open-loop shift programme (s; see the module text). Defaults stated."""

    command_time: float = 0.1
    fill_time: float = 0.05
    torque_phase: float = 0.15
    inertia_phase: float = 0.4
    boost_time: float = 0.05

    def __post_init__(self) -> None:
        for key in ("command_time", "fill_time", "torque_phase", "inertia_phase", "boost_time"):
            object.__setattr__(self, key, _seconds(getattr(self, key), f"controller {key}"))
        if self.inertia_phase <= 0.0:
            raise DynamicsError("dynamics: controller inertia_phase (the target slip time) must be > 0 s.")


@dataclass(frozen=True)
class DynamicsSpec:
    """Everything a shift or launch simulation needs beyond the transmission.

    Parameters
    ----------
    inertias : Inertias
    elements : mapping name → WetElement or Freewheel
    drive : Engine or TorqueTrace
    load : OutputTorque, HeldSpeed or VehicleLoad
    input_speed : float, default 2500
        Input speed at the start, 1/min.
    duration : float, default 1.0
        Simulated time, s (the bound).
    step : float, default 1e-3
        Output step, s.
    line_pressure : float, default 15e5
        Pa.
    controller : ShiftController
    pressures : mapping name → PressureProfile, optional
        Profiles that replace the controller's for those elements.
    launch_element : str, optional
        The element that slips in a launch (default: the first wet element of the first gear that is
        not a brake, else its first wet element).
    launch_ramp : float, default 0.6
        s over which the launch element's pressure ramps from the kiss point to line pressure.
    """

    inertias: Inertias
    elements: Mapping[str, Any]
    drive: Any
    load: Any
    input_speed: float = 2500.0
    duration: float = 1.0
    step: float = 1e-3
    line_pressure: float = DEFAULT_LINE_PRESSURE
    controller: ShiftController = field(default_factory=ShiftController)
    pressures: Mapping[str, PressureProfile] = field(default_factory=dict)
    launch_element: str | None = None
    launch_ramp: float = 0.6
    assumptions: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        if not isinstance(self.inertias, Inertias):
            raise DynamicsError("dynamics: inertias must be an Inertias.")
        object.__setattr__(self, "elements", MappingProxyType(dict(self.elements)))
        object.__setattr__(self, "pressures", MappingProxyType(dict(self.pressures)))
        _seconds(self.duration, "duration", 1e-6)
        if isinstance(self.input_speed, bool) or not isinstance(self.input_speed, (int, float)) \
                or not math.isfinite(self.input_speed) or abs(self.input_speed) > 1e5:
            raise DynamicsError(f"dynamics: input_speed must be a speed in 1/min within ±1e5, got {self.input_speed!r}.")
        if isinstance(self.line_pressure, bool) or not isinstance(self.line_pressure, (int, float)) \
                or not 0 < self.line_pressure <= 1e7:
            raise DynamicsError(f"dynamics: line_pressure must be in (0, 1e7] Pa, got {self.line_pressure!r}.")
        _seconds(self.launch_ramp, "launch_ramp")

    def with_throttle(self, throttle: float) -> DynamicsSpec:
        """The same spec with the engine at throttle θ ∈ [0, 1] (only for an :class:`Engine` drive)."""
        if not isinstance(self.drive, Engine):
            raise DynamicsError("dynamics: --throttle needs an [engine] (the drive is a torque trace).")
        return replace(self, drive=self.drive.with_throttle(throttle))


def shift_elements(transmission, from_gear: str, to_gear: str) -> tuple[str, str, tuple[str, ...]]:
    """(off-going, on-coming, common) of a shift; a clear error for a shift the schedule does not allow.

    Raises
    ------
    DynamicsError
        The same gear twice, or two gears that differ in more than one element each (not a
        clutch-to-clutch shift).
    """
    transmission.gear_train(from_gear), transmission.gear_train(to_gear)  # unknown gears: UnknownGearError
    if from_gear == to_gear:
        raise DynamicsError(f"shift: --from and --to are both gear {from_gear!r}; give two different gears.")
    old, new = set(transmission.schedule[from_gear]), set(transmission.schedule[to_gear])
    off, on = sorted(old - new), sorted(new - old)
    if len(off) != 1 or len(on) != 1:
        allowed = [g for g in transmission.gears if g != from_gear
                   and len(set(transmission.schedule[g]) - old) == 1 and len(old - set(transmission.schedule[g])) == 1]
        raise DynamicsError(
            f"shift: {from_gear} -> {to_gear} releases {', '.join(off) or 'nothing'} and engages "
            f"{', '.join(on) or 'nothing'}; the schedule allows only clutch-to-clutch shifts (one element out, "
            f"one in): from {from_gear!r} to {', '.join(repr(g) for g in allowed) or 'no gear'}.")
    return off[0], on[0], tuple(sorted(old & new))


def _check_models(spec: DynamicsSpec, names, what: str) -> None:
    for name in names:
        if not isinstance(spec.elements.get(name), (WetElement, Freewheel)):
            raise DynamicsError(f"{what}: element {name!r} has no capacity: give its [clutch.capacity] (or "
                                "[brake.capacity]) table with piston_area, faces, mean_radius and friction, or "
                                "make it a freewheel.")


def _start(transmission, spec: DynamicsSpec, gear: str) -> np.ndarray:
    speeds = transmission.speeds(gear, spec.input_speed)
    return np.array([speeds[s] * RPM for s in transmission.train.moving_shafts])


def _dynamics(transmission, spec: DynamicsSpec, pressures) -> TrainDynamics:
    return TrainDynamics(transmission.train, transmission.input, transmission.output, spec.inertias,
                         spec.elements, pressures, spec.drive, spec.load)


def _handover(transmission, spec, omega0, old_locked, new_locked, on, off, line):
    """(on-coming torque in the new gear, pressure for the target slip time) at the state before the shift."""
    pressures = {n: PressureProfile.constant(line if n in new_locked else 0.0, n) for n in spec.elements
                 if isinstance(spec.elements[n], WetElement)}
    d = _dynamics(transmission, spec, pressures)
    omega_new = project(d, omega0, frozenset(new_locked))  # a held output keeps its speed
    need = abs(d.evaluate(0.0, omega_new, Mode(frozenset(new_locked))).element_torques[on])
    model = spec.elements[on]
    s0 = d.slip(on, omega0)
    if not isinstance(model, WetElement) or s0 == 0.0:
        return need, line
    sign = math.copysign(1.0, s0)
    locked = frozenset(old_locked - {off})
    rates = []
    for pressure in (model.capacity.pressure_for(0.5 * need + 1.0), model.capacity.pressure_for(1.5 * need + 2.0)):
        trial = dict(pressures)
        trial[on] = PressureProfile.constant(pressure, on)
        trial[off] = PressureProfile.constant(0.0, off)
        r = _dynamics(transmission, spec, trial).evaluate(0.0, omega0, Mode(locked, {on: sign, off: 0.0}))
        first, second = d.element_columns[on]
        rate = r.accelerations[first] - (r.accelerations[second] if second >= 0 else 0.0)
        rates.append((pressure, rate))
    (p1, r1), (p2, r2) = rates
    target = -s0 / spec.controller.inertia_phase
    if r2 == r1:
        return need, line
    pressure = p1 + (target - r1) * (p2 - p1) / (r2 - r1)
    return need, min(max(pressure, model.capacity.pressure_for(need)), line)


def simulate_shift(transmission, spec: DynamicsSpec, from_gear: str, to_gear: str, *,
                   throttle: float | None = None) -> ShiftResult:
    """Simulate the shift ``from_gear`` → ``to_gear`` from the state of steady ``from_gear`` at the input speed.

    Parameters
    ----------
    transmission : Transmission
    spec : DynamicsSpec
    from_gear, to_gear : str
    throttle : float, optional
        θ ∈ [0, 1] of the engine (default: the spec's).

    Returns
    -------
    ShiftResult
        Completed or "not completed" (stated), never a hang: the simulated time is ``spec.duration``.

    Raises
    ------
    DynamicsError
        A shift the schedule does not allow, an element without capacity.

    References
    ----------
    Naunheimer et al. 2011, §10.3; Benford & Leising 1981 (SAE 810102).
    """
    if throttle is not None:
        spec = spec.with_throttle(throttle)
    off, on, common = shift_elements(transmission, from_gear, to_gear)
    _check_models(spec, (off, on, *common), f"shift {from_gear} -> {to_gear}")
    line, c = spec.line_pressure, spec.controller
    omega0 = _start(transmission, spec, from_gear)
    old = set(transmission.schedule[from_gear])
    new = set(transmission.schedule[to_gear])
    need, inertia_pressure = _handover(transmission, spec, omega0, old, new, on, off, line)
    pressures = {}
    for name, model in spec.elements.items():
        if not isinstance(model, WetElement):
            continue
        kiss = model.capacity.return_spring / model.capacity.piston_area
        if name == on:
            torque_end = min(model.capacity.pressure_for(need), line)
            pressures[name] = PressureProfile.ramps(0.0, [(0.0, kiss), (c.fill_time, kiss),
                                                          (c.torque_phase, torque_end), (0.0, inertia_pressure),
                                                          (c.inertia_phase, inertia_pressure),
                                                          (c.boost_time, line)], t0=c.command_time, name=name)
        elif name == off:
            pressures[name] = PressureProfile.ramps(line, [(c.fill_time, line), (c.torque_phase, 0.0)],
                                                    t0=c.command_time, name=name)
        elif name in common:
            pressures[name] = PressureProfile.constant(line, name)
        else:
            pressures[name] = PressureProfile.constant(0.0, name)
    pressures.update(spec.pressures)
    dynamics = _dynamics(transmission, spec, pressures)
    run = integrate(dynamics, omega0, Mode(frozenset(n for n in old if n in spec.elements)), spec.duration,
                    step=spec.step, breakpoints=dynamics.breakpoints())
    ratios = (transmission.ratio(from_gear), transmission.ratio(to_gear))
    assumptions = spec.assumptions + (
        f"shift controller: command {c.command_time:g} s, fill {c.fill_time:g} s, torque phase {c.torque_phase:g} s, "
        f"inertia phase {c.inertia_phase:g} s, boost {c.boost_time:g} s; line pressure {line / 1e5:g} bar",)
    return collect(dynamics, run, kind="shift", from_gear=from_gear, to_gear=to_gear, off=off, on=on,
                   common=common, command_time=c.command_time, duration=spec.duration, ratios=ratios,
                   assumptions=assumptions, vehicle=spec.load if hasattr(spec.load, "vehicle") else None)


def simulate_launch(transmission, spec: DynamicsSpec, gear: str | None = None, *,
                    throttle: float | None = None) -> ShiftResult:
    """Simulate a launch from standstill in ``gear`` (default the first) with one element slipping.

    The output stands still, the input turns at ``spec.input_speed``; the launch element's
    pressure ramps from its kiss point at the command time to line pressure over ``launch_ramp``;
    the other elements of the gear hold at line pressure.

    Parameters
    ----------
    transmission : Transmission
    spec : DynamicsSpec
    gear : str, optional
    throttle : float, optional

    Returns
    -------
    ShiftResult
        ``kind="launch"``; completed once the launch element sticks and holds.

    Raises
    ------
    DynamicsError
        A launch element that is not in the gear, elements without capacity, a held output.
    """
    if throttle is not None:
        spec = spec.with_throttle(throttle)
    gear = transmission.gears[0] if gear is None else gear
    transmission.gear_train(gear)
    engaged = tuple(transmission.schedule[gear])
    if isinstance(spec.load, HeldSpeed):
        raise DynamicsError("launch: the output cannot be held at its speed in a launch; give a vehicle or an "
                            "output torque as the load.")
    _check_models(spec, engaged, f"launch in {gear}")
    launch = spec.launch_element
    if launch is None:
        wet = [n for n in engaged if isinstance(spec.elements[n], WetElement)]
        clutches = [n for n in wet if n in {e.name for e in transmission.train.shift_elements
                                             if type(e).__name__ == "Clutch"}]
        launch = (clutches or wet or [None])[0]
    if launch not in engaged or not isinstance(spec.elements.get(launch), WetElement):
        raise DynamicsError(f"launch: the launch element {launch!r} must be a wet clutch or brake engaged in gear "
                            f"{gear!r} ({', '.join(engaged)}); set [dynamics] launch_element.")
    line, c = spec.line_pressure, spec.controller
    pressures = {}
    for name, model in spec.elements.items():
        if not isinstance(model, WetElement):
            continue
        kiss = model.capacity.return_spring / model.capacity.piston_area
        if name == launch:
            pressures[name] = PressureProfile.ramps(0.0, [(0.0, kiss), (spec.launch_ramp, line)],
                                                    t0=c.command_time, name=name)
        else:
            pressures[name] = PressureProfile.constant(line if name in engaged else 0.0, name)
    pressures.update(spec.pressures)
    dynamics = _dynamics(transmission, spec, pressures)
    omega0 = np.zeros(len(dynamics.shafts))
    omega0[dynamics.index[transmission.input]] = spec.input_speed * RPM
    locked = frozenset(n for n in engaged if n != launch)
    # the gear without its launch element leaves two freedoms: the input's speed and the output at rest
    omega0 = _rest_output(dynamics, omega0, locked, transmission)
    run = integrate(dynamics, omega0, Mode(locked), spec.duration, step=spec.step,
                    breakpoints=dynamics.breakpoints())
    ratio = transmission.ratio(gear)
    assumptions = spec.assumptions + (
        f"launch: {launch!r} ramps from its kiss point at {c.command_time:g} s to {line / 1e5:g} bar in "
        f"{spec.launch_ramp:g} s; input at {spec.input_speed:g} 1/min, output at rest",)
    return collect(dynamics, run, kind="launch", from_gear=gear, to_gear=gear, off=None, on=launch,
                   common=tuple(n for n in engaged if n != launch), command_time=c.command_time,
                   duration=spec.duration, ratios=(ratio, ratio), assumptions=assumptions,
                   vehicle=spec.load if hasattr(spec.load, "vehicle") else None)


def _rest_output(dynamics: TrainDynamics, omega: np.ndarray, locked, transmission) -> np.ndarray:
    """Speeds with the input as given, the output at rest and the gear's other elements sticking."""
    c = dynamics.constraints(frozenset(locked))
    n = len(dynamics.shafts)
    i_in, i_out = dynamics.index[transmission.input], dynamics.index[transmission.output]
    rows = [c]
    e = np.zeros((2, n))
    e[0, i_in] = 1.0
    e[1, i_out] = 1.0
    a = np.vstack(rows + [e])
    b = np.concatenate([np.zeros(c.shape[0]), [omega[i_in], 0.0]])
    solution, *_ = np.linalg.lstsq(a, b, rcond=None)
    if np.linalg.norm(a @ solution - b) > 1e-9 * (1.0 + abs(omega[i_in])):
        raise DynamicsError("launch: the gear without its launch element does not let the input turn while the "
                            "output stands still; choose another launch_element.")
    solution[np.abs(solution) <= 1e-12 * np.max(np.abs(solution))] = 0.0  # round-off of shafts at rest
    return solution
