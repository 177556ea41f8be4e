"""Flank tolerances of cylindrical gears by accuracy grade: ISO 1328-1:1995 and ISO 1328-1:2013.

One module for both editions, so that the rating (K_v, K_Hα, K_Hβ from the deviations) and the
manufacturing data sheet take the same numbers.  Every tolerance is the grade-5 (class-5) value
times the step factor √2^(Q − 5) and then rounded by the edition's rule.

ISO 1328-1:1995, accuracy grades 0 … 12, formulas of clause 6 and Annex B (grade 5):

* f_pt = 0.3 (m + 0.4 √d) + 4,  F_p = 0.3 m + 1.25 √d + 7,
* F_α = 3.2 √m + 0.22 √d + 0.7,  f_fα = 2.5 √m + 0.17 √d + 0.5,  f_Hα = 2 √m + 0.14 √d + 0.5,
* F_β = 0.1 √d + 0.63 √b + 4.2,  f_fβ = f_Hβ = 0.07 √d + 0.45 √b + 3,
* F_r = 0.8 F_p = 0.24 m + 1.0 √d + 5.6 (ISO 1328-2:1997, Annex B),

evaluated at the geometric mean of the limits of the range that d, m_n and b fall in
(d: 5/20/50/125/280/560/1000/1600/2500/4000/6000/8000/10000 mm, m_n: 0.5/2/3.5/6/10/16/25/40/70 mm,
b: 4/10/20/40/80/160/250/400/650/1000 mm; a value on a limit belongs to the lower range).

ISO 1328-1:2013, flank tolerance classes 1 … 11, eqs. (5)–(12), at the gear's own d, m_n, b:

* f_pT = 0.001 d + 0.4 m_n + 5,  F_pT = 0.002 d + 0.55 √d + 0.7 m_n + 12,
* f_HαT = 0.4 m_n + 0.001 d + 4,  f_fαT = 0.55 m_n + 5,  F_αT = √(f_HαT² + f_fαT²),
* f_HβT = 0.05 √d + 0.35 √b + 4,  f_fβT = 0.07 √d + 0.45 √b + 4,  F_βT = √(f_HβT² + f_fβT²),
* F_rT = 0.9 F_pT (the totals from the unrounded parts).

Rounding (both editions): above 10 µm to the whole µm, from 5 to 10 µm to 0.5 µm, below 5 µm to
0.1 µm.

Neither edition tolerances the transverse base pitch deviation f_pb that ISO 6336-1 takes for K_v
and K_Hα; :func:`base_pitch_deviation` gives f_pb = f_pt cos α_t, the base pitch being the
transverse pitch times cos α_t (ISO/TR 10064-1:1992, base pitch deviation), as commercial rating
programs take it.

References
----------
ISO 1328-1:1995, clause 6 (tolerance formulas, step factor, rounding) and Annex B (f_fα, f_Hα, f_fβ,
f_Hβ); ISO 1328-2:1997, Annex B (F_r); ISO 1328-1:2013, 5.2 (eqs. (5)–(12), step factor 5.2.2,
rounding 5.2.3, no extrapolation beyond its scope, clause 1); ISO/TR 10064-1:1992 (f_pb).
"""

from __future__ import annotations

import math
from bisect import bisect_left
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

from .errors import GeometryError

__all__ = ["EDITIONS", "FlankTolerances", "base_pitch_deviation", "flank_tolerances", "grades",
           "round_tolerance", "step_factor"]

#: The editions of ISO 1328-1 this module knows, and their grade (class) ranges.
EDITIONS: Mapping[str, tuple[int, int]] = MappingProxyType({"1995": (0, 12), "2013": (1, 11)})

#: Range limits of ISO 1328-1:1995 (d, m_n, b in mm): the formulas take their geometric means.
_LIMITS_1995 = {
    "reference diameter": (5.0, 20.0, 50.0, 125.0, 280.0, 560.0, 1000.0, 1600.0, 2500.0, 4000.0, 6000.0, 8000.0,
                           10000.0),
    "normal module": (0.5, 2.0, 3.5, 6.0, 10.0, 16.0, 25.0, 40.0, 70.0),
    "face width": (4.0, 10.0, 20.0, 40.0, 80.0, 160.0, 250.0, 400.0, 650.0, 1000.0),
}
#: Scope of ISO 1328-1:2013 (clause 1): d, m_n, b in mm.
_SCOPE_2013 = {"reference diameter": (5.0, 15000.0), "normal module": (0.5, 70.0), "face width": (4.0, 1200.0)}

