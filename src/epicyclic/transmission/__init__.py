"""Multi-speed transmissions: shift schedules, per-gear analysis, exploration, a library."""

from .explore import Combination, Exploration, explore
from .input_point import InputPoint, input_point
from .results import GearResult, TransmissionAnalysis
from .errors import UnknownGearError
from .transmission import GearFreedomError, ShiftScheduleError, Transmission

__all__ = [
    "Combination",
    "Exploration",
    "GearFreedomError",
    "GearResult",
    "InputPoint",
    "ShiftScheduleError",
    "Transmission",
    "TransmissionAnalysis",
    "UnknownGearError",
    "explore",
    "input_point",
]
