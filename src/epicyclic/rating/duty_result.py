"""The results of a duty cycle: energies by case, element and source; bearing lives; damage sums.

Render themselves as text (:meth:`DutyCycleResult.table`), Markdown, HTML and
JSON-ready data (:meth:`DutyCycleResult.to_dict`: every quantity as
``{"value": ..., "unit": ...}``; an infinite life, of a bearing that carries no
load or does not turn, is ``null`` with a note — the JSON never holds NaN or
Infinity).

References
----------
ISO 281:2007, 5.3, 7.3 and clause 9; Palmgren 1924, Miner 1945.
"""

from __future__ import annotations

import html
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..geometry._render import html_table, text_table
from .bearing_life import (
    BearingLifeError,
    BearingRating,
    basic_rating_life,
    equivalent_load,
    rating_life_hours,
    reference_viscosity,
    spectrum_life,
)
from .duty_cycle import DutyCycle

__all__ = ["SOURCE_ORDER", "BearingLife", "CaseEnergy", "DutyCycleResult"]

#: Report order of the loss sources (the losses' own; others follow alphabetically).
SOURCE_ORDER = ("mesh", "bearing", "drag", "spin")


def _finite(value: float) -> float | None:
    return float(value) if math.isfinite(value) else None


def _quantity(value: float, unit: str) -> dict[str, Any]:
    return {"value": _finite(value), "unit": unit}


def _hours_text(value: float) -> str:
    return "inf" if not math.isfinite(value) else f"{value:.4g}"


@dataclass(frozen=True, eq=False)
class CaseEnergy:
    """Energies per case, kWh (per hour of the cycle where it has no total hours).

    Attributes
    ----------
    input, output : ndarray
        Energy in at the drives and out at the loads, kWh.
    lost : mapping element → mapping source → ndarray
        Energy lost per element and source (``mesh``, ``bearing``, ``drag``, ...), kWh.
    """

    input: np.ndarray
    output: np.ndarray
    lost: Mapping[str, Mapping[str, np.ndarray]]

    def sources(self) -> list[str]:
        """The loss sources present, in report order."""
        found = {s for parts in self.lost.values() for s in parts}
        return [s for s in SOURCE_ORDER if s in found] + sorted(found - set(SOURCE_ORDER))

    def by_source(self) -> dict[str, np.ndarray]:
        """Energy lost per source over all elements, per case, kWh."""
        out = {s: np.zeros_like(self.input) for s in self.sources()}
        for parts in self.lost.values():
            for source, value in parts.items():
                out[source] = out[source] + value
        return out

    @property
    def total_lost(self) -> np.ndarray:
        """Energy lost per case, kWh."""
        total = np.zeros_like(self.input)
        for value in self.by_source().values():
            total = total + value
        return total


