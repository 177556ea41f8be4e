"""Linear equations of a gear train: one row set per element, one column per unknown.

Every element with gears is a *lever* with ports (a, b, c) and ratio
i0 = (n_a − n_c)/(n_b − n_c): a planetary set (a = sun, b = ring, c =
carrier) or a fixed-axis stage (a = first, b = second, c = housing).  Every
engaged clutch or brake is a *link* that makes two shafts turn together.

Kinematics (Willis):  n_a − i0·n_b − (1 − i0)·n_c = 0;  link: n_a − n_b = 0.

Statics, with T the torque a shaft exerts on an element port and M the
external torque on a shaft:

* lever:  T_b + i0·η0^w·T_a = 0  and  T_c + (1 − i0·η0^w)·T_a = 0;
* link:   T_a + T_b = 0;
* shaft:  M_s − Σ_e T_(e,s) = 0  for every shaft but the housing (M_s exists
  only at drives and loads).

The second lever row is the torque sum T_a + T_b + T_c = 0 with T_b
eliminated: each coefficient is formed once, exactly rounded, so that a set
with i0 near 1 or |i0| = 1e6 gives no cancellation in the matrix.  The
housing's balance is not a row: its reaction is the sum of the port torques
on it, computed afterwards (the global equilibrium makes the row redundant,
and a row that sums every element's reaction would couple torques of every
size).

The exponent w = sign(P_wa) ∈ {−1, 0, +1} is the direction of the rolling
power T_a·(ω_a − ω_c): η0 acts in the direction power flows relative to the
carrier, and w = 0 (no rolling power: an idling or locked set) carries no loss.

Structure known before any number: shafts the train holds still (a brake, a
clutch to such a shaft, a stage from one, a set with two such members, a set
locked with one) have speed exactly 0, shafts the train makes turn together
(clutches, locked sets) have exactly the same speed, and ports that can carry no torque (a shaft with no external
torque and one live port, and whatever that makes idle in turn) have torque
exactly 0; the solver sets these exactly instead of computing round-off.

References
----------
Brandenberger 1952, eqs. 1, 2, 3', 7 and 7'; Queitsch, eqs. 12 and 26.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from functools import cached_property, lru_cache

import numpy as np

from ..errors import EpicyclicError, NonFiniteResultError
from ..model.elements import HOUSING, Brake, Clutch, GearStage
from ..model.planetary import PlanetarySet
from ..model.train import GearTrain
from .linear import rank

__all__ = ["Layout", "Lever", "Link", "TrainMatrices", "matrices"]


@dataclass(frozen=True)
class Lever:
    """A three-port element with stationary ratio and efficiency."""

    element: PlanetarySet | GearStage
    ports: tuple[str, str, str]  # port names
    shafts: tuple[str, str, str]  # shaft names (a, b, c)
    ratio: float
    efficiency: float

    def factors(self, w: int) -> tuple[float, float]:
        """(i0·η0^w, 1 − i0·η0^w), each exactly rounded: the torque ratios T_b/T_a and T_c/T_a, negated.

        Raises
        ------
        NonFiniteResultError
            η0^w overflows (an efficiency so small that 1/η0 is not a float).
        """
        return _factors(self.element.name, self.ratio, self.efficiency, int(w))


@lru_cache(maxsize=4096)
def _factors(name: str, ratio: float, efficiency: float, w: int) -> tuple[float, float]:
    if w == 0 or efficiency == 1.0:
        return ratio, 1.0 - ratio  # 1 − i0 is exact where it matters (Sterbenz)
    i0, eta = Fraction(ratio), Fraction(efficiency)
    k = i0 * eta if w > 0 else i0 / eta
    try:
        return float(k), float(1 - k)
    except OverflowError:
        raise NonFiniteResultError(
            f"{name!r}: the stationary efficiency {efficiency!r} is too small to compute with "
            f"(i0/η0 = {ratio!r}/{efficiency!r} overflows); give an efficiency of at least 1e-300, "
            "or 1 to ignore the losses of this element.",
            "efficiency", name,
        ) from None


@dataclass(frozen=True)
class Link:
    """An engaged clutch or brake: two shafts turn together."""

    element: Clutch | Brake
    ports: tuple[str, str]
    shafts: tuple[str, str]


def _levers_and_links(train: GearTrain) -> tuple[tuple[Lever, ...], tuple[Link, ...]]:
    levers: list[Lever] = []
    links: list[Link] = []
    for element in train.elements:
        if isinstance(element, PlanetarySet):
            levers.append(Lever(element, ("sun", "ring", "carrier"), element.shafts,
                                element.stationary_ratio, element.stationary_efficiency))
        elif isinstance(element, GearStage):
            levers.append(Lever(element, ("first", "second", "housing"),
                                (element.first, element.second, HOUSING),
                                element.ratio, element.efficiency))
        elif isinstance(element, Clutch):
            if element.engaged:
                links.append(Link(element, ("first", "second"), element.shafts))
        elif isinstance(element, Brake):
            if element.engaged:
                links.append(Link(element, ("shaft", "housing"), element.shafts))
    return tuple(levers), tuple(links)


@dataclass(frozen=True, eq=False)
class Layout:
    """Where every port, shaft and lever sits in the arrays of a solution."""

    rows: dict[str, int]  # shaft → row (train order, housing last)
    parts: int  # levers, then links
    port_columns: np.ndarray  # torque column of every port (order of port_shaft_columns)
    port_rows: np.ndarray  # shaft row of every port
    port_parts: np.ndarray  # part of every port
    external_rows: np.ndarray
    external_columns: np.ndarray
    lever_a_rows: np.ndarray
    lever_c_rows: np.ndarray
    lever_a_columns: np.ndarray
    lever_b_columns: np.ndarray
    lever_c_columns: np.ndarray
    lever_factors: np.ndarray  # (levers, w + 1, 2): (i0·η0^w, 1 − i0·η0^w), NaN where η0^w overflows
    link_first_columns: np.ndarray
    link_second_columns: np.ndarray
    part_starts: np.ndarray  # first port of every part (ports are grouped by part)
    parts_at: tuple[tuple[int, ...], ...]  # per shaft row: the parts with a port there
    reacting_rows: np.ndarray  # rows of shafts with an external torque or reaction and a port
    reacting_ports: np.ndarray  # their ports, grouped by shaft
    reacting_starts: np.ndarray  # first of each group
    neighbours: np.ndarray  # (parts, most): the parts sharing a moving shaft with each (itself included),
    #                         padded with the index ``parts`` (no part)
    efficiencies: np.ndarray
    part_ports: tuple[tuple[int, ...], ...]  # per part: its ports (indices into port_columns)
    reacting_groups: tuple[tuple[int, ...], ...]  # per reacting row: its ports (indices into port_columns)
    lever_tables: np.ndarray  # (3, levers · 3): k_b = i0·η0^w, k_c = 1 − k_b and η0^w, at 3·lever + w + 1


@dataclass(frozen=True, eq=False)
class TrainMatrices:
    """The train's equations, independent of the operating point.

    Built once per train (see :func:`matrices`) and reused for every operating
    point and loss-direction pattern.
    """

    train: GearTrain
    external: tuple[str, ...]  # moving shafts with an external torque (drives, loads, connected, given)
    #: Prepared speed and torque solvers, keyed by what they were prepared for (see solver.kinematics/statics).
    solvers: dict = field(default_factory=dict, repr=False, compare=False)

    # --------------------------------------------------------------- structure
    @cached_property
    def _parts(self) -> tuple[tuple[Lever, ...], tuple[Link, ...]]:
        return _levers_and_links(self.train)

    @property
    def levers(self) -> tuple[Lever, ...]:
        return self._parts[0]

    @property
    def links(self) -> tuple[Link, ...]:
        return self._parts[1]

    @cached_property
    def speed_index(self) -> dict[str, int]:
        """Column of each moving shaft's speed (the housing has none)."""
        return {s: k for k, s in enumerate(self.train.moving_shafts)}

    @cached_property
    def speed_classes(self) -> dict[str, str]:
        """Every shaft → the shaft that represents all shafts turning at exactly its speed.

        The representative is the housing for the shafts the train holds still, else the first
        shaft of the class in train order.

        Clutches and brakes join two shafts, and so does a stage of ratio exactly 1;
        a set (or stage) with two members turning together turns as a block
        (Willis: n_a = n_c gives n_b = n_c), so its third member joins them.  The housing's class holds the shafts the
        train holds still: a brake, a stage from a held shaft, a set with two held
        members, a set locked with a held member.
        """
        parent = {s: s for s in self.train.shafts}

        def find(s: str) -> str:
            while parent[s] != s:
                parent[s] = parent[parent[s]]
                s = parent[s]
            return s

        def union(members) -> bool:
            roots = sorted({find(m) for m in members}, key=lambda r: (r != HOUSING, self.train.shafts.index(r)))
            for r in roots[1:]:
                parent[r] = roots[0]
            return len(roots) > 1

        changed = True
        while changed:
            changed = False
            for link in self.links:
                changed |= union(link.shafts)
            for lever in self.levers:
                if lever.ports[2] == "housing" and lever.ratio == 1.0:  # a stage of ratio 1: a clutch
                    changed |= union(lever.shafts[:2])
                elif len({find(s) for s in lever.shafts}) < 3:
                    changed |= union(lever.shafts)
        return {s: find(s) for s in self.train.shafts}

    @cached_property
    def held_shafts(self) -> frozenset[str]:
        """Moving shafts that the train itself holds still, whatever speeds are given."""
        classes = self.speed_classes
        return frozenset(s for s in self.train.moving_shafts if classes[s] == classes[HOUSING])

    # --------------------------------------------------------------- kinematics
    @cached_property
    def kinematics(self) -> np.ndarray:
        """Constraint rows K with K @ n = 0 (n: speeds of the moving shafts)."""
        rows = []
        col = self.speed_index
        for lever in self.levers:
            row = np.zeros(len(col))
            for shaft, coef in zip(lever.shafts, (1.0, -lever.ratio, -(1.0 - lever.ratio))):
                if shaft != HOUSING:
                    row[col[shaft]] += coef
            rows.append(row)
        for link in self.links:
            row = np.zeros(len(col))
            for shaft, coef in zip(link.shafts, (1.0, -1.0)):
                if shaft != HOUSING:
                    row[col[shaft]] += coef
            rows.append(row)
        return np.array(rows).reshape(len(rows), len(col))

    @cached_property
    def degrees_of_freedom(self) -> int:
        """Number of speeds that must be given to fix every shaft speed."""
        k = self.kinematics
        return k.shape[1] - rank(k) if k.shape[0] else k.shape[1]

    # --------------------------------------------------------------- statics
    @cached_property
    def torque_columns(self) -> list[tuple[str, str, str]]:
        """Unknown torques: ("port", element, port) for ports, ("external", shaft, "") for shafts."""
        cols: list[tuple[str, str, str]] = []
        for lever in self.levers:
            cols += [("port", lever.element.name, p) for p in lever.ports]
        for link in self.links:
            cols += [("port", link.element.name, p) for p in link.ports]
        cols += [("external", s, "") for s in self.external]
        return cols

    @cached_property
    def torque_index(self) -> dict[tuple[str, str, str], int]:
        return {c: k for k, c in enumerate(self.torque_columns)}

    @cached_property
    def _statics_template(self) -> tuple[np.ndarray, list[tuple[int, int, int]]]:
        """Static rows with η = 1 and the (row, col_a, lever) slots of each lever's two factors."""
        idx = self.torque_index
        ncol = len(idx)
        rows: list[np.ndarray] = []
        slots: list[tuple[int, int, int]] = []
        for k, lever in enumerate(self.levers):
            name = lever.element.name
            a, b, c = (idx[("port", name, p)] for p in lever.ports)
            k_b, k_c = lever.factors(0)
            slots.append((len(rows), a, k))
            for col, factor in ((b, k_b), (c, k_c)):
                row = np.zeros(ncol)
                row[col] = 1.0
                row[a] = factor
                rows.append(row)
        for link in self.links:
            name = link.element.name
            row = np.zeros(ncol)
            row[[idx[("port", name, p)] for p in link.ports]] = 1.0
            rows.append(row)
        for shaft in self.train.moving_shafts:
            row = np.zeros(ncol)
            if ("external", shaft, "") in idx:
                row[idx[("external", shaft, "")]] = 1.0
            for element_name, port, col in self.port_shaft_columns:
                if port == shaft:
                    row[col] -= 1.0
            rows.append(row)
        return np.array(rows).reshape(len(rows), ncol), slots

    @cached_property
    def port_shaft_columns(self) -> list[tuple[str, str, int]]:
        """(element name, shaft, column) for every element port."""
        idx = self.torque_index
        out = []
        for part in (*self.levers, *self.links):
            for port, shaft in zip(part.ports, part.shafts):
                out.append((part.element.name, shaft, idx[("port", part.element.name, port)]))
        return out

    def statics(self, pattern: Sequence[int] | np.ndarray | None = None,
                efficiencies: Mapping[str, float] | None = None) -> np.ndarray:
        """Static rows for a loss-direction pattern w (one entry per lever; None = ideal).

        ``efficiencies`` (element name → η0) replaces the stationary efficiency
        of some levers (used to find self-locking thresholds).
        """
        template, slots = self._statics_template
        matrix = template.copy()
        if pattern is not None:
            for (row, col, k), w in zip(slots, pattern):
                lever = self.levers[k]
                eta = (efficiencies or {}).get(lever.element.name, lever.efficiency)
                matrix[row, col], matrix[row + 1, col] = _factors(lever.element.name, lever.ratio, eta, int(w))
        return matrix

    @cached_property
    def _ports_at_internal_shafts(self) -> list[list[tuple[int, int]]]:
        """Per moving shaft without external torque: its ports as (part index, port index)."""
        parts = [*self.levers, *self.links]
        return [[(k, j) for k, part in enumerate(parts) for j, s in enumerate(part.shafts) if s == shaft]
                for shaft in self.train.moving_shafts if shaft not in self.external]

    def idle_columns(self, pattern: Sequence[int] | np.ndarray | None = None) -> list[int]:
        """Port columns whose torque is exactly 0 for any given torque (idle elements).

        A shaft without external torque and with one live port leaves that port
        no torque; the element is then idle (a lever's three torques are
        proportional, unless T_c = 0 meets 1 − i0·η0^w = 0), which may leave
        another shaft with one live port, and so on.
        """
        parts = [*self.levers, *self.links]
        factors = [lever.factors(0 if pattern is None else int(w))
                   for lever, w in zip(self.levers, pattern if pattern is not None else [0] * len(self.levers))]
        at_shaft = self._ports_at_internal_shafts
        idle: set[int] = set()  # indices into parts
        changed = True
        while changed:
            changed = False
            for ports in at_shaft:
                live = [(k, j) for k, j in ports if k not in idle]
                if len(live) != 1:
                    continue
                k, j = live[0]
                if k < len(self.levers) and j == 2 and factors[k][1] == 0.0:
                    continue  # T_c = 0 with 1 − i0·η0^w = 0 leaves T_a free
                idle.add(k)
                changed = True
        idx = self.torque_index
        return sorted(idx[("port", parts[k].element.name, p)] for k in idle for p in parts[k].ports)

    @cached_property
    def layout(self) -> Layout:
        """Index arrays for evaluating solutions (see :mod:`epicyclic.solver.evaluate`)."""
        rows = {s: k for k, s in enumerate(self.train.shafts)}
        ports = self.port_shaft_columns
        part_names = [part.element.name for part in (*self.levers, *self.links)]
        part_index = {name: k for k, name in enumerate(part_names)}
        idx = self.torque_index
        parts = (*self.levers, *self.links)
        moving = [set(part.shafts) - {HOUSING} for part in parts]
        near = [[j for j, other in enumerate(moving) if j == k or mine & other] for k, mine in enumerate(moving)]
        most = max((len(n) for n in near), default=0)
        neighbours = np.array([n + [len(parts)] * (most - len(n)) for n in near], dtype=int).reshape(len(parts), most)
        port_rows = np.array([rows[s] for _, s, _ in ports], dtype=int)
        reacting = [rows[s] for s in self.train.shafts
                    if (s in self.external or s == HOUSING) and np.any(port_rows == rows[s])]
        groups = [np.flatnonzero(port_rows == r) for r in reacting]
        parts_of_ports = np.array([part_index[name] for name, _, _ in ports], dtype=int)
        efficiencies = np.array([lv.efficiency for lv in self.levers], dtype=float)
        with np.errstate(all="ignore"):
            inverse = 1.0 / efficiencies  # inf where 1/η0 overflows: never used, the solve would have said so

        def factors(lever: Lever) -> list[tuple[float, float]]:
            out = []
            for w in (-1, 0, 1):
                try:
                    out.append(lever.factors(w))
                except EpicyclicError:  # 1/η0 overflows: never used, the solve would have said so
                    out.append((np.nan, np.nan))
            return out

        def columns(names, port) -> np.ndarray:
            return np.array([idx[("port", part.element.name, part.ports[port])] for part in names], dtype=int)

        lever_factors = np.array([factors(lv) for lv in self.levers], dtype=float).reshape(len(self.levers), 3, 2)
        return Layout(
            rows=rows,
            parts=len(part_names),
            port_columns=np.array([col for _, _, col in ports], dtype=int),
            port_rows=port_rows,
            port_parts=np.array([part_index[name] for name, _, _ in ports], dtype=int),
            external_rows=np.array([rows[s] for s in self.external], dtype=int),
            external_columns=np.array([self.external_column(s) for s in self.external], dtype=int),
            lever_a_rows=np.array([rows[lv.shafts[0]] for lv in self.levers], dtype=int),
            lever_c_rows=np.array([rows[lv.shafts[2]] for lv in self.levers], dtype=int),
            lever_a_columns=columns(self.levers, 0),
            lever_b_columns=columns(self.levers, 1),
            lever_c_columns=columns(self.levers, 2),
            lever_factors=lever_factors,
            link_first_columns=columns(self.links, 0),
            link_second_columns=columns(self.links, 1),
            part_starts=np.cumsum([0] + [len(part.ports) for part in parts[:-1]]).astype(int),
            parts_at=tuple(tuple(sorted({part_index[name] for name, s, _ in ports if rows[s] == r}))
                           for r in range(len(rows))),
            reacting_rows=np.array(reacting, dtype=int),
            reacting_ports=np.concatenate(groups).astype(int) if groups else np.zeros(0, dtype=int),
            reacting_starts=np.cumsum([0] + [len(g) for g in groups[:-1]]).astype(int),
            neighbours=neighbours,
            efficiencies=efficiencies,
            part_ports=tuple(tuple(int(j) for j in np.flatnonzero(parts_of_ports == k)) for k in range(len(parts))),
            reacting_groups=tuple(tuple(int(j) for j in g) for g in groups),
            lever_tables=np.stack([lever_factors[:, :, 0].ravel(), lever_factors[:, :, 1].ravel(),
                                   np.stack([inverse, np.ones_like(efficiencies), efficiencies], axis=-1).ravel()]),
        )

    def external_column(self, shaft: str) -> int:
        return self.torque_index[("external", shaft, "")]


def matrices(train: GearTrain, external: Sequence[str]) -> TrainMatrices:
    """The equations of ``train`` with external torques at ``external`` (the housing's reaction is implied).

    The same train and external shafts give the same (cached) object, so that
    repeated solves reuse its prepared solvers.
    """
    return _matrices(train, tuple(dict.fromkeys(s for s in external if s != HOUSING)))


@lru_cache(maxsize=64)
def _matrices(train: GearTrain, external: tuple[str, ...]) -> TrainMatrices:
    return TrainMatrices(train, external)
