"""The result of one failure mode of a mesh beyond pitting and root (micropitting, flank fracture …).

:class:`ModeRating` holds a mode's quantities as :class:`~epicyclic.rating.results.Factor` s — of
the mesh and, where they differ, of each gear — its safety against the minimum, the profile along
the path of contact or the depth (arrays, for plots and the JSON) and its notes.  It renders
itself like the other results (``table()``, ``to_dict()``, ``_repr_html_``); the rating reports
add one section per mode (:func:`mode_rows`).

References
----------
ISO/TS 6336-22:2018 (micropitting); ISO/TS 6336-4:2019 (tooth flank fracture); ISO 6336-1:2019,
clause 4 (symbols).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np

from .results import Factor, json_value

__all__ = ["ModeRating", "mode_rows"]

MODE_HEAD = ["quantity", "symbol", "unit", "gear 1", "gear 2", "given / computed", "clause"]


@dataclass(frozen=True)
class ModeRating:
    """One failure mode of one mesh.

    Parameters
    ----------
    mode : str
        ``"micropitting"``, ``"flank_fracture"`` ...
    title : str
        Heading of its report section.
    standard : str
        The method, e.g. ``"ISO/TS 6336-22:2018, method B"``.
    factors : mapping symbol → Factor
        Quantities of the mesh.
    safety : str
        Symbol of the safety in ``factors`` or ``gear_factors`` (``"S_lambda"``, ``"S_FF"``).
    minimum : float
        The minimum safety.
    gear_factors : (mapping, mapping), optional
        Quantities per gear (gear 1, gear 2); the safety may be one of them.
    gears : (str, str)
        Names of the gears.
    profile : mapping name → array, optional
        Along the path or the depth (JSON: lists).
    notes : tuple of str
        What was assumed (defaults taken, ranges left).

    References
    ----------
    ISO 6336-1:2019, clause 4.
    """

    mode: str
    title: str
    standard: str
    factors: Mapping[str, Factor]
    safety: str
    minimum: float
    gear_factors: tuple[Mapping[str, Factor], Mapping[str, Factor]] | None = None
    gears: tuple[str, str] = ("gear 1", "gear 2")
    profile: Mapping[str, Any] = field(default_factory=lambda: MappingProxyType({}))
    notes: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        object.__setattr__(self, "factors", MappingProxyType(dict(self.factors)))
        if self.gear_factors is not None:
            object.__setattr__(self, "gear_factors", tuple(MappingProxyType(dict(g)) for g in self.gear_factors))
        object.__setattr__(self, "profile", MappingProxyType(dict(self.profile)))

    def __getitem__(self, symbol: str):
        return self.factors[symbol].value

    @property
    def value(self):
        """The safety (the lower of the two gears where it is per gear; number or one per case)."""
        if self.safety in self.factors:
            return self.factors[self.safety].value
        values = [np.asarray(g[self.safety].value, dtype=float) for g in self.gear_factors or () if self.safety in g]
        out = np.minimum(*values) if len(values) == 2 else values[0]
        return float(out) if np.ndim(out) == 0 else out

    @property
    def ok(self) -> bool:
        """Whether the safety meets its minimum in every case."""
        return bool(np.all(np.asarray(self.value, dtype=float) >= self.minimum))

    def below_minimum(self) -> str | None:
        """``"S_lambda 0.81 < 1"`` when the safety falls short, else None."""
        if self.ok:
            return None
        return f"{self.safety} {float(np.min(self.value)):.3g} < {self.minimum:g}"

    def to_dict(self) -> dict[str, Any]:
        """JSON data: standard, safety, minimum, ok, factors, per-gear factors, profile, notes."""
        out: dict[str, Any] = {"standard": self.standard, "safety": self.safety, "value": json_value(self.value),
                               "minimum": self.minimum, "ok": self.ok,
                               "factors": {s: f.to_dict() for s, f in self.factors.items()}}
        if self.gear_factors is not None:
            out["gears"] = {name: {s: f.to_dict() for s, f in g.items()}
                            for name, g in zip(self.gears, self.gear_factors)}
        out["profile"] = {k: ({n: json_value(x) for n, x in v.items()} if isinstance(v, Mapping) else json_value(v))
                          for k, v in self.profile.items()}
        out["notes"] = list(self.notes)
        return out

    def section(self):
        """The mode's report section (:class:`~epicyclic.rating.report_render.Section`), every format's rows."""
        from .report_render import Section

        return Section(f"{self.title} — {self.standard}", MODE_HEAD, mode_rows(self), (3, 4), self.notes, level=4,
                       ok=self.ok)

    def table(self) -> str:
        """The mode's quantities as a plain-text table (a safety below its minimum ends in ``!``)."""
        from .report_render import render_text

        return render_text([self.section()])

    def markdown(self) -> str:
        """The mode's section in Markdown (a safety below its minimum ends in ``!``)."""
        from .report_render import render_markdown

        return render_markdown([self.section()]).rstrip("\n")

    def html(self) -> str:
        """The mode's section as an HTML fragment (a safety below its minimum in red)."""
        from .report_render import render_html

        return render_html([self.section()])

    def _repr_html_(self) -> str:
        return self.html()

    def __repr__(self) -> str:
        return (f"ModeRating({self.mode}: {self.safety} {float(np.min(self.value)):.3f} "
                f"(min {self.minimum:g}), ok {self.ok})")


def mode_rows(mode: ModeRating) -> list[list[str]]:
    """Rows of :data:`MODE_HEAD` for a mode: the mesh's quantities, then those per gear.

    Parameters
    ----------
    mode : ModeRating

    Returns
    -------
    list of list of str
        A safety below its minimum ends in ``!``.

    References
    ----------
    ISO 6336-1:2019, clause 4.
    """
    from .report import _fmt
    from .report_render import iso_symbol, iso_unit

    def cell(symbol, value):
        text = _fmt(value)
        return text + (" !" if symbol == mode.safety and np.any(np.asarray(value, dtype=float) < mode.minimum) else "")

    own_minimum = next((s for s in (mode.safety + "_min", mode.safety + "min") if s in mode.factors), None)

    def row(s, f, other=None):
        one = [f.name, iso_symbol(s), iso_unit(f.unit), cell(s, f.value), cell(s, other.value) if other else "",
               f.source, f.clause]
        if s != mode.safety:
            return [] if s == own_minimum else [one]
        if own_minimum is not None:  # the mode's own minimum, moved beside its safety
            m = mode.factors[own_minimum]
            return [one, [m.name, iso_symbol(own_minimum), iso_unit(m.unit), _fmt(m.value), "", m.source or "given",
                          m.clause]]
        minimum = _fmt(mode.minimum)  # the minimum beside the safety
        return [one, [f"minimum {f.name}", iso_symbol(s) + "min", "1", minimum, minimum if other else "", "given",
                      f.clause]]

    rows = [r for s, f in mode.factors.items() for r in row(s, f)]
    if mode.gear_factors is not None:
        g1, g2 = mode.gear_factors
        for s in [*g1, *(k for k in g2 if k not in g1)]:  # a gear not rated has no factors
            if s in g1:
                rows += row(s, g1[s], g2.get(s))
                continue
            for line in row(s, g2[s]):  # only the second gear's: its value in the second column
                line[3], line[4] = "", line[3]
                rows.append(line)
    return rows
