"""Multi-speed transmissions: shift schedules, per-gear analysis, exploration, a library."""

from .explore import Combination, Exploration, explore
from .results import GearResult, TransmissionAnalysis
from .errors import UnknownGearError
from .transmission import GearFreedomError, ShiftScheduleError, Transmission

__all__ = [
    "Combination",
    "Exploration",
    "GearFreedomError",
    "GearResult",
    "ShiftScheduleError",
    "Transmission",
    "TransmissionAnalysis",
    "UnknownGearError",
    "explore",
]
