"""Losses given to the solver from outside: efficiency factors by source and loss torques on shafts.

A loss model (e.g. :mod:`epicyclic.losses`) can hand the general solver, per
element and per operating point,

* efficiency factors by source (``{"mesh": η_m, "bearing": η_b}``) whose
  product replaces the element's η0 in Brandenberger's rule — applied in the
  direction of the rolling power like any η0;
* loss torques on shafts (``{shaft: T}``, the torque that acts on the shaft,
  opposing its motion: drag), which enter the shafts' torque balances; their
  reactions (on the housing or another shaft) are part of the same mapping.
  They may be given by source (``{source: {shaft: T}}``, e.g. ``clutch_drag``,
  ``churning``), and under the name ``"housing"`` for auxiliaries mounted in the
  housing that belong to no element (oil pump, shaft seals).

The solver reports every element's loss split by source: the rolling loss
P_w (1 − η0^w) is shared between the factors in proportion to their
logarithms (the factors multiply, so each one's share of ln η0 is its share of
the loss, whatever their order); the torques' loss is −Σ T ω (source
``"drag"``, or the source they are given by).  Without overrides the element's own η0 is the source ``"mesh"``.

References
----------
Brandenberger 1952, eqs. 3', 7 (the loss P_w (1 − η0^w)); ISO/TR 14179-2:2001
(the gearbox loss as the sum of load-dependent and no-load losses).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from functools import cached_property
from types import MappingProxyType

import numpy as np

from ..errors import EfficiencyError, ModelError
from ..model.elements import HOUSING, GearStage
from ..model.planetary import PlanetarySet
from ..model.train import GearTrain
from ..results.solution import RPM_TO_RAD_S
from .assembly import TrainMatrices

__all__ = ["GivenLosses", "given_losses", "with_efficiencies", "DRAG"]

#: Source name of the losses of given torques.
DRAG = "drag"
#: Source name of an element's own η0.
OWN = "mesh"


@dataclass(frozen=True, eq=False)
class GivenLosses:
    """Given losses resolved against a train's levers and shafts, points along the last axis.

    Attributes
    ----------
    factors : mapping source → ndarray (levers, P)
        1 where a lever has no factor of that source.
    efficiency : ndarray (levers, P)
        η0 of every lever: product of its factors (its own η0 where none is given).
    torques : ndarray (shafts, P)
        Sum of the given torques acting on each shaft (train order, housing last), N·m.
    element_torques : mapping element → ndarray (shafts, P)
    source_torques : mapping element → mapping source → ndarray (shafts, P)
        The same split by source (``drag`` for torques given without one).
    """

    factors: Mapping[str, np.ndarray]
    efficiency: np.ndarray
    torques: np.ndarray
    element_torques: Mapping[str, np.ndarray]
    source_torques: Mapping[str, Mapping[str, np.ndarray]] = field(default_factory=dict)

    @property
    def has_torques(self) -> bool:
        return bool(np.any(self.torques != 0.0))

    def rows(self, mats: TrainMatrices) -> np.ndarray:
        """Right-hand side of the static rows: −T in each moving shaft's balance (M − ΣT_port = −T).

        The rows are those of :meth:`TrainMatrices.statics`: two per lever, one
        per link, then one per moving shaft in ``train.moving_shafts`` order.
        """
        first = 2 * len(mats.levers) + len(mats.links)
        out = np.zeros((first + len(mats.train.moving_shafts), self.torques.shape[1]))
        for k, shaft in enumerate(mats.train.moving_shafts):
            out[first + k] = -self.torques[mats.layout.rows[shaft]]
        return out

    def drag_loss(self, name: str, speeds: np.ndarray, points: slice = slice(None)) -> np.ndarray:
        """Power lost by the given torques of element ``name``, W: −Σ T ω (≥ 0 for opposing torques).

        Parameters
        ----------
        name : str
            The element whose loss torques are meant; an element without any loses nothing.
        speeds : ndarray (shafts, points)
            Every shaft's speed, 1/min, in the train's shaft order, at the points ``points``.
        points : slice, default all
            Which of the batch's points ``speeds`` holds (the batch solver works in blocks).

        Returns
        -------
        ndarray (points,)
            The drag loss, W, at each point.

        References
        ----------
        ISO/TR 14179-2:2001 (no-load losses as torques that oppose the motion: P = T·ω).
        """
        torques = self.element_torques.get(name)
        if torques is None:
            return np.zeros(speeds.shape[1:])
        return -(torques[:, points] * speeds).sum(axis=0) * RPM_TO_RAD_S + 0.0

    def drag_losses(self, name: str, speeds: np.ndarray, points: slice = slice(None)) -> dict[str, np.ndarray]:
        """:meth:`drag_loss` split by the sources the torques were given by (``drag`` without one).

        Parameters
        ----------
        name : str
            The element (or ``"housing"`` for the auxiliaries).
        speeds : ndarray (shafts, points)
            Every shaft's speed, 1/min, in the train's shaft order.
        points : slice, default all
            Which of the batch's points ``speeds`` holds.

        Returns
        -------
        dict of str to ndarray
            Source → power lost, W, at each point.

        References
        ----------
        ISO/TR 14179-2:2001 (no-load losses as torques that oppose the motion: P = T·ω).
        """
        return {source: -(torques[:, points] * speeds).sum(axis=0) * RPM_TO_RAD_S + 0.0
                for source, torques in self.source_torques.get(name, {}).items()}

    @cached_property
    def _sources(self) -> tuple[tuple[str, ...], ...]:
        """Per lever: the sources with a factor other than 1 at some point."""
        return tuple(tuple(s for s, f in self.factors.items() if np.any(f[k] != 1.0))
                     for k in range(self.efficiency.shape[0]))

    def split(self, k: int, rolling_loss: np.ndarray, points: slice = slice(None)) -> dict[str, np.ndarray]:
        """The rolling loss of lever ``k`` by source (log shares of its factors).

        The factors multiply to the lever's η0, so each factor's share of ln η0 is its share of the
        loss P_w (1 − η0^w), whatever their order.

        Parameters
        ----------
        k : int
            Index of the lever (set or stage) among the train's levers.
        rolling_loss : ndarray (points,)
            The lever's rolling loss, W, at the points ``points``.
        points : slice, default all
            Which of the batch's points ``rolling_loss`` holds; every slice reports the same sources.

        Returns
        -------
        dict of str to ndarray
            Source (``"mesh"``, ``"bearing"``, ...) → its part of the loss, W; the parts add up to
            ``rolling_loss``.

        References
        ----------
        Brandenberger 1952, eqs. 3' and 7 (the loss P_w (1 − η0^w)).
        """
        logs = {s: np.log(self.factors[s][k, points]) for s in self._sources[k]}
        if not logs:
            return {OWN: rolling_loss}
        total = sum(logs.values())
        with np.errstate(divide="ignore", invalid="ignore"):
            return {s: np.where(total != 0, rolling_loss * v / total, 0.0) + 0.0 for s, v in logs.items()}


def _points(value: object, points: int) -> np.ndarray:
    """A number, or an array of the points in any shape (flattened), as an array of ``points`` values."""
    arr = np.asarray(value, dtype=float)
    return arr.ravel() if arr.size == points else np.broadcast_to(arr.ravel(), (points,))


def given_losses(mats: TrainMatrices, efficiencies: Mapping[str, Mapping[str, object]] | None,
                 loss_torques: Mapping[str, Mapping[str, object]] | None, points: int) -> GivenLosses | None:
    """Resolve ``efficiencies`` (element → source → η) and ``loss_torques`` (element → shaft → N·m).

    Parameters
    ----------
    mats : TrainMatrices
        The train's equations (its levers and shafts).
    efficiencies : mapping element → mapping source → float or array, or None
        Efficiency factors by source whose product replaces a set's or stage's η0; sets and stages
        not named keep their own η0 as the source ``"mesh"``.
    loss_torques : mapping element → mapping shaft → float or array, or None
        Torques (N·m) an element puts on shafts against their motion (drag), with their reactions;
        or element → source → shaft → torque, the loss reported by source.  The name ``"housing"``
        takes the torques of auxiliaries that belong to no element (pump, seals).
    points : int
        Number of operating points; every value is a number or an array of ``points`` values.

    Returns
    -------
    GivenLosses or None
        The factors, their product per lever and point, the shafts' loss torques (in all and per
        element); None when nothing is given.

    Raises
    ------
    ModelError
        An unknown element or shaft, an efficiency for a clutch or brake.
    EfficiencyError
        An efficiency outside (0, 1].
    """
    if not efficiencies and not loss_torques:
        return None
    levers = {lever.element.name: k for k, lever in enumerate(mats.levers)}
    names = {e.name for e in mats.train.elements}
    rows = mats.layout.rows

    def known(name: str, what: str) -> None:
        if name not in names:
            raise ModelError(f"given losses: the train has no element {name!r} ({what}); its elements are "
                             f"{', '.join(repr(n) for n in sorted(names))}.")

    own = np.array([lv.efficiency for lv in mats.levers], dtype=float)[:, None] * np.ones((1, points))
    factors: dict[str, np.ndarray] = {}
    replaced = np.zeros(len(mats.levers), dtype=bool)
    for name, by_source in (efficiencies or {}).items():
        known(name, "efficiencies")
        if name not in levers:
            raise ModelError(f"given losses: {name!r} is a clutch or brake; only sets and stages take an efficiency.")
        k = levers[name]
        replaced[k] = True
        for source, value in by_source.items():
            eta = _points(value, points)
            if not np.all((eta > 0.0) & (eta <= 1.0)):
                bad = float(eta[~((eta > 0.0) & (eta <= 1.0))][0])
                raise EfficiencyError(f"given losses: {source} efficiency of {name!r} must lie in (0, 1], got {bad!r}.")
            factors.setdefault(source, np.ones((len(mats.levers), points)))[k] = eta
    if np.any(~replaced):
        factors.setdefault(OWN, np.ones((len(mats.levers), points)))[~replaced] = own[~replaced]
    efficiency = np.ones((len(mats.levers), points))
    for value in factors.values():
        efficiency = efficiency * value
    torques = np.zeros((len(rows), points))
    per_element: dict[str, np.ndarray] = {}
    per_source: dict[str, dict[str, np.ndarray]] = {}
    for name, given in (loss_torques or {}).items():
        if name != HOUSING:
            known(name, "loss_torques")
        by_source = (given if given and all(isinstance(v, Mapping) for v in given.values())
                     else {DRAG: given})
        mine = np.zeros((len(rows), points))
        for source, by_shaft in by_source.items():
            part = np.zeros((len(rows), points))
            for shaft, value in by_shaft.items():
                if shaft not in rows:
                    raise ModelError(f"given losses: {name!r} puts a torque on {shaft!r}, which is not a shaft "
                                     "of the train.")
                value = _points(value, points)
                if not np.all(np.isfinite(value)):
                    raise ModelError(f"given losses: the torque of {name!r} on {shaft!r} must be finite.")
                part[rows[shaft]] += value
            per_source.setdefault(name, {})[source] = part
            mine += part
        per_element[name] = mine
        torques += mine
    return GivenLosses(MappingProxyType(factors), efficiency, torques, MappingProxyType(per_element),
                       MappingProxyType({k: MappingProxyType(v) for k, v in per_source.items()}))


def with_efficiencies(train: GearTrain, efficiencies: Mapping[str, float]) -> GearTrain:
    """``train`` with the efficiencies of some sets and stages replaced.

    Parameters
    ----------
    train : GearTrain
    efficiencies : mapping element name → float
        The new η0 of planetary sets (stationary efficiency) and gear stages; other names are ignored.

    Returns
    -------
    GearTrain
        A copy with the new efficiencies, or ``train`` itself where none changes (so that the
        solver's caches, keyed by the train, are reused).
    """
    elements = []
    for element in train.elements:
        eta = efficiencies.get(element.name)
        if isinstance(element, PlanetarySet) and eta is not None and eta != element.stationary_efficiency:
            element = replace(element, stationary_efficiency=float(eta))
        elif isinstance(element, GearStage) and eta is not None and eta != element.efficiency:
            element = replace(element, efficiency=float(eta))
        elements.append(element)
    changed = any(new is not old for new, old in zip(elements, train.elements))
    return replace(train, elements=tuple(elements)) if changed else train
