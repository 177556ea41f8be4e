"""HTML of the page: the Jinja2 templates of ``epicyclic/web/templates`` and the answer a worker sends back.

Every value a template shows is escaped (autoescaping) and passed through
:func:`epicyclic.text.terminal_text`, so that neither markup nor control
characters (ANSI escapes, bidirectional overrides) from an input reach the
browser; only pictures and the library's own HTML are marked safe, and only
the editor's text (:class:`Verbatim`) keeps its characters.

Examples
--------
>>> print(render("problem_box.html", problem=type("P", (), {"message": "<b>x\\x1b[2J</b>", "line": None})))
<div class="problem" role="alert">
  <p class="message"><strong>error:</strong> &lt;b&gt;x[2J&lt;/b&gt;</p>
</div>
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Any

from ..limits import DPI_RANGE, FPS_RANGE, FRAMES_RANGE, SIZE_RANGE

__all__ = ["Reply", "HTML", "Verbatim", "render", "fmt"]

HTML = "text/html; charset=utf-8"


@dataclass(frozen=True)
class Reply:
    """An answer for the browser: body, HTTP status, media type and, for downloads, a file name.

    ``next_gears`` are the gears the page will most likely show next (the other gears of a transmission,
    nearest first), whose pictures the server may draw ahead while it is idle (:mod:`epicyclic.web.cache`),
    of the text ``next_text`` (the text shown: the form's operating point written in);
    ``headers`` are further response headers (``HX-Retarget``: an answer that goes elsewhere than asked).
    """

    body: str | bytes
    status: int = 200
    media_type: str = HTML
    filename: str | None = None
    next_gears: tuple[str, ...] = ()
    next_text: str = ""
    headers: tuple[tuple[str, str], ...] = ()


class Verbatim(str):
    """Text shown exactly as it is (escaped, control characters kept): the editor's TOML text, which
    must come back unchanged."""


def fmt(value: float | None, digits: int = 4) -> str:
    """A number as the report tables print it (``—`` for None, no ``-0``)."""
    from ..io.tables import fmt as table_fmt

    return table_fmt(value, digits)


def _finalize(value: Any) -> Any:
    """Every shown value: text without control characters (markup marked safe stays safe)."""
    from markupsafe import Markup

    from ..text import terminal_text

    if isinstance(value, Verbatim):
        return value
    if isinstance(value, Markup):
        return Markup(terminal_text(str(value)))
    return terminal_text(value) if isinstance(value, str) else value


@lru_cache(maxsize=1)
def environment() -> Any:
    """The Jinja2 environment of the page's templates (autoescaping on, control characters removed)."""
    import jinja2

    env = jinja2.Environment(loader=jinja2.PackageLoader("epicyclic.web", "templates"),
                             autoescape=True, undefined=jinja2.StrictUndefined, trim_blocks=True,
                             lstrip_blocks=True, finalize=_finalize)
    env.globals["fmt"] = fmt
    env.globals["limits"] = {"size": SIZE_RANGE, "dpi": DPI_RANGE, "frames": FRAMES_RANGE, "fps": FPS_RANGE}
    return env


def render(template: str, **context: Any) -> str:
    """Render a template of ``epicyclic/web/templates``."""
    return environment().get_template(template).render(**context)
