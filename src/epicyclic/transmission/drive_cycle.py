"""A drive cycle: a time series of the output speed and torque a transmission must give.

A cycle is given either at the transmission's output (output speed, output
torque) or at the vehicle (vehicle speed, with a wheel radius and an axle ratio;
the output torque from the road load of :class:`~epicyclic.transmission.vehicle.Vehicle`,
with the acceleration a = dv/dt by central differences, :func:`numpy.gradient`,
second order inside and first order at the ends).  A gear per row may be given.
:func:`~epicyclic.transmission.cycle_energy.run_cycle` runs a transmission
through it.

References
----------
Guzzella, Sciarretta, *Vehicle Propulsion Systems*, 3rd ed. (2013), §2.1 and §3.1 (drive cycles and
the quasi-static, backward-facing simulation: the cycle prescribes the speed, the drivetrain
follows).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import ModelError
from .vehicle import Vehicle

__all__ = ["DriveCycle"]


def _frozen(values, dtype=float) -> np.ndarray:
    array = np.array(values, dtype=dtype)
    array.flags.writeable = False
    return array


@dataclass(frozen=True, eq=False)
class DriveCycle:
    """Time, output speed and output torque of every row, and the gear where given.

    Parameters
    ----------
    time : array_like (R,)
        s, strictly increasing, R ≥ 2.
    output_speed : array_like (R,)
        1/min, ≥ 0 (a cycle drives forward).
    output_torque : array_like (R,)
        N·m; negative while the vehicle brakes (the transmission then carries no torque:
        :mod:`~epicyclic.transmission.cycle_energy`).
    gear : sequence of str, optional
        The gear of every row.
    name : str
        Where it came from (a file).
    lines : array_like of int, optional
        The file line of every row, for messages.
    vehicle_speed : array_like, optional
        m/s, where the cycle came from a vehicle speed.
    vehicle : Vehicle, optional
        The vehicle that turned it into output speed and torque.

    Examples
    --------
    >>> c = DriveCycle([0.0, 1.0, 2.0], [0.0, 500.0, 1000.0], [0.0, 100.0, 100.0])
    >>> c.duration, c.rows
    (2.0, 3)
    """

    time: np.ndarray
    output_speed: np.ndarray
    output_torque: np.ndarray
    gear: tuple[str, ...] | None = None
    name: str = "drive cycle"
    lines: np.ndarray | None = None
    vehicle_speed: np.ndarray | None = None
    vehicle: Vehicle | None = None

    def __post_init__(self) -> None:
        time = _frozen(self.time)
        rows = time.size
        if time.ndim != 1 or rows < 2:
            raise ModelError(f"{self.name}: a drive cycle needs two rows or more, got {rows}.")
        lines = _frozen(self.lines if self.lines is not None else np.arange(1, rows + 1), int)
        object.__setattr__(self, "lines", lines)
        for name in ("time", "output_speed", "output_torque"):
            values = _frozen(getattr(self, name))
            if values.shape != (rows,):
                raise ModelError(f"{self.name}: {name} has {values.size} values, time {rows}.")
            bad = np.flatnonzero(~np.isfinite(values))
            if bad.size:
                raise ModelError(f"{self.where(int(bad[0]), name)}: expected a finite number, got {values[bad[0]]!r}.")
            object.__setattr__(self, name, values)
        step = np.flatnonzero(np.diff(self.time) <= 0)
        if step.size:
            k = int(step[0]) + 1
            raise ModelError(f"{self.where(k, 'time')}: the time must increase row by row, got "
                             f"{self.time[k]:g} s after {self.time[k - 1]:g} s.")
        back = np.flatnonzero(self.output_speed < 0)
        if back.size:
            raise ModelError(f"{self.where(int(back[0]), 'output_speed')}: a drive cycle drives forward: the speed "
                             f"must be >= 0, got {self.output_speed[back[0]]:g}.")
        if self.gear is not None:
            gear = tuple(str(g) for g in self.gear)
            if len(gear) != rows:
                raise ModelError(f"{self.name}: gear has {len(gear)} values, time {rows}.")
            object.__setattr__(self, "gear", gear)
        if self.vehicle_speed is not None:
            object.__setattr__(self, "vehicle_speed", _frozen(self.vehicle_speed))

    def where(self, row: int, column: str) -> str:
        """``"cycle.csv: line 12, column 'time'"``: a row and column, for messages.

        Parameters
        ----------
        row : int
        column : str

        Returns
        -------
        str
        """
        return f"{self.name}: line {int(self.lines[row])}, column {column!r}"

    @property
    def rows(self) -> int:
        return int(self.time.size)

    @property
    def duration(self) -> float:
        """Last time − first time, s."""
        return float(self.time[-1] - self.time[0])

    @classmethod
    def from_columns(cls, time, *, output_speed=None, vehicle_speed=None, output_torque=None, grade=None,
                     gear: Sequence[str] | None = None, vehicle: Vehicle | None = None, name: str = "drive cycle",
                     lines=None) -> DriveCycle:
        """A cycle from the columns of a file: output or vehicle speed, output torque or the road load.

        Parameters
        ----------
        time : array_like
            s.
        output_speed, vehicle_speed : array_like, optional
            1/min at the output, or m/s of the vehicle (then ``vehicle`` gives r and i_A); one of them.
        output_torque : array_like, optional
            N·m; without it the road load of ``vehicle`` (which then needs its mass).
        grade : array_like, optional
            tan α of the road (default 0); used by the road load only.
        gear : sequence of str, optional
            The gear of every row.
        vehicle : Vehicle, optional
        name : str
        lines : array_like of int, optional

        Returns
        -------
        DriveCycle

        Raises
        ------
        ModelError
            Neither or both speeds, a vehicle speed or road load without the vehicle data, bad rows.

        References
        ----------
        Guzzella & Sciarretta 2013, §2.1.
        """
        if (output_speed is None) == (vehicle_speed is None):
            raise ModelError(f"{name}: give one of the columns output_speed and vehicle_speed"
                             + (", not both." if output_speed is not None else "."))
        time = np.asarray(time, dtype=float)
        v = None
        if vehicle_speed is not None:
            if vehicle is None:
                raise ModelError(f"{name}: a vehicle_speed column needs the wheel radius and the axle ratio "
                                 "(--wheel-radius, --axle-ratio).")
            v = np.asarray(vehicle_speed, dtype=float)
            negative = np.flatnonzero(~(v >= 0))
            if negative.size:
                line = int(lines[negative[0]]) if lines is not None else int(negative[0]) + 1
                raise ModelError(f"{name}: line {line}, column 'vehicle_speed': a drive cycle drives forward: the "
                                 f"speed must be >= 0, got {v[negative[0]]:g}.")
            output_speed = vehicle.output_speed(v)
        if output_torque is None:
            if vehicle is None or v is None:
                raise ModelError(f"{name}: without an output_torque column the torque comes from the road load, "
                                 "which needs a vehicle_speed column and the vehicle (--mass, --wheel-radius, "
                                 "--axle-ratio, --drag-area, --rolling-coefficient).")
            if time.size >= 2 and np.all(np.diff(time) > 0):
                acceleration = np.gradient(v, time)
            else:  # the constructor names the row
                acceleration = np.zeros_like(v)
            grade = np.zeros_like(v) if grade is None else np.asarray(grade, dtype=float)
            output_torque = vehicle.output_torque(vehicle.tractive_force(v, acceleration, grade))
        return cls(time, output_speed, output_torque, tuple(gear) if gear is not None else None, name, lines, v,
                   vehicle)

    def __repr__(self) -> str:
        return f"<DriveCycle {self.name!r}: {self.rows} rows, {self.duration:g} s>"

    def to_dict(self) -> dict[str, Any]:
        """Name, rows, duration and (where known) the vehicle."""
        return {"name": self.name, "rows": self.rows, "duration_s": self.duration,
                "vehicle": self.vehicle.to_dict() if self.vehicle is not None else None,
                "gear_given": self.gear is not None}
