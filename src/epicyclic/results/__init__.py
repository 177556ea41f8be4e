"""Result objects and their rendering (table, dict/JSON, HTML)."""

from .circulation import Circulation, PowerLoop
from .solution import ElementState, SelfLocking, ShaftState, Solution

__all__ = ["Circulation", "ElementState", "PowerLoop", "SelfLocking", "ShaftState", "Solution"]
