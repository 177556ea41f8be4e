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
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np

from ..errors import OperatingPointError
from ..model.elements import HOUSING
from ..model.operating_point import OperatingPoint
from ..model.train import GearTrain
from ..results.solution import RPM_TO_RAD_S
from .assembly import matrices
from .kinematics import speed_solver
from .solve import MAX_PATTERN_TRIES, _validate, loss_pattern
from .statics import torque_solver

__all__ = ["BatchSolution", "solve_batch"]

ArrayMap = Mapping[str, np.ndarray]


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
        Loss per element, W.
    input_power, output_power, loss : ndarray
        W.
    efficiency : ndarray
        output/input; NaN exactly where ``self_locking`` is True or no power
        enters (see ``defined``).
    self_locking : ndarray of bool
    patterns : int
        Number of distinct loss-direction patterns solved.
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
            f"{int(self.self_locking.sum())} self-locking, {self.patterns} loss pattern(s)>"
        )


def _broadcast(groups: Sequence[Mapping[str, object]]) -> tuple[list[dict[str, np.ndarray]], tuple[int, ...]]:
    arrays = [np.asarray(v, dtype=float) for g in groups for v in g.values()]
    shape = np.broadcast_shapes(*(a.shape for a in arrays)) if arrays else ()
    out = []
    for g in groups:
        out.append({k: np.broadcast_to(np.asarray(v, dtype=float), shape).ravel() for k, v in g.items()})
    for g in out:
        for k, v in g.items():
            if not np.all(np.isfinite(v)):
                bad = int(np.flatnonzero(~np.isfinite(v))[0])
                raise OperatingPointError(f"batch: value for shaft {k!r} at point {bad} is not finite ({v[bad]!r}).")
    return out, shape


