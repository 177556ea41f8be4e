"""Is the friction state unique?  Other loss-direction patterns that are consistent too.

With Coulomb friction the loss rule makes the torques depend on the directions w of the rolling
power, and w on the torques.  Outside the self-locking band one pattern agrees with its own
solution; inside it (a plus set with η0 < i0 < 1/η0, or a train whose loops act like one) a
pattern may have none, or a second pattern may agree as well: the quasi-static equations do not
decide between the two states, which one acts depends on how the train got there (the
indeterminate case of rigid bodies with dry friction, Champneys & Várkonyi 2016, "The Painlevé
paradox in contact mechanics", IMA J. Appl. Math. 81, sec. 1; for one set the two states are
those of Brandenberger 1952, Bild 8 and Bild 9, with the same given torque).

The alternatives looked at are the shown pattern with one element's direction reversed.  Reversing
w at lever k changes its η0^w in one column of the equations (a rank-one change), so by the
Sherman–Morrison formula the lever's own sun torque becomes T_a' = T_a / c_k with

    c_k = 1 + δ_k · (A⁺[a, row] − A⁺[a, row + 1]),   δ_k = i0·η0^(−w) − i0·η0^w,

the ratio of the two patterns' determinants.  Only where c_k < 0 does the reversed w agree with
the lever's own rolling power; only those alternatives are solved and checked at every element,
and they count when every designated drive still takes in and every designated load still gives
out power (a state that contradicts the given roles is the self-locked one, not an alternative).
For one set this is exact: c = (1 − i0·η0^w)/(1 − i0·η0^−w) < 0 is the band.

References
----------
Brandenberger 1952, eq. 7 and Bild 8–9; Sherman & Morrison 1950, Ann. Math. Stat. 21, 124;
Champneys & Várkonyi 2016, IMA J. Appl. Math. 81, 538.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ..errors import EpicyclicError
from ..results.zero import ZERO_TOLERANCE
from .assembly import TrainMatrices
from .evaluate import evaluate
from .self_locking import SELF_LOCKING_MARGIN
from .statics import TorqueSolver, torque_solver

__all__ = ["reversible_levers", "reversal_ratios", "wrong_way_at_designated", "describe", "ambiguous_points"]


def _gains(solver: TorqueSolver) -> tuple[np.ndarray, np.ndarray]:
    """(G, δ): G[i, j] = A⁺[a_i, row_j] − A⁺[a_i, row_j + 1] and δ_j = k(−w_j) − k(w_j) per lever."""
    mats: TrainMatrices = solver.mats
    key = ("reversal", solver.given, solver.pattern)
    if key not in mats.solvers:
        slots = mats._statics_template[1]
        inverse = solver.system.inverse
        columns = [col for _, col, _ in slots]
        rows = [row for row, _, _ in slots]
        gains = inverse[np.ix_(columns, rows)] - inverse[np.ix_(columns, [r + 1 for r in rows])]
        deltas = []
        for lever, w in zip(mats.levers, solver.pattern):
            try:
                deltas.append(lever.factors(-w)[0] - lever.factors(w)[0] if w else 0.0)
            except EpicyclicError:  # η0^−w overflows: that reversal is no state
                deltas.append(0.0)
        mats.solvers[key] = (gains, np.array(deltas))
    return mats.solvers[key]


def reversal_ratios(solver: TorqueSolver, shift: np.ndarray | None = None,
                    flips: np.ndarray | None = None) -> np.ndarray:
    """c_k per lever (and point): T_a(w_k reversed) / T_a = 1 / c_k.

    ``shift`` (levers × points): the points' own i0·η0^w minus the solver's, where the points have
    their own efficiencies (the batch's per-point factors); ``flips`` then their own δ_k.  Without
    them, one value per lever.  The points' own inverse comes from the solver's by the Woodbury
    identity: G_own = G (I + D G)⁻¹ with D = diag(shift).
    """
    gains, deltas = _gains(solver)
    if shift is None:
        return _flushed(deltas * np.diag(gains))
    levers, points = shift.shape
    m = np.eye(levers)[None] + shift.T[:, :, None] * gains[None]  # (points, levers, levers): I + D G
    own = np.linalg.solve(np.transpose(m, (0, 2, 1)), np.broadcast_to(gains.T, m.shape))  # (G M⁻¹)ᵀ
    diagonal = np.einsum("pkk->kp", own)
    return _flushed((deltas[:, None] if flips is None else flips) * diagonal)


def _flushed(term: np.ndarray) -> np.ndarray:
    """c = 1 + term, exactly 0 where it is round-off of 0: the reversed pattern is then at the
    self-locking limit (its equations singular, its torques unbounded), which is no second state."""
    ratio = 1.0 + term
    return np.where(np.abs(ratio) <= ZERO_TOLERANCE * (1.0 + np.abs(term)), 0.0, ratio)


def reversible_levers(solver: TorqueSolver) -> tuple[int, ...]:
    """Levers whose reversed w would agree with their own rolling power (c_k < 0); cached per solver."""
    key = ("reversible", solver.given, solver.pattern)
    found = solver.mats.solvers.get(key)
    if found is None:
        ratios = reversal_ratios(solver)
        found = solver.mats.solvers[key] = tuple(k for k, w in enumerate(solver.pattern) if w and ratios[k] < 0.0)
    return found


def _reversible(mats: TrainMatrices, given, row) -> bool:
    try:
        return bool(len(row)) and bool(reversible_levers(torque_solver(mats, given, row)))
    except EpicyclicError:  # a singular pattern (its points self-lock)
        return False


def wrong_way_at_designated(powers, shaft_rows: Sequence[tuple[int, str]], scale):
    """Whether a designated drive absorbs or a designated load delivers power (beyond the margin).

    ``shaft_rows``: (row of ``powers``, "drive" or "load") of each designated shaft; ``powers`` a
    list (one point) or an array (rows × points).
    """
    limit = SELF_LOCKING_MARGIN * scale
    wrong = False
    for row, role in shaft_rows:
        wrong = wrong | ((powers[row] < -limit) if role == "drive" else (powers[row] > limit))
    return wrong


def describe(mats: TrainMatrices, shown: Sequence[int], other: Sequence[int], torques: dict[str, float]) -> str:
    """The warning: both patterns, which one is shown, the other state's external torques."""
    def names(pattern):
        return ", ".join(f"{lever.element.name}: {int(w):+d}" for lever, w in zip(mats.levers, pattern)
                         if int(w) != 0)

    return ("the friction state is not unique: the loss directions " + names(shown) + " (shown) and "
            + names(other) + " are both consistent with the given speeds and torques (Coulomb friction "
            "in the self-locking band; which one acts depends on how the train got there). The other "
            "state has the external torques " + ", ".join(f"{s} {t:.6g} N·m" for s, t in torques.items()) + ".")


def ambiguous_points(train, mats: TrainMatrices, given, pattern: np.ndarray, consistent: np.ndarray, tau, rows, effs,
                     speeds: np.ndarray, given_map, dragged, designated, corrected, solved=None) -> np.ndarray:
    """The batch's points whose friction state is not unique (as :func:`~epicyclic.solver.solve.solve` warns).

    ``pattern`` (levers × points) holds the consistent pattern of the points where ``consistent``;
    ``corrected`` is the batch's solve of points with their own efficiencies ``effs``
    (:func:`epicyclic.solver.batch._corrected`); ``solved``, if given, every pattern solved (without
    per-point efficiencies none of the points can be ambiguous unless one of them has a reversible
    lever: checked first, so that the common case costs nothing per point); the other arguments are
    the batch's arrays.
    """
    ambiguous = np.zeros(pattern.shape[1], dtype=bool)
    if effs is None and solved is not None and not any(_reversible(mats, given, row) for row in solved):
        return ambiguous
    points = np.flatnonzero(consistent)
    if not points.size or not pattern.shape[0]:
        return ambiguous
    for row, members in _by_pattern(pattern, points):
        solver = torque_solver(mats, given, row)  # solved before: cached
        if effs is None:  # one ratio per lever for all the members
            ratios = reversal_ratios(solver)
            if not np.any((ratios < 0.0) & (row != 0)):
                continue
        else:
            ratios = reversal_ratios(solver, *_own_factors(mats, row, effs[:, members]))
        for k, w in enumerate(row):
            if w == 0:
                continue
            if effs is None:
                candidates = members[~ambiguous[members]] if ratios[k] < 0.0 else members[:0]
            else:
                candidates = members[(ratios[k] < 0.0) & ~ambiguous[members]]
            if not candidates.size:
                continue
            other = row.copy()
            other[k] = -w
            column = np.repeat(other[:, None], candidates.size, axis=1)
            own = None if effs is None else effs[:, candidates]
            try:
                with np.errstate(all="ignore"):
                    x = corrected(train, mats, given, torque_solver(mats, given, other), other, tau[:, candidates],
                                  None if rows is None else rows[:, candidates], own)
                    ev = evaluate(mats, speeds[:, candidates], x, column,
                                  {s: v[candidates] for s, v in given_map.items()}, own,
                                  None if dragged is None else dragged[:, candidates])
            except EpicyclicError:  # singular or out of range: no state
                continue
            ok = np.all((column == ev.pattern) | (ev.pattern == 0), axis=0)
            ok &= np.logical_not(wrong_way_at_designated(ev.powers, designated, np.max(np.abs(ev.powers), axis=0)))
            ambiguous[candidates[ok]] = True
    return ambiguous


def _own_factors(mats: TrainMatrices, row, effs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per lever and point: its own i0·η0^w minus the pattern's reference, and i0·η0^−w − i0·η0^w."""
    w = np.asarray(row, dtype=int)[:, None]
    i0 = np.array([lv.ratio for lv in mats.levers])[:, None]
    with np.errstate(all="ignore"):
        k = np.where(w > 0, i0 * effs, np.where(w < 0, i0 / effs, i0))
        reversed_k = np.where(w > 0, i0 / effs, np.where(w < 0, i0 * effs, i0))
    reference = np.array([lv.factors(int(wk))[0] for lv, wk in zip(mats.levers, row)])[:, None]
    return k - reference, reversed_k - k


def _by_pattern(pattern: np.ndarray, points: np.ndarray):
    """(pattern, its points) for each distinct pattern (column of ``pattern``) among ``points``."""
    column = pattern[:, points]
    codes = np.zeros(points.size, dtype=np.int64)
    for k in range(column.shape[0]):  # w + 1 as base-3 digits: one integer per pattern
        codes = codes * 3 + (column[k] + 1)
    first = codes[0]
    if np.all(codes == first):
        yield column[:, 0], points
        return
    unique, index, inverse = np.unique(codes, return_index=True, return_inverse=True)
    for j in range(unique.size):
        yield column[:, index[j]], points[inverse.ravel() == j]
