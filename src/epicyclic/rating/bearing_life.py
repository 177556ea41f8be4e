"""Rating life of rolling bearings (ISO 281:2007): L10, L10h and the modified life L_nm.

The basic rating life of a bearing under the equivalent dynamic load P, in
millions of revolutions (ISO 281:2007, 5.3 and 7.3):

.. math:: L_{10} = \\left(\\frac{C}{P}\\right)^p, \\qquad
          L_{10h} = \\frac{10^6}{60\\,n}\\,L_{10}

with the basic dynamic load rating C, the exponent p = 3 for ball and 10/3
for roller bearings, and n the speed of the rotating ring relative to the
stationary one (1/min): a planet bearing turns at the planet's speed relative
to the carrier, a central bearing at its shaft's speed relative to the housing.

The modified rating life for reliability 100 − n % (ISO 281:2007, clause 9):

.. math:: L_{nm} = a_1\\,a_{ISO}\\,L_{10}

where a_1 is the reliability factor (Table 12) and a_ISO the life
modification factor from the viscosity ratio κ = ν/ν1 and the fatigue-load
ratio e_C C_u/P (9.3, radial bearings): for radial ball bearings

.. math:: a_{ISO} = 0.1\\left[1 - \\left(2.5671 - \\frac{b}{\\kappa^{c}}\\right)^{0.83}
          \\left(\\frac{e_C C_u}{P}\\right)^{1/3}\\right]^{-9.3}

with (b, c) = (2.2649, 0.054381) for 0.1 ≤ κ < 0.4, (1.9987, 0.19087) for
0.4 ≤ κ < 1 and (1.9987, 0.071739) for 1 ≤ κ ≤ 4; for radial roller bearings

.. math:: a_{ISO} = 0.1\\left[1 - \\left(1.5859 - \\frac{b}{\\kappa^{c}}\\right)
          \\left(\\frac{e_C C_u}{P}\\right)^{0.4}\\right]^{-9.185}

with b = 1.3993, 1.2348, 1.2348 in the same bands.  κ above 4 counts as 4;
a_ISO is limited to 50.  Below κ = 0.1 the equations do not apply: the life is
refused (an error), not extrapolated.  The reference viscosity (ISO 281:2007,
9.3.3) is

.. math:: \\nu_1 = 45000\\,n^{-0.83}\\,d_m^{-0.5} \\;(n < 1000), \\qquad
          \\nu_1 = 4500\\,n^{-0.5}\\,d_m^{-0.5} \\;(n \\ge 1000)

(ν1 in mm²/s, n in 1/min, d_m = (d + D)/2 in mm).

Over a load spectrum with time shares q_i (Palmgren–Miner for bearings; SKF,
*Rolling bearings* (2013), "Life calculation with variable operating conditions"):

.. math:: P_{eq} = \\left(\\frac{\\sum q_i n_i P_i^p}{\\sum q_i n_i}\\right)^{1/p}, \\qquad
          L_{h} = \\left(\\sum_i \\frac{q_i}{L_{h,i}}\\right)^{-1}

(the two give the same hours: L_h = 10^6 (C/P_eq)^p / (60 Σ q_i n_i)).

What is modelled: radial bearings under P = X F_r + Y F_a with the X, Y the
user gives (default X = 1, Y = 0: the radial load alone); thrust bearings and
the X/Y tables of ISO 281 (which depend on F_a/C_0) are not.

References
----------
ISO 281:2007, *Rolling bearings — Dynamic load ratings and rating life*, 5.3, 7.3, clause 9, Table 12;
SKF, *Rolling bearings* (catalogue 10000, 2013), "Selecting bearing size", Calculation example 1;
ISO/TR 1281-2:2008 (background of a_ISO).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import ModelError

__all__ = [
    "A_ISO_LIMIT",
    "BEARING_KINDS",
    "LIFE_EXPONENT",
    "RELIABILITY_FACTOR",
    "BearingLifeError",
    "BearingRating",
    "basic_rating_life",
    "equivalent_load",
    "life_modification_factor",
    "rating_life_hours",
    "reference_viscosity",
    "reliability_factor",
    "spectrum_life",
]


class BearingLifeError(ModelError):
    """A bearing-life input that is invalid (no load rating, unknown type, κ below the standard's range)."""


#: Bearing type → "ball" or "roller" (the types of :data:`epicyclic.losses.bearing.BEARING_FRICTION` and a
#: few more); the kind sets the exponent p and the a_ISO equation.
BEARING_KINDS = {
    "deep groove ball": "ball",
    "angular contact ball": "ball",
    "self-aligning ball": "ball",
    "needle roller": "roller",
    "cylindrical roller": "roller",
    "cylindrical roller full complement": "roller",
    "tapered roller": "roller",
    "spherical roller": "roller",
}
#: Life exponent p by kind (ISO 281:2007, 5.3 and 7.3).
LIFE_EXPONENT = {"ball": 3.0, "roller": 10.0 / 3.0}
#: Reliability (%) → life modification factor a_1 (ISO 281:2007, Table 12).
RELIABILITY_FACTOR = {90.0: 1.0, 95.0: 0.64, 96.0: 0.55, 97.0: 0.47, 98.0: 0.37, 99.0: 0.25, 99.2: 0.22,
                      99.4: 0.19, 99.6: 0.16, 99.8: 0.12, 99.9: 0.093, 99.92: 0.087, 99.94: 0.08, 99.95: 0.077}
#: Upper limit of a_ISO (ISO 281:2007, 9.3).
A_ISO_LIMIT = 50.0
#: The viscosity-ratio bands of the a_ISO equations (9.3): (upper κ, b ball, b roller, c).
_KAPPA_BANDS = ((0.4, 2.2649, 1.3993, 0.054381), (1.0, 1.9987, 1.2348, 0.19087), (math.inf, 1.9987, 1.2348, 0.071739))


def _positive(value: object, field: str, unit: str, *, allow_none: bool = False) -> float | None:
    if value is None and allow_none:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0:
        raise BearingLifeError(f"bearing: {field} must be a positive number ({unit}), got {value!r}.")
    return float(value)


def basic_rating_life(dynamic_load_rating: float, load: object, exponent: float) -> np.ndarray:
    """Basic rating life L10 = (C/P)^p, millions of revolutions (ISO 281:2007, 5.3 and 7.3).

    Parameters
    ----------
    dynamic_load_rating : float
        C, N.
    load : array_like
        Equivalent dynamic load P ≥ 0, N (0 gives an infinite life).
    exponent : float
        p: 3 for ball, 10/3 for roller bearings.

    Returns
    -------
    ndarray
        L10, 10^6 revolutions.

    Examples
    --------
    SKF calculation example 1: a 6309 deep groove ball bearing, C = 55.3 kN, P = 10 kN:

    >>> round(float(basic_rating_life(55300.0, 10000.0, 3.0)))
    169

    References
    ----------
    ISO 281:2007, 5.3 and 7.3; SKF, *Rolling bearings* (2013), Calculation example 1.
    """
    p = np.abs(np.asarray(load, dtype=float))
    with np.errstate(divide="ignore", over="ignore"):
        return np.where(p > 0, (dynamic_load_rating / np.where(p > 0, p, 1.0)) ** exponent, np.inf)


def rating_life_hours(life: object, speed: object) -> np.ndarray:
    """Rating life in operating hours, L_h = 10^6 L / (60 n) (ISO 281:2007; SKF calculation example 1).

    Parameters
    ----------
    life : array_like
        L, 10^6 revolutions.
    speed : array_like
        Speed of the rotating ring relative to the stationary one, 1/min (its magnitude; 0: infinite).

    Returns
    -------
    ndarray
        Hours.

    Examples
    --------
    >>> round(float(rating_life_hours(169.1, 3000.0)))
    939

    References
    ----------
    ISO 281:2007 (L10h); SKF, *Rolling bearings* (2013), Calculation example 1 (940 h).
    """
    n = np.abs(np.asarray(speed, dtype=float))
    life = np.asarray(life, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(n > 0, 1e6 * life / (60.0 * np.where(n > 0, n, 1.0)), np.inf)


def reference_viscosity(speed: object, pitch_diameter: float) -> np.ndarray:
    """Reference kinematic viscosity ν1 for adequate lubrication, mm²/s (ISO 281:2007, 9.3.3).

    Parameters
    ----------
    speed : array_like
        n, 1/min (> 0).
    pitch_diameter : float
        d_m = (d + D)/2, mm.

    Returns
    -------
    ndarray
        ν1 = 45000 n^-0.83 d_m^-0.5 for n < 1000 1/min, 4500 n^-0.5 d_m^-0.5 from 1000 1/min.

    Examples
    --------
    >>> round(float(reference_viscosity(3000.0, 72.5)), 3)
    9.649

    References
    ----------
    ISO 281:2007, 9.3.3 (viscosity ratio).
    """
    n = np.abs(np.asarray(speed, dtype=float))
    with np.errstate(divide="ignore"):
        slow = 45000.0 * n ** -0.83 / math.sqrt(pitch_diameter)
        fast = 4500.0 * n ** -0.5 / math.sqrt(pitch_diameter)
    return np.where(n < 1000.0, slow, fast)


def life_modification_factor(viscosity_ratio: object, load_ratio: object, kind: str) -> np.ndarray:
    """a_ISO of radial bearings from κ and e_C C_u/P (ISO 281:2007, 9.3; see the module text).

    Parameters
    ----------
    viscosity_ratio : array_like
        κ = ν/ν1 ≥ 0.1 (above 4 counts as 4).
    load_ratio : array_like
        e_C C_u / P ≥ 0.
    kind : {"ball", "roller"}
        Radial ball or roller bearing.

    Returns
    -------
    ndarray
        a_ISO in [0.1, 50].

    Raises
    ------
    BearingLifeError
        κ < 0.1 (outside the standard's equations), a negative load ratio, an unknown kind.

    Examples
    --------
    Without fatigue-load margin (e_C C_u/P = 0) a_ISO is 0.1 at any κ:

    >>> float(life_modification_factor(1.0, 0.0, "roller"))
    0.1

    References
    ----------
    ISO 281:2007, 9.3 (radial ball and radial roller bearings; a_ISO ≤ 50).
    """
    if kind not in LIFE_EXPONENT:
        raise BearingLifeError(f"life_modification_factor: kind must be 'ball' or 'roller', got {kind!r}.")
    kappa = np.asarray(viscosity_ratio, dtype=float)
    ratio = np.asarray(load_ratio, dtype=float)
    if np.any(~np.isfinite(kappa)) or np.any(kappa < 0.1):
        low = float(np.nanmin(kappa)) if kappa.size else float("nan")
        raise BearingLifeError(
            f"life_modification_factor: the viscosity ratio kappa = nu/nu1 must be at least 0.1 (ISO 281:2007, "
            f"9.3: below it the equations do not apply), got {low:.3g}; use a more viscous oil or give no "
            "'viscosity' to get the basic life L10 only.")
    if np.any(~np.isfinite(ratio)) or np.any(ratio < 0):
        raise BearingLifeError(f"life_modification_factor: e_C C_u/P must be >= 0, got {ratio!r}.")
    kappa = np.minimum(kappa, 4.0)
    b = np.zeros_like(kappa)
    c = np.zeros_like(kappa)
    lower = 0.0
    for upper, b_ball, b_roller, exponent in _KAPPA_BANDS:
        band = (kappa >= lower) & (kappa < upper) if math.isfinite(upper) else kappa >= lower
        b = np.where(band, b_ball if kind == "ball" else b_roller, b)
        c = np.where(band, exponent, c)
        lower = upper
    # the lubrication term vanishes at kappa = 0.1 (a_ISO = 0.1); the constants' rounding makes it -7e-5
    # there for roller bearings, so it is taken as >= 0
    if kind == "ball":
        bracket = 1.0 - np.maximum(2.5671 - b / kappa ** c, 0.0) ** 0.83 * ratio ** (1.0 / 3.0)
        power = -9.3
    else:
        bracket = 1.0 - np.maximum(1.5859 - b / kappa ** c, 0.0) * ratio ** 0.4
        power = -9.185
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        value = np.where(bracket > 0, 0.1 * np.where(bracket > 0, bracket, 1.0) ** power, A_ISO_LIMIT)
    return np.minimum(value, A_ISO_LIMIT)


def reliability_factor(reliability: float) -> float:
    """a_1 for a reliability in % (ISO 281:2007, Table 12; 90 % → 1).

    Parameters
    ----------
    reliability : float
        One of the table's reliabilities, %.

    Returns
    -------
    float

    Raises
    ------
    BearingLifeError
        A reliability the table does not list (no interpolation).

    Examples
    --------
    >>> reliability_factor(99)
    0.25

    References
    ----------
    ISO 281:2007, Table 12.
    """
    key = float(reliability) if isinstance(reliability, (int, float)) and not isinstance(reliability, bool) else None
    if key not in RELIABILITY_FACTOR:
        raise BearingLifeError(
            f"bearing: reliability must be one of ISO 281 Table 12 "
            f"({', '.join(f'{r:g}' for r in RELIABILITY_FACTOR)} %), got {reliability!r}.")
    return RELIABILITY_FACTOR[key]


def equivalent_load(loads: object, speeds: object, shares: object, exponent: float) -> float:
    """Equivalent load of a spectrum, P_eq = (Σ q_i n_i P_i^p / Σ q_i n_i)^(1/p), N.

    Parameters
    ----------
    loads : array_like
        P_i, N.
    speeds : array_like
        n_i, 1/min (magnitudes).
    shares : array_like
        Time shares q_i (any positive scale).
    exponent : float
        p.

    Returns
    -------
    float
        P_eq, N (0 when the bearing never turns).

    Examples
    --------
    Equal revolutions at 1 and 2 kN, ball bearing: ((1 + 8)/2)^(1/3) kN:

    >>> round(equivalent_load([1000.0, 2000.0], [100.0, 100.0], [0.5, 0.5], 3.0), 3)
    1650.964

    References
    ----------
    SKF, *Rolling bearings* (2013), "Life calculation with variable operating conditions"; Palmgren 1924.
    """
    p = np.abs(np.asarray(loads, dtype=float))
    weight = np.abs(np.asarray(speeds, dtype=float)) * np.asarray(shares, dtype=float)
    total = float(np.sum(weight))
    if total <= 0:
        return 0.0
    return float((np.sum(weight * p ** exponent) / total) ** (1.0 / exponent))


def spectrum_life(lives: object, shares: object) -> float:
    """Life over a spectrum, L = 1/Σ(q_i/L_i), with Σ q_i = 1 (Palmgren–Miner).

    Parameters
    ----------
    lives : array_like
        Life at each case alone (hours or revolutions; inf where the case does no damage).
    shares : array_like
        Shares q_i of the same measure (time shares for hours), summing to 1.

    Returns
    -------
    float
        The life (inf when no case does damage).

    Examples
    --------
    >>> spectrum_life([1000.0, float("inf")], [0.5, 0.5])
    2000.0

    References
    ----------
    Palmgren 1924, Miner 1945 (linear damage accumulation); SKF, *Rolling bearings* (2013), "Life
    calculation with variable operating conditions".
    """
    life = np.asarray(lives, dtype=float)
    q = np.asarray(shares, dtype=float)
    with np.errstate(divide="ignore"):
        damage = float(np.sum(np.where(np.isinf(life), 0.0, q / life)))
    return math.inf if damage == 0 else 1.0 / damage


@dataclass(frozen=True)
class BearingRating:
    """The rating data of one bearing position (every planet of a set alike).

    Parameters
    ----------
    type : str
        A bearing type of :data:`BEARING_KINDS` (sets p and the a_ISO equation).
    dynamic_load_rating : float
        C, N.
    fatigue_load_limit : float, optional
        C_u, N (needed, with the next three, for the modified life).
    pitch_diameter : float, optional
        d_m = (d + D)/2, mm.
    viscosity : float, optional
        Kinematic viscosity of the oil at operating temperature, mm²/s; without one (and with the
        other three) a duty cycle takes it from the lubricant at each case's oil temperature.
    contamination : float, optional
        e_C in [0, 1] (ISO 281:2007, clause 9: typical values by cleanliness).
    reliability : float, default 90
        %, one of ISO 281 Table 12.
    radial_factor, axial_factor : float, default 1 and 0
        X and Y of P = X F_r + Y F_a.
    exponent : float, optional
        p; default by type (3 ball, 10/3 roller).
    external_load : float, default 0
        A constant radial load added to the load from the tooth forces (weight, an
        unbalanced pull, a belt), N; for central bearings, whose gear load is zero with
        equally spaced planets.

    Examples
    --------
    >>> b = BearingRating("deep groove ball", 55300.0)
    >>> b.kind, b.life_exponent, b.modified
    ('ball', 3.0, False)
    """

    type: str
    dynamic_load_rating: float
    fatigue_load_limit: float | None = None
    pitch_diameter: float | None = None
    viscosity: float | None = None
    contamination: float | None = None
    reliability: float = 90.0
    radial_factor: float = 1.0
    axial_factor: float = 0.0
    exponent: float | None = None
    external_load: float = 0.0

    def __post_init__(self) -> None:
        if self.type not in BEARING_KINDS:
            raise BearingLifeError(f"bearing: unknown type {self.type!r}; expected one of "
                                   f"{', '.join(repr(k) for k in BEARING_KINDS)}.")
        _positive(self.dynamic_load_rating, "dynamic_load_rating C", "N")
        _positive(self.fatigue_load_limit, "fatigue_load_limit C_u", "N", allow_none=True)
        _positive(self.pitch_diameter, "pitch_diameter d_m", "mm", allow_none=True)
        _positive(self.viscosity, "viscosity", "mm^2/s", allow_none=True)
        _positive(self.exponent, "exponent p", "3 ball, 10/3 roller", allow_none=True)
        e = self.contamination
        if e is not None and (isinstance(e, bool) or not isinstance(e, (int, float)) or not 0 <= e <= 1):
            raise BearingLifeError(f"bearing: contamination e_C must lie in [0, 1] (ISO 281 clause 9), got {e!r}.")
        reliability_factor(self.reliability)
        for name in ("radial_factor", "axial_factor", "external_load"):
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) or v < 0:
                raise BearingLifeError(f"bearing: {name} must be a number >= 0, got {v!r}.")
        keys = ("fatigue_load_limit", "pitch_diameter", "viscosity", "contamination")
        given = [k for k in keys if getattr(self, k) is not None]
        if given and len(given) < 4 and given != ["fatigue_load_limit", "pitch_diameter", "contamination"]:
            missing = [k for k in keys if getattr(self, k) is None]
            raise BearingLifeError(
                f"bearing: the modified life L_nm needs fatigue_load_limit, pitch_diameter, viscosity and "
                f"contamination; {', '.join(given)} given, {', '.join(missing)} missing (give all four, or none "
                "for the basic life L10 only; without viscosity a duty cycle takes the lubricant's at the oil "
                "temperature).")

    @property
    def kind(self) -> str:
        """"ball" or "roller"."""
        return BEARING_KINDS[self.type]

    @property
    def life_exponent(self) -> float:
        """p (given, or 3 ball / 10/3 roller)."""
        return float(self.exponent) if self.exponent is not None else LIFE_EXPONENT[self.kind]

    @property
    def modified(self) -> bool:
        """Whether the modified life L_nm (a_1 a_ISO L10) can be computed."""
        return self.fatigue_load_limit is not None

    def equivalent_dynamic_load(self, radial: object, axial: object = 0.0) -> np.ndarray:
        """P = X F_r + Y F_a, N (ISO 281:2007, 5.2 and 7.2).

        Parameters
        ----------
        radial, axial : array_like
            F_r and F_a, N.

        Returns
        -------
        ndarray
        """
        return self.radial_factor * np.abs(np.asarray(radial, float)) + self.axial_factor * np.abs(
            np.asarray(axial, float))

    def life_factor(self, load: object, speed: object, viscosity: object = None) -> np.ndarray:
        """a_1 a_ISO at loads P (N) and speeds n (1/min); ones without the modified-life inputs.

        Parameters
        ----------
        load, speed : array_like
            P, N and n, 1/min.
        viscosity : array_like, optional
            ν at operating temperature, mm²/s (per point); default the rating's ``viscosity``.

        Returns
        -------
        ndarray
            a_1 a_ISO (1 where the bearing does not turn or carries no load).
        """
        p = np.abs(np.asarray(load, dtype=float))
        n = np.abs(np.asarray(speed, dtype=float))
        shape = np.broadcast(p, n).shape
        if not self.modified:
            return np.ones(shape)
        nu = self.viscosity if viscosity is None else viscosity
        if nu is None:
            raise BearingLifeError("bearing: the modified life L_nm needs the oil's viscosity at operating "
                                   "temperature: give viscosity, or [lubricant] viscosity_40, viscosity_100 and "
                                   "temperature.")
        active = (p > 0) & (n > 0)
        out = np.ones(shape)
        if np.any(active):
            pa, na = np.broadcast_to(p, shape)[active], np.broadcast_to(n, shape)[active]
            nu_a = np.broadcast_to(np.asarray(nu, dtype=float), shape)[active]
            kappa = nu_a / reference_viscosity(na, self.pitch_diameter)  # type: ignore[operator]
            ratio = self.contamination * self.fatigue_load_limit / pa  # type: ignore[operator]
            out[active] = reliability_factor(self.reliability) * life_modification_factor(kappa, ratio, self.kind)
        return out

    def to_dict(self) -> dict[str, object]:
        """JSON-ready inputs with units (C, C_u in N; d_m in mm; ν in mm²/s)."""
        return {"type": self.type, "kind": self.kind, "C": {"value": self.dynamic_load_rating, "unit": "N"},
                "p": self.life_exponent,
                "C_u": None if self.fatigue_load_limit is None else {"value": self.fatigue_load_limit, "unit": "N"},
                "d_m": None if self.pitch_diameter is None else {"value": self.pitch_diameter, "unit": "mm"},
                "nu": None if self.viscosity is None else {"value": self.viscosity, "unit": "mm^2/s"},
                "e_C": self.contamination, "reliability": {"value": self.reliability, "unit": "%"},
                "X": self.radial_factor, "Y": self.axial_factor,
                "external_load": {"value": self.external_load, "unit": "N"}}
