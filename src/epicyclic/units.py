"""Units at the edges: parse and print the sources' units with pint.

The core works on plain floats in **1/min, N·m and W**.  This
module is the only place where units are parsed or converted.  It uses its own
:class:`pint.UnitRegistry` (never pint's application registry) with the
definitions the sources need and without pint's traps:

* ``PS`` is the metric horsepower, 75 kp·m/s = 735.49875 W (pint's default
  reads it as petasiemens);
* ``U`` is one revolution (*Umdrehung*), so ``U/min``, ``1/min`` and ``rpm``
  are the same unit (pint's default reads ``U`` as an enzyme unit);
* the angle unit is the *turn*: ``rad`` is 1/(2π) turn, so ``rad/s`` converts
  to 1/min with the factor 30/π and ``rpm`` never goes through Hz and radians
  (pint's default turns 60 rpm into 6.28 Hz);
* ``kp`` (kilopond) is 9.80665 N; a *torque* written as mass × length
  (``cm*kg``, ``m*kg``) is read in the sources' sense as kp·cm, kp·m;
* ``hp`` (mechanical horsepower, 745.7 W), ``lbf*ft``, ``kW``, ``N*m`` are
  pint's own; ``Nm`` is N·m (pint's default reads it as "number meter").

Strings are read by the project's own grammar, never by pint's expression
parser (which evaluates ``"9**9**9 rpm"`` for minutes): a number (exponent
within ±308), then unit names the registry knows, joined with ``*``, ``/``,
``·`` or a space and raised to whole powers up to ±4 (``m**2``, ``s^-3``,
``m²``).  A unit chosen in ``[units]`` has no number and converts to the core
unit by a factor within 1e-12 … 1e12 (see ``docs/limits.md``).

Examples
--------
>>> to_core("3 PS", "power")
2206.49625
>>> to_core("1500 U/min", "speed"), to_core("1500 rpm", "speed")
(1500.0, 1500.0)
>>> round(to_core("143.24 cm*kg", "torque"), 4)  # Brandenberger's cm kg = kp·cm
14.047
>>> round(from_core(2206.49625, "power", "PS"), 6)
3.0

References
----------
Brandenberger 1952, text to eq. (2): M = 71620 N/n cm kg with N in PS and n in
U/min (71620 = 75·100·60/(2π)).  DIN 1301 for PS = 735.49875 W.
"""

from __future__ import annotations

import math
import numbers
import re
from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache
from typing import TYPE_CHECKING

from .errors import EpicyclicError
from .limits import MAX_DECIMAL_EXPONENT, MAX_UNIT_CHARS, MAX_UNIT_POWER, UNIT_FACTOR_RANGE
from .unit_registry import _KNOWN_FACTORS, CORE_UNITS, G0, QUANTITIES, registry

if TYPE_CHECKING:  # pragma: no cover
    import numpy as np
    import pint

__all__ = [
    "CORE_UNITS",
    "QUANTITIES",
    "UnitError",
    "Units",
    "as_units",
    "to_core_array",
    "from_core",
    "registry",
    "to_core",
    "unit_factor",
]


class UnitError(EpicyclicError, ValueError):
    """A value or unit that cannot be read, or has the wrong dimension.

    Attributes
    ----------
    field : str
        Where the value was given (for example ``"operating_point.powers.II"``).
    quantity : str
        ``"speed"``, ``"torque"`` or ``"power"``.
    given : object
        What was given.
    """

    def __init__(self, message: str, field: str = "", quantity: str = "", given: object = None):
        self.field = field
        self.quantity = quantity
        self.given = given
        super().__init__(message)


# ---------------------------------------------------------------- the number-and-unit grammar
# quantity   := number [unit]
# unit       := ["1" "/"] factor ((op | whitespace) factor)*      op: * / · ⋅ ×
# factor     := name [("**" | "^") integer | "²" | "³"]            |integer| <= MAX_UNIT_POWER
# name       := a unit name the registry knows (prefixes such as k, c, M included)
# Nothing is evaluated but float() of the number, checked against MAX_DECIMAL_EXPONENT:
# pint never sees the string, so "9**9**9 rpm" is a syntax error, not minutes of work.
_NUMBER = re.compile(r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE](?P<exponent>[+-]?\d+))?")
_TOKEN = re.compile(
    r"\s*(?:(?P<power>\*\*|\^)|(?P<op>[*/\u00b7\u22c5\u00d7])|(?P<super>[\u00b2\u00b3])"
    r"|(?P<name>[^\W\d]\w*)|(?P<int>[+-]?\d+)|(?P<other>\S))"
)
_SUPERSCRIPT = {"\u00b2": 2, "\u00b3": 3}


