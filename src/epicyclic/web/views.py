"""The page's answers, computed in a worker process: read the text, solve, render HTML.

Every function takes plain data (a :class:`~epicyclic.web.state.PageState` or
strings) and returns a :class:`Reply` (status, body, media type), so that it
can run in a separate process with a time limit (:mod:`epicyclic.web.jobs`).
The work itself is the library's: :func:`epicyclic.io.loads_train_file`,
:meth:`TrainFile.solve`, :mod:`epicyclic.io` reports and tables,
:func:`epicyclic.explain.explain`, :mod:`epicyclic.transmission`,
:mod:`epicyclic.plotting` and :mod:`epicyclic.geometry`; this module only
arranges their results in templates (Jinja2, every value escaped).

Bad input gives status 422 and the loader's or solver's message (the same
text the command line prints), with the line of the text it points at.
"""

from __future__ import annotations

import functools
import re
import sys
import tomllib
import traceback
from dataclasses import dataclass, replace
from functools import lru_cache
from typing import Any

from ..errors import EpicyclicError
from ..io import TrainFile, loads_train_file
from ..units import Units
from .editor import Problem, problem
from .state import PageState, default_operating_rows, operating_rows, write_operating_point

__all__ = ["Reply", "open_text", "apply", "figure", "tool", "download", "render"]

HTML = "text/html; charset=utf-8"


@dataclass(frozen=True)
class Reply:
    """An answer for the browser: body, HTTP status, media type and, for downloads, a file name."""

    body: str | bytes
    status: int = 200
    media_type: str = HTML
    filename: str | None = None


@lru_cache(maxsize=1)
def environment() -> Any:
    """The Jinja2 environment of the page's templates (autoescaping on)."""
    import jinja2

    env = jinja2.Environment(loader=jinja2.PackageLoader("epicyclic.web", "templates"),
                             autoescape=True, undefined=jinja2.StrictUndefined, trim_blocks=True,
                             lstrip_blocks=True)
    env.globals["fmt"] = _fmt
    return env


def render(template: str, **context: Any) -> str:
    """Render a template of ``epicyclic/web/templates``."""
    return environment().get_template(template).render(**context)


def _fmt(value: float | None, digits: int = 4) -> str:
    from ..io.tables import fmt

    return fmt(value, digits)


# ---------------------------------------------------------------------- reading
class _Bad(Exception):
    """Bad input, with the text it was found in."""

    def __init__(self, problem: Problem, text: str):
        self.problem, self.text = problem, text
        super().__init__(problem.message)


def _load(text: str, source: str) -> TrainFile:
    try:
        return loads_train_file(text, source=source)
    except EpicyclicError as exc:
        raise _Bad(problem(text, str(exc)), text) from None
    except RecursionError:  # the TOML parser recurses once per level of nested arrays or inline tables
        raise _Bad(Problem(f"{source}: the text nests arrays or tables too deeply to be read; a train description "
                           "needs at most a few levels."), text) from None


def _proposed(text: str, source: str) -> tuple[str, list[str]]:
    """``text`` with a proposed operating point if it describes a transmission without one."""
    try:
        data = tomllib.loads(text)
    except (tomllib.TOMLDecodeError, RecursionError):
        return text, []
    spec = data.get("transmission")
    if "operating_point" in data or not isinstance(spec, dict):
        return text, []
    train_file = _load(text, source)
    if train_file.transmission is None:
        return text, []
    t = train_file.transmission
    rows = default_operating_rows(train_file.train.moving_shafts, t.input, t.output)
    notice = (f"The file has no [operating_point]; the page proposes one: input {t.input!r} driven at "
              f"1000 1/min with 100 N·m, output {t.output!r} loaded, gear {t.gears[0]!r}. Change it in the form.")
    return write_operating_point(text, rows, t.gears[0]), [notice]


def _rewritten(state: PageState) -> str:
    """The text with the form's operating point written into it."""
    try:
        return write_operating_point(state.text, state.rows, state.gear)
    except (tomllib.TOMLDecodeError, RecursionError):
        _load(state.text, state.source)  # raises the loader's message for bad TOML
        raise


