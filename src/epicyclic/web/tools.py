"""Forms beside the results: fit checks, tooth and bearing forces, the tooth-count search, the efficiency map.

Each form is one :class:`Tool` in :data:`TOOLS`: its fields (rendered by the
page's template) and a function that reads them and calls the library, as the
command line does (``epicyclic fit``, ``forces``, ``search``, ``map``): the
same functions, the same parsers for ranges (:mod:`epicyclic.io.ranges`), the
same limits (:mod:`epicyclic.limits`), so the same results and messages.  A
new form is one more entry.

Field values arrive as text (``tool_<tool>_<field>`` in the page's form) and
are checked here; a bad value raises :class:`ToolError` naming the form and
the field.  Where the file has geometry tables (``[planetary.geometry]``), the
forms start from them (:func:`form_rows`): the set's module, pressure angle,
profile shifts, planets and K_γ; fields left as they are reproduce the file's
geometry exactly (everything the form does not show, such as face widths and
addendum factors, is kept), a changed field gives a variant.  The choice
"every element with geometry" runs the command line's report on all of them.

Examples
--------
>>> [tool.name for tool in TOOLS.values()]
['fit', 'forces', 'rating', 'search', 'map']
>>> read_number("2.5", Field("module", "module [mm]", "2", low=0.05, high=100), "fit")
2.5
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

from ..errors import EpicyclicError
from ..limits import MAX_PLANETS, RATIO_RANGE

if TYPE_CHECKING:  # pragma: no cover
    from ..io import TrainFile
    from ..results import Solution

__all__ = ["Field", "Tool", "ToolError", "Context", "TOOLS", "ALL", "read_number", "run_tool", "form_rows",
           "tool_file", "TOOL_FILES"]


class ToolError(EpicyclicError, ValueError):
    """A form field of a tool that cannot be used."""


@dataclass(frozen=True)
class Field:
    """One input of a tool form.

    ``kind`` is ``"number"``, ``"integer"``, ``"numbers"`` (comma-separated),
    ``"choice"`` (with ``choices``; ``("set",)`` lists the train's planetary
    sets with tooth counts, ``("gear",)`` the gears of its transmission) or
    ``"text"`` read by ``parse(text, name)`` (the command line's range
    grammar).  ``low``/``high`` bound numbers.  ``per_set`` fields describe
    the chosen set's geometry: they start from the file's geometry table of
    that set and are not shown for "every element with geometry".
    """

    name: str
    label: str
    default: str = ""
    kind: str = "number"
    low: float = -math.inf
    high: float = math.inf
    choices: tuple[str, ...] = ()
    optional: bool = False
    per_set: bool = False
    parse: Callable[[str, str], Any] | None = None


@dataclass(frozen=True)
class Tool:
    """A form: title, fields, whether it needs a solved operating point, and its action."""

    name: str
    title: str
    fields: tuple[Field, ...]
    run: Callable[[Context, Mapping[str, Any]], str]
    needs_solution: bool = False
    help: str = ""
    #: The tab of the page it is in: ``"geometry"`` (geometry and rating) or ``"tools"``.  A new form (the
    #: load-capacity rating, the shift map) is one more :data:`TOOLS` entry with its panel.
    panel: str = "tools"
    #: Why the form cannot run on a file (shown in place of its Run button), or None where it can.
    unavailable: Callable[[Context], str | None] | None = None


@dataclass(frozen=True)
class Context:
    """What a tool sees: the file, its solution (for tools that need one) and the gear the page shows."""

    train_file: TrainFile
    solution: Solution | None = None
    gear: str | None = None


#: The set choice that runs a form on every element with a geometry table, as the command line does.
ALL = "every element with geometry"


# ---------------------------------------------------------------------- reading the fields
def read_number(text: str, field: Field, tool: str) -> float:
    """``text`` as a finite number within the field's bounds."""
    where = f"{tool}: {field.label}"
    try:
        value = float(text)
    except ValueError:
        raise ToolError(f"{where}: expected a number, got {text!r}.") from None
    if not math.isfinite(value) or not field.low <= value <= field.high:
        raise ToolError(f"{where}: expected a number from {field.low:g} to {field.high:g}, got {text!r}.")
    if field.kind == "integer" and not value.is_integer():
        raise ToolError(f"{where}: expected a whole number, got {text!r}.")
    return int(value) if field.kind == "integer" else value


