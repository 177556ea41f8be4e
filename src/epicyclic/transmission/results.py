"""Result objects of a transmission analysis: one gear, and all gears.

Both are frozen and render themselves: ``repr``, ``table()`` (text),
``markdown()``, ``_repr_html_()`` and ``to_dict()`` (JSON-ready).  Values are
dimensionless multiples: shift-element torques per input torque, slip speeds
per input speed, rolling power and losses per input power.

References
----------
Brandenberger 1952, eq. 3' (rolling power) and eqs. 7–10 (efficiency);
Brandenberger 1952, text to Bild 11 and 12 (circulating power).
"""

from __future__ import annotations

import html
import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, Protocol

from ..losses.oil import OIL_WARNING_START
from ..model.elements import Clutch
from ..model.planetary import PlanetarySet
from ..results.solution import Solution
from ..text import markdown_text
from .errors import UnknownGearError
from .input_point import InputPoint


class Scheduled(Protocol):
    """What the results read of a :class:`~epicyclic.transmission.Transmission`."""

    train: Any
    input: str
    output: str
    schedule: Any

__all__ = ["GearResult", "TransmissionAnalysis", "gear_result", "efficiency_text"]

#: Loss sources in report order (as :data:`epicyclic.losses.spin.ALL_SOURCES`).
_SOURCE_ORDER = ("mesh", "bearing", "drag", "clutch_drag", "pump", "churning", "windage", "seals")

#: Ratios closer than this (relative) count as equal (duplicates, direct drive).
RATIO_TOLERANCE = 1e-9


def _fmt(value: float | None, digits: int = 4) -> str:
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "—"
    return f"{value:.{digits}f}"


def efficiency_text(value: float | None, solution: Solution) -> str:
    """An efficiency to 4 decimals, else why there is none: ``"self-locking"``, ``"losses > input"`` or ``"—"``."""
    if value is not None:
        return _fmt(value)
    return solution.self_locking.label if solution.self_locking is not None else "—"


