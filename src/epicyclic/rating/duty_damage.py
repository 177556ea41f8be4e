"""Palmgren–Miner damage sums of every gear's flank and root over a duty cycle.

For each mesh with geometry and each of its two gears, the tooth rating of
:mod:`epicyclic.rating.train` (ISO 6336 Method B) is evaluated over all load
cases of a gear at once (:func:`~epicyclic.rating.train.rate_batch`).  Per case
i it gives the contact stress σ_H,i and the root stress σ_F,i, the stresses the
flank and the root endure at the life factor 1,

.. math:: \\sigma_{H,ref} = \\frac{\\sigma_{HG}}{Z_{NT}} = \\sigma_{Hlim} Z_L Z_v Z_R Z_W Z_X, \\qquad
          \\sigma_{F,ref} = \\frac{\\sigma_{FG}}{Y_{NT}} = \\sigma_{Flim} Y_{ST} Y_{\\delta relT} Y_{RrelT} Y_X Y_M

(Z_v with the case's speed), and the load cycles n_i = 60 t_i n_rel,i c (t_i the
case's hours, n_rel the gear's speed relative to the carrier, c the contacts
per revolution: N_planets for a central gear).  The damage is

.. math:: D = \\sum_i \\frac{n_i}{N_i}, \\qquad Z_{NT}(N_i) = \\sigma_{H,i}/\\sigma_{H,ref,i}
          \\;(\\text{flank}), \\quad Y_{NT}(N_i) = \\sigma_{F,i}/\\sigma_{F,ref,i} \\;(\\text{root})

on the material's S–N curve (:mod:`epicyclic.rating.life_factors`); the gear is
expected to last the cycle while D < 1.  A cycle given by shares alone runs for
the rating's required life (``[rating] life``).

What is not separated: the drive and the coast flank (a reverse or coasting
case loads the other flank; here every case counts on one flank, which is
conservative); a stress below the endurance limit does no damage where the
curve is flat (``long_life = "optimum"``), and the standard's sloped line
beyond the reference cycles otherwise.

References
----------
ISO 6336-6:2019, clauses 4 and 5 (load spectrum, Palmgren–Miner); ISO 6336-2:2019, eq. (4) and clause 10;
ISO 6336-3:2019, eq. (5) and clause 12; Palmgren 1924, Miner 1945.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from .life_factors import SNCurve, miner_damage
from .train import mesh_inputs, rate_batch

__all__ = ["DAMAGE_HEAD", "GearDamage", "gear_damages"]

DAMAGE_HEAD = ["set", "mesh", "gear", "D flank", "D root", "max sigma_H [N/mm^2]", "max sigma_F [N/mm^2]",
               "cycles"]


def _finite(value: float) -> float | None:
    return float(value) if math.isfinite(value) else None


@dataclass(frozen=True, eq=False)
class GearDamage:
    """One gear of one mesh over a duty cycle.

    Attributes
    ----------
    element, mesh, gear : str
        The set or stage, the mesh and the gear.
    cycles : ndarray
        Load cycles of the gear per case.
    sigma_H, sigma_F : ndarray
        Contact and root stress per case, N/mm².
    flank_ratio, root_ratio : ndarray
        σ_H/σ_H,ref and σ_F/σ_F,ref per case (the life factor each case needs).
    flank_curve, root_curve : SNCurve
        The material's Z_NT and Y_NT curves.
    S_H, S_F : ndarray, optional
        Safety for pitting and tooth root per case (ISO 6336-2, eq. (4); -3, eq. (5)).
    S_Hmin, S_Fmin : float, default 1.0, 1.4
        The rating's minimum safeties.
    """

    element: str
    mesh: str
    gear: str
    cycles: np.ndarray
    sigma_H: np.ndarray
    sigma_F: np.ndarray
    flank_ratio: np.ndarray
    root_ratio: np.ndarray
    flank_curve: SNCurve
    root_curve: SNCurve
    S_H: np.ndarray | None = None
    S_F: np.ndarray | None = None
    S_Hmin: float = 1.0
    S_Fmin: float = 1.4

    @property
    def flank_damage(self) -> float:
        """D of the flank (pitting), Σ n_i/N_i."""
        return miner_damage(zip(self.flank_ratio.tolist(), self.cycles.tolist()), self.flank_curve, 1.0)

    @property
    def root_damage(self) -> float:
        """D of the tooth root (bending), Σ n_i/N_i."""
        return miner_damage(zip(self.root_ratio.tolist(), self.cycles.tolist()), self.root_curve, 1.0)

    def row(self) -> list[object]:
        """A row of :data:`DAMAGE_HEAD` (a sum D >= 1 marked ``!``)."""
        def mark(d: float) -> str:
            return f"{d:.4g}" + (" !" if not d < 1.0 else "")

        return [self.element, self.mesh, self.gear, mark(self.flank_damage), mark(self.root_damage),
                f"{float(np.max(self.sigma_H)):.1f}", f"{float(np.max(self.sigma_F)):.1f}",
                f"{float(np.sum(self.cycles)):.4g}"]

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready: the damage sums and per case σ_H, σ_F, cycles (an infinite damage is null)."""
        return {"element": self.element, "mesh": self.mesh, "gear": self.gear,
                "D_H": _finite(self.flank_damage), "D_F": _finite(self.root_damage),
                "cases": [{"sigma_H": {"value": float(h), "unit": "N/mm^2"},
                           "sigma_F": {"value": float(f), "unit": "N/mm^2"}, "N": float(n),
                           **({} if self.S_H is None else {"S_H": _finite(float(self.S_H[k])),
                                                           "S_F": _finite(float(self.S_F[k]))})}
                          for k, (h, f, n) in enumerate(zip(self.sigma_H, self.sigma_F, self.cycles))]}


