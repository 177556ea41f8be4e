"""Self-locking: decided with a margin, with the threshold η0 of every lossy element.

A train self-locks in the asked direction (Brandenberger 1952, text to Bild 9)
when, with the losses acting in the directions of the ideal power flow, no
power reaches the loads: the formal efficiency η_f = P_out/P_in is ≤ 0.  The
decision uses a margin: an output power at or below ``SELF_LOCKING_MARGIN``
times the input power counts as self-locking (the train is at or past its
limit), and so does a load that delivers, or a drive that absorbs, more than
the margin times the input power, or a set of loss directions that no
solution agrees with.  Round-off
(1e-15 of the input) can therefore never flip the verdict; a train exactly at
its limit is self-locking.

The threshold of an element is the η0 (others unchanged) at which η_f crosses
the margin: η0 enters the equations through one rank-one change, so η_f is a
Möbius function of i0·η0^w, fixed by three solves and checked on both sides
of its crossing (bisection where that check fails).

References
----------
Brandenberger 1952, text to Bild 9 (self-locking where M3' = 0, η = bd/ac).
"""

from __future__ import annotations

from types import MappingProxyType

import numpy as np

from ..errors import EpicyclicError, NearSingularError, UnderdeterminedError
from ..results.solution import RPM_TO_RAD_S, SelfLocking, Solution
from .assembly import TrainMatrices
from .linear import pseudoinverse
from .statics import TorqueSolver, torque_solver

__all__ = ["SELF_LOCKING_MARGIN", "self_locking", "formal_efficiency", "limit_solver", "with_pattern"]

#: A formal efficiency at or below this (relative power at the loads) is self-locking.
SELF_LOCKING_MARGIN = 1e-9


def _wrong_way(solution: Solution) -> list[str]:
    """Loads that deliver, or drives that absorb, more than the margin of the input power."""
    scale = max(solution.input_power, solution.output_power)
    return [
        s.name for s in solution.shafts.values()
        if (s.role == "load" and s.power > SELF_LOCKING_MARGIN * scale)
        or (s.role == "drive" and s.power < -SELF_LOCKING_MARGIN * scale)
    ]


def self_locking(solution: Solution, consistent: bool, mats: TrainMatrices, given, values, speeds,
                 pattern, *, singular: bool = False) -> SelfLocking | None:
    """Detect self-locking and find each lossy element's threshold η0 (None: the train moves).

    ``pattern`` is the loss-direction pattern of the ideal power flow, ``speeds``
    all shaft speeds (train order), ``given``/``values`` the given
    external torques.  ``singular``: the equations of a loss pattern were singular
    although the lossless ones were not (the train is exactly at its limit; ``solution``
    then holds the formal solution of an earlier pattern or, if none, the lossless one).
    """
    if solution.input_power == 0.0 and solution.output_power == 0.0:
        return None  # no power flows: nothing to lock
    wrong = [] if singular else _wrong_way(solution)
    at_limit = solution.output_power <= SELF_LOCKING_MARGIN * solution.input_power
    if consistent and not wrong and not at_limit:
        return None
    formal = formal_efficiency(mats, given, values, speeds, pattern, solution)
    thresholds = _thresholds(mats, given, values, speeds, pattern, solution)
    if singular:
        reason = ("with losses, the torques would be unbounded: the train is exactly at its self-locking "
                  "limit (i0·η0^w = 1)")
    elif wrong:
        reason = "with losses, " + _wrong_way_words(solution, wrong)
    elif not consistent:
        reason = "no loss-direction pattern is consistent with the given load"
    elif formal is None or formal > -SELF_LOCKING_MARGIN:
        reason = "with losses, no power reaches the load (the train is at its self-locking limit)"
    else:
        reason = "with losses, the load would have to deliver power"
    where = ", ".join(f"{name}: η0 < {eta:.6g}" for name, eta in thresholds.items())
    message = (
        f"the train self-locks in this direction of power flow: {reason}"
        + (f" (formal efficiency {formal + 0.0:.4g})" if formal is not None else "")
        + (f"; self-locking starts at {where}" if where else "")
        + ". Drive it from the other side, or raise the efficiency."
    )
    shown = None if formal is None else (0.0 if abs(formal) <= SELF_LOCKING_MARGIN else formal)
    return SelfLocking(message, shown, MappingProxyType(thresholds))


def _wrong_way_words(solution: Solution, wrong: list[str]) -> str:
    """What the ``wrong`` shafts would have to do, by their declared role.

    A designated drive or load is called so; a shaft declared ``connected`` has its role from the
    lossless power flow, and the words say that.
    """
    point = solution.operating_point
    parts = []
    for shaft in wrong:
        role = solution.shafts[shaft].role
        verb = "deliver" if role == "load" else "absorb"
        if shaft in point.drives or shaft in point.loads:
            parts.append(f"{shaft!r} would have to {verb} power although it is a {role}")
        else:
            parts.append(f"{shaft!r} would have to {verb} power although, without losses, it "
                         + ("takes power out" if role == "load" else "puts power in")
                         + (" (a connected shaft)" if shaft in point.connected else ""))
    return "; ".join(parts)


