"""Torque bars and power rectangles after Brandenberger 1952, Bild 5, 8 and 9.

Torques are drawn as bars, powers as rectangles whose width is the speed
(1/min) and whose height is the torque (N·m), so that the area is the power
(``P = M·n·π/30`` W).  Power put into an element is hatched vertically, power
taken out horizontally (Brandenberger: "Schraffiert man die Antriebsleistungen
vertikal und die Abtriebsleistungen horizontal").

The loss is its own rectangle, with the heavy outline of Bild 8: with the loss
rule ``M_b' = −i0·η0^w·M_a'`` the torque of the central member that is driven
relative to the carrier is smaller than without friction at the same other
torque.  The loss rectangle has that torque difference as height and the
member's speed *relative to the carrier* as width:

* w = +1 (Bild 8): ``ΔM = M_b' − (−i0·M_a')``, width ``n_b − n_c``;
* w = −1 (Bild 9): ``ΔM = M_a' − (−M_b'/i0)``, width ``n_a − n_c``.

Its area ``|ΔM·Δn|·π/30`` equals the loss, and since only relative speeds
enter it does not move when all speeds change by the same amount
(Brandenberger: "Dieses Rechteck ist unabhängig von der jeweils gewählten
Stelle A").  A fixed-axis stage is the same with the housing as carrier.

References
----------
Brandenberger 1952, eqs. 2, 3', 7 and Bild 5, 8, 9 with Tabellen 1–3.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from ._common import RPM_TO_RAD_S, figure_svg, hatch_legend, hatched_rect, lever_elements, pyplot
from ._labels import clear_suptitle, finish, fit_titles, keep_inside, legends, separate
from .context import FigureContext
from .values import ZERO_RELATIVE, Scales, clean, fmt

if TYPE_CHECKING:  # pragma: no cover
    from ..results.solution import Solution

__all__ = ["PowerRect", "ElementPowers", "PowerDiagram", "power_diagram", "TorqueBar", "TorqueDiagram",
           "torque_diagram"]

#: Powers below this fraction of the largest one count as zero (no hatching): the zero rule.
_ZERO = ZERO_RELATIVE


@dataclass(frozen=True)
class PowerRect:
    """A rectangle of the power diagram: width = speed, height = torque.

    ``x0``/``width`` in 1/min, ``y0``/``height`` in N·m (height ≥ 0, the
    torque's magnitude); ``power`` in W (signed: positive into the element);
    ``role`` one of drive, load, loss, none.
    """

    label: str
    x0: float
    width: float
    y0: float
    height: float
    power: float
    role: str

    @property
    def area(self) -> float:
        """|width·height|·π/30: the power the rectangle stands for, W."""
        return abs(self.width * self.height) * RPM_TO_RAD_S


@dataclass(frozen=True)
class ElementPowers:
    """Power rectangles of one element (set or stage), with its loss rectangle."""

    element: str
    kind: str
    rects: tuple[PowerRect, ...]
    loss_rect: PowerRect | None
    loss: float
    loss_direction: int

    @property
    def drive_power(self) -> float:
        """Σ power put in at the ports, W."""
        return sum(r.power for r in self.rects if r.power > 0)

    @property
    def load_power(self) -> float:
        """Σ power taken out at the ports, W (positive)."""
        return -sum(r.power for r in self.rects if r.power < 0)


@dataclass(frozen=True)
class PowerDiagram:
    """Power rectangles of every geared element, with and without friction.

    ``actual`` comes from the solution, ``ideal`` from ``solution.ideal`` (the
    lossless solution at the same operating point); ``ideal`` is empty when the
    solution has none.
    """

    title: str
    actual: tuple[ElementPowers, ...]
    ideal: tuple[ElementPowers, ...]
    context: FigureContext = field(default_factory=FigureContext)
    resting: tuple[str, ...] = ()
    train: Any = field(default=None, repr=False, compare=False)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data: the power rectangles of every element, with friction and without.

        Rectangles span a speed (x, 1/min) and a torque (y, N·m): their area is a power
        (W); the loss rectangle is the rolling power times (1 − η0^w).

        Returns
        -------
        dict
            ``title``, ``units`` and ``actual``/``ideal``: per element its ``loss_W``,
            ``loss_direction`` (w), ``rects`` and ``loss_rect``.

        References
        ----------
        Brandenberger 1952, Bild 8/9 (powers as areas).
        """
        def one(e: ElementPowers) -> dict[str, Any]:
            return {"element": e.element, "loss_W": e.loss, "loss_direction": e.loss_direction,
                    "rects": [r.__dict__ for r in e.rects],
                    "loss_rect": None if e.loss_rect is None else e.loss_rect.__dict__}

        return {"title": self.title, "units": {"x": "1/min", "y": "N*m", "power": "W"},
                "actual": [one(e) for e in self.actual], "ideal": [one(e) for e in self.ideal]}

    def _repr_html_(self) -> str:
        return figure_svg(self.plot())

    def __repr__(self) -> str:
        losses = ", ".join(f"{e.element} {fmt(e.loss)} W" for e in self.actual)
        return f"<PowerDiagram {self.title!r}: loss rectangles {losses}>"

    def plot(self) -> Any:
        """Figure: one row per element carrying power, left without friction, right with friction."""
        plt = pyplot()
        shown = [k for k, e in enumerate(self.actual) if e.element not in self.resting]
        rows = max(len(shown), 1)
        cols = 2 if self.ideal else 1
        fig, axes = plt.subplots(rows, cols, figsize=(7.6 * cols, 4.4 * rows), squeeze=False)
        ctx = self.context
        texts: list[Any] = []
        for row, k in enumerate(shown):
            element = self.actual[k]
            panels = ([(self.ideal[k], "without friction")] if self.ideal else []) + [(element, "with friction")]
            limits = _limits([p for p, _ in panels])
            for ax, (data, what) in zip(axes[row], panels):
                texts += _draw_powers(ax, data, what, limits, ctx)
        if not shown:
            for ax in axes[0]:
                ax.set_axis_off()
        heading = ctx.heading(self.train, "powers as areas (speed × torque), Brandenberger Bild 8/9") \
            if self.train is not None else self.title
        if self.resting:
            heading += f"\nno power in {', '.join(self.resting)} (idle or locked in this state): not drawn"
        fig.suptitle(heading, fontsize=11)
        finish(fig, texts)
        return fig


def _limits(panels: list[ElementPowers]) -> tuple[float, float, float, float]:
    xs, ys = [0.0], [0.0]
    for p in panels:
        for r in (*p.rects, *((p.loss_rect,) if p.loss_rect else ())):
            xs += [r.x0, r.x0 + r.width]
            ys += [r.y0, r.y0 + r.height]
    dx = (max(xs) - min(xs)) or 1.0
    dy = (max(ys) - min(ys)) or 1.0
    return min(xs) - 0.08 * dx, max(xs) + 0.08 * dx, min(ys) - 0.05 * dy, max(ys) + 0.2 * dy


def _draw_powers(ax: Any, data: ElementPowers, what: str, limits: tuple[float, float, float, float],
                 ctx: FigureContext) -> list[Any]:
    """One panel: rectangles in the figure's units (x speed, y torque), labels in its power unit."""
    seen: list[str] = []
    texts = []
    sx, sy = ctx.convert(1.0, "speed"), ctx.convert(1.0, "torque")
    spacing = ((limits[1] - limits[0]) * sx / 90, (limits[3] - limits[2]) * sy / 45)
    scale = max((abs(r.power) for r in data.rects), default=0.0)
    for rect in (*data.rects, *((data.loss_rect,) if data.loss_rect else ())):
        if rect.role not in seen:
            seen.append(rect.role)
        heavy = rect.role == "loss"
        hatched_rect(ax, sx * rect.x0, sy * rect.y0, sx * rect.width, sy * rect.height, rect.role, spacing=spacing,
                     lw=2.5 if heavy else 1.0, zorder=3 if heavy else 2)
        if abs(rect.width) <= _ZERO * max(1.0, *(abs(r.width) for r in data.rects)):
            continue  # a shaft at rest (the housing, a held member) carries no power: nothing to show
        value = rect.area if rect.role == "loss" else rect.power
        text = f"{rect.label}\n{ctx.text(value, 'power', scale)}"
        above = rect.role == "loss"
        x0, x1 = sorted((rect.x0, rect.x0 + rect.width))
        where = ((x0 + x1) / 2 - limits[0]) / ((limits[1] - limits[0]) or 1.0)
        # near an edge of the panel the label grows inwards from the rectangle's end
        x, ha = (x1, "right") if where > 0.66 else (x0, "left") if where < 0.34 else ((x0 + x1) / 2, "center")
        texts.append(ax.text(sx * x, sy * (rect.y0 + (rect.height if above else rect.height / 2)),
                             text, ha=ha, va="bottom" if above else "center", fontsize=8,
                             bbox={"boxstyle": "round,pad=0.2", "fc": "white", "alpha": 0.85, "lw": 0}))
    ax.set_xlim(sx * limits[0], sx * limits[1])
    ax.set_ylim(sy * limits[2], sy * limits[3])
    ax.axvline(0, color="black", lw=0.8)
    ax.set_xlabel(f"speed n in {ctx.unit('speed')} (rectangle width)")
    ax.set_ylabel(f"|torque| M in {ctx.unit('torque')} (rectangle height)")
    ax.set_title(f"{data.element} ({data.kind}), {what}: loss {ctx.text(data.loss, 'power', scale)}", fontsize=10)
    ax.grid(True, alpha=0.3)
    hatch_legend(ax, seen, fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), title="power at the ports",
                 title_fontsize=8)
    return texts