def _grammar_error(text: str, field: str, quantity: str, reason: str) -> UnitError:
    return UnitError(
        f"{field}: cannot read {text!r} as a {quantity} ({reason}). Write a number and a unit, e.g. "
        f"{_example(quantity)!r} (units: {QUANTITIES[quantity]}); unit names may be joined with * / · "
        f"and raised to whole powers up to {MAX_UNIT_POWER}.",
        field, quantity, text,
    )


def _read_number(text: str, field: str, quantity: str) -> tuple[float | None, str]:
    """(number, rest of the text); None if the text does not start with a number."""
    match = _NUMBER.match(text)
    if match is None:
        return None, text
    exponent = match.group("exponent")
    if exponent is not None and (len(exponent.lstrip("+-")) > 4 or abs(int(exponent)) > MAX_DECIMAL_EXPONENT):
        raise _grammar_error(text, field, quantity, f"the exponent e{exponent} is beyond "
                                                    f"±{MAX_DECIMAL_EXPONENT}: not a finite, normal double")
    value = float(match.group())
    if not math.isfinite(value):
        raise UnitError(f"{field}: {text!r} is not a finite {quantity} (it overflows a double).",
                        field, quantity, text)
    return value, text[match.end():]


def _known(text: str, quantity: str, field: str) -> tuple[float, bool] | None:
    """(number, False) for a bare number, (core value, True) for a number with a known unit, None
    if the registry must read ``text``.  The number is read by the grammar's ``_read_number``."""
    if len(text) > MAX_UNIT_CHARS:
        return None
    number, rest = _read_number(text, field, quantity)
    if number is None:
        return None
    unit = rest.strip()
    if not unit:
        return number, False
    factor = _KNOWN_FACTORS[quantity].get(unit) if rest[:1].isspace() or rest[:1].isalpha() else None
    if factor is None or not math.isfinite(number * factor):
        return None
    return number * factor, True


def _read_unit(text: str, full: str, field: str, quantity: str) -> pint.Unit:
    """The unit of ``text`` by the grammar above (``full`` is the whole string, for messages)."""
    ureg = registry()
    tokens = [(m.lastgroup, m.group(m.lastgroup)) for m in _TOKEN.finditer(text) if m.lastgroup]
    unit = ureg.Unit("")
    k, sign, expect_factor = 0, 1, True
    if len(tokens) >= 2 and tokens[0] == ("int", "1") and tokens[1] == ("op", "/"):
        k, sign = 2, -1  # "1/min"
    elif tokens and tokens[0][0] == "op" and text[:1] in "*/":  # "3*PS", "3/min" (no space after the number)
        k, sign = 1, (-1 if tokens[0][1] == "/" else 1)
    while k < len(tokens):
        kind, value = tokens[k]
        if kind == "op":
            if expect_factor:
                raise _grammar_error(full, field, quantity, f"{value!r} without a unit name before it")
            sign, expect_factor = (-1 if value == "/" else 1), True
            k += 1
            continue
        if kind != "name":
            what = {"power": "a power without a unit name", "super": "a power without a unit name",
                    "int": f"the number {value} inside the unit"}.get(kind, f"the character {value!r}")
            raise _grammar_error(full, field, quantity, what)
        power, k = 1, k + 1
        if k < len(tokens) and tokens[k][0] == "super":
            power, k = _SUPERSCRIPT[tokens[k][1]], k + 1
        elif k < len(tokens) and tokens[k][0] == "power":
            if k + 1 >= len(tokens) or tokens[k + 1][0] != "int":
                raise _grammar_error(full, field, quantity, f"{tokens[k][1]!r} must be followed by a whole number")
            power, k = int(tokens[k + 1][1][:8]), k + 2
            if power == 0 or abs(power) > MAX_UNIT_POWER:
                raise _grammar_error(full, field, quantity,
                                     f"the power {tokens[k - 1][1]} of {value!r} is not one of ±1 … ±{MAX_UNIT_POWER}")
        try:
            named = ureg.Unit(value)
        except Exception:  # pint: UndefinedUnitError and friends
            raise _grammar_error(full, field, quantity, f"unknown unit {value!r}") from None
        unit = unit * named ** (sign * power)
        sign, expect_factor = 1, False
    if expect_factor and tokens:
        raise _grammar_error(full, field, quantity, "it ends with an operator")
    return unit


