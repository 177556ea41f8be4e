"""Lever diagrams (Benford–Leising) of simple and compound trains, found from the kinematics.

Every element with gears is a vertical lever with three nodes.  For a set
with ports (sun a, ring b, carrier c) and stationary ratio i0, the speeds of
the nodes are a linear function of their height when

.. math:: \\frac{y_a - y_c}{y_b - y_c} = i_0,

i.e. with the carrier node at ``t = i0/(i0 − 1)`` of the way from the sun
node (0) to the ring node (1): between them for a minus set (sun–carrier :
carrier–ring = z_ring : z_sun), outside for a plus set.  A fixed-axis stage is
a lever whose third node is the housing (ratio n_first/n_second).

Levers combine into one *compound lever* wherever the equations of the
elements joined (with the housing treated as a shaft that may turn) leave two
degrees of freedom, a rigid rotation and one more: then every shaft has one
height ``Y`` and every kinematically possible set of speeds is
``n = α + β·Y``, a straight line across the lever.  The heights are the null
space of the Willis equations ``n_a − i0·n_b − (1 − i0)·n_c = 0``; nothing is
looked up from a list of known gearsets.

* :func:`free_levers` merges the sets and stages of the free state (every
  clutch and brake open) into as few compound levers as the kinematics allows:
  a Simpson or Ravigneaux set is one four-node lever, the ZF 8HP stays four
  levers joined by shafts, the Prius is its power-split lever and an output
  lever (reduction set and stages, pivoting on the housing).
* :func:`compound_lever` is the lever of one shift state: with the engaged
  clutches and brakes (``n_x = n_y``) a gear of any transmission has two
  degrees of freedom with the housing free, so every gear has its *reduced
  lever* with every shaft, the input and the housing on it.

References
----------
Benford, H. L.; Leising, M. B.: The lever analogy: a new tool in transmission
analysis.  SAE Technical Paper 810102 (1981).  Willis equation:
Queitsch eq. 12 (s = i0).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from itertools import combinations
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

import numpy as np

from ..model.elements import HOUSING, Brake, Clutch
from ._common import PlottingError, figure_svg, lever_elements
from .context import FigureContext

if TYPE_CHECKING:  # pragma: no cover
    from ..model.train import GearTrain
    from ..results.solution import Solution

__all__ = ["LeverNode", "Lever", "CompoundLever", "LeverDiagram", "lever_diagram", "compound_lever",
           "free_levers", "gear_speeds"]


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
    """Shafts on one lever: heights in [0, 1] from the kinematics, optionally their speeds.

    Attributes
    ----------
    positions : mapping shaft → height in [0, 1]
    speeds : mapping shaft → 1/min, or None
        Speeds of one state (a straight line over the heights).
    elements : tuple of str
        The sets and stages that form the lever.
    """

    positions: Mapping[str, float]
    speeds: Mapping[str, float] | None = None
    elements: tuple[str, ...] = ()

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

    def with_speeds(self, speeds: Mapping[str, float]) -> CompoundLever:
        """The same lever carrying ``speeds`` (1/min) of its shafts."""
        return CompoundLever(self.positions, MappingProxyType({s: float(speeds[s]) for s in self.positions}),
                             self.elements)


@dataclass(frozen=True)
class LeverDiagram:
    """Levers of a train in one shift state, with its speeds.

    Attributes
    ----------
    title : str
    levers : tuple of Lever
        Every set and stage as its own three-node lever.
    links : tuple of (shaft, lever index, lever index)
        Shafts shared by two element levers (permanent connections).
    shift_elements : tuple of (name, kind, shafts, engaged)
    compound : CompoundLever or None
        The reduced lever of the shift state (all shafts, the joined ones at
        one height), with the solved speeds; None where the state has more
        than one free speed besides a rigid rotation.
    permanent : CompoundLever or None
        The single compound lever of the free state, when the sets and stages
        form one.
    free : tuple of CompoundLever
        The compound levers of the free state (see :func:`free_levers`), with
        the solved speeds when there is a solution.
    input, output : str or None
        The input and output of a transmission, or the one drive and the one
        load of a solution, marked on the drawing.
    drives, loads : tuple of str
        Every drive and load of the solution (marked where there are several).
    gear_lines : mapping gear → (mapping shaft → speed per input speed)
        Speeds of every gear of a transmission over the ``permanent`` lever.
    gear : str or None
        The gear shown (its line is drawn bold).
    context : FigureContext
    """

    title: str
    levers: tuple[Lever, ...]
    links: tuple[tuple[str, int, int], ...]
    shift_elements: tuple[tuple[str, str, tuple[str, str], bool], ...]
    compound: CompoundLever | None
    permanent: CompoundLever | None = None
    free: tuple[CompoundLever, ...] = ()
    input: str | None = None
    output: str | None = None
    gear_lines: Mapping[str, Mapping[str, float]] = field(default_factory=dict)
    gear: str | None = None
    context: FigureContext = field(default_factory=FigureContext)
    train: Any = field(default=None, repr=False, compare=False)
    drives: tuple[str, ...] = ()
    loads: tuple[str, ...] = ()

    def role(self, shaft: str) -> str:
        """" (input)", " (output)", " (drive)", " (load)" or "": how the drawing names a shaft's part."""
        if shaft == self.input:
            return " (input)"
        if shaft == self.output:
            return " (output)"
        if shaft in self.drives:
            return " (drive)"
        if shaft in self.loads:
            return " (load)"
        return ""

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data: every lever, the links between them, the compound lever and the gear lines.

        Returns
        -------
        dict
            ``title``; ``levers`` (element, i0, nodes); ``links`` (shafts that join levers);
            ``compound`` and ``free_levers`` (elements, node positions, speeds in 1/min or
            ``None``); ``input``, ``output``; ``gear_lines`` (gear → shaft → speed per input
            speed); ``units``.
        """
        def lever(c: CompoundLever | None) -> dict[str, Any] | None:
            if c is None:
                return None
            return {"elements": list(c.elements), "positions": dict(c.positions),
                    "speeds": None if c.speeds is None else dict(c.speeds)}

        return {
            "title": self.title,
            "levers": [{"element": lv.element, "ratio": lv.ratio,
                        "nodes": [n.__dict__ for n in lv.nodes]} for lv in self.levers],
            "links": [list(link) for link in self.links],
            "compound": lever(self.compound),
            "free_levers": [lever(c) for c in self.free],
            "input": self.input, "output": self.output,
            "gear_lines": {g: dict(v) for g, v in self.gear_lines.items()},
            "units": {"speed": "1/min", "gear_lines": "speed per input speed"},
        }

    def _repr_html_(self) -> str:
        return figure_svg(self.plot())

    def __repr__(self) -> str:
        state = "compound lever" if self.compound is not None else f"{len(self.free)} free levers"
        return f"<LeverDiagram {self.title!r}: {len(self.levers)} levers, {len(self.links)} links, {state}>"

    @property
    def speed_levers(self) -> tuple[CompoundLever, ...]:
        """The levers whose speeds are drawn: the state's reduced lever, else each free lever."""
        if self.compound is not None:
            return (self.compound,)
        return self.free

    def plot(self) -> Any:
        """Figure: left the levers of the free state with clutches, brakes, input and output;
        right the speeds of the shift state (or of every gear) across the lever."""
        from ._lever_draw import plot_lever_diagram

        return plot_lever_diagram(self)


