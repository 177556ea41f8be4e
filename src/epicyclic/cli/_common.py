"""Shared pieces of the sub-commands: error handling, exit codes, output.

Exit codes: 0 success, 2 bad input (one paragraph on stderr, no traceback),
1 internal error (a bug: one paragraph asking for a report; set
``EPICYCLIC_DEBUG=1`` to see the traceback).
"""

from __future__ import annotations

import functools
import os
import sys
import warnings
from collections.abc import Callable
from enum import Enum
from pathlib import Path
from typing import Annotated, Any, Optional, TypeVar

import typer
from typer.core import TyperGroup

from ..errors import EpicyclicError

__all__ = ["EXIT_OK", "EXIT_INTERNAL", "EXIT_BAD_INPUT", "EXIT_BELOW_MINIMUM", "OutputFormat", "FormatOption", "OutOption",
           "SetOption", "guarded", "emit", "say", "fail", "check_finite", "load", "solved", "report_title",
           "OneLineErrors"]

EXIT_OK = 0
EXIT_INTERNAL = 1
EXIT_BAD_INPUT = 2
#: ``--strict``: the design is below a minimum (a safety, a damage sum, a required life).
EXIT_BELOW_MINIMUM = 3

F = TypeVar("F", bound=Callable[..., Any])


class OutputFormat(str, Enum):
    """Output formats shared by the reporting sub-commands."""

    table = "table"
    json = "json"
    markdown = "markdown"
    html = "html"


#: The ``--format`` and ``--out`` options, the same on every reporting sub-command.
FormatOption = Annotated[OutputFormat, typer.Option("--format", "-f", help="Output format.")]
OutOption = Annotated[Optional[Path], typer.Option("--out", "-o", help="Write to this file instead of stdout.")]
#: ``--set KEY=VALUE`` (repeatable): override a value of the train file before it is read.
SetOption = Annotated[Optional[list[str]], typer.Option(
    "--set", metavar="KEY=VALUE",
    help="Override a value of FILE before it is read (repeatable): a dotted key and a TOML value, "
         "e.g. --set operating_point.speeds.sun=\"2000 rpm\" or --set planetary.P1.stationary_efficiency=0.97.")]


def fail(message: str, code: int = EXIT_BAD_INPUT) -> None:
    """Print ``message`` as one line on stderr (control characters removed) and exit with ``code``."""
    from ..text import terminal_text

    typer.echo(" ".join(terminal_text(message).split()), err=True)
    raise typer.Exit(code)


def guarded(command: F) -> F:
    """Run a command, turning bad input into exit 2 and anything else into exit 1.

    Before the command runs, an ``out`` that is the input ``file`` (or a link
    to it) is refused; errors raised after the file was read (solver,
    transmission) are located in ``file`` with the key they are about.
    """

    @functools.wraps(command)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        from ..io.located import locate_error
        from ..io.output import refuse_input

        source = kwargs.get("file")
        _NOTES.clear()
        try:
            if kwargs.get("out") is not None:
                refuse_input(kwargs["out"], [source])
            with warnings.catch_warnings():  # overflow shows as one clear error, never as numpy warnings
                warnings.simplefilter("ignore", RuntimeWarning)
                result = command(*args, **kwargs)
            for note in _NOTES:  # after the work: an error stays the one line on stderr
                typer.echo(note, err=True)
            return result
        except typer.Exit:
            raise
        except EpicyclicError as exc:
            fail(f"error: {locate_error(exc, str(source)) if source is not None else exc}", EXIT_BAD_INPUT)
        except OSError as exc:  # reading an input file that vanished, a closed stdout, ...
            where = f" ({exc.filename})" if exc.filename else ""
            fail(f"error: {exc.strerror or exc}{where}.", EXIT_BAD_INPUT)
        except Exception as exc:
            if os.environ.get("EPICYCLIC_DEBUG"):
                raise
            fail(f"internal error: {type(exc).__name__}: {exc}. This is a bug in epicyclic; please report it "
                 "with the command and input file (set EPICYCLIC_DEBUG=1 to see the traceback).", EXIT_INTERNAL)

    return wrapper  # type: ignore[return-value]


def emit(text: str, out: Path | None) -> None:
    """Write ``text`` to ``out`` (atomically, creating folders) or to stdout; control characters removed.

    Both end with one newline, whether or not ``text`` does (a file written with ``--out`` is a
    proper text file, and the same bytes as the command prints).
    """
    from ..io.output import write_atomic
    from ..text import terminal_text

    text = terminal_text(text)
    if not text.endswith("\n"):
        text += "\n"
    if out is None:
        typer.echo(text, nl=False)
        return
    say(f"wrote {write_atomic(out, text).resolve()}")


def say(line: str) -> None:
    """Print a status line (e.g. ``wrote PATH``) without control characters."""
    from ..text import terminal_text

    typer.echo(terminal_text(line))


def check_finite(data: Any, file: Path | str | None, what: str = "") -> None:
    """Raise NonFiniteResultError (exit 2) at the first infinite or NaN number of a result's ``to_dict()``."""
    from ..io.located import check_finite as check

    check(data, str(file) if file is not None else "result", what)


#: Lines for stderr once a command has done its work (what a REXS file held that was ignored).
_NOTES: list[str] = []


def note(line: str) -> None:
    """One line for stderr once the command has done its work (a warning about an option's value, ...)."""
    if line not in _NOTES:
        _NOTES.append(line)


