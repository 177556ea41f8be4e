"""Power-flow diagram: drives → shafts, sets and stages → loads, losses below; widths ∝ power.

Nodes are the drives (power put in), the shafts, the elements that carry
power (planetary sets, gear stages, engaged clutches) and the loads (power
taken out).  Every port of an element is an edge between its shaft and the
element, pointing the way power flows (``P = T·n·π/30`` into the element when
positive).  Each element's loss leaves downwards to a label below it.  Band
widths are proportional to the power they carry (one scale for the figure).

The graph is drawn in layers (:mod:`._layered`): drives on the left, loads on
the right, every element between the shafts that feed it and the shafts it
feeds; the layout avoids crossings where it can.  A branch that carries no
power by the zero rule (:mod:`.values`) is left out.  Where power flows
around a closed loop (Brandenberger, text to Bild 11 and 12: "zirkulieren im
Vorgelege Leistungen") the loop's edges are drawn red, the edge that closes
it running back against the layers.  Each planetary set is labelled with its
rolling power ``P_w = T_sun·(n_sun − n_carrier)·π/30``, the part that passes
the teeth relative to the carrier and alone causes loss.

References
----------
Brandenberger 1952, Bild 10–12 and text (rolling and coupling power,
circulating power); Sugiyama, Tagawa & Toda 1981 (layered drawing).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

from ..model.elements import HOUSING
from ._common import figure_svg
from ._flow_draw import BOX, plot_power_flow
from ._layered import layered_layout
from .context import FigureContext
from .values import Scales, clean, fmt, is_zero

if TYPE_CHECKING:  # pragma: no cover
    from ..results.circulation import Circulation
    from ..results.solution import Solution

__all__ = ["FlowNode", "FlowEdge", "PowerFlow", "power_flow", "MAX_WIDTH"]

#: Width (data units; a layer is 2.6 wide) of the band with the largest power.
MAX_WIDTH = 0.15


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
    """Power ``power`` (W, > 0) flowing from ``source`` to ``target``; ``width`` in data units.

    ``circulating``: the edge lies on a closed loop of power flow.
    """

    source: str
    target: str
    power: float
    kind: str  # port, drive, load, loss
    circulating: bool
    width: float
    route: tuple[tuple[float, float], ...] = ()


@dataclass(frozen=True)
class PowerFlow:
    """The power-flow graph of a solved train, laid out in layers.

    Attributes
    ----------
    nodes, edges : tuple
    width_per_watt : float
        Band width (data units) per W, the same for every edge.
    input_power : float
    circulation : Circulation
        The solver's circulating power (``Solution.circulation``: per loop and
        in total, and the largest element power).
    rolling : mapping element → W
    losses : mapping element → W
    crossings : int
        Edge crossings of the layout.
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
    crossings: int = 0
    context: FigureContext = field(default_factory=FigureContext)
    notes: tuple[str, ...] = ()
    train: Any = field(default=None, repr=False, compare=False)

    def node(self, name: str) -> FlowNode:
        """The node (shaft, element, housing or loss) called ``name``.

        Parameters
        ----------
        name : str
            The node's name.

        Returns
        -------
        FlowNode

        Raises
        ------
        StopIteration
            No node has that name.
        """
        return next(n for n in self.nodes if n.name == name)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data of the flow graph: nodes, edges (power in W), circulation, rolling power, losses.

        Returns
        -------
        dict
            ``title``, ``units``, ``nodes``, ``edges`` (without their drawn routes),
            ``input_power``, ``circulation`` (:meth:`Circulation.to_dict
            <epicyclic.results.Circulation.to_dict>`), ``rolling`` and ``losses`` (element →
            W) and ``crossings`` (edge crossings of the layout).
        """
        return {"title": self.title, "units": {"power": "W", "width": "data units"},
                "nodes": [n.__dict__ for n in self.nodes],
                "edges": [{k: v for k, v in e.__dict__.items() if k != "route"} for e in self.edges],
                "input_power": self.input_power, "circulation": self.circulation.to_dict(),
                "rolling": dict(self.rolling), "losses": dict(self.losses), "crossings": self.crossings}

    def _repr_html_(self) -> str:
        return figure_svg(self.plot())

    def __repr__(self) -> str:
        return (f"<PowerFlow {self.title!r}: {len(self.edges)} edges, input {fmt(self.input_power)} W, "
                f"circulating power {fmt(self.circulation.ratio, 3)} × input, {self.crossings} crossings>")

    def plot(self) -> Any:
        """Draw the layered graph; returns the figure."""
        return plot_power_flow(self)


def _loops(edges: list[tuple[str, str]]) -> set[int]:
    """Indices of edges inside a strongly connected part (on a closed loop of power flow)."""
    nodes = {n for e in edges for n in e}
    reach = {n: {b for a, b in edges if a == n} for n in nodes}
    changed = True
    while changed:  # transitive closure (a few dozen nodes)
        changed = False
        for n in nodes:
            more = set().union(*(reach[m] for m in reach[n])) - reach[n]
            if more:
                reach[n] |= more
                changed = True
    return {k for k, (a, b) in enumerate(edges) if a in reach[b]}


def power_flow(solution: Solution, *, max_width: float = MAX_WIDTH,
               context: FigureContext | None = None) -> PowerFlow:
    """The power-flow graph of a solved train, laid out in layers.

    Parameters
    ----------
    solution : Solution
    max_width : float, default 0.15
        Band width (data units) of the edge with the largest power.
    context : FigureContext, optional
        Title, units and notes of the figure.

    References
    ----------
    Brandenberger 1952, text to Bild 11 and 12 (circulating power).

    Examples
    --------
    >>> from epicyclic.demo import brandenberger_1952
    >>> from epicyclic import solve
    >>> flow = power_flow(solve(*brandenberger_1952()))
    >>> [(e.source, e.target, round(e.power)) for e in flow.edges if e.kind == "drive"]
    [('drive: II', 'II', 2206)]
    >>> flow.crossings
    0
    """
    context = context or FigureContext(title=solution.train.name)
    scale = Scales.of(solution).power
    raw: list[tuple[str, str, float, str]] = []
    element_of = {}  # node id → element state; an element named like a shaft gets its kind in its id
    for state in solution.elements.values():
        ports = [(port, clean(p, scale)) for port, p in state.port_powers.items()]
        if not any(p for _, p in ports):
            continue
        node = state.name if state.name not in solution.shafts else f"{state.name} ({state.kind})"
        element_of[node] = state
        for port, power in ports:
            shaft = state.ports[port]
            if power and shaft != HOUSING:
                raw.append((shaft, node, power, "port") if power > 0 else (node, shaft, -power, "port"))
    for shaft in solution.shafts.values():
        power = clean(shaft.power, scale)
        if power > 0:
            raw.append((f"drive: {shaft.name}", shaft.name, power, "drive"))
        elif power < 0:
            raw.append((shaft.name, f"load: {shaft.name}", -power, "load"))
    losses_w = [clean(state.loss, scale) for state in element_of.values()]
    largest = max([p for *_, p, _ in raw] + losses_w, default=1.0) or 1.0
    per_watt = max_width / largest
    loops = _loops([(a, b) for a, b, *_ in raw])
    names = list(dict.fromkeys(n for a, b, *_ in raw for n in (a, b)))
    kinds = {n: ("source" if n.startswith("drive: ") else "sink" if n.startswith("load: ")
                 else "element" if n in element_of else "shaft") for n in names}
    heights = {n: BOX[kinds[n]][1] + (0.55 if kinds[n] == "element" and not is_zero(
        element_of[n].loss, scale) else 0.0) for n in names}
    layout = layered_layout(names, [(a, b) for a, b, *_ in raw], first=[n for n in names if kinds[n] == "source"],
                            last=[n for n in names if kinds[n] == "sink"], heights=heights, dx=2.6, gap=0.45)
    edges = tuple(FlowEdge(a, b, p, kind, k in loops, p * per_watt, tuple(layout.routes[k]))
                  for k, (a, b, p, kind) in enumerate(raw))
    nodes: list[FlowNode] = []
    for n in names:
        x, y = layout.x[n], layout.y[n]
        if kinds[n] == "element":
            state = element_of[n]
            label = f"{state.name}\n{state.kind}"
            if state.kind == "planetary set":
                label += f"\nP_w {context.text(state.rolling_power, 'power', scale)}"
            if not is_zero(state.loss, scale):  # the box sits at the top of its slot, the loss below it
                y += 0.275
                loss = f"loss {context.text(state.loss, 'power', scale)}"
                nodes.append(FlowNode(f"loss: {n}", "loss", x, y - BOX['element'][1] / 2 - 0.42, loss))
        elif kinds[n] == "shaft":
            label = f"{n}\n{context.text(solution.speed(n), 'speed', Scales.of(solution).speed, 5)}"
        else:
            shaft = n.split(": ", 1)[1]
            label = f"{'drive' if kinds[n] == 'source' else 'load'} {shaft}\n" \
                    f"{context.text(abs(solution.power(shaft)), 'power', scale)}"
        nodes.append(FlowNode(n, kinds[n], x, y, label))
    edges = _attach(edges, {node.name: node for node in nodes})
    for node, state in element_of.items():
        if not is_zero(state.loss, scale):
            edges += (FlowEdge(node, f"loss: {node}", state.loss, "loss", False, state.loss * per_watt),)
    rolling = {e.name: clean(e.rolling_power, scale) for e in solution.elements.values() if e.kind == "planetary set"}
    losses = {e.name: clean(e.loss, scale) for e in solution.elements.values()
              if e.kind in ("planetary set", "gear stage")}
    notes = tuple(w for w in solution.warnings if "indeterminate" in w)
    return PowerFlow(context.title or solution.train.name, tuple(nodes), edges, per_watt, solution.input_power,
                     solution.circulation, MappingProxyType(rolling), MappingProxyType(losses),
                     solution.self_locking is not None, layout.crossings, context, notes, solution.train)


def _attach(edges: tuple[FlowEdge, ...], nodes: dict[str, FlowNode]) -> tuple[FlowEdge, ...]:
    """Routes that start and end at the (possibly moved) node centres."""
    out = []
    for e in edges:
        route = list(e.route)
        if route:
            route[0] = (nodes[e.source].x, nodes[e.source].y)
            route[-1] = (nodes[e.target].x, nodes[e.target].y)
        out.append(FlowEdge(e.source, e.target, e.power, e.kind, e.circulating, e.width, tuple(route)))
    return tuple(out)