@dataclass(frozen=True, eq=False)
class BearingLife:
    """One bearing over a duty cycle: loads, speeds, lives per case and over the spectrum.

    Attributes
    ----------
    element : str
        The planetary set.
    position : str
        ``planet 1`` ... or ``sun``, ``ring``, ``carrier``.
    role : str
        ``planet`` or the central member.
    rating : BearingRating
    radial, axial : ndarray
        F_r, F_a per case, N.
    speeds : ndarray
        Speed of the rotating ring relative to the stationary one per case, 1/min.
    shares : ndarray
        Time shares of the cases.
    viscosity : ndarray, optional
        ν of the oil per case, mm²/s, where the rating gives none (the lubricant at the case's oil
        temperature, :attr:`temperature`).
    temperature : ndarray, optional
        The oil temperature per case, °C, that ``viscosity`` is taken at.
    oil_viscosity : ndarray, optional
        The lubricant's ν at that temperature where the rating's ``viscosity`` is typed by hand (a
        note where the two differ by more than 5 %).
    """

    element: str
    position: str
    role: str
    rating: BearingRating
    radial: np.ndarray
    axial: np.ndarray
    speeds: np.ndarray
    shares: np.ndarray
    viscosity: np.ndarray | None = None
    temperature: np.ndarray | None = None
    oil_viscosity: np.ndarray | None = None
    factors: np.ndarray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        # a1 a_ISO per case, now: a viscosity ratio below the standard's range is an input error of this
        # bearing, named here (not when the result is rendered)
        try:
            factors = self.rating.life_factor(self.loads, self.speeds, self.viscosity)
        except BearingLifeError as exc:
            nu = self.rating.viscosity if self.rating.viscosity is not None else self.viscosity
            if nu is None:  # no viscosity at all: the key and where it may come from
                raise BearingLifeError(f"bearing {self.position} of {self.element!r} (key "
                                       f"'bearings.{self.role}.viscosity'): {exc}") from None
            n = np.abs(self.speeds)[(np.abs(self.loads) > 0) & (np.abs(self.speeds) > 0)]
            slowest = float(np.min(n))  # the smallest kappa: nu1 grows as the speed falls
            raise BearingLifeError(
                f"bearing {self.position} of {self.element!r} (key 'bearings.{self.role}.viscosity'): {exc} At "
                f"{slowest:.0f} 1/min nu1 = {float(reference_viscosity(slowest, self.rating.pitch_diameter)):.3g} "
                f"mm^2/s (ISO 281 9.3.3), nu = {float(np.min(nu)):.3g} mm^2/s.") from None
        object.__setattr__(self, "factors", factors)

    @property
    def loads(self) -> np.ndarray:
        """Equivalent dynamic load P = X F_r + Y F_a per case, N."""
        return self.rating.equivalent_dynamic_load(self.radial, self.axial)

    @property
    def case_hours(self) -> np.ndarray:
        """L10h of each case alone, h (inf without load or rotation)."""
        life = basic_rating_life(self.rating.dynamic_load_rating, self.loads, self.rating.life_exponent)
        return rating_life_hours(life, self.speeds)

    @property
    def equivalent_load(self) -> float:
        """P_eq over the spectrum (weighted by revolutions), N."""
        return equivalent_load(self.loads, self.speeds, self.shares, self.rating.life_exponent)

    @property
    def mean_speed(self) -> float:
        """Σ q_i n_i, 1/min."""
        return float(np.sum(self.shares * np.abs(self.speeds)))

    @property
    def life(self) -> float:
        """L10 over the spectrum, 10^6 revolutions: (C/P_eq)^p."""
        return float(basic_rating_life(self.rating.dynamic_load_rating, self.equivalent_load,
                                       self.rating.life_exponent))

    @property
    def life_hours(self) -> float:
        """L10h over the spectrum, h: 1/Σ(q_i/L10h_i)."""
        return spectrum_life(self.case_hours, self.shares)

    @property
    def modified_life_hours(self) -> float | None:
        """L_nmh = 1/Σ(q_i/(a_1 a_ISO,i L10h_i)), h; None without the modified-life inputs."""
        if not self.rating.modified:
            return None
        return spectrum_life(self.case_hours * self.factors, self.shares)

    @property
    def notes(self) -> tuple[str, ...]:
        """What the numbers leave out."""
        out = []
        if self.rating.axial_factor == 0 and np.any(np.abs(self.axial) > 0):
            out.append(f"axial force up to {float(np.max(np.abs(self.axial))):.0f} N not in P (give axial_factor Y)")
        if not math.isfinite(self.life_hours):
            out.append("no load or no rotation in any case: no fatigue")
        typed, oil = self.rating.viscosity, self.oil_viscosity
        if typed is not None and oil is not None and float(np.max(np.abs(oil / typed - 1.0))) > 0.05:
            out.append(f"nu typed {typed:.3g} mm^2/s; [lubricant] gives {float(np.min(oil)):.3g}-"
                       f"{float(np.max(oil)):.3g} mm^2/s at the oil temperature (leave viscosity out to use it)")
        if self.viscosity is not None and self.temperature is not None:
            t, nu = self.temperature, self.viscosity
            out.append(f"nu {float(np.min(nu)):.3g}-{float(np.max(nu)):.3g} mm^2/s: the lubricant at "
                       f"{float(np.min(t)):.1f}-{float(np.max(t)):.1f} degC")
        return tuple(out)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready: inputs, per-case loads/speeds/L10h and the spectrum's P_eq, L10, L10h, L_nmh."""
        modified = self.modified_life_hours
        return {"element": self.element, "position": self.position, "role": self.role,
                "rating": self.rating.to_dict(),
                "cases": [{"F_r": _quantity(fr, "N"), "F_a": _quantity(fa, "N"), "P": _quantity(p, "N"),
                           "n": _quantity(n, "1/min"), "L10h": _quantity(h, "h")}
                          for fr, fa, p, n, h in zip(self.radial, self.axial, self.loads, self.speeds,
                                                     self.case_hours)],
                "P_eq": _quantity(self.equivalent_load, "N"), "n_mean": _quantity(self.mean_speed, "1/min"),
                "L10": _quantity(self.life, "10^6 rev"), "L10h": _quantity(self.life_hours, "h"),
                "Lnmh": None if modified is None else _quantity(modified, "h"),
                "notes": list(self.notes)}


