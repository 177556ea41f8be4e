"""Errors of the geometry package (extend :mod:`epicyclic.errors`).

>>> from epicyclic.errors import EpicyclicError, ToothCountError
>>> issubclass(FittingError, ToothCountError) and issubclass(GeometryError, EpicyclicError)
True
"""

from __future__ import annotations

from collections.abc import Sequence

from ..errors import ModelError, ToothCountError

__all__ = ["GeometryError", "FittingError", "expect_type"]


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