def _file_geometry(context: Context) -> Mapping[str, Any]:
    return getattr(context.train_file, "geometry", None) or {}


def _choices(field: Field, context: Context) -> tuple[str, ...]:
    """The options of a choice field: its own, the train's sets (``"set"``) or gears (``"gear"``)."""
    if field.choices == ("set",):
        geometry = _file_geometry(context)
        sets = tuple(s.name for s in context.train_file.train.planetary_sets if s.teeth is not None)
        return ((ALL,) if geometry else ()) + tuple(s for s in sets if s in geometry) + \
            tuple(s for s in sets if s not in geometry)
    if field.choices == ("gear",):
        spec = context.train_file.transmission
        return tuple(spec.gears) if spec is not None else ()
    return field.choices


def _set_defaults(context: Context, name: str) -> dict[str, str]:
    """The per-set fields' starting values from the file's geometry table of set ``name`` (none without one)."""
    geometry = _file_geometry(context).get(name)
    if geometry is None or not hasattr(geometry, "x_sun"):
        return {}
    rack = geometry.rack
    return {"module": f"{rack.module:g}", "pressure_angle": f"{rack.pressure_angle:g}",
            "helix_angle": f"{rack.helix_angle:g}", "x_sun": f"{geometry.x_sun:g}",
            "x_planet": ", ".join(f"{x:g}" for x in geometry.x_planet), "x_ring": f"{geometry.x_ring:g}",
            "load_sharing": "" if geometry.load_sharing is None else f"{geometry.load_sharing:g}"}


def _first_geometry(context: Context) -> Any:
    return next((g for g in _file_geometry(context).values() if hasattr(g, "x_sun")), None)


def _defaults(tool: Tool, context: Context, chosen_set: str | None) -> dict[str, str]:
    """Every field's starting value: the file's where it has one (geometry, planets, gear), else the field's."""
    values = {f.name: f.default for f in tool.fields}
    for f in tool.fields:
        if f.kind == "choice" and f.choices in (("set",), ("gear",)):
            options = _choices(f, context)
            values[f.name] = options[0] if options else ""
    if context.gear and "gear" in values:
        values["gear"] = context.gear
    if chosen_set and "set" in values:
        values["set"] = chosen_set
    chosen = values.get("set")
    if chosen and chosen != ALL:
        values.update({k: v for k, v in _set_defaults(context, chosen).items() if k in values})
    if tool.name == "map":  # the map's default axes in the file's [units], as `epicyclic map` reads them
        from ..io.ranges import default_axis

        units = _units(context)
        values.update(speed=default_axis("speed", units.speed), torque=default_axis("torque", units.torque))
    first = _first_geometry(context)
    if tool.name == "search" and first is not None:  # search near the file's own design
        values.update(module=f"{first.rack.module:g}", pressure_angle=f"{first.rack.pressure_angle:g}",
                      planets=str(first.planetary_set.planets))
    return values


def _units(context: Context):
    from ..units import Units

    return getattr(context.train_file, "units", None) or Units()


def _labelled(tool: Tool, f: Field, context: Context) -> Field:
    """The field with its unit: the map's axes are in the file's ``[units]``."""
    if tool.name == "map" and f.name in ("speed", "torque"):
        unit = _units(context).of(f.name).replace("*", "·")
        return replace(f, label=f"input {f.name}s [{unit}] (A..B:N, or a unit after it)")
    return f


def form_rows(tool: Tool, context: Context, chosen_set: str | None = None) -> list[tuple[Field, str, tuple[str, ...]]]:
    """(field, starting value, options) of each field the form shows for ``chosen_set`` (default: the first)."""
    values = _defaults(tool, context, chosen_set)
    chosen = values.get("set")
    rows = []
    for f in tool.fields:
        if (f.per_set and chosen == ALL) or (f.choices == ("gear",) and not _choices(f, context)):
            continue
        rows.append((_labelled(tool, f, context), values[f.name], _choices(f, context) if f.kind == "choice" else ()))
    return rows


