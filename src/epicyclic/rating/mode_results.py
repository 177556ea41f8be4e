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

import html
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np

from .results import Factor, json_value

__all__ = ["ModeRating", "mode_rows"]

MODE_HEAD = ["quantity", "symbol", "unit", "gear 1", "gear 2", "clause"]


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

    def table(self) -> str:
        """The mode's quantities as a plain-text table (a safety below its minimum ends in ``!``)."""
        from ..geometry._render import text_table

        return text_table(MODE_HEAD, mode_rows(self), title=f"{self.title} — {self.standard}")

    def markdown(self) -> str:
        """The mode's section in Markdown (a safety below its minimum ends in ``!``)."""
        from .report import _md_table

        notes = "".join(f"\n\n*note: {n}*" for n in self.notes)
        return f"#### {self.title} — {self.standard}\n\n{_md_table(MODE_HEAD, mode_rows(self))}{notes}"

    def html(self) -> str:
        """The mode's section as an HTML fragment (a safety below its minimum in red)."""
        from .report import _RED, _html_rows

        esc = html.escape
        head = "".join(f"<th>{esc(h)}</th>" for h in MODE_HEAD)
        cls = "" if self.ok else f" class='below' style='{_RED}'"
        notes = "".join(f"<p class='note'>{esc(n)}</p>" for n in self.notes)
        return (f"<h4{cls}>{esc(self.title)} — {esc(self.standard)}</h4><table><thead><tr>{head}</tr></thead>"
                f"<tbody>{_html_rows(mode_rows(self), (3, 4))}</tbody></table>{notes}")

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

    def cell(symbol, value):
        text = _fmt(value)
        return text + (" !" if symbol == mode.safety and np.any(np.asarray(value, dtype=float) < mode.minimum) else "")

    rows = [[f.name, s, f.unit, cell(s, f.value), "", f.clause] for s, f in mode.factors.items()]
    if mode.gear_factors is not None:
        g1, g2 = mode.gear_factors
        for s in [*g1, *(k for k in g2 if k not in g1)]:     # a gear not rated has no factors
            f = g1.get(s) or g2[s]
            rows.append([f.name, s, f.unit, cell(s, g1[s].value) if s in g1 else "",
                         cell(s, g2[s].value) if s in g2 else "", f.clause])
    return rows
