"""Power-flow diagram: the train as a graph, arrow widths proportional to power.

Nodes are the shafts (circles) and the elements (boxes); every port of an
element is an edge between its shaft and the element, pointing the way power
flows (``P = T·n·π/30`` into the element when positive).  Drives enter from a
source above their shaft, loads leave to a sink; each element's loss leaves
downwards to its own loss node.  Edge widths are proportional to the power
they carry (one scale for the whole figure).  Edges on a closed loop around
which power circulates (Brandenberger, text to Bild 11 and 12: "zirkulieren
im Vorgelege Leistungen"; see :mod:`epicyclic.results.circulation`) are drawn
in red.  Each planetary
set is labelled with its rolling power ``P_w = T_sun·(n_sun − n_carrier)·π/30``,
the part that passes the teeth relative to the carrier and alone causes loss.

References
----------
Brandenberger 1952, Bild 10–12 and text (rolling and coupling
power, circulating power).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

from ..model.elements import HOUSING
from ._common import figure_svg, fmt, pyplot

if TYPE_CHECKING:  # pragma: no cover
    from ..results.circulation import Circulation
    from ..results.solution import Solution

__all__ = ["FlowNode", "FlowEdge", "PowerFlow", "power_flow"]

#: Edge powers below this fraction of the input power are not drawn.
_ZERO = 1e-9
#: Line width (points) of the edge with the largest power.
MAX_WIDTH = 14.0


@dataclass(frozen=True)
class FlowNode:
    """A node of the flow graph: kind shaft, element, source, sink or loss; position in data units."""

    name: str
    kind: str
    x: float
    y: float
    label: str


@dataclass(frozen=True)
class FlowEdge:
    """Power ``power`` (W, ≥ 0) flowing from ``source`` to ``target``; ``width`` in points."""

    source: str
    target: str
    power: float
    kind: str  # port, drive, load, loss
    circulating: bool
    width: float


@dataclass(frozen=True)
class PowerFlow:
    """The power-flow graph of a solved train.

    Attributes
    ----------
    nodes, edges : tuple
    width_per_watt : float
        Points of line width per W (the same for every edge).
    input_power : float
    circulation : Circulation
        Circulating power per loop and in total, and the largest element power.
    rolling : mapping element → W
    losses : mapping element → W
    """

    title: str
    nodes: tuple[FlowNode, ...]
    edges: tuple[FlowEdge, ...]
    width_per_watt: float
    input_power: float
    circulation: Circulation
    rolling: Mapping[str, float]
    losses: Mapping[str, float]
    self_locking: bool = False

    def node(self, name: str) -> FlowNode:
        return next(n for n in self.nodes if n.name == name)

    def to_dict(self) -> dict[str, Any]:
        return {"title": self.title, "units": {"power": "W", "width": "pt"},
                "nodes": [n.__dict__ for n in self.nodes], "edges": [e.__dict__ for e in self.edges],
                "input_power": self.input_power, "circulation": self.circulation.to_dict(),
                "rolling": dict(self.rolling), "losses": dict(self.losses)}

    def _repr_html_(self) -> str:
        return figure_svg(self.plot())

    def __repr__(self) -> str:
        return (f"<PowerFlow {self.title!r}: {len(self.edges)} edges, input {fmt(self.input_power)} W, "
                f"{self._circulation_text()}>")

    def _circulation_text(self) -> str:
        circ = self.circulation
        if circ.indeterminate:
            return "circulating power not defined (indeterminate torque split)"
        if circ.loops and circ.ratio is not None:
            return f"power circulates: {fmt(circ.ratio, 3)} × input"
        if circ.largest_element_ratio is None:
            return "no power flows"
        return f"no circulating power, largest element power {fmt(circ.largest_element_ratio, 3)} × input"

    def plot(self, ax: Any = None) -> Any:
        """Draw the graph; returns the figure."""
        from matplotlib.patches import FancyArrowPatch

        plt = pyplot()
        if ax is None:
            xs = [n.x for n in self.nodes]
            fig, ax = plt.subplots(figsize=(max(8.0, 1.6 * (max(xs) - min(xs) + 2) + 3.0), 7.0))
        else:
            fig = ax.figure
        for edge in self.edges:
            a, b = self.node(edge.source), self.node(edge.target)
            colour = {"drive": "#D55E00", "load": "#0072B2", "loss": "#999999"}.get(edge.kind, "#009E73")
            if edge.circulating:
                colour = "#CC0000"
            ax.add_patch(FancyArrowPatch((a.x, a.y), (b.x, b.y), arrowstyle="-|>", mutation_scale=12 + edge.width,
                                         lw=edge.width, color=colour, alpha=0.75, shrinkA=22, shrinkB=22,
                                         connectionstyle="arc3,rad=0.08", zorder=2))
            # label near the shaft end, so that crossing edges keep their labels apart
            t = 0.3 if a.kind == "shaft" else 0.7 if b.kind == "shaft" else 0.5
            ax.text(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), f"{fmt(edge.power)} W", fontsize=8, ha="center", va="center",
                    zorder=6, bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": colour, "lw": 0.8})
        for node in self.nodes:
            style = {"shaft": ("circle,pad=0.4", "#ffffff"), "element": ("round,pad=0.5", "#fff3c4"),
                     "loss": ("round,pad=0.3", "#eeeeee")}.get(node.kind, ("round,pad=0.3", "#ffffff"))
            ax.text(node.x, node.y, node.label, ha="center", va="center", fontsize=9, zorder=7,
                    bbox={"boxstyle": style[0], "fc": style[1], "ec": "black"})
        for kind, colour, label in (("drive", "#D55E00", "power in (drive)"), ("load", "#0072B2", "power out (load)"),
                                    ("port", "#009E73", "power through a port"), ("loss", "#999999", "loss"),
                                    ("circ", "#CC0000", "circulating (closed loop)")):
            ax.plot([], [], color=colour, lw=4, label=label)
        ax.plot([], [], color="black", lw=MAX_WIDTH * 0.25, label=f"width: {fmt(1 / self.width_per_watt, 3)} W per pt")
        xs, ys = [n.x for n in self.nodes], [n.y for n in self.nodes]
        ax.set_xlim(min(xs) - 0.9, max(xs) + 0.9)
        ax.set_ylim(min(ys) - 0.6, max(ys) + 0.6)
        ax.set_axis_off()
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.0, 1.0), title="arrow width ∝ power (W)",
                  title_fontsize=8)
        circ = self._circulation_text()
        if self.self_locking:
            circ += " — SELF-LOCKING (formal solution shown)"
        ax.set_title(f"{self.title}: power flow, input {fmt(self.input_power)} W; {circ}", fontsize=11)
        fig.tight_layout()
        return fig


def power_flow(solution: Solution, *, max_width: float = MAX_WIDTH) -> PowerFlow:
    """The power-flow graph of a solved train.

    Parameters
    ----------
    solution : Solution
    max_width : float, default 14
        Line width in points of the edge with the largest power.

    References
    ----------
    Brandenberger 1952, text to Bild 11 and 12 (circulating power).

    Examples
    --------
    >>> from epicyclic.demo import brandenberger_1952
    >>> from epicyclic import solve
    >>> flow = power_flow(solve(*brandenberger_1952()))
    >>> [(e.source, e.target, round(e.power)) for e in flow.edges if e.kind == "drive"]
    [('in: II', 'II', 2206)]
    """
    scale = max(solution.input_power, solution.output_power, 1e-300)
    raw: list[tuple[str, str, float, str]] = []
    elements = [e for e in solution.elements.values() if any(abs(p) > _ZERO * scale for p in e.port_powers.values())
                or e.loss > _ZERO * scale]
    for state in elements:
        for port, power in state.port_powers.items():
            shaft = state.ports[port]
            if abs(power) <= _ZERO * scale:
                continue
            raw.append((shaft, state.name, power, "port") if power > 0 else (state.name, shaft, -power, "port"))
        if state.loss > _ZERO * scale:
            raw.append((state.name, f"loss: {state.name}", state.loss, "loss"))
    for shaft in solution.shafts.values():
        if shaft.power > _ZERO * scale:
            raw.append((f"in: {shaft.name}", shaft.name, shaft.power, "drive"))
        elif shaft.power < -_ZERO * scale:
            raw.append((shaft.name, f"out: {shaft.name}", -shaft.power, "load"))
    largest = max((p for *_, p, _ in raw), default=1.0)
    per_watt = max_width / largest
    on_loop = {pair for loop in solution.circulation.loops
               for pair in zip(loop.path, (*loop.path[1:], loop.path[0]))}
    edges = tuple(FlowEdge(a, b, p, kind, kind == "port" and (a, b) in on_loop, p * per_watt)
                  for a, b, p, kind in raw)
    nodes = _layout(solution, [e.name for e in elements], edges)
    rolling = {e.name: e.rolling_power for e in solution.elements.values() if e.kind == "planetary set"}
    losses = {e.name: e.loss for e in solution.elements.values() if e.kind in ("planetary set", "gear stage")}
    return PowerFlow(solution.train.name, nodes, edges, per_watt, solution.input_power, solution.circulation,
                     MappingProxyType(rolling), MappingProxyType(losses), solution.self_locking is not None)


def _layout(solution: Solution, elements: list[str], edges: tuple[FlowEdge, ...]) -> tuple[FlowNode, ...]:
    """Elements in a row (y = 0), shafts above (y = 1.6), sources/sinks on top, losses below."""
    ex = {name: 2.0 * k for k, name in enumerate(elements)}
    shafts = [s for s in solution.shafts if s != HOUSING and any(s in (e.source, e.target) for e in edges)]
    wanted = {}
    for shaft in shafts:
        linked = [ex[e.target] if e.source == shaft and e.target in ex else ex[e.source]
                  for e in edges if shaft in (e.source, e.target) and (e.source in ex or e.target in ex)]
        wanted[shaft] = sum(linked) / len(linked) if linked else 0.0
    order = sorted(shafts, key=lambda s: (wanted[s], shafts.index(s)))
    span = max(ex.values(), default=0.0)
    step = max(span / max(len(order) - 1, 1), 1.6) if len(order) > 1 else 0.0
    start = (span - step * (len(order) - 1)) / 2
    sx = {s: start + step * k for k, s in enumerate(order)}
    nodes: list[FlowNode] = []
    for name in elements:
        state = solution.elements[name]
        label = f"{name}\n({state.kind})"
        if state.kind == "planetary set":
            label += f"\nP_w = {fmt(state.rolling_power)} W"
        nodes.append(FlowNode(name, "element", ex[name], 0.0, label))
        if state.loss > 0:
            nodes.append(FlowNode(f"loss: {name}", "loss", ex[name], -1.4, f"loss\n{fmt(state.loss)} W"))
    for shaft in order:
        n = solution.speed(shaft)
        nodes.append(FlowNode(shaft, "shaft", sx[shaft], 1.6, f"{shaft}\n{fmt(n, 5)}\n1/min"))
    for edge in edges:
        if edge.kind == "drive":
            nodes.append(FlowNode(edge.source, "source", sx[edge.target] - 0.35, 3.0, f"drive\n{edge.target}"))
        elif edge.kind == "load":
            nodes.append(FlowNode(edge.target, "sink", sx[edge.source] + 0.35, 3.0, f"load\n{edge.source}"))
    return tuple(nodes)


