"""The page's answers, computed in a worker process: read the text, solve, render HTML.

Every function takes plain data (a :class:`~epicyclic.web.state.PageState` or
strings) and returns a :class:`~epicyclic.web.render.Reply` (status, body,
media type), so that it can run in a separate process with a time limit
(:mod:`epicyclic.web.jobs`).  The work itself is the library's:
:func:`epicyclic.io.loads_train_file`, :func:`epicyclic.plotting.figure_subject`
(the state the page shows, as ``epicyclic plot`` draws it), :mod:`epicyclic.io`
reports and tables, :func:`epicyclic.explain.explain`,
:mod:`epicyclic.transmission`, :mod:`epicyclic.plotting` and
:mod:`epicyclic.geometry`; this module only arranges their results in
templates (:mod:`epicyclic.web.render`).

Bad input gives status 422 and the loader's or solver's message (the same
text the command line prints, naming the file and the key), with the line of
the text it points at.
"""

from __future__ import annotations

import functools
import re
import sys
import tomllib
import traceback
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from ..errors import EpicyclicError
from ..io import TrainFile, loads_train_file
from ..units import Units
from .editor import Problem, problem
from .render import Reply, Verbatim, fmt, render
from .state import PageState, default_operating_rows, operating_rows, write_operating_point

if TYPE_CHECKING:  # pragma: no cover
    from ..plotting import Subject

__all__ = ["open_text", "open_file", "apply", "shown_gear", "figure", "save_figure", "tool", "tool_fields", "download"]


# ---------------------------------------------------------------------- reading
class _Bad(Exception):
    """Bad input, with the text it was found in."""

    def __init__(self, problem: Problem, text: str):
        self.problem, self.text = problem, text
        super().__init__(problem.message)


def _load(text: str, source: str) -> TrainFile:
    """The train file of the editor's text, read as the command line reads a file (its size limit too)."""
    from ..io.source import decode_source

    try:
        return loads_train_file(decode_source(text.encode("utf-8", "replace"), source), source=source)
    except EpicyclicError as exc:
        raise _Bad(problem(text, str(exc)), text) from None


def _rewritten(state: PageState) -> str:
    """The text with the form's operating point written into it; the text as it is where the form shows
    the text's own operating point (a change of the gear shown only: the gear is a view, not an edit)."""
    try:
        own = _form(_load(state.text, state.source), state.text)
    except (_Bad, tomllib.TOMLDecodeError, RecursionError):
        own = None
    if own is not None and tuple(state.rows) == tuple(own["rows"]):
        return state.text
    try:
        return write_operating_point(state.text, state.rows, _own_gear(state.text))
    except (tomllib.TOMLDecodeError, RecursionError):
        _load(state.text, state.source)  # raises the loader's message for bad TOML
        raise


def _units(train_file: TrainFile, state: PageState) -> Units:
    from .state import units_of

    return units_of(state.units, train_file.units)


def _subject(train_file: TrainFile, state: PageState) -> Subject:
    """The solved state the page shows, as ``epicyclic plot`` draws it: the file's operating point, or a
    transmission without one at unit input in its first gear; in the units the page shows.

    Raises
    ------
    EpicyclicError
        Located at the file's ``[operating_point]`` or ``[transmission]``; a result that is not a finite
        number is a :class:`~epicyclic.errors.NonFiniteResultError` naming it.
    """
    from ..io.json_report import report_data
    from ..io.located import check_finite, locate_error
    from ..plotting import figure_subject

    try:
        subject = figure_subject(train_file, _view_gear(train_file, state))
    except EpicyclicError as exc:
        raise locate_error(exc, state.source, train_file.operating_point, f"[{_table(train_file)}]") from None
    check_finite(report_data(subject.solution, train_file.units), state.source)
    return replace(subject, context=replace(subject.context, units=_units(train_file, state)))


def _view_gear(train_file: TrainFile, state: PageState) -> str | None:
    """The gear the page shows: the one chosen on the page (a view, like the units: never written into the
    text), where the file's transmission has it; else None (the file's own)."""
    spec = train_file.transmission
    return state.gear if spec is not None and state.gear in spec.gears else None


