"""Label placement on a drawn figure: text boxes measured by the renderer, moved apart, kept inside.

Labels are placed where they belong (next to their node, bar or edge) and
then :func:`separate` measures every text's box with matplotlib's renderer
(``Text.get_window_extent``) and pushes overlapping labels apart vertically,
a few points at a time, until no two boxes overlap; :func:`keep_inside` moves
a label that sticks out of the figure back in.  Only the labels passed in are
moved; axes titles and tick labels stay where matplotlib put them.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

__all__ = ["overlapping_pairs", "separate", "keep_inside", "boxes", "fit_titles", "finish", "clear_suptitle",
           "legends"]

#: Clearance (pixels at the figure's dpi) kept between two label boxes.
PAD = 1.5


def _renderer(fig: Any) -> Any:
    """The canvas renderer: text extents need it, not a full draw (the layout is already fixed)."""
    return fig.canvas.get_renderer()


def boxes(fig: Any, texts: Iterable[Any]) -> list[tuple[Any, Any]]:
    """(text, window extent in pixels) of every visible, non-empty text."""
    renderer = _renderer(fig)
    return [(t, t.get_window_extent(renderer)) for t in texts if t.get_visible() and t.get_text().strip()]


def overlapping_pairs(fig: Any, texts: Iterable[Any], pad: float = 0.0) -> list[tuple[Any, Any]]:
    """Pairs of texts whose boxes overlap by more than ``pad`` pixels in both directions."""
    found = boxes(fig, texts)
    pairs = []
    for i, (a, ba) in enumerate(found):
        for b, bb in found[i + 1:]:
            if min(ba.x1, bb.x1) - max(ba.x0, bb.x0) > pad and min(ba.y1, bb.y1) - max(ba.y0, bb.y0) > pad:
                pairs.append((a, b))
    return pairs


def _shift(text: Any, dx_px: float, dy_px: float) -> None:
    """Move a text by (dx, dy) pixels, whatever coordinates it is placed in."""
    if hasattr(text, "xyann") and getattr(text, "anncoords", None) == "offset points":
        scale = 72.0 / text.figure.dpi
        x, y = text.xyann
        text.xyann = (x + dx_px * scale, y + dy_px * scale)
        return
    transform = text.get_transform()
    x, y = transform.transform(text.get_position())
    text.set_position(tuple(transform.inverted().transform((x + dx_px, y + dy_px))))


def separate(fig: Any, texts: Iterable[Any], *, fixed: Iterable[Any] = (), max_rounds: int = 60) -> int:
    """Push overlapping labels apart vertically (both move, by half the overlap each); returns rounds used.

    ``fixed`` artists (node boxes, say) are obstacles: a label overlapping one
    is moved clear of it, the obstacle stays.
    """
    texts = list(texts)
    renderer = _renderer(fig)
    obstacles = [a.get_window_extent(renderer) for a in fixed]
    for rounds in range(max_rounds):
        found = boxes(fig, texts)
        moved = False
        for text, box in found:
            for ob in obstacles:
                dx = min(box.x1, ob.x1) - max(box.x0, ob.x0)
                dy = min(box.y1, ob.y1) - max(box.y0, ob.y0)
                if dx > 0 and dy > -PAD:
                    up = (box.y0 + box.y1) >= (ob.y0 + ob.y1)
                    _shift(text, 0.0, (ob.y1 - box.y0 + PAD) if up else -(box.y1 - ob.y0 + PAD))
                    moved = True
        if moved:
            continue
        for i, (a, ba) in enumerate(found):
            for b, bb in found[i + 1:]:
                dx = min(ba.x1, bb.x1) - max(ba.x0, bb.x0)
                dy = min(ba.y1, bb.y1) - max(ba.y0, bb.y0)
                if dx <= 0 or dy <= -PAD:
                    continue
                push = (dy + PAD) / 2 + 0.5
                upper, lower = (a, b) if (ba.y0 + ba.y1) >= (bb.y0 + bb.y1) else (b, a)
                _shift(upper, 0.0, push)
                _shift(lower, 0.0, -push)
                moved = True
        if not moved:
            return rounds
    return max_rounds


def keep_inside(fig: Any, texts: Iterable[Any], margin: float = 2.0) -> None:
    """Move labels that stick out of the figure back inside it."""
    frame = fig.bbox
    for text, box in boxes(fig, texts):
        dx = max(frame.x0 + margin - box.x0, 0.0) - max(box.x1 - (frame.x1 - margin), 0.0)
        dy = max(frame.y0 + margin - box.y0, 0.0) - max(box.y1 - (frame.y1 - margin), 0.0)
        if dx or dy:
            _shift(text, dx, dy)


def _wrap(text: Any, width_px: float, renderer: Any) -> None:
    """Re-wrap a text (keeping its own line breaks) until it is at most ``width_px`` wide."""
    import textwrap

    for _ in range(6):
        box = text.get_window_extent(renderer)
        if box.width <= width_px or box.width <= 0:
            return
        lines = text.get_text().split("\n")
        longest = max(len(line) for line in lines)
        chars = max(12, int(longest * width_px / box.width * 0.95))
        text.set_text("\n".join(part for line in lines for part in (textwrap.wrap(line, chars) or [""])))


def fit_titles(fig: Any) -> None:
    """Wrap the figure title, the axes titles and axis labels that are wider than the room they have."""
    renderer = _renderer(fig)
    frame = fig.bbox
    if fig._suptitle is not None:
        _wrap(fig._suptitle, 0.96 * frame.width, renderer)
    for ax in fig.axes:
        if not ax.axison:
            continue
        box = ax.get_window_extent(renderer)
        _wrap(ax.title, box.width * 1.1, renderer)
        _wrap(ax.xaxis.label, box.width, renderer)
        _wrap(ax.yaxis.label, box.height, renderer)


def clear_suptitle(fig: Any, gap: float = 4.0) -> None:
    """Lower the subplots where their titles, labels or legends reach into the figure title."""
    if fig._suptitle is None or not fig._suptitle.get_text():
        return
    renderer = _renderer(fig)
    bottom = fig._suptitle.get_window_extent(renderer).y0
    top = max((ax.get_tightbbox(renderer).y1 for ax in fig.axes if ax.get_visible()), default=0.0)
    if top > bottom - gap:
        shift = (top - bottom + gap) / fig.bbox.height
        fig.subplots_adjust(top=fig.subplotpars.top - shift)


def legends(fig: Any) -> list[Any]:
    """Every legend of the figure (obstacles for labels)."""
    found = [ax.get_legend() for ax in fig.axes] + list(fig.legends)
    return [lg for lg in found if lg is not None]


def finish(fig: Any, texts: Iterable[Any] = (), *, fixed: Iterable[Any] = (), rect: Any = None) -> Any:
    """Lay a figure out: wrap long titles, tight layout, clear the title, labels apart and inside the canvas."""
    texts = list(texts)
    fit_titles(fig)
    if rect is None:
        fig.tight_layout()
    else:
        fig.tight_layout(rect=rect)
    fit_titles(fig)
    clear_suptitle(fig)
    separate(fig, texts, fixed=[*fixed, *legends(fig)])
    keep_inside(fig, texts)
    return fig
