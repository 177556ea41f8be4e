"""epicyclic — analysis of epicyclic (planetary) gear trains.

Describe a train as planetary sets, gear stages, clutches and brakes joining
named shafts; give an operating point; :func:`solve` returns every speed,
torque, power, loss, the efficiency for the real direction of power flow,
self-locking and circulating power.

Core units: speed 1/min, torque N·m, power W.

>>> from epicyclic import GearTrain, PlanetarySet, Brake, OperatingPoint, solve
>>> train = GearTrain([PlanetarySet.simple("P", sun="in", ring="ring", carrier="out",
...                    z_sun=30, z_planet=24, z_ring=78, stationary_efficiency=0.98),
...                    Brake("B", "ring")])
>>> sol = solve(train, OperatingPoint(speeds={"in": 3600}, torques={"in": 100},
...                                   drives=["in"], loads=["out"]))
>>> round(sol.speed("out"), 3), round(sol.efficiency, 5)
(1000.0, 0.98556)
"""

from . import pickling  # noqa: F401  (read-only mappings pickle: every result can go to another process)
from .errors import (
    ContradictionError,
    EfficiencyError,
    EpicyclicError,
    ModelError,
    OperatingPointError,
    ToothCountError,
    TopologyError,
    UnderdeterminedError,
    UnknownShaftError,
)
from .model import HOUSING, Brake, Clutch, GearStage, GearTrain, OperatingPoint, PlanetarySet, Teeth
from .results import ElementState, SelfLocking, ShaftState, Solution
from .solver import solve

__version__ = "0.1.0"


def _notebook_previews() -> None:
    """In a running IPython (a notebook) sets, trains and transmissions show a schematic (epicyclic.notebook)."""
    from .notebook import register

    register()


_notebook_previews()


__all__ = [
    "HOUSING",
    "Brake",
    "Clutch",
    "ContradictionError",
    "EfficiencyError",
    "ElementState",
    "EpicyclicError",
    "GearStage",
    "GearTrain",
    "ModelError",
    "OperatingPoint",
    "OperatingPointError",
    "PlanetarySet",
    "SelfLocking",
    "ShaftState",
    "Solution",
    "Teeth",
    "ToothCountError",
    "TopologyError",
    "UnderdeterminedError",
    "UnknownShaftError",
    "solve",
]
