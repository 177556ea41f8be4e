"""Errors of shift schedules and gears (both are bad input: ``ModelError``)."""

from __future__ import annotations

from collections.abc import Iterable

from ..errors import ModelError, TopologyError, closest

__all__ = ["ShiftScheduleError", "GearFreedomError", "UnknownGearError"]


class ShiftScheduleError(ModelError):
    """A shift schedule names an unknown element, no gear, or a bad input/output shaft."""


class UnknownGearError(ShiftScheduleError, KeyError):
    """A gear the shift schedule does not have; also a KeyError (``analysis["9"]``).

    Attributes
    ----------
    gear : object
        The gear asked for.
    gears : tuple of str
        The gears of the schedule.
    """

    def __init__(self, gear: object, gears: Iterable[str]):
        self.gear = gear
        self.gears = tuple(gears)
        close = closest(str(gear), self.gears)
        hint = " (gear names are strings)" if not isinstance(gear, str) and str(gear) in self.gears else ""
        super().__init__(f"transmission: no gear {gear!r:.40}{hint}; gears are {', '.join(repr(g) for g in self.gears)}."
                         + (f" Did you mean {close!r}?" if close and not hint else ""))

    def __str__(self) -> str:  # the message, not KeyError's quoted repr of it
        return str(self.args[0])


class GearFreedomError(ShiftScheduleError, TopologyError):
    """A gear does not leave exactly one degree of freedom between input and output.

    Attributes
    ----------
    gear : str
    degrees_of_freedom : int
        Of the gear's shift state (speeds that must be given).
    free : tuple of str
        Shafts whose speed the input speed leaves free.
    """

    def __init__(self, message: str, gear: str, dof: int, free: Iterable[str]):
        self.gear = gear
        self.degrees_of_freedom = dof
        self.free = tuple(free)
        super().__init__(message)
