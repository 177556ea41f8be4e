"""Results of a shift or launch: time traces and the shift's figures, as frozen value objects.

Units: time s, speeds 1/min, torques N·m, powers W, energies J, pressures bar in tables (Pa in the
objects and JSON), specific energy J/mm² and specific power W/mm² per friction area (the units of
the clutch literature), temperatures K.

References
----------
Naunheimer, H., Bertsche, B., Ryborz, J., Novak, W.: *Automotive Transmissions*, 2nd ed., Springer
2011, §10.2 (specific friction work and power per friction area as the sizing figures of a wet
clutch).
"""

from __future__ import annotations

import html
import io
import json
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np

__all__ = ["ElementTrace", "Traces", "ElementFigures", "EnergyBalance", "ShiftResult"]


def _frozen(array) -> np.ndarray:
    out = np.array(array, dtype=float)
    out.setflags(write=False)
    return out


@dataclass(frozen=True, eq=False)
class ElementTrace:
    """One shift element over time: slip (1/min), torque (N·m), slip power (W), energy (J), pressure (Pa), stuck."""

    slip: np.ndarray
    torque: np.ndarray
    power: np.ndarray
    energy: np.ndarray
    pressure: np.ndarray
    locked: np.ndarray

    def __post_init__(self) -> None:
        for name in ("slip", "torque", "power", "energy", "pressure"):
            object.__setattr__(self, name, _frozen(getattr(self, name)))
        locked = np.array(self.locked, dtype=bool)
        locked.setflags(write=False)
        object.__setattr__(self, "locked", locked)


@dataclass(frozen=True, eq=False)
class Traces:
    """Every quantity over time at the output steps.

    Attributes
    ----------
    time : ndarray
        s.
    speeds : mapping shaft → ndarray
        1/min.
    shaft_torques : mapping shaft → ndarray
        The net torque that accelerates each shaft, (J ω̇) of its row, N·m.
    set_torques : mapping set or stage → ndarray
        The sun (first) torque of every set or stage, N·m.
    elements : mapping name → ElementTrace
    input_torque, output_torque : ndarray
        N·m at the input (drive) and out of the output shaft into the load (with the load's inertia).
    vehicle_acceleration, vehicle_jerk : ndarray or None
        m/s², m/s³ (the jerk by central differences of the acceleration at the output steps).
    """

    time: np.ndarray
    speeds: Mapping[str, np.ndarray]
    shaft_torques: Mapping[str, np.ndarray]
    set_torques: Mapping[str, np.ndarray]
    elements: Mapping[str, ElementTrace]
    input_torque: np.ndarray
    output_torque: np.ndarray
    vehicle_acceleration: np.ndarray | None = None
    vehicle_jerk: np.ndarray | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "time", _frozen(self.time))
        for name in ("speeds", "shaft_torques", "set_torques"):
            object.__setattr__(self, name, MappingProxyType({k: _frozen(v) for k, v in getattr(self, name).items()}))
        object.__setattr__(self, "elements", MappingProxyType(dict(self.elements)))
        for name in ("input_torque", "output_torque", "vehicle_acceleration", "vehicle_jerk"):
            if getattr(self, name) is not None:
                object.__setattr__(self, name, _frozen(getattr(self, name)))

    def columns(self) -> dict[str, np.ndarray]:
        """Column name (with unit) → values, in a fixed order: the CSV's columns."""
        out = {"time [s]": self.time}
        out.update({f"n_{s} [1/min]": v for s, v in self.speeds.items()})
        out["T_in [N*m]"] = self.input_torque
        out["T_out [N*m]"] = self.output_torque
        for name, e in self.elements.items():
            out[f"{name}_slip [1/min]"] = e.slip
            out[f"{name}_torque [N*m]"] = e.torque
            out[f"{name}_power [W]"] = e.power
            out[f"{name}_energy [J]"] = e.energy
            out[f"{name}_pressure [bar]"] = e.pressure / 1e5
        out.update({f"T_{s}_net [N*m]": v for s, v in self.shaft_torques.items()})
        out.update({f"T_{k}_sun [N*m]": v for k, v in self.set_torques.items()})
        if self.vehicle_acceleration is not None:
            out["a_vehicle [m/s^2]"] = self.vehicle_acceleration
            out["jerk [m/s^3]"] = self.vehicle_jerk
        return out

    def to_csv(self) -> str:
        """The traces as CSV, one row per output step."""
        cols = self.columns()
        buffer = io.StringIO()
        buffer.write(",".join(cols) + "\n")
        data = np.column_stack(list(cols.values()))
        for row in data:
            buffer.write(",".join(f"{v:.10g}" for v in row) + "\n")
        return buffer.getvalue()


