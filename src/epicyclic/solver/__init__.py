"""The general solver: kinematics by rank, statics with Brandenberger's loss rule."""

from .solve import solve

__all__ = ["solve"]
