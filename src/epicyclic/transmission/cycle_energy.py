"""A transmission through a drive cycle: energy in and out, energy lost by source and element, cycle efficiency.

Quasi-static and backward-facing: at every row of the cycle the output turns at
the cycle's speed with its torque, in the row's gear, and the transmission is
solved there with its loss models (one batch solve per gear over all its rows,
:func:`~epicyclic.transmission.gear_points.solve_gear_points`).  The energies
are the time integrals of the powers by the trapezoidal rule,

    E_in = ∫ P_in dt,   E_out = ∫ P_out dt,   E_V = ∫ P_V dt = E_in − E_out,

and the cycle efficiency is E_out / E_in.  Rows where the vehicle brakes
(output torque < 0) carry no torque through the transmission (the brakes take
it; the engine is cut off): there the transmission loses its spin losses at the
row's speed, and E_in counts them (they come from the engine or from the
vehicle's kinetic energy).  Rows at standstill (output speed 0) lose nothing
(the engine's idle and the launch element are not modelled).  Speeds and torques
below :data:`NEGLIGIBLE` count as 0.

The gear of a row is given (a ``gear`` column), or taken from a shift schedule
(its upshift lines), or chosen by the best-gear rule of the shift map (least
loss among the gears that can carry the row) with a minimum dwell time (a
gear is kept at least ``min_dwell`` seconds unless it cannot carry the row) and
a hysteresis (a shift must save more than ``hysteresis`` W).  A row no gear
can carry (below the engine's lowest speed at launch, above its torque) runs
in first gear and is counted.

References
----------
Guzzella, Sciarretta, *Vehicle Propulsion Systems*, 3rd ed. (2013), §3.1 (quasi-static simulation);
Naunheimer et al., *Automotive Transmissions* (2011), §7.4 (shift strategies, hysteresis);
Bronstein-Semendjajew, *Taschenbuch der Mathematik* (trapezoidal rule).
"""

from __future__ import annotations

import json
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np

from ..errors import ModelError
from .drive_cycle import DriveCycle
from .gear_points import CarryLimits, solve_gear_points
from .shift_map import forward_gears
from .shift_schedule import ShiftSchedule

__all__ = ["GearRule", "CycleResult", "run_cycle", "DEFAULT_MIN_DWELL"]

#: Least time (s) the best-gear rule keeps a gear before it shifts again (unless the gear cannot carry a row).
DEFAULT_MIN_DWELL = 2.0
#: Output speeds (1/min) and torques (N·m) of a cycle row below this count as 0 (standstill, no torque): a
#: measured trace's noise, and far below any loss the models resolve (the solver refuses subnormal values).
NEGLIGIBLE = 1e-9
#: J per kWh.
KWH = 3.6e6


