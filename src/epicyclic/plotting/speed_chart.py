"""Speed chart across gears: every shaft's speed and every open clutch's slip, per unit input speed.

The chart transmission engineers use to spot over-speeding elements: for
each gear of the schedule (x) the speed of every shaft as a multiple of the
input speed (left), and the slip speed across every clutch or brake that is
open in that gear (right; a brake's slip is the speed of the shaft it would
hold).  Speeds come from the Willis equations of the gear's shift state
(kinematics only); engaged elements have no slip and are left out of the
right panel in that gear.  The largest magnitude on each panel is named.

References
----------
Queitsch, eq. 12 (Willis equation per set); Naunheimer et al.,
*Automotive Transmissions* (2011), shift-element speeds per gear.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

from ..model.elements import HOUSING
from ._common import SHAFT_COLOURS, figure_svg, pyplot
from ._labels import finish
from .context import FigureContext
from .values import clean, fmt, scale_of

__all__ = ["SpeedChart", "speed_chart"]


@dataclass(frozen=True)
class SpeedChart:
    """Speeds per unit input speed across the gears of a transmission.

    Attributes
    ----------
    gears : tuple of str
        Schedule order.
    engaged : mapping gear → tuple of str
    speeds : mapping shaft → (mapping gear → n / n_in)
    slips : mapping shift element → (mapping gear → slip / n_in)
        Only the gears in which the element is open.
    input, output : str
    gear : str or None
        A gear to highlight.
    """

    title: str
    gears: tuple[str, ...]
    engaged: Mapping[str, tuple[str, ...]]
    speeds: Mapping[str, Mapping[str, float]]
    slips: Mapping[str, Mapping[str, float]]
    input: str
    output: str
    gear: str | None = None
    context: FigureContext = field(default_factory=FigureContext)

    def largest(self, table: Mapping[str, Mapping[str, float]]) -> tuple[str, str, float] | None:
        """(name, gear, value) of the largest magnitude in ``speeds`` or ``slips``."""
        found = [(name, g, v) for name, row in table.items() for g, v in row.items()]
        return max(found, key=lambda t: abs(t[2]), default=None)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data: gears, engaged elements, speeds and slips per unit input speed.

        Returns
        -------
        dict
            ``title``, ``unit`` (``"per input speed"``), ``gears``, ``engaged`` (gear → element
            names), ``speeds`` (shaft → gear → n/n_in), ``slips`` (open shift element → gear
            → slip/n_in), ``input`` and ``output``.
        """
        return {"title": self.title, "unit": "per input speed", "gears": list(self.gears),
                "engaged": {g: list(e) for g, e in self.engaged.items()},
                "speeds": {s: dict(v) for s, v in self.speeds.items()},
                "slips": {s: dict(v) for s, v in self.slips.items()}, "input": self.input, "output": self.output}

    def _repr_html_(self) -> str:
        return figure_svg(self.plot())

    def __repr__(self) -> str:
        top = self.largest(self.speeds)
        peak = f"; fastest shaft {top[0]} {fmt(top[2], 4)} × n_in in gear {top[1]}" if top else ""
        return f"<SpeedChart {self.title!r}: {len(self.gears)} gears, {len(self.speeds)} shafts{peak}>"

    def plot(self) -> Any:
        """Figure: shaft speeds (left) and slip speeds of open clutches and brakes (right) per gear."""
        plt = pyplot()
        width = max(11.0, 1.4 * len(self.gears) + 4.0)
        fig, (left, right) = plt.subplots(1, 2, figsize=(width, 5.8))
        texts: list[Any] = []
        self._panel(left, self.speeds, "shaft speeds", texts, bold={self.input, self.output})
        self._panel(right, self.slips, "slip of open clutches and brakes", texts, bold=set(), every_point=True)
        left.set_ylabel("speed per input speed n / n_in")
        right.set_ylabel("slip speed per input speed Δn / n_in")
        state = f"; gear {self.gear} highlighted ({shift_state_words(self.engaged[self.gear])})" if self.gear else ""
        fig.suptitle(f"{self.title}: speed chart across gears\n(Willis kinematics at n_in = 1){state}", fontsize=11)
        finish(fig, texts)
        return fig

    def _panel(self, ax: Any, table: Mapping[str, Mapping[str, float]], what: str, texts: list[Any],
               bold: set[str], every_point: bool = False) -> None:
        x = {g: k for k, g in enumerate(self.gears)}
        dodge = _dodge(table, self.gears)
        for k, (name, row) in enumerate(table.items()):
            colour = SHAFT_COLOURS[k % len(SHAFT_COLOURS)]
            gears = [g for g in self.gears if g in row]
            strong = name in bold
            # a gap where the element is engaged: no line across it; coincident points side by side
            ax.plot([x[g] + dodge.get((name, g), 0.0) for g in self.gears], [row.get(g, float("nan")) for g in self.gears],
                    "o-", color=colour, lw=2.2 if strong else 1.1, ms=5, alpha=0.95)
            role = " (input)" if name == self.input else " (output)" if name == self.output else ""
            for g in (gears if every_point else gears[-1:]):
                texts.append(ax.annotate(name + (role if g == gears[-1] else ""), (x[g] + dodge.get((name, g), 0.0),
                                         row[g]), xytext=(9 if every_point else 6, 0), textcoords="offset points", va="center",
                                         fontsize=7 if every_point else 8, color=colour,
                                         weight="bold" if strong else "normal"))
        top = self.largest(table)
        if top is not None:
            name, gear, value = top
            ax.plot([x[gear] + _dodge(table, self.gears).get((name, gear), 0.0)], [value], "o", ms=13, mfc="none", mec="#C0392B", mew=1.8, zorder=5)
            texts.append(ax.annotate(f"largest: {name} {fmt(value, 4)} × n_in (gear {gear})", (x[gear], value),
                                     xytext=(0, 12 if value >= 0 else -12), textcoords="offset points",
                                     ha="center", va="bottom" if value >= 0 else "top", fontsize=8,
                                     color="#C0392B", bbox={"boxstyle": "round,pad=0.15", "fc": "white",
                                                            "ec": "none", "alpha": 0.85}))
        if self.gear in x:
            ax.axvspan(x[self.gear] - 0.4, x[self.gear] + 0.4, color="#FFE9A8", alpha=0.6, zorder=0)
        ax.axhline(0, color="black", lw=0.7)
        ax.set_xticks(list(x.values()), [f"{g}\n{_engaged_label(self.engaged[g])}" for g in self.gears], fontsize=8)
        ax.set_xlim(-0.5, len(self.gears) - 0.5 + 0.25 * len(self.gears))
        ax.set_xlabel("gear (engaged clutches and brakes)")
        ax.set_title(what, fontsize=10)
        ax.grid(True, alpha=0.3)
        ax.margins(y=0.15)


