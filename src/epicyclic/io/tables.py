"""Report tables in the user's units, rendered as text, Markdown or HTML.

The solver's result (:class:`~epicyclic.results.Solution`) is in core units;
this module converts it with a :class:`~epicyclic.units.Units` and lays it out
as three sections — shafts, elements, summary — that the text, Markdown and
HTML reports share.  Rendering never computes anything new.
"""

from __future__ import annotations

import html
from dataclasses import dataclass

from ..results.circulation import Circulation
from ..results.render import port_labels
from ..results.solution import Solution
from ..text import markdown_text
from ..units import Units

__all__ = ["ReportTable", "report_tables", "summary_lines", "text_report", "markdown_report", "html_table", "fmt"]


@dataclass(frozen=True)
class ReportTable:
    """One table of a report: a caption, column headers and rows of formatted cells."""

    caption: str
    headers: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]

    def text(self) -> str:
        """Aligned plain text (numbers right-aligned)."""
        widths = [max([len(h)] + [len(r[k]) for r in self.rows]) for k, h in enumerate(self.headers)]
        line = "  ".join(h.ljust(w) for h, w in zip(self.headers, widths)).rstrip()
        rule = "  ".join("-" * w for w in widths)
        body = ["  ".join(c.rjust(w) if k else c.ljust(w) for k, (c, w) in enumerate(zip(r, widths))).rstrip()
                for r in self.rows]
        return "\n".join([self.caption, "", line, rule, *body])

    def markdown(self) -> str:
        """A GitHub-flavoured Markdown table (HTML and pipes in cells escaped)."""
        head = "| " + " | ".join(markdown_text(h) for h in self.headers) + " |"
        align = "|" + "|".join(":---" if k == 0 else "---:" for k in range(len(self.headers))) + "|"
        body = ["| " + " | ".join(markdown_text(c) for c in r) + " |" for r in self.rows]
        return "\n".join([f"### {markdown_text(self.caption)}", "", head, align, *body])

    def html(self) -> str:
        """An HTML ``<table>`` with a caption."""
        return html_table(self.caption, self.headers, self.rows)


def html_table(caption: str, headers, rows) -> str:
    """An escaped HTML table."""
    head = "".join(f"<th>{html.escape(h)}</th>" for h in headers)
    body = "".join(
        "<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>" for r in rows
    )
    return (f"<table><caption>{html.escape(caption)}</caption><thead><tr>{head}</tr></thead>"
            f"<tbody>{body}</tbody></table>")


def fmt(value: float | None, digits: int = 6) -> str:
    """A number with ``digits`` significant digits; ``—`` for None; no ``-0``."""
    if value is None:
        return "—"
    if value == 0:
        value = 0.0
    text = f"{value:.{digits}g}"
    return "0" if text in ("-0", "0") else text


def report_tables(solution: Solution, units: Units | None = None) -> tuple[ReportTable, ReportTable]:
    """The shaft and element tables of ``solution`` in ``units``."""
    u = units or Units()
    shafts = ReportTable(
        "Shafts",
        ("shaft", f"speed [{u.speed}]", f"torque [{u.torque}]", f"power [{u.power}]", "role"),
        tuple(
            (s.name, fmt(u.speed_from_core(s.speed)), fmt(u.torque_from_core(s.torque)),
             fmt(u.power_from_core(s.power)), s.role)
            for s in solution.shafts.values()
        ),
    )
    rows = []
    for e in solution.elements.values():
        labels = port_labels(solution, e)  # first/second for two rings or two suns
        torques = ", ".join(f"{labels.get(p, p)} {fmt(u.torque_from_core(t), 5)}" for p, t in e.torques.items())
        if e.kind in ("clutch", "brake"):
            rolling = coupling = loss = "—"
            direction = f"slip {fmt(u.speed_from_core(e.slip_speed or 0.0), 5)}"
        else:
            rolling = fmt(u.power_from_core(e.rolling_power))
            coupling = fmt(u.power_from_core(e.coupling_power))
            loss = fmt(u.power_from_core(e.loss))
            direction = {1: "w = +1", -1: "w = −1", 0: "w = 0"}[e.loss_direction]
        rows.append((e.name, e.kind, e.status, torques, rolling, coupling, loss, direction))
    elements = ReportTable(
        "Elements",
        ("element", "kind", "state", f"port torques [{u.torque}]", f"rolling power [{u.power}]",
         f"coupling power [{u.power}]", f"loss [{u.power}]", "loss direction"),
        tuple(rows),
    )
    return shafts, elements