def _parse(text: str, field: str, quantity: str, shown: str | None = None) -> pint.Quantity:
    """A number with an optional unit, read by the grammar above (never by pint's parser).

    ``shown`` is the text named in messages (default ``text``).
    """
    shown = text if shown is None else shown
    if len(text) > MAX_UNIT_CHARS:
        raise UnitError(f"{field}: {text[:40]!r}… is too long for a {quantity} "
                        f"(at most {MAX_UNIT_CHARS} characters).", field, quantity, text)
    value, rest = _read_number(text.strip(), field, quantity)
    if value is None:
        special = re.match(r"[+-]?(nan|inf)", text.strip(), re.IGNORECASE)
        raise _grammar_error(shown, field, quantity, "NaN and infinity are not accepted" if special
                             else "it does not start with a number")
    if rest.startswith(("**", "^")):
        raise _grammar_error(shown, field, quantity, f"{rest[:2].strip('0123456789')!r} after the number: powers "
                                                     "of numbers are not evaluated; write e.g. 1e9")
    if rest and not rest[0].isspace() and rest[0] not in "/*" and not rest[0].isalpha():
        raise _grammar_error(shown, field, quantity, f"unexpected {rest[0]!r} after the number"
                             + ("; write a decimal point" if rest[0] == "," else ""))
    return registry().Quantity(value, _read_unit(rest, shown, field, quantity))


def _example(quantity: str) -> str:
    return {"speed": "1500 U/min", "torque": "143.24 kp*cm", "power": "3 PS"}[quantity]


def _check_quantity(quantity: str) -> None:
    if quantity not in CORE_UNITS:
        raise UnitError(
            f"unknown quantity {quantity!r}; expected one of {', '.join(CORE_UNITS)}.",
            quantity=quantity, given=quantity,
        )


def _to_core_quantity(value: pint.Quantity, quantity: str, field: str, given: object) -> float:
    ureg = registry()
    core = ureg.Quantity(1.0, CORE_UNITS[quantity])
    if quantity == "torque" and value.dimensionality == ureg.Quantity(1.0, "kg*m").dimensionality:
        value = value * ureg.Quantity(G0, "N/kg")  # cm kg in the sources' sense: kp·cm
    if value.dimensionality != core.dimensionality:
        raise UnitError(
            f"{field}: {given!r} is not a {quantity}: its unit has the dimension "
            f"{value.dimensionality or 'dimensionless'}, expected that of {CORE_UNITS[quantity]} "
            f"(units: {QUANTITIES[quantity]}).",
            field, quantity, given,
        )
    result = float(value.to(CORE_UNITS[quantity]).magnitude)
    if not math.isfinite(result):
        raise UnitError(f"{field}: {given!r} is not a finite {quantity}.", field, quantity, given)
    return result


