"""The units the project knows: core units, the sources' unit definitions, the unit registry.

The lowest part of :mod:`epicyclic.units` (which re-exports these names and
holds the grammar and the conversions): the core unit of each quantity, the
definitions that make pint read the sources' units as they mean them (``PS``,
``U/min``, ``kp``, ``Nm``), and a table of known factors that reads the
common units without building the registry.

References
----------
DIN 1301 (PS = 735.49875 W); CGPM 1901 (standard gravity 9.80665 m/s², kp = 9.80665 N).
"""

from __future__ import annotations

import math
from functools import lru_cache
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    import pint

__all__ = ["CORE_UNITS", "QUANTITIES", "G0", "registry"]

#: The core unit of every quantity the I/O layer converts.
CORE_UNITS = {"speed": "1/min", "torque": "N*m", "power": "W"}

#: Quantities that carry units, with examples of accepted units (for messages).
QUANTITIES = {
    "speed": "1/min, U/min, rpm, 1/s, rad/s",
    "torque": "N*m, kN*m, kp*cm, cm*kg, kp*m, lbf*ft",
    "power": "W, kW, PS, hp",
}

#: Standard gravity (kp = 9.80665 N exactly).
G0 = 9.80665

_DEFINITIONS = (
    "revolution = 1 = rev = turn = U = Umdrehung",
    "radian = revolution / (2 * pi) = rad",
    "rpm = revolution / minute",
    "PS = 735.49875 W = metric_horsepower_PS",
    "kp = 9.80665 N = kilopond",
    "newton_meter = N * m = Nm",
)


#: Core units per unit for the units of the sources, the examples and the documentation, so that
#: reading them needs neither pint nor its registry (importing pint and building the registry cost
#: about 0.3 s of every start).  Not a second definition: tests/test_units.py checks every entry
#: against the registry, which stays the reference for every other unit.
_KNOWN_FACTORS: dict[str, dict[str, float]] = {
    "speed": {"1/min": 1.0, "U/min": 1.0, "rpm": 1.0, "1/s": 60.0, "rad/s": 30.0 / math.pi},
    "torque": {"N*m": 1.0, "Nm": 1.0, "kN*m": 1000.0, "kp*cm": G0 / 100, "cm*kg": G0 / 100, "kp*m": G0,
               "m*kg": G0, "lbf*ft": 0.45359237 * G0 * 0.3048},
    "power": {"W": 1.0, "kW": 1000.0, "MW": 1e6, "PS": 735.49875, "hp": 0.45359237 * G0 * 0.3048 * 550},
}


@lru_cache(maxsize=1)
def registry() -> pint.UnitRegistry:
    """The project's unit registry (built once; pint's defaults plus the sources' units)."""
    import pint  # imported here: the known units below need neither pint nor its registry

    ureg = pint.UnitRegistry(on_redefinition="ignore", cache_folder=None)
    for definition in _DEFINITIONS:
        ureg.define(definition)
    return ureg
