"""Statics: port and external torques for a loss-direction pattern.

Unknowns are the torques at every element port and the external torques at
drives and loads.  Rows: each lever's two torque ratios with η0^w, each
link's torque pair, torque balance at every moving shaft, and one row per
given external torque (see :mod:`epicyclic.solver.assembly`).  Ports that can
carry no torque (idle elements) get exactly 0; equations too close to
singular raise :class:`~epicyclic.errors.NearSingularError`.

References
----------
Brandenberger 1952, eqs. 2, 7, 7', 8, 9; Queitsch, eqs. 26–29.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..errors import ContradictionError, NearSingularError, UnderdeterminedError
from .assembly import TrainMatrices
from .linear import Pseudoinverse, apply, pseudoinverse, row_products, unreached_columns

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

    @cached_property
    def operator(self) -> np.ndarray:
        """Matrix S with x = S @ given torques; rows of idle ports exactly 0."""
        rows = self.system.matrix.shape[0] - len(self.given)
        unit = np.zeros((self.system.matrix.shape[0], len(self.given)))
        unit[rows:] = np.eye(len(self.given))
        s = self.system.solve(unit)
        s[self.mats.idle_columns(self.pattern)] = 0.0
        s[unreached_columns(self.mats.statics(self.pattern),
                            [self.mats.external_column(g) for g in self.given])] = 0.0
        return s

    @cached_property
    def row_operator(self) -> np.ndarray:
        """Matrix R with x = R @ r for a right-hand side r of the static rows (given loss torques).

        Unlike :attr:`operator`, no port is zeroed as idle: a loss torque loads even
        an element that transmits nothing (see :mod:`epicyclic.solver.given_losses`).
        """
        rows = self.system.matrix.shape[0] - len(self.given)
        unit = np.zeros((self.system.matrix.shape[0], rows))
        unit[:rows] = np.eye(rows)
        return self.system.solve(unit)

    def torques(self, values: Sequence[float] | np.ndarray, rows: np.ndarray | None = None) -> np.ndarray:
        """All torques for given external torques and, optionally, a right-hand side of the static rows."""
        x = apply(self.operator, np.asarray(values, dtype=float))
        return x if rows is None else x + self.row_operator @ rows

    @cached_property
    def _rows(self) -> list[list[float]] | None:
        """:attr:`operator` as lists of rows where one torque is given (see :meth:`point`)."""
        return self.operator.tolist() if self.operator.shape[1] == 1 else None

    def point(self, values: Sequence[float], rows: np.ndarray | None = None) -> list[float]:
        """:meth:`torques` of one point in Python floats (a list; ``rows``, if given, one column)."""
        if rows is None and self._rows is not None:
            return row_products(self._rows, values)
        return self.torques(values, rows).tolist()

    def check(self, values: Sequence[float] | np.ndarray, x: np.ndarray, loss_rows: np.ndarray | None = None) -> None:
        """Raise ContradictionError if the given torques (and loss torques) cannot all hold."""
        if self.system.rank == self.system.matrix.shape[0]:
            return  # full row rank: every right-hand side is reached (Pseudoinverse.is_consistent)
        g = np.asarray(values, dtype=float)
        rows = self.system.matrix.shape[0] - len(self.given)
        rhs = np.concatenate([np.zeros((rows,) + g.shape[1:]) if loss_rows is None else loss_rows, g])
        scale = np.max(np.abs(g), axis=0) if g.size else 1.0
        ok = self.system.is_consistent(np.asarray(x, dtype=float), rhs, scale)
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
    if ("torque", given, key) in mats.solvers:
        return mats.solvers[("torque", given, key)]
    system = pseudoinverse(_system(mats, given, key))
    columns = mats.torque_columns
    free = system.free_columns()
    free_external = [columns[c][1] for c in free if columns[c][0] == "external"]
    if system.near_singular and not free_external:
        raise _near_singular(mats, system)
    if free_external:
        missing = len(mats.torque_columns) - system.rank
        shown = free_external
        raise UnderdeterminedError(
            f"the torques at shaft(s) {', '.join(repr(s) for s in shown)} are not determined "
            f"({'only ' + ', '.join(repr(s) for s in given) if given else 'no torque or power'} given): "
            f"give a torque or power at {missing} more of {', '.join(repr(s) for s in shown)}.",
            shown,
            "torque",
        )
    indeterminate = tuple(dict.fromkeys(columns[c][1] for c in free if columns[c][0] == "port"))
    mats.solvers[("torque", given, key)] = TorqueSolver(mats, given, key, system, indeterminate)
    return mats.solvers[("torque", given, key)]


def _near_singular(mats: TrainMatrices, system) -> NearSingularError:
    distance, direction, row_weights = system.near_singular[-1]
    columns = mats.torque_columns
    big = np.flatnonzero(np.abs(direction) > 0.1 * np.abs(direction).max())
    elements = list(dict.fromkeys(columns[c][1] for c in big if columns[c][0] == "port"))
    shafts = [columns[c][1] for c in big if columns[c][0] == "external"]
    return NearSingularError(
        f"the torques of {', '.join(repr(e) for e in elements) or 'the train'} are fixed only by nearly "
        f"cancelling torque ratios (i0·η0 close to 1 where a set's carrier takes no torque, or ratios of a loop "
        f"that nearly cancel): the equations are {distance:.2g} (relative) from singular, so round-off would decide "
        f"the torques (amplified about {1 / distance:.1g} times). Check the ratios and efficiencies of "
        f"{', '.join(repr(e) for e in elements) or 'the elements'}.",
        "torque", distance, shafts, elements,
    )
