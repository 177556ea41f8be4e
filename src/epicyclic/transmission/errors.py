"""Errors of shift schedules and gears (both are bad input: ``ModelError``)."""

from __future__ import annotations

from collections.abc import Iterable

from ..errors import ModelError, TopologyError

__all__ = ["ShiftScheduleError", "GearFreedomError"]


class ShiftScheduleError(ModelError):
    """A shift schedule names an unknown element, no gear, or a bad input/output shaft."""


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
