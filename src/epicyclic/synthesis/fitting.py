"""Stationary ratios that hit the targets, and the shift schedule that goes with them.

For a screened architecture (:class:`~epicyclic.synthesis.screening.Placement`)
every combination of k engaged elements has a ratio r_t(i0).  For given i0 the
best *schedule* assigns the forward targets, largest first, to combinations
with positive ratios in falling order, and the reverse targets to the negative
ones (a monotone assignment, found by dynamic programming, is optimal for
sorted targets).  With the assignment fixed, the stationary ratios follow from
a bounded nonlinear least-squares fit of log(r/target) (SciPy's trust-region
reflective method); the assignment is then renewed and the fit repeated until it
no longer changes.  Starts are the centres of the boxes that survived
screening.  Inside the fit the ratios and their exact derivatives come from the
determinants at the box's corners (:class:`~epicyclic.synthesis.kinematics.RatioFunctions`:
multilinear, so interpolation is exact), not from a solve per point and finite
differences; the fit is then judged by the general path, :func:`gear_ratios`.

References
----------
Kahraman et al. 2004, J. Mech. Des. 126(6), section 3 (gear ratios from
stationary ratios, tooth counts chosen to meet a ratio set); Branch, Coleman &
Li (1999), SIAM J. Sci. Comput. 21(1), 1–23 (trust-region reflective least squares).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np

from .kinematics import RatioFunctions, gear_ratios
from .mechanisms import Mechanism

__all__ = ["RatioFit", "assign", "fit_ratios", "combinations_of_elements", "single_swap_schedule"]


@dataclass(frozen=True)
class RatioFit:
    """Stationary ratios and schedule of one architecture.

    Attributes
    ----------
    stationary_ratios : tuple of float
        i0 per set.
    schedule : tuple of int
        For each target (forward targets largest first, then reverse), the row
        of the architecture's combinations that gives it.
    ratios : tuple of float
        The gear ratios at ``stationary_ratios``, same order as the targets.
    error : float
        Largest relative ratio error |r/target − 1|.
    """

    stationary_ratios: tuple[float, ...]
    schedule: tuple[int, ...]
    ratios: tuple[float, ...]
    error: float


def combinations_of_elements(elements: tuple[int, ...], engaged: int) -> np.ndarray:
    """Every ``engaged``-subset of ``elements`` (element numbers), shape (C, engaged)."""
    return np.array(list(itertools.combinations(sorted(elements), engaged)), dtype=int).reshape(-1, engaged)


def _monotone(values: np.ndarray, targets: np.ndarray) -> tuple[float, list[int]]:
    """Assign sorted ``targets`` (falling) to a falling subsequence of ``values``; least squared log error."""
    n, m = targets.size, values.size
    if n == 0:
        return 0.0, []
    if m < n:
        return np.inf, []
    order = np.argsort(-values)
    v = np.log(values[order])
    t = np.log(targets)
    cost = np.full((n + 1, m + 1), np.inf)
    cost[0, :] = 0.0
    for i in range(1, n + 1):  # cost[i, j] = min(cost[i, j - 1], cost[i - 1, j - 1] + (v[j - 1] - t[i - 1])^2)
        cost[i, i:] = np.minimum.accumulate(cost[i - 1, i - 1:m] + (v[i - 1:] - t[i - 1]) ** 2)
    return _backtrack(cost, order)


def _backtrack(cost: np.ndarray, order: np.ndarray) -> tuple[float, list[int]]:
    """Least cost and the picks (rows of the unsorted values) from the assignment's cost table (n + 1, m + 1)."""
    n, m = cost.shape[0] - 1, cost.shape[1] - 1
    picks, i, j = [], n, m
    while i > 0:
        if cost[i, j] == cost[i, j - 1] and j > i:
            j -= 1
        else:
            picks.append(int(order[j - 1]))
            i, j = i - 1, j - 1
    return float(cost[n, m]), picks[::-1]


def assign(ratios: np.ndarray, forward: np.ndarray, reverse: np.ndarray) -> tuple[float, list[int]]:
    """Best schedule for given combination ratios: (sum of squared log errors, combination per target).

    Parameters
    ----------
    ratios : ndarray (C,)
        Ratio of every combination (NaN: no gear).
    forward : ndarray
        Forward targets, largest first.
    reverse : ndarray
        Reverse targets (negative), largest magnitude first.

    Examples
    --------
    >>> cost, picks = assign(np.array([1.0, 3.1, -3.0, 4.6, 2.0]), np.array([4.7, 3.1, 1.0]), np.array([-3.3]))
    >>> picks
    [3, 1, 0, 2]
    """
    ratios = np.asarray(ratios, dtype=float)
    pos = np.flatnonzero(ratios > 0)
    neg = np.flatnonzero(ratios < 0)
    c1, p1 = _monotone(ratios[pos], forward)
    c2, p2 = _monotone(-ratios[neg], -reverse)
    if not (np.isfinite(c1) and np.isfinite(c2)):
        return np.inf, []
    return c1 + c2, [int(pos[p]) for p in p1] + [int(neg[p]) for p in p2]


