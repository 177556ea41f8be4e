"""Tooth counts for fitted stationary ratios (reusing the geometry package's search).

Simple sets: :func:`epicyclic.geometry.search_teeth` in the mode "carrier held,
sun drives ring" (whose ratio is i0) gives every standard set within the
bounds that meets i0 within the tolerance and passes coaxiality, equal-spacing
assembly, neighbour clearance, undercut and internal interference.  Plus
(double-planet) sets: the nearest fractions z_ring/z_sun within the bounds (the
geometry package has no double-planet search yet; their fit is not checked).

The options of all sets are then combined (:func:`choose_teeth`, vectorised over all
combinations): every combination whose *gear* ratios (with the exact tooth-count i0) meet
every target within the tolerance is admissible — fit, assembly and, when asked, hunting
teeth are hard constraints, met by every option.  Among the admissible ones the choice
minimises a stated weighted objective (:func:`tooth_objective`)

.. math:: J = w_e \\, \\frac{e}{\\mathrm{tol}} + w_b \\, \\frac{d_\\max/d_\\min - 1}{0.25}

with e the largest relative ratio error, tol the spec's tolerance, d the ring pitch
diameters m·z_ring (ISO 21771) and the weights ``[teeth] ratio_error`` and
``ring_balance`` (:data:`TOOTH_WEIGHTS`, both 1 by default: one tolerance of ratio error
weighs as much as a quarter of ring-size imbalance, the scale of the ranking's
``ring_balance``).  The ring diameters come from the sizing: the combination with the
smallest ratio error is sized by ISO 6336 (:mod:`~epicyclic.synthesis.sizing`), and each
other option's sun diameter follows from it by the laws of the rating held at that set's
torque (:func:`ring_diameter`): pitting σ_H ∝ √(F_t (u+1)/(d b u)) with F_t = 2T/(N d)
and b ∝ d gives d ∝ (S_H (u+1)/(u N))^(1/3) (ISO 6336-2:2019, eq. (4)–(6)), root
σ_F ∝ F_t/(b m) gives d ∝ (S_F z_sun/N)^(1/3) (ISO 6336-3:2019, eq. (3)); the larger
governs, the module is the next ISO 54 module up.  The option chosen is then sized by
ISO 6336 in full, and the lower of its true objective and the reference's is kept.

References
----------
SDP/SI D785 eqs. (13-5), (13-7), (13-9) (via :mod:`epicyclic.geometry.search`);
Kahraman et al. 2004, J. Mech. Des. 126(6), section 3; ISO 6336-2:2019 eq. (4),
ISO 6336-3:2019 eq. (3); ISO 54:1996; ISO 21771:2007.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

import numpy as np

from .kinematics import gear_ratios
from .mechanisms import Mechanism

__all__ = ["SetTeeth", "TOOTH_WEIGHTS", "TOOTH_SCALES", "check_tooth_weights", "choose_teeth", "ring_diameter", "pick_teeth",
           "tooth_objective", "tooth_options"]

#: Default weights of the tooth choice's objective (``[teeth]`` of the spec).
TOOTH_WEIGHTS: Mapping[str, float] = MappingProxyType({"ratio_error": 1.0, "ring_balance": 1.0})
#: Scales: the ratio error per tolerance (1 = the whole tolerance), the ring balance per 0.25.
TOOTH_SCALES: Mapping[str, float] = MappingProxyType({"ring_balance": 0.25})


@dataclass(frozen=True)
class SetTeeth:
    """Tooth counts of one set: z_planet is None for a plus set (not checked)."""

    kind: str
    z_sun: int
    z_ring: int
    z_planet: int | None
    planets: int
    hunting: bool = False

    @property
    def stationary_ratio(self) -> float:
        return (-1.0 if self.kind == "simple" else 1.0) * self.z_ring / self.z_sun

    def to_dict(self) -> dict:
        return {"kind": self.kind, "z_sun": self.z_sun, "z_planet": self.z_planet, "z_ring": self.z_ring,
                "planets": self.planets, "stationary_ratio": self.stationary_ratio}


def tooth_options(stationary_ratio: float, kind: str, *, tolerance: float, sun: tuple[int, int],
                  planet: tuple[int, int], planets: tuple[int, ...], limit: int = 6,
                  hunting: bool = False) -> list[SetTeeth]:
    """Up to ``limit`` tooth-count sets with distinct ratios near ``stationary_ratio``, best first.

    With ``hunting`` only hunting-tooth simple sets (gcd(z_sun, z_planet) = gcd(z_planet, z_ring) = 1,
    every tooth meets every other: even wear) are offered.

    Examples
    --------
    >>> opts = tooth_options(-2.0, "simple", tolerance=0.005, sun=(17, 60), planet=(17, 60), planets=(3, 4))
    >>> (opts[0].z_sun, opts[0].z_planet, opts[0].z_ring, opts[0].stationary_ratio)
    (40, 20, 80, -2.0)
    """
    out: list[SetTeeth] = []
    seen: set[tuple[int, int]] = set()
    if kind == "simple":
        from ..geometry import search_teeth

        found = search_teeth(stationary_ratio, held="carrier", driver="sun", driven="ring", tolerance=tolerance,
                             z_sun=sun, z_planet=(3, planet[1]), planets=planets)
        for c in found.candidates:
            if c.z_planet < planet[0] or hunting and not c.hunting:
                continue
            key = (c.z_sun * 1000 + c.z_ring, 0)
            ratio_key = (round(c.z_ring / c.z_sun, 9), 0)
            if key in seen or ratio_key in seen:
                continue
            seen.update({key, ratio_key})
            out.append(SetTeeth("simple", c.z_sun, c.z_ring, c.z_planet, c.planets, c.hunting))
            if len(out) >= limit:
                break
        return out
    target = abs(stationary_ratio)
    rows = []
    for zs in range(sun[0], sun[1] + 1):
        zr = round(target * zs)
        if zr > zs and abs(zr / zs / target - 1) <= tolerance:
            rows.append((abs(zr / zs / target - 1), zr, zs))
    for _, zr, zs in sorted(rows):
        if (round(zr / zs, 9), 0) in seen:
            continue
        seen.add((round(zr / zs, 9), 0))
        out.append(SetTeeth("plus", zs, zr, None, planets[0]))
        if len(out) >= limit:
            break
    return out


def check_tooth_weights(weights: Mapping[str, Any] | None, error: Callable[[str, str], Exception]
                        ) -> dict[str, float]:
    """Validated weights of the tooth choice: known names, finite numbers ≥ 0; the rest keep their defaults.

    Parameters
    ----------
    weights : mapping name → number, optional
    error : callable (name, message) → Exception
        Builds the error naming the key.

    Returns
    -------
    dict
        Both weights.
    """
    import math

    out = dict(TOOTH_WEIGHTS)
    for name, value in (weights or {}).items():
        if name not in TOOTH_WEIGHTS:
            raise error(str(name), f"unknown; use {', '.join(TOOTH_WEIGHTS)}.")
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not (math.isfinite(value) and value >= 0):
            raise error(str(name), f"a weight is a finite number >= 0 (0 leaves the term out), got {value!r:.40}.")
        out[name] = float(value)
    return out


def tooth_objective(errors: np.ndarray, rings: np.ndarray, tolerance: float,
                    weights: Mapping[str, float] | None = None) -> np.ndarray:
    """J = w_e · e / tol + w_b · (d_max / d_min − 1) / 0.25 per combination (smaller is better).

    Parameters
    ----------
    errors : ndarray (P,)
        Largest relative ratio error of each combination.
    rings : ndarray (P, S)
        Ring pitch diameters, mm (NaN: a set without geometry, left out).
    tolerance : float
        The spec's relative tolerance.
    weights : mapping, optional
        ``ratio_error`` and ``ring_balance`` (default :data:`TOOTH_WEIGHTS`).

    Returns
    -------
    ndarray (P,)

    >>> tooth_objective(np.array([0.005]), np.array([[100.0, 125.0]]), 0.01).round(6).tolist()
    [1.5]
    """
    w = {**TOOTH_WEIGHTS, **dict(weights or {})}
    rings = np.asarray(rings, float)
    with np.errstate(invalid="ignore"):
        balance = np.nanmax(rings, axis=1) / np.nanmin(rings, axis=1) - 1.0 if rings.shape[1] else 0.0
    balance = np.nan_to_num(balance, nan=0.0)
    return w["ratio_error"] * np.asarray(errors, float) / tolerance + w["ring_balance"] * balance / TOOTH_SCALES[
        "ring_balance"]


def ring_diameter(option: SetTeeth, reference: SetTeeth, size: Any, s_hmin: float, s_fmin: float) -> float:
    """Ring pitch diameter (mm) of ``option`` from the ISO 6336 sizing of ``reference`` at the same torque.

    The needed sun diameter at the minimum safeties: pitting
    d_H = d_ref (S_Hmin/S_H)^(2/3) ((u+1)/(u N) / ((u_r+1)/(u_r N_r)))^(1/3), root
    d_F = d_ref (S_Fmin/S_F)^(1/3) ((z_s/N) / (z_s,r/N_r))^(1/3) (b ∝ d; ISO 6336-2 eq. (4),
    ISO 6336-3 eq. (3)); the module is the next ISO 54 module up from max(d_H, d_F)/z_sun.

    Parameters
    ----------
    option, reference : SetTeeth
        Simple sets (with planet teeth).
    size : SetSize
        The reference's sizing (module, lowest S_H and S_F).
    s_hmin, s_fmin : float
        Minimum safeties.

    Returns
    -------
    float
        m · z_ring, mm.

    Examples
    --------
    >>> from epicyclic.synthesis.sizing import SetSize
    >>> t = SetTeeth("simple", 30, 90, 30, 3)
    >>> ring_diameter(t, t, SetSize(2.0, 30.0, "1", 100.0, 1.0, 1.4), 1.0, 1.4)   # itself: its own ring
    180.0
    """
    from ..rating.sizing import ISO_54_MODULES

    def pitting(t: SetTeeth) -> float:
        u = t.z_planet / t.z_sun
        return (u + 1) / (u * t.planets)

    d_ref = size.module * reference.z_sun
    d_h = d_ref * (s_hmin / size.safety_pitting) ** (2 / 3) * (pitting(option) / pitting(reference)) ** (1 / 3)
    d_f = d_ref * (s_fmin / size.safety_bending) ** (1 / 3) * (
        (option.z_sun / option.planets) / (reference.z_sun / reference.planets)) ** (1 / 3)
    need = max(d_h, d_f) / option.z_sun
    module = next((m for m in ISO_54_MODULES if m >= need * (1 - 1e-12)), ISO_54_MODULES[-1])
    return module * option.z_ring


def choose_teeth(mechanism: Mechanism, input: int, output: int, combos: np.ndarray, schedule: tuple[int, ...],
                 targets: np.ndarray, options: list[list[SetTeeth]], tolerance: float
                 ) -> tuple[list[tuple[SetTeeth, ...]], np.ndarray, np.ndarray] | None:
    """Every combination of per-set options whose gear ratios meet every target within ``tolerance``.

    Returns (combinations, gear ratios (P, G), largest relative errors (P,)), smallest error
    first (ties: the order of the options, best first), or None when no combination is
    admissible.
    """
    if any(not o for o in options):
        return None
    grid = list(itertools.product(*options))
    ratios = np.array([[t.stationary_ratio for t in row] for row in grid])
    gears = gear_ratios(mechanism, ratios, combos[list(schedule)], input, output)  # (P, G)
    with np.errstate(invalid="ignore"):
        error = np.nanmax(np.abs(gears / targets - 1.0), axis=1)
    error = np.where(np.all(np.isfinite(gears), axis=1), error, np.inf)
    keep = np.flatnonzero(error <= tolerance * (1 + 1e-9))
    if not keep.size:
        return None
    keep = keep[np.argsort(error[keep], kind="stable")]
    return [grid[k] for k in keep], gears[keep], error[keep]


def pick_teeth(admissible: Sequence[tuple[SetTeeth, ...]], errors: np.ndarray, reference_sizes: Sequence[Any],
               tolerance: float, weights: Mapping[str, float], s_hmin: float, s_fmin: float) -> int:
    """Index of the admissible combination of least estimated objective (0: the reference, smallest error).

    Parameters
    ----------
    admissible : sequence of tuple of SetTeeth
        From :func:`choose_teeth`, the reference first.
    errors : ndarray (P,)
        Their largest relative ratio errors.
    reference_sizes : sequence of SetSize or None
        The ISO 6336 sizing of the reference, per set.
    tolerance : float
    weights : mapping
        Of :data:`TOOTH_WEIGHTS`.
    s_hmin, s_fmin : float
        Minimum safeties of the sizing.

    Returns
    -------
    int
    """
    reference = admissible[0]
    rings = np.array([[np.nan if size is None or t.z_planet is None else
                       ring_diameter(t, reference[k], size, s_hmin, s_fmin)
                       for k, (t, size) in enumerate(zip(row, reference_sizes))] for row in admissible])
    return int(np.argmin(tooth_objective(errors, rings, tolerance, weights)))
