"""What every figure states about its subject: title, gear and shift state, units, assumptions.

A :class:`FigureContext` travels with a picture's data object.  Figures draw
values in the user's units (those of the file's ``[units]`` table, as the
tables of ``analyze`` do), put the train, the gear and the engaged clutches
and brakes into the title, and add a note line for what was assumed (unit
input speed and torque when the file has no operating point, a schematic
geometry where tooth counts are missing).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

from ..units import Units
from .values import clean, fmt

if TYPE_CHECKING:  # pragma: no cover
    from ..model.train import GearTrain

__all__ = ["FigureContext", "shift_state"]


def shift_state(train: GearTrain, gear: str | None = None) -> str:
    """The shift state in words: ``"gear 1: forward + low_reverse engaged"``, ``"B engaged"``, or ``""``.

    Examples
    --------
    >>> from epicyclic import Brake, GearTrain, PlanetarySet
    >>> train = GearTrain([PlanetarySet("P", "a", "b", "c", -2.0), Brake("B", "b")])
    >>> shift_state(train), shift_state(train, "1"), shift_state(train.with_engaged([]))
    ('B engaged', 'gear 1: B engaged', 'all clutches and brakes open')
    """
    shift = train.shift_elements
    engaged = [e.name for e in shift if e.engaged]
    if not shift:
        state = ""
    elif engaged:
        state = " + ".join(engaged) + " engaged"
    else:
        state = "all clutches and brakes open"
    if gear is None:
        return state
    return f"gear {gear}: {state}" if state else f"gear {gear}"


@dataclass(frozen=True)
class FigureContext:
    """The frame of a figure: what is drawn, in which units, under which assumptions.

    Parameters
    ----------
    title : str, optional
        The train's title (default: the train's name).
    units : Units, optional
        Units of speeds, torques and powers on the figure (default 1/min, N·m, W).
    gear : str, optional
        The gear of a transmission the figure shows.
    notes : tuple of str
        Assumptions to state on the figure, e.g. "unit input speed and torque".
    geometry : mapping set name → SetGeometry
        The gear geometry the file gives (``TrainFile.geometry``): the speed plan
        draws those sets at their real operating pitch radii.
    """

    title: str = ""
    units: Units = field(default_factory=Units)
    gear: str | None = None
    notes: tuple[str, ...] = ()
    geometry: Mapping[str, Any] = field(default_factory=dict, compare=False)
    #: Element → what it fails (a mesh below its minimum safety, ISO 6336): drawn red where the element is.
    warnings: Mapping[str, str] = field(default_factory=dict, compare=False)

    def with_note(self, note: str) -> FigureContext:
        """A copy with one more note (notes already present are not repeated)."""
        return self if note in self.notes else replace(self, notes=(*self.notes, note))

    # ------------------------------------------------------------------ words
    def heading(self, train: GearTrain, what: str) -> str:
        """Title of a figure: ``"<title>: <what>"``, then the shift state and the notes on a second line.

        Parameters
        ----------
        train : GearTrain
            The train drawn (its name if the context has no title; its clutches and brakes
            give the shift state).
        what : str
            What the figure shows, e.g. ``"speeds"``.

        Returns
        -------
        str

        Examples
        --------
        >>> from epicyclic import Brake, GearTrain, PlanetarySet
        >>> train = GearTrain([PlanetarySet("P", "a", "b", "c", -2.0), Brake("B", "b")], name="t")
        >>> print(FigureContext(gear="1").heading(train, "torques"))
        t: torques
        gear 1: B engaged
        """
        second = "; ".join(s for s in (shift_state(train, self.gear), *self.notes) if s)
        first = f"{self.title or train.name}: {what}"
        return first + (f"\n{second}" if second else "")

    # ------------------------------------------------------------------ units
    def unit(self, quantity: str) -> str:
        """The unit of ``quantity`` as printed on figures (``*`` as ``·``).

        >>> FigureContext(units=Units(torque="kp*cm")).unit("torque")
        'kp·cm'
        """
        return self.units.of(quantity).replace("*", "·")

    def convert(self, value: float, quantity: str) -> float:
        """A core value (1/min, N·m, W) in the figure's unit.

        Parameters
        ----------
        value : float
            The value in the core unit.
        quantity : {"speed", "torque", "power"}
            What it is.

        Returns
        -------
        float

        Examples
        --------
        >>> from epicyclic.units import Units
        >>> round(FigureContext(units=Units(power="kW")).convert(1500.0, "power"), 6)
        1.5
        """
        return float(self.units.convert(value, quantity))  # type: ignore[arg-type]

    def text(self, value: float, quantity: str, scale: float, digits: int = 4) -> str:
        """``"1500 U/min"``: value (core units) converted, zero rule applied against ``scale``.

        Parameters
        ----------
        value : float
            The value in the core unit (1/min, N·m, W).
        quantity : {"speed", "torque", "power"}
            What it is.
        scale : float
            The size of the figure's values of that quantity (core unit): a value below the
            zero rule's share of it is shown as 0 (:func:`epicyclic.results.zero.clean`).
        digits : int, default 4
            Significant digits.

        Returns
        -------
        str
            The number and the unit.
        """
        return f"{fmt(self.convert(clean(value, scale), quantity), digits)} {self.unit(quantity)}"
