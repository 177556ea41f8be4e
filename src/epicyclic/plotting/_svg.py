"""Drawing of a planetary animation: SMIL SVG and GIF.

The SVG rotates each member with ``animateTransform`` (type ``rotate``): sun
and ring about the centre, the carrier group (arms and planets) about the
centre, each planet inside it about its own axis at its speed *relative to
the carrier*, so the absolute planet speed is the sum (the Willis
superposition).  No scripts, no external references.

Everything is sized from the drawing: the set's outer radius ``R`` sets the
stroke widths (a few thousandths of ``R``), the font size and the caption,
which is wrapped to the drawing's width and lies inside the canvas.  The
drawing takes the animation object duck-typed: this module does not import
:mod:`.animation` (that one imports this lazily).
"""

from __future__ import annotations

import html
import math
import textwrap
from pathlib import Path
from typing import Any

from ._common import SHAFT_COLOURS, pyplot
from ._gears import WILLIS_PHASES, GearShape, extent, gear_outline

__all__ = ["animation_svg", "write_gif", "STROKE"]

COLOURS = {"sun": SHAFT_COLOURS[0], "ring": SHAFT_COLOURS[1], "carrier": SHAFT_COLOURS[2],
           "planet": SHAFT_COLOURS[3], "planet2": SHAFT_COLOURS[4]}
#: Stroke widths as fractions of the set's outer radius R.
STROKE = {"outline": 0.004, "mark": 0.006, "dash": 0.008, "arm": 0.05}
#: Font size of the caption as a fraction of R; characters are about 0.56 font sizes wide.
FONT = 0.058
CHAR = 0.56


def _path(points: list[tuple[float, float]]) -> str:
    return "M " + " L ".join(f"{x:.3f} {y:.3f}" for x, y in points) + " Z"


def _rim(shape: GearShape) -> list[tuple[float, float]]:
    """The outer edge of an internal gear's rim: a circle 3.5 modules beyond the pitch circle."""
    outer = shape.radius + 3.5 * shape.module
    return [(outer * math.cos(2 * math.pi * k / 96), outer * math.sin(2 * math.pi * k / 96)) for k in range(96)]


def _ring_path(shape: GearShape) -> str:
    return _path(_rim(shape)) + " " + _path(gear_outline(shape.teeth, shape.radius, internal=True))


def _ring_annulus(shape: GearShape):
    """The internal gear as a matplotlib path: its rim (3.5 modules beyond the pitch circle) and the tooth
    outline as a hole, wound the other way so that only the ring between them is filled."""
    from matplotlib.path import Path as MplPath

    inner = gear_outline(shape.teeth, shape.radius, internal=True)
    outer = _rim(shape)
    if _signed_area(inner) * _signed_area(outer) > 0:
        inner = inner[::-1]
    vertices = [*outer, outer[0], *inner, inner[0]]
    codes = ([MplPath.MOVETO] + [MplPath.LINETO] * (len(outer) - 1) + [MplPath.CLOSEPOLY]
             + [MplPath.MOVETO] + [MplPath.LINETO] * (len(inner) - 1) + [MplPath.CLOSEPOLY])
    return MplPath(vertices, codes)


def _signed_area(points: list[tuple[float, float]]) -> float:
    """Twice the signed area of a closed polygon (> 0 counter-clockwise; the shoelace formula)."""
    return sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(points, [*points[1:], points[0]]))


def _rotation(anim: Any, member: str, relative_to: str | None = None) -> str:
    """animateTransform of a member (optionally relative to the carrier)."""
    if anim.willis:
        marks = [anim.angles(k * anim.phase_frames) for k in range(4)]
        values = [m[member] - (m[relative_to] if relative_to else 0.0) for m in marks]
        if max(abs(v) for v in values) < 1e-12:
            return ""
        dur = 3 * anim.phase_frames / anim.fps
        return (f'<animateTransform attributeName="transform" type="rotate" values="{";".join(f"{v:.4f}" for v in values)}" '
                f'keyTimes="0;{1 / 3:.6f};{2 / 3:.6f};1" dur="{dur:.6g}s" repeatCount="indefinite"/>')
    rate = anim.degrees_per_second(member) - (anim.degrees_per_second(relative_to) if relative_to else 0.0)
    if abs(rate) < 1e-9:
        return ""
    period = 360.0 / abs(rate)
    return (f'<animateTransform attributeName="transform" type="rotate" from="0" to="{360 if rate > 0 else -360}" '
            f'dur="{period:.9g}s" repeatCount="indefinite"/>')


