"""Kinematics: every shaft speed from the given speeds (Willis equation per set).

The train's constraint rows K (one Willis row per lever, one equality per
engaged clutch or brake) and one row per given speed form A n = b.  The rank
of K gives the degrees of freedom; the null space of A names the shafts whose
speed is still free; a non-zero residual names the givens in conflict.
Shafts the train holds still get exactly 0, shafts it makes turn together get
exactly the same speed; a speed that is round-off of the terms it is computed
from is exactly 0 (the rule of :mod:`epicyclic.results.zero`, with the
componentwise error bound of the solve as the scale).  Equations too close to singular raise
:class:`~epicyclic.errors.NearSingularError` instead of a result that
round-off decides.

References
----------
Brandenberger 1952, eq. 1; Queitsch, eq. 12; tec-science, "Willis-Gleichung" (Grundgleichung).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..errors import ContradictionError, NearSingularError, NonFiniteResultError, UnderdeterminedError
from ..model.elements import HOUSING
from ..results.zero import ZERO_TOLERANCE
from .assembly import TrainMatrices
from .linear import SMALL, Pseudoinverse, apply, pseudoinverse, row_products, span, unreached_columns

#: The smallest normal and the largest finite float.
_TINY, _HUGE = float(np.finfo(float).tiny), float(np.finfo(float).max)

__all__ = ["SpeedSolver", "speed_solver", "degrees_of_freedom", "free_speed_shafts", "solve_speeds", "check_speeds"]


def degrees_of_freedom(mats: TrainMatrices) -> int:
    """Number of speeds that must be given to fix every shaft speed."""
    return mats.degrees_of_freedom


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

    @cached_property
    def operator(self) -> np.ndarray:
        """Matrix S with speeds = S @ given speeds; rows of held shafts exactly 0."""
        rows = self.mats.kinematics.shape[0]
        unit = np.zeros((self.system.matrix.shape[0], len(self.given)))
        unit[rows:] = np.eye(len(self.given))
        s = self.system.solve(unit)
        s[unreached_columns(self.mats.kinematics, [self.mats.speed_index[g] for g in self.given])] = 0.0
        follow = self._representatives
        return np.where((follow >= 0)[:, None], s[np.maximum(follow, 0)], 0.0)

    @cached_property
    def _representatives(self) -> np.ndarray:
        """Per moving shaft: the column whose speed it has exactly (a given shaft of its class if
        there is one), or −1 where the train holds it still."""
        index = self.mats.speed_index
        classes = self.mats.speed_classes
        chosen = {classes[g]: g for g in reversed(self.given)}
        return np.array([-1 if classes[s] == HOUSING else index[chosen.get(classes[s], classes[s])]
                         for s in self.mats.train.moving_shafts], dtype=int)

    def speeds(self, values: Sequence[float] | np.ndarray) -> np.ndarray:
        """Speeds of the moving shafts (1/min): givens exactly, round-off of zero exactly 0.

        A speed n_j is round-off when |n_j| ≤ ZERO_TOLERANCE · (|A⁺|·|A|·|n|)_j: the magnitude of
        the terms it is computed from, every equation's terms weighted by how much n_j depends on
        that equation (A: the equations with the given speeds, A⁺ their pseudoinverse).  This is
        the componentwise error bound of the solve, scaled up; it keeps a chain's 3^-30, and zeroes
        what stands still by the ratios (sets sharing their shafts and a held member).
        """
        g = np.asarray(values, dtype=float)
        below = np.abs(g) < _TINY
        if np.count_nonzero(below):  # a given speed below 2.2e-308 1/min is 0 (−0 too)
            g = np.where(below, 0.0, g)
        n = apply(self.operator, g)
        for r, shaft in enumerate(self.given):
            n[self.mats.speed_index[shaft]] = g[r]
        if n.ndim > 1 and self._settled(n):
            return self._follow(n)
        size = np.where(np.isfinite(n), np.abs(n), 0.0)  # overflow is named by check_speeds
        # measured against the largest speed (per point), so that |A⁺|·|A|·|n| cannot overflow near 1e308
        # (an infinite bound made every speed "round-off": a carrier at 2.8e307 1/min came out as 0)
        peak = _largest_row(size) if size.size else np.ones((1,) + size.shape[1:])
        size = size / np.where(peak > 0.0, peak, 1.0)
        terms = self._magnitudes[1] @ (self._magnitudes[0] @ size)
        zero = size <= ZERO_TOLERANCE * terms
        zero[[self.mats.speed_index[g] for g in self.given]] = False  # a given speed stays as given
        n = np.where(zero & np.isfinite(n), 0.0, n)
        return self._follow(n)

    def _follow(self, n: np.ndarray) -> np.ndarray:
        """Shafts turning together bit for bit at the same speed, held shafts exactly 0 (never −0)."""
        follow = self._representatives
        out = n[np.maximum(follow, 0)]
        out[follow < 0] = 0.0
        out += 0.0
        return out

    def _settled(self, n: np.ndarray) -> bool:
        """Whether the round-off rule of :meth:`speeds` sets no speed to 0 and no speed can be out of the
        float range: every non-zero |n| within 1e-50…1e50 and above ZERO_TOLERANCE · the row sums of
        |A⁺|·|A| (the largest the bound can be, speeds relative to the largest) · the largest |n| of all
        points (a margin of 1e-6 for the round-off of the bound itself).  Two reductions.
        """
        least, most = span(np.abs(n))
        bound = self._magnitudes[2]
        return bool(1e-50 <= least and most <= 1e50 and least > ZERO_TOLERANCE * (1.0 + 1e-6) * bound * most)

    @cached_property
    def _magnitudes(self) -> tuple[np.ndarray, np.ndarray]:
        """|A|, |A⁺| and the largest row sum of |A⁺|·|A| (see :meth:`speeds`)."""
        moduli = np.abs(self.system.matrix), np.abs(self.system.inverse)
        return (*moduli, float((moduli[1] @ (moduli[0] @ np.ones(moduli[0].shape[1]))).max(initial=0.0)))

    @cached_property
    def _plain(self) -> tuple[list[int], list[int], list[list[float]] | None, list[list[float]] | None]:
        """For :meth:`point`: the columns of the given speeds, :attr:`_representatives`, the operator as
        lists of rows where one speed is given (a product per entry: BLAS's numbers), and |A⁺|·|A| as
        lists of rows where it is small (Python loops beat numpy's call overhead there)."""
        bound = self._magnitudes[1] @ self._magnitudes[0]
        return ([self.mats.speed_index[g] for g in self.given], self._representatives.tolist(),
                self.operator.tolist() if self.operator.shape[1] == 1 else None,
                bound.tolist() if bound.size <= SMALL else None)

    def point(self, values: Sequence[float]) -> list[float] | None:
        """:meth:`speeds` of one point in Python floats (the same numbers); None where one is not finite.

        The round-off bound |A⁺|·|A|·|n| is formed as (|A⁺|·|A|)·|n| for a small system, which may differ
        from the array code's in its last bit; it only decides what is round-off of zero.
        """
        g = [0.0 if abs(v) < _TINY else float(v) for v in values]
        columns, follow, operator, bound = self._plain
        if operator is None:
            with np.errstate(all="ignore"):
                n = apply(self.operator, np.array(g)).tolist()
        else:
            n = row_products(operator, g)
        for column, value in zip(columns, g):
            n[column] = value
        if not all(map(math.isfinite, n)):
            return None
        size = [abs(v) for v in n]
        peak = max(size, default=1.0)  # relative to the largest speed, as speeds() does
        if peak > 0.0:
            size = [v / peak for v in size]
        if bound is None:
            with np.errstate(all="ignore"):
                terms = (self._magnitudes[1] @ (self._magnitudes[0] @ np.array(size))).tolist()
        else:
            terms = row_products(bound, size)
        zero = [v <= ZERO_TOLERANCE * term for v, term in zip(size, terms)]
        for column in columns:
            zero[column] = False
        n = [0.0 if z else v for z, v in zip(zero, n)]
        return [n[f] + 0.0 if f >= 0 else 0.0 for f in follow]

    def check(self, values: Sequence[float] | np.ndarray, speeds: np.ndarray) -> None:
        """Raise ContradictionError if the given speeds violate the constraints."""
        if self.system.rank == self.system.matrix.shape[0]:
            return  # full row rank: every right-hand side is reached (Pseudoinverse.is_consistent)
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


def _largest_row(size: np.ndarray) -> np.ndarray:
    """``np.max(size, axis=0, keepdims=True)``, row by row for points along axis 1 (many times faster)."""
    if size.ndim == 1:
        return np.max(size, axis=0, keepdims=True)
    peak = size[0].copy()
    for row in size[1:]:
        np.maximum(peak, row, out=peak)
    return peak[None]


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
    key = ("speed", given)
    if key in mats.solvers:
        return mats.solvers[key]
    system = pseudoinverse(_system(mats, given))
    free = [mats.train.moving_shafts[c] for c in system.free_columns()]
    if system.near_singular and not free:
        raise _near_singular(mats, given, system)
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
    mats.solvers[key] = SpeedSolver(mats, given, system)
    return mats.solvers[key]


def _near_singular(mats: TrainMatrices, given: Sequence[str], system: Pseudoinverse) -> NearSingularError:
    distance, direction, row_weights = system.near_singular[-1]
    shafts = mats.train.moving_shafts
    weak = [shafts[c] for c in np.flatnonzero(np.abs(direction) > 0.1 * np.abs(direction).max())]
    parts = [*mats.levers, *mats.links]
    involved = [parts[r].element.name for r in np.flatnonzero(np.abs(row_weights[:len(parts)]) > 0.1 * np.abs(row_weights).max())]
    near_one = [f"{lv.element.name!r} has i0 − 1 = {lv.ratio - 1.0:.3g}" for lv in mats.levers
                if lv.element.name in involved and abs(lv.ratio - 1.0) < 1e-6]
    return NearSingularError(
        f"the speed of {', '.join(repr(s) for s in weak)} is fixed only by nearly cancelling ratios of "
        f"{', '.join(repr(n) for n in involved) or 'the train'}"
        + (f" ({'; '.join(near_one)})" if near_one else "")
        + f": the equations are {distance:.2g} (relative) from singular, so round-off would decide the result "
        f"(it would be amplified about {1 / distance:.1g} times). Give the speed of {' or '.join(repr(s) for s in weak)} "
        "instead, or check these ratios.",
        "speed", distance, weak, involved,
    )


def check_speeds(mats: TrainMatrices, speeds: np.ndarray) -> None:
    """Raise NonFiniteResultError if a speed over- or underflows (``speeds``: moving shafts, points trailing)."""
    size = np.abs(speeds)
    if size.max(initial=0.0) <= _HUGE and np.count_nonzero(size < _TINY) == np.count_nonzero(size == 0):
        return  # all finite, each 0 or a normal float
    bad = ~np.isfinite(speeds) | ((size < _TINY) & (size > 0))
    where = np.argwhere(bad)[0]
    shaft = mats.train.moving_shafts[where[0]]
    point = f" at operating point {int(where[1])}" if speeds.ndim > 1 and speeds.shape[1] > 1 else ""
    large = not np.isfinite(speeds[tuple(where)])
    raise NonFiniteResultError(
        f"the speed of shaft {shaft!r}{point} "
        + ("is not a finite number: it overflows the floating-point range (about 1.8e308 1/min): the given "
           "speeds are too large for the ratios of this train; give smaller speeds." if large else
           "underflows the floating-point range (below 2.2e-308 1/min it loses its digits): the given speeds "
           "are too small for the ratios of this train; give larger speeds."),
        "speed", shaft,
    )


def solve_speeds(mats: TrainMatrices, speeds: Mapping[str, float]) -> dict[str, float]:
    """All shaft speeds (1/min) from the given ones, the housing at 0."""
    given = [s for s in speeds if s != HOUSING]
    solver = speed_solver(mats, given)
    point = solver.point([speeds[s] for s in given])
    if point is None or not all(v == 0.0 or _TINY <= abs(v) for v in point) or solver.system.rank < len(given) + \
            mats.kinematics.shape[0]:  # the array code names what over- or underflows, or contradicts
        values = np.array([speeds[s] for s in given], dtype=float)
        with np.errstate(all="ignore"):
            n = solver.speeds(values)
        check_speeds(mats, n)
        solver.check(values, n)
        point = n.tolist()
    result = dict(zip(mats.speed_index, point))
    result[HOUSING] = 0.0
    return result
