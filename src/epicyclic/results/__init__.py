"""Result objects and their rendering (table, dict/JSON, HTML)."""

from .solution import ElementState, SelfLocking, ShaftState, Solution

__all__ = ["ElementState", "SelfLocking", "ShaftState", "Solution"]