@lru_cache(maxsize=256)
def unit_factor(unit: str, quantity: str, field: str = "units") -> float:
    """Core units per one ``unit``: ``value_core = value_in_unit · factor``.

    Parameters
    ----------
    unit : str
        A unit such as ``"U/min"``, ``"kp*cm"``, ``"PS"``.
    quantity : {"speed", "torque", "power"}
    field : str
        Where the unit was given (for the message).

    Raises
    ------
    UnitError
        The unit is unknown or has the wrong dimension.

    Examples
    --------
    >>> unit_factor("PS", "power")
    735.49875
    >>> round(unit_factor("rad/s", "speed"), 6)  # 30/π, never through Hz
    9.549297
    """
    _check_quantity(quantity)
    if not isinstance(unit, str) or not unit.strip():
        raise UnitError(
            f"{field}: the {quantity} unit must be a non-empty string such as "
            f"{CORE_UNITS[quantity]!r}, got {unit!r}.", field, quantity, unit,
        )
    text = unit.strip()
    if text[0].isdigit() and not re.match(r"1\s*/", text) or text[0] in "+-.":
        raise UnitError(
            f"{field}: {unit!r} is not a unit: give a unit name without a number, such as "
            f"{CORE_UNITS[quantity]!r} (units: {QUANTITIES[quantity]}).", field, quantity, unit,
        )
    known = _KNOWN_FACTORS[quantity].get(text)
    if known is not None:
        return known
    factor = _to_core_quantity(_parse(f"1 {text}", field, quantity, unit), quantity, field, unit)
    low, high = UNIT_FACTOR_RANGE
    if not low <= abs(factor) <= high:
        raise UnitError(
            f"{field}: {unit!r} is {factor:.3g} {CORE_UNITS[quantity]}, outside the accepted "
            f"{low:g} … {high:g} {CORE_UNITS[quantity]}: a degenerate unit (see docs/limits.md).",
            field, quantity, unit,
        )
    return factor


def to_core(value: object, quantity: str, *, field: str = "value", default_unit: str | None = None) -> float:
    """Convert a value with or without unit into the core unit of ``quantity``.

    Parameters
    ----------
    value : float, int, str or pint.Quantity
        A number (read in ``default_unit``, or the core unit if that is None),
        a string with number and unit, e.g. ``"3 PS"``, ``"1500 U/min"``, or a
        pint quantity of any registry (its unit names are read in ours, so
        ``rpm`` stays 1/min; pint's default registry has already read ``PS`` as
        petasiemens and ``U`` as an enzyme unit, which is an error that says so).
    quantity : {"speed", "torque", "power"}
    field : str
        Where the value was given; named in error messages.
    default_unit : str, optional
        Unit of plain numbers.

    Returns
    -------
    float
        The value in 1/min, N·m or W.

    Raises
    ------
    UnitError
        Unreadable value, unknown unit, wrong dimension ("3 m" for a power).

    Examples
    --------
    >>> to_core(2, "power", default_unit="kW")
    2000.0
    >>> to_core("3 m", "power", field="powers.II")
    Traceback (most recent call last):
    ...
    epicyclic.units.UnitError: powers.II: '3 m' is not a power: its unit has the dimension [length], expected that of W (units: W, kW, PS, hp).
    """
    _check_quantity(quantity)
    if isinstance(value, bool):
        raise UnitError(f"{field}: expected a {quantity}, got the boolean {value!r}.", field, quantity, value)
    if isinstance(value, numbers.Real):  # also numpy scalars (np.int64, np.float32) and fractions
        try:
            number = float(value)
        except OverflowError:  # an integer beyond double precision
            number = math.inf
        if not math.isfinite(number):
            raise UnitError(f"{field}: expected a finite {quantity}, got {value!r}.", field, quantity, value)
        if default_unit is None:
            return number
        core = number * unit_factor(default_unit, quantity, field)
        if not math.isfinite(core):
            raise UnitError(f"{field}: {value!r} {default_unit} is not a finite {quantity} in "
                            f"{CORE_UNITS[quantity]} (it overflows a double).", field, quantity, value)
        return core
    if _is_quantity(value):
        return _from_quantity(value, quantity, field)
    if not isinstance(value, str):
        raise UnitError(
            f"{field}: expected a number or a string with unit such as {_example(quantity)!r}, "
            f"got {type(value).__name__} {value!r}.", field, quantity, value,
        )
    text = value.strip()
    if not text:
        raise UnitError(f"{field}: expected a {quantity}, got an empty string.", field, quantity, value)
    known = _known(text, quantity, field)
    if known is not None:
        value_known, with_unit = known
        return value_known if with_unit else to_core(value_known, quantity, field=field, default_unit=default_unit)
    parsed = _parse(text, field, quantity)
    if parsed.dimensionless and parsed.units == registry().dimensionless:
        # a bare number in a string: same as a plain number
        return to_core(float(parsed.magnitude), quantity, field=field, default_unit=default_unit)
    return _to_core_quantity(parsed, quantity, field, value)


def _is_quantity(value: object) -> bool:
    """Whether ``value`` is a pint quantity (of any registry: the user's, pint's application registry)."""
    return all(hasattr(value, name) for name in ("to_tuple", "magnitude", "units", "dimensionality"))


