"""Small text/HTML table helpers shared by the geometry result objects (render only)."""

from __future__ import annotations

import html
from collections.abc import Sequence


def _cell(value: object) -> str:
    if isinstance(value, bool) or value is None:
        return {True: "yes", False: "no", None: "-"}[value]
    if isinstance(value, float):  # 4 decimals (mm, N); huge values in exponent form
        return f"{value:.4f}" if abs(value) < 1e9 else f"{value:.6g}"
    return str(value)


def text_table(headers: Sequence[str], rows: Sequence[Sequence[object]], title: str = "") -> str:
    """A fixed-width text table.

    >>> print(text_table(["a", "b"], [[1, 2.5]]))
    a  b
    -  ------
    1  2.5000
    """
    cells = [[_cell(v) for v in row] for row in rows]
    widths = [max([len(h)] + [len(r[i]) for r in cells]) for i, h in enumerate(headers)]
    lines = [title] if title else []
    lines.append("  ".join(h.ljust(w) for h, w in zip(headers, widths)).rstrip())
    lines.append("  ".join("-" * w for w in widths))
    lines.extend("  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in cells)
    return "\n".join(lines)


def html_table(headers: Sequence[str], rows: Sequence[Sequence[object]], title: str = "") -> str:
    """The same table as HTML (escaped)."""
    head = "".join(f"<th>{html.escape(h)}</th>" for h in headers)
    body = "".join(
        "<tr>" + "".join(f"<td>{html.escape(_cell(v))}</td>" for v in row) + "</tr>" for row in rows
    )
    caption = f"<caption>{html.escape(title)}</caption>" if title else ""
    return f"<table>{caption}<thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"