def _units(train_file: TrainFile, state: PageState) -> Units:
    return train_file.units if state.units == "file" else Units()


# ---------------------------------------------------------------------- the results section
def _transmission(train_file: TrainFile):
    from ..transmission import Transmission

    spec = train_file.transmission
    return Transmission(train_file.train, dict(spec.schedule), spec.input, spec.output, name=train_file.title)


def _gears(train_file: TrainFile) -> dict[str, Any] | None:
    """The gear table of a transmission, or its error message."""
    if train_file.transmission is None:
        return None
    try:
        analysis = _transmission(train_file).analyze_all()
    except EpicyclicError as exc:
        return {"error": str(exc), "rows": [], "current": None}
    # the transmission's own table (its header and formatted rows), one row per gear in schedule order
    rows = [(g.gear, cells) for g, cells in zip(analysis.gears, analysis._rows())]
    current = next((g for g in analysis.gears if g.gear == train_file.gear), None)
    return {"error": None, "header": analysis.HEADER, "rows": rows, "footer": analysis._footer(),
            "current": current, "current_name": train_file.gear}


def _results(train_file: TrainFile, state: PageState, notices: list[str]) -> dict[str, Any]:
    from ..explain import explain
    from ..io.tables import report_tables, summary_lines
    from .figures import applicable
    from .tools import TOOLS, Context, field_choices

    units = _units(train_file, state)
    solution = None
    solve_problem = None
    if train_file.operating_point is not None:
        try:
            solution = train_file.solve()
        except EpicyclicError as exc:
            solve_problem = problem(state.text, str(exc), fallback="operating_point")
    context = Context(train_file, solution)
    result: dict[str, Any] = {
        "title": train_file.title, "description": train_file.description, "units": units,
        "notices": notices, "solution": solution, "solve_problem": solve_problem,
        "gears": _gears(train_file), "tools": list(TOOLS.values()), "tool_context": context,
        "field_choices": field_choices, "figures": [], "lang": state.lang, "explanation": None,
    }
    if solution is not None:
        shafts, elements = report_tables(solution, units)
        result.update(
            shafts=shafts, elements=elements, summary=summary_lines(solution, units),
            figures=[(k, k.options(solution)) for k in applicable(solution)],
            explanation=explain(solution, units, lang=state.lang, title=train_file.title).html(),
        )
    return result


# ---------------------------------------------------------------------- answers
def _guard(action):
    """Turn bad input into 422 with its message and anything else into 500 (logged), like the CLI."""
    @functools.wraps(action)  # keeps the qualified name: the worker pool pickles the function by name
    def wrapper(*args: Any, **kwargs: Any) -> Reply:
        try:
            return action(*args, **kwargs)
        except _Bad as bad:
            return Reply(render("problem.html", problem=bad.problem, text=bad.text, oob=True), 422)
        except EpicyclicError as exc:
            return Reply(render("problem.html", problem=Problem(str(exc)), text=None, oob=True), 422)
        except Exception as exc:  # a bug: say so, keep serving
            traceback.print_exc(file=sys.stderr)
            message = (f"internal error: {type(exc).__name__}: {exc}. This is a bug in epicyclic; please report "
                       "it with the train description.")
            return Reply(render("problem.html", problem=Problem(message), text=None, oob=True), 500)

    return wrapper


@_guard
def open_text(text: str, source: str, units: str = "file", lang: str = "en") -> Reply:
    """The whole workspace (editor, operating-point form, results) for a newly opened text."""
    state = PageState(text, source, units=units, lang=lang)
    notices: list[str] = []
    try:
        text, notices = _proposed(text, source)
        state = replace(state, text=text)
        train_file = _load(text, source)
    except _Bad as bad:
        return Reply(render("workspace.html", text=text, source=source, rows=(), gear_names=(), gear="",
                            file_units=Units(), problem=bad.problem, results=None), 422)
    return Reply(render("workspace.html", text=text, source=source, problem=None,
                        results=_results(train_file, state, notices), **_form(train_file, text)))