def _parsed(field: Field, text: str, tool: str) -> Any:
    """A text field through its parser (the command line's range grammar); its error is the field's."""
    if field.parse is None:
        return text
    try:
        return field.parse(text, f"{tool}: {field.label}")
    except EpicyclicError as exc:
        raise ToolError(str(exc)) from None


def _read(tool: Tool, given: Mapping[str, str], context: Context) -> dict[str, Any]:
    def text_of(f: Field, defaults: Mapping[str, str]) -> str:
        return (given.get(f"tool_{tool.name}_{f.name}") or "").strip() or defaults[f.name]

    defaults = _defaults(tool, context, None)
    fields = {f.name: f for f in tool.fields}
    if "set" in fields:  # the per-set fields start from the chosen set's geometry
        defaults = _defaults(tool, context, text_of(fields["set"], defaults))
    values: dict[str, Any] = {}
    for f in tool.fields:
        text = text_of(f, defaults)
        if f.kind == "choice":
            choices = _choices(f, context)
            if f.choices == ("gear",) and not choices:
                values[f.name] = None
                continue
            if text not in choices:
                raise ToolError(f"{tool.name}: {f.label}: expected one of "
                                f"{', '.join(repr(c) for c in choices) or '(none)'}, got {text!r}.")
            values[f.name] = text
        elif not text:
            if not f.optional:
                raise ToolError(f"{tool.name}: {f.label}: a value is needed.")
            values[f.name] = None
        elif f.kind == "text":
            values[f.name] = _parsed(f, text, tool.name)
        elif f.kind == "numbers":
            parts = [p for p in text.replace(";", ",").split(",") if p.strip()]
            if not 1 <= len(parts) <= 12:
                raise ToolError(f"{tool.name}: {f.label}: expected 1 to 12 comma-separated values, got {text!r}.")
            values[f.name] = tuple(read_number(p.strip(), f, tool.name) for p in parts)
        else:
            values[f.name] = read_number(text, f, tool.name)
    return values


# ---------------------------------------------------------------------- geometry: fit and forces
def _geometry(context: Context, v: Mapping[str, Any]):
    """The chosen set's geometry: the file's table with the form's values, or built from the form alone."""
    from ..geometry import SetGeometry

    given = _file_geometry(context).get(v["set"])
    x_planet = v["x_planet"] if len(v["x_planet"]) > 1 else v["x_planet"][0]
    shape = dict(x_sun=v["x_sun"], x_planet=x_planet, x_ring=v["x_ring"])
    if given is None:
        return SetGeometry.create(context.train_file.train.element(v["set"]), v["module"],
                                  pressure_angle=v["pressure_angle"], helix_angle=v["helix_angle"], **shape)
    rack = replace(given.rack, module=v["module"], pressure_angle=v["pressure_angle"], helix_angle=v["helix_angle"])
    return replace(given, rack=rack, **shape)


def _chosen(context: Context, v: Mapping[str, Any]) -> Mapping[str, Any]:
    """Element → geometry the form runs on: every element with a table, or the chosen set."""
    return _file_geometry(context) if v["set"] == ALL else {v["set"]: _geometry(context, v)}


def _fit(context: Context, v: Mapping[str, Any]) -> str:
    from ..io.geometry_report import geometry_html, geometry_results

    results = geometry_results(_chosen(context, v), None, planets=v["planets"], allow_unequal=v["unequal"] == "yes",
                               min_clearance=v["min_clearance"], undercut=v["undercut"])
    return geometry_html(results, heading="Geometry and fitting")  # as `epicyclic fit -f html`


def _forces(context: Context, v: Mapping[str, Any]) -> str:
    from ..io.geometry_report import geometry_dict, geometry_html, geometry_results
    from ..io.located import check_finite

    if context.solution is None:
        raise ToolError(f"{context.train_file.source}: [operating_point]: the file has no [operating_point] table, "
                        "so there are no torques for the forces; give an operating point in the form.")
    chosen = dict(_chosen(context, v))
    if v["set"] != ALL and v["load_sharing"] is not None:
        chosen[v["set"]] = replace(chosen[v["set"]], load_sharing=v["load_sharing"])
    # solved with every set of the file, so that a planet the chosen set shares with another is one body
    # the file's loss models belong to the file's geometry: the mesh-loss table only for it, as `epicyclic forces`
    losses = context.train_file.losses if v["set"] == ALL else None
    results = geometry_results({**_file_geometry(context), **chosen}, context.solution, losses=losses)
    results = tuple(r for r in results if r.name in chosen)
    check_finite(geometry_dict(results), context.train_file.source, "forces")
    results = tuple(replace(r, fitting=None) for r in results)  # the forces only, as `epicyclic forces -f html`
    return geometry_html(results, heading="Forces", show_geometry=False)


