"""Conveniences built on the general solver (never beside it)."""

from .modes import ModeTable, TwoShaftMode, three_shaft_speeds, two_shaft_modes

__all__ = ["ModeTable", "TwoShaftMode", "three_shaft_speeds", "two_shaft_modes"]