def _form(train_file: TrainFile, text: str) -> dict[str, Any]:
    data = tomllib.loads(text)
    spec = train_file.transmission
    return {"rows": operating_rows(data, train_file.train.moving_shafts),
            "gear_names": spec.gears if spec else (), "gear": train_file.gear or "", "file_units": train_file.units}


@_guard
def apply(state: PageState, origin: str) -> Reply:
    """Results after a change: of the text (``origin="text"``) or of the operating-point form (``"form"``).

    The answer is the results section; after a text change also the new form,
    after a form change also the rewritten text (out-of-band swaps).
    """
    original = state.text
    if origin == "form":
        text, notices = _rewritten(state), []
    else:
        text, notices = _proposed(state.text, state.source)
    state = replace(state, text=text)
    swap_text = text != original
    try:
        train_file = _load(text, state.source)
    except _Bad as bad:
        return Reply(render("apply.html", problem=bad.problem, results=None, text=text, swap_text=swap_text,
                            swap_form=False), 422)
    results = _results(train_file, state, notices)
    status = 422 if results["solve_problem"] is not None else 200
    return Reply(render("apply.html", problem=None, results=results, text=text, swap_text=swap_text,
                        swap_form=origin == "text", **_form(train_file, text)), status)


@_guard
def figure(state: PageState, kind: str, option: str | None = None) -> Reply:
    """One picture (inline SVG in a figure element) of the solved text."""
    from .figures import FIGURES, Picture, draw

    if kind not in FIGURES:
        return Reply(render("problem.html", problem=Problem(f"no picture {kind!r}; pictures are "
                                                            f"{', '.join(FIGURES)}."), text=None, oob=False), 404)
    train_file = _load(state.text, state.source)
    solution = train_file.solve()
    svg = draw(kind, Picture(solution, train_file, option or None))
    return Reply(render("figure.html", kind=FIGURES[kind], svg=svg))


@_guard
def tool(state: PageState, name: str) -> Reply:
    """The result of a geometry form."""
    from .tools import Context, run_tool

    train_file = _load(state.text, state.source)
    solution = None
    if train_file.operating_point is not None:
        solution = train_file.solve()
    body = run_tool(name, state.extra, Context(train_file, solution))
    return Reply(render("tool_result.html", body=body))


_DOWNLOADS = {"json": "application/json", "html": "text/html; charset=utf-8", "toml": "application/toml"}


def _file_name(train_file_title: str, source: str, suffix: str) -> str:
    base = source[:-5] if source.endswith(".toml") else train_file_title
    slug = re.sub(r"[^A-Za-z0-9_-]+", "_", base).strip("_")[:60] or "epicyclic"
    return f"{slug}{suffix}"


@_guard
def download(state: PageState, kind: str) -> Reply:
    """The TOML text, the JSON report or the HTML report as a file."""
    from ..io.html_report import html_report
    from ..io.json_report import json_report

    if kind not in _DOWNLOADS:
        raise EpicyclicError(f"download: kind must be one of {', '.join(_DOWNLOADS)}, got {kind!r}.")
    if kind == "toml":
        title = "epicyclic"
        try:
            title = tomllib.loads(state.text).get("title", title)
        except (tomllib.TOMLDecodeError, RecursionError):
            pass
        return Reply(state.text, media_type=_DOWNLOADS[kind],
                     filename=_file_name(str(title), state.source, ".toml"))
    train_file = _load(state.text, state.source)
    solution = train_file.solve()
    units = _units(train_file, state)
    if kind == "json":
        body = json_report(solution, units, title=train_file.title, source=state.source)
    else:
        body = html_report(solution, units, title=train_file.title, source=state.source,
                           description=train_file.description, lang=state.lang)
    return Reply(body, media_type=_DOWNLOADS[kind], filename=_file_name(train_file.title, state.source, f".{kind}"))