def _element_powers(solution: Solution, element: Any, ports: tuple[str, str, str], i0: float,
                    scale: float) -> ElementPowers:
    """Rectangles of one element; roles by the zero rule against the train's power ``scale`` (W)."""
    state = solution.elements[element.name]
    rects = []
    y = 0.0
    for port in ports:
        torque, speed = state.torques[port], state.speeds[port]
        power = torque * speed * RPM_TO_RAD_S
        role = "drive" if power > _ZERO * scale else "load" if power < -_ZERO * scale else "none"
        rects.append(PowerRect(f"{port} ({state.ports[port]})", 0.0, speed, y, abs(torque), power, role))
        y += abs(torque)
    a, b, c = ports
    t, n = state.torques, state.speeds
    loss_rect = None
    w = state.loss_direction
    if w != 0 and state.loss > _ZERO * max(scale, 1e-300):
        if w > 0:  # a drives relative to the carrier: b's torque is reduced (Bild 8)
            member, delta = b, t[b] + i0 * t[a]
        else:  # a is driven relative to the carrier: a's torque is reduced (Bild 9)
            member, delta = a, t[a] + t[b] / i0
        width = n[member] - n[c]
        loss_rect = PowerRect(f"loss: ΔM_{member} × (n_{member} − n_{c})", n[c], width, y + 0.06 * max(y, 1e-12),
                              abs(delta), delta * width * RPM_TO_RAD_S, "loss")
    return ElementPowers(element.name, state.kind, tuple(rects), loss_rect, state.loss, w)