def _rating_missing(context: Context) -> str | None:
    """What the file lacks for the load-capacity rating, in words (None: it can be rated)."""
    f = context.train_file
    if f.rating is None:
        return (f"{f.source}: the file has no [rating] table, so there is no load capacity to compute; add one "
                "with material, flank_roughness, root_roughness and the lubricant's viscosity_40 (docs/rating.md), "
                "or open the example \"Simple planetary set, 3 planets, rated by ISO 6336:2019\".")
    if not f.geometry:
        return (f"{f.source}: no element has a geometry table; the rating needs module, face width and tooth "
                "counts (see docs/file-format.md).")
    if context.solution is None:
        return (f"{f.source}: [operating_point]: the rating needs the torques of an operating point; give one in "
                "the form.")
    return None


def _rating(context: Context, v: Mapping[str, Any]) -> str:
    """The ISO 6336 rating of every mesh at the page's operating point and gear, as ``epicyclic rate -f html``."""
    from ..rating.train import rate_solution
    from .rating_view import rating_html

    missing = _rating_missing(context)
    if missing:
        raise ToolError(missing)
    f = context.train_file
    return rating_html(rate_solution(context.solution, f.geometry, f.rating, gear=context.gear))


# ---------------------------------------------------------------------- search
def _ratio(text: str, name: str) -> float:
    try:
        ratio = float(text)
    except ValueError:
        raise ToolError(f"{name}: expected a number, got {text!r}.") from None
    if not RATIO_RANGE[0] <= abs(ratio) <= RATIO_RANGE[1]:  # also NaN; as `epicyclic search --ratio`
        raise ToolError(f"{name}: expected a ratio n_driver/n_driven with {RATIO_RANGE[0]:g} <= |ratio| "
                        f"<= {RATIO_RANGE[1]:g}, got {ratio!r}.")
    return ratio


def _range(low: int, high: int) -> Callable[[str, str], tuple[int, int]]:
    def parse(text: str, name: str) -> tuple[int, int]:
        from ..io.ranges import parse_range

        return parse_range(text, name, low, high)

    return parse


def _tolerance(text: str, name: str) -> float:
    from ..io.ranges import parse_tolerance

    return parse_tolerance(text, name)


def search_of(context: Context, v: Mapping[str, Any]):
    """The :class:`~epicyclic.geometry.ToothSearch` of the form's values (as ``epicyclic search``)."""
    from ..geometry import search_teeth

    if len({v["held"], v["driver"], v["driven"]}) < 3:  # as `epicyclic search`
        raise ToolError(f"search: held member {v['held']}, driving member {v['driver']}, driven member "
                        f"{v['driven']}: give three different members (sun, ring, carrier).")
    low, high = v["planets"]
    return search_teeth(
        v["ratio"], held=v["held"], driver=v["driver"], driven=v["driven"], tolerance=v["tolerance"],
        z_sun=v["sun"], z_planet=v["planet"], z_ring=v["ring"], planets=tuple(range(low, high + 1)),
        module=v["module"], pressure_angle=v["pressure_angle"], min_clearance=v["min_clearance"],
        undercut=v["undercut"], interference=v["interference"] == "yes",
    )


def _downloads(tool: str, formats: tuple[str, ...]) -> str:
    buttons = "".join(f'<button type="button" data-download="/download/{tool}.{f}">{f.upper()}</button>'
                      for f in formats)
    return f'<p class="tool-downloads">Download {buttons}</p>'


