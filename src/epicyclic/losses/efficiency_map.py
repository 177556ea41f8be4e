"""Efficiency maps: η over input speed × input torque, with the losses split by source.

:func:`efficiency_map` solves a train (one gear of a transmission) on a grid of
input speeds and torques with the elements' loss models — one batch solve per
round of the load-dependent friction (:func:`~epicyclic.losses.solve.solve_batch_with_losses`),
never a loop over points — and returns an :class:`EfficiencyMap` that plots
itself (η contours and the share of the load-independent losses), writes CSV
and JSON and renders in notebooks.

References
----------
Brandenberger 1952, eqs. 7–10 (η by the direction of power flow); ISO/TR 14179-2:2001
(load-dependent mesh losses and no-load losses add up to the gearbox loss).
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType
from typing import Any

import numpy as np

from ..errors import ModelError
from ..limits import MAX_MAP_POINTS, check_count
from ..model.train import GearTrain
from ..units import Units, to_core_array, unit_factor

#: Grid points solved at once.  The batch solve's temporary arrays grow with its points (about 3.3 kB a point
#: for the ZF 8HP with geometry and loss models, measured: 132 MB for 200 × 200), so a map is solved in blocks
#: of torque rows of at most this many points and joined: the documented maximum of
#: :data:`~epicyclic.limits.MAX_MAP_POINTS` (10^6) needs about 0.25 GB at a time instead of 3.3 GB, within a
#: page worker's default 2 GiB (``epicyclic serve --worker-memory``).  The points are independent (one
#: operating point each), so the blocks give the same numbers as one solve (tests/losses).
MAP_BLOCK_POINTS = 1 << 16
from .element import ElementLosses
from .spin import ALL_SOURCES as SOURCES
from .solve import solve_batch_with_losses

__all__ = ["EfficiencyMap", "efficiency_map", "MAP_SUFFIXES"]

#: File suffixes :meth:`EfficiencyMap.save` writes.
MAP_SUFFIXES = (".png", ".svg", ".pdf", ".csv", ".json")


@dataclass(frozen=True, eq=False)
class EfficiencyMap:
    """η and losses of a train on a grid of input speed × input torque.

    Attributes
    ----------
    name : str
    gear : str or None
    direction : {"drive", "coast"}
    input, output : str
        The input and output shafts.
    speeds : ndarray (S,)
        Input speeds, 1/min.
    torques : ndarray (T,)
        Input torque magnitudes, N·m (coast: the output torque is torque × |ratio|).
    efficiency : ndarray (T, S)
        NaN where the train self-locks or no power flows.
    input_power, output_power, loss : ndarray (T, S)
        W.
    losses : mapping source → ndarray (T, S)
        Losses by source (``mesh``, ``bearing``, ``drag``, ``clutch_drag``, ``pump``, ``churning``,
        ``windage``, ``seals``), W.
    self_locking : ndarray of bool (T, S)
    ratio : float
        n_input/n_output.
    units : Units, optional
        The units the summary and the figure show speeds and torques in (a
        train file's ``[units]``; default 1/min and N·m).  The arrays, CSV and
        JSON stay in 1/min, N·m and W.
    oil_temperature : ndarray (T, S) or None
        The oil (sump) temperature the spin losses were evaluated at, °C (None without them).
    """

    name: str
    gear: str | None
    direction: str
    input: str
    output: str
    speeds: np.ndarray
    torques: np.ndarray
    efficiency: np.ndarray
    input_power: np.ndarray
    output_power: np.ndarray
    loss: np.ndarray
    losses: Mapping[str, np.ndarray]
    self_locking: np.ndarray
    ratio: float
    units: Units | None = None
    oil_temperature: np.ndarray | None = None

    def shown(self, quantity: str) -> tuple[np.ndarray, str]:
        """The ``"speed"`` or ``"torque"`` axis in the units the map is shown in, and that unit."""
        units = self.units or Units()
        axis = self.speeds if quantity == "speed" else self.torques
        return axis / unit_factor(units.of(quantity), quantity), units.of(quantity)

    def __post_init__(self) -> None:
        # a frozen result: read-only views of the arrays, a read-only mapping of the losses
        for name in ("speeds", "torques", "efficiency", "input_power", "output_power", "loss", "self_locking"):
            object.__setattr__(self, name, _read_only(getattr(self, name)))
        object.__setattr__(self, "losses", MappingProxyType({k: _read_only(v) for k, v in self.losses.items()}))

    @property
    def shape(self) -> tuple[int, int]:
        return self.efficiency.shape  # type: ignore[return-value]

    def loss_split(self) -> dict[str, float]:
        """Share of each source in the summed loss over the map (0…1)."""
        total = sum(float(np.nansum(v)) for v in self.losses.values())
        return {k: (float(np.nansum(v)) / total if total > 0 else 0.0) for k, v in self.losses.items()}

    def summary(self) -> dict[str, Any]:
        """The map in a few numbers: points, efficiency range and mean, self-locking points, loss split.

        Returns
        -------
        dict
            ``points``, ``efficiency_min``, ``efficiency_max``, ``efficiency_mean`` (over the
            points that do not self-lock; ``None`` if all do), ``self_locking_points`` and
            ``loss_split`` (:meth:`loss_split`: share of each source, 0…1).
        """
        eff = self.efficiency[~np.isnan(self.efficiency)]
        return {
            "points": int(self.efficiency.size),
            "efficiency_min": float(eff.min()) if eff.size else None,
            "efficiency_max": float(eff.max()) if eff.size else None,
            "efficiency_mean": float(eff.mean()) if eff.size else None,
            "self_locking_points": int(self.self_locking.sum()),
            "loss_split": self.loss_split(),
        }

    # ------------------------------------------------------------------ rendering
    def title(self) -> str:
        """``"<name>, gear <gear> (<direction>, ratio <ratio>)"``, the heading of the table and figure.

        Returns
        -------
        str
        """
        gear = f", gear {self.gear}" if self.gear is not None else ""
        return f"{self.name}{gear} ({self.direction}, ratio {self.ratio:.4g})"

    def table(self) -> str:
        """The summary as plain text: axes (in the file's units), efficiency range, self-locking, loss split.

        Returns
        -------
        str
        """
        s = self.summary()
        split = ", ".join(f"{k} {100 * v:.1f} %" for k, v in s["loss_split"].items())
        (n, n_unit), (t, t_unit) = self.shown("speed"), self.shown("torque")
        lines = [
            f"efficiency map of {self.title()}",
            f"input speed {_axis_words(n, n_unit)}, input torque {_axis_words(t, t_unit)}",
        ]
        if s["efficiency_min"] is not None:
            lines.append(f"efficiency {s['efficiency_min']:.4f} .. {s['efficiency_max']:.4f} "
                         f"(mean {s['efficiency_mean']:.4f})")
        lines.append(f"self-locking at {s['self_locking_points']} of {s['points']} points")
        lines.append(f"losses by source (sum over the map): {split or 'none'}")
        if self.oil_temperature is not None:
            oil = np.asarray(self.oil_temperature)
            lines.append(f"oil temperature {oil.min():.1f} .. {oil.max():.1f} degC")
        return "\n".join(lines)

    def __repr__(self) -> str:
        s = self.summary()
        span = (f"η {s['efficiency_min']:.4f}…{s['efficiency_max']:.4f}" if s["efficiency_min"] is not None
                else "no defined efficiency")
        return f"<EfficiencyMap {self.title()}: {self.torques.size}×{self.speeds.size} points, {span}>"

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data: axes, 2-D arrays as nested lists (rows: torques), NaN as None."""
        def grid(a: np.ndarray) -> list:
            return [[None if not np.isfinite(v) else float(v) for v in row] for row in a]

        return {
            "name": self.name, "gear": self.gear, "direction": self.direction, "input": self.input,
            "output": self.output, "ratio": self.ratio,
            "units": {"speed": "1/min", "torque": "N*m", "power": "W"},
            "speeds": self.speeds.tolist(), "torques": self.torques.tolist(),
            "efficiency": grid(self.efficiency), "input_power": grid(self.input_power),
            "loss": grid(self.loss), "losses": {k: grid(v) for k, v in self.losses.items()},
            "self_locking": self.self_locking.tolist(), "summary": self.summary(),
            "oil_temperature": None if self.oil_temperature is None else grid(np.asarray(self.oil_temperature)),
        }

    def to_json(self) -> str:
        """:meth:`to_dict` as JSON text (1/min, N·m, W whatever the file's units; NaN as null).

        Returns
        -------
        str
        """
        return json.dumps(self.to_dict(), indent=1, allow_nan=False) + "\n"

    def to_csv(self) -> str:
        """One line per point: speed, torque, efficiency, powers and the losses by source (empty = undefined)."""
        sources = list(self.losses)
        head = ["speed_rpm", "torque_Nm", "efficiency", "input_power_W", "output_power_W", "loss_W",
                *(f"loss_{s}_W" for s in sources), "self_locking"]
        lines = [",".join(head)]

        def cell(v: float) -> str:
            return "" if not np.isfinite(v) else repr(float(v))

        for i, torque in enumerate(self.torques):
            for j, speed in enumerate(self.speeds):
                row = [repr(float(speed)), repr(float(torque)), cell(self.efficiency[i, j]),
                       cell(self.input_power[i, j]), cell(self.output_power[i, j]), cell(self.loss[i, j]),
                       *(cell(self.losses[s][i, j]) for s in sources),
                       "true" if self.self_locking[i, j] else "false"]
                lines.append(",".join(row))
        return "\n".join(lines) + "\n"

    def plot(self, *, figsize: tuple[float, float] = (11.0, 4.6)):
        """η contours over speed × torque, and the share of the load-independent (drag) loss; a Figure."""
        from ..plotting.efficiency_map import efficiency_map_figure

        return efficiency_map_figure(self, figsize=figsize)

    def _repr_html_(self) -> str:
        from ..plotting._common import result_html

        return result_html(self)

    def save(self, path: str | Path) -> Path:
        """Write the map: ``.png``/``.svg``/``.pdf`` (figure), ``.csv`` or ``.json`` by the suffix."""
        path = Path(path)
        suffix = path.suffix.lower()
        if suffix not in MAP_SUFFIXES:
            raise ModelError(
                f"efficiency map: cannot write {path.name!r}; give a file ending in "
                f"{', '.join(MAP_SUFFIXES)}."
            )
        from ..plotting._common import save_result

        return save_result(self, path)


def _axis_words(values: np.ndarray, unit: str) -> str:
    """An axis of the map in words: ``"100..600 rad/s (6 values)"``, one value as ``"1000 1/min"``."""
    if values.size == 1:
        return f"{values.min():g} {unit}"
    return f"{values.min():g}..{values.max():g} {unit} ({values.size} values)"


def _read_only(values) -> np.ndarray:
    view = np.asarray(values).view()
    view.flags.writeable = False
    return view


def _axis(values, name: str, quantity: str) -> np.ndarray:
    arr = to_core_array(values, quantity, field=f"efficiency_map: {name}").ravel()
    if arr.size == 0 or not np.all(np.isfinite(arr)):
        raise ModelError(f"efficiency_map: {name} must be finite numbers, got {values!r}.")
    if np.any(arr <= 0):
        raise ModelError(f"efficiency_map: {name} must be > 0 (magnitudes; give the direction with "
                         f"direction='drive' or 'coast'), got a value {float(arr.min())!r}.")
    return arr


def _check_one_freedom(train: GearTrain, input: str, output: str) -> None:
    """A map over the input speed needs a train whose speeds that one speed fixes."""
    from ..solver.assembly import matrices
    from ..solver.kinematics import free_speed_shafts

    mats = matrices(train, (input, output))
    free = free_speed_shafts(mats, [input])
    if free:
        raise ModelError(
            f"efficiency_map: with the input speed {input!r} given, the speed of "
            f"{', '.join(repr(s) for s in free)} is still free (the train has "
            f"{mats.degrees_of_freedom} degrees of freedom); a map over input speed × torque needs a "
            "train with one: hold a shaft with a brake or engage a clutch (or pick a gear)."
        )


def efficiency_map(train, speeds: Sequence[float] | np.ndarray, torques: Sequence[float] | np.ndarray, *,
                   gear: str | None = None, losses: Mapping[str, ElementLosses] | None = None,
                   direction: str = "drive", input: str | None = None, output: str | None = None,
                   spin=None) -> EfficiencyMap:
    """η and losses over a grid of input speeds × input torques.

    Parameters
    ----------
    train : TrainFile, Transmission or GearTrain
        A train file (its ``[transmission]``, loss tables and operating point's
        drive and load are used), a :class:`~epicyclic.transmission.Transmission`,
        or a train with ``input`` and ``output`` given.
    speeds : array_like
        Input speeds, 1/min (> 0); values may carry units (``"1500 U/min"``), or give one pint
        quantity holding an array (its unit is converted, never stripped).
    torques : array_like
        Input torques, N·m (> 0; in coast the output is driven with torque × |ratio|); units as
        for ``speeds`` (``"15 kp*m"``).  A train file's map shows both in its ``[units]``
        (:func:`epicyclic.io.ranges.map_grid` reads them so).
    gear : str, optional
        Gear of the transmission's schedule (default: the file's operating-point gear).
    losses : mapping element → ElementLosses, optional
        Loss models (default: the train file's).
    direction : {"drive", "coast"}
    input, output : str, optional
        Shafts (default: the transmission's, else the file's drive and load).
    spin : SpinLosses, optional
        Spin losses (clutch drag, pump, churning, windage, seals; default: the train file's).

    Returns
    -------
    EfficiencyMap

    Raises
    ------
    ModelError
        A bad train, gear, shaft, direction or axis.
    LimitError
        More than :data:`~epicyclic.limits.MAX_MAP_POINTS` grid points (the limit the command line and the
        page share).

    Examples
    --------
    >>> from epicyclic.io import load_train_file
    >>> f = load_train_file("examples/geometry_simple_set.toml")
    >>> m = efficiency_map(f, [1000.0, 3000.0], [20.0, 60.0])
    >>> m.shape, bool(((m.efficiency > 0.9) & (m.efficiency < 1)).all())
    ((2, 2), True)
    """
    if direction not in ("drive", "coast"):
        raise ModelError(f"efficiency_map: direction must be 'drive' or 'coast', got {direction!r}.")
    name, title_gear, units, file, transmission_input = "gear train", gear, None, None, input
    if hasattr(train, "operating_train") and hasattr(train, "losses"):  # a TrainFile
        file = train
        name, units = file.title, file.units
        losses = dict(file.losses) if losses is None else losses
        gear = gear if gear is not None else file.gear
        if gear is None and file.transmission is not None:
            raise ModelError(f"{file.source}: a map is drawn in one gear of the [transmission] schedule; pick one "
                             f"(--gear on the command line, gear= in Python): {', '.join(repr(g) for g in file.transmission.schedule)}.")
        if gear is not None:
            if file.transmission is None:
                raise ModelError(f"{file.source}: gear {gear!r} needs a [transmission] table with a schedule.")
            base = file.transmission.train_in_gear(file.train, gear)
        else:
            base = file.train
        op = file.operating_point
        if file.transmission is not None:
            transmission_input = file.transmission.input
            input = input or file.transmission.input
            output = output or file.transmission.output
        elif op is not None:
            input = input or (op.drives[0] if op.drives else None)
            output = output or (op.loads[0] if op.loads else None)
        title_gear = gear
    elif hasattr(train, "gear_train") and hasattr(train, "schedule"):  # a Transmission
        name = train.name
        if gear is None:
            raise ModelError("efficiency_map: a transmission needs gear=... (one of "
                             f"{', '.join(repr(g) for g in train.gears)}).")
        base = train.gear_train(gear)
        transmission_input = train.input
        input, output = input or train.input, output or train.output
        spin = spin if spin is not None else getattr(train, "spin", None)
        losses = losses if losses is not None else dict(getattr(train, "losses", {}) or {})
    elif isinstance(train, GearTrain):
        base, name = train, train.name
    else:
        raise ModelError(f"efficiency_map: expected a TrainFile, Transmission or GearTrain, got {type(train).__name__}.")
    if input is None or output is None:
        raise ModelError("efficiency_map: give input= and output= shafts (or a file with a [transmission] table "
                         "or an [operating_point] with drives and loads).")
    for shaft in (input, output):
        base.check_shaft(shaft, "efficiency_map")
    _check_one_freedom(base, input, output)
    n = _axis(speeds, "speeds", "speed")
    t = _axis(torques, "torques", "torque")
    check_count(n.size * t.size, "efficiency_map: speeds × torques", MAX_MAP_POINTS, "grid points")
    models = dict(losses or {})
    if spin is None and file is not None:
        spin = file.spin
    spin_kw = dict(spin=spin, gear=title_gear, input=transmission_input)
    ratio_sol = solve_batch_with_losses(base, {}, speeds={input: np.array([1000.0])}, torques={input: np.array([1.0])},
                                        drives=[input], loads=[output])
    ratio = float(1000.0 / ratio_sol.speeds[output][0])

    def solved(rows: np.ndarray) -> dict[str, Any]:
        """The map's rows of the torques ``rows``: one batch solve (its temporaries: a few kB a point)."""
        speed_grid, torque_grid = np.meshgrid(n, rows)
        if direction == "drive":
            sol = solve_batch_with_losses(base, models, speeds={input: speed_grid}, torques={input: torque_grid},
                                          drives=[input], loads=[output], **spin_kw)
        else:
            sol = solve_batch_with_losses(base, models, speeds={input: speed_grid},
                                          torques={output: torque_grid * abs(ratio)}, drives=[output],
                                          loads=[input], **spin_kw)
        sources = {s: np.zeros(sol.shape) for s in SOURCES}
        for parts in sol.loss_sources.values():
            for source, value in parts.items():
                sources[source] = sources.get(source, np.zeros(sol.shape)) + value
        oil = sol.oil_temperature
        return {"efficiency": sol.efficiency, "input_power": sol.input_power, "output_power": sol.output_power,
                "loss": sol.loss, "self_locking": sol.self_locking, "oil": oil, "sources": sources}

    step = max(1, MAP_BLOCK_POINTS // n.size)  # torque rows per block
    blocks = [solved(t[k:k + step]) for k in range(0, t.size, step)]

    def joined(name: str) -> np.ndarray:
        return blocks[0][name] if len(blocks) == 1 else np.concatenate([b[name] for b in blocks], axis=0)

    sources = {k: (blocks[0]["sources"][k] if len(blocks) == 1 else
                   np.concatenate([b["sources"][k] for b in blocks], axis=0)) for k in blocks[0]["sources"]}
    sources = {k: v for k, v in sources.items() if np.any(v != 0) or k == "mesh"}
    oil = blocks[0]["oil"]  # one temperature for the map (a given one), or one per point (thermal)
    if oil is not None and len(blocks) > 1 and np.ndim(oil) > 0:
        oil = np.concatenate([np.broadcast_to(b["oil"], b["loss"].shape) for b in blocks], axis=0)
    return EfficiencyMap(name, title_gear, direction, input, output, n, t, joined("efficiency"),
                         joined("input_power"), joined("output_power"), joined("loss"), sources,
                         joined("self_locking"), ratio, units, oil)
