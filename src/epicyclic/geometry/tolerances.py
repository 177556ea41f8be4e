"""Centre-distance tolerances: ISO 286-1 standard tolerance grades and the js fields of DIN 3964.

DIN 3964 gives the centre-distance allowances of a gearbox housing as ISO 286
fields, symmetric ones (``js5`` … ``js11``) being the usual choice: the
allowance is ± IT/2 of the nominal centre distance's size range.  The IT values
below are those of ISO 286-1:2010, Table 1 (µm, grades IT5 … IT11, nominal sizes
up to 3150 mm).

References
----------
ISO 286-1:2010, Table 1 (standard tolerance grades IT1 … IT18); DIN 3964:1980
(Achsabstandsabmaße und Achslagetoleranzen von Gehäusen für Stirnradgetriebe:
js fields by gear quality).
"""

from __future__ import annotations

import math
import re
from bisect import bisect_left

from .errors import GeometryError

__all__ = ["IT_GRADES", "standard_tolerance", "center_distance_allowance", "parse_center_distance_tolerance"]

#: Upper limits of the nominal size ranges, mm (ISO 286-1, Table 1; the first range is 0 … 3 mm).
_SIZES = (3, 6, 10, 18, 30, 50, 80, 120, 180, 250, 315, 400, 500, 630, 800, 1000, 1250, 1600, 2000, 2500, 3150)

#: IT5 … IT11 in µm per size range (ISO 286-1:2010, Table 1).
IT_GRADES: dict[int, tuple[int, ...]] = {
    5: (4, 5, 6, 8, 9, 11, 13, 15, 18, 20, 23, 25, 27, 32, 36, 40, 47, 55, 65, 78, 96),
    6: (6, 8, 9, 11, 13, 16, 19, 22, 25, 29, 32, 36, 40, 44, 50, 56, 66, 78, 92, 110, 135),
    7: (10, 12, 15, 18, 21, 25, 30, 35, 40, 46, 52, 57, 63, 70, 80, 90, 105, 125, 150, 175, 210),
    8: (14, 18, 22, 27, 33, 39, 46, 54, 63, 72, 81, 89, 97, 110, 125, 140, 165, 195, 230, 280, 330),
    9: (25, 30, 36, 43, 52, 62, 74, 87, 100, 115, 130, 140, 155, 175, 200, 230, 260, 310, 370, 440, 540),
    10: (40, 48, 58, 70, 84, 100, 120, 140, 160, 185, 210, 230, 250, 280, 320, 360, 420, 500, 600, 700, 860),
    11: (60, 75, 90, 110, 130, 160, 190, 220, 250, 290, 320, 360, 400, 440, 500, 560, 660, 780, 920, 1100, 1350),
}


def standard_tolerance(grade: int, size: float) -> float:
    """The ISO 286-1 standard tolerance IT``grade`` of a nominal size, mm.

    Parameters
    ----------
    grade : int
        5 … 11.
    size : float
        Nominal size (here a centre distance), mm, 0 < size ≤ 3150.

    Returns
    -------
    float
        IT in mm.

    Raises
    ------
    GeometryError
        A grade outside 5 … 11 or a size outside (0, 3150] mm.

    Examples
    --------
    ISO 286-1 Table 1: IT7 of 50 … 80 mm is 30 µm:

    >>> standard_tolerance(7, 56.8)
    0.03

    References
    ----------
    ISO 286-1:2010, Table 1.
    """
    if grade not in IT_GRADES:
        raise GeometryError(f"standard_tolerance: grade must be one of {min(IT_GRADES)} … {max(IT_GRADES)} "
                            f"(IT5 … IT11, the fields DIN 3964 uses), got {grade!r}.")
    if not (isinstance(size, (int, float)) and math.isfinite(size) and 0 < size <= _SIZES[-1]):
        raise GeometryError(f"standard_tolerance: the nominal size must lie in (0, {_SIZES[-1]}] mm, got {size!r}.")
    return IT_GRADES[grade][bisect_left(_SIZES, size)] / 1000.0


def center_distance_allowance(field: str, center_distance: float) -> float:
    """The symmetric allowance ± A_a of a centre distance in an ISO 286 js field (DIN 3964), mm.

    Parameters
    ----------
    field : str
        ``"js5"`` … ``"js11"``.
    center_distance : float
        Nominal centre distance, mm.

    Returns
    -------
    float
        A_a = IT/2, mm.

    Examples
    --------
    >>> center_distance_allowance("js7", 56.8)
    0.015

    References
    ----------
    DIN 3964:1980 (centre-distance allowances as js fields); ISO 286-1:2010, Table 1.
    """
    return standard_tolerance(_grade(field), center_distance) / 2.0


def _grade(field: str) -> int:
    match = re.fullmatch(r"\s*js\s*(\d{1,2})\s*", field, re.IGNORECASE) if isinstance(field, str) else None
    if match is None or int(match.group(1)) not in IT_GRADES:
        raise GeometryError(f"center-distance tolerance: expected an ISO 286 js field js5 … js11 (DIN 3964) or a "
                            f"number of mm, got {field!r}.")
    return int(match.group(1))


def parse_center_distance_tolerance(value: object) -> float | str:
    """A centre-distance tolerance as given: a number of mm (> 0) or a js field (``"js7"``); checked.

    Parameters
    ----------
    value : float or str
        ± mm, or ``"js5"`` … ``"js11"``.

    Returns
    -------
    float or str
        The number as float, or the field in lower case.

    Raises
    ------
    GeometryError
        Anything else.

    Examples
    --------
    >>> parse_center_distance_tolerance("JS7"), parse_center_distance_tolerance(0.01)
    ('js7', 0.01)

    References
    ----------
    DIN 3964:1980; ISO 286-1:2010.
    """
    if isinstance(value, str):
        return f"js{_grade(value)}"
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0:
        raise GeometryError(f"center-distance tolerance: expected a positive number of mm or a js field such as "
                            f"'js7', got {value!r}.")
    return float(value)
