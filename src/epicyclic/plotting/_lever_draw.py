"""Drawing of :class:`~epicyclic.plotting.lever.LeverDiagram` (Benford–Leising style).

Left panel: the levers of the free state side by side, every shaft a node at
its height; shafts that meet no set or stage (the input of a Simpson or
Ravigneaux train) are vertical rails on the left; clutches are drawn as a
connector with the clutch sign ``||`` between the two nodes they join, brakes
as a ground sign beside their node; engaged ones red and bold, open ones grey.
The input and the output are named at their nodes.

The diagram is taken duck-typed: this module does not import :mod:`.lever`
(that one imports this lazily), so the two are no import cycle.

Right: the speeds over the lever.  For a transmission whose free state is one
compound lever, one line per gear (speed per input speed), the shown gear
bold with its values; otherwise the state's reduced lever (or each free
lever) with the solved speeds as arrows from the lever, their tips on one
straight line, in the figure's speed unit.
"""

from __future__ import annotations

from typing import Any

from ..model.elements import HOUSING
from ._common import SHAFT_COLOURS, pyplot
from ._labels import finish
from .values import clean, fmt, scale_of

__all__ = ["plot_lever_diagram"]

ENGAGED = "#C0392B"
#: White box behind labels, so that a label stays readable over a line.
BOX = {"boxstyle": "round,pad=0.12", "fc": "white", "ec": "none", "alpha": 0.85}
OPEN = "#8C8C8C"


def _colours(diagram: Any) -> dict[str, str]:
    shafts = [s for s in diagram.train.shafts if s != HOUSING] if diagram.train is not None else []
    colours = {s: SHAFT_COLOURS[k % len(SHAFT_COLOURS)] for k, s in enumerate(shafts)}
    colours[HOUSING] = "#555555"
    return colours


def _role(diagram: Any, shaft: str) -> str:
    return diagram.role(shaft)


def plot_lever_diagram(diagram: Any) -> Any:
    plt = pyplot()
    speed_levers = [] if diagram.gear_lines else [c for c in diagram.speed_levers if c.speeds is not None]
    panels = 1 + (1 if diagram.gear_lines else len(speed_levers))
    ratios = [max(1.3, 0.6 * (len(diagram.free) + len(_rails(diagram))) + 0.4)] + [1.25] * (panels - 1)
    fig, axes = plt.subplots(1, panels, figsize=(3.4 * sum(ratios) + 1.5, 6.0), squeeze=False,
                             gridspec_kw={"width_ratios": ratios})
    axes = list(axes[0])
    texts: list[Any] = []
    colours = _colours(diagram)
    _draw_free(axes[0], diagram, colours, texts)
    if diagram.gear_lines:
        _draw_gear_lines(axes[1], diagram, colours, texts)
    else:
        for ax, lever in zip(axes[1:], speed_levers):
            _draw_speeds(ax, diagram, lever, colours, texts)
    fig.suptitle(diagram.context.heading(diagram.train, "lever diagram (Benford–Leising 1981)"), fontsize=11)
    finish(fig, texts)
    return fig


# ---------------------------------------------------------------------- left: the levers
def _rails(diagram: Any) -> list[str]:
    """Shafts on no lever that a clutch joins to one (drawn as rails, left of the levers)."""
    on_levers = {s for c in diagram.free for s in c.positions}
    rails: list[str] = []
    for _, kind, shafts, _ in diagram.shift_elements:
        if kind == "clutch":
            for s in shafts:
                if s not in on_levers and s not in rails:
                    rails.append(s)
    return rails


#: Horizontal distance between two levers in the left panel (data units; heights span 0…1).
SPACING = 1.6


def _spots(diagram: Any) -> dict[str, list[tuple[float, float]]]:
    """Where each shaft appears in the left panel: (x, y) per lever it is on."""
    spots: dict[str, list[tuple[float, float]]] = {}
    for k, lever in enumerate(diagram.free):
        for shaft, y in lever.positions.items():
            spots.setdefault(shaft, []).append((SPACING * k, y))
    return spots