@dataclass(frozen=True)
class GearResult:
    """One gear of a transmission in drive and coast.

    Attributes
    ----------
    gear : str
    engaged : tuple of str
    ratio : float
        i = n_input / n_output (negative: reverse).
    efficiency_drive, efficiency_coast : float or None
        Power out / power in with the input driving (drive) or the output
        driving (coast, engine braking); None where that direction self-locks.
    element_torques : mapping name → float
        Torque carried by each engaged clutch/brake (torque its first shaft
        exerts on it) per input torque, drive with losses.  Signed; a brake's
        torque is its reaction on the shaft it holds, reversed.
    element_torques_ideal : mapping name → float
        The same without losses.
    slip_speeds : mapping name → float
        Speed difference first − second across each open element per input speed.
    rolling_power : mapping set → float
        Rolling power P_w = T_sun (n_sun − n_carrier) of each set per input power (drive).
    set_losses : mapping set → float
        Loss of each set per input power (drive).
    set_status : mapping set → str
        "rolling", "idle" (turns without load) or "locked" (turns as a block or stands).
    circulating_power_ratio : float or None
        Power that circulates around closed loops (Blindleistung) per input
        power (drive); 0 when none circulates, None when the torque split is
        statically indeterminate.
    largest_element_ratio : float or None
        Largest power through any element port per input power (drive); None
        when the torque split is statically indeterminate.
    indeterminate : tuple of str
        Elements whose torque split is statically indeterminate in this gear
        (redundant locking): their torques shown are the minimum-norm split.
    drive, coast : Solution
        The full solutions (not part of ``to_dict``).
    """

    gear: str
    engaged: tuple[str, ...]
    ratio: float
    efficiency_drive: float | None
    efficiency_coast: float | None
    element_torques: Mapping[str, float]
    element_torques_ideal: Mapping[str, float]
    slip_speeds: Mapping[str, float]
    rolling_power: Mapping[str, float]
    set_losses: Mapping[str, float]
    set_status: Mapping[str, str]
    circulating_power_ratio: float | None
    largest_element_ratio: float | None
    indeterminate: tuple[str, ...]
    drive: Solution
    coast: Solution

    @property
    def kind(self) -> str:
        """"reverse", "direct", "overdrive" or "reduction"."""
        return classify(self.ratio)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data (dimensionless multiples, see the class docstring)."""
        return {
            "gear": self.gear, "engaged": list(self.engaged), "ratio": self.ratio, "kind": self.kind,
            "efficiency_drive": self.efficiency_drive, "efficiency_coast": self.efficiency_coast,
            "element_torques_per_input_torque": dict(self.element_torques),
            "element_torques_ideal_per_input_torque": dict(self.element_torques_ideal),
            "slip_speeds_per_input_speed": dict(self.slip_speeds),
            "rolling_power_per_input_power": dict(self.rolling_power),
            "set_losses_per_input_power": dict(self.set_losses),
            "set_status": dict(self.set_status),
            "circulating_power_per_input_power": self.circulating_power_ratio,
            "largest_element_power_per_input_power": self.largest_element_ratio,
            "indeterminate": list(self.indeterminate),
            "loss_sources_per_input_power": self.loss_sources,
            "oil_temperature": self.drive.oil_temperature,
        }

    @property
    def loss_sources(self) -> dict[str, float]:
        """The drive loss by source (mesh, bearing, drag, clutch drag, pump, churning, windage, seals) per input power."""
        p_in = self.drive.input_power
        if not p_in:
            return {}
        parts = self.drive.loss_sources
        ordered = [k for k in _SOURCE_ORDER if k in parts] + sorted(set(parts) - set(_SOURCE_ORDER))
        return {k: parts[k] / p_in for k in ordered if parts[k]}

    def table(self) -> str:
        """Text table: shift elements and sets of this gear."""
        lines = [f"gear {self.gear} ({self.kind}): ratio {self.ratio:.4f}, engaged {', '.join(self.engaged) or '—'}",
                 f"  efficiency drive {_fmt(self.efficiency_drive)}, coast {_fmt(self.efficiency_coast)}"
                 + ("" if self.efficiency_coast is not None else " (self-locking in coast)")
                 + (f", circulating power {self.circulating_power_ratio:.3f} × P_in"
                    if self.circulating_power_ratio is not None else ", circulating power indeterminate")]
        for name, t in self.element_torques.items():
            note = " (indeterminate split)" if name in self.indeterminate else ""
            lines.append(f"  {name:>12}: engaged, torque {t:+.4f} × T_in{note}")
        for name, s in self.slip_speeds.items():
            lines.append(f"  {name:>12}: open, slip {s:+.4f} × n_in")
        for name, status in self.set_status.items():
            lines.append(f"  {name:>12}: {status}, rolling power {self.rolling_power[name]:+.4f} × P_in, "
                         f"loss {self.set_losses[name]:.4f} × P_in")
        return "\n".join(lines)

    def __str__(self) -> str:
        return self.table()

    def __repr__(self) -> str:
        return (f"<GearResult {self.gear!r}: ratio {self.ratio:.4f}, η drive {_fmt(self.efficiency_drive)}, "
                f"coast {_fmt(self.efficiency_coast)}>")

    def _repr_html_(self) -> str:
        return "<pre>" + html.escape(self.table()) + "</pre>"


def classify(ratio: float) -> str:
    """Word for a ratio: reverse (< 0), direct (= 1), overdrive (< 1), reduction (> 1).

    >>> classify(-3.3), classify(1.0), classify(0.67), classify(4.7)
    ('reverse', 'direct', 'overdrive', 'reduction')
    """
    if ratio < 0:
        return "reverse"
    if abs(ratio - 1.0) <= RATIO_TOLERANCE:
        return "direct"
    return "overdrive" if ratio < 1.0 else "reduction"


def _element_torques(t: Scheduled, solution: Solution, input_torque: float) -> dict[str, float]:
    out = {}
    for element in t.train.shift_elements:
        state = solution.elements[element.name]
        if state.engaged:
            port = "first" if isinstance(element, Clutch) else "shaft"
            out[element.name] = state.torques[port] / input_torque
    return out


def gear_result(t: Scheduled, gear: str, ratio: float, drive: Solution, coast: Solution) -> GearResult:
    """Assemble a :class:`GearResult` from the drive and coast solutions of ``gear``."""
    n_in = drive.speed(t.input)
    m_in = drive.torque(t.input)
    p_in = drive.input_power
    ideal = drive.ideal if drive.ideal is not None else drive
    slip = {}
    for element in t.train.shift_elements:
        state = drive.elements[element.name]
        if not state.engaged:
            slip[element.name] = state.slip_speed / n_in
    sets = [e for e in t.train.elements if isinstance(e, PlanetarySet)]
    rolling = {s.name: drive.elements[s.name].rolling_power / p_in for s in sets}
    losses = {s.name: drive.elements[s.name].loss / p_in for s in sets}
    status = {s.name: drive.elements[s.name].status for s in sets}
    return GearResult(
        gear=gear,
        engaged=t.schedule[gear],
        ratio=ratio,
        efficiency_drive=None if drive.self_locking else drive.efficiency,
        efficiency_coast=None if coast.self_locking else coast.efficiency,
        element_torques=MappingProxyType(_element_torques(t, drive, m_in)),
        element_torques_ideal=MappingProxyType(_element_torques(t, ideal, ideal.torque(t.input))),
        slip_speeds=MappingProxyType(slip),
        rolling_power=MappingProxyType(rolling),
        set_losses=MappingProxyType(losses),
        set_status=MappingProxyType(status),
        circulating_power_ratio=drive.circulation.ratio,
        largest_element_ratio=drive.circulation.largest_element_ratio,
        indeterminate=drive.circulation.indeterminate,
        drive=drive,
        coast=coast,
    )


@dataclass(frozen=True)
class TransmissionAnalysis:
    """All gears of a transmission, with steps and spread.

    Attributes
    ----------
    name, input, output : str
    gears : tuple of GearResult
        In schedule order.
    point : InputPoint, optional
        The input speed and torque every gear was analysed at, and where they came from; stated in
        every rendering (the losses of loss models depend on it).

    References
    ----------
    Naunheimer et al., *Automotive Transmissions* (2011), §3.3: ratio spread
    i_1/i_n and step φ_k = i_k/i_(k+1) of a gear series.
    """

    name: str
    input: str
    output: str
    gears: tuple[GearResult, ...]
    point: InputPoint | None = None

    def __getitem__(self, gear: str) -> GearResult:
        for g in self.gears:
            if g.gear == gear:
                return g
        raise UnknownGearError(gear, (g.gear for g in self.gears))

    @property
    def forward(self) -> tuple[GearResult, ...]:
        """Forward gears, largest ratio first."""
        return tuple(sorted((g for g in self.gears if g.ratio > 0), key=lambda g: -g.ratio))

    @property
    def reverse(self) -> tuple[GearResult, ...]:
        return tuple(g for g in self.gears if g.ratio < 0)

    @property
    def steps(self) -> dict[str, float]:
        """Step φ = i_k / i_(k+1) between consecutive forward gears, keyed "k→k+1"."""
        fw = self.forward
        return {f"{a.gear}→{b.gear}": a.ratio / b.ratio for a, b in zip(fw, fw[1:])}

    @property
    def spread(self) -> float | None:
        """Ratio spread i_first / i_last of the forward gears (None with fewer than two)."""
        fw = self.forward
        return fw[0].ratio / fw[-1].ratio if len(fw) >= 2 else None

    @property
    def mean_step(self) -> float | None:
        """Geometric mean step spread^(1/(z−1)) of z forward gears."""
        fw = self.forward
        return self.spread ** (1.0 / (len(fw) - 1)) if len(fw) >= 2 else None

    @property
    def progression(self) -> dict[str, float]:
        """Ratio of consecutive steps φ_k/φ_(k+1) (1 everywhere: geometric series)."""
        values = list(self.steps.items())
        return {f"{a[0]} / {b[0]}": a[1] / b[1] for a, b in zip(values, values[1:])}

    # ------------------------------------------------------------------ rendering
    def _rows(self) -> list[list[str]]:
        step_of = {}
        fw = self.forward
        for a, b in zip(fw, fw[1:]):
            step_of[b.gear] = a.ratio / b.ratio
        rows = []
        for g in self.gears:
            top = max(g.element_torques.items(), key=lambda kv: abs(kv[1]), default=None)
            rolling = [s for s, st in g.set_status.items() if st == "rolling"]
            rows.append([
                g.gear, "+".join(g.engaged), f"{g.ratio:.4f}", _fmt(step_of.get(g.gear), 3),
                efficiency_text(g.efficiency_drive, g.drive), efficiency_text(g.efficiency_coast, g.coast),
                _fmt(g.circulating_power_ratio, 3),
                f"{top[0]} {top[1]:+.3f}" if top else "—",
                ",".join(rolling) or "—",
            ])
        return rows

    HEADER = ("gear", "engaged", "ratio", "step", "η drive", "η coast", "P_circ/P_in",
              "max shift torque /T_in", "sets rolling")

    def table(self) -> str:
        """Plain-text summary table, then steps and spread."""
        rows = [list(self.HEADER)] + self._rows()
        widths = [max(len(r[k]) for r in rows) for k in range(len(self.HEADER))]
        lines = [f"{self.name}: input {self.input!r}, output {self.output!r}"]
        for k, r in enumerate(rows):
            lines.append("  ".join(c.rjust(w) if j >= 2 else c.ljust(w) for j, (c, w) in enumerate(zip(r, widths))))
            if k == 0:
                lines.append("  ".join("-" * w for w in widths))
        lines.append(self._footer())
        split = self.loss_split_lines()
        if split:
            lines += ["", *split]
        return "\n".join(lines)

    def loss_split_lines(self) -> list[str]:
        """Per gear its drive loss by source per input power, when loss models give more than mesh losses."""
        if not any(set(g.loss_sources) - {"mesh"} for g in self.gears):
            return []
        oil = next((g.drive.oil_temperature for g in self.gears if g.drive.oil_temperature is not None), None)
        lines = ["drive losses by source, × P_in" + (f" (oil at {oil:.1f} degC)" if oil is not None else "") + ":"]
        for g in self.gears:
            lines.append(f"  {g.gear}: " + (", ".join(f"{k} {v:.4f}" for k, v in g.loss_sources.items()) or "none"))
        return lines + [f"warning: {w}" for w in self.oil_warnings]

    @property
    def oil_warnings(self) -> tuple[str, ...]:
        """The warnings of the gears' solutions about the oil (a viscosity extrapolated far from its data), once."""
        seen = dict.fromkeys(w for g in self.gears for w in g.drive.warnings if w.startswith(OIL_WARNING_START))
        return tuple(seen)

    def _footer(self) -> str:
        at = f"; analysed at {self.point.describe()}" if self.point is not None else ""
        if self.spread is None:
            return "spread: — (fewer than two forward gears)" + at
        return (f"spread {self.spread:.3f}, mean step {self.mean_step:.3f}, {len(self.forward)} forward, "
                f"{len(self.reverse)} reverse{at}")

    def markdown(self) -> str:
        """GitHub-flavoured Markdown table."""
        esc = markdown_text
        lines = [f"**{esc(self.name)}** (input {esc(self.input)}, output {esc(self.output)})", "",
                 "| " + " | ".join(self.HEADER) + " |", "|" + "---|" * len(self.HEADER)]
        lines += ["| " + " | ".join(esc(c) for c in r) + " |" for r in self._rows()]
        lines += ["", self._footer()]
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        head = "".join(f"<th>{html.escape(h)}</th>" for h in self.HEADER)
        body = "".join("<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>" for r in self._rows())
        return (f"<div><b>{html.escape(self.name)}</b><table><thead><tr>{head}</tr></thead>"
                f"<tbody>{body}</tbody></table><p>{html.escape(self._footer())}</p></div>")

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data: every gear's result, the steps, the spread and the mean step.

        Returns
        -------
        dict
            ``name``, ``input``, ``output``, ``operating_point`` (:meth:`InputPoint.to_dict`, or None),
            ``gears`` (each gear's ``to_dict()``: ratio, efficiencies in drive and coast, element
            torques, ...), ``steps`` (φ = i_k/i_(k+1), keyed ``"k→k+1"``), ``spread``, ``mean_step`` and ``warnings`` (:attr:`oil_warnings`).
        """
        return {
            "name": self.name, "input": self.input, "output": self.output,
            "operating_point": self.point.to_dict() if self.point is not None else None,
            "gears": [g.to_dict() for g in self.gears],
            "steps": self.steps, "spread": self.spread, "mean_step": self.mean_step,
            "warnings": list(self.oil_warnings),
        }

    def __str__(self) -> str:
        return self.table()

    def __repr__(self) -> str:
        ratios = ", ".join(f"{g.gear}: {g.ratio:.3f}" for g in self.gears)
        return f"<TransmissionAnalysis {self.name!r}: {ratios}; spread {_fmt(self.spread, 3)}>"