def _own_gear(text: str) -> str:
    """The ``gear`` the text's own ``[operating_point]`` names ("" for none)."""
    try:
        point = tomllib.loads(text).get("operating_point", {})
    except (tomllib.TOMLDecodeError, RecursionError):
        return ""
    gear = point.get("gear", "") if isinstance(point, dict) else ""
    return gear if isinstance(gear, str) else ""


def _shown(train_file: TrainFile, state: PageState) -> Subject:
    """:func:`_subject` with its errors as :class:`_Bad` at their line (for pictures, forms and downloads)."""
    try:
        return _subject(train_file, state)
    except EpicyclicError as exc:
        raise _Bad(problem(state.text, str(exc), fallback=_table(train_file)), state.text) from None


def _table(train_file: TrainFile) -> str:
    """The table a solver error is about: ``[transmission]`` for a transmission without operating point."""
    gearbox = train_file.operating_point is None and train_file.transmission is not None
    return "transmission" if gearbox else "operating_point"


def _transmission(train_file: TrainFile) -> Any:
    """The file's transmission with its loss models, as ``epicyclic gears`` reads it."""
    from ..transmission import Transmission

    return Transmission.from_train_file(train_file)


def _default_point(train_file: TrainFile, gear: str) -> str:
    """What the page says about a transmission without operating point."""
    from ..transmission import DEFAULT_INPUT_SPEED, DEFAULT_INPUT_TORQUE

    spec, units = train_file.transmission, train_file.units
    level = (f"{DEFAULT_INPUT_SPEED:g} 1/min with {DEFAULT_INPUT_TORQUE:g} N·m" if units == Units() else
             f"{DEFAULT_INPUT_SPEED:g} 1/min ({fmt(units.speed_from_core(DEFAULT_INPUT_SPEED))} {units.speed}) with "
             f"{DEFAULT_INPUT_TORQUE:g} N·m ({fmt(units.torque_from_core(DEFAULT_INPUT_TORQUE))} {units.torque})")
    losses = (" The efficiencies come from the file's loss models and depend on this level." if train_file.losses
              else " Ratios, efficiencies and multiples of the input do not depend on it.")
    return (f"The file has no [operating_point]: the page shows gear {gear} at the default operating point, as "
            f"`epicyclic gears` and `epicyclic plot` use it: {spec.input!r} driven at {level}, {spec.output!r} "
            f"loaded.{losses} Give an operating point in the form to see your own speeds, torques and powers.")


def _gear_level(train_file: TrainFile) -> str:
    """The input point the gear table is analysed at, in words (as ``epicyclic gears`` states it)."""
    from ..errors import EpicyclicError
    from ..transmission.input_point import input_point

    if train_file.transmission is None:
        return ""
    try:
        return input_point(train_file.transmission.input, train_file.operating_point, units=train_file.units).describe()
    except EpicyclicError:  # the gear table reports the error itself
        return ""