_SYMBOLS = ("f_pt", "F_p", "F_alpha", "f_falpha", "f_Halpha", "F_beta", "f_fbeta", "f_Hbeta", "F_r")


def _edition(edition: object) -> str:
    text = str(edition).removeprefix("ISO 1328-1:")
    if text not in EDITIONS:
        raise GeometryError(f"accuracy: edition must be one of {', '.join(map(repr, EDITIONS))} "
                            f"(ISO 1328-1:1995 or :2013), got {edition!r}.")
    return text


def grades(edition: str) -> tuple[int, int]:
    """The lowest and highest accuracy grade (flank tolerance class) of an edition.

    Parameters
    ----------
    edition : {"1995", "2013"}

    Returns
    -------
    tuple of int

    References
    ----------
    ISO 1328-1:1995, clause 5 (grades 0 … 12); ISO 1328-1:2013, 5.1 (classes 1 … 11).

    Examples
    --------
    >>> grades("1995"), grades("2013")
    ((0, 12), (1, 11))
    """
    return EDITIONS[_edition(edition)]


def step_factor(grade: int, edition: str = "2013") -> float:
    """√2^(Q − 5): the ratio of a grade's tolerances to grade 5's.

    Parameters
    ----------
    grade : int
        Accuracy grade Q (1995) or flank tolerance class A (2013).
    edition : {"1995", "2013"}

    Returns
    -------
    float

    Raises
    ------
    GeometryError
        A grade that is not a whole number of the edition's range.

    References
    ----------
    ISO 1328-1:1995, clause 6; ISO 1328-1:2013, 5.2.2.

    Examples
    --------
    >>> round(step_factor(7), 12), step_factor(5, "1995")
    (2.0, 1.0)
    """
    low, high = grades(edition)
    if isinstance(grade, bool) or not isinstance(grade, int) or not low <= grade <= high:
        raise GeometryError(f"accuracy: the grade of ISO 1328-1:{_edition(edition)} must be a whole number "
                            f"{low} ... {high}, got {grade!r}.")
    return math.sqrt(2.0) ** (grade - 5)


def round_tolerance(value: float) -> float:
    """A tolerance rounded by ISO 1328-1: > 10 µm to 1 µm, 5 … 10 µm to 0.5 µm, < 5 µm to 0.1 µm.

    Halves round up (the values are tolerances, never negative).

    Parameters
    ----------
    value : float
        Unrounded tolerance, µm (≥ 0).

    Returns
    -------
    float

    References
    ----------
    ISO 1328-1:1995, clause 6; ISO 1328-1:2013, 5.2.3.

    Examples
    --------
    >>> round_tolerance(28.8), round_tolerance(8.94), round_tolerance(7.2), round_tolerance(4.26)
    (29.0, 9.0, 7.0, 4.3)
    """
    if value > 10.0:
        return float(math.floor(value + 0.5))
    if value >= 5.0:
        return math.floor(2.0 * value + 0.5) / 2.0
    return math.floor(10.0 * value + 0.5 + 1e-9) / 10.0


def _geometric_mean(value: float, name: str) -> float:
    limits = _LIMITS_1995[name]
    if not limits[0] <= value <= limits[-1]:
        raise GeometryError(f"accuracy: the {name} {value:g} mm lies outside ISO 1328-1:1995's ranges "
                            f"({limits[0]:g} ... {limits[-1]:g} mm); its tolerances are to be agreed, not extrapolated.")
    upper = max(1, bisect_left(limits, value))
    return math.sqrt(limits[upper - 1] * limits[upper])