@dataclass(frozen=True)
class ElementFigures:
    """The figures of one element over the run.

    Attributes
    ----------
    energy : float
        Friction (and drag) work, J.
    peak_power : float
        W.
    specific_energy, specific_power : float or None
        J/mm² and W/mm² per friction area (None without a friction area).
    temperature_rise : float or None
        K of the lumped plates (None without a heat capacity).
    slipping_time : float
        s during which the element slipped while carrying friction torque.
    """

    name: str
    energy: float
    peak_power: float
    specific_energy: float | None
    specific_power: float | None
    temperature_rise: float | None
    slipping_time: float


@dataclass(frozen=True)
class EnergyBalance:
    """Energy in = energy to the load + losses + change of kinetic energy, J, and the residual.

    Attributes
    ----------
    input, load, mesh, elements, kinetic_change, residual : float
        J; residual = input − load − mesh − elements − kinetic_change.
    scale : float
        The energy it is measured against: max(|input|, |load|, kinetic energy at start and end), J.
    """

    input: float
    load: float
    mesh: float
    elements: float
    kinetic_change: float
    residual: float
    scale: float

    @property
    def relative_residual(self) -> float:
        return abs(self.residual) / self.scale if self.scale > 0 else 0.0


@dataclass(frozen=True, eq=False)
class ShiftResult:
    """A simulated shift (or launch): its phases, per-element figures, warnings and traces.

    Attributes
    ----------
    kind : str
        ``"shift"`` or ``"launch"``.
    from_gear, to_gear : str
    completed : bool
        The on-coming element (a launch: the launch element) stuck by the end and stayed stuck.
    status : str
        One sentence: completed, or why not ("shift not completed ...").
    duration : float
        The simulated time, s (the bound, stated before the run).
    command_time : float
        When the shift began, s.
    shift_time, torque_phase, inertia_phase : float or None
        s (None where the phase did not happen or the shift did not complete).
    elements : mapping name → ElementFigures
    warnings : tuple of str
    balance : EnergyBalance
    traces : Traces
    events : int
        Stick/slip changes.
    assumptions : tuple of str
        The defaults used, stated.
    """

    kind: str
    from_gear: str
    to_gear: str
    completed: bool
    status: str
    duration: float
    command_time: float
    shift_time: float | None
    torque_phase: float | None
    inertia_phase: float | None
    elements: Mapping[str, ElementFigures]
    warnings: tuple[str, ...]
    balance: EnergyBalance
    traces: Traces = field(repr=False)
    events: int = 0
    assumptions: tuple[str, ...] = ()
    phases: Mapping[str, tuple[float, float]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        object.__setattr__(self, "elements", MappingProxyType(dict(self.elements)))
        object.__setattr__(self, "phases", MappingProxyType(dict(self.phases)))

    # ------------------------------------------------------------------ rendering
    def summary_rows(self) -> list[tuple[str, str]]:
        """(label, value) lines of the shift's figures."""
        def s(v):
            return "—" if v is None else f"{v:.4g} s"
        b = self.balance
        if self.kind == "shift":
            rows = [("shift", f"{self.from_gear} → {self.to_gear}"), ("status", self.status),
                    ("simulated", f"{self.duration:g} s (bound)"), ("shift time", s(self.shift_time)),
                    ("torque phase", s(self.torque_phase)), ("inertia phase", s(self.inertia_phase))]
        else:  # a launch: from the command to the lock-up, and the launch element's slip phase
            rows = [("launch", f"in gear {self.to_gear}"), ("status", self.status),
                    ("simulated", f"{self.duration:g} s (bound)"), ("launch time", s(self.shift_time)),
                    ("slip phase", s(self.inertia_phase))]
        return rows + [("stick/slip changes", str(self.events)),
                ("energy in", f"{b.input:.6g} J"),
                ("energy balance residual", f"{b.residual:.3g} J ({b.relative_residual:.2g} of {b.scale:.6g} J)")]

    def element_rows(self) -> list[list[str]]:
        def g(v, digits=4):
            return "—" if v is None else f"{v:.{digits}g}"
        return [[e.name, g(e.energy), g(e.peak_power), g(e.specific_energy), g(e.specific_power),
                 g(e.temperature_rise), g(e.slipping_time)] for e in self.elements.values()]

    ELEMENT_HEADERS = ("element", "energy [J]", "peak power [W]", "energy/area [J/mm²]", "power/area [W/mm²]",
                       "ΔT plates [K]", "slipping [s]")

    def table(self) -> str:
        """The figures as a text table."""
        width = max(len(k) for k, _ in self.summary_rows())
        lines = [f"{k.ljust(width)}  {v}" for k, v in self.summary_rows()]
        rows = self.element_rows()
        headers = list(self.ELEMENT_HEADERS)
        widths = [max(len(h), *(len(r[k]) for r in rows)) if rows else len(h) for k, h in enumerate(headers)]
        lines += ["", "  ".join(h.ljust(w) for h, w in zip(headers, widths)), "  ".join("-" * w for w in widths)]
        lines += ["  ".join(c.rjust(w) if k else c.ljust(w) for k, (c, w) in enumerate(zip(r, widths)))
                  for r in rows]
        lines += [f"warning: {w}" for w in self.warnings]
        lines += [f"assumed: {a}" for a in self.assumptions]
        return "\n".join(lines)

    def __str__(self) -> str:
        return self.table()

    def __repr__(self) -> str:
        what = f"{self.from_gear}->{self.to_gear}" if self.kind == "shift" else f"launch in {self.to_gear}"
        time = f", shift time {self.shift_time:.4g} s" if self.shift_time is not None else ""
        return f"<ShiftResult {what}: {'completed' if self.completed else 'NOT completed'}{time}, " \
               f"{len(self.warnings)} warning(s)>"

    def _repr_html_(self) -> str:
        summary = "".join(f"<tr><th>{html.escape(k)}</th><td>{html.escape(v)}</td></tr>"
                          for k, v in self.summary_rows())
        head = "".join(f"<th>{html.escape(h)}</th>" for h in self.ELEMENT_HEADERS)
        body = "".join("<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>"
                       for r in self.element_rows())
        warn = "".join(f"<li>{html.escape(w)}</li>" for w in self.warnings)
        return (f"<table>{summary}</table><table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"
                + (f"<ul>{warn}</ul>" if warn else ""))

    def to_dict(self, traces: bool = True) -> dict[str, Any]:
        """JSON-ready (no NaN or infinity; SI units named in the keys)."""
        def clean(v):
            if v is None:
                return None
            v = float(v)
            return v if math.isfinite(v) else None
        out: dict[str, Any] = {
            "kind": self.kind, "from_gear": self.from_gear, "to_gear": self.to_gear, "completed": self.completed,
            "status": self.status, "duration_s": self.duration, "command_time_s": self.command_time,
            "shift_time_s": clean(self.shift_time), "torque_phase_s": clean(self.torque_phase),
            "inertia_phase_s": clean(self.inertia_phase), "events": self.events,
            "phases_s": {k: [clean(a), clean(b)] for k, (a, b) in self.phases.items()},
            "elements": {e.name: {"energy_J": clean(e.energy), "peak_power_W": clean(e.peak_power),
                                  "specific_energy_J_mm2": clean(e.specific_energy),
                                  "specific_power_W_mm2": clean(e.specific_power),
                                  "temperature_rise_K": clean(e.temperature_rise),
                                  "slipping_time_s": clean(e.slipping_time)} for e in self.elements.values()},
            "warnings": list(self.warnings), "assumptions": list(self.assumptions),
            "energy_balance_J": {k: clean(getattr(self.balance, k)) for k in
                                 ("input", "load", "mesh", "elements", "kinetic_change", "residual", "scale")},
        }
        if traces:
            out["traces"] = {k: [clean(x) for x in v] for k, v in self.traces.columns().items()}
        return out

    def to_json(self, traces: bool = True) -> str:
        return json.dumps(self.to_dict(traces), allow_nan=False, ensure_ascii=False)

    def to_csv(self) -> str:
        """The traces as CSV."""
        return self.traces.to_csv()

    def plot(self, **kwargs):
        """The test-bench picture (:func:`epicyclic.plotting.shift_bench.shift_bench_figure`)."""
        from ..plotting.shift_bench import shift_bench_figure

        return shift_bench_figure(self, **kwargs)
