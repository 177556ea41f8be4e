"""Every file in examples/ × every kind of picture renders, and the drawing itself is checked.

Checked from the rendered figure (matplotlib's renderer extents,
``Text.get_window_extent``) and, for the animation, from the SVG text:

* no two label boxes overlap (labels: texts placed on the axes and the figure);
* everything lies inside the canvas (labels, titles, tick labels, legends);
* no label shows a value below the zero rule (a number that is round-off
  against the figure's largest number, or ``-0``);
* stroke widths are a small fraction of the drawing.

A transmission file without operating point is drawn at the default operating point in its
first gear, as ``epicyclic plot`` does; the speed chart where the file has a
transmission.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from PIL import Image

from epicyclic.io import load_train_file
from epicyclic.plotting import KINDS, figure, figure_subject, planetary_animation
from epicyclic.plotting.values import ZERO_RELATIVE

EXAMPLES = sorted((Path(__file__).resolve().parents[2] / "examples").glob("*.toml"))
SVG = "{http://www.w3.org/2000/svg}"
NUMBER = re.compile(r"(?<![\w.])[-−]?\d+(?:\.\d+)?(?:e[-+]?\d+)?")
#: A stroke wider than this fraction of the figure's smaller side is a blot, not a line.
STROKE_FRACTION = 0.03
#: Pixels two label boxes may share (anti-aliasing), and a label may stick out of the canvas.
SLACK = 1.0

_subjects: dict[str, object] = {}


def _subject(path: Path):
    if path.name not in _subjects:
        _subjects[path.name] = figure_subject(load_train_file(path))
    return _subjects[path.name]


def _cases():
    for path in EXAMPLES:
        kinds = list(KINDS) + (["chart"] if "[transmission]" in path.read_text() else [])
        for kind in kinds:
            yield pytest.param(path, kind, id=f"{path.stem}-{kind}")


# ---------------------------------------------------------------------- checks on a matplotlib figure
def _labels(fig):
    texts = [t for ax in fig.axes for t in ax.texts] + list(fig.texts)
    return [t for t in texts if t.get_visible() and t.get_text().strip()]


def _all_texts(fig):
    out = _labels(fig)
    if fig._suptitle is not None:
        out.append(fig._suptitle)
    for ax in fig.axes:
        if not ax.axison:
            continue
        out += [ax.title, ax.xaxis.label, ax.yaxis.label]
        for axis in (ax.xaxis, ax.yaxis):  # the ticks matplotlib draws (those inside the view limits)
            out += [tick.label1 for tick in axis._update_ticks() if tick.label1.get_visible()]
        legend = ax.get_legend()
        if legend is not None:
            out += list(legend.get_texts())
    return [t for t in out if t.get_visible() and t.get_text().strip()]


def _numbers(text: str) -> list[float]:
    return [float(n.replace("−", "-")) for n in NUMBER.findall(text)]


def check_figure(fig) -> None:
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    frame = fig.bbox
    # 1. label boxes do not overlap
    boxes = [(t, t.get_window_extent(renderer)) for t in _labels(fig)]
    for i, (a, ba) in enumerate(boxes):
        for b, bb in boxes[i + 1:]:
            dx = min(ba.x1, bb.x1) - max(ba.x0, bb.x0)
            dy = min(ba.y1, bb.y1) - max(ba.y0, bb.y0)
            assert dx <= SLACK or dy <= SLACK, f"labels overlap: {a.get_text()!r} and {b.get_text()!r}"
    # ... nor a legend, and no axes (title, labels, legend) reaches into the figure title
    for legend in [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None]:
        lb = legend.get_window_extent(renderer)
        for t, box in boxes:
            dx = min(box.x1, lb.x1) - max(box.x0, lb.x0)
            dy = min(box.y1, lb.y1) - max(box.y0, lb.y0)
            assert dx <= SLACK or dy <= SLACK, f"label {t.get_text()!r} on a legend"
    if fig._suptitle is not None:
        bottom = fig._suptitle.get_window_extent(renderer).y0
        for ax in fig.axes:
            assert ax.get_tightbbox(renderer).y1 <= bottom + SLACK, f"{ax.get_title()!r} reaches into the figure title"
    # 2. everything inside the canvas
    for t in _all_texts(fig):
        box = t.get_window_extent(renderer)
        assert (box.x0 >= frame.x0 - SLACK and box.x1 <= frame.x1 + SLACK and box.y0 >= frame.y0 - SLACK
                and box.y1 <= frame.y1 + SLACK), f"outside the canvas: {t.get_text()!r}"
    # 3. no label shows round-off
    words = [t.get_text() for t in _all_texts(fig)]
    values = [abs(v) for w in words for v in _numbers(w)]
    top = max(values, default=0.0)
    for w in words:
        assert not re.search(r"(?<![\w.])[-−]0(?:\.0*)?(?![\d.e])", w), f"'-0' in {w!r}"
        for v in _numbers(w):
            assert v == 0 or abs(v) > ZERO_RELATIVE * top, f"round-off {v} shown in {w!r}"
        assert not re.search(r"e-(?:[1-9]\d|[6-9])\b", w), f"a tiny number in {w!r}"
    # 4. strokes are thin against the drawing
    limit = STROKE_FRACTION * min(frame.width, frame.height) * 72.0 / fig.dpi  # points
    for ax in fig.axes:
        for artist in [*ax.lines, *ax.patches, *ax.collections]:
            widths = artist.get_linewidth()
            for w in (widths if hasattr(widths, "__len__") else [widths]):
                assert w <= limit, f"stroke {w:.1f} pt > {limit:.1f} pt in {type(artist).__name__}"


@pytest.mark.parametrize(("path", "kind"), list(_cases()))
def test_every_kind_of_every_example(path, kind):
    s = _subject(path)
    fig = figure(s.solution, kind, context=s.context, transmission=s.transmission)
    check_figure(fig)
    heading = fig._suptitle.get_text()
    assert s.context.title in heading
    if s.gear is not None:
        assert f"gear {s.gear}" in heading  # the gear (and the shift state) in every title


# ---------------------------------------------------------------------- the animation
def check_svg(text: str, set_has_teeth: bool) -> None:
    root = ET.fromstring(text)
    x0, y0, w, h = (float(v) for v in root.get("viewBox").split())
    assert float(root.get("width")) > 0 and "url(" not in text and "<script" not in text
    for el in root.iter():
        sw = el.get("stroke-width")
        if sw is not None:
            assert float(sw) <= STROKE_FRACTION * w, f"stroke {sw} of {w:.3g} wide drawing"
    shown = []
    for el in root.iter(f"{SVG}text"):
        content = "".join(el.itertext())
        size = float(el.get("font-size"))
        x, y = float(el.get("x")), float(el.get("y"))
        assert x >= x0 and x + 0.56 * size * len(content) <= x0 + w * 1.02, f"caption wider than the canvas: {content!r}"
        assert y0 <= y - size and y <= y0 + h, f"caption below the canvas: {content!r}"
        shown.append(content)
    words = " ".join(shown)
    assert ("schematic" in words) != set_has_teeth
    assert not re.search(r"e-(?:[1-9]\d|[6-9])\b", words), words


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_animation_of_every_example(path, tmp_path):
    s = _subject(path)
    for pset in s.solution.train.planetary_sets:
        anim = planetary_animation(s.solution, pset.name, context=s.context, frames=3, size=160)
        check_svg(anim.svg(), pset.teeth is not None)
    gif = anim.gif(tmp_path / "a.gif", dpi=40)
    with Image.open(gif) as im:
        assert im.format == "GIF" and im.size[0] == 160