def _gear(shape: GearShape, colour: str, R: float) -> str:
    sw = STROKE["outline"] * R
    if shape.member == "ring" and shape.internal:
        body = (f'<path d="{_ring_path(shape)}" fill="{colour}" fill-opacity="0.35" fill-rule="evenodd" '
                f'stroke="black" stroke-width="{sw:.4g}"/>')
    elif shape.step:  # second gear of a stepped planet: drawn over the first, outlined and half transparent
        body = (f'<path d="{_path(gear_outline(shape.teeth, shape.radius))}" fill="{COLOURS["planet2"]}" '
                f'fill-opacity="0.35" stroke="{colour}" stroke-width="{STROKE["dash"] * R:.4g}" '
                f'stroke-dasharray="{0.03 * R:.4g} {0.015 * R:.4g}"/>')
    elif shape.member == "ring":  # an external second central gear
        body = (f'<path d="{_path(gear_outline(shape.teeth, shape.radius))}" fill="{colour}" fill-opacity="0.3" '
                f'stroke="{colour}" stroke-width="{STROKE["dash"] * R:.4g}" '
                f'stroke-dasharray="{0.03 * R:.4g} {0.015 * R:.4g}"/>')
    else:
        body = (f'<path d="{_path(gear_outline(shape.teeth, shape.radius))}" fill="{colour}" fill-opacity="0.55" '
                f'stroke="black" stroke-width="{sw:.4g}"/>')
    mark = 0.8 * shape.radius
    return body + (f'<line x1="0" y1="0" x2="{mark:.3f}" y2="0" stroke="black" '
                   f'stroke-width="{STROKE["mark"] * R:.4g}"/>')


def caption_lines(anim: Any, width_chars: int) -> list[str]:
    """The heading and caption, wrapped to ``width_chars`` characters per line."""
    out: list[str] = []
    for line in [*anim.heading.split("\n"), *anim.caption()]:
        out += textwrap.wrap(line, width_chars) or [""]
    return out


def _drawing(shapes: tuple[GearShape, ...], R: float, rotation: Any) -> list[str]:
    """The SVG elements of the set: central gears, carrier arms, planets; ``rotation(member, relative_to)``
    gives each member's animateTransform ("" for a still picture)."""
    out = []
    for shape in shapes[:2]:  # the central gears, in drawing order
        member = shape.member
        out.append(f'<g transform="rotate({shape.phase:.4f})"><g>{_gear(shape, COLOURS[member], R)}'
                   f'{rotation(member)}</g></g>')
    out.append("<g>")  # carrier
    axes = sorted({(s.axis, s.offset) for s in shapes if s.member.startswith("planet")})
    for axis, offset in axes:
        x, y = axis * math.cos(math.radians(offset)), axis * math.sin(math.radians(offset))
        out.append(f'<line x1="0" y1="0" x2="{x:.3f}" y2="{y:.3f}" stroke="{COLOURS["carrier"]}" '
                   f'stroke-width="{STROKE["arm"] * R:.4g}" stroke-linecap="round" stroke-opacity="0.6"/>')
    out.append(f'<circle r="{0.05 * R:.3f}" fill="{COLOURS["carrier"]}"/>')
    for shape in shapes:
        if not shape.member.startswith("planet"):
            continue
        colour = COLOURS[shape.member]
        out.append(f'<g transform="rotate({shape.offset:.4f}) translate({shape.axis:.4f},0)">'
                   f'<g transform="rotate({shape.phase - shape.offset:.4f})"><g>'
                   f'{_gear(shape, colour, R)}{rotation(shape.member, "carrier")}</g></g>'
                   f'<circle r="{0.02 * R:.3f}" fill="black"/></g>')
    out.append(rotation("carrier"))
    out.append("</g></g>")
    return out