def power_diagram(solution: Solution, *, context: FigureContext | None = None) -> PowerDiagram:
    """Power rectangles of every planetary set and gear stage, with and without friction.

    Elements that carry no power by the zero rule (idle or locked in this
    shift state) are listed in ``resting`` and not drawn.

    Parameters
    ----------
    solution : Solution
    context : FigureContext, optional
        Title, gear, units and notes of the figure.

    Returns
    -------
    PowerDiagram

    References
    ----------
    Brandenberger 1952, Bild 8 and 9 (loss as the heavy rectangle).

    Examples
    --------
    >>> from epicyclic.demo import brandenberger_1952
    >>> from epicyclic import solve
    >>> sol = solve(*brandenberger_1952())
    >>> d = power_diagram(sol)
    >>> round(sum(e.loss_rect.area for e in d.actual), 3) == round(sol.loss, 3)
    True
    """
    levers = lever_elements(solution.train)
    scale = Scales.of(solution).power
    actual = tuple(_element_powers(solution, e, ports, i0, scale) for e, ports, _, i0 in levers)
    ideal: tuple[ElementPowers, ...] = ()
    if solution.ideal is not None:
        ideal = tuple(_element_powers(solution.ideal, e, ports, i0, scale) for e, ports, _, i0 in levers)
    resting = tuple(e.element for e in actual
                    if all(clean(r.power, scale) == 0 for r in e.rects) and clean(e.loss, scale) == 0)
    context = context or FigureContext(title=solution.train.name)
    return PowerDiagram(context.title or solution.train.name, actual, ideal, context, resting, solution.train)


