"""Oil pressure of a shift element over time: a table or a chain of ramps.

A profile is a piecewise-linear function p(t) through its points (constant before the first
and after the last).  :meth:`PressureProfile.ramps` builds one from hold/ramp segments, the way a
shift is programmed: fill, a ramp through the torque phase, a level for the inertia phase, the
boost to line pressure.

References
----------
Naunheimer, H., Bertsche, B., Ryborz, J., Novak, W.: *Automotive Transmissions*, 2nd ed., Springer
2011, §10.3 (the phases of a power shift: fast fill, torque phase, inertia phase; pressure as a
sequence of ramps).
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Sequence
from dataclasses import dataclass

from .errors import DynamicsError

__all__ = ["PressureProfile", "MAX_PROFILE_POINTS", "MAX_PRESSURE"]

#: Most points in one profile (docs/limits.md).
MAX_PROFILE_POINTS = 10_000
#: Highest pressure accepted, Pa (100 bar; automatic transmissions work below about 25 bar).
MAX_PRESSURE = 1e7


@dataclass(frozen=True)
class PressureProfile:
    """p(t) through the points (t, p), linear between, held beyond the ends.

    Parameters
    ----------
    points : sequence of (t, p)
        Time in s (non-decreasing; a repeated time is a step) and pressure in Pa (0 ... 1e7).
    name : str, default ""
        The element it feeds (for messages).

    Examples
    --------
    >>> p = PressureProfile([(0.0, 0.0), (0.1, 2e5), (0.3, 2e5)])
    >>> p(0.05), p(1.0)
    (100000.0, 200000.0)
    """

    points: tuple[tuple[float, float], ...]
    name: str = ""

    def __post_init__(self) -> None:
        owner = f"pressure of {self.name!r}" if self.name else "pressure profile"
        try:
            rows = tuple((float(t), float(p)) for t, p in self.points)
        except (TypeError, ValueError):
            raise DynamicsError(f"{owner}: points must be [time (s), pressure (Pa)] pairs, got "
                                f"{self.points!r:.60}.") from None
        if not 1 <= len(rows) <= MAX_PROFILE_POINTS:
            raise DynamicsError(f"{owner}: give 1 ... {MAX_PROFILE_POINTS} points, got {len(rows)}.")
        for t, p in rows:
            if not (math.isfinite(t) and t >= 0.0 and math.isfinite(p) and 0.0 <= p <= MAX_PRESSURE):
                raise DynamicsError(f"{owner}: every time must be ≥ 0 s and every pressure in 0 ... "
                                    f"{MAX_PRESSURE:g} Pa, got ({t!r}, {p!r}).")
        if any(b[0] < a[0] for a, b in zip(rows, rows[1:])):
            raise DynamicsError(f"{owner}: the times must not decrease, got {[t for t, _ in rows]!r:.80}.")
        object.__setattr__(self, "points", rows)
        object.__setattr__(self, "_times", [t for t, _ in rows])

    @classmethod
    def constant(cls, pressure: float, name: str = "") -> PressureProfile:
        """p(t) = ``pressure`` (Pa).

        Parameters
        ----------
        pressure : float
            Pa.
        name : str, default ""
            The element it feeds.

        Returns
        -------
        PressureProfile
        """
        return cls(((0.0, pressure),), name)

    @classmethod
    def ramps(cls, start: float, segments: Sequence[tuple[float, float]], *, t0: float = 0.0,
              name: str = "") -> PressureProfile:
        """From ``start`` (Pa) at ``t0``, each segment (duration s, end pressure Pa) a linear ramp.

        A segment of duration 0 is a step; one with its end equal to the level before is a hold.

        Parameters
        ----------
        start : float
            Pa at ``t0``.
        segments : sequence of (float, float)
            (duration s, end pressure Pa) of each ramp.
        t0 : float, default 0
            s.
        name : str, default ""
            The element it feeds.

        Returns
        -------
        PressureProfile

        Examples
        --------
        >>> p = PressureProfile.ramps(0.0, [(0.05, 3e5), (0.05, 1e5), (0.2, 1.5e5)], t0=0.1)
        >>> [round(p(t)) for t in (0.0, 0.125, 0.2, 0.3)]
        [0, 150000, 100000, 125000]
        """
        points = [(t0, start)]
        t = t0
        for duration, end in segments:
            if not (isinstance(duration, (int, float)) and math.isfinite(duration) and duration >= 0):
                raise DynamicsError(f"pressure of {name!r}: a ramp's duration must be ≥ 0 s, got {duration!r}.")
            t += float(duration)
            points.append((t, end))
        return cls(tuple(points), name)

    def __call__(self, t: float) -> float:
        rows, times = self.points, self._times
        if t <= times[0]:
            return rows[0][1]
        if t >= times[-1]:
            return rows[-1][1]
        k = bisect.bisect_right(times, t)
        (t0, p0), (t1, p1) = rows[k - 1], rows[k]
        return p1 if t1 == t0 else p0 + (p1 - p0) * (t - t0) / (t1 - t0)

    @property
    def end(self) -> float:
        """Time of the last point, s (the pressure is constant after it)."""
        return self.points[-1][0]
