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

__all__ = ["Transmission"]


@dataclass(frozen=True)
class Transmission:
    """A multi-speed transmission: input and output shaft and the shift schedule.

    Parameters
    ----------
    input, output : str
        The input and output shafts.
    schedule : mapping gear name → tuple of str
        For each gear, the clutches and brakes engaged in it (all others open).
    """

    input: str
    output: str
    schedule: Mapping[str, tuple[str, ...]]

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