# ---------------------------------------------------------------------- the results section
def _results(train_file: TrainFile, state: PageState, charts: bool = True) -> dict[str, Any]:
    """What the results section shows; with ``charts``, the pictures the browser draws as their data
    (:mod:`epicyclic.web.charts`), else every picture is drawn by the server."""
    from ..explain import explain
    from ..io.tables import report_tables, summary_lines
    from .figures import applicable
    from .summary import circulation_view, gear_table, key_figures, loss_split, other_warnings, power_state
    from .tools import TOOLS, Context, form_rows

    units = _units(train_file, state)
    subject = solve_problem = None
    notices: list[str] = []
    if train_file.operating_point is not None or train_file.transmission is not None:
        try:
            subject = _subject(train_file, state)
        except EpicyclicError as exc:
            solve_problem = problem(state.text, str(exc), fallback=_table(train_file))
    solution = subject.solution if subject is not None else None
    if subject is not None and train_file.operating_point is None:
        notices.append(_default_point(train_file, subject.gear))
    transmission = subject.transmission if subject is not None else None
    gear = subject.gear if subject is not None else train_file.gear
    result: dict[str, Any] = {
        "title": train_file.title, "description": train_file.description, "units": units,
        "notices": notices, "solution": solution, "solve_problem": solve_problem,
        "gears": None, "tools": list(TOOLS.values()), "tool_context": Context(train_file, solution, gear),
        "form_rows": form_rows, "figures": [], "charts": {}, "lang": state.lang, "explanation": None,
        "loss_split": None,
        "gear_name": gear if train_file.transmission is not None else None,
        "has_transmission": train_file.transmission is not None, "has_losses": bool(train_file.losses),
        "gear_level": _gear_level(train_file),
    }
    if train_file.transmission is not None:
        # with the file's loss models and at its operating point, as ``epicyclic gears`` computes it
        gears = gear_table(transmission or (lambda: _transmission(train_file)), gear, state.source,
                           train_file.operating_point)
        gears["problem"] = problem(state.text, gears["error"]) if gears["error"] else None
        same = solve_problem is not None and gears["error"] == solve_problem.message  # said once, above
        result["gears"] = None if same else gears
    result["problem"] = solve_problem or (result["gears"] or {}).get("problem")  # marked in the editor
    if subject is not None:
        shafts, elements = report_tables(solution, units)
        lines = summary_lines(solution, units)
        result.update(
            shafts=shafts, elements=elements, summary=lines,
            key_figures=key_figures(solution, units, lines),
            power_state=power_state(solution, units),
            circulation=circulation_view(solution, units),
            warnings=other_warnings(solution),
            figures=[(k, k.options(subject)) for k in applicable(subject)],
            charts=_charts(subject) if charts else {},
            explanation=explain(solution, units, lang=state.lang, title=train_file.title, losses=train_file.losses,
                                spin=train_file.spin, gear=train_file.gear,
                                input=None if train_file.transmission is None else train_file.transmission.input
                                ).html(),
            loss_split=loss_split(solution, units) if train_file.losses or train_file.spin else None,
        )
    return result


def _charts(subject: Subject) -> dict[str, str]:
    from .charts import chart_specs

    return chart_specs(subject)


def _status(results: dict[str, Any]) -> int:
    """422 when the state cannot be shown or a gear of the table fails, else 200."""
    return 422 if results["problem"] is not None else 200


# ---------------------------------------------------------------------- answers
def _guard(action):
    """Turn bad input into 422 with its message and anything else into 500 (logged), like the CLI."""
    @functools.wraps(action)  # keeps the qualified name: the worker pool pickles the function by name
    def wrapper(*args: Any, **kwargs: Any) -> Reply:
        out_of_memory = False
        try:
            return action(*args, **kwargs)
        except _Bad as bad:
            return Reply(render("problem.html", problem=bad.problem, text=bad.text, oob=True), 422)
        except EpicyclicError as exc:
            return Reply(render("problem.html", problem=Problem(str(exc)), text=None, oob=True), 422)
        except MemoryError:
            out_of_memory = True  # raised again below, once this exception and its frames are gone
        except Exception as exc:  # a bug: say so, keep serving
            traceback.print_exc(file=sys.stderr)
            message = (f"internal error: {type(exc).__name__}: {exc}. This is a bug in epicyclic; please report "
                       "it with the train description.")
            return Reply(render("problem.html", problem=Problem(message), text=None, oob=True), 500)
        if out_of_memory:  # the worker's memory limit: the pool says so (epicyclic.web.jobs)
            _release_memory()
            raise MemoryError("the computation needed more memory than the worker may use")
        raise AssertionError("unreachable")  # pragma: no cover

    return wrapper


def _release_memory() -> None:
    """Give back what a computation that ran out of memory left: its arrays (the exception's frames held them,
    now gone), Python's cycles, and the C allocator's free pages (glibc ``malloc_trim``), so that the worker's
    next job starts from its usual size, not at the limit (no false 507 after a refusal)."""
    import ctypes
    import ctypes.util
    import gc

    gc.collect()
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
        libc.malloc_trim(0)
    except (OSError, AttributeError):  # pragma: no cover - not glibc: Python's collection is all there is
        pass


def _form(train_file: TrainFile, text: str, state: PageState | None = None) -> dict[str, Any]:
    """The operating-point form of a text: its ``[operating_point]``, or unit input for a transmission without;
    the gear the page shows (``state.gear`` where the transmission has it); the placeholders and hints in the
    units the page shows."""
    spec = train_file.transmission
    shafts = train_file.train.moving_shafts
    if train_file.operating_point is None and spec is not None:
        rows = default_operating_rows(shafts, spec.input, spec.output)
        gear = spec.gears[0]
    else:
        rows, gear = operating_rows(tomllib.loads(text), shafts), train_file.gear or ""
    shown = _view_gear(train_file, state) if state is not None else None
    return {"rows": rows, "gear_names": spec.gears if spec else (), "gear": shown or gear,
            "file_units": train_file.units,
            "shown_units": _units(train_file, state) if state is not None else train_file.units}


