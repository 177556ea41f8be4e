"""Argument checks shared by the spin-loss models: numbers and arrays that must be finite and positive.

>>> positive(2.0, "clearance (mm)", "ClutchDrag")
2.0
"""

from __future__ import annotations

import math

import numpy as np

from .errors import LossModelError

__all__ = ["positive", "fraction", "finite_array", "non_negative_array", "positive_array"]


def positive(value: object, name: str, owner: str, *, allow_zero: bool = False) -> float:
    """``value`` as a float if it is a finite number > 0 (≥ 0 with ``allow_zero``), else a LossModelError."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or value < 0 or (value == 0 and not allow_zero):
        raise LossModelError(
            f"{owner}: {name} must be a {'non-negative' if allow_zero else 'positive'} finite number, "
            f"got {value!r}."
        )
    return float(value)


def fraction(value: object, name: str, owner: str, *, allow_zero: bool = False) -> float:
    """``value`` as a float in (0, 1] ([0, 1] with ``allow_zero``), else a LossModelError."""
    number = positive(value, name, owner, allow_zero=allow_zero)
    if number > 1.0:
        raise LossModelError(f"{owner}: {name} must lie in {'[' if allow_zero else '('}0, 1], got {value!r}.")
    return number


def finite_array(value: object, name: str, owner: str) -> np.ndarray:
    """``value`` as a float array of finite values, else a LossModelError naming it."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise LossModelError(f"{owner}: {name} must be numbers, got {value!r}.") from None
    if not np.all(np.isfinite(arr)):
        raise LossModelError(f"{owner}: {name} must be finite numbers (no NaN or infinity).")
    return arr


def non_negative_array(value: object, name: str, owner: str) -> np.ndarray:
    """``value`` as a float array of finite values ≥ 0, else a LossModelError."""
    arr = finite_array(value, name, owner)
    if np.any(arr < 0):
        raise LossModelError(f"{owner}: {name} must be >= 0, got {float(arr.min())!r}.")
    return arr


def positive_array(value: object, name: str, owner: str) -> np.ndarray:
    """``value`` as a float array of finite values > 0, else a LossModelError."""
    arr = finite_array(value, name, owner)
    if np.any(arr <= 0):
        raise LossModelError(f"{owner}: {name} must be > 0, got {float(arr.min())!r}.")
    return arr
