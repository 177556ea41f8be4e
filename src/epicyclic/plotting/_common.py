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

def hatched_rect(ax: Any, x0: float, y0: float, width: float, height: float, role: str, *,
                 spacing: tuple[float, float], lw: float = 1.0, label: str | None = None, zorder: float = 2) -> None:
    """A filled rectangle with Brandenberger's hatching drawn as plain lines.

    Vertical lines for a drive, horizontal for a load, both for the loss.
    Drawn as lines (not as a matplotlib hatch pattern) so that the SVG needs
    no ``url(#pattern)`` reference and embeds in any page.  ``spacing`` is
    (dx, dy) in data units.
    """
    from matplotlib.collections import LineCollection
    from matplotlib.patches import Rectangle

    style = ROLE_STYLE[role]
    ax.add_patch(Rectangle((x0, y0), width, height, facecolor=style["facecolor"], edgecolor="black", lw=lw,
                           zorder=zorder, label=label))
    xa, xb = sorted((x0, x0 + width))
    ya, yb = sorted((y0, y0 + height))
    segments = []
    if role in ("drive", "loss") and spacing[0] > 0:
        k = math.floor(xa / spacing[0]) + 1
        while k * spacing[0] < xb and len(segments) < 2000:
            segments.append([(k * spacing[0], ya), (k * spacing[0], yb)])
            k += 1
    if role in ("load", "loss") and spacing[1] > 0:
        k = math.floor(ya / spacing[1]) + 1
        while k * spacing[1] < yb and len(segments) < 4000:
            segments.append([(xa, k * spacing[1]), (xb, k * spacing[1])])
            k += 1
    if segments:
        ax.add_collection(LineCollection(segments, colors="black", linewidths=0.6, zorder=zorder + 0.1))


def hatch_legend(ax: Any, roles: list[str], **kwargs: Any) -> Any:
    """A legend with one hatched swatch per role (drawn as lines, like the rectangles)."""
    from matplotlib.legend_handler import HandlerBase
    from matplotlib.lines import Line2D
    from matplotlib.patches import Rectangle

    class Swatch(HandlerBase):
        def __init__(self, role: str) -> None:
            super().__init__()
            self.role = role

        def create_artists(self, legend, orig_handle, xdescent, ydescent, width, height, fontsize, trans):
            x0, y0 = -xdescent, -ydescent
            art = [Rectangle((x0, y0), width, height, facecolor=ROLE_STYLE[self.role]["facecolor"],
                             edgecolor="black", lw=2.0 if self.role == "loss" else 0.8, transform=trans)]
            if self.role in ("drive", "loss"):
                art += [Line2D([x0 + f * width] * 2, [y0, y0 + height], color="black", lw=0.6, transform=trans)
                        for f in (0.25, 0.5, 0.75)]
            if self.role in ("load", "loss"):
                art += [Line2D([x0, x0 + width], [y0 + f * height] * 2, color="black", lw=0.6, transform=trans)
                        for f in (0.33, 0.67)]
            return art

    proxies = [Rectangle((0, 0), 1, 1, label=ROLE_STYLE[r]["label"]) for r in roles]
    handles, labels = ax.get_legend_handles_labels()
    return ax.legend([*handles, *proxies], [*labels, *(p.get_label() for p in proxies)],
                     handler_map={p: Swatch(r) for p, r in zip(proxies, roles)}, **kwargs)


#: Colour cycle for shafts / members (colour-blind friendly, Okabe–Ito).
#: The Okabe–Ito yellow is replaced by a dark gold that stays visible as a thin line on white.
SHAFT_COLOURS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#8C6D1F")


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
    return self_contained_svg(text[start:] if start >= 0 else text)


_USE = re.compile(r'<use xlink:href="#([^"]+)"((?: [a-z-]+="[^"]*")*)\s*/>')
_DEF_PATH = re.compile(r'<path id="([^"]+)" d="([^"]*)"(?: style="([^"]*)")?\s*/>')


