"""Errors of the losses package.

>>> from epicyclic.errors import ModelError
>>> issubclass(LossModelError, ModelError) and issubclass(LossModelError, ValueError)
True
"""

from __future__ import annotations

from ..errors import ModelError

__all__ = ["LossModelError"]


class LossModelError(ModelError):
    """A loss model input that is invalid (friction coefficient < 0, viscosity ≤ 0, no face width, ...)."""