def still_svg(shapes: tuple[GearShape, ...], label: str, px: int, lines: list[str]) -> str:
    """A still SVG of a set's gears (no motion), ``px`` wide, with ``lines`` of text under it."""
    R = extent(shapes)
    size = FONT * R
    height = 2 * R + (1.35 * len(lines) + 0.6) * size
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{-R:.3f} {-R:.3f} {2 * R:.3f} {height:.3f}" '
           f'width="{px}" height="{px * height / (2 * R):.0f}" role="img" aria-label="{html.escape(label)}">',
           f"<title>{html.escape(label)}</title>", '<g transform="scale(1,-1)">',
           *_drawing(shapes, R, lambda member, relative_to=None: "")]  # closes the scale group too
    for k, text in enumerate(lines):
        out.append(f'<text x="{-R + size:.3f}" y="{R + 1.3 * size + 1.35 * k * size:.3f}" font-size="{size:.3f}" '
                   f'font-family="sans-serif">{html.escape(text)}</text>')
    out.append("</svg>")
    return "\n".join(out)


def animation_svg(anim: Any) -> str:
    """The animated SVG text (see module docs)."""
    R = extent(anim.shapes)
    size = FONT * R
    width = 2 * R
    lines = caption_lines(anim, max(20, int((width - 2 * size) / (CHAR * size))))
    caption_h = (1.35 * len(lines) + (2.0 if anim.willis else 0.6)) * size
    height = 2 * R + caption_h
    px = anim.size
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{-R:.3f} {-R:.3f} {width:.3f} {height:.3f}" '
           f'width="{px}" height="{px * height / width:.0f}" role="img" '
           f'aria-label="animation of planetary set {html.escape(anim.set_name)}">',
           f"<title>{html.escape(anim.heading or anim.set_name)}</title>",
           '<g transform="scale(1,-1)">']
    out += _drawing(anim.shapes, R, lambda member, relative_to=None: _rotation(anim, member, relative_to))
    y = R + 1.3 * size
    heading = len(anim.heading.split("\n")[0]) if anim.heading else 0
    for k, text in enumerate(lines):
        weight = ' font-weight="bold"' if k == 0 and heading else ""
        out.append(f'<text x="{-R + size:.3f}" y="{y + 1.35 * k * size:.3f}" font-size="{size:.3f}" '
                   f'font-family="sans-serif"{weight}>{html.escape(text)}</text>')
    if anim.willis:
        dur = 3 * anim.phase_frames / anim.fps
        y_w = y + 1.35 * len(lines) * size + 0.2 * size
        for k, text in enumerate(WILLIS_PHASES):
            values = ";".join("1" if j == k else "0" for j in range(3))
            out.append(f'<text x="{-R + size:.3f}" y="{y_w:.3f}" font-size="{1.1 * size:.3f}" '
                       f'font-family="sans-serif" font-weight="bold" opacity="{1 if k == 0 else 0}">'
                       f'Willis {html.escape(text)}<animate attributeName="opacity" values="{values}" '
                       f'keyTimes="0;{1 / 3:.6f};{2 / 3:.6f}" calcMode="discrete" dur="{dur:.6g}s" '
                       f'repeatCount="indefinite"/></text>')
    out.append("</svg>")
    return "\n".join(out)