def self_contained_svg(text: str) -> str:
    """matplotlib SVG without internal references (``url(#…)``, ``xlink:href``).

    Marker definitions (``<use xlink:href>``) are inlined as paths, clip
    paths are dropped (the figures set limits that hold every artist) and the
    RDF metadata removed, so that the SVG embeds in a page that forbids
    ``url(`` and ``href=`` (the HTML report's self-containment check).
    """
    defs = {m.group(1): (m.group(2), m.group(3) or "") for m in _DEF_PATH.finditer(text)}

    def inline(match: re.Match[str]) -> str:
        d, def_style = defs.get(match.group(1), ("", ""))
        attrs = dict(re.findall(r'([a-z-]+)="([^"]*)"', match.group(2)))
        x, y = attrs.pop("x", "0"), attrs.pop("y", "0")
        style = attrs.pop("style", def_style)
        rest = "".join(f' {k}="{v}"' for k, v in attrs.items() if k != "clip-path")
        return f'<path d="{d}" transform="translate({x} {y})" style="{style}"{rest}/>'

    text = _USE.sub(inline, text)
    text = re.sub(r'\s*clip-path="url\(#[^)]*\)"', "", text)
    text = re.sub(r"<clipPath\b.*?</clipPath>\s*", "", text, flags=re.S)
    text = re.sub(r"<metadata>.*?</metadata>\s*", "", text, flags=re.S)
    text = re.sub(r'\s*xmlns:xlink="[^"]*"', "", text)
    return text


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
    """Write ``fig`` to ``path`` (.svg, .png or .pdf by suffix) and close it.

    In SVG, text stays text (searchable, small), as in :func:`figure_svg`.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure (closed afterwards).
    path : str or Path
        The file; its suffix (.svg, .png, .pdf) chooses the format; missing folders
        are made.
    dpi : int, default 150
        Resolution of a PNG.

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    PlottingError
        Another suffix.
    """
    import matplotlib

    path = check_suffix(path, FIGURE_SUFFIXES, "save figure")
    path.parent.mkdir(parents=True, exist_ok=True)
    with matplotlib.rc_context({"svg.fonttype": "none", "svg.hashsalt": "epicyclic"}):
        fig.savefig(path, dpi=dpi, bbox_inches="tight")
    pyplot().close(fig)
    return path


def lever_elements(train: GearTrain) -> list[tuple[Any, tuple[str, str, str], tuple[str, str, str], float]]:
    """(element, ports, shafts, ratio) of every three-port element with gears.

    A planetary set has ports (sun, ring, carrier) and ratio i0; a fixed-axis
    stage has ports (first, second, housing) and its speed ratio: it is a set
    whose carrier is the housing (Queitsch, Bild 3).
    """
    out = []
    for element in train.elements:
        if isinstance(element, PlanetarySet):
            out.append((element, ("sun", "ring", "carrier"), element.shafts, element.stationary_ratio))
        elif isinstance(element, GearStage):
            out.append((element, ("first", "second", "housing"), (element.first, element.second, HOUSING),
                        element.ratio))
    return out


def member_name(pset: PlanetarySet, port: str) -> str:
    """A port's name as the set's file says it: ``first``/``second`` for two rings or two suns.

    >>> member_name(PlanetarySet.two_rings("W", first="a", second="b", carrier="c", z_first=81,
    ...                                    z_planet_first=27, z_planet_second=24, z_second=78), "sun")
    'first'
    """
    return port if pset.teeth is None else pset.teeth.label(port)


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


def result_html(result: Any) -> str:
    """A map-like result in a notebook: its text table above its figure (``result.table()``, ``.plot()``).

    Parameters
    ----------
    result : EfficiencyMap or ShiftMap
        Anything with ``table()`` and ``plot()``.
    """
    import html

    fig = result.plot()
    svg = figure_svg(fig)
    fig.clf()
    return f"<div><pre>{html.escape(result.table())}</pre>{svg}</div>"


def save_result(result: Any, path: Path) -> Path:
    """Write a map-like result by the suffix: ``.csv`` (``to_csv()``), ``.json`` (``to_json()``) or its
    figure (``.png``/``.svg``/``.pdf``); the caller has checked the suffix.

    Parameters
    ----------
    result : EfficiencyMap or ShiftMap
    path : Path
    """
    path.parent.mkdir(parents=True, exist_ok=True)
    suffix = path.suffix.lower()
    if suffix == ".csv":
        path.write_text(result.to_csv(), encoding="utf-8")
    elif suffix == ".json":
        path.write_text(result.to_json(), encoding="utf-8")
    else:
        save_figure(result.plot(), path)
    return path
