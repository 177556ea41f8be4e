"""One operating point evaluated in plain Python floats: the scalar solver's :func:`evaluate`.

:func:`~epicyclic.solver.evaluate.evaluate` is written for arrays of points; on one point its hundred
small numpy operations cost far more than the arithmetic.  :func:`evaluate_point` does the same
operations, in the same order, on Python floats (IEEE double, like numpy's float64), so that it gives
the same numbers bit for bit, and returns the same :class:`~epicyclic.solver.evaluate.Evaluation`.
Where a value is not finite or below the normal float range (overflow, underflow: the rare cases
that the zero rule's flush and :func:`~epicyclic.solver.evaluate.check_finite` handle) it hands the
point to the array code, which names the quantity.  The batch solver always uses the array code, and
the tests compare the two over 10^4 random trains (``tests/solver/test_edges_hypothesis.py``).

References
----------
Brandenberger 1952, eqs. 3' and 7; Queitsch, Wälz- und Kupplungsleistung (as
:mod:`epicyclic.solver.evaluate`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np

from ..model.elements import HOUSING
from ..results.solution import RPM_TO_RAD_S
from ..results.zero import ZERO_TOLERANCE
from .assembly import TrainMatrices
from .evaluate import _SAFE_HIGH, _SAFE_LOW, Evaluation, evaluate

__all__ = ["evaluate_point", "PointEvaluation"]

_TINY, _HUGE = float(np.finfo(float).tiny), float(np.finfo(float).max)


@dataclass(frozen=True)
class _Plain:
    """The index arrays of a :class:`~epicyclic.solver.assembly.Layout` as tuples of ints."""

    rows: dict
    parts: int
    port_columns: tuple
    port_parts: tuple
    part_ports: tuple
    neighbours: tuple  # per part: its neighbours, without the padding
    parts_at: tuple
    reacting: tuple  # (row, its ports)
    bare: tuple  # rows that take a loss torque's reaction without a port
    external: tuple  # (column, row)
    levers: tuple  # (a column, b column, c column, a row, c row, ratio, 3·lever + 1)
    links: tuple  # (first column, second column)
    tables: tuple  # k_b, k_c, η0^w at 3·lever + w + 1
    tables_within: bool  # every η0^w within the safe range (see _settled)


@lru_cache(maxsize=64)
def _plain(mats: TrainMatrices) -> _Plain:
    lay = mats.layout
    ints = lambda a: tuple(int(v) for v in a)  # noqa: E731
    reacting = set(lay.reacting_rows.tolist())
    return _Plain(
        rows=dict(lay.rows),
        parts=lay.parts,
        port_columns=ints(lay.port_columns),
        port_parts=ints(lay.port_parts),
        part_ports=lay.part_ports,
        neighbours=tuple(tuple(int(j) for j in row if j < lay.parts) for row in lay.neighbours),
        parts_at=lay.parts_at,
        reacting=tuple(zip(ints(lay.reacting_rows), lay.reacting_groups)),
        bare=tuple(row for row in (lay.rows[s] for s in (*mats.external, HOUSING)) if row not in reacting),
        external=tuple(zip(ints(lay.external_columns), ints(lay.external_rows))),
        levers=tuple(zip(ints(lay.lever_a_columns), ints(lay.lever_b_columns), ints(lay.lever_c_columns),
                         ints(lay.lever_a_rows), ints(lay.lever_c_rows), [lv.ratio for lv in mats.levers],
                         [3 * k + 1 for k in range(len(mats.levers))])),
        links=tuple(zip(ints(lay.link_first_columns), ints(lay.link_second_columns))),
        tables=tuple(tuple(float(v) for v in table) for table in lay.lever_tables),
        tables_within=_within(float(v) for v in lay.lever_tables[2]),
    )


class _Unusual(Exception):
    """A value is not finite or not normal: the array code decides."""


def evaluate_point(mats: TrainMatrices, speeds: Sequence[float], x: Sequence[float],
                   pattern: Sequence[int] | None, given: Mapping[str, float],
                   efficiencies: np.ndarray | None = None,
                   shaft_torques: np.ndarray | None = None) -> Evaluation | PointEvaluation:
    """:func:`~epicyclic.solver.evaluate.evaluate` of one point: ``speeds`` (train order), the unknowns
    ``x`` and the ``pattern`` as lists, ``given`` as floats; ``efficiencies``, ``shaft_torques`` arrays
    with one column, as for the array code.

    Returns
    -------
    PointEvaluation or Evaluation
        The same numbers as the array code's (an Evaluation, of one column, where the array code took over).

    Raises
    ------
    NonFiniteResultError
        A quantity over- or underflows (from the array code).
    """
    w = None if pattern is None else list(pattern)
    eta = None if efficiencies is None else efficiencies[:, 0].tolist()
    loss_torques = None if shaft_torques is None else shaft_torques[:, 0].tolist()
    try:
        values = _evaluate(_plain(mats), speeds, list(x), w, given, eta, loss_torques)
    except _Unusual:
        column = lambda values: np.array(values, dtype=float).reshape(-1, 1)  # noqa: E731
        return evaluate(mats, column(speeds), column(x), None if w is None else np.array(w).reshape(-1, 1),
                        {s: np.array([v]) for s, v in given.items()}, efficiencies, shaft_torques)
    names = ("x", "torques", "powers", "relative", "rolling", "coupling", "loss", "pattern", "direction")
    return PointEvaluation(dict(zip(names, values), speeds=speeds))


class PointEvaluation:
    """An :class:`~epicyclic.solver.evaluate.Evaluation` of one point, kept as lists of floats.

    ``floats`` maps each quantity's name to its list; the arrays of an Evaluation (one column) are
    made from them on first use.
    """

    normal = True  # every value finite and 0 or normal: checked before it was made
    block = None

    def __init__(self, floats: dict):
        self.floats = floats

    def _column(self, name: str) -> np.ndarray:
        return np.array(self.floats[name], dtype=int if name in ("pattern", "direction") else float).reshape(-1, 1)

    speeds = cached_property(lambda self: self._column("speeds"))
    x = cached_property(lambda self: self._column("x"))
    torques = cached_property(lambda self: self._column("torques"))
    powers = cached_property(lambda self: self._column("powers"))
    relative = cached_property(lambda self: self._column("relative"))
    rolling = cached_property(lambda self: self._column("rolling"))
    coupling = cached_property(lambda self: self._column("coupling"))
    loss = cached_property(lambda self: self._column("loss"))
    pattern = cached_property(lambda self: self._column("pattern"))
    direction = cached_property(lambda self: self._column("direction"))


def _pairwise(values: list) -> float:
    """numpy's pairwise sum of a contiguous run (what ``np.add.reduceat`` adds to a group's first value)."""
    n = len(values)
    if n < 8:
        total = 0.0
        for v in values:
            total += v
        return total
    if n > 128:
        half = n // 2
        half -= half % 8
        return _pairwise(values[:half]) + _pairwise(values[half:])
    r = values[:8]
    i = 8
    while i < n - n % 8:
        for j in range(8):
            r[j] += values[i + j]
        i += 8
    total = ((r[0] + r[1]) + (r[2] + r[3])) + ((r[4] + r[5]) + (r[6] + r[7]))
    for v in values[i:]:
        total += v
    return total


def _normal(values) -> bool:
    """Whether every value is finite and 0 or at least the smallest normal float."""
    for v in values:
        if not (_TINY <= abs(v) <= _HUGE or v == 0.0):
            return False
    return True


def _within(values) -> bool:
    """Whether every non-zero magnitude of ``values`` lies in [_SAFE_LOW, _SAFE_HIGH] (NaN does not)."""
    for v in values:
        a = abs(v)
        if a and not (_SAFE_LOW <= a <= _SAFE_HIGH):
            return False
    return True


def _settled(lay: _Plain, size: list, n: list, given: Mapping[str, float], eta: list | None,
             loss_torques: list | None) -> bool:
    """evaluate._settled of one point: the zero rule leaves every port torque as it is and no result
    can leave the range of normal floats (every non-zero magnitude going in within the safe range, the
    smallest non-zero port torque more than ZERO_TOLERANCE times the largest torque)."""
    if not (_within(size) and _within(n) and _within(given.values())
            and (lay.tables_within if eta is None else _within(eta))
            and (loss_torques is None or _within(loss_torques))):
        return False
    low = min([a for a in size if a], default=math.inf)
    peak = max(size, default=0.0)
    for values in (given.values(), loss_torques or ()):
        for v in values:
            peak = max(peak, abs(v))
    return low > ZERO_TOLERANCE * peak


def _idle_cleaned(lay: _Plain, x: list, port: list, size: list, given: Mapping[str, float],
                  loss_torques: list | None) -> None:
    """The zero rule on the port torques (as evaluate._idle_cleaned): idle elements, and each port's
    round-off of its element's largest, exactly 0; ``port`` and ``x`` changed in place."""
    tol = ZERO_TOLERANCE
    own = [max([size[j] for j in ports]) for ports in lay.part_ports]
    scale = [max([own[j] for j in near]) for near in lay.neighbours]
    for shaft, value in given.items():
        for k in lay.parts_at[lay.rows[shaft]]:
            scale[k] = max(scale[k], abs(value))
    if loss_torques is not None:
        for row in range(len(lay.rows) - 1):
            for k in lay.parts_at[row]:
                scale[k] = max(scale[k], abs(loss_torques[row]))
    idle = [o <= tol * s for o, s in zip(own, scale)]
    for _ in range(lay.parts if any(idle) else 0):
        padded = [s if i else 0.0 for s, i in zip(scale, idle)]
        reach = [max([padded[j] for j in near]) for near in lay.neighbours]
        grown = [max(s, r) if (i or o <= tol * r) else s for s, r, i, o in zip(scale, reach, idle, own)]
        more = [o <= tol * g for o, g in zip(own, grown)]
        if more == idle and grown == scale:
            break
        scale, idle = grown, [i or m for i, m in zip(idle, more)]
    for j, (column, part) in enumerate(zip(lay.port_columns, lay.port_parts)):
        value = 0.0 if idle[part] or size[j] <= tol * own[part] else port[j] + 0.0
        port[j] = x[column] = value


