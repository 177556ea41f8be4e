"""Errors of the geometry package (extend :mod:`epicyclic.errors`).

>>> from epicyclic.errors import EpicyclicError, ToothCountError
>>> issubclass(FittingError, ToothCountError) and issubclass(GeometryError, EpicyclicError)
True
"""

from __future__ import annotations

from collections.abc import Sequence

from ..errors import ModelError, ToothCountError

__all__ = ["GeometryError", "FittingError"]


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
