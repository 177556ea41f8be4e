"""Notebook previews of the descriptions: a schematic and the key figures, before anything is solved.

``PlanetarySet._repr_html_``, ``GearTrain._repr_html_`` and ``Transmission._repr_html_`` call these
(lazily: the model does not depend on the pictures), so that a set, a train or a transmission shows
itself in Jupyter as the results do:

* a planetary set: its gears drawn still (its own teeth, or the schematic teeth of a set given by
  i0 alone, labelled so) beside a table of i0, η0, tooth counts and planets;
* a train: the lever diagram of the train as described (Benford & Leising 1981) beside a table of its
  elements;
* a transmission: the lever diagram of the free train beside the shift schedule with each gear's
  ratio and step.

All of it is one self-contained HTML fragment (inline SVG, no scripts, every text escaped).

References
----------
Benford, H. L. and Leising, M. B., "The Lever Analogy", SAE 810102 (1981).
"""

from __future__ import annotations

import html
from typing import Any

from ..model.elements import Brake, Clutch, GearStage
from ..model.planetary import PlanetarySet
from .values import fmt

__all__ = ["set_svg", "set_html", "train_html", "transmission_html"]

#: Width of the still drawing of a set, pixels.
SET_SIZE = 260
_TABLE = "border-collapse:collapse;font-size:0.9em"
_CELL = "border:1px solid #ccc;padding:2px 6px;text-align:left"


def _table(caption: str, header: tuple[str, ...], rows: list[tuple[Any, ...]]) -> str:
    head = "".join(f'<th style="{_CELL}">{html.escape(str(h))}</th>' for h in header)
    body = "".join("<tr>" + "".join(f'<td style="{_CELL}">{html.escape(str(c))}</td>' for c in row) + "</tr>"
                   for row in rows)
    return (f'<table style="{_TABLE}"><caption style="text-align:left;font-weight:bold">{html.escape(caption)}'
            f"</caption><tr>{head}</tr>{body}</table>")


def _side_by_side(picture: str, table: str) -> str:
    return (f'<div style="display:flex;gap:1em;align-items:flex-start;flex-wrap:wrap">'
            f"<div>{picture}</div><div>{table}</div></div>")


def set_svg(pset: PlanetarySet, size: int = SET_SIZE) -> str:
    """The set's gears drawn still, as inline SVG (schematic teeth for a set given by i0 alone).

    Parameters
    ----------
    pset : PlanetarySet
    size : int, default 260
        Width in pixels.

    Returns
    -------
    str
        ``<svg ...>`` text.
    """
    from ._gears import gear_shapes
    from ._svg import still_svg
    from .speed_plan import set_layout

    layout = set_layout(pset)
    shapes = gear_shapes(layout, layout.drawn.teeth, pset.planets)
    return still_svg(shapes, f"planetary set {pset.name}", size, [])


def _set_rows(pset: PlanetarySet) -> list[tuple[str, str]]:
    rows = [("sun (first central member)", pset.sun), ("ring (second central member)", pset.ring),
            ("carrier", pset.carrier), ("stationary ratio i0", fmt(pset.stationary_ratio, 6)),
            ("stationary efficiency η0", fmt(pset.stationary_efficiency, 6)),
            ("kind", "plus set" if pset.is_plus_set else "minus set"), ("planets", str(pset.planets))]
    if pset.teeth is not None:
        t = pset.teeth
        rows.append(("teeth (sun/planet/ring)", "/".join(str(z) for z in (t.sun, *t.planet, t.ring))))
    else:
        from .schematic import drawn_set

        t = drawn_set(pset).teeth
        rows.append(("drawn with", "schematic teeth " + "/".join(str(z) for z in (t.sun, *t.planet, t.ring))
                     + " (the set is given by i0 alone)"))
    return rows


def set_html(pset: PlanetarySet) -> str:
    """A set as HTML: the still drawing beside its key figures.

    Parameters
    ----------
    pset : PlanetarySet

    Returns
    -------
    str
    """
    return _side_by_side(set_svg(pset), _table(f"PlanetarySet {pset.name}", ("", ""), _set_rows(pset)))


def _element_rows(train: Any) -> list[tuple[str, str, str, str]]:
    rows = []
    for element in train.elements:
        if isinstance(element, PlanetarySet):
            rows.append((element.name, "planetary set", f"{element.sun}, {element.ring}, {element.carrier}",
                         f"i0 {fmt(element.stationary_ratio, 5)}, η0 {fmt(element.stationary_efficiency, 5)}"))
        elif isinstance(element, GearStage):
            rows.append((element.name, "gear stage", f"{element.first}, {element.second}",
                         f"ratio {fmt(element.ratio, 5)}, η {fmt(element.efficiency, 5)}"))
        elif isinstance(element, (Clutch, Brake)):
            kind = "clutch" if isinstance(element, Clutch) else "brake"
            shafts = ", ".join(element.shafts)
            rows.append((element.name, kind, shafts, "engaged" if element.engaged else "open"))
        else:
            rows.append((element.name, type(element).__name__, "", ""))
    return rows


def _lever_svg(train: Any, **kwargs: Any) -> str:
    from ..errors import EpicyclicError
    from ._common import figure_svg
    from .lever import lever_diagram

    try:
        return figure_svg(lever_diagram(train=train, **kwargs).plot())
    except EpicyclicError as exc:  # a train the lever analogy cannot draw (no set): the table alone
        return f"<p><i>no lever diagram: {html.escape(str(exc))}</i></p>"


def train_html(train: Any) -> str:
    """A train as HTML: its lever diagram beside the table of its elements.

    Parameters
    ----------
    train : GearTrain

    Returns
    -------
    str
    """
    table = _table(f"GearTrain {train.name or ''}: {len(train.elements)} elements, shafts "
                   f"{', '.join(train.moving_shafts)}", ("element", "kind", "shafts", "figures"), _element_rows(train))
    return _side_by_side(_lever_svg(train), table)


def transmission_html(transmission: Any) -> str:
    """A transmission as HTML: the lever diagram of the free train beside the shift schedule with
    each gear's ratio (n_in/n_out, from the kinematics) and the step to the next gear.

    Parameters
    ----------
    transmission : Transmission

    Returns
    -------
    str
    """
    ratios = transmission.ratios
    forward = [g for g in transmission.gears if ratios[g] > 0]
    rows = []
    for gear in transmission.gears:
        ratio = ratios[gear]
        k = forward.index(gear) if gear in forward else None
        step = fmt(ratio / ratios[forward[k + 1]], 4) if k is not None and k + 1 < len(forward) else ""
        rows.append((gear, " + ".join(transmission.schedule[gear]) or "—", fmt(ratio, 5), step))
    spread = ratios[forward[0]] / ratios[forward[-1]] if len(forward) > 1 else None
    caption = (f"Transmission {transmission.name}: input {transmission.input}, output {transmission.output}"
               + (f", spread {fmt(spread, 4)}" if spread else ""))
    table = _table(caption, ("gear", "engaged", "ratio", "step"), rows)
    return _side_by_side(_lever_svg(transmission.train, transmission=transmission), table)
