"""Pictures of a solved gear train (placeholder, completed below)."""

from ._common import PlottingError

__all__ = ["PlottingError"]
