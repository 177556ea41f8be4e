"""The charts the browser draws itself: the pictures' data as JSON, in the units the page shows.

The matplotlib pictures of the page take 0.2–2 s each to draw (the ZF 8HP
speed plan with four sets 1–2 s); the data they are drawn from takes well
under a millisecond.  For the pictures that are plain charts — the speed plan
(Kutzbach) of every set, the speed chart across gears, the torques and the
powers — the page therefore sends that data with the results and the browser
draws it (``static/charts.js`` with the vendored Chart.js), with the values
under the pointer and zoom.  The downloads (SVG, PNG, PDF) stay the matplotlib
files of ``epicyclic plot`` (:mod:`epicyclic.web.figures`), and each chart can
show that picture too.

Every chart is built from the plotting package's data objects and their
``to_dict()`` (:func:`epicyclic.plotting.speed_chart`,
:func:`~epicyclic.plotting.torque_diagram`, :func:`~epicyclic.plotting.power_diagram`,
:func:`~epicyclic.plotting.speed_plan`): the same numbers as the pictures, with
the same zero rule (:mod:`epicyclic.plotting.values`), converted to the page's
units.  A chart is a title, notes and panels; a panel is one of

* ``line``: categories on x (the gears), one series of values per shaft (``null``: no point);
* ``bar``: categories on x, a bar without friction (outline) and with friction per category;
* ``xy``: lines through points (x, y), optionally marked;
* ``rects``: rectangles spanning a speed (x) and a torque (y): powers as areas.

The JSON holds no NaN or infinity (a value that is not finite is ``null``).

References
----------
Queitsch, Bild 5 (speed plan); Brandenberger 1952, Bild 8/9 (powers as areas) and Bild 10
(torques); Naunheimer et al., *Automotive Transmissions* (2011) (speed chart across gears).

Examples
--------
>>> from epicyclic.io import load_train_file
>>> from epicyclic.plotting import figure_subject
>>> charts = chart_specs(figure_subject(load_train_file("examples/simpson_c4_3speed.toml"), "2"))
>>> sorted(charts)
['chart', 'power', 'speed', 'torque']
>>> '"highlight":1' in charts["chart"] and "NaN" not in charts["chart"]
True
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # pragma: no cover
    from ..plotting import Subject

__all__ = ["CHART_KINDS", "chart_specs", "chart_json", "ahead_kinds"]

#: The pictures the browser draws as charts (the others stay matplotlib pictures).
CHART_KINDS = ("speed", "chart", "torque", "power")


def ahead_kinds(browser_charts: bool) -> tuple[str, ...]:
    """The pictures the server draws ahead: those the page shows as pictures (the animation is cheap).

    Parameters
    ----------
    browser_charts : bool
        Whether the browser draws :data:`CHART_KINDS` itself (then the server need not draw them).
    """
    from .cache import AHEAD_KINDS

    return tuple(k for k in AHEAD_KINDS if not (browser_charts and k in CHART_KINDS))


def _finite(value: Any) -> Any:
    """``value`` with every float that is not finite replaced by None (JSON has no NaN)."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(v) for v in value]
    return value


def chart_json(spec: dict[str, Any]) -> str:
    """A chart as JSON text (no NaN, no infinity: those become ``null``).

    Parameters
    ----------
    spec : dict
        A chart (title, notes, panels).
    """
    return json.dumps(_finite(spec), ensure_ascii=False, allow_nan=False, separators=(",", ":"))


def _roles() -> dict[str, dict[str, str]]:
    """Colour and legend text of each power role, as the pictures have them (Brandenberger's hatching)."""
    from ..plotting._common import ROLE_STYLE

    return {role: {"colour": style["facecolor"], "label": style["label"]} for role, style in ROLE_STYLE.items()}


def _colours() -> tuple[str, ...]:
    from ..plotting._common import SHAFT_COLOURS

    return SHAFT_COLOURS