def _next_gears(form: dict[str, Any], results: dict[str, Any]) -> tuple[str, ...]:
    """The gears the page shows after a click on another gear, nearest first: the server draws their
    pictures ahead while it is idle (the text stays, the gear is the page's view)."""
    gears, current = list(form["gear_names"]), form["gear"]
    if not gears or results["problem"] is not None or current not in gears:
        return ()
    here = gears.index(current)
    return tuple(sorted((g for g in gears if g != current), key=lambda g: (abs(gears.index(g) - here), gears.index(g))))


#: Where the answer to a file that cannot be read at all goes: above the results, so that the file that
#: is open stays with its editor, form and tabs (htmx response headers).
_BESIDE = (("HX-Retarget", "#results"), ("HX-Reswap", "afterbegin"))


def shown_gear(text: str, source: str) -> str:
    """The gear the page shows first for ``text`` (the file's, or a transmission's first; "" for none or a
    text that cannot be read): what the page's form sends with its picture requests."""
    try:
        return _form(_load(text, source), text)["gear"]
    except (_Bad, tomllib.TOMLDecodeError, RecursionError, EpicyclicError):
        return ""


@_guard
def open_file(data: bytes, source: str, units: str = "file", lang: str = "en", charts: bool = True,
              rows: tuple = (), gear: str = "", example: str = "") -> Reply:
    """:func:`open_text` of an uploaded file, read as the command line reads one (size, NUL bytes, UTF-8).

    A REXS file (XML, JSON or zip, by content) opens as the commented TOML that ``epicyclic convert`` writes.
    A file that gives no text at all (a malformed REXS file, bytes that are no UTF-8) is refused with its
    message above the results, and the file that was open stays (its editor, form and tabs).
    """
    from ..io.source import decode_source, sniff

    try:
        if sniff(data[:4096]) is not None:
            from ..exchange.convert import toml_text
            from ..exchange.reading import loads_rexs_document
            from ..io.toml_format import read_document

            text = toml_text(read_document(loads_rexs_document(data, source)))
        else:
            text = decode_source(data, source)
    except EpicyclicError as exc:
        message = f"{exc} The file was not opened; the page still shows the file that was open."
        return Reply(render("problem.html", problem=Problem(message), text=None, oob=False), 422, headers=_BESIDE)
    return open_text(text, source, units, lang, rows, gear, charts=charts, example=example)


def _line_ending(text: str) -> str:
    """``"crlf"`` for a text written with Windows line endings, else ``"lf"`` (the editor shows LF)."""
    return "crlf" if "\r\n" in text else "lf"


def _restored(text: str, source: str, rows: tuple) -> str:
    """``text`` with the operating point of the address written in, unchanged where it is the text's own (the
    address's gear is the page's view, never written)."""
    try:
        own = _form(_load(text, source), text)
    except (_Bad, tomllib.TOMLDecodeError, RecursionError):
        return text  # the text's own error is shown
    if not rows or tuple(rows) == tuple(own["rows"]):
        return text
    return write_operating_point(text, rows, _own_gear(text))


@_guard
def open_text(text: str, source: str, units: str = "file", lang: str = "en", rows: tuple = (),
              gear: str = "", charts: bool = True, example: str = "") -> Reply:
    """The whole workspace (editor, operating-point form, results) for a newly opened text.

    ``rows`` and ``gear`` (from a shared link or a reload: the URL holds them) are written into the
    text's ``[operating_point]`` as the form would write them; ``charts``: the browser draws the charts
    (:mod:`epicyclic.web.charts`); ``example``: the key of the bundled example opened (empty for a file
    of one's own, whatever its name), which the page's address names.
    """
    eol = _line_ending(text)
    text = text.replace("\r\n", "\n")
    if rows:
        text = _restored(text, source, tuple(rows))
    state = PageState(text, source, units=units, lang=lang, eol=eol, gear=gear)
    try:
        train_file = _load(text, source)
    except _Bad as bad:
        return Reply(render("workspace.html", text=Verbatim(text), source=source, rows=(), gear_names=(), gear="",
                            file_units=Units(), problem=bad.problem, results=None, eol=eol, example=example), 422)
    results = _results(train_file, state, charts)
    form = _form(train_file, text, state)
    return Reply(render("workspace.html", text=Verbatim(text), source=source, problem=None, results=results,
                        eol=eol, example=example, **form), _status(results), next_gears=_next_gears(form, results),
                 next_text=text)