def _evaluate(lay: _Plain, n: list, x: list, w: list | None, given: Mapping[str, float], eta: list | None,
              loss_torques: list | None):
    """The steps of evaluate._evaluate, in its order, on floats."""
    tol = ZERO_TOLERANCE
    # every element's torques exactly in its own ratios
    for k, (a, b, c, _, _, ratio, entry) in enumerate(lay.levers):
        wk = 0 if w is None else w[k]
        if eta is None:
            k_b, k_c = lay.tables[0][entry + wk], lay.tables[1][entry + wk]
        else:
            k_b = ratio * eta[k] if wk > 0 else ratio / eta[k] if wk < 0 else ratio
            k_c = 1.0 - k_b
        t_a = x[a]
        x[b] = -k_b * t_a + 0.0
        x[c] = -k_c * t_a + 0.0
    for first, second in lay.links:
        x[second] = -x[first] + 0.0
    port = [x[c] for c in lay.port_columns]
    size = [abs(v) for v in port]
    settled = _settled(lay, size, n, given, eta, loss_torques)
    if settled:  # no port torque is round-off of another: the zero rule changes nothing but −0
        for j, column in enumerate(lay.port_columns):
            port[j] = x[column] = port[j] + 0.0
    else:
        if not (_normal(n) and _normal(x) and _normal(given.values()) and _normal(port)
                and (eta is None or _normal(eta)) and (loss_torques is None or _normal(loss_torques))):
            raise _Unusual
        _idle_cleaned(lay, x, port, size, given, loss_torques)

    # external torques
    torques = [0.0] * len(lay.rows)
    for row, ports in lay.reacting:
        total = port[ports[0]] + _pairwise([port[j] for j in ports[1:]]) if len(ports) > 1 else port[ports[0]]
        terms = max([abs(port[j]) for j in ports])
        if loss_torques is not None:
            total = total - loss_torques[row]
            terms = max(terms, abs(loss_torques[row]))
        torques[row] = 0.0 if abs(total) <= tol * terms else total + 0.0
    if loss_torques is not None:
        for row in lay.bare:
            torques[row] = -loss_torques[row] + 0.0
    for shaft, value in given.items():
        torques[lay.rows[shaft]] = value
    for column, row in lay.external:
        x[column] = torques[row]
    powers = [t * s * RPM_TO_RAD_S + 0.0 for t, s in zip(torques, n)]

    # levers
    relative, rolling, coupling, loss, observed, direction = [], [], [], [], [], []
    for k, (a, _, _, row_a, row_c, _, entry) in enumerate(lay.levers):
        speed_a, speed_c = n[row_a], n[row_c]
        difference = speed_a - speed_c
        rel = 0.0 if abs(difference) <= tol * max(abs(speed_a), abs(speed_c)) else difference + 0.0
        t_a = x[a]
        roll = t_a * rel * RPM_TO_RAD_S + 0.0
        wk = 0 if w is None else w[k]
        if eta is None:
            factor = lay.tables[2][entry + wk]
        else:
            factor = eta[k] if wk > 0 else 1.0 / eta[k] if wk < 0 else 1.0
        sign = (roll > 0.0) - (roll < 0.0)
        relative.append(rel)
        rolling.append(roll)
        coupling.append(t_a * speed_c * RPM_TO_RAD_S + 0.0)
        loss.append(roll * (1.0 - factor) + 0.0)
        observed.append(sign)
        direction.append(sign if w is None else (0 if sign == 0 else wk))
    if not settled and not _normal(x + torques + powers + relative + rolling + coupling + loss):
        raise _Unusual  # settled: no value can leave the range of normal floats
    return x, torques, powers, relative, rolling, coupling, loss, observed, direction
