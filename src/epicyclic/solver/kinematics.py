"""Kinematics: every shaft speed from the given speeds (Willis equation per set).

The train's constraint rows K (one Willis row per lever, one equality per
engaged clutch or brake) and one row per given speed form A n = b.  The rank
of K gives the degrees of freedom; the null space of A names the shafts whose
speed is still free; a non-zero residual names the givens in conflict.

References
----------
Brandenberger 1952, eq. 1; Queitsch, eq. 12; tec-science, "Willis-Gleichung" (Grundgleichung).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from ..errors import ContradictionError, UnderdeterminedError
from ..model.elements import HOUSING
from .assembly import TrainMatrices
from .linear import Pseudoinverse, pseudoinverse

__all__ = ["SpeedSolver", "speed_solver", "degrees_of_freedom", "free_speed_shafts"]


def degrees_of_freedom(mats: TrainMatrices) -> int:
    """Number of speeds that must be given to fix every shaft speed."""
    k = mats.kinematics
    if k.shape[0] == 0:
        return k.shape[1]
    return k.shape[1] - pseudoinverse(k).rank


def free_speed_shafts(mats: TrainMatrices, given: Sequence[str] = ()) -> list[str]:
    """Shafts whose speed is not fixed by the train and the ``given`` speeds."""
    system = pseudoinverse(_system(mats, given))
    shafts = mats.train.moving_shafts
    return [shafts[c] for c in system.free_columns()]


def _system(mats: TrainMatrices, given: Sequence[str]) -> np.ndarray:
    col = mats.speed_index
    rows = np.zeros((len(given), len(col)))
    for r, shaft in enumerate(given):
        rows[r, col[shaft]] = 1.0
    return np.vstack([mats.kinematics, rows]) if len(col) else rows


@dataclass(frozen=True, eq=False)
class SpeedSolver:
    """Linear map from given speeds to all shaft speeds, for one set of given shafts.

    ``speeds(values)`` accepts floats or numpy arrays (one entry per given
    shaft, same shape each) and returns the speeds of the moving shafts
    stacked along axis 0.
    """

    mats: TrainMatrices
    given: tuple[str, ...]
    system: Pseudoinverse

    def speeds(self, values: Sequence[float] | np.ndarray) -> np.ndarray:
        g = np.asarray(values, dtype=float)
        return self.system.inverse[:, self.mats.kinematics.shape[0]:] @ g

    def check(self, values: Sequence[float] | np.ndarray, speeds: np.ndarray) -> None:
        """Raise ContradictionError if the given speeds violate the constraints."""
        g = np.asarray(values, dtype=float)
        rhs = np.concatenate([np.zeros((self.mats.kinematics.shape[0],) + g.shape[1:]), g])
        scale = np.max(np.abs(g), axis=0) if g.size else 1.0
        ok = self.system.is_consistent(speeds, rhs, scale)
        if np.all(ok):
            return
        if g.ndim > 1:  # batch: report the first bad point
            first = int(np.flatnonzero(~np.asarray(ok))[0])
            raise _contradiction(self.mats, self.given, g[:, first], prefix=f"operating point {first}: ")
        raise _contradiction(self.mats, self.given, g)


def _contradiction(mats: TrainMatrices, given: Sequence[str], values: np.ndarray, prefix: str = "") -> ContradictionError:
    """Name the given speeds whose removal restores consistency."""
    culprits: list[str] = []
    details: list[str] = []
    for k, shaft in enumerate(given):
        others = [s for j, s in enumerate(given) if j != k]
        other_values = np.array([v for j, v in enumerate(values) if j != k])
        sub = pseudoinverse(_system(mats, others))
        rhs = np.concatenate([np.zeros(mats.kinematics.shape[0]), other_values])
        x = sub.inverse @ rhs
        scale = float(np.max(np.abs(values))) if len(values) else 1.0
        column = mats.speed_index[shaft]
        determined = column not in sub.free_columns()
        if sub.is_consistent(x, rhs, scale) and determined:
            culprits.append(shaft)
            details.append(
                f"n[{shaft}] = {values[k]:g} 1/min is given, but the train"
                + (" and the other given speeds imply " if others else " implies ")
                + f"n[{shaft}] = {(0.0 if abs(x[column]) < 1e-9 * max(scale, 1.0) else x[column]):.6g} 1/min"
            )
    if not culprits:
        culprits = list(given)
    dof = degrees_of_freedom(mats)
    message = (
        f"{prefix}the given speeds contradict each other or the train: "
        + ("; ".join(details) if details else ", ".join(f"n[{s}]" for s in given) + " cannot all hold")
        + f". The train has {dof} degree(s) of freedom, so give {dof} independent speed(s); "
        f"drop or correct the speed at {' or '.join(repr(s) for s in culprits)}."
    )
    return ContradictionError(message, culprits, "speed")


def speed_solver(mats: TrainMatrices, given: Sequence[str]) -> SpeedSolver:
    """Prepare the speed solution for the ``given`` shafts; raise if speeds stay free.

    Raises
    ------
    UnderdeterminedError
        Some shaft speeds are not fixed: the message names them.
    """
    given = tuple(given)
    system = pseudoinverse(_system(mats, given))
    free = [mats.train.moving_shafts[c] for c in system.free_columns()]
    if free:
        dof = degrees_of_freedom(mats)
        missing = mats.train.moving_shafts.__len__() - system.rank
        state = f"{len(given)} speed(s) given" if given else "no speed given"
        raise UnderdeterminedError(
            f"the speed of shaft(s) {', '.join(repr(s) for s in free)} is still free "
            f"(the train has {dof} degree(s) of freedom, {state}): give {missing} more "
            f"speed(s) among {', '.join(repr(s) for s in free)}, or engage a brake or clutch "
            "that fixes them.",
            free,
            "speed",
        )
    return SpeedSolver(mats, given, system)


def solve_speeds(mats: TrainMatrices, speeds: Mapping[str, float]) -> dict[str, float]:
    """All shaft speeds (1/min) from the given ones, the housing at 0."""
    given = [s for s in speeds if s != HOUSING]
    values = np.array([speeds[s] for s in given], dtype=float)
    solver = speed_solver(mats, given)
    n = solver.speeds(values)
    solver.check(values, n)
    result = {s: float(n[c]) for s, c in mats.speed_index.items()}
    result.update({s: float(v) for s, v in zip(given, values)})  # givens exactly, not round-off
    result[HOUSING] = 0.0
    return result
