"""Multi-speed transmissions: shift schedules, per-gear analysis, exploration, a library; shift maps and drive cycles."""

from .cycle_energy import CycleResult, GearRule, run_cycle
from .drive_cycle import DriveCycle
from .explore import Combination, Exploration, explore
from .gear_points import CarryLimits, GearPoints, solve_gear_points
from .input_point import InputPoint, input_point
from .results import GearResult, TransmissionAnalysis
from .errors import UnknownGearError
from .shift_map import ShiftMap, shift_map
from .shift_schedule import ShiftSchedule
from .transmission import GearFreedomError, ShiftScheduleError, Transmission
from .vehicle import Vehicle

__all__ = [
    "CarryLimits",
    "Combination",
    "CycleResult",
    "DriveCycle",
    "Exploration",
    "GearFreedomError",
    "GearPoints",
    "GearResult",
    "GearRule",
    "InputPoint",
    "ShiftMap",
    "ShiftSchedule",
    "ShiftScheduleError",
    "Transmission",
    "TransmissionAnalysis",
    "UnknownGearError",
    "Vehicle",
    "explore",
    "input_point",
    "run_cycle",
    "shift_map",
    "solve_gear_points",
]
