"""Circulating power (Blindleistung): power that flows around a closed loop of the train.

Brandenberger (1952, text to Bild 11 and 12): where two members of a set are
joined by a further gear stage, power can flow around the closed loop
set → shaft → stage → shaft → set, "Leistungen, die gegen aussen im An- und
Abtrieb nicht zur Geltung kommen"; Müller (Die Umlaufgetriebe, 1998) calls it
Blindleistung.  Such power loads the teeth and bearings of the loop beyond the
input power without reaching the output.

The power flow of a solution is a network: shafts and elements are nodes,
every element port with speed and torque is an edge carrying |T·ω| in the
direction the power flows; drives feed it, loads and losses drain it.  A
loop where power circulates is a directed cycle of this network.  The
circulating power is the flow that goes all the way round: cycles are taken
out one at a time, the one with the largest bottleneck (its smallest edge)
first, until no directed cycle is left; what remains flows from the drives
to the loads and losses without returning.  Each loop is reported with the
power around it, and with that power as a multiple of the input power.

With a loop of one set and one stage (Bild 11 and 12) the loop's power is
the power that the stage hands back to the shaft where it joins the input
power, so the set's port there carries input + circulating power.

A statically indeterminate train (e.g. two sets locked as blocks, whose
torque split between parallel paths the rigid-body equations leave open)
has no defined circulating power, and its largest element power is not
defined either: :class:`Circulation` then says so instead of giving numbers
from an arbitrary split.

References
----------
Brandenberger 1952, text to Bild 11 and 12; Müller 1998, Die Umlaufgetriebe
(Blindleistung in Koppelgetrieben); Ahuja, Magnanti & Orlin 1993, Network
Flows, §3.5 (flow decomposition into paths and cycles).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

__all__ = ["PowerLoop", "Circulation", "circulation", "indeterminate_circulation", "CIRCULATION_FLOOR",
           "CIRCULATION_THRESHOLD"]

#: Loops carrying less than this fraction of the largest element power are not reported: the zero
#: rule (1e-12 of the neighbouring torques) can leave flows of that order, which are no circulation.
CIRCULATION_FLOOR = 1e-9
#: Loops carrying less than this fraction of the input power are reported as none: with load-dependent
#: losses a set that idles in a gear still passes its own small loss power around a loop (4 W of 41.9 kW
#: in the 8th gear of the ZF 8HP70 example), which loads nothing; every output (tables, warnings, reports,
#: the page) reads the circulation from here, so all of them say "none" alike.
CIRCULATION_THRESHOLD = 1e-3


@dataclass(frozen=True)
class PowerLoop:
    """One closed loop of the train around which power circulates.

    Attributes
    ----------
    path : tuple of str
        Shaft, element, shaft, element, … in the direction of the power; the
        loop closes back to the first shaft.
    power : float
        Power around the loop, W (> 0).
    ratio : float or None
        ``power`` as a multiple of the input power (None when no power enters).
    """

    path: tuple[str, ...]
    power: float
    ratio: float | None

    def describe(self) -> str:
        """``'I → planetary → III → stage → I'``."""
        return " → ".join((*self.path, self.path[0]))

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data of one loop.

        Returns
        -------
        dict
            ``path`` (shaft, element, shaft, ... in the direction of the power, closing on
            itself), ``power`` (W) and ``ratio`` (× input power, ``None`` without input power).
        """
        return {"path": list(self.path), "power": self.power, "ratio": self.ratio}