def write_gif(anim: Any, path: Path, dpi: int) -> Path:
    """Render the frames with matplotlib (the still parts once) and write them as a GIF, ``anim.size`` pixels wide."""
    from matplotlib.patches import PathPatch, Polygon
    from matplotlib.transforms import Affine2D

    plt = pyplot()
    R = extent(anim.shapes)
    inches = anim.size / dpi
    font = max(5.0, 0.025 * anim.size * 72 / dpi)  # points: 2.5 % of the width
    lines = caption_lines(anim, max(20, int(anim.size / (CHAR * font * dpi / 72))))
    caption = (len(lines) + 1.2) * 1.3 * font / 72  # inches
    fig = plt.figure(figsize=(inches, inches + caption), dpi=dpi)
    ax = fig.add_axes((0.0, caption / (inches + caption), 1.0, inches / (inches + caption)))
    ax.set_xlim(-R, R)
    ax.set_ylim(-R, R)
    ax.set_aspect("equal")
    ax.set_axis_off()
    lw = max(0.5, STROKE["outline"] * anim.size * 72 / dpi)  # points, from the drawing's size
    patches: list[tuple[GearShape, Any]] = []
    for shape in anim.shapes:
        colour = COLOURS["planet2"] if shape.step else COLOURS[shape.member]
        internal = shape.member == "ring" and shape.internal
        dashed = shape.step or (shape.member == "ring" and not shape.internal)
        style = {"facecolor": colour, "alpha": 0.35 if internal or dashed else 0.6, "edgecolor": "black",
                 "lw": lw, "ls": "--" if dashed else "-"}
        if internal:  # an internal gear: the rim, teeth pointing inwards (as the SVG draws it)
            patch = PathPatch(_ring_annulus(shape), **style)
        else:
            patch = Polygon(gear_outline(shape.teeth, shape.radius), closed=True, **style)
        ax.add_patch(patch)
        mark = ax.plot([0, 0.8 * shape.radius], [0, 0], color="black", lw=1.5 * lw)[0]
        patches.append((shape, (patch, mark)))
    axes = sorted({(s.axis, s.offset) for s in anim.shapes if s.member.startswith("planet")})
    arms = [ax.plot([], [], color=COLOURS["carrier"], lw=STROKE["arm"] * anim.size * 72 / dpi / 2, alpha=0.6,
                    solid_capstyle="round")[0] for _ in axes]
    fig.text(0.03, caption / (inches + caption) - 0.3 * font / 72 / (inches + caption), "\n".join(lines),
             ha="left", va="top", fontsize=font, linespacing=1.3)
    phase = fig.text(0.03, 0.995, "", ha="left", va="top", fontsize=1.1 * font, weight="bold")

    def update(frame: int) -> list[Any]:
        angles = anim.angles(frame)
        carrier = angles["carrier"]
        for arm, (axis, offset) in zip(arms, axes):
            a = math.radians(offset + carrier)
            arm.set_data([0, axis * math.cos(a)], [0, axis * math.sin(a)])
        for shape, (patch, mark) in patches:
            if shape.member.startswith("planet"):
                a = math.radians(shape.offset + carrier)
                centre = (shape.axis * math.cos(a), shape.axis * math.sin(a))
            else:
                centre = (0.0, 0.0)
            t = Affine2D().rotate_deg(shape.phase + angles[shape.member]).translate(*centre) + ax.transData
            patch.set_transform(t)
            mark.set_transform(t)
        if anim.willis:
            phase.set_text(f"Willis {WILLIS_PHASES[min(int(frame // anim.phase_frames), 2)]}")
        return []

    frames = 3 * anim.phase_frames + 1 if anim.willis else anim.frames
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        _save_frames(fig, update, [a for _, pair in patches for a in pair] + arms + ([phase] if anim.willis else []),
                     frames, anim.fps, path)
    finally:
        plt.close(fig)
    return path


def _save_frames(fig: Any, update: Any, moving: list[Any], frames: int, fps: int, path: Path) -> None:
    """The frames of ``update`` as a GIF: the still parts (caption, axes) drawn once and kept, only the
    ``moving`` artists drawn per frame (matplotlib's blitting); every frame mapped to one palette of the
    first frame's colours without dithering (a flat-coloured drawing: fewer colours, smaller LZW codes).

    References
    ----------
    Matplotlib, "Faster rendering by using blitting" (users guide, animations); GIF89a specification
    (W3C/CompuServe 1990): a global colour table, per-frame delay in 1/100 s.
    """
    from PIL import Image

    canvas = fig.canvas
    moving = sorted(moving, key=lambda a: a.get_zorder())  # as the figure draws them: patches, then lines
    for artist in moving:
        artist.set_animated(True)
    canvas.draw()  # the still parts, once
    background = canvas.copy_from_bbox(fig.bbox)
    images = []
    for frame in range(frames):
        update(frame)
        canvas.restore_region(background)
        for artist in moving:
            artist.axes.draw_artist(artist) if artist.axes is not None else fig.draw_artist(artist)
        rgb = Image.frombuffer("RGBA", canvas.get_width_height(), bytes(canvas.buffer_rgba()), "raw", "RGBA", 0, 1)
        images.append(rgb.convert("RGB"))
    palette = images[0].quantize(colors=48, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    frames_p = [palette] + [im.quantize(palette=palette, dither=Image.Dither.NONE) for im in images[1:]]
    frames_p[0].save(path, save_all=True, append_images=frames_p[1:], duration=10 * max(1, round(100 / fps)), loop=0,  # GIF delays: 1/100 s
                     optimize=False, disposal=1)