def _clutch_ends(spots: dict[str, list[tuple[float, float]]], rail_x: dict[str, float], a: str, b: str
                 ) -> tuple[tuple[float, float], tuple[float, float]]:
    """The two places a clutch joins: nearest pair on different levers (a rail meets the other end's height)."""
    def places(s: str, other: str) -> list[tuple[float, float | None]]:
        return list(spots[s]) if s in spots else [(rail_x[s], None)]

    pairs = [(p, q) for p in places(a, b) for q in places(b, a)]
    apart = [pq for pq in pairs if abs(pq[0][0] - pq[1][0]) > 1e-9] or pairs
    (x0, y0), (x1, y1) = min(apart, key=lambda pq: abs(pq[0][0] - pq[1][0]) + abs((pq[0][1] or 0) - (pq[1][1] or 0))
                             if None not in (pq[0][1], pq[1][1]) else abs(pq[0][0] - pq[1][0]))
    y0 = y1 if y0 is None else y0
    y1 = y0 if y1 is None else y1
    return (x0, y0), (x1, y1)  # type: ignore[return-value]


def _clutch_sign(ax: Any, x: float, y: float, vertical: bool, colour: str, lw: float) -> None:
    """The clutch sign: two short bars across the connector."""
    for d in (-0.045, 0.045):
        if vertical:
            ax.plot([x - 0.08, x + 0.08], [y + d / 2, y + d / 2], color=colour, lw=lw + 0.6, zorder=3)
        else:
            ax.plot([x + d, x + d], [y - 0.035, y + 0.035], color=colour, lw=lw + 0.6, zorder=3)


