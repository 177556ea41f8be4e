"""Shift map and best gear: the gear of least loss at each point of output speed × output torque.

For every forward gear the transmission is solved once over the whole grid of
output speeds and torques with its loss models
(:func:`~epicyclic.transmission.gear_points.solve_gear_points`: one batch solve
per gear).  At each point the *best gear* is the one with the least loss
among those that can carry the point (:class:`~epicyclic.transmission.gear_points.CarryLimits`:
engine speed range, engine torque, shift-element capacities, no self-locking).
At a given output power the least loss is the highest efficiency,
η = P_out/(P_out + P_V), so the best gear's efficiency is the *efficiency
envelope* of the gears.  With a given shift schedule
(:class:`~epicyclic.transmission.shift_schedule.ShiftSchedule`) the map also
gives the loss the schedule's gear has there and the loss the best gear saves
against it.

References
----------
Naunheimer, Bertsche, Ryborz, Novak, *Automotive Transmissions*, 2nd ed. (2011), §7.4 (shift maps);
Brandenberger 1952, eqs. 7–10; ISO/TR 14179-2:2001 (the gearbox loss by source).
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType
from typing import Any

import numpy as np

from ..errors import ModelError
from ..limits import MAX_MAP_POINTS, check_count
from ..units import to_core_array
from .gear_points import CarryLimits, GearPoints, solve_gear_points
from .shift_schedule import ShiftSchedule

__all__ = ["ShiftMap", "shift_map", "SHIFT_MAP_SUFFIXES", "forward_gears"]

#: File suffixes :meth:`ShiftMap.save` writes.
SHIFT_MAP_SUFFIXES = (".png", ".svg", ".pdf", ".json", ".csv")


def _read_only(values) -> np.ndarray:
    view = np.asarray(values).view()
    view.flags.writeable = False
    return view


def forward_gears(transmission) -> tuple[str, ...]:
    """The forward gears of a transmission, largest ratio first (first gear first).

    Parameters
    ----------
    transmission : Transmission

    Returns
    -------
    tuple of str
    """
    ratios = {g: transmission.ratio(g) for g in transmission.gears}
    return tuple(sorted((g for g, r in ratios.items() if r > 0), key=lambda g: -ratios[g]))


@dataclass(frozen=True, eq=False)
class ShiftMap:
    """Best gear, efficiency envelope and the loss saved against a schedule, over output speed × torque.

    Attributes
    ----------
    name : str
    gears : tuple of str
        The gears compared, first gear first.
    ratios : mapping gear → float
    output_speeds : ndarray (S,)
        1/min.
    output_torques : ndarray (T,)
        N·m.
    loss : ndarray (G, T, S)
        Loss of each gear at each point, W (also where it cannot carry the point).
    efficiency : ndarray (G, T, S)
        η of each gear; NaN where it self-locks.
    carries : ndarray of bool (G, T, S)
        Where each gear can carry the point (:attr:`limits`).
    best : ndarray of int (T, S)
        Index into :attr:`gears` of the best gear; −1 where no gear carries the point.
    limits : CarryLimits
    losses_by_source : mapping source → ndarray (T, S)
        The best gear's loss by source, W (NaN where no gear carries the point).
    schedule : ShiftSchedule or None
    scheduled : ndarray of int (T, S) or None
        Index into :attr:`gears` of the schedule's gear (−1 where the schedule names a gear not compared).
    """

    name: str
    gears: tuple[str, ...]
    ratios: Mapping[str, float]
    output_speeds: np.ndarray
    output_torques: np.ndarray
    loss: np.ndarray
    efficiency: np.ndarray
    carries: np.ndarray
    best: np.ndarray
    limits: CarryLimits
    losses_by_source: Mapping[str, np.ndarray]
    schedule: ShiftSchedule | None = None
    scheduled: np.ndarray | None = None

    def __post_init__(self) -> None:
        for name in ("output_speeds", "output_torques", "loss", "efficiency", "carries", "best", "scheduled"):
            if getattr(self, name) is not None:
                object.__setattr__(self, name, _read_only(getattr(self, name)))
        object.__setattr__(self, "ratios", MappingProxyType(dict(self.ratios)))
        object.__setattr__(self, "losses_by_source",
                           MappingProxyType({k: _read_only(v) for k, v in self.losses_by_source.items()}))

    # ------------------------------------------------------------------ derived arrays
    @property
    def shape(self) -> tuple[int, int]:
        return self.best.shape  # type: ignore[return-value]

    @property
    def output_power(self) -> np.ndarray:
        """P_out = T ω at each point, W (T, S)."""
        speeds, torques = np.meshgrid(self.output_speeds, self.output_torques)
        return torques * speeds * np.pi / 30.0

    def _pick(self, values: np.ndarray, index: np.ndarray) -> np.ndarray:
        picked = np.take_along_axis(values, np.maximum(index, 0)[None], axis=0)[0]
        return np.where(index >= 0, picked, np.nan)

    @property
    def best_loss(self) -> np.ndarray:
        """Loss of the best gear, W (NaN where no gear carries the point)."""
        return self._pick(self.loss, self.best)

    @property
    def envelope(self) -> np.ndarray:
        """The efficiency envelope: η of the best gear (NaN where no gear carries the point)."""
        return self._pick(self.efficiency, self.best)

    @property
    def scheduled_loss(self) -> np.ndarray | None:
        """Loss of the schedule's gear, W (NaN where it cannot carry the point); None without schedule."""
        if self.scheduled is None:
            return None
        carried = self._pick(self.carries.astype(float), self.scheduled) == 1.0
        return np.where(carried, self._pick(self.loss, self.scheduled), np.nan)

    @property
    def saved(self) -> np.ndarray | None:
        """Loss the best gear saves against the schedule's, W (≥ 0; NaN where either cannot carry the point)."""
        scheduled = self.scheduled_loss
        return None if scheduled is None else scheduled - self.best_loss

    def best_gear_names(self) -> np.ndarray:
        """The best gear's name at each point (``""`` where none carries it), array of str (T, S)."""
        names = np.array(list(self.gears) + [""], dtype=object)
        return names[np.where(self.best >= 0, self.best, len(self.gears))]

    # ------------------------------------------------------------------ summary and rendering
    def summary(self) -> dict[str, Any]:
        """Points, the share each gear is best at, the envelope's range, the schedule's loss and the saving.

        Returns
        -------
        dict
            ``points``, ``carried_points`` (some gear carries them), ``best_share`` (gear → share of
            the carried points where it is best), ``envelope_min``/``envelope_max``/``envelope_mean``,
            ``loss_split`` (the best gear's loss by source, share of the sum), and with a schedule
            ``schedule_points`` (carried by the schedule's gear too), ``schedule_uncarried_points``,
            ``saved_mean_W``, ``saved_max_W`` and ``saved_share`` (saved / the schedule's loss, summed
            over the points both carry).
        """
        carried = self.best >= 0
        envelope = self.envelope[carried & np.isfinite(self.envelope)]
        total = sum(float(np.nansum(v)) for v in self.losses_by_source.values())
        out: dict[str, Any] = {
            "points": int(self.best.size),
            "carried_points": int(carried.sum()),
            "best_share": {g: float(np.sum(self.best == k)) / max(int(carried.sum()), 1)
                           for k, g in enumerate(self.gears)},
            "envelope_min": float(envelope.min()) if envelope.size else None,
            "envelope_max": float(envelope.max()) if envelope.size else None,
            "envelope_mean": float(envelope.mean()) if envelope.size else None,
            "loss_split": {k: (float(np.nansum(v)) / total if total > 0 else 0.0)
                           for k, v in self.losses_by_source.items()},
        }
        if self.scheduled is not None:
            saved, scheduled = self.saved, self.scheduled_loss
            both = np.isfinite(saved)
            out.update({
                "schedule_points": int(both.sum()),
                "schedule_uncarried_points": int((carried & ~np.isfinite(scheduled)).sum()),
                "saved_mean_W": float(saved[both].mean()) if both.any() else None,
                "saved_max_W": float(saved[both].max()) if both.any() else None,
                "saved_share": (float(saved[both].sum() / scheduled[both].sum())
                                if both.any() and scheduled[both].sum() > 0 else None),
            })
        return out

    def title(self) -> str:
        """``"<name>: best gear over output speed × torque"``.

        Returns
        -------
        str
        """
        return f"{self.name}: best gear over output speed × output torque"

    def table(self) -> str:
        """The map in a few lines: axes, limits, each gear's share as best gear, envelope, saving.

        Returns
        -------
        str
        """
        s = self.summary()
        n, t = self.output_speeds, self.output_torques
        lines = [self.title(),
                 f"output speed {n.min():g}..{n.max():g} 1/min ({n.size} values), output torque "
                 f"{t.min():g}..{t.max():g} N*m ({t.size} values); gears {', '.join(self.gears)}",
                 f"a gear carries a point with {self.limits.describe()}, and where it does not self-lock",
                 f"carried by some gear: {s['carried_points']} of {s['points']} points"]
        share = ", ".join(f"{g} {100 * v:.1f} %" for g, v in s["best_share"].items() if v > 0)
        lines.append(f"best gear (least loss) at the carried points: {share or 'none'}")
        if s["envelope_min"] is not None:
            lines.append(f"efficiency envelope {s['envelope_min']:.4f} .. {s['envelope_max']:.4f} "
                         f"(mean {s['envelope_mean']:.4f})")
        split = ", ".join(f"{k} {100 * v:.1f} %" for k, v in s["loss_split"].items())
        lines.append(f"best gear's losses by source (sum over the map): {split or 'none'}")
        if self.schedule is not None:
            lines.append(f"against {self.schedule.name} (upshift lines, gears {', '.join(self.schedule.gears)}): "
                         f"{s['schedule_points']} points carried by both")
            if s["saved_mean_W"] is not None:
                lines.append(f"loss saved by the best gear: mean {s['saved_mean_W']:.1f} W, most "
                             f"{s['saved_max_W']:.1f} W, {100 * (s['saved_share'] or 0.0):.2f} % of the schedule's loss")
            if s["schedule_uncarried_points"]:
                lines.append(f"the schedule's gear cannot carry {s['schedule_uncarried_points']} points that "
                             "another gear carries")
        return "\n".join(lines)

    def __repr__(self) -> str:
        return (f"<ShiftMap {self.name!r}: {self.output_torques.size}×{self.output_speeds.size} points, "
                f"gears {', '.join(self.gears)}>")

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data (1/min, N·m, W; rows: torques; NaN and "no gear" as null)."""
        def grid(a: np.ndarray) -> list:
            return [[None if not np.isfinite(v) else float(v) for v in row] for row in a]

        names = self.best_gear_names()
        data: dict[str, Any] = {
            "name": self.name, "gears": list(self.gears), "ratios": dict(self.ratios),
            "units": {"speed": "1/min", "torque": "N*m", "power": "W"},
            "limits": self.limits.to_dict(),
            "output_speeds": self.output_speeds.tolist(), "output_torques": self.output_torques.tolist(),
            "best_gear": [[g or None for g in row] for row in names],
            "envelope": grid(self.envelope), "best_loss": grid(self.best_loss),
            "losses_by_source": {k: grid(v) for k, v in self.losses_by_source.items()},
            "summary": self.summary(),
        }
        if self.schedule is not None:
            data["schedule"] = self.schedule.to_dict()
            data["scheduled_gear"] = [[self.gears[k] if k >= 0 else None for k in row] for row in self.scheduled]
            data["saved"] = grid(self.saved)
        return data

    def to_json(self) -> str:
        """:meth:`to_dict` as JSON text (no NaN).

        Returns
        -------
        str
        """
        return json.dumps(self.to_dict(), indent=1, allow_nan=False) + "\n"

    def to_csv(self) -> str:
        """One line per point: speed, torque, best gear, envelope, best loss, each gear's loss (empty: undefined)."""
        def cell(v: float) -> str:
            return "" if not np.isfinite(v) else repr(float(v))

        head = ["output_speed_rpm", "output_torque_Nm", "best_gear", "envelope", "best_loss_W",
                *(f"loss_gear_{g}_W" for g in self.gears)]
        if self.schedule is not None:
            head += ["scheduled_gear", "saved_W"]
        lines = [",".join(head)]
        names, envelope, best_loss = self.best_gear_names(), self.envelope, self.best_loss
        saved = self.saved
        for i in range(self.output_torques.size):
            for j in range(self.output_speeds.size):
                row = [repr(float(self.output_speeds[j])), repr(float(self.output_torques[i])), names[i, j],
                       cell(envelope[i, j]), cell(best_loss[i, j]),
                       *(cell(self.loss[k, i, j]) if self.carries[k, i, j] else "" for k in range(len(self.gears)))]
                if self.schedule is not None:
                    k = int(self.scheduled[i, j])
                    row += [self.gears[k] if k >= 0 else "", cell(saved[i, j])]
                lines.append(",".join(row))
        return "\n".join(lines) + "\n"

    def plot(self, *, figsize: tuple[float, float] = (10.0, 6.0)):
        """The shift map: gear regions filled and labelled, envelope contours, the schedule over it; a Figure."""
        from ..plotting.shift_map import shift_map_figure

        return shift_map_figure(self, figsize=figsize)

    def _repr_html_(self) -> str:
        from ..plotting._common import result_html

        return result_html(self)

    def save(self, path: str | Path) -> Path:
        """Write the map: ``.png``/``.svg``/``.pdf`` (figure), ``.csv`` or ``.json`` by the suffix."""
        path = Path(path)
        suffix = path.suffix.lower()
        if suffix not in SHIFT_MAP_SUFFIXES:
            raise ModelError(f"shift map: cannot write {path.name!r}; give a file ending in "
                             f"{', '.join(SHIFT_MAP_SUFFIXES)}.")
        from ..plotting._common import save_result

        return save_result(self, path)


