"""Tooth counts for fitted stationary ratios (reusing the geometry package's search).

Simple sets: :func:`epicyclic.geometry.search_teeth` in the mode "carrier held,
sun drives ring" (whose ratio is i0) gives every standard set within the
bounds that meets i0 within the tolerance and passes coaxiality, equal-spacing
assembly, neighbour clearance, undercut and internal interference.  Plus
(double-planet) sets: the nearest fractions z_ring/z_sun within the bounds (the
geometry package has no double-planet search yet; their fit is not checked).

The options of all sets are then combined and the combination whose *gear*
ratios (with the exact tooth-count i0) are closest to the targets is kept
(:func:`choose_teeth`), vectorised over all combinations.

References
----------
SDP/SI D785 eqs. (13-5), (13-7), (13-9) (via :mod:`epicyclic.geometry.search`);
Kahraman et al. 2004, J. Mech. Des. 126(6), section 3.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np

from .kinematics import gear_ratios
from .mechanisms import Mechanism

__all__ = ["SetTeeth", "tooth_options", "choose_teeth"]


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


def choose_teeth(mechanism: Mechanism, input: int, output: int, combos: np.ndarray, schedule: tuple[int, ...],
                 targets: np.ndarray, options: list[list[SetTeeth]], tolerance: float
                 ) -> tuple[tuple[SetTeeth, ...], np.ndarray, float] | None:
    """The combination of per-set options whose gear ratios are closest to the targets.

    Returns (teeth per set, gear ratios, largest relative error) or None when
    no combination meets every target within ``tolerance``.
    """
    if any(not o for o in options):
        return None
    grid = list(itertools.product(*options))
    ratios = np.array([[t.stationary_ratio for t in row] for row in grid])
    gears = gear_ratios(mechanism, ratios, combos[list(schedule)], input, output)  # (P, G)
    with np.errstate(invalid="ignore"):
        error = np.nanmax(np.abs(gears / targets - 1.0), axis=1)
    error = np.where(np.all(np.isfinite(gears), axis=1), error, np.inf)
    best = int(np.argmin(error))
    if not error[best] <= tolerance * (1 + 1e-9):
        return None
    return tuple(grid[best]), gears[best], float(error[best])
