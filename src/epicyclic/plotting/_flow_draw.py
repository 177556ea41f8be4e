"""Drawing of :class:`~epicyclic.plotting.flow.PowerFlow`: boxes, bands with arrow heads, labels.

Bands are thick lines whose width in points is the edge's width in data
units (equal aspect), ending in a triangular head drawn as its own polygon,
so that a wide band has a head of the same proportion rather than a blob.
Power values sit on the bands in white boxes; overlapping labels are pushed
apart after drawing.  The flow is taken duck-typed: this module does not
import :mod:`.flow` (which imports this one), so the two are no import cycle.
"""

from __future__ import annotations

import math
from typing import Any

from ._common import pyplot
from ._labels import fit_titles, keep_inside, separate

__all__ = ["plot_power_flow", "BOX", "COLOURS", "MIN_WIDTH"]

#: Narrowest band drawn (data units), so that a small power stays visible (the data keep the true width).
MIN_WIDTH = 0.012
#: Box sizes (width, height) in data units per node kind.
BOX = {"element": (1.5, 0.95), "shaft": (1.25, 0.62), "source": (1.25, 0.62), "sink": (1.25, 0.62)}
COLOURS = {"drive": "#D55E00", "load": "#0072B2", "port": "#009E73", "loss": "#8C8C8C", "loop": "#C0392B"}

FILL = {"element": "#FFF3C4", "shaft": "#FFFFFF", "source": "#FBE3D2", "sink": "#DCEAF7", "loss": "#EEEEEE"}
#: Inches per data unit.
INCH = 0.78


def _clip(inside: tuple[float, float], outside: tuple[float, float], box: tuple[float, float]
          ) -> tuple[float, float]:
    """Where the segment from a box centre towards ``outside`` leaves the box (w, h)."""
    (x0, y0), (x1, y1) = inside, outside
    dx, dy = x1 - x0, y1 - y0
    if dx == 0 and dy == 0:
        return inside
    t = min(box[0] / 2 / abs(dx) if dx else math.inf, box[1] / 2 / abs(dy) if dy else math.inf)
    return x0 + t * dx, y0 + t * dy


def _colour(edge: Any) -> str:
    return COLOURS["loop"] if edge.circulating else COLOURS[edge.kind]


def _band(ax: Any, points: list[tuple[float, float]], width: float, colour: str, ppu: float) -> None:
    """A band of ``width`` data units along ``points`` ending in an arrow head at the last point."""
    from matplotlib.patches import Polygon

    head_w = max(1.9 * width, 0.09)
    head_l = max(1.4 * width, 0.13)
    (xa, ya), (xb, yb) = points[-2], points[-1]
    length = math.hypot(xb - xa, yb - ya) or 1.0
    ux, uy = (xb - xa) / length, (yb - ya) / length
    base = (xb - head_l * ux, yb - head_l * uy)
    line = [*points[:-1], base]
    xs, ys = zip(*line)
    ax.plot(xs, ys, color=colour, lw=width * ppu, alpha=0.8, solid_capstyle="butt", solid_joinstyle="round",
            zorder=2)
    nx, ny = -uy * head_w / 2, ux * head_w / 2
    ax.add_patch(Polygon([(base[0] + nx, base[1] + ny), (xb, yb), (base[0] - nx, base[1] - ny)], closed=True,
                         facecolor=colour, edgecolor="none", alpha=0.9, zorder=2.1))


def _label_spot(points: list[tuple[float, float]]) -> tuple[float, float]:
    """Middle of the longest segment (a band's label)."""
    k = max(range(len(points) - 1), key=lambda i: math.dist(points[i], points[i + 1]))
    (x0, y0), (x1, y1) = points[k], points[k + 1]
    return (x0 + x1) / 2, (y0 + y1) / 2


