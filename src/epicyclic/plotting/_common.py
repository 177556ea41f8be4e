"""Shared helpers of the plotting package: lazy matplotlib, output, errors, colours.

matplotlib is imported only inside functions, so ``import epicyclic`` stays
fast and works without a display.  Figures are written by :func:`save_figure`
(format from the file suffix) or turned into inline SVG text by
:func:`figure_svg` for the HTML report.
"""

from __future__ import annotations

import io
import math
import re
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..errors import EpicyclicError
from ..model.elements import HOUSING, GearStage
from ..model.planetary import PlanetarySet

if TYPE_CHECKING:  # pragma: no cover
    from ..model.train import GearTrain
    from ..results.solution import Solution

__all__ = [
    "PlottingError",
    "RPM_TO_RAD_S",
    "FIGURE_SUFFIXES",
    "pyplot",
    "figure_svg",
    "save_figure",
    "lever_elements",
    "planetary_set",
    "ROLE_STYLE",
    "SHAFT_COLOURS",
]

#: 1/min → rad/s, explicit (never through Hz).
RPM_TO_RAD_S = math.pi / 30.0

#: File suffixes :func:`save_figure` can write.
FIGURE_SUFFIXES = (".svg", ".png", ".pdf")

#: Hatching after Brandenberger 1952 (text to Bild 5 and 8): power put in is
#: hatched vertically, power taken out horizontally; the loss is cross-hatched
#: and drawn with a heavy outline.
ROLE_STYLE = {
    "drive": {"hatch": "|||", "facecolor": "#f4c7a1", "label": "drive (power in)"},
    "load": {"hatch": "---", "facecolor": "#a9c9e8", "label": "load (power out)"},
    "loss": {"hatch": "xx", "facecolor": "#e8a0a0", "label": "loss"},
    "none": {"hatch": "", "facecolor": "#dddddd", "label": "no power"},
}

#: Colour cycle for shafts / members (colour-blind friendly, Okabe–Ito).
SHAFT_COLOURS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442")


class PlottingError(EpicyclicError, ValueError):
    """A picture cannot be made from what was given (unknown kind, element, file type)."""


def pyplot() -> Any:
    """``matplotlib.pyplot``, imported lazily (the backend is left as configured)."""
    import matplotlib.pyplot as plt

    return plt


def figure_svg(fig: Any) -> str:
    """The figure as inline SVG text (no XML prolog or DOCTYPE), and close it.

    The result starts with ``<svg`` and can be pasted into an HTML page.
    """
    import matplotlib

    buffer = io.StringIO()
    # text stays text (small, searchable); one salt so that ids are reproducible
    with matplotlib.rc_context({"svg.fonttype": "none", "svg.hashsalt": "epicyclic"}):
        fig.savefig(buffer, format="svg", bbox_inches="tight")
    pyplot().close(fig)
    text = buffer.getvalue()
    start = text.find("<svg")
    return text[start:] if start >= 0 else text


def check_suffix(path: str | Path, allowed: tuple[str, ...], what: str) -> Path:
    """``path`` as a Path if its suffix is one of ``allowed``, else PlottingError."""
    path = Path(path)
    if path.suffix.lower() not in allowed:
        raise PlottingError(
            f"{what}: output file {str(path)!r} has suffix {path.suffix or '(none)'!r}; expected one of "
            f"{', '.join(allowed)}. Name the file e.g. 'figure{allowed[0]}'."
        )
    return path


def save_figure(fig: Any, path: str | Path, *, dpi: int = 150) -> Path:
    """Write ``fig`` to ``path`` (.svg, .png or .pdf by suffix) and close it."""
    path = check_suffix(path, FIGURE_SUFFIXES, "save figure")
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=dpi, bbox_inches="tight")
    pyplot().close(fig)
    return path


def lever_elements(train: GearTrain) -> list[tuple[Any, tuple[str, str, str], tuple[str, str, str], float]]:
    """(element, ports, shafts, ratio) of every three-port element with gears.

    A planetary set has ports (sun, ring, carrier) and ratio i0; a fixed-axis
    stage has ports (first, second, housing) and its speed ratio: it is a set
    whose carrier is the housing (DESIGN.md §3).
    """
    out = []
    for element in train.elements:
        if isinstance(element, PlanetarySet):
            out.append((element, ("sun", "ring", "carrier"), element.shafts, element.stationary_ratio))
        elif isinstance(element, GearStage):
            out.append((element, ("first", "second", "housing"), (element.first, element.second, HOUSING),
                        element.ratio))
    return out


def planetary_set(solution: Solution, name: str | None) -> PlanetarySet:
    """The planetary set called ``name`` (the first one if None), else PlottingError."""
    sets = solution.train.planetary_sets
    if not sets:
        raise PlottingError(
            f"train {solution.train.name!r} has no planetary set; this picture needs one "
            "(add a PlanetarySet or choose another kind of plot)."
        )
    if name is None:
        return sets[0]
    for s in sets:
        if s.name == name:
            return s
    raise PlottingError(
        f"train {solution.train.name!r}: no planetary set named {name!r}; planetary sets are "
        f"{', '.join(repr(s.name) for s in sets)}."
    )


def fmt(value: float, digits: int = 4) -> str:
    """A compact number for labels (``-0`` shown as ``0``)."""
    if 10 ** (digits - 1) <= abs(value) < 1e12:
        return f"{value:.0f}"
    text = f"{value:.{digits}g}"
    return "0" if re.fullmatch(r"-0(\.0*)?", text) else text
