"""Safe text at the edges: what a user wrote, shown on a terminal or in Markdown.

Names, titles and descriptions come from input files.  Shown verbatim, an ANSI
escape in a title would clear the terminal and ``<script>`` or ``|`` in a name
would break out of a Markdown table.  Every renderer passes user text through
one of these functions; HTML renderers use :func:`html.escape`.

Examples
--------
>>> terminal_text("Bild 10\\x1b[2J")
'Bild 10[2J'
>>> markdown_text("<script>|x")
'&lt;script&gt;\\\\|x'
>>> short("x" * 100, 10)
"'xxxxxxxx…"
"""

from __future__ import annotations

import html
import re

__all__ = ["terminal_text", "markdown_text", "short"]

# C0 controls but tab and newline, DEL, C1 controls, and the Unicode bidirectional
# overrides and isolates that reorder what a terminal shows (CVE-2021-42574).
_CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069]")


def terminal_text(text: str) -> str:
    """``text`` without control characters (but newline and tab) and bidirectional overrides.

    Removing (rather than escaping) keeps JSON output valid.
    """
    return _CONTROL.sub("", text)


def markdown_text(text: str) -> str:
    """``text`` for Markdown: HTML escaped, table pipes escaped, one line, no control characters."""
    text = terminal_text(text).replace("\t", " ").replace("\n", " ")
    return html.escape(text, quote=False).replace("|", "\\|")


def short(value: object, limit: int = 60) -> str:
    """``repr(value)`` cut to ``limit`` characters (for messages that quote what was given).

    Parameters
    ----------
    value : object
        Anything; a value nested too deeply for ``repr`` is described by its type.
    limit : int, default 60
        Most characters returned; a longer text ends in ``…``.

    Returns
    -------
    str

    Examples
    --------
    >>> short("x" * 100, 10)
    "'xxxxxxxx…"
    """
    try:
        text = repr(value)
    except RecursionError:  # a value nested too deeply to print
        text = f"<{type(value).__name__} nested too deeply to show>"
    return text if len(text) <= limit else text[: limit - 1] + "…"
