"""Batch solution: the same analysis over numpy arrays of operating points.

The equations depend on the train and on the loss-direction pattern w, not
on the operating point.  So the speeds of all points come from
one matrix product, the ideal torques from another, and the lossy torques
from one product per distinct pattern w — typically one or two for a whole
efficiency map.  Self-locking points are flagged, never given a negative
efficiency.

References
----------
Brandenberger 1952, eqs. 1–10.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np

from ..errors import EpicyclicError, NonFiniteResultError, OperatingPointError
from ..model.elements import HOUSING
from ..model.operating_point import OperatingPoint
from ..model.train import GearTrain
from ..results.solution import RPM_TO_RAD_S
from ..units import to_core_array
from .assembly import matrices
from .evaluate import directions, evaluate, given_columns, relative_speeds
from .friction_state import ambiguous_points
from .given_losses import given_losses, with_efficiencies
from .kinematics import check_speeds, speed_solver
from .linear import span
from .self_locking import SELF_LOCKING_MARGIN, limit_solver, with_pattern
from .solve import MAX_PATTERN_TRIES, _validate
from .statics import TorqueSolver, torque_solver

__all__ = ["BatchSolution", "solve_batch"]

ArrayMap = Mapping[str, np.ndarray]
#: The smallest normal and the largest finite float.
_TINY, _HUGE = np.finfo(float).tiny, np.finfo(float).max


@dataclass(frozen=True, eq=False)
class BatchSolution:
    """Arrays of results, one entry per operating point (shape of the inputs).

    Attributes
    ----------
    speeds, torques, powers : mapping shaft → ndarray
        1/min, N·m (external), W (positive into the train).
    port_torques : mapping (element, port) → ndarray
        Torque a shaft exerts on each element port, N·m.
    losses : mapping element → ndarray
        Loss per element, W (and under ``"housing"`` the auxiliaries' given torques: pump, seals).
    input_power, output_power, loss : ndarray
        W.
    efficiency : ndarray
        output/input; NaN exactly where ``self_locking`` is True or no power
        enters (see ``defined``).
    self_locking : ndarray of bool
    ambiguous : ndarray of bool
        Where the friction state is not unique: another loss-direction pattern (one element's
        reversed) is consistent too and keeps the designated drives and loads; the result shows
        the one reached from the lossless power flow, as :func:`~epicyclic.solver.solve.solve`
        does (which warns).  See :mod:`~epicyclic.solver.friction_state`.
    patterns : int
        Number of distinct loss-direction patterns solved.
    loss_sources : mapping element → mapping source → ndarray
        Each element's loss by source (``mesh``, ``bearing``, ``drag``, or the sources the loss
        torques are given by), W; ``"housing"``: the auxiliaries' (pump, seals).
    oil_temperature : ndarray or None
        The oil temperature the spin losses were evaluated at, °C (None without spin losses;
        see :func:`epicyclic.losses.solve_batch_with_losses`).
    """

    train: GearTrain
    speeds: ArrayMap
    torques: ArrayMap
    powers: ArrayMap
    port_torques: Mapping[tuple[str, str], np.ndarray]
    losses: ArrayMap
    input_power: np.ndarray
    output_power: np.ndarray
    loss: np.ndarray
    efficiency: np.ndarray
    self_locking: np.ndarray
    patterns: int
    loss_sources: Mapping[str, ArrayMap] = field(default_factory=dict)
    ambiguous: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=bool))
    oil_temperature: np.ndarray | None = None

    @property
    def shape(self) -> tuple[int, ...]:
        return self.input_power.shape

    @property
    def defined(self) -> np.ndarray:
        """Where the efficiency is defined (power enters and no self-locking)."""
        return ~np.isnan(self.efficiency)

    def __len__(self) -> int:
        return int(self.input_power.size)

    def __repr__(self) -> str:
        eff = self.efficiency[self.defined]
        span = f"efficiency {eff.min():.4f}…{eff.max():.4f}" if eff.size else "no defined efficiency"
        return (
            f"<BatchSolution {self.train.name!r}: {len(self)} points, {span}, "
            f"{int(self.self_locking.sum())} self-locking, {self.patterns} loss pattern(s)"
            + (f", {int(self.ambiguous.sum())} with a friction state that is not unique" if self.ambiguous.any() else "")
            + ">"
        )


def _broadcast(groups: Sequence[Mapping[str, object]]) -> tuple[list[dict[str, np.ndarray]], tuple[int, ...]]:
    """The given speeds, torques and powers in 1/min, N·m, W (units converted, never stripped; errors name
    the field and index: :func:`~epicyclic.units.to_core_array`), flattened in one broadcast shape."""
    groups = [{k: to_core_array(v, quantity, field=f"solve_batch: {name}[{k!r}]") for k, v in g.items()}
              for name, quantity, g in zip(("speeds", "torques", "powers"), ("speed", "torque", "power"), groups)]
    named = {f"{n}[{k!r}]": v.shape for n, g in zip(("speeds", "torques", "powers"), groups) for k, v in g.items()}
    try:
        shape = np.broadcast_shapes(*named.values())
    except ValueError:  # name the arrays, not numpy's argument numbers
        shapes = ", ".join(f"{n} has shape {s}" for n, s in named.items())
        raise OperatingPointError(f"solve_batch: the given arrays do not broadcast to one shape ({shapes}).") from None
    return [{k: np.broadcast_to(v, shape).ravel() for k, v in g.items()} for g in groups], shape


def solve_batch(
    train: GearTrain,
    *,
    speeds: Mapping[str, object],
    torques: Mapping[str, object] | None = None,
    powers: Mapping[str, object] | None = None,
    drives: Sequence[str] = (),
    loads: Sequence[str] = (),
    connected: Sequence[str] = (),
    efficiencies: Mapping[str, Mapping[str, object]] | None = None,
    loss_torques: Mapping[str, Mapping[str, object]] | None = None,
) -> BatchSolution:
    """Solve ``train`` at many operating points at once.

    Parameters
    ----------
    train : GearTrain
    speeds, torques, powers : mapping shaft → array_like
        As in :class:`~epicyclic.OperatingPoint`: plain numbers in 1/min, N·m, W, or
        values with units (strings such as ``"1500 U/min"``, pint quantities, also a
        quantity holding an array), each value an array; all broadcast to one shape.
    drives, loads, connected : sequence of str
        As in :class:`~epicyclic.OperatingPoint`.
    efficiencies, loss_torques : mapping, optional
        As in :func:`~epicyclic.solver.solve.solve`, each value a number or an
        array of the points (flattened order): per-point efficiency factors are
        solved with the operator of their loss pattern and a correction of the
        lever rows (:func:`_corrected`), the torques as a right-hand side.

    Returns
    -------
    BatchSolution

    Raises
    ------
    UnitError
        A value that cannot be read or has the wrong dimension; the message names the
        field and the index, e.g. ``solve_batch: speeds['sun'][2]``.
    OperatingPointError, UnderdeterminedError, ContradictionError
        As :func:`~epicyclic.solver.solve.solve`, naming the first bad point.

    Examples
    --------
    >>> import numpy as np
    >>> from epicyclic import GearTrain, PlanetarySet, Brake
    >>> train = GearTrain([PlanetarySet("P", "sun", "ring", "carrier", -2.0, 0.97), Brake("B", "ring")])
    >>> res = solve_batch(train, speeds={"sun": np.linspace(100, 3000, 4)},
    ...                   torques={"sun": 10.0}, drives=["sun"], loads=["carrier"])
    >>> res.efficiency.round(4).tolist(), res.patterns
    ([0.98, 0.98, 0.98, 0.98], 1)
    """
    (speed_in, torque_in, power_in), shape = _broadcast([speeds, torques or {}, powers or {}])
    template = OperatingPoint(
        speeds={k: 0.0 for k in speed_in}, torques={k: 0.0 for k in torque_in},
        powers={k: 0.0 for k in power_in}, drives=tuple(drives), loads=tuple(loads),
        connected=tuple(connected),
    )
    _validate(train, template)
    problem = _Problem(train, matrices(train, template.external_shafts), speed_in, torque_in, power_in,
                       tuple(drives), tuple(loads), efficiencies, loss_torques,
                       int(np.prod(shape)) if shape else 1)
    if problem.points <= BLOCK:
        results, solved = _solve_points(problem, slice(None))
        return _assembled(problem, results, solved, shape)
    results, solved = {}, set()
    try:
        for start in range(0, problem.points, BLOCK):
            block = slice(start, start + BLOCK)
            values, patterns = _solve_points(problem, block)
            for key, value in values.items():  # each block's results go to their place while in cache
                if key not in results:
                    results[key] = np.empty(problem.points, dtype=value.dtype)
                results[key][block] = value
            solved |= patterns
    except EpicyclicError:
        # the error as the whole batch in one block reports it (the first bad point, checks in the same order)
        _solve_points(_Problem(*problem.inputs), slice(None))
        raise
    return _assembled(problem, results, solved, shape)


#: Operating points solved together: a block's arrays stay in the processor's cache instead of
#: streaming every intermediate array of all points through memory (see docs/performance.md).
#: Every result is computed point by point, so the blocks give the same numbers as one block.
BLOCK = 16384


class _Problem:
    """What every block of points shares: the train's equations, the given arrays, the given losses."""

    def __init__(self, train, mats, speed_in, torque_in, power_in, drives, loads, efficiencies, loss_torques,
                 points):
        self.inputs = (train, mats, speed_in, torque_in, power_in, drives, loads, efficiencies, loss_torques,
                       points)
        self.train, self.mats, self.points = train, mats, points
        self.speed_in, self.torque_in, self.power_in = speed_in, torque_in, power_in
        self.drives, self.loads = drives, loads
        self.efficiencies, self.loss_torques = efficiencies, loss_torques
        self.given_speed = [s for s in speed_in if s != HOUSING]
        self.given = list(dict.fromkeys([*power_in, *torque_in]))
        self.shaft_row = {s: k for k, s in enumerate(train.shafts)}
        self._losses = None

    def losses(self):
        """(given losses, their train's equations, lever rows of the loss torques); for all points, once."""
        if self._losses is None:
            mats = self.mats
            extra = given_losses(mats, self.efficiencies, self.loss_torques, self.points)
            rows = None
            if extra is not None:  # reference η0 per lever: the median over the points; the rest is a correction
                mats = matrices(with_efficiencies(self.train, {lv.element.name: float(np.median(extra.efficiency[k]))
                                                               for k, lv in enumerate(mats.levers)}), mats.external)
                rows = extra.rows(mats) if extra.has_torques else None
            self._losses = (extra, mats, rows)
        return self._losses