# ---------------------------------------------------------------------- kinematics
def _lever(element: Any, ports: tuple[str, str, str], shafts: tuple[str, str, str], ratio: float) -> Lever:
    t = ratio / (ratio - 1.0)  # carrier node, sun at 0, ring at 1
    raw = (0.0, 1.0, t)
    lo, hi = min(raw), max(raw)
    nodes = tuple(LeverNode(p, s, (y - lo) / (hi - lo)) for p, s, y in zip(ports, shafts, raw))
    kind = "planetary set" if ports[0] == "sun" else "gear stage"
    return Lever(element.name, kind, ratio, nodes)  # type: ignore[arg-type]


def _willis_rows(train: GearTrain, names: set[str] | None = None) -> list[dict[str, float]]:
    """One row ``n_a − i0·n_b − (1 − i0)·n_c = 0`` per set or stage (all, or those named)."""
    return [dict(zip(shafts, (1.0, -ratio, -(1.0 - ratio))))
            for element, _, shafts, ratio in lever_elements(train) if names is None or element.name in names]


def _null_space_heights(order: tuple[str, ...], rows: list[dict[str, float]],
                        first_set: tuple[str, str] | None) -> dict[str, float] | None:
    """Heights of the shafts in ``rows`` if their null space is two-dimensional, else None.

    The housing counts as a shaft that may turn, so a rigid rotation is always
    in the null space; the other direction gives the heights.  Orientation:
    the housing in the lower half, else the first sun below its ring.
    """
    used = [s for s in order if any(s in row for row in rows)]
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
    projected = null - np.outer(null @ ones, ones)  # the direction orthogonal to the rigid rotation
    v = projected[int(np.argmax(np.linalg.norm(projected, axis=1)))]
    if np.ptp(v) <= 1e-12:
        return None
    key = v[index[HOUSING]] - v.mean() if HOUSING in index else 0.0
    if abs(key) <= 1e-9 * np.ptp(v) and first_set is not None and all(s in index for s in first_set):
        key = v[index[first_set[0]]] - v[index[first_set[1]]]
    if key > 0:
        v = -v
    y = (v - v.min()) / np.ptp(v)
    y = np.where(np.abs(y) < 1e-12, 0.0, np.where(np.abs(y - 1.0) < 1e-12, 1.0, y))
    return {s: float(y[index[s]]) for s in used}


