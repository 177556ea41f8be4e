"""A given shift schedule: upshift lines, output speed against output torque.

A shift schedule (Schaltkennfeld) of a stepped automatic says in which gear the
transmission runs at a point of output speed × output torque.  Here it is given
by its upshift lines: for each upshift k → k+1 the output speed at which it
happens, tabulated against the output torque (linear interpolation between the
rows, the end values held beyond them).  At a point the gear is the highest
one whose upshift speed the point has reached — the steady-state gear; the
downshift lines (the hysteresis below the upshift lines) matter only in time,
and :mod:`epicyclic.transmission.drive_cycle` states its own hysteresis.

References
----------
Naunheimer, Bertsche, Ryborz, Novak, *Automotive Transmissions*, 2nd ed., Springer 2011, §7.4
(shift maps: upshift and downshift lines over vehicle speed and load).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import ModelError

__all__ = ["ShiftSchedule"]


@dataclass(frozen=True, eq=False)
class ShiftSchedule:
    """Upshift lines of a stepped transmission over output torque.

    Parameters
    ----------
    gears : sequence of str
        The forward gears in shift order (first gear first), at least two.
    torques : array_like (K,)
        Output torques of the table rows, N·m, increasing (≥ 0).
    upshift_speeds : array_like (len(gears) − 1, K)
        Row k: the output speed (1/min) at which gear k shifts up to gear k+1 at each torque
        (> 0; at every torque each upshift at or above the one before).
    name : str, optional
        Where the schedule came from (a file), for messages and tables.

    Examples
    --------
    >>> s = ShiftSchedule(["1", "2", "3"], [0.0, 400.0], [[300.0, 600.0], [600.0, 1200.0]])
    >>> s.gear_index([100.0, 450.0, 450.0, 2000.0], [0.0, 0.0, 400.0, 200.0]).tolist()
    [0, 1, 0, 2]

    References
    ----------
    Naunheimer et al. 2011, §7.4.
    """

    gears: tuple[str, ...]
    torques: np.ndarray
    upshift_speeds: np.ndarray
    name: str = "shift schedule"

    def __post_init__(self) -> None:
        gears = tuple(self.gears)
        if len(gears) < 2 or not all(isinstance(g, str) and g for g in gears) or len(set(gears)) != len(gears):
            raise ModelError(f"{self.name}: gears must be two or more distinct gear names, got {list(gears)!r:.120}.")
        torques = np.asarray(self.torques, dtype=float).ravel()
        speeds = np.asarray(self.upshift_speeds, dtype=float)
        if torques.size == 0 or not np.all(np.isfinite(torques)) or np.any(torques < 0) \
                or np.any(np.diff(torques) <= 0):
            raise ModelError(f"{self.name}: the output torques must be finite, >= 0 and increasing row by row, "
                             f"got {torques.tolist()!r:.120}.")
        if speeds.shape != (len(gears) - 1, torques.size):
            raise ModelError(f"{self.name}: expected {len(gears) - 1} upshift lines ({len(gears)} gears) of "
                             f"{torques.size} speeds each, got an array of shape {speeds.shape}.")
        if not np.all(np.isfinite(speeds)) or np.any(speeds <= 0):
            raise ModelError(f"{self.name}: every upshift speed must be a finite output speed > 0 (1/min).")
        below = np.flatnonzero(np.any(np.diff(speeds, axis=0) < 0, axis=1))
        if below.size:
            k = int(below[0])
            raise ModelError(f"{self.name}: the upshift {self.label(k + 1, gears)} lies below "
                             f"{self.label(k, gears)} at some torque; each upshift must come at or above the one "
                             "before it.")
        object.__setattr__(self, "gears", gears)
        for name, value in (("torques", torques), ("upshift_speeds", speeds)):
            value = value.copy()
            value.flags.writeable = False
            object.__setattr__(self, name, value)

    @staticmethod
    def label(k: int, gears: Sequence[str]) -> str:
        """``"1-2"``: the name of upshift ``k`` (from ``gears[k]`` to ``gears[k + 1]``).

        Parameters
        ----------
        k : int
            The upshift's index.
        gears : sequence of str
            The gears in shift order.

        Returns
        -------
        str
        """
        return f"{gears[k]}-{gears[k + 1]}"

    @classmethod
    def from_columns(cls, torques, columns: Mapping[str, Any], name: str = "shift schedule") -> ShiftSchedule:
        """From upshift columns named ``"1-2"``, ``"2-3"``, … (the CSV layout of ``docs/shift-map.md``).

        Parameters
        ----------
        torques : array_like
            Output torques of the rows, N·m.
        columns : mapping str → array_like
            Upshift name ``"<from>-<to>"`` → output speeds, 1/min, one per row; consecutive names
            must chain (the gear an upshift leads to is the one the next starts from).
        name : str
            Where they came from.

        Returns
        -------
        ShiftSchedule
        """
        gears: list[str] = []
        for label in columns:
            start, sep, end = str(label).partition("-")
            if not sep or not start or not end:
                raise ModelError(f"{name}: column {label!r:.60} is not an upshift such as '1-2'.")
            if gears and gears[-1] != start:
                raise ModelError(f"{name}: upshift {label!r:.60} does not start from gear {gears[-1]!r}, where the "
                                 "upshift before it leads; give the upshifts in order (1-2, 2-3, ...).")
            if not gears:
                gears.append(start)
            gears.append(end)
        return cls(tuple(gears), torques, [np.asarray(v, dtype=float) for v in columns.values()], name)

    def gear_index(self, output_speed, output_torque) -> np.ndarray:
        """Index into :attr:`gears` of the steady-state gear at each point (arrays broadcast).

        Parameters
        ----------
        output_speed : array_like
            Output speed, 1/min (its magnitude).
        output_torque : array_like
            Output torque, N·m (its magnitude; beyond the table the end row holds).

        Returns
        -------
        ndarray of int
        """
        n, t = np.broadcast_arrays(np.abs(np.asarray(output_speed, dtype=float)),
                                   np.abs(np.asarray(output_torque, dtype=float)))
        index = np.zeros(n.shape, dtype=int)
        for k, line in enumerate(self.upshift_speeds):
            index = np.where(n >= np.interp(t, self.torques, line), k + 1, index)
        return index

    def to_dict(self) -> dict[str, Any]:
        """``name``, ``gears``, ``torques_Nm`` and ``upshift_speeds_rpm`` (upshift name → speeds)."""
        return {"name": self.name, "gears": list(self.gears), "torques_Nm": self.torques.tolist(),
                "upshift_speeds_rpm": {self.label(k, self.gears): line.tolist()
                                       for k, line in enumerate(self.upshift_speeds)}}

    def __repr__(self) -> str:
        return (f"<ShiftSchedule {self.name!r}: gears {', '.join(self.gears)}, {self.torques.size} torque rows "
                f"{self.torques[0]:g}..{self.torques[-1]:g} N*m>")

