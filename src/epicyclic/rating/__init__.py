"""Load capacity: tooth rating (ISO 6336), bearing life (ISO 281) and duty cycles."""

from .bearing_life import BearingLifeError, BearingRating
from .duty_analysis import analyse_duty_cycle
from .duty_cycle import DutyCycle, DutyCycleError, LoadCase
from .duty_result import BearingLife, DutyCycleResult

__all__ = ["BearingLifeError", "BearingRating", "BearingLife", "DutyCycle", "DutyCycleError", "DutyCycleResult",
           "LoadCase", "analyse_duty_cycle"]