def plot_power_flow(flow: Any) -> Any:
    from matplotlib.patches import FancyBboxPatch

    plt = pyplot()
    nodes = {n.name: n for n in flow.nodes}
    xs = [n.x for n in flow.nodes]
    ys = [n.y for n in flow.nodes] + [y for e in flow.edges for _, y in e.route]
    x0, x1 = min(xs) - 1.0, max(xs) + 1.0
    y0, y1 = min(ys) - 0.7, max(ys) + 0.7
    fig, ax = plt.subplots(figsize=(max(7.5, (x1 - x0) * INCH), max(4.2, (y1 - y0) * INCH + 1.6)))
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal")
    ax.set_axis_off()
    fig.tight_layout(rect=(0, 0.1, 1, 0.9))
    ppu = ax.transData.transform((1, 0))[0] - ax.transData.transform((0, 0))[0]
    ppu *= 72.0 / fig.dpi  # points per data unit
    # a small graph is drawn enlarged to the least figure size: its bands are not (one factor for all)
    narrow = min(1.0, INCH * 72.0 / ppu)
    ctx = flow.context
    scale = max(e.power for e in flow.edges) if flow.edges else 1.0
    texts: list[Any] = []
    boxes: list[Any] = []
    for edge in flow.edges:
        a, b = nodes[edge.source], nodes[edge.target]
        if edge.kind == "loss":
            top = (a.x, a.y - BOX["element"][1] / 2)
            points = [top, (b.x, b.y + 0.17)]
        else:
            points = list(edge.route)
            points[0] = _clip(points[0], points[1], BOX.get(a.kind, (0.5, 0.5)))
            points[-1] = _clip(points[-1], points[-2], BOX.get(b.kind, (0.5, 0.5)))
        colour = _colour(edge)
        _band(ax, points, max(narrow * edge.width, MIN_WIDTH), colour, ppu)
        if edge.kind != "loss":
            x, y = _label_spot(points)
            texts.append(ax.text(x, y, ctx.text(edge.power, "power", scale), fontsize=7.5, ha="center",
                                 va="center", zorder=6, color="black",
                                 bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": colour, "lw": 0.7}))
    for node in flow.nodes:
        if node.kind == "loss":
            texts.append(ax.text(node.x, node.y, node.label, ha="center", va="center", fontsize=7.5, zorder=7,
                                 bbox={"boxstyle": "round,pad=0.2", "fc": FILL["loss"], "ec": "#8C8C8C"}))
            continue
        w, h = BOX[node.kind]
        boxes.append(ax.add_patch(FancyBboxPatch((node.x - w / 2, node.y - h / 2), w, h,
                                                 boxstyle="round,pad=0,rounding_size=0.1",
                                                 facecolor=FILL[node.kind], edgecolor="black", lw=0.9, zorder=5)))
        ax.text(node.x, node.y, node.label, ha="center", va="center", fontsize=7.5, zorder=7,
                weight="bold" if node.kind in ("source", "sink") else "normal")
    _legend(ax, flow)
    fig.suptitle(_title(flow), fontsize=10.5)
    fit_titles(fig)
    separate(fig, texts, fixed=boxes)
    keep_inside(fig, texts)
    return fig


def _title(flow: Any) -> str:
    heading = flow.context.heading(flow.train, "power flow") if flow.train is not None else flow.title
    # the solver's figures (Solution.circulation): circulating power and the largest element power
    c = flow.circulation
    if c.indeterminate:
        circ = "circulating power not defined (statically indeterminate torque split)"
    elif c.loops and c.ratio is not None:
        circ = f"circulating power {c.ratio:.3g} × input"
    else:
        circ = "no circulating power"
    if c.largest_element_ratio is not None:
        circ += f", largest element power {c.largest_element_ratio:.3g} × input"
    if any(e.circulating for e in flow.edges):
        circ += " — power flows around a closed loop (red)"
    if flow.self_locking:
        circ += " — SELF-LOCKING (formal solution shown)"
    extra = "; ".join(flow.notes)
    return heading + f"\ninput {flow.context.text(flow.input_power, 'power', flow.input_power)}; {circ}" + (
        f"\n{extra}" if extra else "")


def _legend(ax: Any, flow: Any) -> None:
    kinds = {e.kind for e in flow.edges}
    entries = [(k, label) for k, label in (("drive", "power in (drive)"), ("port", "power through a port"),
                                             ("load", "power out (load)"), ("loss", "loss")) if k in kinds]
    for kind, label in entries:
        ax.plot([], [], color=COLOURS[kind], lw=5, label=label)
    if any(e.circulating for e in flow.edges):
        ax.plot([], [], color=COLOURS["loop"], lw=5, label="around a closed loop")
    widest = max((e.power for e in flow.edges), default=0.0)
    ax.plot([], [], " ", label=f"band width ∝ power; widest {flow.context.text(widest, 'power', widest)}")
    ax.legend(fontsize=7.5, loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=3, frameon=False)