def _draw_free(ax: Any, diagram: Any, colours: dict[str, str], texts: list[Any]) -> None:
    spots = _spots(diagram)
    rails = _rails(diagram)
    rail_x = {s: -SPACING * (k + 1) for k, s in enumerate(rails)}
    rail_ys: dict[str, list[float]] = {s: [] for s in rails}
    legend: dict[str, tuple[str, float, str]] = {}
    bracket = clutches = 0
    for name, kind, (a, b), engaged in diagram.shift_elements:
        colour, lw = (ENGAGED, 2.4) if engaged else (OPEN, 1.2)
        state = "engaged" if engaged else "open"
        weight = "bold" if engaged else "normal"
        if kind == "brake":
            if a not in spots:
                continue
            x, y = spots[a][0]
            g = x + 0.42
            ax.plot([x, g], [y, y], color=colour, lw=lw, zorder=3)
            ax.plot([g, g], [y - 0.035, y + 0.035], color=colour, lw=lw, zorder=3)
            for d in (-0.03, 0.0, 0.03):  # the ground hatching
                ax.plot([g, g + 0.06], [y + d, y + d - 0.02], color=colour, lw=0.8, zorder=3)
            texts.append(ax.annotate(name, (g + 0.06, y), xytext=(3, 0), textcoords="offset points", va="center",
                                     fontsize=8, color=colour, weight=weight, bbox=BOX))
            legend.setdefault(f"brake {state}", (colour, lw, "-"))
            continue
        (x0, y0), (x1, y1) = _clutch_ends(spots, rail_x, a, b)
        for s, (x, y) in ((a, (x0, y0)), (b, (x1, y1))):
            if s in rail_ys:
                rail_ys[s].append(y)
        if abs(x0 - x1) < 1e-9:  # both ends on one lever: a bracket left of it
            bracket += 1
            bx = x0 - 0.25 * bracket
            ax.plot([x0, bx, bx, x1], [y0, y0, y1, y1], color=colour, lw=lw, zorder=2)
            mx, my, vertical = bx, (y0 + y1) / 2, True
            offset, ha = (-6, 0), "right"
        else:
            ax.plot([x0, x1], [y0, y1], color=colour, lw=lw, zorder=2, solid_capstyle="butt")
            t = (0.5, 0.32, 0.68)[clutches % 3]  # signs of crossing connectors apart
            clutches += 1
            mx, my, vertical = x0 + t * (x1 - x0), y0 + t * (y1 - y0), False
            offset, ha = (0, 11), "center"
        _clutch_sign(ax, mx, my, vertical, colour, lw)
        texts.append(ax.annotate(name, (mx, my), xytext=offset, textcoords="offset points", ha=ha, va="center",
                                 fontsize=8, color=colour, weight=weight, bbox=BOX))
        legend.setdefault(f"clutch {state}", (colour, lw, "-"))
    for shaft in rails:
        ys = rail_ys[shaft] or [0.5]
        x = rail_x[shaft]
        ax.plot([x, x], [min(ys) - 0.04, max(ys) + 0.04], color=colours.get(shaft, "black"), lw=3,
                solid_capstyle="round", zorder=4)
        texts.append(ax.annotate(shaft + _role(diagram, shaft), (x, max(ys) + 0.04), xytext=(0, 5),
                                 textcoords="offset points", ha="center", fontsize=8, weight="bold"))
    failing = diagram.context.warnings  # elements with a mesh below its minimum safety: drawn red
    for k, lever in enumerate(diagram.free):
        x = SPACING * k
        ys = list(lever.positions.values())
        red = any(e in failing for e in lever.elements)
        ax.plot([x, x], [min(ys), max(ys)], color=UNSAFE if red else "black", lw=3.5, solid_capstyle="round",
                zorder=4)
        for y, shafts in lever.groups():
            colour = colours.get(shafts[0], "black")
            ax.plot([x], [y], "o", ms=8, color=colour, mec="black", zorder=6)
            text = " = ".join(s + _role(diagram, s) for s in shafts)
            marked = any(_role(diagram, s) for s in shafts)
            texts.append(ax.annotate(text, (x, y), xytext=(7, 4), textcoords="offset points", va="bottom",
                                     fontsize=8, weight="bold" if marked else "normal", bbox=BOX))
        label = "\n".join(_element_label(diagram, e) + (f"\nbelow minimum safety:\n{failing[e]}" if e in failing else "")
                          for e in lever.elements)
        texts.append(ax.annotate(label, (x, 0.0), xytext=(0, -16), textcoords="offset points", ha="center",
                                 va="top", fontsize=8, color=UNSAFE if red else "black",
                                 weight="bold" if red else "normal"))
    for shaft, places in spots.items():
        if shaft == HOUSING:
            continue
        for (x0, y0), (x1, y1) in zip(places, places[1:]):
            ax.plot([x0, x1], [y0, y1], color=colours.get(shaft, "grey"), lw=1.3, ls="--", zorder=1)
    for label, (colour, lw, ls) in legend.items():
        ax.plot([], [], color=colour, lw=lw, ls=ls, label=label)
    if any(len(p) > 1 for s, p in spots.items() if s != HOUSING):
        ax.plot([], [], color="grey", lw=1.3, ls="--", label="same shaft")
    left = min([*rail_x.values(), -0.25 * bracket, 0.0]) - 0.8
    ax.set_xlim(left, SPACING * (len(diagram.free) - 1) + 1.2)
    extra = max((sum(failing[e].count("\n") + 2 for e in lever.elements if e in failing)
                 for lever in diagram.free), default=0)  # lines a below-minimum note adds under its lever
    ax.set_ylim(-0.22 - 0.06 * extra, 1.1)  # room under the nodes for the names, clear of markers and frame
    ax.set_yticks([0.0, 0.2, 0.4, 0.6, 0.8, 1.0])
    ax.set_xticks([])
    ax.set_ylabel("node height on the lever (from the ratios)")
    ax.set_title("levers of the train, clutches and brakes", fontsize=10)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=3, frameon=False)
    ax.grid(True, axis="y", alpha=0.25)


#: The colour of an element below its minimum safety (as the rating's HTML tables mark it).
UNSAFE = "#C0392B"


def _element_label(diagram: Any, name: str) -> str:
    lever = next(lv for lv in diagram.levers if lv.element == name)
    what = "i0" if lever.kind == "planetary set" else "ratio"
    return f"{name}: {what} {fmt(lever.ratio, 4)}"


# ---------------------------------------------------------------------- right: speeds
def _lever_bar(ax: Any, lever: Any, colours: dict[str, str]) -> None:
    ys = list(lever.positions.values())
    ax.plot([0, 0], [min(ys), max(ys)], color="black", lw=3.5, solid_capstyle="round", zorder=4)
    for y, shafts in lever.groups():
        ax.plot([0], [y], "o", ms=7, color=colours.get(shafts[0], "black"), mec="black", zorder=6)