# ---------------------------------------------------------------------- the charts
def _speed_chart(subject: Subject) -> dict[str, Any] | None:
    """Shaft speeds and the slips of open clutches and brakes per gear, per unit input speed."""
    from ..plotting import speed_chart
    from ..plotting.speed_chart import shift_state_words

    if subject.transmission is None:
        return None
    chart = speed_chart(subject.transmission, gear=subject.gear, context=subject.context)
    data, colours = chart.to_dict(), _colours()
    gears = data["gears"]
    labels = [[g, *data["engaged"][g]] for g in gears]  # one engaged element a line: no tick runs into the next
    highlight = gears.index(chart.gear) if chart.gear in gears else None

    def panel(table: dict[str, dict[str, float]], title: str, axis: str, bold: set[str]) -> dict[str, Any]:
        series = []
        for k, (name, row) in enumerate(table.items()):
            role = " (input)" if name == data["input"] else " (output)" if name == data["output"] else ""
            series.append({"name": name + role, "values": [row.get(g) for g in gears],
                           "colour": colours[k % len(colours)], "bold": name in bold})
        return {"type": "line", "title": title, "x": {"title": "gear (engaged clutches and brakes)", "labels": labels},
                "y": {"title": axis, "unit": "× n_in"}, "series": series, "highlight": highlight}

    state = "" if highlight is None else \
        f"; gear {chart.gear} highlighted ({shift_state_words(data['engaged'][chart.gear])})"
    return {"title": f"{data['title']}: speed chart across gears (Willis kinematics at n_in = 1){state}",
            "notes": [], "panels": [
                panel(data["speeds"], "shaft speeds", "speed per input speed n / n_in",
                      {data["input"], data["output"]}),
                panel(data["slips"], "slip of open clutches and brakes", "slip speed per input speed Δn / n_in",
                      set())]}


def _torques(subject: Subject) -> dict[str, Any]:
    """Torque bars with and without friction: the external shafts and the ports of every element."""
    from ..plotting import torque_diagram

    diagram = torque_diagram(subject.solution, context=subject.context)
    context, data = subject.context, diagram.to_dict()
    k, unit = context.convert(1.0, "torque"), context.unit("torque")
    panels = []
    for group in diagram.groups:
        bars = [{"label": bar["label"].split("\n"), "ideal": None if bar["ideal"] is None else k * bar["ideal"],
                 "actual": k * bar["actual"], "role": bar["role"]} for bar in data["bars"] if bar["group"] == group]
        panels.append({"type": "bar", "title": "external torques on shafts" if group == "external" else
                       f"torques on {group}", "x": {"title": ""}, "y": {"title": f"torque M in {unit}", "unit": unit},
                       "bars": bars})
    notes = [f"no torque on {', '.join(diagram.resting)} (idle in this state): not drawn"] if diagram.resting else []
    return {"title": context.heading(subject.solution.train, "torques with and without friction (housing: reaction)"),
            "notes": notes, "panels": panels, "roles": _roles()}


def _powers(subject: Subject) -> dict[str, Any]:
    """Power rectangles (speed × torque) of every element carrying power, with friction filled and without
    friction as an outline; the loss rectangle (Brandenberger Bild 8/9)."""
    from ..plotting import power_diagram

    diagram = power_diagram(subject.solution, context=subject.context)
    context = subject.context
    sx, sy = context.convert(1.0, "speed"), context.convert(1.0, "torque")
    ideal = {e.element: e for e in diagram.ideal}
    panels = []
    for element in diagram.actual:
        if element.element in diagram.resting:
            continue
        scale = max((abs(r.power) for r in element.rects), default=0.0)
        rects = []
        for friction, shown in ((False, ideal.get(element.element)), (True, element)):
            if shown is None:
                continue
            for rect in (*shown.rects, *((shown.loss_rect,) if shown.loss_rect else ())):
                x0, x1 = sorted((rect.x0, rect.x0 + rect.width))
                value = rect.area if rect.role == "loss" else rect.power
                rects.append({"label": rect.label, "x0": sx * x0, "x1": sx * x1, "y0": sy * rect.y0,
                              "y1": sy * (rect.y0 + rect.height), "role": rect.role, "friction": friction,
                              "power": context.text(value, "power", scale),
                              "speed": context.text(rect.width, "speed", 0.0),
                              "torque": context.text(rect.height, "torque", 0.0)})
        lossless = ideal.get(element.element)
        without = f", without friction {context.text(lossless.loss, 'power', scale)}" if lossless else ""
        panels.append({"type": "rects", "title": f"{element.element} ({element.kind}): loss "
                       f"{context.text(element.loss, 'power', scale)}{without}",
                       "x": {"title": f"speed n in {context.unit('speed')} (rectangle width)"},
                       "y": {"title": f"|torque| M in {context.unit('torque')} (rectangle height)"}, "rects": rects})
    notes = [f"no power in {', '.join(diagram.resting)} (idle or locked in this state): not drawn"] \
        if diagram.resting else []
    if diagram.ideal:
        notes.append("filled: with friction; dashed outline: without friction")
    what = "powers as areas (speed × torque), Brandenberger Bild 8/9"
    return {"title": context.heading(subject.solution.train, what),
            "notes": notes, "panels": panels, "roles": _roles()}