def _grade5_1995(d: float, m: float, b: float) -> dict[str, float]:
    d, m, b = (_geometric_mean(d, "reference diameter"), _geometric_mean(m, "normal module"),
               _geometric_mean(b, "face width"))
    rd, rm, rb = math.sqrt(d), math.sqrt(m), math.sqrt(b)
    helix = 0.07 * rd + 0.45 * rb + 3.0
    total_pitch = 0.3 * m + 1.25 * rd + 7.0
    return {"f_pt": 0.3 * (m + 0.4 * rd) + 4.0, "F_p": total_pitch, "F_alpha": 3.2 * rm + 0.22 * rd + 0.7,
            "f_falpha": 2.5 * rm + 0.17 * rd + 0.5, "f_Halpha": 2.0 * rm + 0.14 * rd + 0.5,
            "F_beta": 0.1 * rd + 0.63 * rb + 4.2, "f_fbeta": helix, "f_Hbeta": helix, "F_r": 0.8 * total_pitch}


def _grade5_2013(d: float, m: float, b: float) -> dict[str, float]:
    for name, value in (("reference diameter", d), ("normal module", m), ("face width", b)):
        low, high = _SCOPE_2013[name]
        if not low <= value <= high:
            raise GeometryError(f"accuracy: the {name} {value:g} mm lies outside the scope of ISO 1328-1:2013 "
                                f"({low:g} ... {high:g} mm, clause 1); its tolerances are to be agreed, "
                                "not extrapolated.")
    rd, rb = math.sqrt(d), math.sqrt(b)
    slope, form = 0.4 * m + 0.001 * d + 4.0, 0.55 * m + 5.0
    h_slope, h_form = 0.05 * rd + 0.35 * rb + 4.0, 0.07 * rd + 0.45 * rb + 4.0
    total_pitch = 0.002 * d + 0.55 * rd + 0.7 * m + 12.0
    return {"f_pt": 0.001 * d + 0.4 * m + 5.0, "F_p": total_pitch, "F_alpha": math.hypot(slope, form),
            "f_falpha": form, "f_Halpha": slope, "F_beta": math.hypot(h_slope, h_form), "f_fbeta": h_form,
            "f_Hbeta": h_slope, "F_r": 0.9 * total_pitch}


@dataclass(frozen=True)
class FlankTolerances:
    """The flank tolerances of one gear at one accuracy grade, µm (rounded by the edition's rule).

    Attributes
    ----------
    edition : str
        ``"1995"`` or ``"2013"`` (ISO 1328-1).
    grade : int
        Accuracy grade Q (1995) or flank tolerance class A (2013).
    reference_diameter, normal_module, face_width : float
        d, m_n, b the tolerances are for, mm.
    f_pt, F_p, F_alpha, f_falpha, f_Halpha, F_beta, f_fbeta, f_Hbeta, F_r : float
        Single pitch, total cumulative pitch, total profile, profile form, profile slope, total
        helix, helix form, helix slope tolerances and the runout tolerance, µm (rounded).
    unrounded : mapping symbol → float
        The same before rounding, µm.

    References
    ----------
    ISO 1328-1:1995, clause 6 and Annex B; ISO 1328-2:1997, Annex B; ISO 1328-1:2013, 5.2.

    Examples
    --------
    >>> t = flank_tolerances(6, 120.0, 3.0, 30.0, "2013")
    >>> t.f_pt, t.F_p, t.F_alpha
    (9.0, 29.0, 12.0)
    """

    edition: str
    grade: int
    reference_diameter: float
    normal_module: float
    face_width: float
    f_pt: float
    F_p: float
    F_alpha: float
    f_falpha: float
    f_Halpha: float
    F_beta: float
    f_fbeta: float
    f_Hbeta: float
    F_r: float
    unrounded: Mapping[str, float] = field(default_factory=dict, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "unrounded", MappingProxyType(dict(self.unrounded)))

    @property
    def standard(self) -> str:
        """``"ISO 1328-1:1995"`` or ``"ISO 1328-1:2013"``."""
        return f"ISO 1328-1:{self.edition}"

    def to_dict(self) -> dict[str, float | int | str]:
        """The tolerances by symbol (µm), the edition, grade and the gear data they are for."""
        out: dict[str, float | int | str] = {"standard": self.standard, "grade": self.grade,
                                             "reference_diameter": self.reference_diameter,
                                             "normal_module": self.normal_module, "face_width": self.face_width}
        out.update({s: getattr(self, s) for s in _SYMBOLS})
        return out

    def table(self) -> str:
        """The tolerances as a plain-text table (µm)."""
        from ._render import text_table

        rows = [[s, f"{getattr(self, s):g}", f"{self.unrounded.get(s, float('nan')):.3f}"] for s in _SYMBOLS]
        return text_table(["symbol", "tolerance [µm]", "unrounded [µm]"], rows,
                          title=f"{self.standard}, grade {self.grade}: d = {self.reference_diameter:g} mm, "
                                f"m_n = {self.normal_module:g} mm, b = {self.face_width:g} mm")

    def __repr__(self) -> str:
        return (f"FlankTolerances({self.standard}, grade {self.grade}, f_pt {self.f_pt:g} µm, "
                f"F_alpha {self.F_alpha:g} µm, F_beta {self.F_beta:g} µm)")


