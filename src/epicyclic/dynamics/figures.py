"""From a run to its traces and figures: phases, energy and power per element, warnings.

Phases of a clutch-to-clutch shift (Naunheimer et al. 2011, §10.3):

* torque phase: the on-coming element carries friction torque while the off-going one still
  sticks (the ratio has not changed yet; the torque is handed over);
* inertia phase: from the off-going element's break-away to the on-coming element's lock-up
  (the speeds change to the new gear's);
* shift time: from the shift command to the on-coming element's final lock-up.

Warnings: a *tie-up* (the off-going element, still sticking, carries torque of the opposite sign
to the one it carried before the shift: the two elements fight), a *flare* (the input runs faster
than the faster of the two gears' synchronous speeds by more than ``flare_tolerance``: neither
element holds the engine), *capacity exceeded* (an element that should hold — engaged in both
gears, or the on-coming one after its lock-up — slips).

References
----------
Naunheimer, H., Bertsche, B., Ryborz, J., Novak, W.: *Automotive Transmissions*, 2nd ed., Springer
2011, §10.2–10.3; Budynas & Nisbett 2011, §16-10 (lumped temperature rise ΔT = E/(C m)).
"""

from __future__ import annotations

import bisect
import math

import numpy as np

from .equations import Mode, TrainDynamics
from .friction import WetElement
from .integrate import Run
from .results import ElementFigures, ElementTrace, EnergyBalance, ShiftResult, Traces

__all__ = ["collect", "FLARE_TOLERANCE"]

#: The input may overrun the faster gear's synchronous speed by this share before a flare is reported.
FLARE_TOLERANCE = 0.02
RPM = math.pi / 30.0


def _mode_at(run: Run, t: float) -> Mode:
    starts = [s for s, _ in run.modes]
    return run.modes[max(bisect.bisect_right(starts, t) - 1, 0)][1]


