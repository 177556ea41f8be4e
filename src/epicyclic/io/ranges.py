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
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..errors import ModelError
from ..limits import MAX_MAP_POINTS, MAX_MAP_VALUES
from ..text import short

if TYPE_CHECKING:  # pragma: no cover
    import numpy as np

__all__ = ["parse_range", "parse_tolerance", "parse_axis", "map_grid"]


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
        value = float(raw.rstrip("%").strip())
    except ValueError:
        raise ModelError(f"{name}: expected a relative deviation such as 3% or 0.03, got {short(text)}.") from None
    value = value / 100.0 if percent else value
    if not 0.0 <= value < 1.0:
        raise ModelError(f"{name}: expected 0 <= tolerance < 100 %, got {short(text)}.")
    return round(value, 12)


def parse_axis(text: str, name: str, unit: str) -> np.ndarray:
    """``"500..6000:50"`` → 50 evenly spaced values from 500 to 6000 (ends included); ``"1500"`` → one value.

    Raises
    ------
    ModelError
        Not numbers, not 0 < A <= B, or a count outside 2..:data:`~epicyclic.limits.MAX_MAP_VALUES`.
    """
    import numpy as np

    raw = text.strip()
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
    return np.linspace(values[0], values[1], count)


def map_grid(speed: str, torque: str, names: tuple[str, str] = ("--speed", "--torque")) -> tuple[np.ndarray, np.ndarray]:
    """The speeds (1/min) and torques (N·m) of an efficiency map, at most :data:`~epicyclic.limits.MAX_MAP_POINTS`.

    Raises
    ------
    ModelError
        A bad axis (:func:`parse_axis`) or more grid points than the limit.
    """
    speeds = parse_axis(speed, names[0], "1/min")
    torques = parse_axis(torque, names[1], "N*m")
    if speeds.size * torques.size > MAX_MAP_POINTS:
        raise ModelError(f"{names[0]}/{names[1]}: {speeds.size} × {torques.size} points exceed the limit of "
                         f"{MAX_MAP_POINTS:,}; use fewer values.")
    return speeds, torques