def _solve_points(problem: _Problem, points: slice) -> dict:
    """Every result of the points ``points`` (a slice of all points): arrays with the points last."""
    train, shaft_row, given = problem.train, problem.shaft_row, problem.given
    drives, loads = problem.drives, problem.loads
    mats = problem.mats
    speed_in = {k: v[points] for k, v in problem.speed_in.items()}
    torque_in = {k: v[points] for k, v in problem.torque_in.items()}
    power_in = {k: v[points] for k, v in problem.power_in.items()}
    count = len(range(*points.indices(problem.points)))

    # kinematics: one product for all points (held shafts exactly 0, givens exactly)
    given_speed = problem.given_speed
    g = np.array([speed_in[s] for s in given_speed]).reshape(len(given_speed), count)
    kin = speed_solver(mats, given_speed)
    with np.errstate(all="ignore"):
        moving = kin.speeds(g) if given_speed else np.zeros((len(mats.speed_index), count))
    speed_span = span(np.abs(moving))  # also for evaluate's range check
    if not (_TINY <= speed_span[0] and speed_span[1] <= _HUGE):  # else check_speeds passes
        check_speeds(mats, moving)
    kin.check(g, moving)
    n = np.vstack([moving, np.zeros((1, count))])  # housing last

    # given external torques (powers → torques; roles set signs)
    tau = np.empty((len(given), count))
    for r, shaft in enumerate(given):
        omega = n[shaft_row[shaft]] * RPM_TO_RAD_S
        if shaft in power_in:
            still = omega == 0.0
            if np.any(still):
                k = int(np.flatnonzero(still)[0])
                raise OperatingPointError(
                    f"batch: powers[{shaft!r}] is given, but shaft {shaft!r} stands still at point {k}; "
                    "give a torque there instead."
                )
            with np.errstate(all="ignore"):
                value = power_in[shaft] / omega
            if not np.all(np.isfinite(value)):
                k = int(np.flatnonzero(~np.isfinite(value))[0])
                raise NonFiniteResultError(
                    f"batch: powers[{shaft!r}] at point {k} needs a torque beyond the floating-point range "
                    "(about 1.8e308 N·m); give a larger speed or a smaller power.", "torque", shaft)
        else:
            value = torque_in[shaft]
        if shaft in drives:
            sign = np.sign(omega)
            value = np.where(sign != 0, np.abs(value) * sign, value)
        elif shaft in loads:
            sign = np.sign(omega)
            value = np.where(sign != 0, -np.abs(value) * sign, value)
        tau[r] = value
    given_map = {s: tau[r] for r, s in enumerate(given)}

    ideal = torque_solver(mats, given, None)
    with np.errstate(all="ignore"):
        x_ideal = ideal.torques(tau)
    ideal.check(tau, x_ideal)
    relative = relative_speeds(mats, n)
    # the lossless solution: with losses only its loss directions and the roles of connected shafts count
    # (evaluate.directions); the full evaluation where it is the result or the zero rule could act
    role_rows = [shaft_row[s] for s in mats.external if s not in drives and s not in loads]
    maybe_lossy = any(lever.efficiency != 1.0 for lever in mats.levers) or problem.efficiencies or problem.loss_torques
    lean = directions(mats, n, x_ideal, given_map, relative, role_rows, speed_span) if maybe_lossy else None
    ev = None
    if lean is None:
        ev = evaluate(mats, n, x_ideal, None, given_map, relative=relative, speed_span=speed_span)
        lean = ev.pattern, {row: ev.powers[row] for row in role_rows}
    extra, lossy_mats, all_rows = problem.losses()  # after the lossless evaluation's errors, as ever
    rows = effs = dragged = None
    if extra is not None:
        effs = extra.efficiency[:, points]
        dragged = extra.torques[:, points] if all_rows is not None else None
        rows = None if all_rows is None else all_rows[:, points]
    lossy = any(lever.efficiency != 1.0 for lever in lossy_mats.levers) or (
        extra is not None and (dragged is not None or bool(np.any(extra.efficiency != 1.0))))
    if ev is None and (not lossy or not count):  # the lossless evaluation is the result (settled: no error)
        ev = evaluate(mats, n, x_ideal, None, given_map, relative=relative, speed_span=speed_span)
    ideal_pattern, ideal_powers = lean
    mats = lossy_mats

    # loss directions: group points by pattern, one solve per pattern; then all points are evaluated
    # at once, and only the (rare) points whose re-read pattern differs are tried again
    pattern = ideal_pattern.copy()
    first_pattern = pattern.copy()
    x = first_x = x_ideal  # (copied before any change)
    consistent = np.zeros(count, dtype=bool)
    pending = np.arange(count)
    solved: set[tuple[int, ...]] = set()
    retried = False
    singular: set[tuple[int, ...]] = set()  # loss patterns whose equations are singular (limit_solver)
    at_limit_points = np.zeros(count, dtype=bool)
    for attempt in range(MAX_PATTERN_TRIES if lossy else 0):
        if pending.size == 0:
            break
        with np.errstate(all="ignore"):
            if attempt == 0 and len(given) == 1 and effs is None and rows is None:
                # one given torque: each point's torques are its pattern's column times the torque
                # (Statics.torques point by point, without gathering the points of each pattern)
                patterns, which = _pattern_index(pattern)
                solved |= {tuple(int(w) for w in row) for row in patterns}
                columns = np.stack([limit_solver(mats, given, row, ideal, singular).operator[:, 0]
                                    for row in patterns], axis=1)
                read = given_columns(mats)  # the only columns evaluate reads
                x = np.zeros((columns.shape[0], count))
                x[read] = columns[read].take(which, axis=1) * tau + 0.0  # + 0.0 as linear.apply
            else:
                groups = list(_groups(pattern, pending, attempt == 0))
                solved |= {tuple(int(w) for w in row) for row, _, _ in groups}
                if x is first_x:  # the first solution stays as it is for the points that find no pattern
                    x = x.copy()
                for row, members, _ in groups:
                    solver = limit_solver(mats, given, row, ideal, singular)
                    x[:, members] = _corrected(train, mats, given, solver, row, tau[:, members],
                                               None if rows is None else rows[:, members],
                                               None if effs is None else effs[:, members])
        column = pattern if attempt == 0 else pattern[:, pending]
        if attempt == 0:  # every point (pending is all of them): this evaluation is kept where consistent
            first_x = x
            ev = evaluate(mats, n, x, pattern, given_map, effs, dragged, relative, speed_span)
            observed = ev.pattern
        else:
            retried = True
            observed = evaluate(mats, n[:, pending], x[:, pending], column,
                                {s: v[pending] for s, v in given_map.items()},
                                None if effs is None else effs[:, pending],
                                None if dragged is None else dragged[:, pending]).pattern
        ok = _agrees(column, observed)
        if singular:  # exactly at a self-locking limit: no finite state with this pattern, none tried after it
            hit = with_pattern(column, singular)
            at_limit_points[pending[hit]] = True
            ok |= hit  # settled (not consistent: see below)
        consistent[pending[ok]] = True
        pending = pending[~ok]
        if pending.size:
            pattern[:, pending] = np.where(observed[:, ~ok] == 0, column[:, ~ok], observed[:, ~ok])
    consistent &= ~at_limit_points
    if not lossy:
        consistent[:] = True
        solved.add(tuple(int(w) for w in first_pattern[:, 0]) if count else ())
    elif retried or not consistent.all():
        # points with no consistent pattern keep the formal solution of the ideal pattern
        x[:, ~consistent] = first_x[:, ~consistent]
        pattern[:, ~consistent] = first_pattern[:, ~consistent]
        if at_limit_points.any():  # no finite lossy state: the lossless numbers are shown, as solve does
            x[:, at_limit_points] = x_ideal[:, at_limit_points]
            pattern[:, at_limit_points] = 0
        ev = evaluate(mats, n, x, pattern, given_map, effs, dragged)

    # the results of these points
    lever_index = {lever.element.name: k for k, lever in enumerate(mats.levers)}
    losses, sources = {}, {}
    for e in train.elements:
        k = lever_index.get(e.name)
        rolling = ev.loss[k] if k is not None else np.zeros(count)
        parts = ({"mesh": rolling} if extra is None else extra.split(k, rolling, points)) if k is not None else {}
        spin = 0.0
        if extra is not None and e.name in extra.element_torques:
            for source, value in extra.drag_losses(e.name, ev.speeds, points).items():
                parts[source] = parts[source] + value if source in parts else value
                spin = spin + value
        losses[e.name] = rolling + spin
        sources[e.name] = parts
    if extra is not None and HOUSING in extra.element_torques:  # auxiliaries: pump, seals
        sources[HOUSING] = extra.drag_losses(HOUSING, ev.speeds, points)
        losses[HOUSING] = sum(sources[HOUSING].values())
    drive_power = np.zeros(count)
    load_power = np.zeros(count)
    for s in mats.external:
        power = ev.powers[shaft_row[s]]
        if s in drives:
            drive_power += power
        elif s in loads:
            load_power -= power
        else:  # role from the ideal solution's sign
            ideal_power = ideal_powers[shaft_row[s]]
            drive_power += power * (ideal_power > 0)  # as np.where(…, power, 0.0): ±0 adds nothing
            load_power -= power * (ideal_power < 0)
    drive_power += 0.0
    load_power += 0.0
    scale = np.maximum(drive_power, load_power)
    flowing = (drive_power != 0) | (load_power != 0)
    loss = np.zeros(count)
    for value in losses.values():
        loss += value
    loss += 0.0
    with np.errstate(divide="ignore", invalid="ignore"):
        wrong = _wrong_way(ev.powers, mats, drives, loads, ideal_powers, shaft_row, scale)
        at_limit = load_power <= SELF_LOCKING_MARGIN * drive_power
        self_locking = flowing & (wrong | ~consistent | at_limit)
        efficiency = np.where((drive_power > 0) & ~self_locking, load_power / drive_power, np.nan)
    efficiency = np.minimum(efficiency, 1.0)
    lossless = loss == 0
    if np.count_nonzero(lossless):
        efficiency[lossless & (np.abs(efficiency - 1.0) <= 1e-9)] = 1.0  # no efficiency from round-off
    results = {("speeds", s): ev.speeds[k] for s, k in shaft_row.items()}
    results |= {("torques", s): ev.torques[k] for s, k in shaft_row.items()}
    results |= {("powers", s): ev.powers[k] for s, k in shaft_row.items()}
    results |= {("port_torques", (e, p)): ev.x[c] for (kind, e, p), c in mats.torque_index.items() if kind == "port"}
    results |= {("losses", e): value for e, value in losses.items()}
    results |= {("sources", e, k): value for e, parts in sources.items() for k, value in parts.items()}
    ambiguous = (ambiguous_points(train, mats, given, pattern, consistent, tau, rows, effs, n, given_map, dragged,
                                  [(shaft_row[s], "drive") for s in drives] + [(shaft_row[s], "load") for s in loads],
                                  _corrected, solved) if lossy else np.zeros(count, dtype=bool))
    results |= {"input_power": drive_power, "output_power": load_power, "loss": loss, "efficiency": efficiency,
                "self_locking": self_locking, "ambiguous": ambiguous}
    return results, solved


