"""The model: immutable, validated descriptions of elements, trains and operating points."""

from .elements import HOUSING, Brake, Clutch, GearStage
from .operating_point import OperatingPoint
from .planetary import PlanetarySet, Teeth
from .train import GearTrain

__all__ = ["HOUSING", "Brake", "Clutch", "GearStage", "GearTrain", "OperatingPoint", "PlanetarySet", "Teeth"]