def collect(dynamics: TrainDynamics, run: Run, *, kind: str, from_gear: str, to_gear: str, off: str | None,
            on: str, common: tuple[str, ...], command_time: float, duration: float, ratios: tuple[float, float],
            assumptions: tuple[str, ...] = (), vehicle=None, notes: tuple[str, ...] = ()) -> ShiftResult:
    """The :class:`ShiftResult` of ``run`` (see the module text for the phases and warnings).

    Parameters
    ----------
    dynamics : TrainDynamics
    run : Run
    kind : {"shift", "launch"}
    from_gear, to_gear : str
    off : str or None
        The off-going element (None for a launch).
    on : str
        The on-coming (launch) element.
    common : tuple of str
        Elements engaged in both gears.
    command_time, duration : float
        s.
    ratios : (float, float)
        Input/output speed ratio of the two gears.
    assumptions, notes : tuple of str
    vehicle : VehicleLoad or None

    Returns
    -------
    ShiftResult
    """
    n = len(dynamics.shafts)
    names = run.element_names
    times, states = run.times, run.states
    evaluations = [dynamics.evaluate(t, y[:n], _mode_at(run, t)) for t, y in zip(times, states)]
    omega = states[:, :n]
    acc = np.array([e.accelerations for e in evaluations]).reshape(len(times), n)
    net = acc @ dynamics.mass.T
    i_out = dynamics.index[dynamics.output]
    load_inertia = getattr(dynamics.load, "inertia", 0.0)
    out_torque = np.array([e.load_torque for e in evaluations]) + load_inertia * acc[:, i_out]
    elements = {}
    for k, name in enumerate(names):
        locked = np.array([name in _mode_at(run, t).locked for t in times])
        elements[name] = ElementTrace(
            slip=np.array([e.element_slips[name] for e in evaluations]) / RPM,
            torque=np.array([e.element_torques[name] for e in evaluations]),
            power=np.array([e.element_powers[name] for e in evaluations]),
            energy=states[:, n + 3 + k], pressure=np.array([dynamics.pressure(name, t) for t in times]),
            locked=locked)
    accel = jerk = None
    if vehicle is not None:
        accel = acc[:, i_out] * vehicle.vehicle.wheel_radius / vehicle.vehicle.axle_ratio
        jerk = np.gradient(accel, times) if len(times) > 1 else np.zeros_like(accel)
    traces = Traces(times, {s: omega[:, k] / RPM for k, s in enumerate(dynamics.shafts)},
                    {s: net[:, k] for k, s in enumerate(dynamics.shafts)},
                    {lv.element.name: np.array([e.lever_torques[j] for e in evaluations])
                     for j, lv in enumerate(dynamics.levers)},
                    elements, np.array([e.drive_torque for e in evaluations]), out_torque, accel, jerk)
    # ---------------------------------------------------------------- phases
    lock_times = [t for t, m in run.modes if on in m.locked]
    on_locked_at_end = on in run.modes[-1][1].locked
    last_lock = None
    if on_locked_at_end:
        k = len(run.modes) - 1
        while k > 0 and on in run.modes[k - 1][1].locked:
            k -= 1
        last_lock = run.modes[k][0]
    release = None
    if off is not None:
        release = next((t for t, m in run.modes if t >= command_time and off not in m.locked), None)
    model = dynamics.elements.get(on)
    onset = None
    if isinstance(model, WetElement):
        onset = next((t for t in times if t >= command_time
                      and model.capacity.normal_force(dynamics.pressure(on, t)) > 0.0), None)
    completed = on_locked_at_end and (off is None or release is not None) and run.ended == "time"
    phases = {}
    torque_phase = inertia_phase = shift_time = None
    if completed:
        shift_time = last_lock - command_time
        if off is not None:
            start = release
            if onset is not None and onset < release:
                torque_phase = release - onset
                phases["torque phase"] = (onset, release)
            inertia_phase = max(last_lock - start, 0.0)
            phases["inertia phase"] = (start, last_lock)
        else:
            start = onset if onset is not None else command_time
            inertia_phase = max(last_lock - start, 0.0)
            phases["slip phase"] = (start, last_lock)
        status = f"{kind} completed: {on!r} stuck at t = {last_lock:.6g} s and held to the end ({duration:g} s)"
    elif run.ended != "time":
        status = f"{kind} not completed: {run.ended}"
    elif off is not None and release is None:
        status = (f"{kind} not completed within the simulated {duration:g} s: the off-going element {off!r} never "
                  "broke away (its pressure does not fall below what it holds)")
    else:
        status = (f"{kind} not completed within the simulated {duration:g} s: the on-coming element {on!r} "
                  + ("stuck but slipped again" if lock_times else "never reached synchronism") +
                  " (more capacity, a longer inertia phase or a longer simulation)")
    # ---------------------------------------------------------------- figures per element
    figures = {}
    for name in names:
        e = elements[name]
        model = dynamics.elements[name]
        area = getattr(getattr(model, "capacity", None), "friction_area", None)
        heat = getattr(getattr(model, "capacity", None), "heat_capacity", None)
        energy = float(e.energy[-1])
        peak = float(np.max(e.power)) if e.power.size else 0.0
        dt = np.diff(times)
        slipping = float(np.sum(dt[(~e.locked[:-1]) & (np.abs(e.torque[:-1]) > 0) & (np.abs(e.slip[:-1]) > 0)]))
        figures[name] = ElementFigures(name, energy, peak, None if area is None else energy / (area * 1e6),
                                       None if area is None else peak / (area * 1e6),
                                       None if heat is None else energy / heat, slipping)
    # ---------------------------------------------------------------- warnings
    warnings = list(notes)
    if off is not None:
        before = [j for j, t in enumerate(times) if t <= command_time]
        if before:
            sign0 = math.copysign(1.0, elements[off].torque[before[-1]]) if elements[off].torque[before[-1]] else 0.0
            fight = [t for j, t in enumerate(times) if t > command_time and elements[off].locked[j]
                     and sign0 and elements[off].torque[j] * sign0 < -1e-6 * (1.0 + abs(elements[off].torque[j]))]
            if fight:
                warnings.append(f"tie-up: the off-going element {off!r} still sticks and carries torque of the "
                                f"opposite sign from t = {fight[0]:.4g} s (the on-coming {on!r} pulls against it); "
                                "release it earlier or ramp the on-coming element slower")
    i_in = dynamics.index[dynamics.input]
    sync = np.max(np.abs(ratios)) * np.abs(omega[:, i_out])
    over = np.abs(omega[:, i_in]) > (1.0 + FLARE_TOLERANCE) * sync + 1.0  # 1 rad/s: none at standstill
    if kind == "shift" and np.any(over & (times > command_time)):
        j = int(np.argmax(over & (times > command_time)))
        warnings.append(f"flare: the input runs {np.abs(omega[j, i_in]) / RPM:.5g} 1/min at t = {times[j]:.4g} s, "
                        f"more than {FLARE_TOLERANCE:.0%} above the slower gear's synchronous "
                        f"{sync[j] / RPM:.5g} 1/min (neither element holds the engine)")
    for name in common:
        if name in names and not np.all(elements[name].locked):
            j = int(np.argmax(~elements[name].locked))
            warnings.append(f"capacity exceeded: {name!r}, engaged in both gears, slips from t = {times[j]:.4g} s "
                            "(its static capacity is below the torque it must hold)")
    if on_locked_at_end is False and lock_times:
        warnings.append(f"capacity exceeded: the on-coming {on!r} stuck at t = {lock_times[0]:.4g} s but broke away "
                        "again (its capacity is below the new gear's torque)")
    # ---------------------------------------------------------------- energy balance
    y0, y1 = states[0], states[-1]
    ke0, ke1 = dynamics.kinetic_energy(y0[:n]), dynamics.kinetic_energy(y1[:n])
    e_in, e_load, e_mesh, e_el = y1[n], y1[n + 1], y1[n + 2], float(np.sum(y1[n + 3:]))
    residual = e_in - e_load - e_mesh - e_el - (ke1 - ke0)
    scale = max(abs(e_in), abs(e_load), ke0, ke1)
    balance = EnergyBalance(float(e_in), float(e_load), float(e_mesh), e_el, ke1 - ke0, float(residual), scale)
    return ShiftResult(kind, from_gear, to_gear, completed, status, duration, command_time, shift_time,
                       torque_phase, inertia_phase, figures, tuple(warnings), balance, traces, run.events,
                       assumptions, phases)