def note_exchange(train_file) -> None:
    """For a REXS file: one line for stderr, after the command's work, saying what was read and what was
    ignored (stdout stays the report; a command that fails prints only its error)."""
    if getattr(train_file, "exchange", None) is not None:
        from ..text import terminal_text

        note(" ".join(terminal_text(train_file.exchange.summary).split()))


def note_rexs(file: Path) -> None:
    """:func:`note_exchange` for a command that read ``file`` itself (``gears``, ``explore``): a REXS file's
    summary line (the file read once more, a few milliseconds)."""
    from ..io.source import sniff

    with open(file, "rb") as handle:
        head = handle.read(4096)
    if sniff(head) is not None:
        from ..io import load_train_file

        note_exchange(load_train_file(file))


def load(file: Path, gear: str | None = None, overrides: list[str] | None = None):
    """The train file ``file`` (a :class:`~epicyclic.io.TrainFile`), in ``gear`` of its schedule if given.

    ``overrides`` are the ``--set KEY=VALUE`` values, applied before the file is read.
    """
    from dataclasses import replace

    from ..errors import ModelError
    from ..io import load_train_file

    train_file = load_train_file(file, overrides=overrides or ())
    note_exchange(train_file)
    if gear is None:
        return train_file
    if train_file.transmission is None:
        raise ModelError(f"--gear {gear!r:.40} needs a [transmission] table with a schedule in the file.")
    if gear not in train_file.transmission.schedule:
        raise ModelError(f"--gear: no gear {gear!r:.40} in the [transmission] schedule; gears are "
                         f"{', '.join(repr(g) for g in train_file.transmission.schedule)}.")
    return replace(train_file, gear=gear)


def _report_gear(train_file) -> str | None:
    """The gear a report of ``train_file`` is in: ``--gear`` or the file's, else the first gear of a
    transmission without operating point (as :func:`epicyclic.plotting.figure_subject` draws it)."""
    if train_file.gear is None and train_file.operating_point is None and train_file.transmission is not None:
        return next(iter(train_file.transmission.schedule))
    return train_file.gear


def report_title(train_file) -> str:
    """The title of a report on ``train_file``: the file's title, and the gear it is solved in."""
    title = train_file.title or train_file.train.name
    gear = _report_gear(train_file)
    return f"{title}, gear {gear}" if gear else title


def solved(train_file, file: Path):
    """The solution of ``train_file``, its numbers (and the ideal ones) checked to be finite.

    A transmission without an ``[operating_point]`` is solved as ``plot`` draws it
    (:func:`epicyclic.plotting.figure_subject`): at the default operating point in its gear
    (``--gear``, else the first), and the report says so among the warnings.
    """
    from ..io.json_report import report_data

    if train_file.operating_point is None and train_file.transmission is not None:
        from dataclasses import replace

        from ..plotting.subject import figure_subject

        subject = figure_subject(train_file, _report_gear(train_file))
        solution = replace(subject.solution, warnings=(*subject.context.notes, *subject.solution.warnings))
    else:
        solution = train_file.solve()
    notes = _coaxial_notes(train_file)
    if notes:
        from dataclasses import replace

        solution = replace(solution, warnings=(*solution.warnings, *notes))
    check_finite(report_data(solution, train_file.units), file)
    return solution


def _coaxial_notes(train_file) -> tuple[str, ...]:
    """For a simple set without a geometry table whose counts miss z_ring = z_sun + 2 z_planet: how far, and that
    profile shift must close it (issue 19; with a geometry table `fit` checks the working centre distances)."""
    from ..model import PlanetarySet
    from ..model.teeth import coaxial_note

    notes = []
    for element in train_file.train.elements:
        if isinstance(element, PlanetarySet) and element.teeth is not None and element.teeth.kind == "simple" \
                and element.name not in train_file.geometry:
            note = coaxial_note(element.teeth)
            if note:
                notes.append(f"planetary set {element.name!r}: {note}.")
    return tuple(notes)


class OneLineErrors(TyperGroup):
    """The command group: usage errors (a bad option value, an unknown option, a missing
    argument) are one line on stderr with exit code 2, like every other bad input."""

    def main(self, args=None, prog_name=None, complete_var=None, standalone_mode=True, **extra):  # type: ignore[override]
        if not standalone_mode:
            return super().main(args, prog_name, complete_var, standalone_mode=False, **extra)
        try:
            code = super().main(args, prog_name, complete_var, standalone_mode=False, **extra)
        except typer.TyperException as exc:  # click's ClickException family
            if type(exc).__name__ == "NoArgsIsHelpError":
                typer.echo(exc.format_message())
            else:
                ctx = getattr(exc, "ctx", None)
                command = ctx.command_path if ctx is not None else "epicyclic"
                try:
                    typer.echo(" ".join(f"error: {command}: {exc.format_message().rstrip('.')} (see '{command} --help')."
                                        .split()), err=True)
                except OSError:
                    pass
            sys.exit(getattr(exc, "exit_code", EXIT_BAD_INPUT))
        except RuntimeError as exc:
            if type(exc).__name__ != "Abort":
                raise
            typer.echo("Aborted.", err=True)
            sys.exit(EXIT_INTERNAL)
        sys.exit(code if isinstance(code, int) else EXIT_OK)