def summary_lines(solution: Solution, units: Units | None = None) -> list[tuple[str, str]]:
    """(label, value) pairs: powers, loss, efficiency, ratio, self-locking, circulating power."""
    u = units or Units()
    lines = [
        ("input power", f"{fmt(u.power_from_core(solution.input_power))} {u.power}"),
        ("output power", f"{fmt(u.power_from_core(solution.output_power))} {u.power}"),
        ("total loss", f"{fmt(u.power_from_core(solution.loss))} {u.power}"),
    ]
    sources = solution.loss_sources
    if set(sources) - {"mesh"}:  # losses from loss models (docs/losses.md)
        lines.append(("loss by source", ", ".join(f"{k} {fmt(u.power_from_core(v))} {u.power}"
                                                   for k, v in sources.items())))
    if solution.oil_temperature is not None:
        lines.append(("oil temperature", f"{fmt(solution.oil_temperature, 4)} degC"))
    if solution.self_locking is not None:
        label = solution.self_locking.label
        lines.append(("efficiency", f"— ({label})"))
        lines.append((label, solution.self_locking.message))
    else:
        lines.append(("efficiency", fmt(solution.efficiency, 4) if solution.efficiency is not None else "—"))
    if solution.ratio is not None:
        lines.append(("speed ratio n_drive/n_load", fmt(solution.ratio)))
    lines += _circulation_lines(solution.circulation, u)
    lines.append(("degrees of freedom", str(solution.degrees_of_freedom)))
    lines += [("warning", w) for w in solution.warnings]
    return lines


def _circulation_lines(circulation: Circulation, u: Units) -> list[tuple[str, str]]:
    """Circulating power (total, per loop) and the largest element power, both × input."""
    if circulation.indeterminate:
        return [("circulating power", "not defined: the torque split of "
                 + ", ".join(repr(n) for n in circulation.indeterminate) + " is statically indeterminate")]
    if circulation.ratio is None:
        return [("circulating power", "—")]
    lines = [("circulating power", f"{fmt(u.power_from_core(circulation.power))} {u.power} = "
              f"{fmt(circulation.ratio, 4)} × input power" if circulation.loops else "none")]
    lines += [("circulating loop", f"{loop.describe()}: {fmt(u.power_from_core(loop.power))} {u.power} "
               f"({fmt(loop.ratio, 4)} × input power)") for loop in circulation.loops]
    lines.append(("largest element power", f"{fmt(circulation.largest_element_ratio, 4)} × input power"))
    return lines


def text_report(solution: Solution, units: Units | None = None, title: str | None = None) -> str:
    """A plain-text report for terminals: title, shafts, elements, summary."""
    shafts, elements = report_tables(solution, units)
    summary = summary_lines(solution, units)
    width = max(len(k) for k, _ in summary)
    name = title or solution.train.name
    return "\n\n".join([
        f"{name}\n{'=' * len(name)}",
        shafts.text(),
        elements.text(),
        "Summary\n\n" + "\n".join(f"{k.ljust(width)}  {v}" for k, v in summary),
    ]) + "\n"


def markdown_report(solution: Solution, units: Units | None = None, title: str | None = None) -> str:
    """A Markdown report (tables render on GitHub and in most editors)."""
    shafts, elements = report_tables(solution, units)
    summary = ["| quantity | value |", "|:---|:---|"] + [
        f"| {markdown_text(k)} | {markdown_text(v)} |" for k, v in summary_lines(solution, units)
    ]
    return "\n\n".join([
        f"# {markdown_text(title or solution.train.name)}",
        shafts.markdown(),
        elements.markdown(),
        "### Summary\n\n" + "\n".join(summary),
    ]) + "\n"