def _search(context: Context, v: Mapping[str, Any]) -> str:
    import html

    result = search_of(context, v)
    return (f"<p>{len(result)} sets found.</p>" + _downloads("search", ("csv", "json"))
            + f"<pre>{html.escape(result.table(int(v['limit'])))}</pre>")


# ---------------------------------------------------------------------- efficiency map
def map_of(context: Context, v: Mapping[str, Any]):
    """The :class:`~epicyclic.losses.EfficiencyMap` of the form's values (as ``epicyclic map``)."""
    from ..io.ranges import map_grid
    from ..losses.efficiency_map import efficiency_map

    speeds, torques = map_grid(v["speed"], v["torque"], ("map: input speeds", "map: input torques"),
                               units=_units(context))
    return efficiency_map(context.train_file, speeds, torques, gear=v["gear"], direction=v["direction"])


def _map(context: Context, v: Mapping[str, Any]) -> str:
    import html

    from ..plotting import figure_svg

    emap = map_of(context, v)
    if min(len(emap.speeds), len(emap.torques)) < 2:  # a line of points has no contours to draw
        svg = "<p class=\"hint\">No contour picture: it needs at least two speeds and two torques.</p>"
    else:
        figure = emap.plot()
        svg = figure_svg(figure)
        figure.clf()
    note = "" if context.train_file.losses or context.train_file.spin is not None else (
        "<p class=\"hint\">The file has no loss tables: η is the stationary efficiency typed in, the same at every "
        "point. Add [planetary.losses] and [lubricant] to compute it from the geometry (docs/losses.md).</p>")
    return (note + _downloads("map", ("csv", "json", "png")) + f"<pre>{html.escape(emap.table())}</pre>"
            + f'<div class="map-figure">{svg}</div>')


#: Files the tools' results offer: ``<tool>.<format>`` → (media type, function of (context, values)).
TOOL_FILES: dict[str, tuple[str, Callable[[Context, Mapping[str, Any]], str | bytes]]] = {
    "search.csv": ("text/csv; charset=utf-8", lambda c, v: search_of(c, v).to_csv()),
    "search.json": ("application/json", lambda c, v: _json(search_of(c, v).to_dict())),
    "map.csv": ("text/csv; charset=utf-8", lambda c, v: map_of(c, v).to_csv()),
    "map.json": ("application/json", lambda c, v: map_of(c, v).to_json()),
    "map.png": ("image/png", lambda c, v: _png(map_of(c, v).plot())),
}


def _json(data: Any) -> str:
    import json

    return json.dumps(data, indent=2, ensure_ascii=False, allow_nan=False) + "\n"


def _png(figure: Any) -> bytes:
    import io

    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", dpi=150)
    figure.clf()
    return buffer.getvalue()


# ---------------------------------------------------------------------- the forms
_MEMBERS = ("sun", "ring", "carrier")
_YES_NO = ("no", "yes")
_UNDERCUT = ("theoretical", "practical")
_GEOMETRY = (
    Field("set", "planetary set", kind="choice", choices=("set",)),
    Field("module", "module [mm]", "2", low=0.05, high=100, per_set=True),
    Field("pressure_angle", "pressure angle [°]", "20", low=10, high=35, per_set=True),
    Field("helix_angle", "helix angle [°]", "0", low=0, high=45, per_set=True),
    Field("x_sun", "profile shift sun", "0", low=-1.5, high=1.5, per_set=True),
    Field("x_planet", "profile shift planet(s)", "0", kind="numbers", low=-1.5, high=1.5, per_set=True),
    Field("x_ring", "profile shift ring (ISO 21771 sign)", "0", low=-1.5, high=1.5, per_set=True),
)