def _agrees(column: np.ndarray, observed: np.ndarray) -> np.ndarray:
    """Per point: every lever's observed direction is the one solved with, or 0 (row by row)."""
    ok = np.ones(column.shape[1:], dtype=bool)
    for solved_with, seen in zip(column, observed):
        ok &= (solved_with == seen) | (seen == 0)
    return ok


def _pattern_index(pattern: np.ndarray) -> tuple[list[np.ndarray], np.ndarray]:
    """The distinct loss-direction patterns (columns of ``pattern``, in the order of their codes) and,
    per point, the index of its pattern among them."""
    levers = pattern.shape[0]
    if levers == 0 or pattern.shape[1] == 0:
        return [pattern[:, 0] if pattern.shape[1] else pattern[:, :0].sum(axis=1)], np.zeros(pattern.shape[1], int)
    if levers > 12:  # too many codes to count
        unique, which = np.unique(pattern, axis=1, return_inverse=True)
        return list(unique.T), which.ravel()
    codes = _codes(pattern)
    present = np.flatnonzero(np.bincount(codes, minlength=3 ** levers))
    digits = (present[None, :] // 3 ** np.arange(levers)[:, None]) % 3 - 1
    if present.size == 1:
        return [digits[:, 0]], np.zeros(pattern.shape[1], dtype=int)
    lookup = np.zeros(3 ** levers, dtype=int)
    lookup[present] = np.arange(present.size)
    return list(digits.T), lookup.take(codes)


def _codes(column: np.ndarray) -> np.ndarray:
    """One integer per point: the directions w + 1 as base-3 digits, lever 0 first."""
    codes = column[0] + 1
    for k in range(1, column.shape[0]):
        codes += (column[k] + 1) * 3 ** k
    return codes


def _groups(pattern: np.ndarray, pending: np.ndarray, everything: bool = False):
    """(pattern, its points, their mask or None) for every distinct loss-direction pattern among the
    ``pending`` points, in the order of their codes (w + 1 as base-3 digits, lever 0 first).

    ``everything``: pending is every point, in order; then the mask (over all points) comes too.
    """
    column = pattern if everything else pattern[:, pending]
    levers = column.shape[0]
    if not column.size or levers == 0:
        yield column[:, 0], pending, (True if everything else None)
        return
    codes = _codes(column)  # one integer code per pattern is much faster to group than rows
    if levers > 12:  # too many codes to count
        unique_codes, first_index, inverse = np.unique(codes, return_index=True, return_inverse=True)
        for k in range(unique_codes.size):
            yield column[:, first_index[k]], pending[inverse.ravel() == k], None
        return
    present = np.flatnonzero(np.bincount(codes, minlength=3 ** levers))
    if present.size == 1:
        yield column[:, 0], pending, (True if everything else None)
        return
    for code in present:
        members = codes == code
        yield column[:, int(np.argmax(members))], pending[members], (members if everything else None)


def _assembled(problem: _Problem, results: dict, solved: set, shape: tuple[int, ...]) -> BatchSolution:
    """The BatchSolution of the results of all points (keyed as :func:`_solve_points` returns them)."""
    group: dict[str, dict] = {"speeds": {}, "torques": {}, "powers": {}, "port_torques": {}, "losses": {},
                              "sources": {e.name: {} for e in problem.train.elements}}
    for key, value in results.items():
        if isinstance(key, tuple) and key[0] == "sources":
            group["sources"].setdefault(key[1], {})[key[2]] = value.reshape(shape)
        elif isinstance(key, tuple):
            group[key[0]][key[1]] = value.reshape(shape)
    return BatchSolution(
        train=problem.train,
        **{name: MappingProxyType(values) for name, values in group.items() if name != "sources"},
        **{name: results[name].reshape(shape) for name in
           ("input_power", "output_power", "loss", "efficiency", "self_locking", "ambiguous")},
        patterns=len(solved),
        loss_sources=MappingProxyType({e: MappingProxyType(parts) for e, parts in group["sources"].items()}),
    )


def _wrong_way(powers, mats, drives, loads, ideal_powers, shaft_row, scale) -> np.ndarray:
    """Points where a load delivers, or a drive absorbs, more than the margin of the input power."""
    wrong = np.zeros(scale.shape, dtype=bool)
    limit = SELF_LOCKING_MARGIN * scale
    for s in mats.external:
        power = powers[shaft_row[s]]
        if s in drives:
            wrong |= power < -limit
        elif s in loads:
            wrong |= power > limit
        else:
            ideal_power = ideal_powers[shaft_row[s]]
            wrong |= (ideal_power > 0) & (power < -limit)
            wrong |= (ideal_power < 0) & (power > limit)
    return wrong


#: Rounds of the lever-row correction before a point is solved with its own matrix.
CORRECTION_ROUNDS = 60


def _corrected(train, mats, given, solver: TorqueSolver, row, tau, rows, effs) -> np.ndarray:
    """Torques of points that share the pattern ``row`` but have their own lever efficiencies ``effs``.

    The lever rows T_b + k T_a = 0, T_c + (1 − k) T_a = 0 with the point's
    k = i0·η0^w differ from the pattern's reference k0 only on the right-hand
    side: T_b + k0 T_a = −(k − k0) T_a, T_c + (1 − k0) T_a = (k − k0) T_a.  Iterating
    x ← S τ + R (r + correction(x)) converges geometrically (the corrections are
    of the order of the spread of η0 times the torque gain); a point that does
    not settle is solved with its own matrix.
    """
    x = solver.torques(tau, rows)
    if effs is None:
        return x
    levers = mats.levers
    w = np.asarray(row, dtype=int)[:, None]
    i0 = np.array([lv.ratio for lv in levers])[:, None]
    k = np.where(w > 0, i0 * effs, np.where(w < 0, i0 / effs, i0))
    k0 = np.array([lv.factors(int(wk))[0] for lv, wk in zip(levers, row)])[:, None]
    delta = k - k0
    if not np.any(delta):
        return x
    slots = mats._statics_template[1]
    size = solver.row_operator.shape[1]
    pending = np.arange(tau.shape[1])
    for _ in range(CORRECTION_ROUNDS):
        rhs = np.zeros((size, pending.size)) if rows is None else rows[:, pending].copy()
        for r, col, lever in slots:
            rhs[r] -= delta[lever, pending] * x[col, pending]
            rhs[r + 1] += delta[lever, pending] * x[col, pending]
        new = solver.torques(tau[:, pending], rhs)
        scale = np.max(np.abs(new), axis=0) + 1e-300
        done = np.max(np.abs(new - x[:, pending]), axis=0) <= 1e-14 * scale
        x[:, pending] = new
        pending = pending[~done]
        if pending.size == 0:
            return x
    for j in pending:  # too slow to settle (near self-locking): the point's own equations
        own = matrices(with_efficiencies(train, {lv.element.name: float(effs[q, j]) for q, lv in enumerate(levers)}),
                       mats.external)
        exact = torque_solver(own, given, row)
        x[:, j] = exact.torques(tau[:, j], None if rows is None else rows[:, j])
    return x
