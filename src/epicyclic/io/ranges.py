"""The range grammar of the command line and the page: ``12..80``, ``500..6000:50``, ``3%``.

``epicyclic search`` and ``epicyclic map`` read their ranges with these
functions, and so do the page's forms (``epicyclic serve``), so that a bad
value gets the same message in both; ``name`` is what the message calls the
value (``--speed`` on the command line, the form's field on the page).

Examples
--------
>>> parse_range("3..6", "--planets")
(3, 6)
>>> parse_tolerance("3%"), parse_tolerance("0.5 %")
(0.03, 0.005)
>>> parse_axis("10..50:5", "--torque", "N*m").tolist()
[10.0, 20.0, 30.0, 40.0, 50.0]

The map's axes are read in the file's units, or in the unit written after the
range; they come back in core units (1/min, N·m):

>>> parse_axis("100..200:3 rad/s", "--speed", "1/min", "speed").round(2).tolist()
[954.93, 1432.39, 1909.86]
>>> default_axis("speed", "rad/s")
'52.3599..628.319:50'
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from ..errors import ModelError
from ..limits import MAX_MAP_POINTS, MAX_MAP_VALUES
from ..text import short

if TYPE_CHECKING:  # pragma: no cover
    import numpy as np

__all__ = ["parse_range", "parse_tolerance", "parse_axis", "map_grid", "default_axis", "MAP_DEFAULTS"]

#: The efficiency map's axes when none is given: (first, last, count) in core units (1/min, N·m).
MAP_DEFAULTS = {"speed": (500.0, 6000.0, 50), "torque": (10.0, 500.0, 50)}

#: A range ``A..B:N`` and what follows it (a unit, or nothing).
_AXIS = re.compile(r"^\s*(?P<range>[-+0-9.eE]+(?:\s*\.\.\s*[-+0-9.eE]+)?(?:\s*:\s*[-+0-9]+)?)\s*(?P<unit>.*?)\s*$")


def parse_range(text: str, name: str, low: int = 3, high: int = 400) -> tuple[int, int]:
    """``"12..80"`` → (12, 80); ``"20"`` → (20, 20); whole numbers within ``low``..``high``.

    Raises
    ------
    ModelError
        Not whole numbers, reversed, or outside ``low``..``high``.
    """
    parts = text.split("..")
    try:
        values = [int(p.strip()) for p in parts]
    except ValueError:
        raise ModelError(f"{name}: expected a whole number or a range such as 12..80, got {short(text)}.") from None
    if len(values) == 1:
        values *= 2
    if len(values) != 2 or values[0] > values[1] or values[0] < low or values[1] > high:
        raise ModelError(f"{name}: expected a range LOW..HIGH with {low} <= LOW <= HIGH <= {high}, got {short(text)}.")
    return values[0], values[1]


def parse_tolerance(text: str, name: str = "search: --tolerance") -> float:
    """``"3%"`` → 0.03, ``"0.03"`` → 0.03: a relative deviation 0 ≤ tolerance < 1.

    Raises
    ------
    ModelError
        Not a number, or outside [0, 100 %).
    """
    raw = text.strip()
    percent = raw.endswith("%")
    try:
        value = float((raw[:-1] if percent else raw).strip())
    except ValueError:
        raise ModelError(f"{name}: expected a relative deviation such as 3% or 0.03, got {short(text)}.") from None
    value = value / 100.0 if percent else value
    if not 0.0 <= value < 1.0:
        raise ModelError(f"{name}: expected 0 <= tolerance < 100 %, got {short(text)}.")
    return round(value, 12)


def default_axis(quantity: str, unit: str) -> str:
    """The default map axis of ``quantity`` (:data:`MAP_DEFAULTS`) written in ``unit``, as ``A..B:N``."""
    from ..units import from_core

    first, last, count = MAP_DEFAULTS[quantity]
    return f"{from_core(first, quantity, unit):.6g}..{from_core(last, quantity, unit):.6g}:{count}"


def parse_axis(text: str, name: str, unit: str, quantity: str | None = None) -> np.ndarray:
    """``"500..6000:50"`` → 50 evenly spaced values from 500 to 6000 (ends included); ``"1500"`` → one value.

    Parameters
    ----------
    text : str
        ``A..B:N`` or ``A``, optionally followed by a unit (``500..6000:50 rpm``) when ``quantity`` is given.
    name : str
        What a message calls the value (``--speed``).
    unit : str
        The unit of numbers without one (the file's ``[units]``).
    quantity : {"speed", "torque"}, optional
        Convert to the core unit of this quantity (1/min, N·m); without it the numbers come back as written.

    Raises
    ------
    ModelError
        Not numbers, not 0 < A <= B, or a count outside 2..:data:`~epicyclic.limits.MAX_MAP_VALUES`.
    UnitError
        An unknown unit, or one of another quantity.
    """
    import numpy as np

    raw = text.strip()
    match = _AXIS.match(raw) if quantity is not None else None
    if match and match["unit"] and not match["unit"].startswith(":"):  # ":many" is a bad count, not a unit
        raw, unit = match["range"], match["unit"]
    count = None
    if ":" in raw:
        raw, _, tail = raw.partition(":")
        try:
            count = int(tail)
        except ValueError:
            raise ModelError(f"{name}: the count after ':' must be a whole number, got {short(text)} "
                             f"(e.g. 500..6000:50 for 50 values).") from None
    parts = raw.split("..")
    try:
        values = [float(p) for p in parts]
    except ValueError:
        raise ModelError(f"{name}: expected a value or a range A..B:N in {unit}, e.g. 500..6000:50, got "
                         f"{short(text)}.") from None
    if len(values) == 1:
        if count not in (None, 1):
            raise ModelError(f"{name}: a single value takes no count, got {short(text)}.")
        values, count = values * 2, 1
    if len(values) != 2 or not all(np.isfinite(values)) or values[0] <= 0 or values[1] < values[0]:
        raise ModelError(f"{name}: expected 0 < A <= B in A..B:N ({unit}), got {short(text)}.")
    count = 20 if count is None else count
    if not 1 <= count <= MAX_MAP_VALUES or (count == 1 and values[0] != values[1]):
        raise ModelError(f"{name}: the number of values N must lie in 2..{MAX_MAP_VALUES} for a range, "
                         f"got {short(text)}.")
    axis = np.linspace(values[0], values[1], count)
    if quantity is None:
        return axis
    from ..units import unit_factor

    return axis * unit_factor(unit, quantity, name)


def map_grid(speed: str | None, torque: str | None, names: tuple[str, str] = ("--speed", "--torque"),
             units=None) -> tuple[np.ndarray, np.ndarray]:
    """The speeds (1/min) and torques (N·m) of an efficiency map, at most :data:`~epicyclic.limits.MAX_MAP_POINTS`.

    Parameters
    ----------
    speed, torque : str or None
        Axes ``A..B:N`` in ``units`` (or with a unit after them); None: :data:`MAP_DEFAULTS`.
    names : (str, str)
        What messages call the two axes.
    units : Units, optional
        The file's ``[units]`` (default: core units).

    Raises
    ------
    ModelError
        A bad axis (:func:`parse_axis`) or more grid points than the limit.
    """
    import numpy as np

    def axis(text, name, quantity):
        if text is None:
            first, last, count = MAP_DEFAULTS[quantity]
            return np.linspace(first, last, count)
        return parse_axis(text, name, units.of(quantity) if units is not None else _CORE[quantity], quantity)

    speeds = axis(speed, names[0], "speed")
    torques = axis(torque, names[1], "torque")
    if speeds.size * torques.size > MAX_MAP_POINTS:
        raise ModelError(f"{names[0]}/{names[1]}: {speeds.size} × {torques.size} points exceed the limit of "
                         f"{MAX_MAP_POINTS:,}; use fewer values.")
    return speeds, torques


_CORE = {"speed": "1/min", "torque": "N*m"}