def _first_set(train: GearTrain, names: set[str] | None = None) -> tuple[str, str] | None:
    for element, _, shafts, _ in lever_elements(train):
        if names is None or element.name in names:
            return shafts[0], shafts[1]
    return None


def free_levers(train: GearTrain) -> tuple[CompoundLever, ...]:
    """The compound levers of the free state: sets and stages merged while two DOF remain.

    Starting from one lever per set or stage, two levers are merged whenever
    their elements together still leave two degrees of freedom (the housing
    free): they then share two shafts, and all their shafts lie on one lever.
    This repeats until no pair merges.  The result does not depend on a list
    of known gearsets.

    Examples
    --------
    >>> from epicyclic import GearTrain, PlanetarySet
    >>> simpson = GearTrain([PlanetarySet("front", "sun", "front_ring", "out", -72 / 33),
    ...                      PlanetarySet("rear", "sun", "out", "rear_carrier", -72 / 33)])
    >>> [sorted(c.positions) for c in free_levers(simpson)]
    [['front_ring', 'out', 'rear_carrier', 'sun']]
    """
    items = lever_elements(train)
    groups = [{element.name} for element, *_ in items]
    shafts_of = {element.name: set(shafts) for element, _, shafts, _ in items}

    def heights(group: set[str]) -> dict[str, float] | None:
        return _null_space_heights(train.shafts, _willis_rows(train, group), _first_set(train, group))

    merged = True
    while merged:
        merged = False
        for a, b in combinations(range(len(groups)), 2):
            common = set().union(*(shafts_of[n] for n in groups[a])) & set().union(*(shafts_of[n] for n in groups[b]))
            if len(common) >= 2 and heights(groups[a] | groups[b]) is not None:
                groups[a] |= groups.pop(b)
                merged = True
                break
    order = [element.name for element, *_ in items]
    out = []
    for group in groups:
        positions = heights(group)
        if positions is None:  # pragma: no cover - a single set or stage always has two DOF
            raise PlottingError(f"lever: elements {sorted(group)} do not form a lever.")
        ordered = {s: positions[s] for s in train.shafts if s in positions}
        out.append(CompoundLever(MappingProxyType(ordered), None, tuple(n for n in order if n in group)))
    return tuple(out)