#: Units that pint's default registry makes of the sources' names (the name is lost once pint has read it).
_PINT_MISREADINGS = {
    "petasiemens": ("PS", "give the power as a string ('10 PS') or in 'metric_horsepower'"),
    "enzyme_unit": ("U", "give the speed as a string ('1500 U/min') or in 'rpm'"),
}


def _from_quantity(value: object, quantity: str, field: str) -> float:
    """A pint quantity of any registry in core units, read unit name by unit name in ours.

    The names are looked up in this module's registry, so a user's ``1500 rpm`` is 1500 1/min
    (not 1500·2π as pint's default turns revolutions into radians) and ``3 PS`` is metric horsepower.
    """
    magnitude, units = value.to_tuple()  # type: ignore[attr-defined]
    for name, _ in units:
        if name in _PINT_MISREADINGS:
            written, fix = _PINT_MISREADINGS[name]
            raise UnitError(f"{field}: {value!r} — pint's default registry reads {written!r} as {name}; {fix}.",
                            field, quantity, value)
    if isinstance(magnitude, bool) or not isinstance(magnitude, numbers.Real):
        raise UnitError(f"{field}: expected one {quantity}, got the quantity {value!r} "
                        f"(its magnitude is {type(magnitude).__name__}, not a number).", field, quantity, value)
    ureg = registry()
    unit = ureg.Unit("")
    for name, power in units:
        try:
            unit = unit * ureg.Unit(name) ** power
        except Exception:  # pint: UndefinedUnitError and friends
            raise UnitError(f"{field}: the unit {name!r} of {value!r} is not known here; give the {quantity} "
                            f"as a string such as {_example(quantity)!r} (units: {QUANTITIES[quantity]}).",
                            field, quantity, value) from None
    return _to_core_quantity(ureg.Quantity(float(magnitude), unit), quantity, field, value)


def from_core(value: float, quantity: str, unit: str) -> float:
    """Convert ``value`` from the core unit of ``quantity`` into ``unit``.

    Parameters
    ----------
    value : float
        The value in the core unit (1/min, N·m, W).
    quantity : {"speed", "torque", "power"}
        What it is.
    unit : str
        The unit wanted (``"U/min"``, ``"kp*cm"``, ``"PS"``, ``"rad/s"``, ...).

    Returns
    -------
    float

    Raises
    ------
    UnitError
        A unit that is unknown or does not fit ``quantity``.

    Examples
    --------
    >>> round(from_core(14.047045, "torque", "kp*cm"), 2)
    143.24
    """
    return value / unit_factor(unit, quantity)


@dataclass(frozen=True)
class Units:
    """The units a user chose for speeds, torques and powers (defaults: core units).

    Parameters
    ----------
    speed, torque, power : str
        Unit strings; validated on construction.

    Examples
    --------
    >>> u = Units(speed="U/min", torque="kp*cm", power="PS")
    >>> round(u.power_from_core(2206.49625), 6)
    3.0
    """

    speed: str = CORE_UNITS["speed"]
    torque: str = CORE_UNITS["torque"]
    power: str = CORE_UNITS["power"]

    def __post_init__(self) -> None:
        for quantity in CORE_UNITS:
            unit_factor(getattr(self, quantity), quantity, f"units.{quantity}")

    def of(self, quantity: str) -> str:
        """The unit chosen for ``quantity``."""
        _check_quantity(quantity)
        return getattr(self, quantity)

    def convert(self, value: float | None, quantity: str) -> float | None:
        """A core value in the chosen unit (None stays None).

        Parameters
        ----------
        value : float or None
            The value in the core unit (1/min, N·m, W).
        quantity : {"speed", "torque", "power"}
            What it is.

        Returns
        -------
        float or None
        """
        return None if value is None else from_core(value, quantity, self.of(quantity))

    def speed_from_core(self, value: float) -> float:
        """A speed ``value`` in 1/min converted into :attr:`speed` (float)."""
        return from_core(value, "speed", self.speed)

    def torque_from_core(self, value: float) -> float:
        """A torque ``value`` in N·m converted into :attr:`torque` (float).

        >>> round(Units(torque="kp*cm").torque_from_core(14.047045), 2)   # Brandenberger's input torque
        143.24
        """
        return from_core(value, "torque", self.torque)

    def power_from_core(self, value: float) -> float:
        """A power ``value`` in W converted into :attr:`power` (float)."""
        return from_core(value, "power", self.power)

    def to_dict(self) -> dict[str, str]:
        """The unit of each quantity: ``{"speed": ..., "torque": ..., "power": ...}``."""
        return {"speed": self.speed, "torque": self.torque, "power": self.power}


