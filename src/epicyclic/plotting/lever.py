"""Lever diagrams (Benford–Leising) of simple and compound trains.

Every element with gears is a vertical lever with three nodes.  For a set
with ports (sun a, ring b, carrier c) and stationary ratio i0, the speeds of
the nodes are a linear function of their height when

.. math:: \\frac{y_a - y_c}{y_b - y_c} = i_0,

i.e. with the carrier node at ``t = i0/(i0 − 1)`` of the way from the sun
node (0) to the ring node (1): between them for a minus set (sun–carrier :
carrier–ring = z_ring : z_sun), outside for a plus set.  A fixed-axis stage is
a lever whose third node is the housing (ratio n_first/n_second).

The levers of a train combine into one *compound lever* when the train (in
the shift state, with the housing treated as a shaft that may turn) has two
degrees of freedom, a rigid rotation and one more: then every shaft has one
height ``Y`` and every kinematically possible set of speeds is
``n = α + β·Y``, a straight line across the lever.  The heights come from the
null space of the Willis equations ``n_a − i0·n_b − (1 − i0)·n_c = 0`` (plus
``n_x = n_y`` for every engaged clutch or brake).

References
----------
Benford, H. L.; Leising, M. B.: The lever analogy: a new tool in transmission
analysis.  SAE Technical Paper 810102 (1981).  Willis equation:
Queitsch eq. 12 (s = i0).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

import numpy as np

from ..model.elements import HOUSING, Brake, Clutch
from ._common import SHAFT_COLOURS, figure_svg, fmt, lever_elements, pyplot

if TYPE_CHECKING:  # pragma: no cover
    from ..model.train import GearTrain
    from ..results.solution import Solution

__all__ = ["LeverNode", "Lever", "CompoundLever", "LeverDiagram", "lever_diagram", "compound_lever"]


@dataclass(frozen=True)
class LeverNode:
    """A node of a lever: which port, which shaft, at what height (0…1)."""

    port: str
    shaft: str
    position: float


@dataclass(frozen=True)
class Lever:
    """One element as a lever: nodes at heights from its ratio (span 0…1)."""

    element: str
    kind: str
    ratio: float
    nodes: tuple[LeverNode, LeverNode, LeverNode]

    def position(self, port: str) -> float:
        """Height of the node of ``port``."""
        for node in self.nodes:
            if node.port == port:
                return node.position
        raise KeyError(port)


@dataclass(frozen=True)
class CompoundLever:
    """All shafts of a two-degree-of-freedom train on one lever.

    Attributes
    ----------
    positions : mapping shaft → height in [0, 1]
    speeds : mapping shaft → 1/min, or None
        The solved speeds (a straight line over the heights).
    """

    positions: Mapping[str, float]
    speeds: Mapping[str, float] | None = None

    def speed_line(self) -> tuple[float, float]:
        """(α, β) of the least-squares line n = α + β·Y through the speeds (1/min)."""
        if self.speeds is None:
            raise ValueError("no speeds")
        ys = np.array([self.positions[s] for s in self.positions])
        ns = np.array([self.speeds[s] for s in self.positions])
        beta, alpha = np.polyfit(ys, ns, 1)
        return float(alpha), float(beta)

    def groups(self) -> list[tuple[float, list[str]]]:
        """Shafts at the same height (joined shafts), bottom to top."""
        out: list[tuple[float, list[str]]] = []
        for shaft, y in sorted(self.positions.items(), key=lambda kv: kv[1]):
            if out and abs(out[-1][0] - y) <= 1e-9:
                out[-1][1].append(shaft)
            else:
                out.append((y, [shaft]))
        return out


@dataclass(frozen=True)
class LeverDiagram:
    """Levers of a train, the links between them and, if it exists, the compound lever.

    Attributes
    ----------
    levers : tuple of Lever
    links : tuple of (shaft, lever index, lever index)
        Shafts shared by two levers (permanent connections).
    shift_elements : tuple of (name, kind, shafts, engaged)
    compound : CompoundLever or None
    """

    title: str
    levers: tuple[Lever, ...]
    links: tuple[tuple[str, int, int], ...]
    shift_elements: tuple[tuple[str, str, tuple[str, str], bool], ...]
    compound: CompoundLever | None
    permanent: CompoundLever | None = None

    def to_dict(self) -> dict[str, Any]:
        return {
            "title": self.title,
            "levers": [{"element": lv.element, "ratio": lv.ratio,
                        "nodes": [n.__dict__ for n in lv.nodes]} for lv in self.levers],
            "links": [list(link) for link in self.links],
            "compound": None if self.compound is None else {
                "positions": dict(self.compound.positions),
                "speeds": None if self.compound.speeds is None else dict(self.compound.speeds)},
            "units": {"speed": "1/min"},
        }

    def _repr_html_(self) -> str:
        return figure_svg(self.plot())

    def __repr__(self) -> str:
        state = "compound lever" if self.compound is not None else "no compound lever"
        return f"<LeverDiagram {self.title!r}: {len(self.levers)} levers, {len(self.links)} links, {state}>"

    def plot(self) -> Any:
        """Figure: left the levers with their links, right the speeds on the compound lever."""
        plt = pyplot()
        fig, (left, right) = plt.subplots(1, 2, figsize=(13, 5.5), gridspec_kw={"width_ratios": [1, 1.25]})
        self._plot_levers(left)
        self._plot_speeds(right)
        fig.suptitle(f"{self.title}: lever diagram (Benford–Leising)", fontsize=12)
        fig.tight_layout()
        return fig

    def _heights(self, lever: Lever) -> dict[str, float]:
        """Node heights for the left panel: the permanent compound lever if the sets and
        stages alone form one, else each lever on its own scale."""
        if self.permanent is not None and all(n.shaft in self.permanent.positions for n in lever.nodes):
            return {n.port: self.permanent.positions[n.shaft] for n in lever.nodes}
        return {n.port: n.position for n in lever.nodes}

    def _plot_levers(self, ax: Any) -> None:
        colours = _shaft_colours(self)
        spots: dict[tuple[str, int], tuple[float, float]] = {}
        for k, lever in enumerate(self.levers):
            h = self._heights(lever)
            ax.plot([k, k], [min(h.values()), max(h.values())], color="black", lw=4, solid_capstyle="round")
            for node in lever.nodes:
                y = h[node.port]
                spots[(node.shaft, k)] = (k, y)
                ax.plot([k], [y], "o", ms=10, color=colours[node.shaft], mec="black", zorder=5)
                left = k == 0 and len(self.levers) > 1
                ax.annotate(f"{node.port} ({node.shaft})", (k, y), xytext=(-9 if left else 9, 4),
                            textcoords="offset points", fontsize=8, ha="right" if left else "left")
            ax.annotate(f"{lever.element}\n{'i0' if lever.kind == 'planetary set' else 'ratio'} = {fmt(lever.ratio)}",
                        (k, -0.08), ha="center", va="top", fontsize=9, annotation_clip=False)
        for shaft, i, j in self.links:
            (x0, y0), (x1, y1) = spots[(shaft, i)], spots[(shaft, j)]
            ax.plot([x0, x1], [y0, y1], color=colours[shaft], lw=2, ls="--", zorder=1)
        drawn_label = False
        for name, kind, shafts, engaged in self.shift_elements:
            ends = [spots[(s, k)] for s in shafts for k in range(len(self.levers)) if (s, k) in spots]
            if len(ends) >= 2 and engaged:
                (x0, y0), (x1, y1) = ends[0], ends[-1]
                ax.plot([x0, x1], [y0, y1], color="red", lw=2.5, zorder=2,
                        label=None if drawn_label else "engaged clutch/brake")
                drawn_label = True
                ax.annotate(name, ((x0 + x1) / 2, (y0 + y1) / 2), color="red", fontsize=8)
            elif kind == "brake" and engaged and ends:
                x, y = ends[0]
                ax.plot([x - 0.25, x], [y, y], color="red", lw=2.5, label=None if drawn_label else "engaged brake")
                ax.annotate(f"{name} (held)", (x - 0.25, y), color="red", fontsize=8, ha="right")
                drawn_label = True
        ax.plot([], [], color="grey", ls="--", label="same shaft (link)")
        ax.set_xlim(-0.9, len(self.levers) - 0.1)
        ax.set_xticks([])
        ax.set_ylabel("node height on the lever (0…1, from the ratios)")
        ax.set_title("levers and links", fontsize=10)
        ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=2)
        ax.grid(True, axis="y", alpha=0.3)

    def _plot_speeds(self, ax: Any) -> None:
        colours = _shaft_colours(self)
        if self.compound is None or self.compound.speeds is None:
            ax.text(0.5, 0.5, "no single compound lever:\nthe train has more than one free speed",
                    ha="center", va="center", transform=ax.transAxes)
            ax.set_axis_off()
            return
        c = self.compound
        ys = [y for y, _ in c.groups()]
        ax.plot([0, 0], [min(ys), max(ys)], color="black", lw=5, solid_capstyle="round", label="compound lever")
        alpha, beta = c.speed_line()
        ax.plot([alpha + beta * (min(ys) - 0.05), alpha + beta * (max(ys) + 0.05)], [min(ys) - 0.05, max(ys) + 0.05],
                color="grey", lw=1.5, ls="-", label="speeds: one straight line")
        top = max(abs(v) for v in c.speeds.values()) or 1.0
        for y, shafts in c.groups():
            n = c.speeds[shafts[0]]
            n = 0.0 if abs(n) <= 1e-9 * top else n
            colour = colours[shafts[0]]
            ax.annotate("", (n, y), (0, y), arrowprops={"arrowstyle": "->", "color": colour, "lw": 2})
            ax.plot([n], [y], "o", color=colour, mec="black", ms=9, zorder=5)
            ax.annotate(f"{' = '.join(shafts)}: {fmt(n, 5)} 1/min", (n, y), xytext=(8, 4), textcoords="offset points",
                        fontsize=9)
        ax.axvline(0, color="black", lw=0.6)
        ax.set_xlabel("speed n in 1/min")
        ax.set_ylabel("node height on the compound lever")
        ax.set_title("speeds of the shift state across the lever", fontsize=10)
        ax.margins(x=0.25)
        ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=2)
        ax.grid(True, alpha=0.3)


def _shaft_colours(diagram: LeverDiagram) -> dict[str, str]:
    shafts: list[str] = []
    for lever in diagram.levers:
        for node in lever.nodes:
            if node.shaft not in shafts:
                shafts.append(node.shaft)
    if diagram.compound is not None:
        shafts += [s for s in diagram.compound.positions if s not in shafts]
    colours = {s: SHAFT_COLOURS[k % len(SHAFT_COLOURS)] for k, s in enumerate(s for s in shafts if s != HOUSING)}
    colours[HOUSING] = "#777777"
    return colours


def _lever(element: Any, ports: tuple[str, str, str], shafts: tuple[str, str, str], ratio: float) -> Lever:
    t = ratio / (ratio - 1.0)  # carrier node, sun at 0, ring at 1
    raw = (0.0, 1.0, t)
    lo, hi = min(raw), max(raw)
    nodes = tuple(LeverNode(p, s, (y - lo) / (hi - lo)) for p, s, y in zip(ports, shafts, raw))
    kind = "planetary set" if ports[0] == "sun" else "gear stage"
    return Lever(element.name, kind, ratio, nodes)  # type: ignore[arg-type]


def compound_lever(train: GearTrain) -> CompoundLever | None:
    """Heights of all shafts on one lever, or None if the train has more free speeds.

    The heights come from the permanent elements (sets and stages) when they
    alone leave two degrees of freedom; shafts that only an engaged clutch or
    brake touches (e.g. the housing) sit at the height of the shaft they are
    joined to.  Otherwise the engaged clutches and brakes are included in the
    equations.  The housing counts as a shaft that may turn.  Returns None when
    no two-dimensional null space is found.

    Examples
    --------
    >>> from epicyclic.demo import brandenberger_1952
    >>> lever = compound_lever(brandenberger_1952()[0])
    >>> {s: round(y, 4) for s, y in lever.positions.items()}
    {'I': 0.5189, 'II': 0.2841, 'III': 1.0, 'housing': 0.0}
    """
    rows: list[dict[str, float]] = []
    for _, _, shafts, ratio in lever_elements(train):
        rows.append(dict(zip(shafts, (1.0, -ratio, -(1.0 - ratio)))))
    links = [element.shafts for element in train.shift_elements if element.engaged]
    positions = _null_space_heights(train, rows)
    if positions is None:
        positions = _null_space_heights(train, rows + [{a: 1.0, b: -1.0} for a, b in links])
        if positions is None:
            return None
    for _ in range(len(links)):
        for a, b in links:
            if a in positions and b not in positions:
                positions[b] = positions[a]
            elif b in positions and a not in positions:
                positions[a] = positions[b]
    ordered = {s: positions[s] for s in train.shafts if s in positions}
    return CompoundLever(MappingProxyType(ordered))


def _null_space_heights(train: GearTrain, rows: list[dict[str, float]]) -> dict[str, float] | None:
    used: list[str] = [s for s in train.shafts if any(s in row for row in rows)]
    if not rows or not used:
        return None
    index = {s: k for k, s in enumerate(used)}
    matrix = np.zeros((len(rows), len(used)))
    for r, row in enumerate(rows):
        for shaft, coef in row.items():
            matrix[r, index[shaft]] += coef
    _, sv, vt = np.linalg.svd(matrix)
    rank = int(np.sum(sv > 1e-10 * max(1.0, sv.max(initial=0.0))))
    null = vt[rank:]
    if null.shape[0] != 2:
        return None
    ones = np.ones(len(used)) / np.sqrt(len(used))
    # the direction in the null space orthogonal to the rigid rotation
    projected = null - np.outer(null @ ones, ones)
    v = projected[int(np.argmax(np.linalg.norm(projected, axis=1)))]
    if np.ptp(v) <= 1e-12:
        return None
    # a fixed orientation: the housing in the lower half, else the first sun below its ring
    key = v[index[HOUSING]] - v.mean() if HOUSING in index else 0.0
    if abs(key) <= 1e-9 * np.ptp(v):
        _, _, shafts0, _ = lever_elements(train)[0]
        key = v[index[shafts0[0]]] - v[index[shafts0[1]]]
    if key > 0:
        v = -v
    y = (v - v.min()) / np.ptp(v)
    y = np.where(np.abs(y) < 1e-12, 0.0, y)
    return {s: float(y[index[s]]) for s in used}


def lever_diagram(solution: Solution | None = None, *, train: GearTrain | None = None) -> LeverDiagram:
    """The lever diagram of a solved train (speeds drawn) or of a bare train.

    Parameters
    ----------
    solution : Solution, optional
        Gives the train (in its shift state) and the speeds.
    train : GearTrain, optional
        Without a solution: only the levers and positions.

    References
    ----------
    Benford & Leising 1981 (SAE 810102); Willis equation (Queitsch eq. 12).

    Examples
    --------
    >>> from epicyclic.demo import brandenberger_1952
    >>> from epicyclic import solve
    >>> d = lever_diagram(solve(*brandenberger_1952()))
    >>> lv = d.levers[0]
    >>> round((lv.position("sun") - lv.position("carrier")) / (lv.position("ring") - lv.position("carrier")), 4)
    0.672
    """
    from ._common import PlottingError

    if solution is None and train is None:
        raise PlottingError("lever diagram: give a solution (or train=...) to draw, got neither.")
    if solution is not None:
        train = solution.train
    assert train is not None
    items = lever_elements(train)
    levers = tuple(_lever(e, ports, shafts, ratio) for e, ports, shafts, ratio in items)
    links = []
    last_seen: dict[str, int] = {}
    for k, lever in enumerate(levers):
        for node in lever.nodes:
            if node.shaft in last_seen and node.shaft != HOUSING:
                links.append((node.shaft, last_seen[node.shaft], k))
            last_seen[node.shaft] = k
    shift = tuple((e.name, "clutch" if isinstance(e, Clutch) else "brake", e.shafts, e.engaged)
                  for e in train.shift_elements if isinstance(e, (Clutch, Brake)))
    compound = compound_lever(train)
    permanent = compound_lever(train.with_engaged([])) if train.shift_elements else compound
    if permanent is not None and len({round(y, 9) for y in permanent.positions.values()}) < 2:
        permanent = None
    if compound is not None and solution is not None:
        compound = CompoundLever(compound.positions,
                                 MappingProxyType({s: solution.speed(s) for s in compound.positions}))
    return LeverDiagram(train.name, levers, tuple(links), shift, compound, permanent)
