"""Hardness with its scale (HB, HV, HRC) and the conversion between scales of a stated table.

Factors that take a hardness take it in one scale: Z_W of ISO 6336-2 in Brinell (HB), the
ISO 6336-5 lines in HV or HB as drawn.  A value in another scale is converted by ASTM E140,
Table 1 (non-austenitic steels: Rockwell C, Vickers HV and Brinell HBW with a carbide ball,
3000 kgf), linearly between its rows at every 5 HRC from 20 to 60 HRC:

=====  =====  =====
HRC    HV     HBW
=====  =====  =====
20     238    226
25     266    253
30     302    286
35     345    327
40     392    371
45     446    421
50     513    481
55     595    560
60     697    654
=====  =====  =====

Outside the table (below 238 HV / 226 HB, above 697 HV / 654 HB) there is no conversion: an
error names the material's key and asks for the hardness in the scale the factor needs.
ASTM E140 states the conversions are approximate; a measured value in the needed scale is better.

References
----------
ASTM E140-12b (2019), Standard Hardness Conversion Tables for Metals, Table 1 (non-austenitic
steels); ISO 18265:2013 (the same conversions for steels); ISO 6336-2:2006, clause 12 (Z_W in HB).
"""

from __future__ import annotations

import numpy as np

from .errors import RatingError

__all__ = ["SCALES", "convert_hardness"]

#: The hardness scales a material's hardness may be given in.
SCALES = ("HB", "HV", "HRC")

#: ASTM E140-12b, Table 1: (HRC, HV, HBW) at every 5 HRC.
_TABLE = np.array([
    (20, 238, 226), (25, 266, 253), (30, 302, 286), (35, 345, 327), (40, 392, 371), (45, 446, 421),
    (50, 513, 481), (55, 595, 560), (60, 697, 654)], dtype=float)
_COLUMN = {"HRC": 0, "HV": 1, "HB": 2}


def convert_hardness(value: float, scale: str, to: str, *, key: str = "hardness") -> float:
    """``value`` in ``scale`` converted to the scale ``to`` by ASTM E140, Table 1.

    Parameters
    ----------
    value : float
        The hardness.
    scale, to : {"HB", "HV", "HRC"}
        Its scale and the one wanted.
    key : str, default "hardness"
        The input key named in an error (e.g. ``"rating.materials.MySteel.hardness"``).

    Returns
    -------
    float

    Raises
    ------
    RatingError
        An unknown scale, or a value outside the table (the message names ``key``).

    References
    ----------
    ASTM E140-12b (2019), Table 1 (linear between its rows).

    Examples
    --------
    >>> convert_hardness(392, "HV", "HB"), convert_hardness(45, "HRC", "HV")
    (371.0, 446.0)
    >>> round(convert_hardness(300, "HV", "HB"), 1)
    284.2
    """
    for name in (scale, to):
        if name not in SCALES:
            raise RatingError(f"{key}: unknown hardness scale {name!r}; expected one of {', '.join(SCALES)}.")
    if scale == to:
        return float(value)
    source, target = _TABLE[:, _COLUMN[scale]], _TABLE[:, _COLUMN[to]]
    if not source[0] <= value <= source[-1]:
        raise RatingError(f"{key}: {value:g} {scale} lies outside the conversion table of ASTM E140 (Table 1: "
                          f"{source[0]:g} ... {source[-1]:g} {scale}); give the hardness in {to} "
                          f"(hardness_scale = {to!r}).")
    return float(np.interp(value, source, target))
