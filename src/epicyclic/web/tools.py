"""Geometry as forms: fit checks, tooth and bearing forces, the tooth-count search.

Each form is one :class:`Tool` in :data:`TOOLS`: its fields (rendered by the
page's template) and a function that reads them, calls :mod:`epicyclic.geometry`
and returns the result's own HTML (``_repr_html_``).  A new form is one more
entry.  Field values arrive as text (``tool_<tool>_<field>`` in the page's
form) and are checked here; a bad value raises :class:`ToolError` naming the
field and the expected range.

Examples
--------
>>> [tool.name for tool in TOOLS.values()]
['fit', 'forces', 'search']
>>> read_number("2.5", Field("module", "module [mm]", "2", low=0.05, high=100), "fit")
2.5
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from ..errors import EpicyclicError

if TYPE_CHECKING:  # pragma: no cover
    from ..io import TrainFile
    from ..results import Solution

__all__ = ["Field", "Tool", "ToolError", "TOOLS", "read_number", "run_tool"]


class ToolError(EpicyclicError, ValueError):
    """A form field of a geometry tool that cannot be used."""


@dataclass(frozen=True)
class Field:
    """One input of a tool form.

    ``kind`` is ``"number"``, ``"integer"``, ``"numbers"`` (comma-separated),
    ``"integers"`` or ``"choice"`` (with ``choices``; ``"set"`` lists the
    train's planetary sets with tooth counts).  ``low``/``high`` bound numbers.
    """

    name: str
    label: str
    default: str = ""
    kind: str = "number"
    low: float = -math.inf
    high: float = math.inf
    choices: tuple[str, ...] = ()
    optional: bool = False


@dataclass(frozen=True)
class Tool:
    """A geometry form: title, fields, whether it needs a solved operating point, and its action."""

    name: str
    title: str
    fields: tuple[Field, ...]
    run: Callable[[Context, Mapping[str, Any]], str]
    needs_solution: bool = False
    help: str = ""


@dataclass(frozen=True)
class Context:
    """What a tool sees: the file and, when the file has an operating point, its solution."""

    train_file: TrainFile
    solution: Solution | None = None


def read_number(text: str, field: Field, tool: str) -> float:
    """``text`` as a finite number within the field's bounds."""
    where = f"{tool}: {field.label}"
    try:
        value = float(text)
    except ValueError:
        raise ToolError(f"{where}: expected a number, got {text!r}.") from None
    if not math.isfinite(value) or not field.low <= value <= field.high:
        raise ToolError(f"{where}: expected a number from {field.low:g} to {field.high:g}, got {text!r}.")
    if field.kind in ("integer", "integers") and not value.is_integer():
        raise ToolError(f"{where}: expected a whole number, got {text!r}.")
    return int(value) if field.kind in ("integer", "integers") else value


def _read(tool: Tool, given: Mapping[str, str], context: Context) -> dict[str, Any]:
    values: dict[str, Any] = {}
    for field in tool.fields:
        text = (given.get(f"tool_{tool.name}_{field.name}") or "").strip() or field.default
        if not text and field.choices == ("set",):
            text = next(iter(_set_choices(context)), "")
        if not text:
            if field.optional:
                values[field.name] = None
                continue
            raise ToolError(f"{tool.name}: {field.label}: a value is needed.")
        if field.kind == "choice":
            choices = _set_choices(context) if field.choices == ("set",) else field.choices
            if text not in choices:
                raise ToolError(f"{tool.name}: {field.label}: expected one of "
                                f"{', '.join(repr(c) for c in choices) or '(none)'}, got {text!r}.")
            values[field.name] = text
        elif field.kind in ("numbers", "integers"):
            parts = [p for p in text.replace(";", ",").split(",") if p.strip()]
            if not 1 <= len(parts) <= 12:
                raise ToolError(f"{tool.name}: {field.label}: expected 1 to 12 comma-separated values, got {text!r}.")
            values[field.name] = tuple(read_number(p.strip(), field, tool.name) for p in parts)
        else:
            values[field.name] = read_number(text, field, tool.name)
    return values


def _set_choices(context: Context) -> tuple[str, ...]:
    return tuple(s.name for s in context.train_file.train.planetary_sets if s.teeth is not None)


#: Choices of where a set's geometry comes from: the file's geometry table of the set when it has one,
#: else (or always, with the second choice) the form's fields.
FROM_FILE, FROM_FORM = "the file's, if it has one", "these fields"


def _geometry(context: Context, v: Mapping[str, Any]):
    from ..geometry import SetGeometry

    given = getattr(context.train_file, "geometry", None) or {}
    if v["source"] == FROM_FILE and v["set"] in given:
        return given[v["set"]]
    pset = context.train_file.train.element(v["set"])
    x_planet = v["x_planet"] if len(v["x_planet"]) > 1 else v["x_planet"][0]
    return SetGeometry.create(pset, v["module"], pressure_angle=v["pressure_angle"], helix_angle=v["helix_angle"],
                              x_sun=v["x_sun"], x_planet=x_planet, x_ring=v["x_ring"])


def _fit(context: Context, v: Mapping[str, Any]) -> str:
    from ..geometry import check_fitting

    geometry = _geometry(context, v)
    planets = None if v["planets"] is None else int(v["planets"])
    return check_fitting(geometry, planets)._repr_html_() + geometry._repr_html_()


def _forces(context: Context, v: Mapping[str, Any]) -> str:
    from ..geometry import planetary_forces

    if context.solution is None:
        raise ToolError("forces: the file has no operating point to take the torques from; give one in the form.")
    return planetary_forces(context.solution, v["set"], _geometry(context, v),
                            load_sharing=v["load_sharing"])._repr_html_()


def _search(context: Context, v: Mapping[str, Any]) -> str:
    from ..geometry import search_teeth

    result = search_teeth(
        v["ratio"], held=v["held"], driver=v["driver"], driven=v["driven"], tolerance=v["tolerance"] / 100,
        z_sun=(int(v["z_sun_min"]), int(v["z_sun_max"])), z_planet=(int(v["z_planet_min"]), int(v["z_planet_max"])),
        planets=tuple(int(n) for n in v["planets"]), module=v["module"],
    )
    return f"<p>{len(result)} sets found.</p>" + result._repr_html_()


_MEMBERS = ("sun", "ring", "carrier")
_GEOMETRY = (
    Field("set", "planetary set", kind="choice", choices=("set",)),
    Field("source", "geometry", FROM_FILE, kind="choice", choices=(FROM_FILE, FROM_FORM)),
    Field("module", "module [mm]", "2", low=0.05, high=100),
    Field("pressure_angle", "pressure angle [°]", "20", low=10, high=35),
    Field("helix_angle", "helix angle [°]", "0", low=0, high=45),
    Field("x_sun", "profile shift sun", "0", low=-1.5, high=1.5),
    Field("x_planet", "profile shift planet(s)", "0", kind="numbers", low=-1.5, high=1.5),
    Field("x_ring", "profile shift ring", "0", low=-1.5, high=1.5),
)

TOOLS: dict[str, Tool] = {t.name: t for t in (
    Tool("fit", "Fit checks", _GEOMETRY + (
        Field("planets", "planets (default: the file's)", kind="integer", low=1, high=40, optional=True),),
        _fit, help="Coaxiality, assembly, neighbours, undercut and interference of one set (ISO 21771)."),
    Tool("forces", "Tooth and bearing forces", _GEOMETRY + (
        Field("load_sharing", "load sharing K_γ (default by planets)", kind="number", low=1, high=3, optional=True),),
        _forces, needs_solution=True,
        help="Tangential, radial and axial tooth forces, planet bearing and pin loads at the operating point."),
    Tool("search", "Tooth-count search", (
        Field("ratio", "target ratio n_driver/n_driven", "4", low=-100, high=100),
        Field("held", "held member", "ring", kind="choice", choices=_MEMBERS),
        Field("driver", "driving member", "sun", kind="choice", choices=_MEMBERS),
        Field("driven", "driven member", "carrier", kind="choice", choices=_MEMBERS),
        Field("tolerance", "tolerance [%]", "1", low=0, high=20),
        Field("z_sun_min", "z sun from", "12", kind="integer", low=3, high=300),
        Field("z_sun_max", "z sun to", "60", kind="integer", low=3, high=300),
        Field("z_planet_min", "z planet from", "12", kind="integer", low=3, high=300),
        Field("z_planet_max", "z planet to", "60", kind="integer", low=3, high=300),
        Field("planets", "planets", "3, 4, 5", kind="integers", low=1, high=40),
        Field("module", "module [mm]", "1", low=0.05, high=100),
    ), _search, help="Simple sets (sun, planet, ring) that give a ratio and fit, ranked (vectorised search)."),
)}


def run_tool(name: str, given: Mapping[str, str], context: Context) -> str:
    """Read the fields of tool ``name`` from ``given`` and run it; returns HTML.

    Raises
    ------
    ToolError
        Unknown tool, a bad field, or a tool that needs a solution without one.
    EpicyclicError
        From :mod:`epicyclic.geometry` (e.g. a set without tooth counts).
    """
    if name not in TOOLS:
        raise ToolError(f"unknown tool {name!r}; tools are {', '.join(TOOLS)}.")
    tool = TOOLS[name]
    return tool.run(context, _read(tool, given, context))


def field_choices(field: Field, context: Context | None) -> tuple[str, ...]:
    """The options of a choice field (the train's sets for ``"set"``)."""
    if field.choices == ("set",):
        return _set_choices(context) if context is not None else ()
    return field.choices