def formal_efficiency(mats: TrainMatrices, given, values, speeds, pattern, solution, etas=None) -> float | None:
    """Efficiency from the loss rule with ``pattern`` held fixed (may be ≤ 0); None if no power flows.

    ``etas`` (element → η0) replaces stationary efficiencies.  Computed straight from the equations
    (no zero rule): it is compared with the margin only.
    """
    matrix = mats.statics(pattern, etas)
    rows = np.zeros((len(given), matrix.shape[1]))
    for r, shaft in enumerate(given):
        rows[r, mats.external_column(shaft)] = 1.0
    system = pseudoinverse(np.vstack([matrix, rows]))
    columns = mats.torque_columns
    if any(columns[c][0] == "external" for c in system.free_columns()):
        return None  # singular: exactly at the limit, the torques are unbounded and the ratio undefined
    x = system.solve(np.concatenate([np.zeros(matrix.shape[0]), np.asarray(values, dtype=float)]))
    shafts = mats.train.shafts
    powers = {s: x[mats.external_column(s)] * speeds[k] * RPM_TO_RAD_S
              for k, s in enumerate(shafts) if s in mats.external}
    drive = sum(p for s, p in powers.items() if solution.shafts[s].role == "drive")
    load = -sum(p for s, p in powers.items() if solution.shafts[s].role == "load")
    if drive == 0.0 and load == 0.0:
        return None
    # The ratio is invariant to which side's torque is given (a load torque makes both signs flip).
    if drive == 0.0:
        return -np.inf if load < 0 else np.inf
    return float(load / drive)


def limit_solver(mats: TrainMatrices, given, row, ideal: TorqueSolver, singular: set) -> TorqueSolver:
    """The torque solver of the loss pattern ``row`` (for the batch, as :func:`~epicyclic.solver.solve.solve`).

    Where its equations are singular although the lossless ones are not, the train is exactly at its
    self-locking limit (i0·η0^w = 1: unbounded torques); ``row`` then goes into ``singular`` and the
    lossless solver ``ideal`` stands in (the points of that pattern self-lock).
    """
    try:
        return torque_solver(mats, given, row)
    except (UnderdeterminedError, NearSingularError):
        singular.add(tuple(int(w) for w in row))
        return ideal


def with_pattern(column: np.ndarray, rows: set[tuple[int, ...]]) -> np.ndarray:
    """Points (columns of ``column``) whose loss pattern is one of ``rows``."""
    hit = np.zeros(column.shape[1], dtype=bool)
    for row in rows:
        hit |= np.all(column == np.array(row, dtype=column.dtype)[:, None], axis=0)
    return hit


def _thresholds(mats, given, values, speeds, pattern, solution) -> dict[str, float]:
    """Per lossy element: the η0 at which the formal efficiency crosses the margin (others unchanged)."""
    out: dict[str, float] = {}
    for k, lever in enumerate(mats.levers):
        w = int(pattern[k])
        if lever.efficiency == 1.0 or w == 0:
            continue

        def efficiency(eta: float, name: str = lever.element.name) -> float:
            try:
                value = formal_efficiency(mats, given, values, speeds, pattern, solution, {name: eta})
            except EpicyclicError:  # singular (or nearly) exactly at the threshold
                return 0.0
            return -np.inf if value is None else value

        if efficiency(1.0) <= SELF_LOCKING_MARGIN or efficiency(lever.efficiency) > SELF_LOCKING_MARGIN:
            continue  # locks even without this element's loss, or does not lock because of it
        eta = _moebius_crossing(efficiency, lever.ratio, w, lever.efficiency)
        out[lever.element.name] = eta if eta is not None else _bisection(efficiency, lever.efficiency)
    return out


def _moebius_crossing(efficiency, ratio: float, w: int, low: float) -> float | None:
    """The η0 where ``efficiency`` crosses the margin, from three samples.

    η0 enters the equations only through k = i0·η0^w, in one column of the
    matrix (a rank-one change), so the formal efficiency is a Möbius function
    (p1 + q1·k)/(p2 + q2·k) of k: three samples fix it, its crossing is
    closed-form.  Checked on both sides; None if the samples do not fit.
    """
    etas = (1.0, 0.5 * (1.0 + low), low + 0.25 * (1.0 - low))
    ks = [ratio * e**w for e in etas]
    ys = [efficiency(e) for e in etas]
    if not all(np.isfinite(ys)):
        return None
    rows = np.array([[1.0, kk, -y, -y * kk] for kk, y in zip(ks, ys)])
    p1, q1, p2, q2 = np.linalg.svd(rows)[2][-1]
    m = SELF_LOCKING_MARGIN
    if q1 - m * q2 == 0:
        return None
    k_star = (m * p2 - p1) / (q1 - m * q2)
    eta = (k_star / ratio) ** w if k_star / ratio > 0 else None
    if eta is None or not low < eta < 1.0:
        return None
    step = 1e-9 * eta
    if efficiency(min(eta + step, 1.0)) > m and efficiency(max(eta - step, low)) <= m:
        return float(eta)
    return None


def _bisection(efficiency, low: float) -> float:
    lo, hi = low, 1.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if efficiency(mid) > SELF_LOCKING_MARGIN:
            hi = mid
        else:
            lo = mid
        if hi - lo <= 1e-15:
            break
    return 0.5 * (lo + hi)
