"""``epicyclic fit FILE``, ``epicyclic forces FILE`` and ``epicyclic search``: gear geometry on the command line.

``fit`` runs every fitting condition (coaxiality, assembly and phasing,
neighbours, undercut, internal interference) of each set with a ``geometry``
table, each with what to change; ``forces`` solves the file's operating point
and prints tooth, bearing and pin forces (design values × K_γ) of every element
with geometry; ``search`` is the vectorised tooth-count search for a target
ratio.  Lengths in mm, forces in N.  Exit codes: 0 (also when a set does not
fit: the report says so), 2 bad input, 1 internal error.
"""

from __future__ import annotations

import json
from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer

from ..limits import MAX_PLANETS, MODULE_RANGE
from ._common import (FormatOption, OutOption, OutputFormat, SetOption, check_finite, emit, guarded, load,
                      report_title, solved)

__all__ = ["fit", "forces", "search", "parse_range", "parse_tolerance"]


def _load(file: Path, gear: str | None, overrides: list[str] | None, *, tooth_counts: bool = False):
    """The train file with ``--set`` and ``--gear`` applied; an error if it has no geometry table.

    ``tooth_counts``: a file whose sets have tooth counts but no geometry table is enough (``fit``).
    """
    from ..errors import ModelError
    from ..model import PlanetarySet

    train_file = load(file, gear, overrides)
    if tooth_counts and any(isinstance(e, PlanetarySet) and e.teeth is not None for e in train_file.train.elements):
        return train_file
    if not train_file.geometry:
        raise ModelError(
            f"{file}: no element has a geometry table; add one to a [[planetary]] or [[gear]] element, e.g. "
            "[planetary.geometry] with module = 2.0 (mm) (see docs/file-format.md)."
        )
    return train_file


def _clearance(value: float, command: str) -> float:
    """``--min-clearance`` as a finite number of mm ≥ 0 (typer's ``min`` lets nan and inf through)."""
    import math

    from ..errors import ModelError

    if not math.isfinite(value) or value < 0:
        raise ModelError(f"{command}: --min-clearance: expected a finite number of mm >= 0 (the least tip clearance "
                         f"between neighbouring planets), got {value!r}.")
    return value


def _render(results, format: OutputFormat, title: str, what: str) -> str:
    """``fit``: gears, meshes and fitting; ``forces``: the forces only (the gears are what ``fit`` shows)."""
    from dataclasses import replace

    from ..io.geometry_report import geometry_dict, geometry_html, geometry_markdown, geometry_text

    show = {"show_geometry": what == "fitting"}
    heading = {"fitting": "Geometry and fitting", "forces": "Forces"}[what]
    if what == "forces":
        results = tuple(replace(r, fitting=None) for r in results)
    if format is OutputFormat.json:
        return json.dumps({"title": title, what: geometry_dict(results)}, indent=2, ensure_ascii=False,
                          allow_nan=False, default=str) + "\n"
    if format is OutputFormat.markdown:
        return f"# {title}\n\n" + geometry_markdown(results, heading=heading, **show)
    if format is OutputFormat.html:
        import html

        return ("<!DOCTYPE html><html><head><meta charset='utf-8'><title>" + html.escape(title)
                + f"</title></head><body><h1>{html.escape(title)}</h1>"
                + geometry_html(results, heading=heading, **show) + "</body></html>\n")
    return f"{title}\n{'=' * len(title)}\n\n" + geometry_text(results, **show) + "\n"


class Undercut(str, Enum):
    """Undercut limit."""

    theoretical = "theoretical"
    practical = "practical"


@guarded
def fit(
    file: Annotated[Path, typer.Argument(help="Train description (.toml) with geometry tables.")],
    format: FormatOption = OutputFormat.table,
    out: OutOption = None,
    planets: Annotated[Optional[int], typer.Option(help="Check with this number of planets (default: the file's).",
                                                   min=1, max=MAX_PLANETS)] = None,
    allow_unequal: Annotated[bool, typer.Option("--allow-unequal", help="Accept unequal planet spacing.")] = False,
    min_clearance: Annotated[float, typer.Option(help="Least tip clearance between planets, mm.", min=0.0)] = 0.0,
    undercut: Annotated[Undercut, typer.Option(help="Undercut limit.")] = Undercut.theoretical,
    set_: SetOption = None,
) -> None:
    """Fitting of every set with geometry: coaxiality, assembly and phasing, neighbours, undercut, interference.

    Sets without a geometry table get what their tooth counts decide: coaxiality of standard gears (how far the
    counts are off, for profile shift to close) and the assembly of equally spaced planets.
    """
    from ..io.geometry_report import geometry_results, tooth_count_results

    _clearance(min_clearance, "fit")
    train_file = _load(file, None, set_, tooth_counts=True)
    results = geometry_results(train_file.geometry, None, planets=planets, allow_unequal=allow_unequal,
                               min_clearance=min_clearance, undercut=undercut.value)
    with_geometry = {r.name for r in results}
    results += tuple(r for r in tooth_count_results(train_file.train, planets=planets, allow_unequal=allow_unequal)
                     if r.name not in with_geometry)
    emit(_render(results, format, f"fitting of {train_file.title or train_file.train.name}", "fitting"), out)


