"""Tables of the elastic results as plain text, Markdown and HTML (one set of rows, three renderings)."""

from __future__ import annotations

import html

from ..text import markdown_text, terminal_text

__all__ = ["grid", "markdown", "html_table", "number", "Tabular"]


def number(value: float, digits: int = 5) -> str:
    """``value`` with ``digits`` significant digits (``—`` for None).

    >>> number(1475.6789), number(None)
    ('1475.7', '—')
    """
    return "—" if value is None else f"{value:.{digits}g}"


def grid(headers: list[str], rows: list[list[str]], title: str = "") -> str:
    """A plain-text table, numbers right-aligned, a title line above.

    >>> print(grid(["a", "b"], [["x", "1"]]))
    a  b
    -  -
    x  1
    """
    widths = [max([len(h)] + [len(r[k]) for r in rows]) for k, h in enumerate(headers)]
    lines = ["  ".join(h.ljust(w) for h, w in zip(headers, widths)), "  ".join("-" * w for w in widths)]
    lines += ["  ".join(c.rjust(w) if k else c.ljust(w) for k, (c, w) in enumerate(zip(r, widths))) for r in rows]
    return terminal_text("\n".join(([title] if title else []) + lines))


def markdown(headers: list[str], rows: list[list[str]], title: str = "") -> str:
    """A Markdown table (cells escaped).

    >>> print(markdown(["a"], [["x|y"]]))
    | a |
    |---|
    | x\\|y |
    """
    out = ([f"**{markdown_text(title)}**", ""] if title else [])
    out.append("| " + " | ".join(markdown_text(h) for h in headers) + " |")
    out.append("|" + "|".join("---" for _ in headers) + "|")
    out += ["| " + " | ".join(markdown_text(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


def html_table(headers: list[str], rows: list[list[str]], title: str = "") -> str:
    """An HTML table (cells escaped) with an optional caption.

    >>> html_table(["a"], [["<b>"]])
    '<table><tr><th>a</th></tr><tr><td>&lt;b&gt;</td></tr></table>'
    """
    cap = f"<caption>{html.escape(title)}</caption>" if title else ""
    head = "<tr>" + "".join(f"<th>{html.escape(h)}</th>" for h in headers) + "</tr>"
    body = "".join("<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>" for r in rows)
    return f"<table>{cap}{head}{body}</table>"


class Tabular:
    """Renders a result from its ``_rows()`` (headers, rows) and ``_title()``: text, Markdown, HTML."""

    def _rows(self) -> tuple[list[str], list[list[str]]]:  # pragma: no cover - every result defines it
        raise NotImplementedError

    def _title(self) -> str:  # pragma: no cover
        raise NotImplementedError

    def table(self) -> str:
        """The result as a plain-text table."""
        return grid(*self._rows(), title=self._title())

    def markdown(self) -> str:
        """The result as a Markdown table."""
        return markdown(*self._rows(), title=self._title())

    def _repr_html_(self) -> str:
        return html_table(*self._rows(), title=self._title())
