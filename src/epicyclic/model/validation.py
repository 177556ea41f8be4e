"""Validation of the model's values: names, efficiencies, numbers of planets, finite numbers.

Every element checks its fields with these at construction (the one place where
the model's values are validated); the messages name the element, the field,
what was expected and what was given.  Tooth counts are checked in
:mod:`epicyclic.model.teeth`.
"""

from __future__ import annotations

import math

from ..errors import EfficiencyError, ModelError
from ..limits import MAX_NAME_CHARS, MAX_PLANETS

__all__ = ["check_name", "check_planets", "finite_float", "check_efficiency"]


def check_name(value: object, field_name: str, owner: str) -> str:
    """Return ``value`` if it is a usable name, else raise ModelError.

    A name is a non-empty string of at most :data:`~epicyclic.limits.MAX_NAME_CHARS`
    printable characters without leading or trailing spaces (names appear in
    tables, terminals and file names).

    >>> check_name("sun", "sun", "set P1")
    'sun'
    """
    if not isinstance(value, str) or not value.strip():
        raise ModelError(f"{owner}: {field_name} must be a non-empty shaft name, got {value!r:.60}.")
    if len(value) > MAX_NAME_CHARS:
        raise ModelError(f"{owner}: {field_name} {value[:20]!r}… is {len(value)} characters long; at most "
                         f"{MAX_NAME_CHARS} are accepted.")
    if not value.isprintable() or value != value.strip():
        raise ModelError(f"{owner}: {field_name} {value!r} contains control characters or leading/trailing "
                         "spaces; use letters, digits and punctuation.")
    return value


def check_planets(value: object, field_name: str, owner: str) -> int:
    """Return ``value`` if it is a whole number of planets in 1 … MAX_PLANETS, else raise ModelError."""
    if isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= MAX_PLANETS:
        raise ModelError(f"{owner}: {field_name} must be a whole number >= 1 and <= {MAX_PLANETS}, got {value!r:.40}.")
    return value


def finite_float(value: object) -> float | None:
    """``value`` as float if it is a finite real number (not a boolean), else None.

    Integers beyond double precision (``10**400``) are not finite numbers here.

    >>> finite_float(3), finite_float(float("nan")), finite_float(10**400), finite_float(True)
    (3.0, None, None, None)
    """
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    try:
        number = float(value)
    except OverflowError:
        return None
    return number if math.isfinite(number) else None


def check_efficiency(value: object, field_name: str, owner: str) -> float:
    """Return ``value`` as float if it lies in (0, 1], else raise EfficiencyError.

    >>> check_efficiency(0.97, "stationary_efficiency", "set P1")
    0.97
    """
    number = finite_float(value)
    if number is None and not (isinstance(value, float) and math.isnan(value)):
        raise EfficiencyError(f"{owner}: {field_name} must be a number in (0, 1], got {value!r:.40}.")
    value = float("nan") if number is None else number
    if not (0.0 < value <= 1.0):
        raise EfficiencyError(
            f"{owner}: {field_name} must lie in (0, 1] (1 = lossless), got {value!r}. "
            "Give an efficiency such as 0.98, not a percentage or a loss."
        )
    return value