def as_units(value: object, field: str = "units") -> Units:
    """``value`` as :class:`Units`: a Units, None (core units) or a mapping such as ``{"power": "PS"}``.

    Parameters
    ----------
    value : Units, mapping or None
        Units, or a mapping quantity → unit (quantities not named keep the core unit).
    field : str, default "units"
        What the value was given as, the start of a message.

    Returns
    -------
    Units

    Raises
    ------
    UnitError
        Anything else (a bare unit string cannot say which quantity it is for), or a unit that does
        not fit its quantity.

    Examples
    --------
    >>> as_units({"speed": "U/min", "power": "PS"})
    Units(speed='U/min', torque='N*m', power='PS')
    """
    if value is None:
        return Units()
    if isinstance(value, Units):
        return value
    if isinstance(value, Mapping):
        unknown = [k for k in value if k not in CORE_UNITS]
        if unknown:
            raise UnitError(f"{field}: unknown quantity {unknown[0]!r:.40}; give units for "
                            f"{', '.join(CORE_UNITS)}, e.g. {{'power': 'PS'}}.", field, "", value)
        return Units(**{k: str(v) for k, v in value.items()})
    raise UnitError(f"{field}: expected Units(speed=..., torque=..., power=...) or a mapping such as "
                    f"{{'speed': 'U/min', 'torque': 'kp*cm', 'power': 'PS'}}, got {type(value).__name__} "
                    f"{value!r:.40}.", field, "", value)


def to_core_array(values: object, quantity: str, *, field: str = "values") -> np.ndarray:
    """Convert a sequence of values, or one pint quantity holding an array, into core units.

    Each value may be a number (core unit), a string with a unit or a pint quantity; a pint
    quantity whose magnitude is an array is converted by the factor of its unit (read in this
    module's registry, as :func:`to_core` does), never stripped of it.  The shape is kept (a
    single value gives a 0-d array); an error names the flat index of the bad value.

    Parameters
    ----------
    values : sequence, array or pint.Quantity
        The values; a single value is one value.
    quantity : {"speed", "torque", "power"}
    field : str
        Named in error messages, with the index of a bad value.

    Returns
    -------
    ndarray of float, the shape of ``values``

    Examples
    --------
    >>> to_core_array(["1500 U/min", 3000, "50 1/s"], "speed", field="speeds").tolist()
    [1500.0, 3000.0, 3000.0]
    """
    import numpy as np

    factor = 1.0
    if _is_quantity(values) and not isinstance(getattr(values, "magnitude", None), numbers.Real):
        factor = to_core(1.0 * values.units, quantity, field=field)  # type: ignore[attr-defined]
        values = values.magnitude  # type: ignore[attr-defined]
    try:
        try:
            array = np.asarray(values)
        except (TypeError, ValueError):  # pint quantities or strings beside numbers: one by one below
            array = np.asarray(values, dtype=object)
        if array.dtype.kind not in "iuf":  # strings, quantities, booleans: one by one below
            array = np.asarray(values, dtype=object)
    except (TypeError, ValueError):  # ragged nesting
        raise UnitError(f"{field}: expected a sequence of {quantity}s, got {type(values).__name__}.",
                        field, quantity, values) from None
    shape, array = array.shape, array.ravel()
    if array.dtype.kind in "iuf":  # plain numbers (in the core unit, or in the quantity's unit): at once
        core = array.astype(float) * factor
        bad = np.flatnonzero(~np.isfinite(core))
        if bad.size:
            k = int(bad[0])
            raise UnitError(f"{field}[{k}]: expected a finite {quantity}, got {float(array[k])!r}.", field, quantity,
                            array[k])
        return core.reshape(shape)
    return np.array([to_core(v, quantity, field=f"{field}[{k}]") for k, v in enumerate(array.tolist())],
                    dtype=float).reshape(shape)