def _axis(values, name: str, quantity: str) -> np.ndarray:
    arr = to_core_array(values, quantity, field=f"shift_map: {name}").ravel()
    if arr.size == 0 or not np.all(np.isfinite(arr)) or np.any(arr <= 0):
        raise ModelError(f"shift_map: {name} must be finite numbers > 0, got {values!r:.80}.")
    return np.unique(arr)


def best_gear_index(loss: np.ndarray, carries: np.ndarray) -> np.ndarray:
    """Index of the least loss along axis 0 among the carrying gears (−1 where none carries).

    Parameters
    ----------
    loss : ndarray (G, ...)
    carries : ndarray of bool (G, ...)

    Returns
    -------
    ndarray of int
        Ties go to the first (lower) gear.
    """
    masked = np.where(carries, loss, np.inf)
    index = np.argmin(masked, axis=0)
    return np.where(carries.any(axis=0), index, -1)


def shift_map(transmission, output_speeds: Sequence[float] | np.ndarray, output_torques: Sequence[float] | np.ndarray,
              *, gears: Iterable[str] | None = None, limits: CarryLimits | None = None,
              schedule: ShiftSchedule | None = None) -> ShiftMap:
    """Best gear, efficiency envelope and saving against a schedule, over output speed × output torque.

    Parameters
    ----------
    transmission : Transmission
        With its loss models (``Transmission.from_file`` brings the file's); without any, every
        gear's loss is its typed-in stationary efficiencies' and the best gear is the one of the
        least such loss.
    output_speeds, output_torques : array_like
        Output speeds (1/min) and torques (N·m), > 0; values may carry units.  At most
        :data:`~epicyclic.limits.MAX_MAP_POINTS` points.
    gears : iterable of str, optional
        The gears compared (default: every forward gear, first gear first).
    limits : CarryLimits, optional
        What a gear must keep to carry a point (default: input 800..6000 1/min, no torque limits).
    schedule : ShiftSchedule, optional
        A given shift schedule to compare with.

    Returns
    -------
    ShiftMap

    Raises
    ------
    ModelError
        Bad axes, an unknown gear, a capacity for an element the transmission lacks.
    LimitError
        Too many points.

    Examples
    --------
    >>> from epicyclic.transmission import Transmission
    >>> t = Transmission.from_file("examples/zf_8hp70_geometry.toml")
    >>> m = shift_map(t, [300.0, 1500.0], [200.0, 800.0])
    >>> m.best_gear_names().tolist()
    [['1', '6'], ['1', '6']]

    References
    ----------
    Naunheimer et al. 2011, §7.4; Brandenberger 1952, eqs. 7–10.
    """
    limits = limits or CarryLimits()
    limits.check_elements(e.name for e in transmission.train.shift_elements)
    n = _axis(output_speeds, "output_speeds", "speed")
    t = _axis(output_torques, "output_torques", "torque")
    check_count(n.size * t.size, "shift_map: output speeds × output torques", MAX_MAP_POINTS, "grid points")
    chosen = tuple(forward_gears(transmission) if gears is None else gears)
    if not chosen:
        raise ModelError("shift_map: the transmission has no forward gear to compare.")
    for gear in chosen:
        if gear not in transmission.schedule:
            raise ModelError(f"shift_map: no gear {gear!r:.40} in the schedule; gears are "
                             f"{', '.join(repr(g) for g in transmission.gears)}.")
    speed_grid, torque_grid = np.meshgrid(n, t)
    per_gear: list[GearPoints] = [solve_gear_points(transmission, g, speed_grid, torque_grid) for g in chosen]
    loss = np.stack([p.loss for p in per_gear])
    efficiency = np.stack([p.efficiency for p in per_gear])
    carries = np.stack([limits.carries(p) for p in per_gear])
    best = best_gear_index(loss, carries)
    sources = sorted({s for p in per_gear for s in p.losses_by_source}, key=_source_order)
    by_source = {}
    for source in sources:
        stacked = np.stack([np.broadcast_to(p.losses_by_source.get(source, 0.0), speed_grid.shape) for p in per_gear])
        picked = np.take_along_axis(stacked, np.maximum(best, 0)[None], axis=0)[0]
        by_source[source] = np.where(best >= 0, picked, np.nan)
    scheduled = None
    if schedule is not None:
        index = schedule.gear_index(speed_grid, torque_grid)
        lookup = np.array([chosen.index(g) if g in chosen else -1 for g in schedule.gears])
        scheduled = lookup[index]
    name = getattr(transmission, "name", "transmission")
    return ShiftMap(name, chosen, {g: p.ratio for g, p in zip(chosen, per_gear)}, n, t, loss, efficiency, carries,
                    best, limits, by_source, schedule, scheduled)


_ORDER = ("mesh", "bearing", "drag", "clutch_drag", "pump", "churning", "windage", "seals")


def _source_order(source: str) -> tuple[int, str]:
    return (_ORDER.index(source) if source in _ORDER else len(_ORDER), source)