def _residuals(functions: RatioFunctions, chosen: np.ndarray, targets: np.ndarray, scale: float):
    """Residuals log(r/target)/scale of the chosen combinations and their exact Jacobian, each point computed once."""
    memo: dict[bytes, tuple[np.ndarray, np.ndarray]] = {}

    def at(z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        key = z.tobytes()
        if key not in memo:
            memo.clear()
            r, jac = functions.with_jacobian(z)
            r, jac = r[chosen], jac[chosen]
            with np.errstate(invalid="ignore", divide="ignore"):
                res = np.log(r / targets) / scale
                d_res = jac / (r[:, None] * scale)
            bad = ~np.isfinite(res)  # no gear, or the wrong sign: a large constant, as before
            memo[key] = (np.where(bad, 1e3, res), np.where(bad[:, None] | ~np.isfinite(d_res), 0.0, d_res))
        return memo[key]

    return (lambda z: at(z)[0]), (lambda z: at(z)[1])


def fit_ratios(mechanism: Mechanism, input: int, output: int, combos: np.ndarray, low: np.ndarray,
               high: np.ndarray, forward: np.ndarray, reverse: np.ndarray, tolerance: float,
               starts: np.ndarray) -> RatioFit | None:
    """Fit the stationary ratios of one architecture to the targets.

    Parameters
    ----------
    mechanism : Mechanism
    input, output : int
        Shaft numbers.
    combos : ndarray (C, k)
        The architecture's element combinations.
    low, high : ndarray (S,)
        Bounds of the stationary ratios.
    forward, reverse : ndarray
        Targets (forward falling, reverse by falling magnitude).
    tolerance : float
        Relative tolerance; the fit is returned only if every ratio is within it.
    starts : ndarray (P, S)
        Starting points (inside the bounds).

    Returns
    -------
    RatioFit or None
    """
    from scipy.optimize import least_squares

    targets = np.concatenate([forward, reverse])
    scale = np.log1p(tolerance)
    functions = RatioFunctions.of(mechanism, low, high, combos, input, output)  # exact over the box, cheap

    # rank the starts by their assignment cost, keep the two best
    at_starts = functions(starts)
    costs = [assign(r, forward, reverse)[0] for r in at_starts]
    best: RatioFit | None = None
    for s in np.argsort(costs)[:2]:
        if not np.isfinite(costs[s]):
            continue
        x = starts[s].copy()
        picks = assign(at_starts[s], forward, reverse)[1]
        for _ in range(3):
            residual, jacobian = _residuals(functions, np.array(picks), targets, scale)
            sol = least_squares(residual, x, jac=jacobian, bounds=(low, high), method="trf", xtol=1e-12, ftol=1e-12,
                                max_nfev=80)
            x = sol.x
            cost, new = assign(functions(x)[0], forward, reverse)
            if not np.isfinite(cost) or new == picks:
                break
            picks = new
        # the fit is judged by the general path (the null-space solve), not by the interpolation
        r = gear_ratios(mechanism, x[None, :], combos, input, output)[0]
        if not picks or not np.all(np.isfinite(r[picks])):
            continue
        error = float(np.max(np.abs(r[picks] / targets - 1.0)))
        if error <= tolerance * (1 + 1e-9) and (best is None or error < best.error):
            best = RatioFit(tuple(float(v) for v in x), tuple(picks), tuple(float(v) for v in r[picks]), error)
    return best


def single_swap_schedule(mechanism: Mechanism, input: int, output: int, combos: np.ndarray,
                         schedule: tuple[int, ...], forward: int, points: np.ndarray) -> tuple[int, ...]:
    """The schedule with the fewest multi-element shifts among combinations of identical ratio.

    Two combinations whose ratios agree (relative 1e-9) at every one of ``points`` (the fitted
    stationary ratios and a second, unrelated point: multilinear fractions that agree at two generic
    points are the same function there, and a coincidence at both is not met in practice) are the same
    gear; of them the forward gears take, by dynamic programming over the gear sequence, those that make
    the fewest consecutive shifts swap more than one element (Naunheimer et al. 2011, section 12.3:
    single-swap, clutch-to-clutch shifts).  Ties keep the fitted choice; reverse gears are kept.

    Parameters
    ----------
    mechanism : Mechanism
    input, output : int
        Shaft numbers.
    combos : ndarray (C, k)
        The architecture's element combinations.
    schedule : tuple of int
        Row of ``combos`` per target (forward gears first).
    forward : int
        Number of forward gears.
    points : ndarray (P, S)
        Stationary ratios at which ratios must agree.

    Returns
    -------
    tuple of int
        Same length as ``schedule``.

    Examples
    --------
    >>> from epicyclic.synthesis.mechanisms import Mechanism
    >>> m = Mechanism(("simple",), (0, 1, 2))        # one set: brake sun, ring or carrier
    >>> single_swap_schedule(m, 0, 2, np.array([[1]]), (0,), 1, np.array([[-2.0], [-3.0]]))
    (0,)
    """
    ratios = gear_ratios(mechanism, np.asarray(points, float), combos, input, output)  # (P, C)
    sets = [set(map(int, row)) for row in combos]
    choices = []
    for g, row in enumerate(schedule[:forward]):
        same = np.all(np.isclose(ratios, ratios[:, [row]], rtol=1e-9, atol=0.0), axis=0)
        others = [j for j in np.flatnonzero(same) if j != row]
        choices.append([row] + [int(j) for j in others])
    cost = [[0] * len(choices[0])]
    back: list[list[int]] = []
    for g in range(1, len(choices)):
        row_cost, row_back = [], []
        for j in choices[g]:
            steps = [cost[-1][i] + (len(sets[p] ^ sets[j]) > 2) for i, p in enumerate(choices[g - 1])]
            best = int(np.argmin(steps))  # first minimum: the fitted choice on ties
            row_cost.append(steps[best])
            row_back.append(best)
        cost.append(row_cost)
        back.append(row_back)
    if not choices:
        return tuple(schedule)
    pick = [int(np.argmin(cost[-1]))]
    for g in range(len(choices) - 1, 0, -1):
        pick.append(back[g - 1][pick[-1]])
    pick.reverse()
    return tuple(choices[g][i] for g, i in enumerate(pick)) + tuple(schedule[forward:])
