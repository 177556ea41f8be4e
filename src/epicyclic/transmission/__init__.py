"""Multi-speed transmissions: shift schedules, per-gear analysis, exploration, a library."""

from .explore import Combination, Exploration, explore
from .results import GearResult, TransmissionAnalysis
from .default_point import DEFAULT_INPUT_SPEED, DEFAULT_INPUT_TORQUE, default_operating_point, default_point_note
from .errors import UnknownGearError
from .transmission import GearFreedomError, ShiftScheduleError, Transmission

__all__ = [
    "Combination",
    "DEFAULT_INPUT_SPEED",
    "DEFAULT_INPUT_TORQUE",
    "Exploration",
    "GearFreedomError",
    "GearResult",
    "ShiftScheduleError",
    "Transmission",
    "TransmissionAnalysis",
    "UnknownGearError",
    "default_operating_point",
    "default_point_note",
    "explore",
]