def _draw_speeds(ax: Any, diagram: Any, lever: Any, colours: dict[str, str],
                 texts: list[Any]) -> None:
    ctx = diagram.context
    assert lever.speeds is not None
    scale = scale_of(lever.speeds.values())
    speed = {s: ctx.convert(clean(n, scale), "speed") for s, n in lever.speeds.items()}
    _lever_bar(ax, lever, colours)
    ys = [y for y, _ in lever.groups()]
    alpha, beta = lever.with_speeds(speed).speed_line()
    ax.plot([alpha + beta * min(ys), alpha + beta * max(ys)], [min(ys), max(ys)], color="#444444", lw=1.4,
            zorder=3, label="speeds: one straight line")
    for y, shafts in lever.groups():
        n = speed[shafts[0]]
        colour = colours.get(shafts[0], "black")
        if n:
            ax.annotate("", (n, y), (0, y), arrowprops={"arrowstyle": "-|>", "color": colour, "lw": 1.6,
                                                        "shrinkA": 0, "shrinkB": 0}, zorder=5)
        ax.plot([n], [y], "o", color=colour, mec="black", ms=6, zorder=6)
        name = " = ".join(s + _role(diagram, s) for s in shafts)
        right = n >= 0
        texts.append(ax.annotate(f"{name}: {fmt(n, 5)} {ctx.unit('speed')}", (n, y), xytext=(7 if right else -7, 0),
                                 textcoords="offset points", va="center", ha="left" if right else "right",
                                 fontsize=8))
    xs = [0.0, *speed.values()]
    span = (max(xs) - min(xs)) or 1.0
    ax.set_xlim(min(xs) - 0.75 * span, max(xs) + 0.75 * span)
    ax.set_ylim(-0.08, 1.08)
    ax.axvline(0, color="black", lw=0.6)
    ax.set_xlabel(f"speed n in {ctx.unit('speed')}")
    members = " + ".join(lever.elements) if diagram.compound is None else "reduced lever of this state"
    ax.set_title(f"speeds across the lever ({members})", fontsize=10)
    ax.set_yticks([])
    ax.grid(True, axis="x", alpha=0.25)


def _draw_gear_lines(ax: Any, diagram: Any, colours: dict[str, str], texts: list[Any]) -> None:
    lever = diagram.permanent
    assert lever is not None
    _lever_bar(ax, lever, colours)
    ys = [y for y, _ in lever.groups()]
    lo, hi = min(ys), max(ys)
    xs = [0.0, 1.0]
    for k, (gear, speeds) in enumerate(diagram.gear_lines.items()):
        values = {s: clean(speeds[s], scale_of(speeds.values())) for s in lever.positions}
        fit = lever.with_speeds(values)
        alpha, beta = fit.speed_line()
        bold = gear == diagram.gear
        colour = SHAFT_COLOURS[k % len(SHAFT_COLOURS)]
        ax.plot([alpha + beta * lo, alpha + beta * hi], [lo, hi], color=colour, lw=2.6 if bold else 1.2,
                alpha=1.0 if bold else 0.8, zorder=5 if bold else 3)
        top = alpha + beta * hi
        texts.append(ax.annotate(f"gear {gear}", (top, hi), xytext=(0, 6), textcoords="offset points", ha="center",
                                 fontsize=8, color=colour, weight="bold" if bold else "normal"))
        xs += list(values.values())
        if bold:
            for y, shafts in lever.groups():
                n = values[shafts[0]]
                ax.plot([n], [y], "o", color=colour, mec="black", ms=6, zorder=6)
                texts.append(ax.annotate(fmt(n, 4), (n, y), xytext=(6, -3), textcoords="offset points",
                                         fontsize=8, va="top", color=colour))
    for y, shafts in lever.groups():
        texts.append(ax.annotate(" = ".join(s + _role(diagram, s) for s in shafts), (min(xs), y), xytext=(-6, 0),
                                 textcoords="offset points", ha="right", va="center", fontsize=8))
    span = (max(xs) - min(xs)) or 1.0
    ax.set_xlim(min(xs) - 0.1 * span, max(xs) + 0.1 * span)
    ax.set_ylim(-0.08, 1.12)
    ax.axvline(0, color="black", lw=0.6)
    ax.axvline(1, color="grey", lw=0.6, ls=":")
    ax.set_xlabel("speed per input speed n / n_in")
    ax.set_yticks([])
    ax.set_title("every gear's speed line over the compound lever", fontsize=10)
    ax.grid(True, axis="x", alpha=0.25)