@dataclass(frozen=True)
class Circulation:
    """Circulating power of a solution, per loop and in total, and the largest element power.

    Attributes
    ----------
    loops : tuple of PowerLoop
        Loops with circulating power (empty when none circulates or it is indeterminate).
    power : float or None
        Sum of the loops' power, W (0 when none circulates; None when indeterminate).
    ratio : float or None
        ``power`` as a multiple of the input power.
    largest_element_power : float or None
        The largest power through any element port, W (None when indeterminate).
    largest_element_ratio : float or None
        ``largest_element_power`` as a multiple of the input power.
    indeterminate : tuple of str
        Elements whose torque split is statically indeterminate (then nothing
        above is defined).
    """

    loops: tuple[PowerLoop, ...] = ()
    power: float | None = 0.0
    ratio: float | None = None
    largest_element_power: float | None = 0.0
    largest_element_ratio: float | None = None
    indeterminate: tuple[str, ...] = ()

    @property
    def determinate(self) -> bool:
        return not self.indeterminate

    def describe(self) -> str:
        """One line for reports."""
        if self.indeterminate:
            return ("not defined: the torque split of " + ", ".join(repr(n) for n in self.indeterminate)
                    + " is statically indeterminate")
        if not self.loops:
            return "none"
        shown = "; ".join(
            f"{_fmt(loop.power)} W" + (f" ({_fmt(loop.ratio, 4)} × input)" if loop.ratio is not None else "")
            + f" around {loop.describe()}" for loop in self.loops)
        return shown

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data: circulating power per loop and in total, largest element power.

        Powers in W (the core unit; reports convert them), ratios as multiples of the
        input power; ``None`` where the torque split is statically indeterminate.

        Returns
        -------
        dict
            ``power``, ``ratio``, ``loops`` (:meth:`PowerLoop.to_dict`),
            ``largest_element_power``, ``largest_element_ratio``, ``indeterminate``
            (names of the elements whose split is open).

        References
        ----------
        Brandenberger 1952, text to Bild 11/12 (Blindleistung); Müller 1998.
        """
        return {
            "power": self.power,
            "ratio": self.ratio,
            "loops": [loop.to_dict() for loop in self.loops],
            "largest_element_power": self.largest_element_power,
            "largest_element_ratio": self.largest_element_ratio,
            "indeterminate": list(self.indeterminate),
        }


def _fmt(value: float | None, digits: int = 6) -> str:
    return "—" if value is None else f"{value:.{digits}g}"


def indeterminate_circulation(elements: Iterable[str]) -> Circulation:
    """The circulation of a statically indeterminate solution: nothing defined, the elements named."""
    return Circulation((), None, None, None, None, tuple(elements))


Node = tuple[str, str]  # ("shaft" | "element", name)


def circulation(port_powers: Sequence[tuple[str, str, float]], input_power: float,
                shaft_order: Sequence[str] = ()) -> Circulation:
    """The circulating power of a power-flow network.

    Parameters
    ----------
    port_powers : sequence of (element, shaft, power)
        Power into ``element`` from ``shaft`` at each port, W (negative: out of
        the element into the shaft).
    input_power : float
        W, for the ratios.
    shaft_order : sequence of str, optional
        Shaft names in the train's order; a loop's path starts at its first
        shaft in this order.

    Returns
    -------
    Circulation

    Examples
    --------
    A set that hands 500 W back to its input shaft through a stage (1000 W in):

    >>> c = circulation([("set", "I", 1500.0), ("set", "II", -1000.0), ("set", "III", -500.0),
    ...                  ("stage", "III", 500.0), ("stage", "I", -500.0)], 1000.0, ["I", "II", "III"])
    >>> c.power, c.ratio, c.loops[0].describe()
    (500.0, 0.5, 'I → set → III → stage → I')

    A loop below :data:`CIRCULATION_THRESHOLD` of the input power is none:

    >>> circulation([("set", "I", 1000.5), ("set", "II", -1000.0), ("set", "III", -0.5),
    ...              ("stage", "III", 0.5), ("stage", "I", -0.5)], 1000.0, ["I", "II", "III"]).loops
    ()
    """
    largest = max((abs(p) for _, _, p in port_powers), default=0.0)
    ratio_of = (lambda p: p / input_power) if input_power > 0 else (lambda p: None)
    flow: dict[Node, dict[Node, float]] = {}
    for element, shaft, power in port_powers:
        if power == 0.0:
            continue
        a, b = ("shaft", shaft), ("element", element)
        source, target = (a, b) if power > 0 else (b, a)
        flow.setdefault(source, {})
        flow[source][target] = flow[source].get(target, 0.0) + abs(power)
    floor = CIRCULATION_FLOOR * largest
    loops: dict[tuple[str, ...], float] = {}
    while _has_cycle(flow, floor):
        cycles = _simple_cycles(flow, floor)
        if not cycles:
            break
        best = max(cycles, key=lambda c: (_bottleneck(flow, c), [n for n in c]))
        amount = _bottleneck(flow, best)
        for u, v in zip(best, best[1:] + best[:1]):
            flow[u][v] -= amount
        path = _rotated(best, shaft_order)
        loops[path] = loops.get(path, 0.0) + amount
    threshold = CIRCULATION_THRESHOLD * abs(input_power)
    ordered = tuple(PowerLoop(path, power, ratio_of(power)) for path, power in
                    sorted(loops.items(), key=lambda item: -item[1]) if power >= threshold)
    total = sum(loop.power for loop in ordered)
    return Circulation(ordered, total, ratio_of(total), largest, ratio_of(largest))


def _has_cycle(flow: Mapping[Node, Mapping[Node, float]], floor: float) -> bool:
    """Whether some directed cycle runs through edges carrying more than ``floor`` (Kahn's algorithm:
    a graph is acyclic exactly when repeatedly taking out nodes without incoming edges empties it)."""
    incoming: dict[Node, int] = {}
    for u, targets in flow.items():
        incoming.setdefault(u, 0)
        for v, f in targets.items():
            if f > floor:
                incoming[v] = incoming.get(v, 0) + 1
    free = [u for u, count in incoming.items() if count == 0]
    left = len(incoming)
    while free:
        u = free.pop()
        left -= 1
        for v, f in flow.get(u, {}).items():
            if f > floor:
                incoming[v] -= 1
                if incoming[v] == 0:
                    free.append(v)
    return left > 0


def _bottleneck(flow: Mapping[Node, Mapping[Node, float]], cycle: Sequence[Node]) -> float:
    return min(flow[u][v] for u, v in zip(cycle, [*cycle[1:], cycle[0]]))


def _rotated(cycle: Sequence[Node], shaft_order: Sequence[str]) -> tuple[str, ...]:
    rank = {name: k for k, name in enumerate(shaft_order)}
    starts = [k for k, (kind, _) in enumerate(cycle) if kind == "shaft"]
    start = min(starts, key=lambda k: (rank.get(cycle[k][1], len(rank)), cycle[k][1]))
    return tuple(name for _, name in (*cycle[start:], *cycle[:start]))


def _simple_cycles(flow: Mapping[Node, Mapping[Node, float]], floor: float, limit: int = 10_000) -> list[list[Node]]:
    """Every simple directed cycle through edges carrying more than ``floor`` (each once, smallest node first)."""
    nodes = sorted({*flow, *(v for targets in flow.values() for v in targets)})
    order = {n: k for k, n in enumerate(nodes)}
    out: list[list[Node]] = []

    def successors(u: Node) -> list[Node]:
        return sorted((v for v, f in flow.get(u, {}).items() if f > floor), key=order.__getitem__)

    for start in nodes:
        stack = [(start, iter(successors(start)))]
        path, on_path = [start], {start}
        while stack and len(out) < limit:
            node, children = stack[-1]
            child = next(children, None)
            if child is None:
                stack.pop()
                on_path.discard(path.pop())
                continue
            if child == start:
                out.append(list(path))
            elif child not in on_path and order[child] > order[start]:
                path.append(child)
                on_path.add(child)
                stack.append((child, iter(successors(child))))
    return out
