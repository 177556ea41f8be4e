"""Errors of the geometry package (extend :mod:`epicyclic.errors`).

>>> from epicyclic.errors import EpicyclicError, ToothCountError
>>> issubclass(FittingError, ToothCountError) and issubclass(GeometryError, EpicyclicError)
True
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from ..errors import ModelError, ToothCountError

__all__ = ["GeometryError", "FittingError", "expect_type", "finite_number"]


class GeometryError(ModelError):
    """Gear geometry input that is invalid (module ≤ 0, pressure angle out of range, ...)."""


class FittingError(ToothCountError):
    """A planetary set does not fit: one or more fitting conditions fail.

    Attributes
    ----------
    failures : tuple
        The failing condition results (each says which condition, by how much,
        and what to change).
    """

    def __init__(self, message: str, failures: Sequence[object] = ()):
        self.failures = tuple(failures)
        super().__init__(message)


def expect_type(value: object, kind: type, where: str, field_name: str, fix: str) -> None:
    """Raise GeometryError unless ``value`` is a ``kind`` (an argument given in the wrong place or of the wrong kind).

    >>> expect_type(2.0, str, "f", "name", "give a string")
    Traceback (most recent call last):
    ...
    epicyclic.geometry.errors.GeometryError: f: name must be a str, got a float; give a string.
    """
    if not isinstance(value, kind):
        raise GeometryError(f"{where}: {field_name} must be a {kind.__name__}, got a {type(value).__name__}; {fix}.")


def finite_number(value: object, where: str, field_name: str, *, minimum: float | None = None,
                  above: bool = False, unit: str = "") -> float:
    """``value`` as a float if it is a finite number (≥ ``minimum``, or > it with ``above``), else GeometryError.

    The message names the function, the argument and what it accepts.

    >>> finite_number(0.5, "max_planets", "min_clearance", minimum=0.0, unit="mm")
    0.5
    >>> finite_number(float("nan"), "max_planets", "min_clearance", minimum=0.0, unit="mm")
    Traceback (most recent call last):
    ...
    epicyclic.geometry.errors.GeometryError: max_planets: min_clearance must be a finite number >= 0 mm, got nan.
    """
    bound = "" if minimum is None else f" {'>' if above else '>='} {minimum:g}"
    wanted = f"a finite number{bound}{(' ' if bound else ' in ') + unit if unit else ''}"
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or (minimum is not None and (value < minimum or (above and value == minimum))):
        raise GeometryError(f"{where}: {field_name} must be {wanted}, got {value!r}.")
    return float(value)
