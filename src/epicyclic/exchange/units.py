"""The units REXS writes, converted explicitly to the units of a train file.

REXS names its units in plain ASCII (``mum`` for µm, ``1 / min``, ``N m``,
``deg`` or ``°``, ``C`` for °C, ``kg / dm^3``); every attribute carries one.
:func:`to_file_unit` converts a value to the unit the train file uses for that
quantity (mm, degrees, 1/min, N·m, W, °C, mm²/s, kg/dm³, mPa·s, a fraction of
1), and refuses a unit of another quantity or one it does not know, naming the
component and the attribute.  The factors are checked against pint in
``tests/exchange/test_units.py``.

Examples
--------
>>> to_file_unit(250.0, "kW", "power", "where")
250000.0
>>> to_file_unit(12.0, "mum", "length", "where")
0.012
>>> to_file_unit(20.0, "N", "length", "component 5 'G', attribute 'face_width'")
Traceback (most recent call last):
...
epicyclic.exchange.units.RexsUnitError: component 5 'G', attribute 'face_width': the unit 'N' is not a length; REXS writes lengths in mm, mum or m.

References
----------
REXS 1.7 unit list (``rexs_schema_1.7.xml``, FVA GmbH, github.com/fva-net/rexs-api-java, Apache-2.0).
"""

from __future__ import annotations

import math

from ..errors import ModelError

__all__ = ["FILE_UNITS", "REXS_UNITS", "RexsUnitError", "rexs_unit", "to_file_unit"]


class RexsUnitError(ModelError):
    """A REXS attribute whose unit is unknown or of another quantity."""


#: REXS unit name → (quantity, factor to the train file's unit, offset added after the factor).
REXS_UNITS: dict[str, tuple[str, float, float]] = {
    "mm": ("length", 1.0, 0.0),
    "mum": ("length", 1e-3, 0.0),
    "m": ("length", 1e3, 0.0),
    "deg": ("angle", 1.0, 0.0),
    "°": ("angle", 1.0, 0.0),
    "rad": ("angle", 180.0 / math.pi, 0.0),
    "1 / min": ("speed", 1.0, 0.0),
    "1 / s": ("speed", 60.0, 0.0),
    "rad / s": ("speed", 30.0 / math.pi, 0.0),
    "N m": ("torque", 1.0, 0.0),
    "N mm": ("torque", 1e-3, 0.0),
    "kN m": ("torque", 1e3, 0.0),
    "W": ("power", 1.0, 0.0),
    "kW": ("power", 1e3, 0.0),
    "N": ("force", 1.0, 0.0),
    "kN": ("force", 1e3, 0.0),
    "C": ("temperature", 1.0, 0.0),
    "K": ("temperature", 1.0, -273.15),
    "mm^2 / s": ("kinematic viscosity", 1.0, 0.0),
    "kg / dm^3": ("density", 1.0, 0.0),
    "mPa s": ("dynamic viscosity", 1.0, 0.0),
    "%": ("fraction", 0.01, 0.0),
    "h": ("time", 1.0, 0.0),
    "N / mm^2": ("stress", 1.0, 0.0),
    "MPa": ("stress", 1.0, 0.0),
    "HV": ("hardness", 1.0, 0.0),
    "HB": ("hardness", 1.0, 0.0),
    "HRC": ("hardness", 1.0, 0.0),
    "none": ("number", 1.0, 0.0),
    "": ("number", 1.0, 0.0),
}

#: The train file's unit of each quantity (what :func:`to_file_unit` returns).
FILE_UNITS = {"length": "mm", "angle": "deg", "speed": "1/min", "torque": "N*m", "power": "W", "force": "N",
              "temperature": "degC", "kinematic viscosity": "mm^2/s", "density": "kg/dm^3",
              "dynamic viscosity": "mPa*s", "fraction": "1", "time": "h", "number": "1", "stress": "N/mm^2",
              "hardness": "HV, HB or HRC (the attribute's scale)"}

#: The unit the writer gives each quantity (REXS 1.7 spelling).
_WRITTEN = {"length": "mm", "angle": "deg", "speed": "1 / min", "torque": "N m", "power": "kW", "force": "N",
            "temperature": "C", "kinematic viscosity": "mm^2 / s", "density": "kg / dm^3",
            "dynamic viscosity": "mPa s", "fraction": "%", "time": "h", "number": "none",
            "stress": "N / mm^2"}

def _spoken(units: list[str]) -> str:
    return units[0] if len(units) == 1 else ", ".join(units[:-1]) + " or " + units[-1]


_EXAMPLES = {quantity: _spoken([u for u, (q, _, _) in REXS_UNITS.items() if q == quantity and u])
             for quantity in FILE_UNITS}


def to_file_unit(value: float, unit: str | None, quantity: str, where: str) -> float:
    """``value`` given in the REXS ``unit``, in the train file's unit of ``quantity``.

    Parameters
    ----------
    value : float
        The number as the file gives it.
    unit : str or None
        The attribute's REXS unit (None or ``""``: none given, read as the REXS unit of the
        quantity's default, i.e. the number unchanged).
    quantity : str
        A key of :data:`FILE_UNITS` (``"length"``, ``"speed"``, ...).
    where : str
        The component and attribute, the start of an error message.

    Returns
    -------
    float

    Raises
    ------
    RexsUnitError
        The unit is unknown, or of another quantity.
    """
    unit = (unit or "").strip()
    if unit in ("", "none") and quantity != "number":
        return float(value)  # Bearinx writes no unit for dimensionless and some default-unit values
    known = REXS_UNITS.get(unit)
    if known is None or known[0] != quantity:
        article = "an" if quantity[0] in "aeiou" else "a"
        what = "unknown to REXS" if known is None else f"not {article} {quantity}"
        raise RexsUnitError(f"{where}: the unit {unit[:40]!r} is {what}; REXS writes {quantity}s in "
                            f"{_EXAMPLES[quantity]}.")
    _, factor, offset = known
    if factor < 1.0 and (1.0 / factor).is_integer():  # divide by 100 or 1000: 35 % is 0.35, not 0.35000000000000003
        return float(value) / (1.0 / factor) + offset
    return float(value) * factor + offset


def rexs_unit(quantity: str) -> str:
    """The REXS unit the writer uses for ``quantity`` (values are converted to it by the writer).

    Parameters
    ----------
    quantity : str
        A key of :data:`FILE_UNITS`.

    Returns
    -------
    str
        E.g. ``"1 / min"`` for ``"speed"``.
    """
    return _WRITTEN[quantity]