TOOLS: dict[str, Tool] = {t.name: t for t in (
    Tool("fit", "Fit checks", _GEOMETRY + (
        Field("planets", "planets (empty = the file's)", kind="integer", low=1, high=MAX_PLANETS, optional=True),
        Field("unequal", "accept unequal spacing", "no", kind="choice", choices=_YES_NO),
        Field("min_clearance", "least tip clearance [mm]", "0", low=0, high=1000),
        Field("undercut", "undercut limit", "theoretical", kind="choice", choices=_UNDERCUT),
    ), _fit, panel="geometry", help="Coaxiality, assembly and phasing, neighbours, undercut and interference, each with its fix "
                  "(ISO 21771), as epicyclic fit."),
    Tool("forces", "Tooth and bearing forces", _GEOMETRY + (
        Field("load_sharing", "load sharing K_γ (default by planets)", kind="number", low=1, high=3, optional=True,
              per_set=True),),
        _forces, needs_solution=True, panel="geometry",
        help="Tangential, radial and axial tooth forces, planet bearing and pin loads (× K_γ) at the operating "
             "point, as epicyclic forces."),
    Tool("rating", "Load capacity (ISO 6336)", (), _rating, needs_solution=True, panel="geometry",
         unavailable=_rating_missing,
         help="Pitting and tooth-root safety of every mesh (ISO 6336 method B) with every factor and its clause, "
              "at the operating point and gear shown; a mesh below its minimum safety is marked red, as "
              "epicyclic rate -f html."),
    Tool("search", "Tooth-count search", (
        Field("ratio", "target ratio n_driver/n_driven", "4", kind="text", parse=_ratio),
        Field("tolerance", "tolerance (3% or 0.03)", "1%", kind="text", parse=_tolerance),
        Field("planets", "planets (3..6 or 4)", "3..5", kind="text", parse=_range(1, MAX_PLANETS)),
        Field("module", "module [mm]", "1", low=1e-3, high=100),
        Field("held", "held member", "ring", kind="choice", choices=_MEMBERS),
        Field("driver", "driving member", "sun", kind="choice", choices=_MEMBERS),
        Field("driven", "driven member", "carrier", kind="choice", choices=_MEMBERS),
        Field("sun", "sun teeth (12..80)", "12..80", kind="text", parse=_range(3, 400)),
        Field("planet", "planet teeth", "12..80", kind="text", parse=_range(3, 400)),
        Field("ring", "ring teeth (empty = any)", "", kind="text", optional=True, parse=_range(3, 400)),
        Field("pressure_angle", "pressure angle [°]", "20", low=1, high=44),
        Field("min_clearance", "least tip clearance [mm]", "0", low=0, high=1000),
        Field("undercut", "undercut limit", "theoretical", kind="choice", choices=_UNDERCUT),
        Field("interference", "reject internal interference", "yes", kind="choice", choices=("yes", "no")),
        Field("limit", "rows shown", "20", kind="integer", low=1, high=1000),
    ), _search, help="Simple sets (sun, planet, ring) that give a ratio and fit, ranked (vectorised), "
                     "as epicyclic search."),
    Tool("map", "Efficiency map", (
        Field("speed", "input speeds [1/min] (A..B:N)", "500..6000:50", kind="text"),
        Field("torque", "input torques [N·m] (A..B:N)", "10..500:50", kind="text"),
        Field("gear", "gear", kind="choice", choices=("gear",)),
        Field("direction", "power flow", "drive", kind="choice", choices=("drive", "coast")),
    ), _map, help="η over input speed × torque with the file's loss models, the losses split by source "
                  "(mesh, bearing, drag), as epicyclic map. Coast: driven from the output (engine braking)."),
)}


def run_tool(name: str, given: Mapping[str, str], context: Context) -> str:
    """Read the fields of tool ``name`` from ``given`` and run it; returns HTML.

    Raises
    ------
    ToolError
        Unknown tool, a bad field, or a tool that needs a solution without one.
    EpicyclicError
        From the library (e.g. a set without tooth counts, a load beyond the friction correlation).
    """
    if name not in TOOLS:
        raise ToolError(f"unknown tool {name!r}; tools are {', '.join(TOOLS)}.")
    tool = TOOLS[name]
    return tool.run(context, _read(tool, given, context))


def tool_file(kind: str, given: Mapping[str, str], context: Context) -> tuple[str | bytes, str]:
    """The file ``kind`` (``"map.csv"``, ``"search.json"``, ...) of a tool's result: (body, media type)."""
    if kind not in TOOL_FILES:
        raise ToolError(f"download: no file {kind!r}; files are {', '.join(TOOL_FILES)}.")
    media_type, make = TOOL_FILES[kind]
    tool = TOOLS[kind.split(".")[0]]
    return make(context, _read(tool, given, context)), media_type