@_guard
def apply(state: PageState, origin: str, charts: bool = True) -> Reply:
    """Results after a change: of the text (``origin="text"``) or of the operating-point form (``"form"``).

    The answer is the results section; after a text change also the new form,
    after a form change also the rewritten text (out-of-band swaps).
    """
    original = state.text
    text = _rewritten(state) if origin == "form" else state.text
    state = replace(state, text=text)
    swap_text = text != original
    try:
        train_file = _load(text, state.source)
    except _Bad as bad:
        return Reply(render("apply.html", problem=bad.problem, results=None, text=Verbatim(text),
                            swap_text=swap_text, swap_form=False), 422)
    results = _results(train_file, state, charts)
    form = _form(train_file, text, state)
    return Reply(render("apply.html", problem=None, results=results, text=Verbatim(text), swap_text=swap_text,
                        swap_form=origin == "text", **form), _status(results), next_gears=_next_gears(form, results),
                 next_text=text)


def _picture(state: PageState, name: str):
    """(kind, Picture) of picture ``name`` of the state the page shows."""
    from .figures import FIGURES, Picture, read_settings

    kind = FIGURES[name]
    settings = read_settings(kind, state.extra)
    return kind, Picture(_shown(_load(state.text, state.source), state), settings)


def _drawn(state: PageState, draw: Any, *args: Any) -> Any:
    """``draw(*args)`` with the library's errors (a chart without transmission, an unknown set) naming the file."""
    from ..io.located import located

    try:
        return draw(*args)
    except EpicyclicError as exc:
        raise located(exc, state.source) from None


def _no_such_picture(name: str) -> Reply:
    from .figures import FIGURES

    message = f"no picture {name!r}; pictures are {', '.join(FIGURES)}."
    return Reply(render("problem.html", problem=Problem(message), text=None, oob=False), 404)


@_guard
def figure(state: PageState, name: str) -> Reply:
    """One picture (inline SVG in a figure element) of the state the page shows."""
    from .figures import FIGURES, inline_svg

    if name not in FIGURES:
        return _no_such_picture(name)
    kind, picture = _picture(state, name)
    return Reply(render("figure.html", kind=kind, svg=_drawn(state, inline_svg, kind, picture)))


@_guard
def save_figure(state: PageState, name: str) -> Reply:
    """One picture as a file (SVG, PNG or PDF; the animation as HTML, SVG or GIF)."""
    from .figures import FIGURES, MEDIA_TYPES, save

    if name not in FIGURES:
        return _no_such_picture(name)
    kind, picture = _picture(state, name)
    suffix = picture.settings.format
    title = picture.subject.context.title
    return Reply(_drawn(state, save, kind, picture), media_type=MEDIA_TYPES[suffix],
                 filename=_file_name(title, state.source, f"-{name}.{suffix}"))


def _tool_context(state: PageState, name: str) -> Any:
    """The file (and, for a tool that needs it, the solved state the page shows) a tool runs on."""
    from .tools import TOOLS, Context, ToolError

    if name not in TOOLS:
        raise ToolError(f"unknown tool {name!r}; tools are {', '.join(TOOLS)}.")
    train_file = _load(state.text, state.source)
    solution = gear = None
    if TOOLS[name].needs_solution and (train_file.operating_point is not None or train_file.transmission is not None):
        subject = _shown(train_file, state)
        solution, gear = subject.solution, subject.gear
    return Context(train_file, solution, gear or state.gear or train_file.gear)


