"""The ``[transmission]`` table of a train file: input and output shaft, and the shift schedule.

Examples
--------
>>> t = Transmission("in", "out", {"1": ("B",), "2": ("C",)})
>>> t.gears
('1', '2')
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType

from ..errors import ModelError
from ..model import GearTrain
from ..text import short
from ..units import to_core
from .reader import at_key

__all__ = ["Transmission", "rated_limits"]


@dataclass(frozen=True)
class Transmission:
    """A multi-speed transmission: input and output shaft and the shift schedule.

    Parameters
    ----------
    input, output : str
        The input and output shafts.
    schedule : mapping gear name → tuple of str
        For each gear, the clutches and brakes engaged in it (all others open).
    input_speed_range : (float, float) or None
        The rated input (engine) speeds, 1/min (``[transmission] input_speed_range``): what a gear may run
        at, the default of ``shiftmap`` and ``cycle``; None: not stated.
    max_input_torque : float or None
        The rated input torque, N·m (``[transmission] max_input_torque``); None: not stated.
    """

    input: str
    output: str
    schedule: Mapping[str, tuple[str, ...]]
    input_speed_range: tuple[float, float] | None = None
    max_input_torque: float | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "schedule", MappingProxyType({k: tuple(v) for k, v in self.schedule.items()}))

    @property
    def gears(self) -> tuple[str, ...]:
        """Gear names in the file's order."""
        return tuple(self.schedule)

    def train_in_gear(self, train: GearTrain, gear: str) -> GearTrain:
        """``train`` with exactly the shift elements of ``gear`` engaged.

        Parameters
        ----------
        train : GearTrain
            The file's train (its clutches and brakes in any state).
        gear : str
            A gear of the schedule (``"1"``, ``"R"``, ...).

        Returns
        -------
        GearTrain
            A copy whose clutches and brakes named by ``schedule[gear]`` are engaged, all
            others open.

        Raises
        ------
        ModelError
            ``gear`` is not in the schedule; the message lists the gears.
        """
        if gear not in self.schedule:
            raise ModelError(
                f"transmission: no gear {short(gear)} in the schedule; gears are "
                f"{', '.join(repr(g) for g in self.schedule) or 'none'}."
            )
        return train.with_engaged(self.schedule[gear])


def rated_limits(reader, table: Mapping, where: str) -> tuple[tuple[float, float] | None, float | None]:
    """``input_speed_range`` and ``max_input_torque`` of a ``[transmission]`` table, in 1/min and N·m.

    Plain numbers are in the file's ``[units]``; strings carry their unit (``"6500 rpm"``, ``"70 kp*m"``).

    Parameters
    ----------
    reader : the file reader (its ``units``, ``error`` and ``checked``)
    table : mapping
        The ``[transmission]`` table.
    where : str
        ``"[transmission]"``, for messages.

    Returns
    -------
    (speed range or None, torque or None)
    """
    speeds = torque = None
    if "input_speed_range" in table:
        key = at_key(where, "input_speed_range")
        value = table["input_speed_range"]
        if not isinstance(value, list) or len(value) != 2:
            raise reader.error(key, "expected [lowest, highest] rated input speed, e.g. [800, 6500] or "
                                    f"[\"800 rpm\", \"6500 rpm\"], got {short(value)}.")
        low, high = (reader.checked(key, "input_speed_range", to_core, v, "speed", field="input_speed_range",
                                    default_unit=reader.units.speed) for v in value)
        if not 0.0 <= low < high:
            raise reader.error(key, f"expected 0 <= lowest < highest speed, got {low:g} and {high:g} 1/min.")
        speeds = (low, high)
    if "max_input_torque" in table:
        key = at_key(where, "max_input_torque")
        torque = reader.checked(key, "max_input_torque", to_core, table["max_input_torque"], "torque",
                                field="max_input_torque", default_unit=reader.units.torque)
        if not torque > 0.0:
            raise reader.error(key, f"expected a positive torque, got {torque:g} N*m.")
    return speeds, torque
