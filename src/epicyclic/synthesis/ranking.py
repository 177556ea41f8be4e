"""Ranking synthesised transmissions by what decides a layout: weighted criteria, Pareto front, explanations.

Every criterion is a figure the project's solver gives for the candidate
(:func:`~epicyclic.synthesis.candidate.evaluate`), smaller is better, and has a
*scale*: the difference an engineer would call one step (1 % of mean loss,
0.1 × P_in of circulating power, 1 × T_in of element torque, ...).  The score of
a candidate is

.. math:: S = \\sum_k w_k \\, v_k / s_k

with user weights w_k (default in :data:`CRITERIA`), so each term reads "so many
steps of this criterion" and the explanation of a rank is the list of terms
against the best candidate.  Beside the weighted rank, the Pareto front: the
candidates no other candidate beats on one criterion without losing on another
(weights do not enter it).

Criteria
--------
loss_mean
    1 − mean drive efficiency over the forward gears (the file's loss models;
    Brandenberger 1952, eqs. 7–10).
circulating_power
    Largest power circulating in a closed loop, any gear, × P_in (Brandenberger
    1952, text to Bild 11 and 12: "Blindleistung" loads the sets without moving
    the vehicle).
element_torque
    Largest torque on any engaged brake or clutch, × T_in.
element_capacity
    Sum over the shift elements of each one's largest torque, × T_in: the
    clutch-pack capacity the transmission must carry (each element is sized for
    its worst gear).
slip_speed
    Largest slip speed of an open element in a forward gear, × n_in (drag loss of
    open wet clutches grows with it; Naunheimer et al. 2011, section 10.4).
planet_speed
    Largest planet speed relative to its carrier, × n_in (planet bearings).
ring_balance
    Largest over smallest ring diameter, − 1 (packaging: sets of one size share
    a housing diameter).
ring_diameter
    Largest ring pitch diameter m·z_ring (ISO 21771), mm, with the module of each
    set from its torque (:mod:`~epicyclic.synthesis.sizing`), else the module given
    (``[ranking] module``), or from a sizing function (see :func:`rank`).
step_irregularity
    Largest change of the logarithmic ratio step between neighbouring steps
    (Naunheimer et al. 2011, section 6.2: steps that fall smoothly, geometric or
    progressive).
double_shifts
    Consecutive forward gears that swap more than one element (single-swap,
    clutch-to-clutch shifts; Naunheimer et al. 2011, section 12.3).

References
----------
Brandenberger, H. (1952), eqs. 7–10 and Bild 11/12; Naunheimer, H.; Bertsche, B.;
Ryborz, J.; Novak, W. (2011), *Automotive Transmissions*, 2nd ed., sections 6.2,
10.4, 12.3; ISO 21771:2007 (pitch diameter d = m·z); Deb, K. (2001),
*Multi-Objective Optimization using Evolutionary Algorithms*, section 2.4
(Pareto dominance).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

__all__ = ["Criterion", "CRITERIA", "Standing", "criterion_values", "rank", "pareto_front", "check_weights"]


@dataclass(frozen=True)
class Criterion:
    """One ranking criterion: its name, what it measures, its unit, scale and default weight."""

    name: str
    description: str
    unit: str
    scale: float
    weight: float


CRITERIA: tuple[Criterion, ...] = (
    Criterion("loss_mean", "mean forward drive loss", "× P_in", 0.01, 1.0),
    Criterion("circulating_power", "largest circulating power", "× P_in", 0.1, 1.0),
    Criterion("element_torque", "largest shift-element torque", "× T_in", 1.0, 1.0),
    Criterion("element_capacity", "summed shift-element capacity", "× T_in", 1.0, 1.0),
    Criterion("slip_speed", "largest open-element slip, forward gears", "× n_in", 1.0, 1.0),
    Criterion("planet_speed", "largest planet speed to its carrier", "× n_in", 1.0, 1.0),
    Criterion("ring_balance", "largest/smallest ring diameter − 1", "", 0.25, 1.0),
    Criterion("ring_diameter", "largest ring pitch diameter", "mm", 100.0, 1.0),
    Criterion("step_irregularity", "largest change of log ratio step", "", 0.1, 1.0),
    Criterion("double_shifts", "shifts swapping more than one element", "", 1.0, 10.0),
)
_BY_NAME = {c.name: c for c in CRITERIA}


def check_weights(weights: Mapping[str, Any] | None, error: Callable[[str, str], Exception]) -> dict[str, float]:
    """Validated weights: known criterion names, finite numbers ≥ 0; the rest keep their defaults.

    Parameters
    ----------
    weights : mapping name → number, optional
    error : callable (name, message) → Exception
        Builds the error naming the key (the spec's place).

    Returns
    -------
    dict
        Every criterion's weight.
    """
    out = {c.name: c.weight for c in CRITERIA}
    for name, value in (weights or {}).items():
        if name not in _BY_NAME:
            raise error(str(name), f"unknown criterion; use {', '.join(_BY_NAME)}.")
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not (math.isfinite(value) and value >= 0):
            raise error(str(name), f"a weight is a finite number >= 0 (0 leaves the criterion out), got {value!r:.40}.")
        out[name] = float(value)
    return out


def criterion_values(candidate: Any, module: float, diameters: Callable[[Any], Sequence[float]] | None = None
                     ) -> dict[str, float]:
    """The criteria of one evaluated candidate (smaller is better; inf where a gear self-locks).

    Parameters
    ----------
    candidate : Candidate
        With :attr:`~epicyclic.synthesis.candidate.Candidate.metrics` filled by ``evaluate``.
    module : float
        Module of every set, mm, for the ring diameters m·z_ring.
    diameters : callable (candidate) → ring pitch diameters in mm, optional
        A sizing function to use instead of the fixed module (the hook for a load-capacity sizing).

    Returns
    -------
    dict
        One value per criterion of :data:`CRITERIA`.
    """
    m = candidate.metrics
    eff = m.get("efficiency_mean")
    if diameters is not None:
        rings = list(diameters(candidate))
    else:  # the sized module of each set, else the given one
        sizes = getattr(candidate, "sizes", ()) or (None,) * len(candidate.teeth)
        rings = [(z.module if z is not None else module) * t.z_ring for t, z in zip(candidate.teeth, sizes)]
    return {
        "loss_mean": 1.0 - eff if eff is not None else math.inf,
        "circulating_power": m.get("circulating_power_max", 0.0),
        "element_torque": m.get("element_torque_max", 0.0),
        "element_capacity": m.get("element_capacity", 0.0),
        "slip_speed": m.get("slip_speed_max", 0.0),
        "planet_speed": m.get("planet_speed_max", 0.0),
        "ring_balance": max(rings) / min(rings) - 1.0 if rings else 0.0,
        "ring_diameter": max(rings, default=0.0),
        "step_irregularity": m.get("step_irregularity", 0.0),
        "double_shifts": float(m.get("double_shifts", 0)),
    }


@dataclass(frozen=True)
class Standing:
    """Where one candidate stands: its criteria, weighted terms, score and Pareto status.

    Attributes
    ----------
    rank : int
        1 is the best score.
    score : float
        Σ weight · value / scale (smaller is better).
    values : mapping name → float
        The criteria (:data:`CRITERIA` units).
    terms : mapping name → float
        weight · value / scale per criterion.
    pareto : bool
        No other candidate is at least as good on every criterion and better on one.
    dominated_by : int or None
        Rank of the best-ranked candidate that dominates this one.
    """

    rank: int
    score: float
    values: Mapping[str, float]
    terms: Mapping[str, float]
    pareto: bool
    dominated_by: int | None

    def explain(self, best: Standing | None = None, count: int = 3) -> str:
        """Why the candidate ranks where it does: score, the criteria that cost it most against ``best``.

        Parameters
        ----------
        best : Standing, optional
            The candidate compared with (default: none; the largest terms are named).
        count : int, default 3
            Criteria named.

        Returns
        -------
        str
        """
        pareto = "on the Pareto front" if self.pareto else f"dominated by #{self.dominated_by}"
        if best is None or best.rank == self.rank:
            parts = sorted(self.terms.items(), key=lambda kv: -kv[1])[:count]
            named = ", ".join(f"{_BY_NAME[k].description} {_value(k, self.values[k])} ({v:.2f})" for k, v in parts
                              if v > 0)
            return f"#{self.rank}: score {self.score:.2f}, {pareto}; largest terms: {named or 'none'}"
        diff = {k: self.terms[k] - best.terms[k] for k in self.terms}
        worse = [k for k, v in sorted(diff.items(), key=lambda kv: -kv[1]) if v > 1e-9][:count]
        better = [k for k, v in sorted(diff.items(), key=lambda kv: kv[1]) if v < -1e-9][:count]
        text = f"#{self.rank}: score {self.score:.2f} ({self.score - best.score:+.2f} against #{best.rank}), {pareto}"
        if worse:
            text += "; behind on " + ", ".join(f"{_BY_NAME[k].description} {_value(k, self.values[k])} vs "
                                               f"{_value(k, best.values[k])} ({diff[k]:+.2f})" for k in worse)
        if better:
            text += "; ahead on " + ", ".join(f"{_BY_NAME[k].description} {_value(k, self.values[k])} "
                                              f"({diff[k]:+.2f})" for k in better)
        return text

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready (infinite values, for self-locking gears, as None)."""
        def clean(v: float) -> float | None:
            return v if math.isfinite(v) else None

        return {"rank": self.rank, "score": clean(self.score), "pareto": self.pareto,
                "dominated_by": self.dominated_by, "criteria": {k: clean(v) for k, v in self.values.items()},
                "terms": {k: clean(v) for k, v in self.terms.items()}}


def _value(name: str, value: float) -> str:
    unit = _BY_NAME[name].unit
    if name == "double_shifts":
        return f"{value:.0f}"
    if name == "loss_mean":
        return f"{100 * value:.2f} %"
    return f"{value:.3g}{' ' + unit if unit else ''}"


def pareto_front(vectors: Sequence[Sequence[float]]) -> list[int | None]:
    """For each vector, None when no other dominates it, else the first index that does.

    a dominates b when a ≤ b in every component and a < b in at least one (Deb 2001, def. 2.5).

    Parameters
    ----------
    vectors : sequence of sequences of float
        One per candidate, in rank order (so the dominator named is the best-ranked one).

    >>> pareto_front([[1, 2], [2, 1], [2, 2], [1, 2]])
    [None, None, 0, None]
    """
    out: list[int | None] = []
    for b in vectors:
        found = None
        for j, a in enumerate(vectors):
            if all(x <= y for x, y in zip(a, b)) and any(x < y for x, y in zip(a, b)):
                found = j
                break
        out.append(found)
    return out


def rank(candidates: Sequence[Any], weights: Mapping[str, float] | None = None, module: float = 2.0,
         diameters: Callable[[Any], Sequence[float]] | None = None) -> tuple[tuple[Any, ...], tuple[Standing, ...]]:
    """Candidates sorted by weighted score, with their standings (ties: fewer shafts, then the canonical key).

    Parameters
    ----------
    candidates : sequence of Candidate
        Evaluated (metrics filled).
    weights : mapping name → float, optional
        Per criterion (default :data:`CRITERIA`'s; 0 leaves a criterion out of score and front).
    module : float, default 2.0
        mm, for the ring diameters.
    diameters : callable, optional
        Ring pitch diameters per candidate, mm, from a sizing function (instead of ``module``).

    Returns
    -------
    candidates, standings : tuple, tuple of Standing
        In rank order.
    """
    w = {c.name: c.weight for c in CRITERIA}
    w.update(weights or {})
    rows = []
    for cand in candidates:
        values = criterion_values(cand, module, diameters)
        terms = {c.name: (w[c.name] * values[c.name] / c.scale if w[c.name] else 0.0) for c in CRITERIA}
        rows.append((sum(terms.values()), cand.metrics.get("shafts", 99), cand.key, cand, values, terms))
    rows.sort(key=lambda r: (round(r[0], 9), r[1], r[2]))
    active = [c.name for c in CRITERIA if w[c.name] > 0]
    front = pareto_front([[r[4][k] for k in active] for r in rows])
    standings = tuple(Standing(k + 1, r[0], MappingProxyType(r[4]), MappingProxyType(r[5]), front[k] is None,
                               None if front[k] is None else front[k] + 1) for k, r in enumerate(rows))
    return tuple(r[3] for r in rows), standings