@guarded
def forces(
    file: Annotated[Path, typer.Argument(
        help="Train description (.toml) with geometry tables and an operating point.")],
    format: FormatOption = OutputFormat.table,
    out: OutOption = None,
    gear: Annotated[Optional[str], typer.Option("--gear", "-g", help="Gear of the [transmission] schedule.")] = None,
    set_: SetOption = None,
) -> None:
    """Tooth, bearing and pin forces (× K_γ) at the file's operating point, for every element with geometry."""
    from ..io.geometry_report import geometry_dict, geometry_results

    train_file = _load(file, gear, set_)
    results = geometry_results(train_file.geometry, solved(train_file, file), losses=train_file.losses)
    check_finite(geometry_dict(results), file, "forces")
    emit(_render(results, format, f"forces of {report_title(train_file)}", "forces"), out)


# ---------------------------------------------------------------------- search
def parse_range(text: str, name: str, low: int = 3, high: int = 400) -> tuple[int, int]:
    """``"12..80"`` → (12, 80) (:func:`epicyclic.io.ranges.parse_range`, shared with the page).

    >>> parse_range("3..6", "--planets")
    (3, 6)
    """
    from ..io.ranges import parse_range as parse

    return parse(text, name, low, high)


def parse_tolerance(text: str) -> float:
    """``"3%"`` → 0.03 (:func:`epicyclic.io.ranges.parse_tolerance`, shared with the page).

    >>> parse_tolerance("3%"), parse_tolerance("0.5 %")
    (0.03, 0.005)
    """
    from ..io.ranges import parse_tolerance as parse

    return parse(text)


class Member(str, Enum):
    """Members of a simple set."""

    sun = "sun"
    ring = "ring"
    carrier = "carrier"


class SearchFormat(str, Enum):
    """Output formats of ``search``."""

    table = "table"
    json = "json"
    csv = "csv"


@guarded
def search(
    ratio: Annotated[float, typer.Option("--ratio", "-r", help="Target ratio n_driver/n_driven.")],
    tolerance: Annotated[str, typer.Option(help="Allowed deviation: 3% or 0.03.")] = "1%",
    planets: Annotated[str, typer.Option(help="Numbers of planets: 3..6 or 4.")] = "3..5",
    module: Annotated[float, typer.Option(help="Module, mm (scales the clearance).", min=MODULE_RANGE[0],
                                       max=MODULE_RANGE[1])] = 1.0,
    held: Annotated[Member, typer.Option(help="The held member.")] = Member.ring,
    driver: Annotated[Member, typer.Option(help="The driving member.")] = Member.sun,
    driven: Annotated[Member, typer.Option(help="The driven member.")] = Member.carrier,
    sun: Annotated[str, typer.Option(help="Sun teeth range.")] = "12..80",
    planet: Annotated[str, typer.Option(help="Planet teeth range.")] = "12..80",
    ring: Annotated[Optional[str], typer.Option(help="Ring teeth range (default: any).")] = None,
    pressure_angle: Annotated[float, typer.Option(help="Pressure angle, degrees.", min=1.0, max=44.0)] = 20.0,
    min_clearance: Annotated[float, typer.Option(help="Least tip clearance between planets, mm.", min=0.0)] = 0.0,
    undercut: Annotated[Undercut, typer.Option(help="Undercut limit.")] = Undercut.theoretical,
    interference: Annotated[bool, typer.Option("--interference/--no-interference",
                                               help="Reject internal-gear interference.")] = True,
    limit: Annotated[int, typer.Option(help="Rows shown in the table.", min=1, max=100000)] = 20,
    format: Annotated[SearchFormat, typer.Option("--format", "-f", help="Output format.")] = SearchFormat.table,
    out: OutOption = None,
) -> None:
    """Tooth counts of simple sets for a target ratio: every candidate that fits, ranked (vectorised)."""
    from ..errors import ModelError
    from ..geometry import search_teeth
    from ..limits import RATIO_RANGE

    if not RATIO_RANGE[0] <= abs(ratio) <= RATIO_RANGE[1]:  # also NaN
        raise ModelError(f"search: --ratio: expected a ratio n_driver/n_driven with {RATIO_RANGE[0]:g} <= |ratio| "
                         f"<= {RATIO_RANGE[1]:g}, got {ratio!r}.")
    if len({held, driver, driven}) < 3:
        raise ModelError(f"search: --held {held.value}, --driver {driver.value}, --driven {driven.value}: give three "
                         "different members (sun, ring, carrier), e.g. --held ring --driver sun --driven carrier.")
    _clearance(min_clearance, "search")
    low, high = parse_range(planets, "search: --planets", 1, MAX_PLANETS)
    result = search_teeth(
        ratio, held=held.value, driver=driver.value, driven=driven.value, tolerance=parse_tolerance(tolerance),
        z_sun=parse_range(sun, "search: --sun"), z_planet=parse_range(planet, "search: --planet"),
        z_ring=parse_range(ring, "search: --ring") if ring else None, planets=tuple(range(low, high + 1)),
        module=module,
        pressure_angle=pressure_angle, min_clearance=min_clearance, undercut=undercut.value,
        interference=interference,
    )
    if format is SearchFormat.json:
        text = json.dumps(result.to_dict(), indent=2, ensure_ascii=False, allow_nan=False) + "\n"
    elif format is SearchFormat.csv:
        text = result.to_csv()
    else:
        text = result.table(limit) + "\n"
    emit(text, out)
