"""Shared pieces of the sub-commands: error handling, exit codes, output.

Exit codes: 0 success, 2 bad input (one paragraph on stderr, no traceback),
1 internal error (a bug: one paragraph asking for a report; set
``EPICYCLIC_DEBUG=1`` to see the traceback).
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable
from enum import Enum
from pathlib import Path
from typing import Annotated, Any, Optional, TypeVar

import typer

from ..errors import EpicyclicError

__all__ = ["EXIT_OK", "EXIT_INTERNAL", "EXIT_BAD_INPUT", "OutputFormat", "FormatOption", "OutOption",
           "guarded", "emit", "fail", "load_in_gear"]

EXIT_OK = 0
EXIT_INTERNAL = 1
EXIT_BAD_INPUT = 2

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


def fail(message: str, code: int = EXIT_BAD_INPUT) -> None:
    """Print ``message`` as one paragraph (one line; terminals wrap it) on stderr and exit with ``code``."""
    typer.echo(" ".join(message.split()), err=True)
    raise typer.Exit(code)


def guarded(command: F) -> F:
    """Run a command, turning bad input into exit 2 and anything else into exit 1."""

    @functools.wraps(command)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return command(*args, **kwargs)
        except typer.Exit:
            raise
        except EpicyclicError as exc:
            fail(f"error: {exc}", EXIT_BAD_INPUT)
        except OSError as exc:  # writing --out, reading an input file
            fail(f"error: {exc.strerror or exc} ({exc.filename or ''}).", EXIT_BAD_INPUT)
        except Exception as exc:
            if os.environ.get("EPICYCLIC_DEBUG"):
                raise
            fail(f"internal error: {type(exc).__name__}: {exc}. This is a bug in epicyclic; please report it "
                 "with the command and input file (set EPICYCLIC_DEBUG=1 to see the traceback).", EXIT_INTERNAL)

    return wrapper  # type: ignore[return-value]


def emit(text: str, out: Path | None) -> None:
    """Write ``text`` to ``out`` (creating folders) or to stdout."""
    if out is None:
        typer.echo(text, nl=not text.endswith("\n"))
        return
    out = Path(out)
    if out.parent and not out.parent.exists():
        out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(text, encoding="utf-8")
    typer.echo(f"wrote {out.resolve()}")


def load_in_gear(file: Path, gear: str | None):
    """The train file at ``file``, its operating point applied in ``gear`` of its schedule when given."""
    from dataclasses import replace

    from ..errors import ModelError
    from ..io import load_train_file

    train_file = load_train_file(file)
    if gear is not None:
        if train_file.transmission is None:
            raise ModelError(f"{file}: --gear {gear!r} needs a [transmission] table with a schedule in the file.")
        train_file.transmission.train_in_gear(train_file.train, gear)  # validates the gear name
        train_file = replace(train_file, gear=gear)
    return train_file
