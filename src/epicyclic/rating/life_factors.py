"""Life factors Z_NT (pitting) and Y_NT (tooth root) and Palmgren–Miner damage sums.

The life factor scales the endurance limit of a material to a finite number of
load cycles N_L (ISO 6336-2 clause 10, ISO 6336-3 clause 12, Method B).  Each
material treatment has an S–N curve of straight lines in log–log coordinates
through these points (factor 1 at the reference number of cycles N_ref, the
static value up to N_static, and 0.85 at 10^10 — or 1.0 there for optimum
material, lubrication and manufacturing, ``long_life="optimum"``):

==============================================================  ==========  ======  ======  ======
treatment (ISO 6336-5 symbols)                                   N_static    static  N_ref   curve
==============================================================  ==========  ======  ======  ======
Z_NT, St, V, GGG perl., GTS, Eh, IF, some pitting permitted      6·10^5      1.6     10^9    (10^7, 1.3)
Z_NT, the same, no pitting permitted (default)                   10^5        1.6     5·10^7
Z_NT, GG, GGG ferr., NT (nitrided), NV (nitrided)                10^5        1.3     2·10^6
Z_NT, NV nitrocarburised                                         10^5        1.1     2·10^6
Y_NT, V, GGG perl., GTS                                          10^4        2.5     3·10^6
Y_NT, Eh, IF (root hardened)                                     10^3        2.5     3·10^6
Y_NT, St, NT, NV (nitrided), GG, GGG ferr.                       10^3        1.6     3·10^6
Y_NT, NV nitrocarburised                                         10^3        1.1     3·10^6
==============================================================  ==========  ======  ======  ======

Both editions (2006, 2019) use these corner points.  Beyond 10^10 cycles they differ: the 2006
editions end their curves at 10^10 and the factor stays at its 10^10 value (0.85, or 1.0), the 2019
editions continue the last line (its slope) into the long-life region; ``edition`` selects which.

Public API (stable; the duty-cycle code of :mod:`epicyclic` builds on it):

* :class:`SNCurve` — one curve: ``factor(cycles)`` (vectorised), ``cycles_to_failure(ratio)``,
  ``static_cycles``, ``reference_cycles``, ``static_factor``, ``clause``;
* :func:`pitting_curve` / :func:`bending_curve` — the curve of a treatment;
* :func:`pitting_life_factor` / :func:`bending_life_factor` — Z_NT and Y_NT at N_L;
* :func:`pitting_damage` / :func:`bending_damage` — the Palmgren–Miner sum
  D = Σ n_i / N_i over ``(stress, cycles)`` cases against the stress the
  flank or root endures at N_ref (σ at life factor 1).

References
----------
ISO 6336-2:2006, clause 10, Table 2 and Figure 5 (Z_NT); ISO 6336-3:2006,
clause 12, Table 3 and Figure 3 (Y_NT); the same in the 2019 editions.
ISO 6336-6:2019, clause 5 (Palmgren–Miner rule for a load spectrum).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np

from .errors import RatingError
from .standard import edition

__all__ = [
    "TREATMENTS",
    "SNCurve",
    "bending_curve",
    "bending_damage",
    "bending_life_factor",
    "miner_damage",
    "pitting_curve",
    "pitting_damage",
    "pitting_life_factor",
]

#: Material treatments by their ISO 6336-5 symbols, what each means.
TREATMENTS = {
    "St": "normalised structural steel",
    "St(cast)": "cast steel",
    "V": "through-hardened (quenched and tempered) wrought steel",
    "V(cast)": "through-hardened cast steel",
    "GGG(perl)": "nodular cast iron, pearlitic or bainitic",
    "GGG(ferr)": "nodular cast iron, ferritic",
    "GTS": "black malleable cast iron (pearlitic)",
    "GG": "grey cast iron",
    "Eh": "case-carburised (case-hardened) steel",
    "IF": "flame or induction hardened steel (root hardened)",
    "NT": "nitriding steel, nitrided",
    "NV": "through-hardening steel, nitrided",
    "NV(nitrocar)": "through-hardening steel, nitrocarburised",
}

_LONG_LIFE_CYCLES = 1e10


@dataclass(frozen=True)
class SNCurve:
    """A life-factor curve: straight lines in log N – log factor through ``points``.

    Parameters
    ----------
    points : tuple of (float, float)
        (N_L, factor) corners in increasing N_L: the first is the end of the static
        range, the factor 1.0 marks the reference (endurance) number of cycles, the
        last is (10^10, 0.85) or (10^10, 1.0).
    symbol : str
        ``"Z_NT"`` or ``"Y_NT"``.
    clause : str
        The table of the standard the points come from.
    beyond : {"extend", "hold"}, default "extend"
        Beyond the last point: continue the last line (ISO 6336-2/-3:2019) or hold the last value
        (ISO 6336-2/-3:2006, whose curves end at 10^10 cycles).

    References
    ----------
    ISO 6336-2:2006, Table 2; ISO 6336-3:2006, Table 3; ISO 6336-2:2019, clause 10.

    Examples
    --------
    >>> curve = pitting_curve("Eh")
    >>> curve.static_cycles, curve.reference_cycles, curve.static_factor
    (100000.0, 50000000.0, 1.6)
    >>> round(float(curve.factor(1e6)), 4)
    1.3443
    """

    points: tuple[tuple[float, float], ...]
    symbol: str
    clause: str
    beyond: str = "extend"

    def __post_init__(self) -> None:
        if self.beyond not in ("extend", "hold"):
            raise RatingError(f"{self.symbol}: beyond must be 'extend' (ISO 6336:2019) or 'hold' (ISO 6336:2006), "
                              f"got {self.beyond!r}.")

    @property
    def static_cycles(self) -> float:
        """N_L up to which the static value applies."""
        return self.points[0][0]

    @property
    def static_factor(self) -> float:
        """The life factor of the static range (N_L ≤ :attr:`static_cycles`)."""
        return self.points[0][1]

    @property
    def reference_cycles(self) -> float:
        """N_L at which the factor is 1 (the endurance limit's number of cycles)."""
        return next(n for n, f in self.points if f == 1.0)

    @property
    def long_life_factor(self) -> float:
        """The factor at 10^10 cycles (0.85, or 1.0 for optimum conditions)."""
        return self.points[-1][1]

    def factor(self, cycles):
        """The life factor at ``cycles`` load cycles (scalar or array, ≥ 1).

        Parameters
        ----------
        cycles : float or array_like
            Number of load cycles N_L of the flank or root.

        Returns
        -------
        float or numpy.ndarray
            Z_NT or Y_NT; beyond 10^10 the last line continues (its slope, or flat at 1.0) or, for
            ``beyond="hold"``, the 10^10 value holds.

        Raises
        ------
        RatingError
            A number of cycles < 1 or not finite.

        References
        ----------
        ISO 6336-2:2006, Table 2; ISO 6336-3:2006, Table 3.
        """
        n = np.asarray(cycles, dtype=float)
        if not np.all(np.isfinite(n)) or np.any(n < 1.0):
            raise RatingError(f"{self.symbol}: the number of load cycles must be a finite number >= 1, got {cycles!r}.")
        logs = np.log10([p[0] for p in self.points])
        values = np.log10([p[1] for p in self.points])
        x = np.log10(n)
        out = np.interp(x, logs, values)
        if self.beyond == "extend":  # np.interp holds the last value beyond it
            last = (values[-1] - values[-2]) / (logs[-1] - logs[-2])
            out = np.where(x > logs[-1], values[-1] + last * (x - logs[-1]), out)
        result = 10.0 ** out
        return float(result) if np.ndim(result) == 0 else result

    def cycles_to_failure(self, ratio: float) -> float:
        """The number of cycles N at which ``factor(N) == ratio`` (stress / endurance stress).

        Parameters
        ----------
        ratio : float
            σ / σ_ref, the stress over the stress endured at the reference number of cycles.

        Returns
        -------
        float
            N; 0.0 above the static factor (fails at once), ``math.inf`` where the curve
            never falls to ``ratio`` (a flat long-life line at or above it).

        References
        ----------
        ISO 6336-6:2019, clause 5 (S–N curve of the damage calculation).
        """
        if not ratio > 0 or not math.isfinite(ratio):
            raise RatingError(f"{self.symbol}: the stress ratio must be a positive number, got {ratio!r}.")
        if ratio > self.static_factor:
            return 0.0
        pts = self.points
        for (n0, f0), (n1, f1) in itertools.pairwise(pts):
            if f1 <= ratio <= f0 and f0 != f1:
                t = (math.log10(ratio) - math.log10(f0)) / (math.log10(f1) - math.log10(f0))
                return 10.0 ** (math.log10(n0) + t * (math.log10(n1) - math.log10(n0)))
        if ratio == self.static_factor:
            return self.static_cycles
        (n0, f0), (n1, f1) = pts[-2], pts[-1]
        if f0 == f1 or self.beyond == "hold":
            return math.inf
        slope = (math.log10(f1) - math.log10(f0)) / (math.log10(n1) - math.log10(n0))
        return 10.0 ** (math.log10(n1) + (math.log10(ratio) - math.log10(f1)) / slope)


def _check_treatment(treatment: str, symbol: str) -> None:
    if treatment not in TREATMENTS:
        raise RatingError(f"{symbol}: unknown material treatment {treatment!r}; expected one of "
                          f"{', '.join(TREATMENTS)} (ISO 6336-5 symbols).")


def _long(long_life: str, symbol: str) -> float:
    if long_life not in ("standard", "optimum"):
        raise RatingError(f"{symbol}: long_life must be 'standard' (0.85 at 10^10 cycles) or 'optimum' (1.0), "
                          f"got {long_life!r}.")
    return 0.85 if long_life == "standard" else 1.0


def _beyond(edition_: str) -> tuple[str, str]:
    year = edition(edition_)
    return ("hold" if year == "2006" else "extend"), year


def pitting_curve(treatment: str, *, pitting_permitted: bool = False, long_life: str = "standard",
                  edition: str = "2019") -> SNCurve:
    """The Z_NT curve of a material treatment.

    Parameters
    ----------
    treatment : str
        ISO 6336-5 symbol (:data:`TREATMENTS`), e.g. ``"Eh"``, ``"V"``, ``"NT"``.
    pitting_permitted : bool, default False
        St, V, GGG perl., GTS, Eh, IF only: the curve for some pitting permitted
        (reference 10^9 cycles) instead of none (5·10^7).
    long_life : {"standard", "optimum"}
        Factor 0.85 or 1.0 at 10^10 cycles.
    edition : {"2006", "2019"}, default "2019"
        ISO 6336-2 edition: beyond 10^10 cycles the 2006 curve holds its value, the 2019 one falls on.

    Returns
    -------
    SNCurve

    References
    ----------
    ISO 6336-2:2006, clause 10, Table 2 (lines 1–4); ISO 6336-2:2019, clause 10.
    """
    _check_treatment(treatment, "Z_NT")
    beyond, year = _beyond(edition)
    end = _long(long_life, "Z_NT")
    if treatment in ("St", "St(cast)", "V", "V(cast)", "GGG(perl)", "GTS", "Eh", "IF"):
        if pitting_permitted:
            pts = ((6e5, 1.6), (1e7, 1.3), (1e9, 1.0), (_LONG_LIFE_CYCLES, end))
        else:
            pts = ((1e5, 1.6), (5e7, 1.0), (_LONG_LIFE_CYCLES, end))
    elif treatment in ("GG", "GGG(ferr)", "NT", "NV"):
        pts = ((1e5, 1.3), (2e6, 1.0), (_LONG_LIFE_CYCLES, end))
    else:  # NV(nitrocar)
        pts = ((1e5, 1.1), (2e6, 1.0), (_LONG_LIFE_CYCLES, end))
    return SNCurve(pts, "Z_NT", f"ISO 6336-2:{year}, clause 10, Table 2", beyond)


def bending_curve(treatment: str, *, long_life: str = "standard", edition: str = "2019") -> SNCurve:
    """The Y_NT curve of a material treatment.

    Parameters
    ----------
    treatment : str
        ISO 6336-5 symbol (:data:`TREATMENTS`).
    long_life : {"standard", "optimum"}
        Factor 0.85 or 1.0 at 10^10 cycles.
    edition : {"2006", "2019"}, default "2019"
        ISO 6336-3 edition: beyond 10^10 cycles the 2006 curve holds its value, the 2019 one falls on.

    Returns
    -------
    SNCurve

    References
    ----------
    ISO 6336-3:2006, clause 12, Table 3 (lines 1–4); ISO 6336-3:2019, clause 12.
    """
    _check_treatment(treatment, "Y_NT")
    beyond, year = _beyond(edition)
    end = _long(long_life, "Y_NT")
    if treatment in ("V", "V(cast)", "GGG(perl)", "GTS"):
        pts = ((1e4, 2.5), (3e6, 1.0), (_LONG_LIFE_CYCLES, end))
    elif treatment in ("Eh", "IF"):
        pts = ((1e3, 2.5), (3e6, 1.0), (_LONG_LIFE_CYCLES, end))
    elif treatment in ("St", "St(cast)", "NT", "NV", "GG", "GGG(ferr)"):
        pts = ((1e3, 1.6), (3e6, 1.0), (_LONG_LIFE_CYCLES, end))
    else:  # NV(nitrocar)
        pts = ((1e3, 1.1), (3e6, 1.0), (_LONG_LIFE_CYCLES, end))
    return SNCurve(pts, "Y_NT", f"ISO 6336-3:{year}, clause 12, Table 3", beyond)


def pitting_life_factor(cycles, treatment: str, *, pitting_permitted: bool = False, long_life: str = "standard"):
    """Z_NT at ``cycles`` load cycles for a material treatment.

    Parameters
    ----------
    cycles : float or array_like
        N_L of the flank (≥ 1).
    treatment : str
        ISO 6336-5 symbol, e.g. ``"Eh"``.
    pitting_permitted : bool, default False
        See :func:`pitting_curve`.
    long_life : {"standard", "optimum"}
        See :func:`pitting_curve`.

    Returns
    -------
    float or numpy.ndarray

    References
    ----------
    ISO 6336-2:2006, clause 10, Table 2.

    Examples
    --------
    >>> [round(pitting_life_factor(n, "Eh"), 3) for n in (1e4, 5e7, 1e10)]
    [1.6, 1.0, 0.85]
    """
    return pitting_curve(treatment, pitting_permitted=pitting_permitted, long_life=long_life).factor(cycles)


def bending_life_factor(cycles, treatment: str, *, long_life: str = "standard"):
    """Y_NT at ``cycles`` load cycles for a material treatment.

    Parameters
    ----------
    cycles : float or array_like
        N_L of the tooth root (≥ 1).
    treatment : str
        ISO 6336-5 symbol, e.g. ``"Eh"``.
    long_life : {"standard", "optimum"}
        See :func:`bending_curve`.

    Returns
    -------
    float or numpy.ndarray

    References
    ----------
    ISO 6336-3:2006, clause 12, Table 3.

    Examples
    --------
    >>> [round(bending_life_factor(n, "Eh"), 3) for n in (1e3, 3e6, 1e10)]
    [2.5, 1.0, 0.85]
    """
    return bending_curve(treatment, long_life=long_life).factor(cycles)


def miner_damage(cases: Iterable[tuple[float, float]], curve: SNCurve, reference_stress: float) -> float:
    """Palmgren–Miner damage D = Σ n_i / N_i of ``(stress, cycles)`` cases on ``curve``.

    N_i is the number of cycles at which ``curve.factor(N_i) = stress_i / reference_stress``.

    Parameters
    ----------
    cases : iterable of (float, float)
        (σ_i in N/mm², n_i load cycles) per load case.
    curve : SNCurve
        Z_NT or Y_NT curve of the material.
    reference_stress : float
        The stress the flank or root endures at the reference number of cycles
        (σ_HG or σ_FG with life factor 1), N/mm².

    Returns
    -------
    float
        D (≥ 0); ``math.inf`` if a case exceeds the static strength.

    Raises
    ------
    RatingError
        A negative stress or number of cycles, a non-positive reference stress.

    References
    ----------
    ISO 6336-6:2019, clause 5, eq. (1) (Palmgren–Miner).
    """
    if not reference_stress > 0 or not math.isfinite(reference_stress):
        raise RatingError(f"damage: reference_stress must be a positive number of N/mm², got {reference_stress!r}.")
    total = 0.0
    for stress, cycles in cases:
        if not (stress >= 0 and cycles >= 0) or not (math.isfinite(stress) and math.isfinite(cycles)):
            raise RatingError(f"damage: each case needs a stress >= 0 and a number of cycles >= 0, got "
                              f"({stress!r}, {cycles!r}).")
        if stress == 0 or cycles == 0:
            continue
        failure = curve.cycles_to_failure(stress / reference_stress)
        if failure == 0.0:
            return math.inf
        total += cycles / failure
    return total


def pitting_damage(cases: Iterable[tuple[float, float]], reference_stress: float, treatment: str, *,
                   pitting_permitted: bool = False, long_life: str = "standard") -> float:
    """Flank damage sum over ``(sigma_H, cycles)`` cases (Palmgren–Miner on the Z_NT curve).

    Parameters
    ----------
    cases : iterable of (float, float)
        (σ_H in N/mm², n load cycles of the flank) per load case.
    reference_stress : float
        σ_HG at life factor 1: σ_Hlim Z_L Z_v Z_R Z_W Z_X, N/mm².
    treatment : str
        ISO 6336-5 symbol of the material.
    pitting_permitted, long_life
        See :func:`pitting_curve`.

    Returns
    -------
    float
        D; the flank is expected to last while D < 1.

    References
    ----------
    ISO 6336-6:2019, clause 5; ISO 6336-2:2006, clause 10.

    Examples
    --------
    Half the cycles to failure at 1.3 σ_ref (curve "Eh" without pitting: 1.3 at 2.24·10^6):

    >>> n = pitting_curve("Eh").cycles_to_failure(1.3)
    >>> round(pitting_damage([(1300.0, n / 2)], 1000.0, "Eh"), 6)
    0.5
    """
    return miner_damage(cases, pitting_curve(treatment, pitting_permitted=pitting_permitted, long_life=long_life),
                        reference_stress)


def bending_damage(cases: Iterable[tuple[float, float]], reference_stress: float, treatment: str, *,
                   long_life: str = "standard") -> float:
    """Root damage sum over ``(sigma_F, cycles)`` cases (Palmgren–Miner on the Y_NT curve).

    Parameters
    ----------
    cases : iterable of (float, float)
        (σ_F in N/mm², n load cycles of the root) per load case.
    reference_stress : float
        σ_FG at life factor 1: σ_Flim Y_ST Y_δrelT Y_RrelT Y_X (Y_M), N/mm².
    treatment : str
        ISO 6336-5 symbol of the material.
    long_life : {"standard", "optimum"}
        See :func:`bending_curve`.

    Returns
    -------
    float
        D; the root is expected to last while D < 1.

    References
    ----------
    ISO 6336-6:2019, clause 5; ISO 6336-3:2006, clause 12.
    """
    return miner_damage(cases, bending_curve(treatment, long_life=long_life), reference_stress)