def _run(state: PageState, work: Any, *args: Any) -> Any:
    """``work(*args)`` with the library's errors located in the file as the command line locates them
    (``error: FILE: [where]: message``) and marked at their line in the editor; a bad field of the form
    (:class:`~epicyclic.web.tools.ToolError`) is said as it is."""
    from ..io.located import locate_error
    from .tools import ToolError

    try:
        return work(*args)
    except ToolError:
        raise  # a field of the form, not the file
    except EpicyclicError as exc:
        message = str(locate_error(exc, state.source))
        raise _Bad(problem(state.text, message), state.text) from None


@_guard
def tool(state: PageState, name: str) -> Reply:
    """The result of a tool's form (fit, forces, search, map)."""
    from .tools import run_tool

    context = _tool_context(state, name)
    return Reply(render("tool_result.html", body=_run(state, run_tool, name, state.extra, context)))


@_guard
def tool_fields(state: PageState, name: str) -> Reply:
    """A tool's fields again, starting from the geometry of the set chosen in the form."""
    from .tools import TOOLS, form_rows

    context = _tool_context(state, name)
    chosen = state.extra.get(f"tool_{name}_set")
    return Reply(render("tool_fields.html", tool=TOOLS[name], rows=form_rows(TOOLS[name], context, chosen)))


_DOWNLOADS = {"json": "application/json", "html": "text/html; charset=utf-8", "toml": "application/toml",
              "gears": "text/html; charset=utf-8"}


def _file_name(title: str, source: str, suffix: str) -> str:
    base = source[:-5] if source.endswith(".toml") else title
    slug = re.sub(r"[^A-Za-z0-9_-]+", "_", base).strip("_")[:60] or "epicyclic"
    return f"{slug}{suffix}"


def _gears_report(train_file: TrainFile, state: PageState) -> str:
    from ..io.gears_report import gears_html
    from .summary import gear_table

    if train_file.transmission is None:
        raise EpicyclicError(f"{state.source}: the gears report needs a [transmission] table with a schedule.")
    table = gear_table(lambda: _transmission(train_file), None, state.source, train_file.operating_point)
    if table["error"]:
        raise _Bad(problem(state.text, table["error"]), state.text)
    return gears_html(table["transmission"], table["analysis"], _units(train_file, state),
                      title=train_file.title or None, source=state.source)


@_guard
def download(state: PageState, kind: str) -> Reply:
    """The TOML text, the JSON report, the HTML report or the gears report as a file."""
    from ..io.html_report import html_report
    from ..io.json_report import json_report

    from .tools import TOOL_FILES, tool_file

    if kind in TOOL_FILES:  # a tool's result as a file: search.csv, map.json, ...
        train_file = _load(state.text, state.source)
        body, media_type = _run(state, tool_file, kind, state.extra, _tool_context(state, kind.split(".")[0]))
        return Reply(body, media_type=media_type, filename=_file_name(train_file.title, state.source,
                                                                      "-" + kind))
    if kind not in _DOWNLOADS:
        raise EpicyclicError(f"download: kind must be one of {', '.join((*_DOWNLOADS, *TOOL_FILES))}, got {kind!r}.")
    if kind == "toml":
        title = "epicyclic"
        try:
            title = tomllib.loads(state.text).get("title", title)
        except (tomllib.TOMLDecodeError, RecursionError):
            pass
        text = state.text.replace("\r\n", "\n")  # the user's line endings, as the file was opened
        return Reply(text.replace("\n", "\r\n") if state.eol == "crlf" else text, media_type=_DOWNLOADS[kind],
                     filename=_file_name(str(title), state.source, ".toml"))
    train_file = _load(state.text, state.source)
    name = _file_name(train_file.title, state.source, ".gears.html" if kind == "gears" else f".{kind}")
    if kind == "gears":
        return Reply(_gears_report(train_file, state), media_type=_DOWNLOADS[kind], filename=name)
    subject = _shown(train_file, state)
    units = subject.context.units
    if kind == "json":
        body = json_report(subject.solution, units, title=train_file.title, source=state.source)
    else:
        description = " ".join(filter(None, (train_file.description, *subject.context.notes)))
        body = html_report(subject.solution, units, title=train_file.title, source=state.source,
                           description=description, lang=state.lang, geometry=subject.context.geometry,
                           losses=train_file.losses, spin=train_file.spin)
    return Reply(body, media_type=_DOWNLOADS[kind], filename=name)
