"""The edition of ISO 6336 a rating follows: ``"2006"`` or ``"2019"``.

Both editions are selectable (``rating.standard`` in a train file,
``RatingSpec(standard=...)`` in Python).  Where they differ, the factor
functions take the edition and say so in their docstring.  What this
package changes with the edition:

=======================  =====================================  =====================================
factor                   ISO 6336:2006                          ISO 6336:2019
=======================  =====================================  =====================================
Y_β (part 3, 7.3)        1 − ε_β β/120°                         (1 − ε_β β/120°) / cos³β
clause names             2006 numbering                         2019 numbering (stated per factor)
=======================  =====================================  =====================================

Method B of part 3 uses Y_F and Y_S for the load at the outer point of single
pair tooth contact in both editions; the contact ratio factor Y_ε of the 1996
edition is not part of it (it survives in the upper limit ε_γ/(ε_α Y_ε) of K_Fα,
ISO 6336-1:2006 eq. (76), which is kept for both editions here).  Everything else (K_v method B, K_Hα,
Z_H, Z_E, Z_ε, Z_B/Z_D, Z_L, Z_v, Z_R, the 30° tangent tooth form, Y_S,
Y_δrelT, Y_RrelT, Y_X and the life factors Z_NT, Y_NT) is computed the same for
both editions here.

References
----------
ISO 6336-1:2006 and ISO 6336-1:2019; ISO 6336-2:2006 and :2019; ISO 6336-3:2006
and :2019 (clause 7.3, helix angle factor).
"""

from __future__ import annotations

from .errors import RatingError

__all__ = ["DEFAULT_EDITION", "EDITIONS", "clause", "edition"]

#: The editions of ISO 6336 that can be chosen.
EDITIONS = ("2006", "2019")
#: The edition used when none is given.
DEFAULT_EDITION = "2019"


def edition(value: object) -> str:
    """The edition ``"2006"`` or ``"2019"`` from ``2006``, ``"ISO 6336:2006"``, ``"2019"``, ...

    Parameters
    ----------
    value : str or int
        The edition as a year, or the standard's name with the year.

    Returns
    -------
    str
        ``"2006"`` or ``"2019"``.

    Raises
    ------
    RatingError
        Any other value; the message lists the editions.

    References
    ----------
    ISO 6336-1:2006; ISO 6336-1:2019.

    Examples
    --------
    >>> edition("ISO 6336:2006"), edition(2019)
    ('2006', '2019')
    """
    text = str(value).strip()
    for year in EDITIONS:
        if text in (year, f"ISO 6336:{year}", f"ISO6336:{year}", f"ISO 6336-{year}"):
            return year
    raise RatingError(f"rating.standard: expected one of {', '.join(EDITIONS)} (or 'ISO 6336:2019'), got {value!r}; "
                      f"the default is {DEFAULT_EDITION!r}.")


def clause(part: int, year: str, where: str) -> str:
    """The citation ``"ISO 6336-<part>:<year>, <where>"`` that a factor carries.

    Parameters
    ----------
    part : int
        Part of ISO 6336 (1, 2, 3, 5).
    year : str
        Edition, ``"2006"`` or ``"2019"``.
    where : str
        Clause, equation or table, e.g. ``"eq. (13)"``.

    Returns
    -------
    str

    References
    ----------
    ISO 6336 parts 1, 2, 3, 5.

    Examples
    --------
    >>> clause(2, "2019", "6.1, Z_H")
    'ISO 6336-2:2019, 6.1, Z_H'
    """
    return f"ISO 6336-{part}:{year}, {where}"
