"""Linear equations of a gear train: one row set per element, one column per unknown.

Every element with gears is a *lever* with ports (a, b, c) and ratio
i0 = (n_a − n_c)/(n_b − n_c): a planetary set (a = sun, b = ring, c =
carrier) or a fixed-axis stage (a = first, b = second, c = housing).  Every
engaged clutch or brake is a *link* that makes two shafts turn together.

Kinematics (Willis):  n_a − i0·n_b − (1 − i0)·n_c = 0;  link: n_a − n_b = 0.

Statics, with T the torque a shaft exerts on an element port and M the
external torque on a shaft:

* lever:  T_b + i0·η0^w·T_a = 0  and  T_a + T_b + T_c = 0;
* link:   T_a + T_b = 0;
* shaft:  M_s − Σ_e T_(e,s) = 0  (M_s exists only at external shafts and the housing).

The exponent w = sign(P_wa) ∈ {−1, 0, +1} is the direction of the rolling
power T_a·(ω_a − ω_c): η0 acts in the direction power flows relative to the
carrier, and w = 0 (no rolling power: an idling or locked set) carries no loss.

References
----------
Brandenberger 1952, eqs. 1, 2, 3', 7 and 7'; Queitsch, eqs. 12 and 26.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..model.elements import HOUSING, Brake, Clutch, GearStage
from ..model.planetary import PlanetarySet
from ..model.train import GearTrain

__all__ = ["Lever", "Link", "TrainMatrices", "matrices"]


@dataclass(frozen=True)
class Lever:
    """A three-port element with stationary ratio and efficiency."""

    element: PlanetarySet | GearStage
    ports: tuple[str, str, str]  # port names
    shafts: tuple[str, str, str]  # shaft names (a, b, c)
    ratio: float
    efficiency: float


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
class TrainMatrices:
    """The train's equations, independent of the operating point.

    Built once per train (see :func:`matrices`) and reused for every operating
    point and loss-direction pattern.
    """

    train: GearTrain
    external: tuple[str, ...]  # shafts with an external torque (housing last)

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
        """Static rows with η = 1 and the (row, col_a, lever) slots that carry i0·η0^w."""
        idx = self.torque_index
        ncol = len(idx)
        rows: list[np.ndarray] = []
        slots: list[tuple[int, int, int]] = []
        for k, lever in enumerate(self.levers):
            name = lever.element.name
            a, b, c = (idx[("port", name, p)] for p in lever.ports)
            ratio_row = np.zeros(ncol)
            ratio_row[b] = 1.0
            ratio_row[a] = lever.ratio
            slots.append((len(rows), a, k))
            rows.append(ratio_row)
            sum_row = np.zeros(ncol)
            sum_row[[a, b, c]] = 1.0
            rows.append(sum_row)
        for link in self.links:
            name = link.element.name
            row = np.zeros(ncol)
            row[[idx[("port", name, p)] for p in link.ports]] = 1.0
            rows.append(row)
        for shaft in self.train.shafts:
            row = np.zeros(ncol)
            if ("external", shaft, "") in idx:
                row[idx[("external", shaft, "")]] = 1.0
            for element_name, port, col in self.port_shaft_columns:
                if port == shaft:
                    row[col] -= 1.0
            rows.append(row)
        return np.array(rows), slots

    @cached_property
    def port_shaft_columns(self) -> list[tuple[str, str, int]]:
        """(element name, shaft, column) for every element port."""
        idx = self.torque_index
        out = []
        for part in (*self.levers, *self.links):
            for port, shaft in zip(part.ports, part.shafts):
                out.append((part.element.name, shaft, idx[("port", part.element.name, port)]))
        return out

    def statics(self, pattern: Sequence[int] | np.ndarray | None = None) -> np.ndarray:
        """Static rows for a loss-direction pattern w (one entry per lever; None = ideal)."""
        template, slots = self._statics_template
        matrix = template.copy()
        if pattern is not None:
            for (row, col, k), w in zip(slots, pattern):
                matrix[row, col] = self.levers[k].ratio * self.levers[k].efficiency ** float(w)
        return matrix

    def external_column(self, shaft: str) -> int:
        return self.torque_index[("external", shaft, "")]


def matrices(train: GearTrain, external: Sequence[str]) -> TrainMatrices:
    """The equations of ``train`` with external torques at ``external`` (housing added)."""
    ext = tuple(s for s in external if s != HOUSING) + (HOUSING,)
    return TrainMatrices(train, ext)
