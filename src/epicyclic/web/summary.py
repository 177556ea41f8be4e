"""What the page says about a solved state: key figures, where the power goes, circulating loops, gears.

The numbers are the library's (:class:`~epicyclic.results.Solution`,
:class:`~epicyclic.results.circulation.Circulation`,
:class:`~epicyclic.transmission.TransmissionAnalysis`); this module only puts
them into words in the reader's units, and says so honestly where there is
nothing to say: a train through which no power flows has no efficiency, a
drive or load that the train holds still takes a reaction torque and no power,
and circulating power is not defined where the torque split is statically
indeterminate (Brandenberger 1952, text to Bild 11 and 12; Müller 1998).

Examples
--------
>>> from epicyclic.demo import brandenberger_1952
>>> from epicyclic import solve
>>> state = power_state(solve(*brandenberger_1952()), Units())
>>> state.kind, state.text
('flows', 'Not self-locking: power flows from the drive to the load as asked.')
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from ..errors import EpicyclicError
from ..units import Units
from .render import fmt

if TYPE_CHECKING:  # pragma: no cover
    from ..results import Solution

__all__ = ["PowerState", "Loop", "CirculationView", "power_state", "circulation_view", "key_figures",
           "other_warnings", "gear_table", "loss_split"]


@dataclass(frozen=True)
class PowerState:
    """Where the power goes, in words.

    Attributes
    ----------
    kind : {"flows", "none", "self-locking"}
    text : str
        The sentence the page shows.
    held : tuple of str
        One sentence per drive or load that the train holds still (reaction torque, no power).
    """

    kind: str
    text: str
    held: tuple[str, ...] = ()


def _plural(names: Sequence[str], word: str) -> str:
    return word + ("s" if len(names) > 1 else "")


def power_state(solution: Solution, units: Units) -> PowerState:
    """Whether power flows from the drives to the loads, none flows, or the train self-locks."""
    held = tuple(
        f"{s.name!r} is a {s.role} but the train holds it still (speed 0): it takes "
        f"{fmt(units.torque_from_core(abs(s.torque)), 6)} {units.torque} as a reaction torque, not power."
        for s in solution.shafts.values()
        if s.role in ("drive", "load") and s.speed == 0.0 and s.torque != 0.0
    )
    if solution.self_locking is not None:
        return PowerState("self-locking", solution.self_locking.message, held)
    if solution.input_power == 0.0 and solution.output_power == 0.0:
        return PowerState("none", "No power flows through the train at this operating point, so it has no "
                                  "efficiency.", held)
    drives, loads = solution.drives, solution.loads
    return PowerState("flows", f"Not self-locking: power flows from the {_plural(drives, 'drive')} to the "
                               f"{_plural(loads, 'load')} as asked.", held)


@dataclass(frozen=True)
class Loop:
    """One loop of circulating power as the page shows it."""

    path: str
    power: str
    ratio: str


@dataclass(frozen=True)
class CirculationView:
    """Circulating power (Blindleistung) of a solution in words and in the reader's units.

    Attributes
    ----------
    short : str
        For the key figure: ``"none"``, ``"0.651 × input"``, ``"not defined"`` or ``"—"``.
    text : str
        A sentence saying what the loops below are, or that there are none, or why it is not defined.
    loops : tuple of Loop
    largest : str
        The largest power through any element port, as a multiple of the input ("" if not defined).
    """

    short: str
    text: str
    loops: tuple[Loop, ...] = ()
    largest: str = ""


def circulation_view(solution: Solution, units: Units) -> CirculationView:
    """The circulating power of ``solution`` per loop (Brandenberger 1952, text to Bild 11 and 12)."""
    c = solution.circulation
    if c.indeterminate:
        names = ", ".join(repr(n) for n in c.indeterminate)
        return CirculationView("not defined", f"Not defined: the torque split of {names} is statically "
                               "indeterminate (redundant locking), so neither the circulating power nor the "
                               "largest element power is defined.")
    largest = "" if c.largest_element_ratio is None else f"{fmt(c.largest_element_ratio, 4)} × input power"
    if c.ratio is None:
        return CirculationView("—", "No power enters the train, so no power circulates.")
    if not c.loops:
        return CirculationView("none", "No power circulates around a closed loop of the train.", (), largest)
    loops = tuple(Loop(loop.describe(), f"{fmt(units.power_from_core(loop.power), 6)} {units.power}",
                       "—" if loop.ratio is None else fmt(loop.ratio, 4)) for loop in c.loops)
    text = (f"Power circulates around {len(loops)} closed {_plural(loops, 'loop')}: "
            f"{fmt(units.power_from_core(c.power), 6)} {units.power} = {fmt(c.ratio, 4)} × input power in all. "
            "It loads the teeth and bearings of the loop without reaching the output.")
    return CirculationView(f"{fmt(c.ratio, 4)} × input", text, loops, largest)


def key_figures(solution: Solution, units: Units, summary: Sequence[tuple[str, str]]) -> list[tuple[str, str, str]]:
    """(element id, label, value) of the key figures above the tables, from the summary lines."""
    values = dict(summary)
    shown = [("efficiency", "efficiency", values.get("efficiency")),
             ("input-power", "input power", values.get("input power")),
             ("output-power", "output power", values.get("output power")),
             ("loss", "total loss", values.get("total loss")),
             ("circulating", "circulating power", circulation_view(solution, units).short),
             ("ratio", "ratio n_drive/n_load", values.get("speed ratio n_drive/n_load"))]
    return [(key, label, value) for key, label, value in shown if value is not None]


def loss_split(solution: Solution, units: Units) -> Any:
    """The loss of each element by source (mesh, bearing, drag) and in all, as a report table.

    Only for a train whose file has loss models (``[planetary.losses]``, ``[gear.losses]``): with a
    typed-in stationary efficiency every loss is mesh loss and the elements table says it already.
    The numbers are the solver's (:attr:`~epicyclic.results.ElementState.loss_sources`, ISO/TR 14179-2:
    load-dependent mesh losses and load-independent losses add up).
    """
    from ..io.tables import ReportTable
    from ..losses.spin import ALL_SOURCES as SOURCES

    def power(value: float) -> str:
        return fmt(units.power_from_core(value), 6)

    elements = [e for e in solution.elements.values() if e.loss_sources]
    sources = [s for s in SOURCES if any(s in e.loss_sources for e in elements)]
    housing_sources = set(solution.housing_loss_sources)
    sources = [s for s in SOURCES if any(s in e.loss_sources for e in elements) or s in housing_sources]
    sources += sorted(({s for e in elements for s in e.loss_sources} | housing_sources) - set(sources))
    rows = [(e.name, *(power(e.loss_sources.get(s, 0.0)) for s in sources), power(sum(e.loss_sources.values())))
            for e in elements]
    housing = solution.housing_loss_sources
    if housing:  # auxiliaries that belong to no element: pump, seals
        rows.append(("housing (pump, seals)", *(power(housing.get(s, 0.0)) for s in sources),
                     power(sum(housing.values()))))
    totals = solution.loss_sources
    rows.append(("all", *(power(totals.get(s, 0.0)) for s in sources), power(sum(totals.values()))))
    return ReportTable("Losses by source", ("element", *(f"{s} [{units.power}]" for s in sources),
                                            f"total [{units.power}]"), tuple(rows))


#: Parts of the solver's warnings that the page shows in its own words (power state, circulation).
_SHOWN_ELSEWHERE = ("holds it still (speed 0)", "no power flows through the train", "power circulates:",
                    "is statically indeterminate")


def other_warnings(solution: Solution) -> list[str]:
    """The solver's warnings that the power state and the circulation section do not already say."""
    return [w for w in solution.warnings if not any(part in w for part in _SHOWN_ELSEWHERE)]


