"""Statics: port and external torques for a loss-direction pattern.

Unknowns are the torques at every element port and the external torques at
drives, loads and the housing.  Rows: each lever's torque ratio with
η0^w and its torque sum, each link's torque pair, torque balance at every
shaft, and one row per given external torque.

References
----------
Brandenberger 1952, eqs. 2, 7, 7', 8, 9; Queitsch, eqs. 26–29.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..errors import ContradictionError, UnderdeterminedError
from ..model.elements import HOUSING
from .assembly import TrainMatrices
from .linear import Pseudoinverse, pseudoinverse

__all__ = ["TorqueSolver", "torque_solver"]


def _system(mats: TrainMatrices, given: Sequence[str], pattern) -> np.ndarray:
    base = mats.statics(pattern)
    rows = np.zeros((len(given), base.shape[1]))
    for r, shaft in enumerate(given):
        rows[r, mats.external_column(shaft)] = 1.0
    return np.vstack([base, rows])


@dataclass(frozen=True, eq=False)
class TorqueSolver:
    """Linear map from given external torques to all torques, for one pattern.

    Attributes
    ----------
    indeterminate : tuple of str
        Elements whose internal torque split the equations leave open (e.g. a
        set locked by two clutches); the minimum-norm split is used, which
        does not change any external torque or loss.
    """

    mats: TrainMatrices
    given: tuple[str, ...]
    pattern: tuple[int, ...] | None
    system: Pseudoinverse
    indeterminate: tuple[str, ...]

    @property
    def operator(self) -> np.ndarray:
        """Matrix S with x = S @ given torques."""
        rows = self.system.matrix.shape[0] - len(self.given)
        return self.system.inverse[:, rows:]

    def torques(self, values: Sequence[float] | np.ndarray) -> np.ndarray:
        return self.operator @ np.asarray(values, dtype=float)

    def check(self, values: Sequence[float] | np.ndarray, x: np.ndarray) -> None:
        """Raise ContradictionError if the given torques cannot all hold."""
        g = np.asarray(values, dtype=float)
        rows = self.system.matrix.shape[0] - len(self.given)
        rhs = np.concatenate([np.zeros((rows,) + g.shape[1:]), g])
        scale = np.max(np.abs(g), axis=0) if g.size else 1.0
        ok = self.system.is_consistent(x, rhs, scale)
        if np.all(ok):
            return
        if g.ndim > 1:
            first = int(np.flatnonzero(~np.asarray(ok))[0])
            g = g[:, first]
        culprits = []
        for k, shaft in enumerate(self.given):
            others = [s for j, s in enumerate(self.given) if j != k]
            sub = pseudoinverse(_system(self.mats, others, self.pattern))
            sub_rhs = np.concatenate([np.zeros(rows), np.delete(g, k)])
            if sub.is_consistent(sub.inverse @ sub_rhs, sub_rhs, float(np.max(np.abs(g)))):
                culprits.append(shaft)
        culprits = culprits or list(self.given)
        if len(self.given) == 1:
            shaft = self.given[0]
            raise ContradictionError(
                f"the torque given at {shaft!r} cannot be balanced: no other shaft of the train takes "
                "torque from outside. Name the shafts where power leaves (loads) or enters (drives), "
                "or hold a shaft with a brake.",
                culprits,
                "torque",
            )
        raise ContradictionError(
            "the given torques/powers contradict each other: at "
            + ", ".join(repr(s) for s in self.given)
            + " they cannot all hold, because the train's torque balance fixes their ratio. "
            f"Give the torque or power at only one of {', '.join(repr(s) for s in culprits)} "
            "and mark the other as a drive or load without a value.",
            culprits,
            "torque",
        )


def torque_solver(mats: TrainMatrices, given: Sequence[str], pattern: Sequence[int] | None = None) -> TorqueSolver:
    """Prepare the torque solution; raise if an external torque stays free.

    Raises
    ------
    UnderdeterminedError
        Too few torques or powers are given: the message names the shafts.
    """
    given = tuple(given)
    key = None if pattern is None else tuple(int(w) for w in pattern)
    system = pseudoinverse(_system(mats, given, key))
    columns = mats.torque_columns
    free = system.free_columns()
    free_external = [columns[c][1] for c in free if columns[c][0] == "external"]
    if free_external:
        missing = len(mats.torque_columns) - system.rank
        shown = [s for s in free_external if s != HOUSING] or free_external
        raise UnderdeterminedError(
            f"the torques at shaft(s) {', '.join(repr(s) for s in shown)} are not determined "
            f"({'only ' + ', '.join(repr(s) for s in given) if given else 'no torque or power'} given): "
            f"give a torque or power at {missing} more of {', '.join(repr(s) for s in shown)}.",
            shown,
            "torque",
        )
    indeterminate = tuple(dict.fromkeys(columns[c][1] for c in free if columns[c][0] == "port"))
    return TorqueSolver(mats, given, key, system, indeterminate)
