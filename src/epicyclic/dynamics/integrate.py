"""Integration of the motion with exact lock-up and break-away: solve_ivp with terminal events.

Between events the mode (which elements stick, which way the others slip) is fixed and the motion
is smooth; :func:`scipy.integrate.solve_ivp` integrates it with events that end the segment where

* a slipping wet element or an overrunning freewheel reaches zero slip (it would lock: the slip
  changes sign in the direction it slipped),
* a sticking wet element needs more torque than it holds (|λ| reaches its static capacity), or a
  locked freewheel's torque reverses (it overruns).

At each event the new mode is settled: the element that reached synchronism sticks (its slip set
exactly to zero by projecting the speeds onto the new constraints), then every sticking element
whose reaction exceeds its capacity is released, the worst first, slipping the way its reaction
pushed (:func:`settle`), until the mode agrees with itself.  The integration restarts in that
mode: no smoothing of the friction law, no stiff regularisation.  The energy of every source and
sink is integrated with the motion (quadratures in the state), so the balance can be checked
against the kinetic energy of the final speeds.

The simulated time and the number of events are bounded before the run starts; a run that
reaches either bound ends there and says so.

References
----------
Virtanen, P. et al.: *SciPy 1.0*, Nature Methods 17 (2020) 261–272 (``solve_ivp`` with events);
Dormand, J. R., Prince, P. J.: *A family of embedded Runge–Kutta formulae*, J. Comp. Appl. Math.
6 (1980) 19–26; Pfeiffer, F., Glocker, C.: *Multibody Dynamics with Unilateral Contacts*, Wiley
1996, ch. 6 (stick–slip transitions as switching of the constraint set, checked by the
reaction's friction bound).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from .equations import Mode, TrainDynamics
from .errors import DynamicsError
from .friction import Freewheel, WetElement

__all__ = ["Run", "integrate", "project", "settle", "MAX_EVENTS", "MAX_EVALUATIONS", "MAX_DURATION"]

#: Most mode changes in one run (a chattering run ends there, stated).
MAX_EVENTS = 2000
#: The slip (rad/s) past synchronism at which a lock-up event fires: round-off of a slip that starts at
#: exactly zero and runs the wrong way is still seen (the speeds are then projected onto exact lock-up).
EVENT_SLIP = 1e-9
#: Most right-hand-side evaluations in one run (a run that would need more, e.g. a stiff or chattering model,
#: ends there and says so: never a hang).
MAX_EVALUATIONS = 500_000
#: Longest simulated time, s.
MAX_DURATION = 600.0


@dataclass(frozen=True, eq=False)
class Run:
    """The raw result of an integration: output times, states and the modes with their start times."""

    times: np.ndarray
    states: np.ndarray  # (points, n + 3 + elements): ω, E_in, E_load, E_mesh, E per element
    modes: tuple[tuple[float, Mode], ...]
    element_names: tuple[str, ...]
    ended: str  # "time" or a sentence saying why it stopped early
    events: int


def settle(dynamics: TrainDynamics, t: float, omega: np.ndarray, mode: Mode) -> Mode:
    """The mode that agrees with itself at (t, ω): sticking elements within their capacity.

    Parameters
    ----------
    dynamics : TrainDynamics
    t : float
    omega : ndarray
    mode : Mode
        The candidate.

    Returns
    -------
    Mode

    References
    ----------
    Pfeiffer & Glocker 1996, ch. 6 (the transition from stick to slip where the reaction leaves the
    friction cone).
    """
    locked, signs = set(mode.locked), dict(mode.signs)
    for _ in range(len(dynamics.elements) + 1):
        result = dynamics.evaluate(t, omega, Mode(frozenset(locked), signs))
        worst, excess = None, 0.0
        for name in locked:
            model = dynamics.elements[name]
            lam = result.element_torques[name]
            if isinstance(model, Freewheel):
                over = lam * model.blocking  # > 0: the freewheel would have to pull the other way
                scale = 1e-9 * (1.0 + abs(lam))
            else:
                cap = dynamics.static_capacity(name, t)
                over = abs(lam) - cap
                scale = 1e-9 * (1.0 + cap)
            if over > scale and over / (1.0 + abs(lam)) > excess:
                worst, excess = name, over / (1.0 + abs(lam))
        if worst is None:
            return _directions(dynamics, omega, Mode(frozenset(locked), signs), result)
        lam = result.element_torques[worst]
        model = dynamics.elements[worst]
        locked.discard(worst)
        signs[worst] = model.blocking if isinstance(model, Freewheel) else math.copysign(1.0, lam)
    raise DynamicsError("dynamics: no consistent stick/slip state found (every element released in turn); "
                        "check the capacities and pressures.")


def _directions(dynamics: TrainDynamics, omega: np.ndarray, mode: Mode, result) -> Mode:
    """Each wet element at exact synchronism and slipping slips the way its slip then accelerates."""
    signs = dict(mode.signs)
    changed = False
    for name, model in dynamics.elements.items():
        if name in mode.locked or not isinstance(model, WetElement) or dynamics.slip(name, omega) != 0.0:
            continue
        first, second = dynamics.element_columns[name]
        rate = result.accelerations[first] - (result.accelerations[second] if second >= 0 else 0.0)
        if rate != 0.0 and math.copysign(1.0, rate) != signs.get(name, 0.0):
            signs[name] = math.copysign(1.0, rate)
            changed = True
    return Mode(mode.locked, signs) if changed else mode


def _with_signs(dynamics: TrainDynamics, t: float, omega: np.ndarray, mode: Mode) -> Mode:
    """The mode with every slipping element's direction from its slip; a wet element with capacity at exact
    synchronism (and no direction yet) is a candidate to stick."""
    locked, signs = set(mode.locked), dict(mode.signs)
    for name, model in dynamics.elements.items():
        if name in locked:
            continue
        s = dynamics.slip(name, omega)
        if s != 0.0:
            signs[name] = math.copysign(1.0, s)
        elif signs.get(name, 0.0) == 0.0 and (isinstance(model, Freewheel)
                                              or dynamics.static_capacity(name, t) > 0.0):
            locked.add(name)
    return Mode(frozenset(locked), signs)


def project(dynamics: TrainDynamics, omega: np.ndarray, locked: frozenset[str]) -> np.ndarray:
    """ω moved onto C ω = 0 (least change); the held output keeps its speed."""
    c = dynamics.constraints(locked)
    target = np.zeros(c.shape[0])
    if dynamics.held:
        target[-1] = omega[dynamics.index[dynamics.output]]
    residual = c @ omega - target
    if not np.any(residual):
        return omega
    return omega - np.linalg.lstsq(c, residual, rcond=None)[0]


def integrate(dynamics: TrainDynamics, omega0, mode: Mode, t_end: float, *, step: float = 1e-3,
              rtol: float = 1e-8, atol: float = 1e-8, max_events: int = MAX_EVENTS,
              method: str = "DOP853", breakpoints=()) -> Run:
    """Integrate from t = 0 with speeds ``omega0`` (rad/s) in ``mode`` (settled first) to ``t_end``.

    Parameters
    ----------
    dynamics : TrainDynamics
    omega0 : array_like
        rad/s per moving shaft (projected onto the mode's constraints).
    mode : Mode
    t_end : float
        s, at most :data:`MAX_DURATION` (the bound, stated before the run).
    step : float, default 1e-3
        Output step, s.
    rtol, atol : float
        Tolerances of ``solve_ivp``.
    max_events : int, default 2000
        Most mode changes.
    method : str, default "DOP853"
    breakpoints : sequence of float, default ()
        Times where the right-hand side has a kink or a step (the corners of pressure profiles): each
        segment ends there, so no step straddles one.

    Returns
    -------
    Run

    Raises
    ------
    DynamicsError
        A duration or step out of range.
    """
    if not (isinstance(t_end, (int, float)) and math.isfinite(t_end) and 0.0 < t_end <= MAX_DURATION):
        raise DynamicsError(f"dynamics: the simulated time must be in (0, {MAX_DURATION:g}] s, got {t_end!r}.")
    if not (isinstance(step, (int, float)) and math.isfinite(step) and 1e-6 <= step <= t_end):
        raise DynamicsError(f"dynamics: the output step must be in [1e-6 s, duration], got {step!r}.")
    points = int(round(t_end / step))
    if points > 2_000_000:
        raise DynamicsError(f"dynamics: {points} output points; at most 2000000 (a longer step or a shorter run).")
    grid = np.linspace(0.0, t_end, points + 1)
    names = tuple(dynamics.elements)
    n = len(dynamics.shafts)
    omega = np.asarray(omega0, dtype=float).copy()
    mode = _with_signs(dynamics, 0.0, project(dynamics, omega, mode.locked), mode)
    mode = settle(dynamics, 0.0, project(dynamics, omega, mode.locked), mode)
    omega = project(dynamics, omega, mode.locked)
    y = np.concatenate([omega, np.zeros(3 + len(names))])
    t = 0.0
    times, states, modes = [], [], [(0.0, mode)]
    events = 0
    ended = "time"
    counter = [0]
    stops = sorted({float(b) for b in breakpoints if 0.0 < b < t_end} | {t_end})
    while True:
        fun, event_list, meaning = _segment(dynamics, mode, names, n, counter)
        t_stop = next(b for b in stops if b > t)
        window = grid[(grid > t) & (grid <= t_stop)] if times else grid[grid <= t_stop]
        extra = not window.size or window[-1] != t_stop
        if extra:
            window = np.append(window, t_stop)
        try:
            sol = solve_ivp(fun, (t, t_stop), y, method=method, t_eval=window, events=event_list, rtol=rtol,
                            atol=atol)
        except _Exhausted:
            ended = (f"stopped after {MAX_EVALUATIONS} evaluations of the equations near t = {t:.6g} s (the "
                     "motion needs ever smaller steps there); the run is not complete")
            break
        if sol.status < 0:
            ended = f"the integrator stopped at t = {t:.6g} s: {sol.message}"
            break
        ts, ys = np.asarray(sol.t), np.asarray(sol.y).T
        if sol.status == 0:
            y = ys[-1].copy()
            if extra:
                ts, ys = ts[:-1], ys[:-1]
        if ts.size:
            times.append(ts)
            states.append(ys)
        if sol.status == 0:
            t = t_stop
            if t >= t_end:
                break
            omega = y[:n]
            mode = settle(dynamics, t, omega, _with_signs(dynamics, t, omega, mode))  # a step in a profile
            if mode != modes[-1][1]:
                y[:n] = project(dynamics, omega, mode.locked)
                modes.append((t, mode))
            continue
        fired = [(sol.t_events[k][0], k) for k in range(len(event_list)) if sol.t_events[k].size]
        t_event, k = min(fired)
        y = sol.y_events[k][0].copy()
        t = float(t_event)
        events += 1
        if events > max_events:
            ended = (f"stopped after {max_events} stick/slip changes at t = {t:.6g} s (the element(s) chatter); "
                     "the run is not complete")
            break
        kind, name = meaning[k]
        locked, signs = set(mode.locked), dict(mode.signs)
        if kind == "lock":
            locked.add(name)
        else:
            locked.discard(name)
            result = dynamics.evaluate(t, y[:n], mode)
            model = dynamics.elements[name]
            signs[name] = model.blocking if isinstance(model, Freewheel) \
                else math.copysign(1.0, result.element_torques[name])
        omega = project(dynamics, y[:n], frozenset(locked))
        mode = settle(dynamics, t, omega, _with_signs(dynamics, t, omega, Mode(frozenset(locked), signs)))
        y[:n] = project(dynamics, omega, mode.locked)
        modes.append((t, mode))
        if t >= t_end:
            break
    if times:
        all_t = np.concatenate(times)
        all_y = np.vstack(states)
    else:
        all_t, all_y = np.array([0.0]), y[None, :]
    return Run(all_t, all_y, tuple(modes), names, ended, events)


class _Exhausted(Exception):
    """The run used up :data:`MAX_EVALUATIONS`."""


def _segment(dynamics: TrainDynamics, mode: Mode, names: tuple[str, ...], n: int, counter: list):
    """The right-hand side and the terminal events of one mode."""
    column = {name: k for k, name in enumerate(names)}
    last: dict = {}

    def evaluate(t, y):
        key = (t, y[:n].tobytes())
        if last.get("key") != key:
            last["key"] = key
            last["value"] = dynamics.evaluate(t, y[:n], mode)
        return last["value"]

    def fun(t, y):
        counter[0] += 1
        if counter[0] > MAX_EVALUATIONS:
            raise _Exhausted
        r = evaluate(t, y)
        dy = np.empty(n + 3 + len(names))
        dy[:n] = r.accelerations
        dy[n] = r.input_power
        dy[n + 1] = r.load_power
        dy[n + 2] = r.mesh_power
        for name, k in column.items():
            dy[n + 3 + k] = r.element_powers.get(name, 0.0)
        return dy

    events, meaning = [], []
    for name, model in dynamics.elements.items():
        if name in mode.locked:
            if isinstance(model, Freewheel):
                def release(t, y, name=name, blocking=model.blocking):
                    return evaluate(t, y).element_torques[name] * blocking
            else:
                def release(t, y, name=name):
                    return abs(evaluate(t, y).element_torques[name]) - dynamics.static_capacity(name, t)
            release.terminal, release.direction = True, 1.0
            events.append(release)
            meaning.append(("release", name))
        else:
            if isinstance(model, Freewheel):
                sign = model.blocking
            elif isinstance(model, WetElement):
                sign = mode.signs.get(name, 0.0)
            else:
                continue
            if sign == 0.0:
                continue

            def lock(t, y, name=name, sign=sign):  # offset: a slip that starts at exactly 0 is seen reversing
                return dynamics.slip(name, y[:n]) * sign + EVENT_SLIP
            lock.terminal, lock.direction = True, -1.0
            events.append(lock)
            meaning.append(("lock", name))
    return fun, events, meaning