def gear_table(transmission: Any, current: str | None, source: str, operating_point: Any = None) -> dict[str, Any]:
    """The gear table of a transmission (its own header and rows), or its error located in the file.

    ``transmission`` is a :class:`~epicyclic.transmission.Transmission` or a function that makes one
    (whose errors, e.g. a gear that leaves the train free, are located at their schedule key too).
    Every gear is analysed at the input point ``epicyclic gears`` uses: the speed and torque of the
    transmission's input in ``operating_point`` (the file's), else 1000 1/min and 100 N·m; the footer
    states it (:func:`~epicyclic.transmission.input_point.input_point`).
    """
    from ..transmission.input_point import input_point

    from ..io.located import locate_error
    from ..transmission import TransmissionAnalysis

    def failed(exc: EpicyclicError, where: str) -> dict[str, Any]:
        return {"error": str(locate_error(exc, source, None, where)), "rows": [], "current": None}

    if callable(transmission):
        try:
            transmission = transmission()
        except EpicyclicError as exc:
            return failed(exc, "[transmission]")
    try:
        point = input_point(transmission.input, operating_point)
    except EpicyclicError as exc:
        return failed(exc, "[operating_point]")
    results = []
    for gear in transmission.gears:
        try:
            results.append(transmission.analyze(gear, input_speed=point.speed, input_torque=point.torque))
        except EpicyclicError as exc:  # name the gear, as ``epicyclic gears`` does
            return failed(exc, f"[transmission], key {f'schedule.{gear}'!r}")
    analysis = TransmissionAnalysis(transmission.name, transmission.input, transmission.output, tuple(results),
                                    point)
    rows = [(g.gear, cells) for g, cells in zip(analysis.gears, analysis._rows())]
    return {"error": None, "transmission": transmission, "analysis": analysis, "header": analysis.HEADER,
            "rows": rows, "footer": analysis._footer(), "current_name": current,
            "current": next((g for g in analysis.gears if g.gear == current), None)}
