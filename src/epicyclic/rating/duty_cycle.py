"""Duty cycles (load spectra): a table of load cases, each an operating point for a time.

A :class:`DutyCycle` is a tuple of :class:`LoadCase` s.  Each case is one
:class:`~epicyclic.OperatingPoint` (speeds, torques or powers, drives, loads),
the gear it runs in (for a transmission) and its duration: hours, or a time
share of the cycle's total hours.  The same value object is built from a train
file's ``[[duty_cycle.case]]`` tables (``docs/file-format.md``) or from a list of
operating points (a REXS ``load_spectrum``: :meth:`DutyCycle.from_operating_points`).

Shares must sum to 1 (within 10⁻⁶: a cycle of shares 0.5 and 0.3 is refused,
not scaled, so that a forgotten case is noticed); hours are non-negative and the
cycle's total is their sum.  A cycle given by shares alone has no total: its
energies are per hour of the cycle and its damage per hour (see
:class:`~epicyclic.rating.duty_analysis.DutyCycleResult`).

References
----------
Palmgren 1924, Miner 1945 (linear damage accumulation over a load spectrum);
ISO 6336-6:2019, clause 4 (load spectrum: torque, speed and duration of each bin).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np

from ..errors import ModelError
from ..model.operating_point import OperatingPoint

__all__ = ["SHARE_TOLERANCE", "DutyCycle", "DutyCycleError", "LoadCase"]

#: How far the time shares may sum from 1.
SHARE_TOLERANCE = 1e-6


class DutyCycleError(ModelError):
    """A duty cycle that is invalid: no case, negative hours, shares not summing to 1, a repeated name."""


def _duration(value: object, field: str) -> float | None:
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value < 0:
        raise DutyCycleError(f"duty cycle: {field} must be a number >= 0, got {value!r}.")
    return float(value)


@dataclass(frozen=True)
class LoadCase:
    """One load case of a duty cycle.

    Parameters
    ----------
    name : str
        Unique within the cycle.
    operating_point : OperatingPoint
        Core units (1/min, N·m, W).
    gear : str, optional
        The gear of the transmission it runs in (None: the train as it is).
    hours : float, optional
        Duration, h (≥ 0).
    share : float, optional
        Time share of the cycle in [0, 1]; give ``hours`` or ``share``, not both.

    Examples
    --------
    >>> from epicyclic import OperatingPoint
    >>> case = LoadCase("cruise", OperatingPoint(speeds={"in": 2000}, torques={"in": 100}, drives=["in"],
    ...                 loads=["out"]), gear="3", share=0.6)
    >>> case.share, case.hours
    (0.6, None)
    """

    name: str
    operating_point: OperatingPoint
    gear: str | None = None
    hours: float | None = None
    share: float | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name.strip():
            raise DutyCycleError(f"duty cycle: a case name must be a non-empty string, got {self.name!r}.")
        if not isinstance(self.operating_point, OperatingPoint):
            raise DutyCycleError(f"duty cycle, case {self.name!r}: operating_point must be an OperatingPoint, got "
                                 f"{type(self.operating_point).__name__}.")
        if self.gear is not None and not isinstance(self.gear, str):
            raise DutyCycleError(f"duty cycle, case {self.name!r}: gear must be a gear name (a string), got "
                                 f"{self.gear!r}.")
        hours = _duration(self.hours, f"case {self.name!r}: hours")
        share = _duration(self.share, f"case {self.name!r}: share")
        if (hours is None) == (share is None):
            raise DutyCycleError(f"duty cycle, case {self.name!r}: give its duration as 'hours' or as a time "
                                 "'share', " + ("not both." if hours is not None else "got neither."))
        if share is not None and share > 1:
            raise DutyCycleError(f"duty cycle, case {self.name!r}: share must lie in [0, 1], got {share!r}.")
        object.__setattr__(self, "hours", hours)
        object.__setattr__(self, "share", share)

    def to_dict(self) -> dict[str, object]:
        """Name, gear, duration and the operating point (1/min, N·m, W)."""
        op = self.operating_point
        return {"name": self.name, "gear": self.gear, "hours": self.hours, "share": self.share,
                "speeds": dict(op.speeds), "torques": dict(op.torques), "powers": dict(op.powers),
                "drives": list(op.drives), "loads": list(op.loads)}


@dataclass(frozen=True)
class DutyCycle:
    """A duty cycle: load cases with hours, or with time shares and optionally the total hours.

    Parameters
    ----------
    cases : sequence of LoadCase
        At least one; all with ``hours`` or all with ``share``.
    total_hours : float, optional
        The cycle's hours for cases given by share (h); with cases in hours it must be their sum
        or be left out.
    name : str, default "duty cycle"

    Raises
    ------
    DutyCycleError
        No case, repeated names, hours and shares mixed, shares not summing to 1, a total that
        contradicts the cases' hours.

    Examples
    --------
    >>> from epicyclic import OperatingPoint
    >>> op = OperatingPoint(speeds={"in": 2000}, torques={"in": 100}, drives=["in"], loads=["out"])
    >>> cycle = DutyCycle([LoadCase("a", op, hours=300.0), LoadCase("b", op, hours=100.0)])
    >>> cycle.shares.tolist(), cycle.total_hours
    ([0.75, 0.25], 400.0)
    """

    cases: tuple[LoadCase, ...]
    total_hours: float | None = None
    name: str = "duty cycle"

    def __post_init__(self) -> None:
        cases = tuple(self.cases) if isinstance(self.cases, Iterable) else ()
        if not cases or not all(isinstance(c, LoadCase) for c in cases):
            raise DutyCycleError("duty cycle: expected at least one LoadCase, e.g. DutyCycle([LoadCase('cruise', "
                                 f"op, share=1.0)]), got {self.cases!r:.60}.")
        names = [c.name for c in cases]
        twice = sorted({n for n in names if names.count(n) > 1})
        if twice:
            raise DutyCycleError(f"duty cycle: case names must be unique; {', '.join(map(repr, twice))} used twice.")
        by_hours = [c.hours is not None for c in cases]
        if any(by_hours) and not all(by_hours):
            raise DutyCycleError("duty cycle: give every case in 'hours' or every case as a 'share', not a mix "
                                 f"(hours: {', '.join(c.name for c in cases if c.hours is not None)}; shares: "
                                 f"{', '.join(c.name for c in cases if c.share is not None)}).")
        total = _duration(self.total_hours, "total_hours")
        if all(by_hours):
            hours = sum(c.hours for c in cases)  # type: ignore[misc]
            if hours <= 0:
                raise DutyCycleError("duty cycle: the cases' hours sum to 0; give at least one case a positive "
                                     "duration.")
            if total is not None and not math.isclose(total, hours, rel_tol=1e-9):
                raise DutyCycleError(f"duty cycle: total_hours = {total:g} h, but the cases' hours sum to "
                                     f"{hours:g} h; give the total once (leave 'hours' out of [duty_cycle]).")
            total = hours
        else:
            s = sum(c.share for c in cases)  # type: ignore[misc]
            if abs(s - 1.0) > SHARE_TOLERANCE:
                raise DutyCycleError(
                    f"duty cycle: the time shares sum to {s:.6g}, not 1 ({', '.join(f'{c.name}: {c.share:g}' for c in cases)}); "
                    "correct them (a missing case?), or give each case its 'hours' instead.")
            if total is not None and total <= 0:
                raise DutyCycleError(f"duty cycle: total_hours must be positive, got {total!r}.")
        if not isinstance(self.name, str):
            raise DutyCycleError(f"duty cycle: name must be a string, got {self.name!r}.")
        object.__setattr__(self, "cases", cases)
        object.__setattr__(self, "total_hours", total)

    @classmethod
    def from_operating_points(cls, points: Sequence[OperatingPoint], *, hours: Sequence[float] | None = None,
                              shares: Sequence[float] | None = None, gears: Sequence[str | None] | None = None,
                              names: Sequence[str] | None = None, total_hours: float | None = None,
                              name: str = "duty cycle") -> DutyCycle:
        """A cycle from a list of operating points (a REXS load spectrum's load cases).

        Parameters
        ----------
        points : sequence of OperatingPoint
            One per case.
        hours, shares : sequence of float
            The cases' durations (h) or time shares; exactly one of the two.
        gears : sequence of str or None, optional
            The gear of each case.
        names : sequence of str, optional
            Default ``case 1``, ``case 2``, ...
        total_hours : float, optional
            With ``shares``: the cycle's hours.
        name : str, default "duty cycle"

        Returns
        -------
        DutyCycle

        Raises
        ------
        DutyCycleError
            Lengths that differ, both or neither of hours and shares, and the errors of the constructor.

        Examples
        --------
        >>> from epicyclic import OperatingPoint
        >>> ops = [OperatingPoint(speeds={"in": n}, torques={"in": 50}, drives=["in"], loads=["out"])
        ...        for n in (1000, 3000)]
        >>> [c.name for c in DutyCycle.from_operating_points(ops, shares=[0.5, 0.5]).cases]
        ['case 1', 'case 2']
        """
        points = list(points)
        if (hours is None) == (shares is None):
            raise DutyCycleError("DutyCycle.from_operating_points: give hours or shares (one per point), "
                                 + ("not both." if hours is not None else "got neither."))
        durations = list(hours if hours is not None else shares)  # type: ignore[arg-type]
        gears = list(gears) if gears is not None else [None] * len(points)
        names = list(names) if names is not None else [f"case {k + 1}" for k in range(len(points))]
        if not len(durations) == len(gears) == len(names) == len(points):
            raise DutyCycleError(f"DutyCycle.from_operating_points: {len(points)} points but {len(durations)} "
                                 f"durations, {len(gears)} gears and {len(names)} names; give one of each per point.")
        key = "hours" if hours is not None else "share"
        cases = [LoadCase(n, op, g, **{key: d}) for n, op, g, d in zip(names, points, gears, durations)]
        return cls(tuple(cases), total_hours, name)

    @classmethod
    def from_load_cases(cls, load_cases, *, total_hours: float | None = None,
                        name: str = "load spectrum") -> DutyCycle:
        """A cycle from the load cases of a REXS ``load_spectrum`` (or anything shaped like them).

        Each load case needs ``to_operating_point()``, ``duration_fraction`` (its time share, 0 … 1),
        ``gear`` (a gear name or None) and ``id`` (the REXS load case id); the case is named
        ``load case <id>``.

        Parameters
        ----------
        load_cases : iterable
            E.g. ``epicyclic.exchange.operating.RexsLoadCase`` objects of one spectrum.
        total_hours : float, optional
            The spectrum's hours (REXS gives only fractions).
        name : str, default "load spectrum"

        Returns
        -------
        DutyCycle

        Raises
        ------
        DutyCycleError
            A load case without a duration fraction (the message names its id), fractions not
            summing to 1, and the errors of the constructor.

        Examples
        --------
        >>> from types import SimpleNamespace
        >>> from epicyclic import OperatingPoint
        >>> op = OperatingPoint(speeds={"in": 1500}, torques={"in": 80}, drives=["in"], loads=["out"])
        >>> cases = [SimpleNamespace(id=k, gear=None, duration_fraction=f, to_operating_point=lambda: op)
        ...          for k, f in ((1, 0.25), (2, 0.75))]
        >>> DutyCycle.from_load_cases(cases, total_hours=4000.0).hours.tolist()
        [1000.0, 3000.0]
        """
        cases = list(load_cases)
        missing = [getattr(c, "id", k + 1) for k, c in enumerate(cases) if getattr(c, "duration_fraction", None) is None]
        if missing:
            raise DutyCycleError(f"load spectrum: load case(s) {', '.join(map(str, missing))} give no "
                                 "load_duration_fraction; a duty cycle needs the time share of every case.")
        return cls.from_operating_points(
            [c.to_operating_point() for c in cases], shares=[float(c.duration_fraction) for c in cases],
            gears=[getattr(c, "gear", None) for c in cases],
            names=[f"load case {getattr(c, 'id', k + 1)}" for k, c in enumerate(cases)],
            total_hours=total_hours, name=name)

    def __len__(self) -> int:
        return len(self.cases)

    @property
    def names(self) -> tuple[str, ...]:
        """The cases' names."""
        return tuple(c.name for c in self.cases)

    @property
    def shares(self) -> np.ndarray:
        """Time share of each case (sums to 1)."""
        if self.cases[0].hours is not None:
            return np.array([c.hours for c in self.cases]) / self.total_hours
        return np.array([c.share for c in self.cases], dtype=float)

    @property
    def hours(self) -> np.ndarray | None:
        """Hours of each case (None for a cycle of shares without total hours)."""
        if self.total_hours is None:
            return None
        return self.shares * self.total_hours

    def to_dict(self) -> dict[str, object]:
        """Name, total hours and the cases."""
        return {"name": self.name, "total_hours": self.total_hours, "cases": [c.to_dict() for c in self.cases]}