def compound_lever(train: GearTrain) -> CompoundLever | None:
    """The lever of the train in its shift state, or None if it has more free speeds.

    The heights come from the sets and stages when they alone leave two
    degrees of freedom (the housing free); shafts that only an engaged clutch
    or brake touches (the input, the housing) sit at the height of the shaft
    they are joined to.  Otherwise the engaged clutches and brakes
    (``n_x = n_y``) are part of the equations: this is the *reduced lever* of
    a gear.  Returns None when no two-dimensional null space is found.

    Examples
    --------
    >>> from epicyclic.demo import brandenberger_1952
    >>> lever = compound_lever(brandenberger_1952()[0])
    >>> {s: round(y, 4) for s, y in lever.positions.items()}
    {'I': 0.5189, 'II': 0.2841, 'III': 1.0, 'housing': 0.0}
    """
    rows = _willis_rows(train)
    links = [element.shafts for element in train.shift_elements if element.engaged]
    first = _first_set(train)
    positions = _null_space_heights(train.shafts, rows, first)
    if positions is None:
        positions = _null_space_heights(train.shafts, rows + [{a: 1.0, b: -1.0} for a, b in links], first)
        if positions is None:
            return None
    for _ in range(len(links)):
        for a, b in links:
            if a in positions and b not in positions:
                positions[b] = positions[a]
            elif b in positions and a not in positions:
                positions[a] = positions[b]
    ordered = {s: positions[s] for s in train.shafts if s in positions}
    return CompoundLever(MappingProxyType(ordered), None, tuple(e.name for e, *_ in lever_elements(train)))


def gear_speeds(transmission: Any) -> dict[str, dict[str, float]]:
    """Every shaft's speed per unit input speed in every gear of ``transmission``.

    ``transmission`` is an :class:`epicyclic.transmission.Transmission` (its
    ``gears`` and ``speeds(gear)``, Willis kinematics only).
    """
    return {gear: dict(transmission.speeds(gear, 1.0)) for gear in transmission.gears}


def lever_diagram(solution: Solution | None = None, *, train: GearTrain | None = None,
                  transmission: Any = None, gear: str | None = None,
                  context: FigureContext | None = None) -> LeverDiagram:
    """The lever diagram of a solved train (speeds drawn) or of a bare train.

    Parameters
    ----------
    solution : Solution, optional
        Gives the train (in its shift state), the speeds, input and output.
    train : GearTrain, optional
        Without a solution: only the levers and positions.
    transmission : Transmission, optional
        A multi-speed transmission: its input and output are marked and, when
        the free state is one compound lever, every gear's speed line is drawn
        over it (speeds per input speed).
    gear : str, optional
        The gear the solution or train is in (drawn bold, named in the title).
    context : FigureContext, optional
        Title, units and notes of the figure.

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
    if solution is None and train is None:
        raise PlottingError("lever diagram: give a solution (or train=...) to draw, got neither.")
    if solution is not None:
        train = solution.train
    assert train is not None
    context = context or FigureContext(title=train.name, gear=gear)
    items = lever_elements(train)
    if not items:
        raise PlottingError(f"train {train.name!r} has no planetary set or gear stage; a lever diagram needs one.")
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
    free = free_levers(train)
    permanent = free[0] if len(free) == 1 else None
    compound = compound_lever(train)
    if solution is not None:
        speeds = {s: solution.speed(s) for s in train.shafts}
        free = tuple(c.with_speeds(speeds) for c in free)
        if compound is not None:
            compound = compound.with_speeds(speeds)
    drives = solution.drives if solution is not None else ()
    loads = solution.loads if solution is not None else ()
    inp = transmission.input if transmission is not None else (drives[0] if len(drives) == 1 else None)
    out = transmission.output if transmission is not None else (loads[0] if len(loads) == 1 else None)
    lines: dict[str, dict[str, float]] = {}
    if transmission is not None and permanent is not None:
        lines = gear_speeds(transmission)
    return LeverDiagram(context.title or train.name, levers, tuple(links), shift, compound, permanent, free,
                        inp, out, MappingProxyType(lines), gear if gear is not None else context.gear, context,
                        train, tuple(drives), tuple(loads))