@dataclass(frozen=True)
class GearRule:
    """How the gear of each row is chosen.

    Parameters
    ----------
    mode : {"given", "best", "schedule"}
        The cycle's ``gear`` column; the least loss (shift map); a shift schedule's upshift lines.
    schedule : ShiftSchedule, optional
        For ``"schedule"``.
    min_dwell : float, default 2.0
        ``"best"``: least time in a gear before the next shift, s (≥ 0).
    hysteresis : float, default 0.0
        ``"best"``: least loss a shift must save, W (≥ 0).

    Examples
    --------
    >>> GearRule("best", min_dwell=3.0, hysteresis=50.0).describe()
    'best gear (least loss), min dwell 3 s, hysteresis 50 W'
    """

    mode: str = "best"
    schedule: ShiftSchedule | None = None
    min_dwell: float = DEFAULT_MIN_DWELL
    hysteresis: float = 0.0

    def __post_init__(self) -> None:
        if self.mode not in ("given", "best", "schedule"):
            raise ModelError(f"gear rule: mode must be 'given', 'best' or 'schedule', got {self.mode!r:.40}.")
        if self.mode == "schedule" and not isinstance(self.schedule, ShiftSchedule):
            raise ModelError("gear rule: mode 'schedule' needs a ShiftSchedule (--schedule FILE).")
        for name in ("min_dwell", "hysteresis"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not 0 <= value < float("inf"):
                raise ModelError(f"gear rule: {name} must be a finite number >= 0, got {value!r:.40}.")
            object.__setattr__(self, name, float(value))

    def describe(self) -> str:
        """The rule in words.

        Returns
        -------
        str
        """
        if self.mode == "given":
            return "gear given per row"
        if self.mode == "schedule":
            return f"gear by the upshift lines of {self.schedule.name}"  # type: ignore[union-attr]
        return f"best gear (least loss), min dwell {self.min_dwell:g} s, hysteresis {self.hysteresis:g} W"


@dataclass(frozen=True, eq=False)
class CycleResult:
    """Energies of a transmission over a drive cycle, with the per-row powers.

    Attributes
    ----------
    name, rule : str
    limits : CarryLimits
    cycle : DriveCycle
    gear : tuple of str
        The gear of every row.
    input_power, output_power, loss : ndarray (R,)
        W.
    losses_by_source, losses_by_element : mapping → ndarray (R,)
        W.
    carried : ndarray of bool (R,)
        Where the row's gear carries the row within :attr:`limits` (standstill rows count as carried).
    shifts : int
    """

    name: str
    rule: str
    limits: CarryLimits
    cycle: DriveCycle
    gear: tuple[str, ...]
    input_power: np.ndarray
    output_power: np.ndarray
    loss: np.ndarray
    losses_by_source: Mapping[str, np.ndarray]
    losses_by_element: Mapping[str, np.ndarray]
    carried: np.ndarray
    shifts: int
    energies: Mapping[str, Any] = field(init=False, repr=False)

    def __post_init__(self) -> None:
        for name in ("input_power", "output_power", "loss", "carried"):
            value = np.asarray(getattr(self, name)).copy()
            value.flags.writeable = False
            object.__setattr__(self, name, value)
        for name in ("losses_by_source", "losses_by_element"):
            object.__setattr__(self, name, MappingProxyType(dict(getattr(self, name))))
        t = self.cycle.time

        def energy(power) -> float:
            return float(np.trapezoid(power, t))

        gears = {}
        for g in sorted(set(self.gear), key=lambda g: (not g.isdigit(), int(g) if g.isdigit() else 0, g)):
            held = np.array([x == g for x in self.gear])
            gears[g] = float(np.sum(np.diff(t) * held[:-1]))  # time from a row to the next in its gear
        object.__setattr__(self, "energies", MappingProxyType({
            "in": energy(self.input_power), "out": energy(self.output_power), "lost": energy(self.loss),
            "by_source": {k: energy(v) for k, v in self.losses_by_source.items()},
            "by_element": {k: energy(v) for k, v in self.losses_by_element.items()},
            "time_in_gear": gears,
        }))

    @property
    def energy_in(self) -> float:
        """E_in = ∫ P_in dt, J."""
        return self.energies["in"]

    @property
    def energy_out(self) -> float:
        """E_out = ∫ P_out dt, J."""
        return self.energies["out"]

    @property
    def energy_lost(self) -> float:
        """E_V = ∫ P_V dt, J."""
        return self.energies["lost"]

    @property
    def efficiency(self) -> float | None:
        """E_out / E_in (None where no energy goes in)."""
        return self.energy_out / self.energy_in if self.energy_in > 0 else None

    def summary(self) -> dict[str, Any]:
        """Energies (J and kWh), cycle efficiency, energy lost by source and element, time in gear, shifts.

        Returns
        -------
        dict
        """
        e = self.energies
        moving = self.cycle.output_speed > 0
        return {
            "cycle": self.cycle.to_dict(), "rule": self.rule, "limits": self.limits.to_dict(),
            "energy_in_J": e["in"], "energy_out_J": e["out"], "energy_lost_J": e["lost"],
            "energy_in_kWh": e["in"] / KWH, "energy_out_kWh": e["out"] / KWH, "energy_lost_kWh": e["lost"] / KWH,
            "efficiency": self.efficiency,
            "energy_lost_by_source_J": dict(e["by_source"]), "energy_lost_by_element_J": dict(e["by_element"]),
            "time_in_gear_s": dict(e["time_in_gear"]), "shifts": self.shifts,
            "rows": self.cycle.rows, "rows_braking": int(np.sum(moving & (self.cycle.output_torque < 0))),
            "rows_standstill": int(np.sum(~moving)), "rows_not_carried": int(np.sum(~self.carried)),
        }

    def table(self) -> str:
        """The result as plain text: energies, efficiency, losses by source and element, gears.

        Returns
        -------
        str
        """
        s = self.summary()
        c = self.cycle
        lines = [f"{self.name} through {c.name}: {c.rows} rows, {c.duration:g} s; {self.rule}",
                 f"a gear carries a row with {self.limits.describe()}"]
        if c.vehicle is not None:
            lines.append(f"vehicle: {c.vehicle.describe()}")
        eff = "—" if s["efficiency"] is None else f"{s['efficiency']:.4f}"
        lines += [f"energy in {s['energy_in_kWh']:.4f} kWh, out {s['energy_out_kWh']:.4f} kWh, lost "
                  f"{s['energy_lost_kWh']:.4f} kWh; cycle efficiency {eff}", "energy lost by source:"]
        total = max(s["energy_lost_J"], 1e-300)
        for k, v in sorted(s["energy_lost_by_source_J"].items(), key=lambda kv: -kv[1]):
            lines.append(f"  {k:>12}: {v / 3600:10.2f} Wh  {100 * v / total:5.1f} %")
        lines.append("energy lost by element:")
        for k, v in sorted(s["energy_lost_by_element_J"].items(), key=lambda kv: -kv[1]):
            if v > 0:
                lines.append(f"  {k:>12}: {v / 3600:10.2f} Wh  {100 * v / total:5.1f} %")
        gears = ", ".join(f"{g} {v:g} s" for g, v in s["time_in_gear_s"].items())
        lines.append(f"time in gear: {gears}; {s['shifts']} shifts")
        lines.append(f"rows braking (spin losses only) {s['rows_braking']}, at standstill {s['rows_standstill']}"
                     + (f", not carried by their gear within the limits {s['rows_not_carried']} (run in it anyway)"
                        if s["rows_not_carried"] else ""))
        return "\n".join(lines)

    def __repr__(self) -> str:
        eff = "—" if self.efficiency is None else f"{self.efficiency:.4f}"
        return f"<CycleResult {self.name!r} through {self.cycle.name!r}: {self.cycle.rows} rows, η_cycle {eff}>"

    def to_dict(self) -> dict[str, Any]:
        """:meth:`summary` (JSON-ready: no NaN; SI units)."""
        return self.summary()

    def to_json(self) -> str:
        """:meth:`to_dict` as JSON text.

        Returns
        -------
        str
        """
        return json.dumps(self.to_dict(), indent=1, allow_nan=False) + "\n"

    def to_csv(self) -> str:
        """One line per row: time, output speed and torque, gear, powers, losses by source."""
        sources = list(self.losses_by_source)
        head = ["time_s", "output_speed_rpm", "output_torque_Nm", "gear", "input_power_W", "output_power_W", "loss_W",
                *(f"loss_{s}_W" for s in sources), "carried"]
        columns = [self.cycle.time, self.cycle.output_speed, self.cycle.output_torque, None, self.input_power,
                   self.output_power, self.loss, *(self.losses_by_source[s] for s in sources)]
        lines = [",".join(head)]
        for i in range(self.cycle.rows):
            cells = [self.gear[i] if col is None else repr(float(col[i])) for col in columns]
            lines.append(",".join(cells + ["true" if self.carried[i] else "false"]))
        return "\n".join(lines) + "\n"


def _choose(loss: np.ndarray, carries: np.ndarray, moving: np.ndarray, time: np.ndarray,
            rule: GearRule) -> tuple[np.ndarray, int]:
    """The best-gear rule row by row with the minimum dwell and the hysteresis: (gear index per row, shifts)."""
    masked = np.where(carries, loss, np.inf)
    best = np.argmin(masked, axis=0).tolist()
    any_gear = carries.any(axis=0).tolist()
    loss_rows, carries_rows = loss.T.tolist(), carries.T.tolist()
    times, moving_rows = time.tolist(), moving.tolist()
    chosen = [0] * len(times)
    current, changed, shifts = -1, -np.inf, 0
    for i, t in enumerate(times):
        if not moving_rows[i]:
            chosen[i] = max(current, 0)
            continue
        if not any_gear[i]:
            new = 0  # launch or beyond the engine: first gear (counted as not carried)
        elif current < 0 or not carries_rows[i][current]:
            new = best[i]
        elif best[i] != current and t - changed >= rule.min_dwell \
                and loss_rows[i][current] - loss_rows[i][best[i]] > rule.hysteresis:
            new = best[i]
        else:
            new = current
        if new != current:
            shifts += current >= 0
            current, changed = new, t
        chosen[i] = current
    return np.array(chosen, dtype=int), shifts


def run_cycle(transmission, cycle: DriveCycle, *, rule: GearRule | None = None, limits: CarryLimits | None = None,
              progress: Callable[[int, int], None] | None = None) -> CycleResult:
    """Run ``transmission`` through ``cycle``: energies in, out and lost (by source and element).

    Parameters
    ----------
    transmission : Transmission
        With its loss models (``Transmission.from_file`` brings the file's, spin losses included).
    cycle : DriveCycle
    rule : GearRule, optional
        Default: the cycle's gears where it has them, else the best-gear rule (min dwell 2 s).
    limits : CarryLimits, optional
        What a gear must keep to carry a row (default: input 800..6000 1/min).
    progress : callable (done, total), optional
        Called after each gear's batch solve (for a progress bar).

    Returns
    -------
    CycleResult

    Raises
    ------
    ModelError
        A given gear (or a schedule's) that the transmission does not have, named with its line;
        rule ``"given"`` for a cycle without gears.

    Examples
    --------
    >>> from epicyclic.transmission import Transmission
    >>> t = Transmission.from_file("examples/zf_8hp70_geometry.toml")
    >>> c = DriveCycle([0.0, 10.0], [1000.0, 1000.0], [200.0, 200.0], gear=("6", "6"))
    >>> r = run_cycle(t, c)
    >>> abs(r.energy_in - r.energy_out - r.energy_lost) < 1e-6 * r.energy_in
    True

    References
    ----------
    Guzzella & Sciarretta 2013, §3.1; Naunheimer et al. 2011, §7.4.
    """
    t = transmission
    limits = limits or CarryLimits()
    limits.check_elements(e.name for e in t.train.shift_elements)
    if rule is None:
        rule = GearRule("given") if cycle.gear is not None else GearRule("best")
    if rule.mode == "given" and cycle.gear is None:
        raise ModelError(f"{cycle.name}: the rule 'gear given per row' needs a gear column in the cycle.")
    speed = np.where(cycle.output_speed > NEGLIGIBLE, cycle.output_speed, 0.0)
    moving = speed > 0
    torque = np.where(cycle.output_torque > NEGLIGIBLE, cycle.output_torque, 0.0)  # braking: no torque through
    gears = forward_gears(t)
    solved: dict[str, list[tuple[np.ndarray, Any]]] = {}

    def solve(gear: str, rows: np.ndarray):
        points = solve_gear_points(t, gear, speed[rows], torque[rows])
        solved.setdefault(gear, []).append((rows, points))
        return points

    if rule.mode == "best":
        names, shifts = _best_gears(t, gears, speed, torque, moving, cycle.time, rule, limits, solve, progress)
    else:
        if rule.mode == "given":
            names = cycle.gear  # type: ignore[assignment]
        else:
            schedule = rule.schedule
            names = tuple(schedule.gears[k] for k in schedule.gear_index(speed, torque))  # type: ignore[union-attr]
        for i, gear in enumerate(names):
            if gear not in t.schedule:
                column = "gear" if rule.mode == "given" else "output_speed"
                raise ModelError(f"{cycle.where(i, column)}: no gear {gear!r:.40} in the transmission's schedule; "
                                 f"gears are {', '.join(repr(g) for g in t.gears)}.")
        shifts = int(sum(a != b for a, b, m in zip(names, names[1:], moving[1:]) if m))
    return _assemble(t, cycle, names, solved, solve, moving, limits, rule, shifts, progress)


def _spin_bounds(t, gear: str, speed: np.ndarray) -> np.ndarray | None:
    """A lower bound of the loss of ``gear`` at output speeds ``speed``: its spin losses alone.

    The spin losses (clutch drag, pump, churning, windage, seals) depend on the shafts' speeds and the oil
    temperature only, and every other loss is ≥ 0.  The speeds of a one-degree-of-freedom gear are the
    output speed times fixed ratios (one lossless solve at n_out = 1).  None without spin losses, or with
    the thermal balance (its temperature depends on the load-dependent losses).
    """
    from ..solver.batch import solve_batch

    spin = getattr(t, "spin", None)
    if spin is None or spin.thermal:
        return None
    train = t.gear_train(gear)
    unit = solve_batch(train, speeds={t.output: np.array([1.0])}, torques={t.output: np.array([1.0])},
                       drives=[t.input], loads=[t.output])
    speeds = {shaft: float(value[0]) * speed for shaft, value in unit.speeds.items()}
    return np.asarray(spin.evaluate(speeds, train=train, gear=gear, input=t.input).total, dtype=float)


def _best_gears(t, gears, speed, torque, moving, time, rule: GearRule, limits: CarryLimits, solve,
                progress) -> tuple[tuple[str, ...], int]:
    """The best-gear rule over the cycle, solving no gear at a row where it cannot win.

    A gear is solved at a row only where it can carry the row by its kinematics (input speed n_out·i within
    the range, lossless input torque T_out/i within the limit: a lower bound of the real one in drive) and
    where its spin losses alone (:func:`_spin_bounds`, a lower bound of its loss) do not exceed the least
    loss found there (first the gear of the least bound) by more than the hysteresis.  Such a gear is
    never the best gear; it can only be kept by the minimum dwell, and where the rule keeps one, it is
    solved there and the rule run again with its real loss and limits, until nothing changes — so the
    result is the same as solving every gear at every row.
    """
    count, rows_total = len(gears), time.size
    loss = np.full((count, rows_total), np.inf)
    carries = np.zeros((count, rows_total), dtype=bool)
    known = np.zeros((count, rows_total), dtype=bool)
    reach = np.zeros((count, rows_total), dtype=bool)
    bound = np.zeros((count, rows_total))
    bounded = True
    for k, gear in enumerate(gears):
        ratio = abs(t.ratio(gear))
        n_in = speed * ratio
        reach[k] = moving & (n_in >= limits.input_speed[0]) & (n_in <= limits.input_speed[1])
        if limits.max_input_torque is not None:
            reach[k] &= torque / ratio <= limits.max_input_torque
        rows = np.flatnonzero(reach[k])
        value = _spin_bounds(t, gear, speed[rows]) if bounded and rows.size else None
        if value is None and rows.size:
            bounded = False
        elif rows.size:
            bound[k, rows] = value

    def run(k: int, rows: np.ndarray) -> None:
        if rows.size:
            points = solve(gears[k], rows)
            loss[k, rows], carries[k, rows], known[k, rows] = points.loss, limits.carries(points), True

    if not bounded:  # every reachable gear at every row
        for k in range(count):
            run(k, np.flatnonzero(reach[k]))
            if progress is not None:
                progress(k + 1, count + 1)
    else:
        first = np.argmin(np.where(reach, bound, np.inf), axis=0)
        for k in range(count):
            run(k, np.flatnonzero(reach[k] & (first == k)))
        least = np.min(np.where(carries, loss, np.inf), axis=0)
        margin = rule.hysteresis + 1e-9 * np.where(np.isfinite(least), np.abs(least), 0.0)
        for k in range(count):
            run(k, np.flatnonzero(reach[k] & ~known[k] & (bound[k] <= least + margin)))
            if progress is not None:
                progress(k + 1, count + 1)
    while True:
        # a gear not solved at a row loses at least its bound there and is taken to carry it; the rule keeps
        # such a gear only through the dwell, and then it is solved there and the rule runs again
        index, shifts = _choose(np.where(known, loss, bound), known & carries | reach & ~known, moving, time, rule)
        rows = np.flatnonzero(moving & ~known[index, np.arange(rows_total)] & reach[index, np.arange(rows_total)])
        if not rows.size:
            return tuple(gears[k] for k in index), shifts
        for k in np.unique(index[rows]):
            run(int(k), rows[index[rows] == k])


def _assemble(t, cycle: DriveCycle, names, solved, solve, moving, limits: CarryLimits, rule: GearRule, shifts: int,
              progress) -> CycleResult:
    """The per-row powers of the chosen gears (from the rule's solves where it made them, else solved now)."""
    rows_total = cycle.rows
    p_in, p_out, loss = np.zeros(rows_total), np.zeros(rows_total), np.zeros(rows_total)
    carried = np.ones(rows_total, dtype=bool)
    by_source: dict[str, np.ndarray] = {}
    by_element: dict[str, np.ndarray] = {}
    gear_array = np.array(names, dtype=object)
    distinct = list(dict.fromkeys(g for g, m in zip(names, moving) if m))
    for step, gear in enumerate(distinct):
        rows = np.flatnonzero((gear_array == gear) & moving)
        parts = []  # (rows of the cycle, points, index into the points) from the rule's solves, and solved now
        for have_rows, have_points in list(solved.get(gear, ())):
            inside = np.isin(rows, have_rows)
            if inside.any():
                parts.append((rows[inside], have_points, np.searchsorted(have_rows, rows[inside])))
                rows = rows[~inside]
        if rows.size:  # rows the rule did not solve in this gear (a launch in first gear)
            parts.append((rows, solve(gear, rows), slice(None)))
        for rows, points, pick in parts:
            p_in[rows], p_out[rows] = points.input_power[pick], points.output_power[pick]
            loss[rows], carried[rows] = points.loss[pick], limits.carries(points)[pick]
            for target, values in ((by_source, points.losses_by_source), (by_element, points.losses_by_element)):
                for key, value in values.items():
                    target.setdefault(key, np.zeros(rows_total))[rows] = np.broadcast_to(value, points.shape)[pick]
        if progress is not None and rule.mode != "best":
            progress(step + 1, len(distinct))
    if progress is not None and rule.mode == "best":
        progress(len(forward_gears(t)) + 1, len(forward_gears(t)) + 1)
    name = getattr(t, "name", "transmission")
    return CycleResult(name, rule.describe(), limits, cycle, tuple(names), p_in, p_out, loss, by_source, by_element,
                       carried, shifts)