#: Horizontal distance (in gears) between coincident points of one gear, so that each stays visible.
DODGE = 0.07


def _dodge(table: Mapping[str, Mapping[str, float]], gears: tuple[str, ...]) -> dict[tuple[str, str], float]:
    """(series, gear) → x offset for points that coincide with others in that gear (same value to 1e-9 of
    the panel's largest magnitude): they are set side by side, centred on the gear."""
    scale = max((abs(v) for row in table.values() for v in row.values()), default=0.0) or 1.0
    offsets: dict[tuple[str, str], float] = {}
    for g in gears:
        groups: dict[int, list[str]] = {}
        for name, row in table.items():
            if g in row:
                groups.setdefault(round(row[g] / scale * 1e9), []).append(name)
        for names in groups.values():
            for j, name in enumerate(names):
                if len(names) > 1:
                    offsets[(name, g)] = (j - (len(names) - 1) / 2) * DODGE
    return offsets


def _engaged_label(engaged: tuple[str, ...]) -> str:
    """The engaged elements under a gear's tick: on two lines when there are more than three."""
    if len(engaged) <= 3:
        return "+".join(engaged)
    half = (len(engaged) + 1) // 2
    return "+".join(engaged[:half]) + "+\n" + "+".join(engaged[half:])


def shift_state_words(engaged: tuple[str, ...]) -> str:
    return " + ".join(engaged) + " engaged" if engaged else "all open"


def speed_chart(transmission: Any, *, gear: str | None = None, context: FigureContext | None = None) -> SpeedChart:
    """The speed chart of a transmission (see the module text).

    Parameters
    ----------
    transmission : epicyclic.transmission.Transmission
    gear : str, optional
        A gear to highlight.
    context : FigureContext, optional

    Examples
    --------
    >>> from epicyclic.transmission import Transmission
    >>> chart = speed_chart(Transmission.from_file("examples/simpson_c4_3speed.toml"))
    >>> round(chart.speeds["out"]["1"], 4), round(chart.slips["high_reverse"]["1"], 4)
    (0.4068, 1.8875)
    """
    train = transmission.train
    speeds: dict[str, dict[str, float]] = {s: {} for s in train.moving_shafts}
    slips: dict[str, dict[str, float]] = {e.name: {} for e in train.shift_elements}
    engaged = {}
    for g in transmission.gears:
        n = transmission.speeds(g, 1.0)
        scale = scale_of(n.values())
        gear_train = transmission.gear_train(g)
        engaged[g] = tuple(e.name for e in gear_train.shift_elements if e.engaged)
        for shaft in speeds:
            speeds[shaft][g] = clean(n[shaft], scale)
        for element in gear_train.shift_elements:
            if not element.engaged:
                a, b = element.shafts
                slip = n[a] - (0.0 if b == HOUSING else n[b])
                slips[element.name][g] = clean(slip, scale)
    context = context or FigureContext(title=transmission.name)
    return SpeedChart(context.title or transmission.name, tuple(transmission.gears), MappingProxyType(engaged),
                      MappingProxyType({s: MappingProxyType(v) for s, v in speeds.items()}),
                      MappingProxyType({s: MappingProxyType(v) for s, v in slips.items() if v}),
                      transmission.input, transmission.output, gear, context)
