"""Errors of the transient simulation (bad input: ``ModelError``)."""

from __future__ import annotations

from ..errors import ModelError

__all__ = ["DynamicsError"]


class DynamicsError(ModelError):
    """Bad input to a shift or launch simulation: an element without capacity, a shift the schedule does not
    allow, a profile or table that cannot be used, a bound out of range. The message names the element or key."""