def _speed_plans(subject: Subject) -> dict[str, Any] | None:
    """The speed plan (Kutzbach) of every planetary set: radius up, peripheral speed across."""
    from ..plotting import speed_plan
    from ..plotting._common import RPM_TO_RAD_S
    from ..plotting.values import scale_of

    solution, context = subject.solution, subject.context
    sets = list(solution.train.planetary_sets)
    if not sets:
        return None
    colours = _colours()
    panels = []
    for pset in sets:
        plan = speed_plan(solution, pset.name, context=context)
        data = plan.to_dict()
        names = {"sun": "sun", "ring": "ring" if plan.layout.central["ring"][1] else "2nd central",
                 "carrier": "carrier"}
        drawn = plan.layout.drawn
        if drawn is not None and not plan.layout.schematic and drawn.teeth.arrangement in ("two rings", "two suns"):
            names.update(sun="first", ring="second")
        top = max(plan.speed_scale, scale_of((*plan.omegas.values(), *plan.planet_omegas)) / RPM_TO_RAD_S)

        def speed(omega: float) -> str:
            return context.text(omega / RPM_TO_RAD_S, "speed", top, 5)

        series = [{"name": f"{names[p]} ({member['shaft']}): {speed(plan.omegas[p])}", "colour": colours[k],
                   "points": [[v, r] for r, v in member["points"]], "width": 2}
                  for k, (p, member) in enumerate(data["members"].items())]
        for k, (body, planet) in enumerate(zip(plan.layout.bodies, data["planets"])):
            series.append({"name": f"{planet['label']}: {speed(plan.planet_omegas[body.index])}",
                           "colour": colours[(3 + k) % len(colours)], "width": 4,
                           "points": [[v, r] for r, v in planet["line"]]})
            series.append({"name": f"{planet['label']}: mesh points and axis", "colour": "#000000", "width": 0,
                           "legend": False, "points": [[v, r] for r, v in planet["points"].values()],
                           "point_labels": [names[n] if n != "carrier" else "axis" for n in planet["points"]]})
        own = plan.layout.schematic or plan.layout.note
        heading = f"Speed plan (Kutzbach) of set {pset.name!r}"
        panels.append({"type": "xy", "title": [heading, plan.assumptions()] if own else heading,
                       "x": {"title": f"peripheral speed v in {plan.velocity_unit}", "unit": plan.velocity_unit},
                       "y": {"title": "radius r in mm" if own else f"radius r in mm ({plan.assumptions()})",
                             "unit": "mm"},
                       "series": series})
    return {"title": context.heading(solution.train, "speeds (speed plan of every set)"),
            "notes": ["the speed ranges 1–7 of every set (Brandenberger Bild 3/4) are in the picture"],
            "panels": panels}


_MAKERS: dict[str, Callable[[Subject], dict[str, Any] | None]] = {
    "speed": _speed_plans, "chart": _speed_chart, "torque": _torques, "power": _powers}


def chart_specs(subject: Subject) -> dict[str, str]:
    """The charts of :data:`CHART_KINDS` that exist for ``subject``, each as JSON text (name → JSON).

    Parameters
    ----------
    subject : epicyclic.plotting.Subject
        The solved state the page shows (:func:`epicyclic.plotting.figure_subject`, in the page's units).

    Returns
    -------
    dict
        Picture name → the chart as JSON (:func:`chart_json`); a picture that does not apply (the speed
        chart without a transmission, a speed plan without planetary set) is left out.
    """
    charts = {}
    for name in CHART_KINDS:
        spec = _MAKERS[name](subject)
        if spec is not None:
            charts[name] = chart_json({"kind": name, **spec})
    return charts