def _positive(value: float, name: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0:
        raise GeometryError(f"accuracy: the {name} must be a positive number of mm, got {value!r}.")
    return float(value)


def flank_tolerances(grade: int, reference_diameter: float, normal_module: float, face_width: float,
                     edition: str = "2013") -> FlankTolerances:
    """The ISO 1328-1 flank tolerances of a gear of accuracy grade ``grade``.

    Parameters
    ----------
    grade : int
        Accuracy grade (1995: 0 … 12) or flank tolerance class (2013: 1 … 11).
    reference_diameter : float
        |d|, mm (an internal gear's as a positive number).
    normal_module : float
        m_n, mm.
    face_width : float
        b, mm.
    edition : {"1995", "2013"}, default "2013"

    Returns
    -------
    FlankTolerances

    Raises
    ------
    GeometryError
        An unknown edition, a grade out of the edition's range, a size outside its ranges.

    References
    ----------
    ISO 1328-1:1995, clause 6 and Annex B; ISO 1328-2:1997, Annex B (F_r); ISO 1328-1:2013, 5.2,
    eqs. (5)–(12).

    Examples
    --------
    ISO 1328-1:1995, d = 100 mm (range 50 … 125), m_n = 3 mm (2 … 3.5), grade 5:
    f_pt = 0.3 (√7 + 0.4 √√6250) + 4 = 5.86 µm, rounded to 6.0 µm:

    >>> t = flank_tolerances(5, 100.0, 3.0, 20.0, "1995")
    >>> round(t.unrounded["f_pt"], 3), t.f_pt
    (5.861, 6.0)
    """
    edition = _edition(edition)
    step = step_factor(grade, edition)
    d = abs(_positive(abs(reference_diameter) if isinstance(reference_diameter, (int, float))
                      and not isinstance(reference_diameter, bool) else reference_diameter, "reference diameter"))
    m, b = _positive(normal_module, "normal module"), _positive(face_width, "face width")
    base = _grade5_1995(d, m, b) if edition == "1995" else _grade5_2013(d, m, b)
    raw = {s: v * step for s, v in base.items()}
    return FlankTolerances(edition, grade, d, m, b, **{s: round_tolerance(v) for s, v in raw.items()}, unrounded=raw)


def base_pitch_deviation(single_pitch: float, transverse_pressure_angle: float) -> float:
    """f_pb = f_pt cos α_t, µm: the transverse base pitch deviation from the single pitch tolerance.

    Parameters
    ----------
    single_pitch : float
        f_pt, µm.
    transverse_pressure_angle : float
        α_t, rad.

    Returns
    -------
    float

    References
    ----------
    ISO/TR 10064-1:1992 (base pitch = transverse pitch × cos α_t); ISO 6336-1:2006, 6.5.9 and 8.3
    (f_pb in K_v and K_Hα).

    Examples
    --------
    >>> round(base_pitch_deviation(10.0, math.radians(20.0)), 4)
    9.3969
    """
    return single_pitch * math.cos(transverse_pressure_angle)