@dataclass(frozen=True, eq=False)
class DutyCycleResult:
    """A train over a duty cycle (:func:`~epicyclic.rating.duty_analysis.analyse_duty_cycle`).

    Attributes
    ----------
    duty : DutyCycle
    energy : CaseEnergy
    bearings : tuple of BearingLife
    per_hour : bool
        True for a cycle of shares without total hours: energies are per hour of the cycle.
    title : str
    damage : tuple of GearDamage
        Flank and root damage sums per gear of every mesh
        (:class:`~epicyclic.rating.duty_damage.GearDamage`), empty without a tooth rating.
    required_life : float or None
        The life the bearings must reach, h (the cycle's hours, else the rating's ``life``).
    """

    duty: DutyCycle
    energy: CaseEnergy
    bearings: tuple[BearingLife, ...] = ()
    per_hour: bool = False
    title: str = ""
    damage: tuple[Any, ...] = field(default_factory=tuple)
    required_life: float | None = None

    @property
    def shortfalls(self) -> tuple[Any, ...]:
        """Every case and sum below its minimum (:func:`~epicyclic.rating.duty_checks.shortfalls`)."""
        from .duty_checks import shortfalls

        return shortfalls(self, self.required_life)

    @property
    def ok(self) -> bool:
        """Whether nothing is below its minimum."""
        return not self.shortfalls

    @property
    def input_energy(self) -> float:
        """Σ E_in, kWh."""
        return float(np.sum(self.energy.input))

    @property
    def output_energy(self) -> float:
        """Σ E_out, kWh."""
        return float(np.sum(self.energy.output))

    @property
    def lost_energy(self) -> float:
        """Σ E_lost, kWh."""
        return float(np.sum(self.energy.total_lost))

    @property
    def cycle_efficiency(self) -> float:
        """Σ E_out / Σ E_in (NaN when no energy enters)."""
        return self.output_energy / self.input_energy if self.input_energy > 0 else math.nan

    @property
    def case_efficiency(self) -> np.ndarray:
        """E_out/E_in per case (NaN where no energy enters)."""
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(self.energy.input > 0, self.energy.output / np.where(self.energy.input > 0,
                                                                                 self.energy.input, 1.0), np.nan)

    def lost_by_element(self) -> dict[str, dict[str, float]]:
        """Σ over the cycle of the energy lost per element and source, kWh."""
        return {e: {s: float(np.sum(v)) for s, v in parts.items()} for e, parts in self.energy.lost.items()
                if parts}

    # ------------------------------------------------------------------ rendering
    @property
    def _energy_unit(self) -> str:
        return "kWh per cycle hour" if self.per_hour else "kWh"

    def _case_rows(self) -> tuple[list[str], list[list[object]]]:
        sources = self.energy.sources()
        by_source = self.energy.by_source()
        safeties = self._case_safeties()
        head = ["case", "gear", "hours" if not self.per_hour else "share", "E_in", "E_out",
                *[f"lost {s}" for s in sources], "eta", *(["min S_H", "min S_F"] if safeties else [])]
        durations = self.duty.shares if self.per_hour else self.duty.hours
        rows: list[list[object]] = []
        for k, case in enumerate(self.duty.cases):
            eta = self.case_efficiency[k]
            rows.append([case.name, case.gear or "-", f"{durations[k]:.6g}", f"{self.energy.input[k]:.4g}",
                         f"{self.energy.output[k]:.4g}", *[f"{by_source[s][k]:.4g}" for s in sources],
                         "-" if not math.isfinite(eta) else f"{eta:.4f}", *[column[k] for column in safeties]])
        eta = self.cycle_efficiency
        rows.append(["cycle", "", f"{np.sum(durations):.6g}", f"{self.input_energy:.4g}",
                     f"{self.output_energy:.4g}", *[f"{float(np.sum(by_source[s])):.4g}" for s in sources],
                     "-" if not math.isfinite(eta) else f"{eta:.4f}", *([""] * len(safeties))])
        return head, rows

    def _case_safeties(self) -> list[list[str]]:
        """Per case the smallest S_H and S_F over the gears, marked ``!`` below S_Hmin/S_Fmin ([] without)."""
        rated = [d for d in self.damage if getattr(d, "S_H", None) is not None]
        if not rated:
            return []
        out = []
        for key, limit in (("S_H", rated[0].S_Hmin), ("S_F", rated[0].S_Fmin)):
            low = np.min(np.vstack([getattr(d, key) for d in rated]), axis=0)
            out.append([f"{v:.4g}" + (" !" if not v >= limit else "") for v in low])
        return out

    def _element_rows(self) -> tuple[list[str], list[list[object]]]:
        sources = self.energy.sources()
        head = ["element", *sources, "total"]
        rows = [[e, *[f"{parts.get(s, 0.0):.4g}" for s in sources], f"{sum(parts.values()):.4g}"]
                for e, parts in self.lost_by_element().items()]
        return head, rows

    _BEARING_HEAD = ("set", "bearing", "type", "C [N]", "p", "P_eq [N]", "n_mean [1/min]", "L10 [1e6 rev]",
                     "L10h [h]", "Lnmh [h]", "notes")

    def _bearing_rows(self) -> list[list[object]]:
        def life(value: float | None, checked: bool) -> str:
            if value is None:
                return "-"
            short = checked and self.required_life is not None and not value >= self.required_life
            return _hours_text(value) + (" !" if short else "")

        return [[b.element, b.position, b.rating.type, f"{b.rating.dynamic_load_rating:.0f}",
                 f"{b.rating.life_exponent:.4g}", f"{b.equivalent_load:.1f}", f"{b.mean_speed:.1f}",
                 _hours_text(b.life), life(b.life_hours, b.modified_life_hours is None),
                 life(b.modified_life_hours, True), "; ".join(b.notes)]
                for b in self.bearings]

    def _sections(self) -> list[tuple[str, list[str], list[list[object]]]]:
        head, rows = self._case_rows()
        out = [(f"{self.title}: {self.duty.name}, {len(self.duty)} cases; energies in {self._energy_unit}", head, rows)]
        head, rows = self._element_rows()
        if rows:
            out.append((f"energy lost by element and source, {self._energy_unit}", head, rows))
        if self.bearings:
            required = "" if self.required_life is None else f", required {self.required_life:.6g} h"
            out.append((f"bearing rating life over the cycle (ISO 281:2007){required}", list(self._BEARING_HEAD),
                        self._bearing_rows()))
        if self.damage:
            from .duty_damage import DAMAGE_HEAD

            out.append(("Palmgren-Miner damage sums of the teeth over the cycle (ISO 6336-6; D < 1: lasts)",
                        DAMAGE_HEAD, [d.row() for d in self.damage]))
        return out

    def table(self) -> str:
        """Text tables: per case and cycle energies, losses by element and source, bearing lives, damage."""
        text = "\n\n".join(text_table(h, r, title=t) for t, h, r in self._sections())
        missed = self.shortfalls
        return text + (f"\n\nBELOW MINIMUM: {len(missed)} value(s), marked !" if missed else "")

    def markdown(self) -> str:
        """The same tables in Markdown."""
        parts = [f"# Duty cycle: {self.title}".replace("<", "&lt;")]
        for title, head, rows in self._sections():
            def cell(v: object) -> str:
                return str(v).replace("|", "\\|").replace("<", "&lt;")
            parts.append(f"## {cell(title)}\n\n| " + " | ".join(cell(h) for h in head) + " |\n|"
                         + "---|" * len(head) + "\n" + "\n".join("| " + " | ".join(cell(v) for v in r) + " |"
                                                                  for r in rows))
        return "\n\n".join(parts) + "\n"

    def _repr_html_(self) -> str:
        return "".join(html_table(h, r, title=t) for t, h, r in self._sections())

    def html(self) -> str:
        """A standalone HTML page of the tables."""
        title = html.escape(f"Duty cycle: {self.title}")
        return (f"<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>{title}</title></head><body>"
                f"<h1>{title}</h1>{self._repr_html_()}</body></html>")

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready: cases with energies (kWh) by source, the cycle's totals and efficiency, bearings, damage."""
        unit = "kWh/h" if self.per_hour else "kWh"
        by_source = self.energy.by_source()
        cases = []
        for k, case in enumerate(self.duty.cases):
            cases.append({
                "name": case.name, "gear": case.gear, "share": float(self.duty.shares[k]),
                "hours": None if self.duty.hours is None else _quantity(float(self.duty.hours[k]), "h"),
                "energy_in": _quantity(float(self.energy.input[k]), unit),
                "energy_out": _quantity(float(self.energy.output[k]), unit),
                "energy_lost": {s: _quantity(float(v[k]), unit) for s, v in by_source.items()},
                "energy_lost_by_element": {e: {s: _quantity(float(v[k]), unit) for s, v in parts.items()}
                                           for e, parts in self.energy.lost.items() if parts},
                "efficiency": _finite(float(self.case_efficiency[k])),
            })
        return {
            "title": self.title, "duty_cycle": self.duty.name, "per_cycle_hour": self.per_hour,
            "total_hours": None if self.duty.total_hours is None else _quantity(self.duty.total_hours, "h"),
            "cases": cases,
            "cycle": {"energy_in": _quantity(self.input_energy, unit),
                      "energy_out": _quantity(self.output_energy, unit),
                      "energy_lost": {s: _quantity(float(np.sum(v)), unit) for s, v in by_source.items()},
                      "energy_lost_by_element": {e: {s: _quantity(v, unit) for s, v in parts.items()}
                                                 for e, parts in self.lost_by_element().items()},
                      "efficiency": _finite(self.cycle_efficiency)},
            "bearings": [b.to_dict() for b in self.bearings],
            "damage": [d.to_dict() for d in self.damage],
            "required_life": None if self.required_life is None else _quantity(self.required_life, "h"),
            "shortfalls": [m.to_dict() for m in self.shortfalls], "ok": self.ok,
        }

    def __repr__(self) -> str:
        eta = self.cycle_efficiency
        return (f"<DutyCycleResult {self.title!r}: {len(self.duty)} cases, E_in {self.input_energy:.4g} "
                f"{self._energy_unit}, cycle efficiency {eta:.4f}, {len(self.bearings)} bearings>")

    def __str__(self) -> str:
        return self.table()


