"""Errors and warnings of the tooth load capacity rating (ISO 6336).

:class:`RatingError` is raised for bad input: a missing material, roughness or
lubricant value (the message names the key and the default it would take), a
value the standard does not define.  :class:`RatingWarning` is issued for a
value outside the standard's range of validity; its message names the clause,
and the calculation goes on with the value clamped to that range (never
silently extrapolated).

References
----------
ISO 6336-1:2019, clause 4 (scope and validity of the methods).
"""

from __future__ import annotations

import warnings

from ..errors import ModelError

__all__ = ["RatingError", "RatingWarning", "warn_validity"]


class RatingError(ModelError):
    """Bad input to a tooth load capacity rating (also a ``ValueError``)."""


class RatingWarning(UserWarning):
    """A value outside the range of validity of an ISO 6336 clause (the clause is named)."""


def warn_validity(message: str, clause: str) -> None:
    """Issue a :class:`RatingWarning` ``"<clause>: <message>"``.

    Parameters
    ----------
    message : str
        What is out of range and what the calculation does instead (e.g. clamps).
    clause : str
        The clause whose range is left, e.g. ``"ISO 6336-3:2019, 7.2.2"``.

    References
    ----------
    ISO 6336-1:2019, clause 4.
    """
    warnings.warn(f"{clause}: {message}", RatingWarning, stacklevel=3)
