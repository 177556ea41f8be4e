"""From solved speeds and torques to the quantities of a result, cleaned once.

The scalar solver and the batch solver both call :func:`evaluate`, with the
operating points along the last axis of every array, so that they agree point
for point.  Here the zero rule of :mod:`epicyclic.results.zero` is applied:

* every element's torques keep its own ratios exactly (T_b = −i0·η0^w·T_a,
  T_c = −(1 − i0·η0^w)·T_a, the two torques of a clutch or brake opposite),
  and a port torque that is round-off of the element's largest is 0;
* an element whose torques are round-off of the torques of the elements it
  shares a shaft with (the housing, which takes every element's reaction,
  aside) is idle (all its torques exactly 0), and so is an element whose
  torques are round-off of the scale by which a neighbour was found idle;
* a lever whose relative speed is round-off of its port speeds is locked
  (relative speed, rolling power and loss exactly 0);
* external torques are the given values exactly, and elsewhere the balance of
  the (cleaned) port torques on the shaft: the housing's reaction, a load's
  torque;
* powers are products of cleaned torques and speeds (0 where either is 0);
* the loss of a lever is P_w·(1 − η0^w), never a difference of large port powers.

References
----------
Brandenberger 1952, eqs. 3' and 7 (the loss is the rolling power times 1 − η0^w);
Queitsch, Wälz- und Kupplungsleistung.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from ..errors import NonFiniteResultError
from ..results.solution import RPM_TO_RAD_S
from ..results.zero import ZERO_TOLERANCE
from ..model.elements import HOUSING
from .assembly import TrainMatrices
from .linear import span

__all__ = ["Evaluation", "evaluate", "check_finite", "directions", "given_columns", "relative_speeds"]

#: The smallest normal float: below it a result has lost its precision (underflow).
_TINY = np.finfo(float).tiny
#: The largest finite float.
_HUGE = np.finfo(float).max
#: Non-zero magnitudes of speeds, torques and factors in which no result of :func:`evaluate` (products
#: of at most four of them, sums of such products) can over- or underflow: far inside the float range.
_SAFE_LOW, _SAFE_HIGH = 1e-50, 1e50


@dataclass(frozen=True, eq=False)
class Evaluation:
    """Cleaned quantities, shafts/columns/levers along axis 0, points along the last axis.

    Attributes
    ----------
    speeds : ndarray (shafts, P)
        1/min, in ``train.shafts`` order (housing last, exactly 0).
    x : ndarray (columns, P)
        Port torques (idle ones exactly 0) and external torques, N·m.
    torques, powers : ndarray (shafts, P)
        External torque (N·m) and power (W) of every shaft; 0 where none acts.
    relative : ndarray (levers, P)
        n_a − n_c of every lever, 1/min (exactly 0 when locked).
    rolling, coupling, loss : ndarray (levers, P)
        W.
    pattern : ndarray of int (levers, P)
        Sign of the rolling power (0 exactly where it is 0).
    direction : ndarray of int (levers, P)
        The loss direction w the torques were solved with where rolling power
        flows, 0 where none flows (equal to ``pattern`` in a consistent solution,
        and to it without losses).
    """

    speeds: np.ndarray
    x: np.ndarray
    torques: np.ndarray
    powers: np.ndarray
    relative: np.ndarray
    rolling: np.ndarray
    coupling: np.ndarray
    loss: np.ndarray
    pattern: np.ndarray
    direction: np.ndarray
    block: np.ndarray | None = None  # x, torques, powers, rolling, coupling, loss, relative: rows of one array
    normal: bool | None = None  # every value (speeds included) finite and 0 or normal (None: not known)


def evaluate(mats: TrainMatrices, speeds: np.ndarray, x: np.ndarray, pattern: np.ndarray | None,
             given: Mapping[str, np.ndarray], efficiencies: np.ndarray | None = None,
             shaft_torques: np.ndarray | None = None, relative: np.ndarray | None = None,
             speed_span: tuple[float, float] | None = None) -> Evaluation:
    """Clean the solved torques and derive torques, powers, rolling powers and losses.

    Parameters
    ----------
    mats : TrainMatrices
    speeds : ndarray (shafts, P)
        All shaft speeds in ``train.shafts`` order, 1/min.
    x : ndarray (columns, P)
        Solved torques, N·m (columns of ``mats.torque_columns``).
    pattern : ndarray (levers, P) or None
        Loss directions the torques were solved with (None: lossless).
    given : mapping shaft → ndarray (P,)
        Given external torques (signed), N·m.
    efficiencies : ndarray (levers, P), optional
        η0 of every lever at every point (default: the levers' own).
    shaft_torques : ndarray (shafts, P), optional
        Given loss torques acting on the shafts (:mod:`~epicyclic.solver.given_losses`),
        N·m: a shaft's external torque balances them too (M_s + T_loss − Σ T_port = 0).
    relative : ndarray (levers, P), optional
        :func:`relative_speeds` of ``speeds``, where already known.
    speed_span : (float, float), optional
        :func:`~epicyclic.solver.linear.span` of ``|speeds|``, where already known.

    Returns
    -------
    Evaluation
    """
    with np.errstate(all="ignore"):  # overflow is reported by check_finite, by name
        result = _evaluate(mats, speeds, x, pattern, given, efficiencies, shaft_torques, relative, speed_span)
    check_finite(mats, result)
    return result


def directions(mats: TrainMatrices, speeds: np.ndarray, x: np.ndarray, given: Mapping[str, np.ndarray],
               relative: np.ndarray, rows, speed_span: tuple[float, float] | None = None
               ) -> tuple[np.ndarray, dict[int, np.ndarray]] | None:
    """Of the lossless evaluation, only what a lossy solution needs: the ``pattern`` (sign of every
    lever's rolling power) and the ``powers`` of the shaft rows ``rows`` (the roles of connected shafts).

    The same numbers as ``evaluate(mats, speeds, x, None, given, relative=relative)`` gives, where
    :func:`_settled` shows that the zero rule leaves the port torques as they are and nothing can
    leave the float range; None elsewhere (then call :func:`evaluate`).  Only the ports a balance
    needs are computed, and the span of the others follows from the lever ports a (T_b = −i0·T_a,
    T_c = −(1 − i0)·T_a without losses, each rounded once): a fraction of the operations.
    """
    lay = mats.layout
    with np.errstate(all="ignore"):
        t_a = x[lay.lever_a_columns]
        first = x[lay.link_first_columns]
        lever = 3 * np.arange(len(mats.levers)) + 1  # w = 0
        k_b, k_c = lay.lever_tables[0][lever], lay.lever_tables[1][lever]
        factors = np.abs(np.concatenate([k_b, k_c]))
        if not np.isfinite(factors).all():
            return None
        factors = factors[factors > 0]
        least_a, most_a = span(np.abs(t_a))
        least_first, most_first = span(np.abs(first))
        low = min(least_a, least_first, least_a * factors.min(initial=np.inf) * (1.0 - 1e-12))
        peak = max(most_a, most_first, most_a * factors.max(initial=0.0) * (1.0 + 1e-12))
        if not _settled(lay, (low, peak), speeds, given, None, None, speed_span):
            return None
        derived = {}  # port column → how evaluate computes it
        for k, (a, b, c) in enumerate(zip(lay.lever_a_columns, lay.lever_b_columns, lay.lever_c_columns)):
            derived |= {int(a): lambda k=k: t_a[k] + 0.0, int(b): lambda k=k: -k_b[k] * t_a[k] + 0.0,
                        int(c): lambda k=k: -k_c[k] * t_a[k] + 0.0}
        for k, (one, two) in enumerate(zip(lay.link_first_columns, lay.link_second_columns)):
            derived |= {int(one): lambda k=k: first[k] + 0.0, int(two): lambda k=k: -first[k] + 0.0}
        given_rows = {lay.rows[s]: value for s, value in given.items()}
        reacting = dict(zip(lay.reacting_rows.tolist(), lay.reacting_groups))
        powers = {}
        for row in rows:
            if row in given_rows:
                torque = given_rows[row]
            elif row in reacting:
                group = reacting[row]
                port = np.array([derived[int(lay.port_columns[j])]() for j in group])
                if len(group) == 1:  # _clean(p, |p|) is p + 0.0
                    torque = port[0]
                else:
                    whole = [tuple(range(len(group)))]
                    torque = _clean(_sums(port, whole)[0], _rows(np.maximum, np.abs(port), whole)[0])
            else:
                torque = np.zeros(speeds.shape[1:])
            power = torque * speeds[row]
            power *= RPM_TO_RAD_S
            power += 0.0
            powers[row] = power
        rolling = t_a * relative
        rolling *= RPM_TO_RAD_S
        rolling += 0.0
        return _signs(rolling), powers


def _signs(values: np.ndarray) -> np.ndarray:
    """``np.sign(values).astype(int)`` for values without NaN (−0 → 0)."""
    return np.sign(values).astype(int)


def relative_speeds(mats: TrainMatrices, speeds: np.ndarray) -> np.ndarray:
    """n_a − n_c of every lever (1/min), exactly 0 where it is round-off of its port speeds (locked)."""
    lay = mats.layout
    with np.errstate(all="ignore"):
        a, c = speeds[lay.lever_a_rows], speeds[lay.lever_c_rows]
        return _clean(a - c, np.maximum(np.abs(a), np.abs(c)))


def _evaluate(mats: TrainMatrices, speeds: np.ndarray, x: np.ndarray, pattern: np.ndarray | None,
              given: Mapping[str, np.ndarray], efficiencies: np.ndarray | None = None,
              shaft_torques: np.ndarray | None = None, relative: np.ndarray | None = None,
              speed_span: tuple[float, float] | None = None) -> Evaluation:
    # Reductions over the few rows of a part or a shaft are written row by row (_rows): numpy's
    # reductions along axis 0 of a (rows, points) array are many times slower than whole-row operations.
    # The results are rows of one array (``block``), so that one pass checks them all (check_finite).
    lay = mats.layout
    points = speeds.shape[1:]
    levers, shafts, columns = len(mats.levers), len(lay.rows), len(mats.torque_columns)
    block = np.empty((columns + 2 * shafts + 4 * levers,) + points)
    x_in, x = x, block[:columns]
    kept = given_columns(mats)  # the columns not derived below (lever ports b, c, links' second, externals)
    x[kept] = x_in[kept]
    torques = block[columns:columns + shafts]
    powers = block[columns + shafts:columns + 2 * shafts]
    rolling, coupling, loss, relative_out = (block[columns + 2 * shafts + k * levers:columns + 2 * shafts
                                                   + (k + 1) * levers] for k in range(4))

    # the lever's entries of k_b, k_c and η0^w: index 3·lever + w + 1 of lay.lever_tables
    table = (3 * np.arange(levers) + 1).reshape((-1,) + (1,) * len(points))
    used = None if pattern is None else np.asarray(pattern, dtype=int)
    if used is not None:
        table = table + used
    elif efficiencies is not None:
        used = np.zeros((levers,) + points, dtype=int)

    # every element's torques exactly in its own ratios: T_b = −k_b·T_a, T_c = −k_c·T_a, link T_2 = −T_1
    if levers:
        if efficiencies is None:  # −k_b, −k_c from the negated tables (the same numbers as −(k·T))
            minus_b, minus_c = (-lay.lever_tables[0]).take(table), (-lay.lever_tables[1]).take(table)
        else:  # η0 per point (given losses): k_b = i0·η0^w, k_c = 1 − k_b
            i0 = np.array([lv.ratio for lv in mats.levers]).reshape((-1,) + (1,) * len(points))
            k_b = np.where(used > 0, i0 * efficiencies, np.where(used < 0, i0 / efficiencies, i0))
            minus_b, minus_c = -k_b, -(1.0 - k_b)
        t_a = x[lay.lever_a_columns]
        x[lay.lever_b_columns] = minus_b * t_a + 0.0
        x[lay.lever_c_columns] = minus_c * t_a + 0.0
    x[lay.link_second_columns] = -x[lay.link_first_columns] + 0.0

    ports = _ports(lay)
    port = x[ports]
    size = np.abs(port)
    settled = _settled(lay, span(size), speeds, given, efficiencies, shaft_torques, speed_span)
    if settled:  # no port torque is round-off of another: the zero rule changes nothing but −0
        port += 0.0
    else:
        port = _idle_cleaned(lay, port, size, given, shaft_torques)
    if not (settled and isinstance(ports, slice)):  # else port is a view of x
        x[ports] = port

    # external torques: given exactly, else the balance of the port torques on the shaft
    torques[...] = 0.0
    reacting_rows, groups = _balanced(lay, given, shaft_torques is None)
    if len(reacting_rows):
        total = _sums(port, groups)
        terms = _rows(np.maximum, size if settled else np.abs(port), groups)
        if shaft_torques is not None:  # M_s = Σ T_port − T_loss
            total = total - shaft_torques[reacting_rows]
            terms = np.maximum(terms, np.abs(shaft_torques[reacting_rows]))
        torques[reacting_rows] = _clean(total, terms)
    if shaft_torques is None:  # one port, no loss torque: the balance is the (cleaned) port torque itself
        given_rows = {lay.rows[s] for s in given}
        for row, group in zip(lay.reacting_rows.tolist(), lay.reacting_groups):
            if len(group) == 1 and row not in given_rows:
                torques[row] = port[group[0]]
    if shaft_torques is not None:  # reactions of loss torques where no port is (the housing, say)
        reacting = set(lay.reacting_rows.tolist())
        bare = [row for row in (lay.rows[s] for s in (*mats.external, HOUSING)) if row not in reacting]
        torques[bare] = -shaft_torques[bare] + 0.0
    for shaft, value in given.items():
        torques[lay.rows[shaft]] = value
    x[lay.external_columns] = torques[lay.external_rows]
    np.multiply(torques, speeds, out=powers)
    powers *= RPM_TO_RAD_S
    powers += 0.0  # P = M·ω, never −0

    # levers: relative speed, rolling and coupling power, loss
    relative_out[...] = relative_speeds(mats, speeds) if relative is None else relative
    relative = relative_out
    c = speeds[lay.lever_c_rows]
    t_a = x[lay.lever_a_columns]
    for out, other in ((rolling, relative), (coupling, c)):  # T_a·(n_a − n_c)·π/30 and T_a·n_c·π/30
        np.multiply(t_a, other, out=out)
        out *= RPM_TO_RAD_S
        out += 0.0
    if efficiencies is None:
        lost = (1.0 - lay.lever_tables[2]).take(table)  # 1 − η0^w (1/η0 only where solved with it)
    else:
        lost = 1.0 - np.where(used > 0, efficiencies, np.where(used < 0, 1.0 / efficiencies, 1.0))
    np.multiply(rolling, lost, out=loss)
    loss += 0.0
    normal = _block_normal(block, speeds) if not settled else True  # settled: no value can leave the range
    if normal is None and _subnormal(block[columns + shafts:columns + 2 * shafts + 3 * levers]):  # powers, rolling, coupling, loss
        # rare: a power below the float range next to normal powers is 0 (torques and speeds are not
        # flushed: a subnormal torque at a huge speed can still carry power; check_finite names them)
        for array in (powers, rolling, coupling, loss):
            array[...] = _flush(array)
    observed = _signs(rolling)
    direction = observed if pattern is None else used * (observed != 0)
    return Evaluation(speeds, x, torques, powers, relative, rolling, coupling, loss, observed, direction, block,
                      normal)


def given_columns(mats: TrainMatrices) -> np.ndarray | slice:
    """The columns of x that :func:`evaluate` reads: lever ports a and links' first ports (the others
    follow from them exactly; all columns where some column is neither a port nor an external torque)."""
    lay = mats.layout
    if len(lay.port_columns) + len(lay.external_columns) != len(mats.torque_columns):
        return slice(None)
    return np.concatenate([lay.lever_a_columns, lay.link_first_columns]).astype(int)


def _balanced(lay, given: Mapping[str, np.ndarray], plain: bool) -> tuple[np.ndarray, tuple]:
    """Reacting rows whose torque is a balance to compute, and their groups of ports: not the rows of
    given torques (they are the given values), nor, where ``plain`` (no loss torques), single ports
    (their balance is the port torque: ``_clean(p, |p|)`` is ``p + 0.0``, which the port already is)."""
    rows = {lay.rows[s] for s in given}
    keep = [k for k, (row, group) in enumerate(zip(lay.reacting_rows.tolist(), lay.reacting_groups))
            if row not in rows and not (plain and len(group) == 1)]
    return lay.reacting_rows[keep], tuple(lay.reacting_groups[k] for k in keep)


def _idle_cleaned(lay, port: np.ndarray, size: np.ndarray, given: Mapping[str, np.ndarray],
                  shaft_torques: np.ndarray | None) -> np.ndarray:
    """The port torques with the zero rule applied: idle elements and round-off ports exactly 0."""
    points = port.shape[1:]
    # idle elements: torques that are round-off of the torques of the elements they share a shaft with
    padded = np.zeros((lay.parts + 1,) + points)  # the last row: no neighbour
    own = padded[:-1]
    _rows(np.maximum, size, lay.part_ports, own)
    own = own.copy()
    scale = _neighbours(padded, lay.neighbours) if lay.parts else own.copy()
    for shaft, value in given.items():  # a given torque at one of its shafts
        for k in lay.parts_at[lay.rows[shaft]]:
            scale[k] = np.maximum(scale[k], np.abs(value))
    if shaft_torques is not None:  # and a loss torque
        for row in range(len(lay.rows) - 1):
            for k in lay.parts_at[row]:
                scale[k] = np.maximum(scale[k], np.abs(shaft_torques[row]))
    finite = np.isfinite(own)  # an overflowed torque is never idle (inf <= 1e-12·inf): check_finite names it
    idle = finite & (own <= ZERO_TOLERANCE * scale)
    # an idle element hands the scale it was judged by on to its neighbours (an isolated group of
    # elements that only a now-idle element joined to the rest is round-off of the same scale)
    for _ in range(lay.parts if idle.any() else 0):
        padded[:-1] = np.where(idle, scale, 0.0)
        reach = _neighbours(padded, lay.neighbours)
        grown = np.where(idle | (own <= ZERO_TOLERANCE * reach), np.maximum(scale, reach), scale)
        more = finite & (own <= ZERO_TOLERANCE * grown)
        if (more == idle).all() and (grown == scale).all():
            break
        scale, idle = grown, idle | more
    # a port torque that is round-off of its element's largest is 0 (the zero rule of clean_array)
    zero = idle[lay.port_parts] | ((size <= ZERO_TOLERANCE * own[lay.port_parts]) & np.isfinite(port))
    port = np.where(zero, 0.0, port) + 0.0
    return port


def _block_normal(block: np.ndarray, speeds: np.ndarray) -> bool | None:
    """Whether every value of ``block`` and ``speeds`` is finite and 0 or normal; None where some is subnormal."""
    size = np.abs(block)
    small = size < _TINY
    if not np.count_nonzero(small) or not np.count_nonzero(size[small]):  # no subnormal value
        return bool(size.max(initial=0.0) <= _HUGE) and _normal(speeds)
    return None


def _settled(lay, port_span: tuple[float, float], speeds: np.ndarray, given: Mapping[str, np.ndarray],
             efficiencies: np.ndarray | None, shaft_torques: np.ndarray | None,
             speed_span: tuple[float, float] | None = None) -> bool:
    """Whether the zero rule leaves every port torque as it is and no result can leave the float range.

    Both hold when every non-zero magnitude going in (port torques, ``port_span`` = their smallest non-zero
    and largest magnitude or bounds of them, speeds, given and loss
    torques, the factors η0^w) lies within [``_SAFE_LOW``, ``_SAFE_HIGH``] — the few products and sums
    of :func:`_evaluate` then stay far inside the range of normal floats — and the smallest non-zero
    port torque is more than ``ZERO_TOLERANCE`` times the largest torque of all points (no element can
    be idle and no port round-off of its element's largest: the scales they are judged by are never
    larger).  Two reductions per array instead of the zero rule's and the range check's passes
    (``speed_span``: :func:`~epicyclic.solver.linear.span` of ``|speeds|`` where already known).
    """
    low, peak = port_span
    torques = (*given.values(), *(() if shaft_torques is None else (shaft_torques,)))  # scales of the rule too
    factor = lay.lever_tables[2] if efficiencies is None else efficiencies
    for values in (*torques, factor, *(() if speed_span else (speeds,))):
        least, most = span(np.abs(values))
        if not (least >= _SAFE_LOW and most <= _SAFE_HIGH):
            return False
        if any(values is t for t in torques):
            peak = max(peak, most)
    if speed_span and not (speed_span[0] >= _SAFE_LOW and speed_span[1] <= _SAFE_HIGH):
        return False
    return bool(_SAFE_LOW <= low and peak <= _SAFE_HIGH and low > ZERO_TOLERANCE * peak)  # NaN fails too


def _ports(lay) -> slice | np.ndarray:
    """The port columns of x: a slice where they are the first columns in order (a view, no copy)."""
    columns = lay.port_columns
    if np.array_equal(columns, np.arange(columns.size)):
        return slice(0, int(columns.size))
    return columns


def _clean(values: np.ndarray, scale: np.ndarray) -> np.ndarray:
    """:func:`~epicyclic.results.zero.clean_array` for a float array and a scale ≥ 0 of its shape.

    ``values`` is a temporary: it is cleaned in place where nothing in it is round-off (the usual case).
    """
    zero = np.abs(values) <= ZERO_TOLERANCE * scale
    if not np.count_nonzero(zero):
        values += 0.0
        return values
    zero &= np.isfinite(values)
    out = np.where(zero, 0.0, values)
    out += 0.0
    return out


def _rows(ufunc, array: np.ndarray, groups, out: np.ndarray | None = None) -> np.ndarray:
    """``ufunc`` reduced over each group of rows of ``array``, in order (one output row per group)."""
    if out is None:
        out = np.empty((len(groups),) + array.shape[1:])
    for k, rows in enumerate(groups):
        if len(rows) == 1:
            out[k] = array[rows[0]]
            continue
        ufunc(array[rows[0]], array[rows[1]], out=out[k])
        for r in rows[2:]:
            ufunc(out[k], array[r], out=out[k])
    return out


def _sums(array: np.ndarray, groups) -> np.ndarray:
    """Per group of rows of ``array``: their sum, added in the order of ``np.add.reduceat`` along axis 0.

    That is the first row plus the sum of the rest, row after row (the whole group through
    ``reduceat`` where the rest has 8 rows or more, or the points are one: numpy then sums pairwise).
    """
    out = np.empty((len(groups),) + array.shape[1:])
    for k, rows in enumerate(groups):
        if len(rows) == 1:
            out[k] = array[rows[0]]
        elif len(rows) > 8 or array.shape[1:] == (1,):
            out[k] = np.add.reduceat(array[list(rows)], [0], axis=0)[0]
        else:
            rest = array[rows[1]].copy()
            for r in rows[2:]:
                rest += array[r]
            np.add(array[rows[0]], rest, out=out[k])
    return out


def _neighbours(padded: np.ndarray, neighbours: np.ndarray) -> np.ndarray:
    """Per part: the largest value of ``padded`` among its neighbours (its own row included)."""
    out = padded[neighbours[:, 0]]
    for j in range(1, neighbours.shape[1]):
        np.maximum(out, padded[neighbours[:, j]], out=out)
    return out


def _subnormal(values: np.ndarray) -> bool:
    """Whether some value is below the smallest normal float but not 0 (a NaN is not)."""
    size = np.abs(values)
    return bool(np.count_nonzero(size < _TINY) != np.count_nonzero(size == 0))


def _flush(values: np.ndarray) -> np.ndarray:
    """Subnormal values that are numerically zero next to their kind at the same point become 0.

    What stays subnormal is a whole quantity below the float range: :func:`check_finite` names it.
    """
    size = np.abs(values)
    if values.size == 0 or not np.any((size < _TINY) & (size > 0)):
        return values
    scale = size.max(axis=0, keepdims=True)
    return np.where((size < _TINY) & (size <= ZERO_TOLERANCE * scale), 0.0, values) + 0.0


def _normal(values: np.ndarray) -> bool:
    """Whether every value is finite and either 0 or at least the smallest normal float."""
    size = np.abs(values)
    return bool(size.max(initial=0.0) <= _HUGE) and np.count_nonzero(size < _TINY) == np.count_nonzero(size == 0)


def check_finite(mats: TrainMatrices, ev: Evaluation) -> None:
    """Raise :class:`~epicyclic.errors.NonFiniteResultError` naming the first quantity that over- or underflows."""
    # first all at once: the block holds every checked array (and x's external columns, copies of the
    # torques, and the relative speeds, which never decide alone); where it is not all normal, the
    # arrays one by one say whether one of them over- or underflows, and which
    if ev.normal or (ev.block is not None and _normal(ev.block) and _normal(ev.speeds)):
        return
    arrays = (ev.speeds, ev.x[mats.layout.port_columns], ev.torques, ev.powers, ev.rolling, ev.coupling, ev.loss)
    shafts = [f"shaft {s!r}" for s in mats.train.shafts]
    ports = [f"{element!r} at shaft {shaft!r}" for element, shaft, _ in mats.port_shaft_columns]
    levers = [repr(lever.element.name) for lever in mats.levers]
    for quantity, array, labels, unit in zip(
        ("speed", "torque", "torque", "power", "rolling power", "coupling power", "loss"), arrays,
        (shafts, ports, shafts, shafts, levers, levers, levers), ("1/min", "N·m", "N·m", "W", "W", "W", "W"),
    ):
        size = np.abs(array)
        bad = ~np.isfinite(array) | ((size < _TINY) & (size > 0))
        if not bad.any():
            continue
        where = np.argwhere(bad)[0]
        point = f" at operating point {int(where[1])}" if array.ndim > 1 and array.shape[1] > 1 else ""
        how = ("is not a finite number: it overflows" if not np.isfinite(array[tuple(where)])
               else "underflows")
        raise NonFiniteResultError(
            f"the {quantity} of {labels[where[0]]}{point} {how} the floating-point range "
            f"(about 2.2e-308 to 1.8e308 {unit}): the given speeds, torques or powers are too "
            f"{'small' if how == 'underflows' else 'large'} for this train; give them in a range where "
            "speeds and torques and their products stay between about 1e-300 and 1e300.",
            quantity, labels[where[0]],
        )