def _values(factor, count: int) -> np.ndarray:
    return np.broadcast_to(np.asarray(factor.value, dtype=float), (count,)).copy()


@dataclass(frozen=True)
class _AllCases:
    """The cases of several batch solutions (one per gear) as one, in the duty cycle's order: what
    :func:`~epicyclic.rating.train.rate_batch` reads (the train's elements, port torques, shaft speeds)."""

    train: Any
    port_torques: Any
    speeds: Any


def _all_cases(groups, count: int) -> _AllCases:
    ports: dict[tuple[str, str], np.ndarray] = {}
    speeds: dict[str, np.ndarray] = {}
    train = None
    for batch, members in groups:
        idx = np.asarray(members)
        train = batch.train if train is None else train
        for key, value in batch.port_torques.items():
            ports.setdefault(key, np.zeros(count))[idx] = np.asarray(value).reshape(-1)
        for shaft, value in batch.speeds.items():
            speeds.setdefault(shaft, np.zeros(count))[idx] = np.asarray(value).reshape(-1)
    return _AllCases(train, ports, speeds)


def gear_damages(groups, count: int, hours: np.ndarray, geometry, spec) -> tuple[GearDamage, ...]:
    """Damage sums of every gear over the cases of all groups.

    All cases are rated in one :func:`~epicyclic.rating.train.rate_batch` call (the gears of a
    transmission differ in their shift elements only, not in their sets and stages).

    Parameters
    ----------
    groups : sequence of (BatchSolution, sequence of int)
        Each batch solution and the indices of the duty cycle's cases it holds.
    count : int
        Number of cases.
    hours : ndarray
        Hours of each case.
    geometry : mapping element → SetGeometry or StageGeometry
        The train's gear geometry.
    spec : RatingSpec
        The tooth rating inputs.

    Returns
    -------
    tuple of GearDamage

    References
    ----------
    ISO 6336-6:2019, clause 5.
    """
    planned = mesh_inputs(geometry, spec)
    curves = {(p.input.element, p.input.name): (p.input.static["Z_curves"], p.input.static["Y_curves"])
              for p in planned[0]}
    data: dict[tuple[str, str, str], dict[str, Any]] = {}
    order: list[tuple[str, str, str]] = []
    rating = rate_batch(_all_cases(groups, count), geometry, spec, planned=planned)
    for mesh in rating.meshes:
        for k, gear in enumerate(mesh.gears):
            key = (mesh.element, mesh.mesh, gear.gear)
            f = gear.factors
            sigma_h, sigma_f = _values(f["sigma_H"], count), _values(f["sigma_F"], count)
            data[key] = {
                "k": k, "sigma_H": sigma_h, "sigma_F": sigma_f,
                "fr": sigma_h / (_values(f["sigma_HG"], count) / _values(f["Z_NT"], count)),
                "rr": sigma_f / (_values(f["sigma_FG"], count) / _values(f["Y_NT"], count)),
                # N_L = 60 L_h n c over the rating's life: per hour N_L / L_h, times the case's hours
                "cycles": _values(f["N_L"], count) / spec.life * hours,
                "S_H": _values(f["S_H"], count), "S_F": _values(f["S_F"], count),
            }
            order.append(key)
    out = []
    for element, mesh, gear in order:
        d = data[(element, mesh, gear)]
        k = int(d["k"])  # type: ignore[arg-type]
        z_curves, y_curves = curves[(element, mesh)]
        out.append(GearDamage(element, mesh, gear, d["cycles"], d["sigma_H"], d["sigma_F"], d["fr"], d["rr"],
                              z_curves[k], y_curves[k], d["S_H"], d["S_F"], spec.S_Hmin, spec.S_Fmin))
    return tuple(out)
