"""Brandenberger's speed diagram of a set: parallel 45° lines, ranges 1–7, the operating point.

Brandenberger's speed diagram (Bild 3 and 4): at ``x = 0`` the speeds of the
central members with the carrier held, ``n1' = n1 − n3`` and
``n2' = n2 − n3``, are marked, and parallel 45° lines drawn through ``0``,
``n1'`` and ``n2'``.  A vertical line at ``x`` cuts them at three speeds that
belong together (all shafts given the extra turn ``x``); the actual operating
point is ``x = n3``.  The three points where a line crosses zero (one shaft
stands still: cases 2, 4, 6) split the axis into the four ranges 1, 3, 5, 7,
numbered from the right.  Brandenberger orients the diagram so that the
faster central member with the carrier held (his system II) turns
positively; where that member turns negatively here, the figure shows the
true speeds with both axes reversed (said on the axes), which gives the
same picture.

References
----------
Brandenberger 1952, eq. 1 and Bild 3–5 (text: "je vier verschiedene Bereiche
1, 3, 5, 7 … neben drei Einzelfällen 2, 4, 6").
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

from ._common import SHAFT_COLOURS, figure_svg, member_name, planetary_set, pyplot
from .context import FigureContext

if TYPE_CHECKING:  # pragma: no cover
    from ..results.solution import Solution

__all__ = ["RangeDiagram", "range_diagram"]


@dataclass(frozen=True)
class RangeDiagram:
    """Brandenberger's speed diagram of one set (Bild 3/4) with the operating point.

    Attributes
    ----------
    labels : tuple of str
        ("I", "II", "III") mapped to ports in ``ports``: II is the central
        member that is faster with the carrier held.
    ports : tuple of str
        Ports (sun/ring) of I and II, then "carrier".
    shafts : tuple of str
    offsets : tuple of float
        n1', n2', 0 in 1/min, after the sign scaling.
    sign : float
        +1 or −1: the factor applied to all speeds.
    x_operating : float
        sign·n3, the position of the operating point.
    zero_points : tuple of float
        x where each line crosses zero (cases 2, 4, 6 from the right).
    operating_range : int or None
        1…7 (None for a set without relative motion).

    References
    ----------
    Brandenberger 1952, eq. 1 and Bild 3–5.
    """

    set_name: str
    labels: tuple[str, str, str]
    ports: tuple[str, str, str]
    shafts: tuple[str, str, str]
    offsets: tuple[float, float, float]
    sign: float
    x_operating: float
    zero_points: tuple[float, float, float]
    operating_range: int | None
    context: FigureContext = field(default_factory=FigureContext)
    names: tuple[str, str, str] | None = None  # the ports as the set's file names them (first/second)

    def speeds_at(self, x: float) -> tuple[float, float, float]:
        """Scaled speeds of I, II, III at position x (the three lines)."""
        return tuple(o + x for o in self.offsets)  # type: ignore[return-value]

    def range_of(self, x: float) -> int:
        """The range number 1…7 of position x (2, 4, 6: a shaft stands still)."""
        p = self.zero_points
        tol = 1e-9 * max(1.0, *(abs(v) for v in p))
        for k, point in enumerate(p):
            if abs(x - point) <= tol:
                return 2 * k + 2
        return 1 + 2 * sum(x < point for point in p)

    def graphical_torques(self) -> tuple[float, float, float]:
        """Torque magnitudes of I, II, III read from the diagram (Bild 3), up to one factor.

        "Ein Drehmoment entspricht der Grösse nach dem Abstand der Geraden, durch
        welche die Drehzahlen der beiden anderen Systeme graphisch dargestellt
        werden": |M1| ∝ |n2' − 0|, |M2| ∝ |n1' − 0|, |M3| ∝ |n1' − n2'| (frictionless).
        """
        n1, n2, n3 = self.offsets
        return abs(n2 - n3), abs(n1 - n3), abs(n1 - n2)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data of the range diagram (speeds in 1/min after the sign scaling).

        Returns
        -------
        dict
            ``set``, ``labels`` (I, II, III), ``ports``, ``shafts``, ``offsets``, ``sign``,
            ``x_operating``, ``zero_points`` and ``operating_range`` (1…7 or ``None``).

        References
        ----------
        Brandenberger 1952, Bild 3–5 (the seven ranges).
        """
        return {"set": self.set_name, "labels": self.labels, "ports": self.ports, "shafts": self.shafts,
                "offsets": self.offsets, "sign": self.sign, "x_operating": self.x_operating,
                "zero_points": self.zero_points, "operating_range": self.operating_range}

    def _repr_html_(self) -> str:
        return figure_svg(self.plot().figure)

    def __repr__(self) -> str:
        return f"<RangeDiagram {self.set_name!r}: operating point in range {self.operating_range}>"

    def plot(self, ax: Any = None) -> Any:
        """Draw the parallel 45° lines, the ranges and the operating point (true speeds, file units)."""
        plt = pyplot()
        if ax is None:
            _, ax = plt.subplots(figsize=(6, 5))
        ctx = self.context
        k = self.sign * ctx.convert(1.0, "speed")  # diagram coordinate → true speed in the figure's unit
        p = self.zero_points
        span = max(abs(self.x_operating), *(abs(v) for v in p), 1.0)
        lo, hi = min(min(p), self.x_operating) - 0.35 * span, max(max(p), self.x_operating, 0.0) + 0.35 * span
        for j in range(3):
            ax.plot([k * lo, k * hi], [k * (self.offsets[j] + lo), k * (self.offsets[j] + hi)], color=SHAFT_COLOURS[j],
                    lw=2, label=f"{self.labels[j]} = {(self.names or self.ports)[j]} ({self.shafts[j]})")
            ax.plot([0], [k * self.offsets[j]], "o", color=SHAFT_COLOURS[j], mec="black")
        edges = [hi, *p, lo]
        for j, point in enumerate(p):
            ax.axvline(k * point, color="grey", lw=0.8, ls=":")
            ax.annotate(str(2 * j + 2), (k * point, 0), textcoords="offset points", xytext=(3, 4), fontsize=9,
                        color="grey")
        for j in range(4):
            mid = 0.5 * (edges[j] + edges[j + 1])
            ax.text(k * mid, 0.05, str(2 * j + 1), transform=ax.get_xaxis_transform(), ha="center", fontsize=12,
                    color="grey", weight="bold")
        # Bild 3: a torque is the distance between the lines of the other two shafts (at x = 0)
        tq = self.graphical_torques()
        total = sum(tq) or 1.0
        ax.plot([], [], " ", label="torques ∝ distance of the other two lines:\n"
                + " : ".join(f"M{lab} {t / total:.3f}" for lab, t in zip(self.labels, tq)))
        locked = self.operating_range is None  # no relative motion: all three shafts at the carrier's speed
        ys = [k * y for y in ((self.x_operating,) * 3 if locked else self.speeds_at(self.x_operating))]
        x_op = k * self.x_operating
        ax.plot([x_op] * 2, [min(*ys, 0), max(*ys, 0)], color="black", lw=2.5,
                label=f"operating point (range {self.operating_range})" if self.operating_range else
                "operating point (set locked: no range)")
        for j, y in enumerate(ys):
            ax.plot([x_op], [y], "s", color=SHAFT_COLOURS[j], mec="black", ms=8, zorder=5)
        ax.axhline(0, color="black", lw=0.8)
        unit = ctx.unit("speed")
        reversed_ = ", axis reversed (II turns negatively)" if self.sign < 0 else ""
        ax.set_xlabel(f"carrier speed n_III in {unit} (extra turn of all shafts){reversed_}")
        ax.set_ylabel(f"shaft speed n in {unit}{reversed_}")
        if self.sign < 0:
            ax.invert_xaxis()
            ax.invert_yaxis()
        ax.set_title(f"Speed ranges 1–7 of set {self.set_name!r} (Brandenberger Bild 3/4)", fontsize=10)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8, loc="upper left")
        return ax


