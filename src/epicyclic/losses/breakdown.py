"""The losses of a solved train by source and by element: a table, JSON and a stacked bar picture.

:func:`loss_breakdown` reads a :class:`~epicyclic.results.Solution` (each
element's ``loss_sources`` and the housing's auxiliaries: pump, seals);
:func:`gear_loss_breakdown` the drive solutions of every gear of a
:class:`~epicyclic.transmission.TransmissionAnalysis`.  The rows are elements
(or gears), the columns the sources in report order (mesh, bearing, drag,
clutch drag, pump, churning, windage, seals); every value is ≥ 0 and the row
sums are the losses the solver reports (ISO/TR 14179-2: the losses add up).

References
----------
ISO/TR 14179-2:2001 (P_V = P_VZP + P_VZ0 + P_VLP + P_VL0 + P_VD + P_VX).
"""

from __future__ import annotations

import html
import json
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

from .spin import ALL_SOURCES

__all__ = ["LossBreakdown", "loss_breakdown", "gear_loss_breakdown"]

#: What the housing's row stands for.
HOUSING_LABEL = "housing (pump, seals)"


@dataclass(frozen=True)
class LossBreakdown:
    """Losses in W by row (element or gear) and source.

    Attributes
    ----------
    title : str
    rows : mapping row → mapping source → float
        W, ≥ 0; only rows with some loss.
    input_power : mapping row → float or None
        The input power each row's losses are a share of (gears), W; None for elements.
    oil_temperature : float or None
        °C, where the spin losses were evaluated.
    """

    title: str
    rows: Mapping[str, Mapping[str, float]]
    input_power: Mapping[str, float] | None = None
    oil_temperature: float | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "rows", MappingProxyType({r: MappingProxyType(dict(v)) for r, v in self.rows.items()}))

    @property
    def sources(self) -> tuple[str, ...]:
        """The sources with a loss somewhere, in report order."""
        present = {s for v in self.rows.values() for s, w in v.items() if w}
        return tuple(s for s in ALL_SOURCES if s in present) + tuple(sorted(present - set(ALL_SOURCES)))

    def totals(self) -> dict[str, float]:
        """Loss by source summed over the rows, W."""
        return {s: sum(v.get(s, 0.0) for v in self.rows.values()) for s in self.sources}

    @property
    def total(self) -> float:
        return sum(self.totals().values())

    def table(self) -> str:
        """Plain text: one line per row, a column per source and the row total (W)."""
        sources = self.sources
        head = ["", *sources, "total"]
        body = [[r, *(f"{v.get(s, 0.0):.1f}" for s in sources), f"{sum(v.values()):.1f}"] for r, v in self.rows.items()]
        body.append(["all", *(f"{w:.1f}" for w in self.totals().values()), f"{self.total:.1f}"])
        widths = [max(len(str(line[k])) for line in [head, *body]) for k in range(len(head))]
        lines = [f"{self.title}: losses in W by source"
                 + (f" (oil at {self.oil_temperature:.1f} degC)" if self.oil_temperature is not None else "")]
        for k, line in enumerate([head, *body]):
            lines.append("  ".join(c.ljust(w) if j == 0 else c.rjust(w) for j, (c, w) in enumerate(zip(line, widths))))
            if k == 0:
                lines.append("  ".join("-" * w for w in widths))
        return "\n".join(lines)

    def __str__(self) -> str:
        return self.table()

    def __repr__(self) -> str:
        return f"<LossBreakdown {self.title!r}: {len(self.rows)} rows, {self.total:.4g} W>"

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready: ``rows`` (row → source → W), ``totals``, ``total``, ``oil_temperature``, units."""
        return {"title": self.title, "unit": "W", "sources": list(self.sources),
                "rows": {r: dict(v) for r, v in self.rows.items()}, "totals": self.totals(), "total": self.total,
                "input_power": None if self.input_power is None else dict(self.input_power),
                "oil_temperature": self.oil_temperature}

    def to_json(self) -> str:
        """:meth:`to_dict` as JSON text."""
        return json.dumps(self.to_dict(), indent=1, allow_nan=False) + "\n"

    def _repr_html_(self) -> str:
        sources = self.sources
        head = "".join(f"<th>{html.escape(h)}</th>" for h in ("", *sources, "total"))
        body = "".join("<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in
                                        (r, *(f"{v.get(s, 0.0):.1f}" for s in sources), f"{sum(v.values()):.1f}"))
                       + "</tr>" for r, v in self.rows.items())
        return f"<table><caption>{html.escape(self.title)} (W)</caption><thead><tr>{head}</tr></thead>" \
               f"<tbody>{body}</tbody></table>"

    def plot(self, *, figsize: tuple[float, float] = (8.0, 4.2)):
        """A stacked bar per row, one colour per source (matplotlib Figure)."""
        from ..plotting.loss_bars import loss_bar_figure

        return loss_bar_figure(self, figsize=figsize)


def _row(parts: Mapping[str, float]) -> dict[str, float]:
    return {s: max(float(v), 0.0) for s, v in parts.items() if float(v) != 0.0}


def loss_breakdown(solution, title: str = "losses") -> LossBreakdown:
    """The losses of ``solution`` by element and source.

    Parameters
    ----------
    solution : Solution
        A solve with loss models (or a typed-in η0: all of it ``mesh``).
    title : str, default "losses"

    Returns
    -------
    LossBreakdown
        A row per element with a loss, and ``housing (pump, seals)`` for the auxiliaries.
    """
    rows = {name: _row(e.loss_sources) for name, e in solution.elements.items()}
    housing = _row(getattr(solution, "housing_loss_sources", {}) or {})
    if housing:
        rows[HOUSING_LABEL] = housing
    return LossBreakdown(title, {k: v for k, v in rows.items() if v}, None,
                         getattr(solution, "oil_temperature", None))


def gear_loss_breakdown(analysis, title: str | None = None) -> LossBreakdown:
    """The drive losses of every gear of ``analysis`` by source (summed over the elements).

    Parameters
    ----------
    analysis : TransmissionAnalysis
        From :meth:`~epicyclic.transmission.Transmission.analyze_all`.
    title : str, optional
        Default: the transmission's name.

    Returns
    -------
    LossBreakdown
        A row per gear (its drive solution's loss by source, W) with the input power.
    """
    rows, powers = {}, {}
    oil = None
    for g in analysis.gears:
        rows[f"gear {g.gear}"] = _row(g.drive.loss_sources)
        powers[f"gear {g.gear}"] = g.drive.input_power
        oil = getattr(g.drive, "oil_temperature", None) if oil is None else oil
    return LossBreakdown(title or analysis.name, rows, powers, oil)
