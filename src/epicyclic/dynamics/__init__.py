"""A shift as it happens: the transient motion of a transmission with slipping and sticking shift elements.

Equations of motion of any train from its kinematic constraints (:mod:`.equations`), wet clutches and
brakes with capacity from pressure and freewheels (:mod:`.friction`), pressure profiles
(:mod:`.pressure`), drives and loads (:mod:`.drive`), exact stick–slip by events (:mod:`.integrate`),
and the shift's figures (:mod:`.results`, :mod:`.shift`).
"""

from .drive import Engine, HeldSpeed, OutputTorque, TorqueTrace, VehicleLoad
from .equations import Mode, TrainDynamics
from .errors import DynamicsError
from .friction import Freewheel, FrictionCapacity, WetElement
from .inertia import Inertias, PlanetInertia, rimmed_blank_inertia, solid_blank_inertia
from .integrate import Run, integrate, settle
from .pressure import PressureProfile

__all__ = [
    "DynamicsError", "Engine", "Freewheel", "FrictionCapacity", "HeldSpeed", "Inertias", "Mode", "OutputTorque",
    "PlanetInertia", "PressureProfile", "Run", "TorqueTrace", "TrainDynamics", "VehicleLoad", "WetElement",
    "integrate", "rimmed_blank_inertia", "settle", "solid_blank_inertia",
]
