"""Multi-speed transmissions: shift schedules, per-gear analysis, exploration, a library; shift maps and drive cycles."""

from .cycle_energy import CycleResult, GearRule, run_cycle
from .drive_cycle import DriveCycle
from .explore import Combination, Exploration, explore
from .gear_points import CarryLimits, GearPoints, solve_gear_points
from .input_point import InputPoint, input_point
from .results import GearResult, TransmissionAnalysis
from .default_point import DEFAULT_INPUT_SPEED, DEFAULT_INPUT_TORQUE, default_operating_point, default_point_note
from .errors import UnknownGearError
from .shift_map import ShiftMap, shift_map
from .shift_schedule import ShiftSchedule
from .train_in_gear import TrainInGear, train_in_gear
from .transmission import GearFreedomError, ShiftScheduleError, Transmission
from .vehicle import Vehicle

__all__ = [
    "CarryLimits",
    "Combination",
    "CycleResult",
    "DriveCycle",
    "DEFAULT_INPUT_SPEED",
    "DEFAULT_INPUT_TORQUE",
    "Exploration",
    "GearFreedomError",
    "GearPoints",
    "GearResult",
    "GearRule",
    "InputPoint",
    "ShiftMap",
    "ShiftSchedule",
    "ShiftScheduleError",
    "TrainInGear",
    "Transmission",
    "TransmissionAnalysis",
    "UnknownGearError",
    "Vehicle",
    "default_operating_point",
    "default_point_note",
    "explore",
    "input_point",
    "run_cycle",
    "shift_map",
    "solve_gear_points",
    "train_in_gear",
]
