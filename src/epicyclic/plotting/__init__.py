"""Pictures of a solved gear train: speed plans, torque and power diagrams, levers, power flow, animation.

Every picture is computed first into a frozen data object (``speed_plan``,
``range_diagram``, ``torque_diagram``, ``power_diagram``, ``lever_diagram``,
``power_flow``, ``planetary_animation``) and drawn from it (``.plot()``,
``.svg()``); matplotlib is imported only when drawing.

:func:`figure` draws one kind of picture; :func:`report_figures` returns every
picture as inline SVG for the HTML report.

References
----------
Brandenberger 1952, Bild 3–9; Queitsch, Bild 5; tec-science, "Willis-Gleichung";
Benford & Leising 1981 (SAE 810102).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from ._common import FIGURE_SUFFIXES, PlottingError, figure_svg, save_figure
from .animation import PlanetaryAnimation, planetary_animation
from .context import FigureContext
from .diagrams import PowerDiagram, TorqueDiagram, power_diagram, torque_diagram
from .flow import PowerFlow, power_flow
from .lever import CompoundLever, LeverDiagram, compound_lever, free_levers, lever_diagram
from .ranges import RangeDiagram, range_diagram
from .speed_chart import SpeedChart, speed_chart
from .speed_plan import SpeedPlan, plot_speed_plan, set_layout, speed_plan
from .subject import Subject, figure_subject

if TYPE_CHECKING:  # pragma: no cover
    from ..results.solution import Solution

__all__ = [
    "KINDS",
    "ALL_KINDS",
    "FIGURE_SUFFIXES",
    "CompoundLever",
    "FigureContext",
    "SpeedChart",
    "Subject",
    "figure_subject",
    "free_levers",
    "speed_chart",
    "LeverDiagram",
    "PlanetaryAnimation",
    "PlottingError",
    "PowerDiagram",
    "PowerFlow",
    "RangeDiagram",
    "SpeedPlan",
    "TorqueDiagram",
    "compound_lever",
    "figure",
    "figure_svg",
    "lever_diagram",
    "planetary_animation",
    "plot_speed_plan",
    "power_diagram",
    "power_flow",
    "range_diagram",
    "report_figures",
    "save_figure",
    "save_plot",
    "set_layout",
    "speed_plan",
    "torque_diagram",
]

#: The kinds of picture :func:`figure` draws of any solved train.
KINDS = ("speed", "torque", "power", "lever", "flow")
#: With the speed chart across gears, which needs a transmission.
ALL_KINDS = (*KINDS, "chart")


def figure(solution: Solution, kind: str, *, context: FigureContext | None = None, transmission: Any = None,
           gear: str | None = None) -> Any:
    """A matplotlib figure of one kind: speed, torque, power, lever, flow or chart.

    Parameters
    ----------
    solution : Solution
    kind : str
        One of :data:`ALL_KINDS`.
    context : FigureContext, optional
        Title, units, gear and notes (default: the train's name, 1/min, N·m, W).
    transmission : epicyclic.transmission.Transmission, optional
        Marks input and output on the lever, draws every gear's speed line
        where the free state is one lever; needed for ``"chart"``.
    gear : str, optional
        The gear shown (named in the title, highlighted).

    Raises
    ------
    PlottingError
        Unknown kind, a speed plan of a train without planetary set, a chart
        without transmission.

    Examples
    --------
    >>> import matplotlib; matplotlib.use("Agg")
    >>> from epicyclic.demo import brandenberger_1952
    >>> from epicyclic import solve
    >>> fig = figure(solve(*brandenberger_1952()), "power")
    >>> len(fig.axes)
    4
    """
    from dataclasses import replace

    context = context or FigureContext(title=solution.train.name)
    if gear is not None and context.gear is None:
        context = replace(context, gear=gear)
    gear = context.gear
    if kind == "speed":
        return plot_speed_plan(solution, context=context)
    if kind == "torque":
        return torque_diagram(solution, context=context).plot()
    if kind == "power":
        return power_diagram(solution, context=context).plot()
    if kind == "lever":
        return lever_diagram(solution, transmission=transmission, gear=gear, context=context).plot()
    if kind == "flow":
        return power_flow(solution, context=context).plot()
    if kind == "chart":
        if transmission is None:
            raise PlottingError(f"plot: the speed chart shows every gear of a transmission; train "
                                f"{solution.train.name!r} has none (add a [transmission] table with a schedule).")
        return speed_chart(transmission, gear=gear, context=context).plot()
    raise PlottingError(f"plot: kind must be one of {', '.join(ALL_KINDS)}, got {kind!r}.")


def save_plot(solution: Solution, kind: str, path: str | Path, *, dpi: int = 150, **options: Any) -> Path:
    """Draw ``kind`` (options as for :func:`figure`) and write it to ``path`` (.svg, .png or .pdf).

    Parameters
    ----------
    solution : Solution
        A solved train.
    kind : str
        One of :data:`ALL_KINDS`.
    path : str or Path
        The file; its suffix (.svg, .png, .pdf) chooses the format.
    dpi : int, default 150
        Resolution of a PNG.
    **options
        ``context``, ``transmission``, ``gear`` as for :func:`figure`.

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    PlottingError
        Another suffix, or what :func:`figure` raises.
    """
    from ._common import check_suffix

    check_suffix(path, FIGURE_SUFFIXES, "plot")
    return save_figure(figure(solution, kind, **options), path, dpi=dpi)


def report_figures(solution: Solution, *, units: Any = None, title: str | None = None,
                   geometry: Any = None) -> list[tuple[str, str]]:
    """Every picture of a solution as (title, inline SVG text) for the HTML report.

    The SVG texts start with ``<svg`` (no XML prolog) and contain no scripts
    or external references.  Pictures that do not apply (a speed plan without
    planetary set) are left out.  The last entry is the animation of the first
    planetary set (SMIL, plays in the browser).

    Parameters
    ----------
    solution : Solution
        A solved train.
    units : Units, optional
        The file's units (:class:`~epicyclic.units.Units`); default 1/min, N·m, W.
    title : str, optional
        Title of the figures, as the report's (default: the train's name).
    geometry : mapping element name → geometry, optional
        The file's geometry tables; the sets' :class:`~epicyclic.geometry.SetGeometry`
        give the speed plan its operating pitch radii.

    Returns
    -------
    list of (str, str)
        (title, SVG text) per picture.

    Examples
    --------
    >>> import matplotlib; matplotlib.use("Agg")
    >>> from epicyclic.demo import brandenberger_1952
    >>> from epicyclic import solve
    >>> [title for title, _ in report_figures(solve(*brandenberger_1952()))]  # doctest: +NORMALIZE_WHITESPACE
    ['Speed plan (Kutzbach) and speed ranges 1–7', 'Torques with and without friction',
     'Powers as areas, loss rectangle (Brandenberger Bild 8/9)', 'Lever diagram', 'Power flow',
     'Animation of set planetary']
    """
    titles = {
        "speed": "Speed plan (Kutzbach) and speed ranges 1–7",
        "torque": "Torques with and without friction",
        "power": "Powers as areas, loss rectangle (Brandenberger Bild 8/9)",
        "lever": "Lever diagram",
        "flow": "Power flow",
    }
    from ..units import Units

    sets = {name: g for name, g in (geometry or {}).items() if hasattr(g, "sun_mesh")}
    context = FigureContext(title=title or solution.train.name, units=units or Units(), geometry=sets)
    out: list[tuple[str, str]] = []
    has_sets = bool(solution.train.planetary_sets)
    for kind in KINDS:
        if kind == "speed" and not has_sets:
            continue
        out.append((titles[kind], figure_svg(figure(solution, kind, context=context))))
    if has_sets:
        anim = planetary_animation(solution, context=context)
        out.append((f"Animation of set {anim.set_name}", anim.svg()))
    return out
