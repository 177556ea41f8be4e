"""Exception taxonomy of epicyclic.

Every error the toolkit raises on bad input derives from :class:`EpicyclicError`
and from a built-in exception (``ValueError`` or ``TypeError``), so callers may
catch either.  Messages name the element or field, what was expected, what was
given, and how to fix it.

Examples
--------
>>> from epicyclic.errors import EfficiencyError, EpicyclicError
>>> issubclass(EfficiencyError, ValueError) and issubclass(EfficiencyError, EpicyclicError)
True
"""

from __future__ import annotations

from collections.abc import Sequence

__all__ = [
    "EpicyclicError",
    "ModelError",
    "ToothCountError",
    "EfficiencyError",
    "TopologyError",
    "UnknownShaftError",
    "OperatingPointError",
    "UnderdeterminedError",
    "ContradictionError",
    "NumericalError",
    "NearSingularError",
    "NonFiniteResultError",
    "closest",
]


class EpicyclicError(Exception):
    """Base class of every error raised by epicyclic on bad input."""


class ModelError(EpicyclicError, ValueError):
    """An element or train description is invalid (raised at construction)."""


class ToothCountError(ModelError):
    """Tooth counts that are not positive integers or cannot mesh."""


class EfficiencyError(ModelError):
    """An efficiency outside the interval (0, 1]."""


class TopologyError(ModelError):
    """The way elements are joined is impossible (e.g. a brake on the housing)."""


class UnknownShaftError(EpicyclicError, ValueError):
    """A shaft name that the train does not have."""

    def __init__(self, name: str, known: Sequence[str], where: str = "operating point"):
        self.name = name
        self.known = tuple(known)
        close = closest(name, self.known)
        hint = f" Did you mean {close!r}?" if close else ""
        what = "unknown shaft" if isinstance(name, str) else f"a shaft is named by a string, got {type(name).__name__}"
        super().__init__(
            (f"{where}: " if where else "") + f"{what} {name!r:.70}; the train has shafts "
            f"{', '.join(repr(k) for k in self.known)}.{hint}"
        )


def closest(name: object, known: Sequence[str]) -> str | None:
    """The name in ``known`` that ``name`` most likely misspells (another case, a typo), or None.

    A name that differs only in case wins; otherwise the closest by
    :func:`difflib.get_close_matches` with a similarity of at least 0.6.

    Parameters
    ----------
    name : object
        What the user gave (anything that is not a string has no close name).
    known : sequence of str
        The names that exist.

    Returns
    -------
    str or None

    Examples
    --------
    >>> closest("sunn", ["sun", "ring", "carrier"]), closest("Ring", ["sun", "ring"]), closest("x", ["sun"])
    ('sun', 'ring', None)
    """
    if not isinstance(name, str):
        return None
    same = [k for k in known if k.lower() == name.lower()]
    if same:
        return same[0]
    import difflib

    lowered = {k.lower(): k for k in known}
    close = difflib.get_close_matches(name.lower(), list(lowered), n=1, cutoff=0.6)
    return lowered[close[0]] if close else None


class OperatingPointError(EpicyclicError, ValueError):
    """The operating point does not fit the train.

    Attributes
    ----------
    group : str
        The part of the operating point at fault — ``"speeds"``, ``"torques"``,
        ``"powers"``, ``"drives"``, ``"loads"`` — or ``""``; the file reader
        turns it into the key (``[operating_point], key 'powers.sun'``).
    shafts : tuple of str
        The shafts concerned.
    """

    def __init__(self, message: str = "", *, group: str = "", shafts: Sequence[str] = ()):
        self.group = group
        self.shafts = tuple(shafts)
        super().__init__(message)


class UnderdeterminedError(OperatingPointError):
    """Too little is given: some speeds or torques remain free.

    Attributes
    ----------
    free : tuple of str
        The shafts whose speed (or torque) is still free.
    quantity : str
        ``"speed"`` or ``"torque"``.
    """

    def __init__(self, message: str, free: Sequence[str], quantity: str):
        self.free = tuple(free)
        self.quantity = quantity
        super().__init__(message)


class ContradictionError(OperatingPointError):
    """The given values contradict each other or the train's constraints.

    Attributes
    ----------
    conflicting : tuple of str
        The shafts whose given values are in conflict.
    quantity : str
        ``"speed"`` or ``"torque"``.
    """

    def __init__(self, message: str, conflicting: Sequence[str], quantity: str):
        self.conflicting = tuple(conflicting)
        self.quantity = quantity
        super().__init__(message)


class NumericalError(EpicyclicError, ValueError):
    """The train and operating point are valid, but floating point cannot give a trustworthy result.

    Attributes
    ----------
    quantity : str
        What could not be computed (``"speed"``, ``"torque"``, ``"power"``, ...).
    """

    def __init__(self, message: str, quantity: str):
        self.quantity = quantity
        super().__init__(message)


class NearSingularError(NumericalError):
    """The train's equations are too close to singular: round-off would decide the result.

    Attributes
    ----------
    distance : float
        Relative distance of the (equilibrated) equations from singular: the
        smallest singular value divided by the largest.
    shafts : tuple of str
        The shafts whose speed (or torque) the nearly singular equations leave open.
    elements : tuple of str
        The elements whose ratios nearly cancel.
    """

    def __init__(self, message: str, quantity: str, distance: float, shafts: Sequence[str] = (),
                 elements: Sequence[str] = ()):
        self.distance = distance
        self.shafts = tuple(shafts)
        self.elements = tuple(elements)
        super().__init__(message, quantity)


class NonFiniteResultError(NumericalError):
    """A result overflows the floating-point range (or an input makes it infinite).

    Attributes
    ----------
    where : str
        The shaft or element whose value overflows (empty where ``quantity`` says it all,
        e.g. a path into a result such as ``"shafts.sun.power"``).
    """

    def __init__(self, message: str, quantity: str = "", where: str = ""):
        self.where = where
        super().__init__(message, quantity)