def range_diagram(solution: Solution, element: str | None = None, *,
                  context: FigureContext | None = None) -> RangeDiagram:
    """Brandenberger's speed diagram (ranges 1–7) of a set at the solved point.

    Parameters
    ----------
    solution : Solution
    element : str, optional
        Name of the planetary set (default: the first).
    context : FigureContext, optional
        Units of the figure.

    Returns
    -------
    RangeDiagram

    References
    ----------
    Brandenberger 1952, eq. 1 and Bild 3–5.

    Examples
    --------
    >>> from epicyclic.demo import brandenberger_1952
    >>> from epicyclic import solve
    >>> range_diagram(solve(*brandenberger_1952())).operating_range  # Brandenberger: "Bereich 7"
    7
    """
    pset = planetary_set(solution, element)
    state = solution.elements[pset.name]
    n = state.speeds
    rel = {"sun": n["sun"] - n["carrier"], "ring": n["ring"] - n["carrier"]}
    i0 = pset.stationary_ratio
    if max(abs(v) for v in rel.values()) <= 1e-12 * max(1.0, *(abs(v) for v in n.values())):
        rel = {"sun": 1000.0 * i0, "ring": 1000.0}  # locked set: only the shape of the diagram
        locked = True
    else:
        locked = False
    first, second = ("sun", "ring") if abs(rel["ring"]) >= abs(rel["sun"]) else ("ring", "sun")
    sign = 1.0 if rel[second] > 0 else -1.0
    offsets = (sign * rel[first], sign * rel[second], 0.0)
    zero = tuple(sorted((-o for o in offsets), reverse=True))
    x_op = sign * n["carrier"]
    ports = (first, second, "carrier")
    diagram = RangeDiagram(pset.name, ("I", "II", "III"), ports, tuple(state.ports[p] for p in ports),  # type: ignore[arg-type]
                           offsets, sign, x_op, zero, None, context or FigureContext(),  # type: ignore[arg-type]
                           tuple(member_name(pset, p) for p in ports))  # type: ignore[arg-type]
    if locked:
        return diagram
    return replace(diagram, operating_range=diagram.range_of(x_op))


