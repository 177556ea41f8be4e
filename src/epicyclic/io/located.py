"""Errors located in the input file: every message names the file and the key.

The model, the solver and the transmission layer know nothing of files; their
errors carry structured fields instead (``free``, ``conflicting``,
``quantity``, ``gear``, ``shafts``, ``group``).  At the boundary — the file
reader, :meth:`TrainFile.solve`, the command line — this module turns them
into the table and key of the file they came from, keeping the error's class
and fields (so ``except UnderdeterminedError`` still works) and adding
``source`` and ``where``.  A result that is not finite becomes a
:class:`NonFiniteResultError` naming the quantity.

Examples
--------
>>> from epicyclic.errors import UnderdeterminedError
>>> exc = UnderdeterminedError("the speed of shaft(s) 'ring' is still free.", ["ring"], "speed")
>>> print(locate_error(exc, "t.toml"))
t.toml: [operating_point], key 'speeds': the speed of shaft(s) 'ring' is still free.
>>> check_finite({"shafts": {"in": {"power": float("inf")}}}, "t.toml")
Traceback (most recent call last):
...
epicyclic.errors.NonFiniteResultError: t.toml: result 'shafts.in.power' is inf, not a finite number: the numbers overflow double precision (about 1.8e308). Give smaller speeds, torques or powers in [operating_point], or a train further from singular (see docs/limits.md).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from ..errors import EpicyclicError, NonFiniteResultError

__all__ = ["NonFiniteResultError", "located", "locate_error", "operating_point_where", "check_finite"]


def located(exc: EpicyclicError, source: str, where: str = "", owner: str = "") -> EpicyclicError:
    """``exc`` with its message prefixed by ``source`` and ``where``; same class and fields.

    An error that is already located (has a ``source``) is returned as it is,
    so that a message never names the file or the element twice.  ``owner``
    (e.g. ``"planetary set 'P'"``) is dropped from the front of the message
    when ``where`` already names the element.
    """
    if getattr(exc, "source", None):
        return exc
    message = str(exc)
    if owner and message.startswith(owner + ": "):
        message = message[len(owner) + 2:]
    new = exc.__class__.__new__(exc.__class__)
    new.__dict__.update(exc.__dict__)
    if message.startswith(f"{source}: "):  # the file is named already (e.g. by Transmission.from_file)
        message = message[len(source) + 2:]
    new.args = (f"{source}: {where}: {message}" if where else f"{source}: {message}",)
    new.source, new.where = source, where
    new.__cause__, new.__suppress_context__ = None, True
    return new


def _keys(group: str, shafts: Any) -> str:
    names = [s for s in shafts if isinstance(s, str)]
    if not names:
        return f"key {group!r}"
    return ("key " if len(names) == 1 else "keys ") + ", ".join(repr(f"{group}.{s}") for s in names)


def operating_point_where(exc: BaseException, operating_point: Any = None) -> str:
    """The ``[operating_point]`` key an operating-point error is about, from its structured fields.

    Parameters
    ----------
    exc : EpicyclicError
        An error with ``quantity`` and ``free``/``conflicting``, or ``group`` and ``shafts``.
    operating_point : OperatingPoint, optional
        Tells whether a conflicting torque was given as a torque or a power.
    """
    quantity = getattr(exc, "quantity", "")
    group = getattr(exc, "group", "")
    if group:
        return f"[operating_point], {_keys(group, getattr(exc, 'shafts', ()))}"
    conflicting = getattr(exc, "conflicting", None)
    if quantity == "speed":
        return f"[operating_point], {_keys('speeds', conflicting or ())}" if conflicting else \
            "[operating_point], key 'speeds'"
    if quantity == "torque":
        if conflicting:
            powers = getattr(operating_point, "powers", {})
            keys = [f"powers.{s}" if s in powers else f"torques.{s}" for s in conflicting]
            return "[operating_point], " + ("key " if len(keys) == 1 else "keys ") + ", ".join(map(repr, keys))
        return "[operating_point], key 'torques' or 'powers'"
    return "[operating_point]"


def locate_error(exc: EpicyclicError, source: str, operating_point: Any = None, default: str = "") -> EpicyclicError:
    """Locate an error raised *after* the file was read (solver, transmission) in the file.

    Transmission errors with a ``gear`` point at ``[transmission], key
    'schedule.<gear>'``; operating-point errors at the keys of
    :func:`operating_point_where`; anything else at ``default`` (e.g.
    ``"[operating_point]"`` for an error of the solver).

    Parameters
    ----------
    exc : EpicyclicError
        The error raised by the solver or the transmission code.
    source : str
        The input file.
    operating_point : OperatingPoint, optional
        The file's operating point, to find the keys of the shafts that the error names.
    default : str, default ""
        Where an error of any other kind points (a table, e.g. ``"[operating_point]"``).

    Returns
    -------
    EpicyclicError
        Of the same class and fields, its message prefixed by the file and key
        (``exc`` itself if it already names a file).
    """
    if getattr(exc, "source", None):
        return exc
    from ..errors import OperatingPointError

    gear = getattr(exc, "gear", None)
    if isinstance(gear, str):
        where = f"[transmission], key {f'schedule.{gear}'!r}"
    elif isinstance(exc, OperatingPointError) or hasattr(exc, "free") or hasattr(exc, "conflicting"):
        where = operating_point_where(exc, operating_point)
    elif type(exc).__name__ in ("ShiftScheduleError", "GearFreedomError"):
        where = "[transmission]"
    else:
        where = default
    return located(exc, source, where)


def check_finite(data: Any, source: str, what: str = "") -> None:
    """Raise :class:`NonFiniteResultError` at the first infinite or NaN number in ``data``.

    Parameters
    ----------
    data : dict or list
        A result's ``to_dict()`` (nested dicts and lists).
    source : str
        The input file, the start of the message.
    what : str, default ""
        Prefix of the path in the message (e.g. ``"ideal"``).

    Raises
    ------
    NonFiniteResultError
        A number is infinite or NaN; the message gives its path (``"shafts.out.power"``)
        and how to stay within double precision; the error's ``field`` is the path.

    Examples
    --------
    >>> check_finite({"shafts": {"out": {"power": 1.0}}}, "t.toml")
    >>> check_finite({"shafts": {"out": {"power": float("inf")}}}, "t.toml")
    Traceback (most recent call last):
    ...
    epicyclic.errors.NonFiniteResultError: t.toml: result 'shafts.out.power' is inf, not a finite number: ...
    """
    stack: list[tuple[Any, str]] = [(data, what)]
    while stack:
        value, path = stack.pop()
        if isinstance(value, float) and not math.isfinite(value):
            raise NonFiniteResultError(
                f"{source}: result {path!r} is {value!r}, not a finite number: the numbers overflow double "
                "precision (about 1.8e308). Give smaller speeds, torques or powers in [operating_point], or a "
                "train further from singular (see docs/limits.md).", path)
        if isinstance(value, Mapping):
            stack.extend((v, f"{path}.{k}" if path else str(k)) for k, v in reversed(list(value.items())))
        elif isinstance(value, (list, tuple)):
            stack.extend((v, f"{path}[{k}]") for k, v in reversed(list(enumerate(value))))
