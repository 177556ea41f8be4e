"""Command-line options that carry a quantity: ``--mass "1.8 t"``, ``--wheel-radius "310 mm"``.

Every quantity option takes a unit, as the files do; a plain number is read in the option's stated unit.
A bad value is an :class:`OptionError`, whose message names the option (never the input file).

>>> quantity_option("1.8 t", "--mass", "mass")
1800.0
>>> quantity_option("310 mm", "--wheel-radius", "length")
0.31
>>> quantity_option("1800", "--mass", "mass")
1800.0
>>> quantity_option("1800 parsec", "--mass", "mass")
Traceback (most recent call last):
...
epicyclic.cli.options.OptionError: --mass: unknown mass unit 'parsec'; write one of kg, t, lb.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterator, Mapping
from contextlib import contextmanager

from ..errors import ModelError

__all__ = ["OptionError", "quantity_option", "naming_options"]

_NUMBER = re.compile(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


class OptionError(ModelError):
    """A command-line option's value is bad; the message starts with the option's name.

    Its ``source`` is the option, so the command's error handling does not locate it in the input file.
    """

    def __init__(self, option: str, message: str, *, joined: str = ": "):
        self.source = option
        super().__init__(f"{option}{joined}{message}")


def quantity_option(text: str | float | None, option: str, quantity: str) -> float | None:
    """The value of a quantity option in the core unit (kg, m, m², kg/m³, s, m/s; 1/min, N·m, W), or None.

    Parameters
    ----------
    text : str, float or None
        ``"1800"`` (the core unit), ``"1800 kg"``, ``"1.8 t"``; None: not given.
    option : str
        The option, e.g. ``"--mass"``, for messages.
    quantity : str
        ``"mass"``, ``"length"``, ``"area"``, ``"density"``, ``"time"``, ``"velocity"``, ``"fraction"``
        (units of :data:`epicyclic.io.csv_table.UNITS`) or ``"speed"``, ``"torque"``, ``"power"``.

    Returns
    -------
    float or None

    Raises
    ------
    OptionError
        Not a number, not finite, or a unit that is not one of the quantity's.
    """
    if text is None:
        return None
    if quantity in ("speed", "torque", "power"):
        from ..units import UnitError, to_core

        try:
            return to_core(text, quantity, field=option)
        except UnitError as exc:
            raise OptionError(option, str(exc).removeprefix(f"{option}: ")) from None
    from ..io.csv_table import UNITS

    units = UNITS[quantity]
    core = next(iter(units))
    match = _NUMBER.match(str(text))
    if match is None:
        raise OptionError(option, f"expected a {quantity} such as '2 {core}', got {str(text)!r:.60}.")
    number, unit = float(match.group(1)), match.group(2) or core
    if unit not in units:
        raise OptionError(option, f"unknown {quantity} unit {unit!r:.40}; write one of {', '.join(units)}.")
    value = number * units[unit]
    if not math.isfinite(value):
        raise OptionError(option, f"expected a finite {quantity}, got {str(text)!r:.60}.")
    return value


@contextmanager
def naming_options(owner: str, options: Mapping[str, str]) -> Iterator[None]:
    """Re-raise an ``owner``'s ModelError about one of its fields as an OptionError naming the option.

    ``"vehicle: mass (kg) must be ..."`` with ``options = {"mass": "--mass"}`` becomes
    ``"--mass (kg) must be ..."``: the user typed an option, and the message says which.

    >>> with naming_options("gear rule", {"min_dwell": "--min-dwell"}):
    ...     raise ModelError("gear rule: min_dwell must be a finite number >= 0, got nan.")
    Traceback (most recent call last):
    ...
    epicyclic.cli.options.OptionError: --min-dwell must be a finite number >= 0, got nan.
    """
    try:
        yield
    except OptionError:
        raise
    except ModelError as exc:
        message = str(exc)
        for field, option in options.items():
            if message.startswith(f"{owner}: {field} "):
                raise OptionError(option, message.removeprefix(f"{owner}: {field} "), joined=" ") from None
        raise