def solve_batch(
    train: GearTrain,
    *,
    speeds: Mapping[str, object],
    torques: Mapping[str, object] | None = None,
    powers: Mapping[str, object] | None = None,
    drives: Sequence[str] = (),
    loads: Sequence[str] = (),
    connected: Sequence[str] = (),
) -> BatchSolution:
    """Solve ``train`` at many operating points at once.

    Parameters
    ----------
    train : GearTrain
    speeds, torques, powers : mapping shaft → array_like
        As in :class:`~epicyclic.OperatingPoint` (1/min, N·m, W), each value
        an array; all broadcast to one shape.
    drives, loads, connected : sequence of str
        As in :class:`~epicyclic.OperatingPoint`.

    Returns
    -------
    BatchSolution

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
    mats = matrices(train, template.external_shafts)
    points = int(np.prod(shape)) if shape else 1

    # kinematics: one product for all points
    given_speed = [s for s in speed_in if s != HOUSING]
    g = np.array([speed_in[s] for s in given_speed]).reshape(len(given_speed), points)
    kin = speed_solver(mats, given_speed)
    moving = kin.speeds(g) if given_speed else np.zeros((len(mats.speed_index), points))
    kin.check(g, moving)
    for r, shaft in enumerate(given_speed):  # givens exactly, not round-off
        moving[mats.speed_index[shaft]] = g[r]
    n = np.vstack([moving, np.zeros((1, points))])  # housing last
    shaft_row = {s: k for k, s in enumerate(train.shafts)}

    # given external torques (powers → torques; roles set signs)
    given = list(dict.fromkeys([*power_in, *torque_in]))
    tau = np.empty((len(given), points))
    for r, shaft in enumerate(given):
        omega = n[shaft_row[shaft]] * RPM_TO_RAD_S
        if shaft in power_in:
            still = np.abs(omega) < 1e-12
            if np.any(still):
                k = int(np.flatnonzero(still)[0])
                raise OperatingPointError(
                    f"batch: powers[{shaft!r}] is given, but shaft {shaft!r} stands still at point {k}; "
                    "give a torque there instead."
                )
            value = power_in[shaft] / omega
        else:
            value = torque_in[shaft].copy()
        sign = np.sign(omega)
        if shaft in drives:
            value = np.where(sign != 0, np.abs(value) * sign, value)
        elif shaft in loads:
            value = np.where(sign != 0, -np.abs(value) * sign, value)
        tau[r] = value

    ideal = torque_solver(mats, given, None)
    x_ideal = ideal.operator @ tau
    ideal.check(tau, x_ideal)

    # loss directions: group points by pattern, one solve per pattern
    pattern = loss_pattern(mats, x_ideal, n)
    first_pattern = pattern.copy()
    x = np.array(x_ideal)
    consistent = np.zeros(points, dtype=bool)
    pending = np.arange(points)
    solved: set[tuple[int, ...]] = set()
    first_x = np.array(x_ideal)
    for attempt in range(MAX_PATTERN_TRIES):
        if pending.size == 0:
            break
        # one integer code per pattern (base 3) is much faster to group than rows
        codes = ((pattern[:, pending] + 1) * (3 ** np.arange(pattern.shape[0]))[:, None]).sum(axis=0)
        unique_codes, first_index, inverse = np.unique(codes, return_index=True, return_inverse=True)
        still_pending = []
        for k in range(unique_codes.size):
            row = pattern[:, pending[first_index[k]]]
            members = pending[inverse.ravel() == k]
            solver = torque_solver(mats, given, row)
            solved.add(tuple(int(w) for w in row))
            xs = solver.operator @ tau[:, members]
            x[:, members] = xs
            if attempt == 0:
                first_x[:, members] = xs
            observed = loss_pattern(mats, xs, n[:, members])
            column = row[:, None]
            ok = np.all((column == observed) | (observed == 0), axis=0)
            consistent[members[ok]] = True
            bad = members[~ok]
            if bad.size:
                nxt = np.where(observed[:, ~ok] == 0, column, observed[:, ~ok])
                pattern[:, bad] = nxt
                still_pending.append(bad)
        pending = np.concatenate(still_pending) if still_pending else np.array([], dtype=int)
    # points with no consistent pattern keep the formal solution of the ideal pattern
    x[:, ~consistent] = first_x[:, ~consistent]
    pattern[:, ~consistent] = first_pattern[:, ~consistent]

    # assemble results
    ext_torque = {s: (x[mats.external_column(s)] if s in mats.external else np.zeros(points)) for s in train.shafts}
    power = {s: ext_torque[s] * n[shaft_row[s]] * RPM_TO_RAD_S for s in train.shafts}
    port_torques = {(e, p): x[c] for (kind, e, p), c in mats.torque_index.items() if kind == "port"}
    losses = {}
    for element in train.elements:
        total = np.zeros(points)
        for (name, shaft, col) in mats.port_shaft_columns:
            if name == element.name:
                total = total + x[col] * n[shaft_row[shaft]] * RPM_TO_RAD_S
        losses[element.name] = total

    external = [s for s in mats.external if s != HOUSING]
    drive_power = np.zeros(points)
    load_power = np.zeros(points)
    wrong = np.zeros(points, dtype=bool)
    ideal_power = {s: x_ideal[mats.external_column(s)] * n[shaft_row[s]] for s in external}
    scale = np.zeros(points)
    for s in external:
        scale = np.maximum(scale, np.abs(power[s]))
    for s in external:
        if s in drives:
            is_drive, is_load = np.ones(points, dtype=bool), np.zeros(points, dtype=bool)
        elif s in loads:
            is_drive, is_load = np.zeros(points, dtype=bool), np.ones(points, dtype=bool)
        else:  # role from the ideal solution's sign
            is_drive, is_load = ideal_power[s] > 0, ideal_power[s] < 0
        drive_power += np.where(is_drive, power[s], 0.0)
        load_power -= np.where(is_load, power[s], 0.0)
        wrong |= is_drive & (power[s] < -1e-9 * scale)
        wrong |= is_load & (power[s] > 1e-9 * scale)
    with np.errstate(divide="ignore", invalid="ignore"):
        nothing_out = (drive_power > 0) & (load_power <= 1e-12 * drive_power)  # formal η ≤ 0
    self_locking = wrong | ~consistent | nothing_out
    loss = sum(losses.values(), np.zeros(points))
    with np.errstate(divide="ignore", invalid="ignore"):
        efficiency = np.where((drive_power > 0) & ~self_locking, load_power / drive_power, np.nan)
    efficiency = np.where((efficiency > 1.0) & (efficiency <= 1.0 + 1e-9), 1.0, efficiency)  # round-off

    def shaped(a: np.ndarray) -> np.ndarray:
        return a.reshape(shape)

    return BatchSolution(
        train=train,
        speeds=MappingProxyType({s: shaped(n[shaft_row[s]]) for s in train.shafts}),
        torques=MappingProxyType({s: shaped(v) for s, v in ext_torque.items()}),
        powers=MappingProxyType({s: shaped(v) for s, v in power.items()}),
        port_torques=MappingProxyType({k: shaped(v) for k, v in port_torques.items()}),
        losses=MappingProxyType({k: shaped(v) for k, v in losses.items()}),
        input_power=shaped(drive_power),
        output_power=shaped(load_power),
        loss=shaped(loss),
        efficiency=shaped(efficiency),
        self_locking=shaped(self_locking),
        patterns=len(solved),
    )
