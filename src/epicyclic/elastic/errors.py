"""Errors of the elastic models of a planetary set (extend :mod:`epicyclic.errors`).

>>> from epicyclic.errors import ModelError
>>> issubclass(ElasticError, ModelError) and issubclass(ElasticError, ValueError)
True
"""

from __future__ import annotations

import math

from ..errors import ModelError

__all__ = ["ElasticError", "positive", "non_negative", "finite"]


class ElasticError(ModelError):
    """Bad input to an elastic model: a mass, stiffness, error or speed that cannot be (the key is named)."""


def finite(value: object, key: str) -> float:
    """``value`` as a finite float, or ElasticError naming ``key``.

    >>> finite(2, "k_p")
    2.0
    """
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(float(value)):
        raise ElasticError(f"{key} must be a finite number, got {value!r}.")
    return float(value)


def positive(value: object, key: str) -> float:
    """``value`` as a float > 0, or ElasticError naming ``key``.

    >>> positive(1e8, "k_sp")
    100000000.0
    """
    number = finite(value, key)
    if number <= 0.0:
        raise ElasticError(f"{key} must be > 0, got {value!r}.")
    return number


def non_negative(value: object, key: str) -> float:
    """``value`` as a float ≥ 0, or ElasticError naming ``key`` (0: no spring, a free member).

    >>> non_negative(0, "k_su")
    0.0
    """
    number = finite(value, key)
    if number < 0.0:
        raise ElasticError(f"{key} must be >= 0 (0 = free), got {value!r}.")
    return number