@dataclass(frozen=True)
class TorqueBar:
    """One bar pair: the torque without and with friction (N·m) at a port or shaft."""

    group: str
    label: str
    ideal: float | None
    actual: float
    role: str


@dataclass(frozen=True)
class TorqueDiagram:
    """Torque bars of the external shafts and of every geared element's ports.

    Groups: ``"external"`` (torques acting on the train from outside) and one
    group per element (torques on the element at each port; they sum to zero,
    Brandenberger eq. 2).
    """

    title: str
    bars: tuple[TorqueBar, ...]
    context: FigureContext = field(default_factory=FigureContext)
    resting: tuple[str, ...] = ()
    train: Any = field(default=None, repr=False, compare=False)

    @property
    def groups(self) -> tuple[str, ...]:
        out: list[str] = []
        for bar in self.bars:
            if bar.group not in out:
                out.append(bar.group)
        return tuple(out)

    def group(self, name: str) -> tuple[TorqueBar, ...]:
        """The bars of one group: ``"external"`` (external shafts) or an element's name (its ports).

        Parameters
        ----------
        name : str
            The group.

        Returns
        -------
        tuple of TorqueBar
            Empty for an unknown group or a resting element.
        """
        return tuple(b for b in self.bars if b.group == name)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data: every torque bar with and without friction (N·m).

        Returns
        -------
        dict
            ``title``, ``unit`` (``"N*m"``) and ``bars``: group, label, ideal and actual
            torque, role of each.
        """
        return {"title": self.title, "unit": "N*m", "bars": [b.__dict__ for b in self.bars]}

    def _repr_html_(self) -> str:
        return figure_svg(self.plot())

    def __repr__(self) -> str:
        return f"<TorqueDiagram {self.title!r}: {len(self.bars)} bars in {len(self.groups)} groups>"

    def plot(self) -> Any:
        """Figure: one panel per group, bars without friction (outline) and with friction (hatched)."""
        plt = pyplot()
        ctx = self.context
        k = ctx.convert(1.0, "torque")
        groups = self.groups
        fig, axes = plt.subplots(1, len(groups), figsize=(4.6 * len(groups), 4.8), squeeze=False)
        roles: dict[str, None] = {}
        texts: list[Any] = []
        for ax, name in zip(axes[0], groups):
            bars = self.group(name)
            xs = range(len(bars))
            if any(b.ideal is not None for b in bars):
                ax.bar([x - 0.2 for x in xs], [k * (b.ideal or 0.0) for b in bars], width=0.38, facecolor="white",
                       edgecolor="grey", ls="--", lw=1.5, label="without friction")
            values = [0.0, *(k * b.actual for b in bars), *(k * (b.ideal or 0.0) for b in bars)]
            spacing = (0.38 / 5, (max(values) - min(values)) / 40)
            for x, bar in zip(xs, bars):
                roles.setdefault(bar.role, None)
                hatched_rect(ax, x + 0.01, 0.0, 0.38, k * bar.actual, bar.role, spacing=spacing)
                texts.append(ax.annotate(fmt(k * bar.actual), (x + 0.2, k * bar.actual), ha="center", fontsize=8,
                                         xytext=(0, 3 if bar.actual >= 0 else -11), textcoords="offset points"))
            ax.axhline(0, color="black", lw=0.8)
            ax.set_xticks(list(xs), [b.label for b in bars], fontsize=9)
            ax.set_ylabel(f"torque M in {ctx.unit('torque')}")
            ax.set_title("external torques on shafts" if name == "external" else f"torques on {name}", fontsize=10)
            ax.grid(True, axis="y", alpha=0.3)
            ax.margins(y=0.15)
        heading = ctx.heading(self.train, "torques with and without friction (housing: reaction)") \
            if self.train is not None else self.title
        if self.resting:
            heading += f"\nno torque on {', '.join(self.resting)} (idle in this state): not drawn"
        fig.suptitle(heading, fontsize=11)
        fig.tight_layout(rect=(0, 0.1, 1, 1))
        legend_ax = fig.add_axes((0.0, 0.0, 1.0, 0.08))
        legend_ax.set_axis_off()
        legend_ax.plot([], [], color="grey", ls="--", lw=1.5, label="without friction (outline)")
        hatch_legend(legend_ax, list(roles), loc="center", ncol=1 + len(roles), fontsize=9,
                     title="hatched bars: with friction", title_fontsize=9)
        fit_titles(fig)
        clear_suptitle(fig)
        separate(fig, texts, fixed=legends(fig))
        keep_inside(fig, texts)
        return fig


def _role(power: float, scale: float) -> str:
    return "drive" if power > _ZERO * scale else "load" if power < -_ZERO * scale else "none"


def torque_diagram(solution: Solution, *, context: FigureContext | None = None) -> TorqueDiagram:
    """Torque bars, with and without friction, of the external shafts and element ports.

    Values are cleaned by the zero rule against the train's torque scale;
    elements without any torque (idle in this shift state) are listed in
    ``resting`` and get no panel.

    Parameters
    ----------
    solution : Solution
        A solved train (its ``ideal`` gives the bars without friction).
    context : FigureContext, optional
        Title, units, gear and notes (default: the train's name, N·m).

    Returns
    -------
    TorqueDiagram
        Plot it with ``.plot()``.

    References
    ----------
    Brandenberger 1952, eq. 2 and Bild 3, 8, 9 (M1' + M2' + M3' = 0).

    Examples
    --------
    >>> from epicyclic.demo import brandenberger_1952, KP_CM
    >>> from epicyclic import solve
    >>> d = torque_diagram(solve(*brandenberger_1952()))
    >>> [round(abs(b.actual) / KP_CM, 1) for b in d.group("planetary")]  # Brandenberger: 66.7, 40.3, 26.4 cm·kg
    [66.6, 40.3, 26.3]
    """
    ideal = solution.ideal
    scales = Scales.of(solution)
    scale, torque = scales.power, scales.torque
    bars = []

    def ideal_of(value: float | None) -> float | None:
        return None if value is None else clean(value, torque)

    for shaft in solution.shafts.values():
        value = clean(shaft.torque, torque)
        if shaft.role == "internal" or value == 0.0:
            continue
        ideal_torque = ideal_of(ideal.torque(shaft.name) if ideal is not None else None)
        bars.append(TorqueBar("external", shaft.name, ideal_torque, value, _role(shaft.power, scale)))
    resting = []
    for element, ports, _, _ in lever_elements(solution.train):
        state = solution.elements[element.name]
        powers = state.port_powers
        group = []
        for port in ports:
            ideal_torque = ideal_of(ideal.elements[element.name].torques[port] if ideal is not None else None)
            group.append(TorqueBar(element.name, f"{port}\n({state.ports[port]})", ideal_torque,
                                   clean(state.torques[port], torque), _role(powers[port], scale)))
        if all(b.actual == 0.0 and not b.ideal for b in group):
            resting.append(element.name)
        else:
            bars += group
    context = context or FigureContext(title=solution.train.name)
    return TorqueDiagram(context.title or solution.train.name, tuple(bars), context, tuple(resting), solution.train)
