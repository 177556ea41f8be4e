"""Drawing of :class:`~epicyclic.plotting.animation.PlanetaryAnimation`: SMIL SVG and GIF.

The SVG rotates each member with ``animateTransform`` (type ``rotate``): sun
and ring about the centre, the carrier group (arms and planets) about the
centre, each planet inside it about its own axis at its speed *relative to
the carrier*, so the absolute planet speed is the sum (the Willis
superposition).  No scripts, no external references.
"""

from __future__ import annotations

import html
import math
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ._common import SHAFT_COLOURS, fmt, pyplot
from .animation import WILLIS_PHASES, GearShape, gear_outline

if TYPE_CHECKING:  # pragma: no cover
    from .animation import PlanetaryAnimation

__all__ = ["animation_svg", "write_gif"]

COLOURS = {"sun": SHAFT_COLOURS[0], "ring": SHAFT_COLOURS[1], "carrier": SHAFT_COLOURS[2],
           "planet": SHAFT_COLOURS[3], "planet2": SHAFT_COLOURS[4]}


def _path(points: list[tuple[float, float]]) -> str:
    return "M " + " L ".join(f"{x:.3f} {y:.3f}" for x, y in points) + " Z"


def _ring_path(shape: GearShape) -> str:
    outline = gear_outline(shape.teeth, shape.radius, internal=True)
    m = 2 * shape.radius / shape.teeth if shape.teeth else shape.radius * 0.05
    outer = shape.radius + 3.5 * m
    circle = [(outer * math.cos(2 * math.pi * k / 96), outer * math.sin(2 * math.pi * k / 96)) for k in range(96)]
    return _path(circle) + " " + _path(outline)


def _extent(anim: PlanetaryAnimation) -> float:
    r = 0.0
    for s in anim.shapes:
        m = 2 * s.radius / s.teeth if s.teeth else 0.05 * s.radius
        r = max(r, s.axis + s.radius + (3.5 * m if s.member == "ring" and s.internal else 1.5 * m))
    return r * 1.05


def _rotation(anim: PlanetaryAnimation, member: str, relative_to: str | None = None) -> str:
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


def _gear(shape: GearShape, colour: str) -> str:
    if shape.member == "ring" and shape.internal:
        body = f'<path d="{_ring_path(shape)}" fill="{colour}" fill-opacity="0.35" fill-rule="evenodd" stroke="black" stroke-width="0.3"/>'
    elif shape.step or (shape.member == "ring" and not shape.internal):
        body = (f'<path d="{_path(gear_outline(shape.teeth, shape.radius))}" fill="none" stroke="{colour}" '
                f'stroke-width="1.0" stroke-dasharray="2 1"/>')
    else:
        body = (f'<path d="{_path(gear_outline(shape.teeth, shape.radius))}" fill="{colour}" fill-opacity="0.55" '
                f'stroke="black" stroke-width="0.3"/>')
    mark = 0.8 * shape.radius
    return body + f'<line x1="0" y1="0" x2="{mark:.3f}" y2="0" stroke="black" stroke-width="0.5"/>'


def animation_svg(anim: PlanetaryAnimation) -> str:
    """The animated SVG text (see module docs)."""
    R = _extent(anim)
    caption_h = 0.55 * R
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{-R:.3f} {-R:.3f} {2 * R:.3f} {2 * R + caption_h:.3f}" '
           f'width="520" role="img" aria-label="animation of planetary set {html.escape(anim.set_name)}">',
           f"<title>{html.escape(anim.set_name)}: planetary set at the solved speeds</title>",
           '<g transform="scale(1,-1)">']
    for shape in anim.shapes[:2]:  # the central gears, in drawing order
        member = shape.member
        out.append(f'<g transform="rotate({shape.phase:.4f})"><g>{_gear(shape, COLOURS[member])}'
                   f'{_rotation(anim, member)}</g></g>')
    out.append("<g>")  # carrier
    axes = sorted({(s.axis, s.offset) for s in anim.shapes if s.member.startswith("planet")})
    for axis, offset in axes:
        x, y = axis * math.cos(math.radians(offset)), axis * math.sin(math.radians(offset))
        out.append(f'<line x1="0" y1="0" x2="{x:.3f}" y2="{y:.3f}" stroke="{COLOURS["carrier"]}" stroke-width="{0.06 * R:.3f}" '
                   'stroke-linecap="round" stroke-opacity="0.6"/>')
    out.append(f'<circle r="{0.05 * R:.3f}" fill="{COLOURS["carrier"]}"/>')
    for shape in anim.shapes:
        if not shape.member.startswith("planet"):
            continue
        out.append(f'<g transform="rotate({shape.offset:.4f}) translate({shape.axis:.4f},0)">'
                   f'<g transform="rotate({shape.phase - shape.offset:.4f})"><g>'
                   f'{_gear(shape, COLOURS[shape.member])}{_rotation(anim, shape.member, "carrier")}</g></g>'
                   f'<circle r="{0.02 * R:.3f}" fill="black"/></g>')
    out.append(_rotation(anim, "carrier"))
    out.append("</g></g>")
    # caption (not mirrored)
    size = 0.055 * R
    y = R + 1.2 * size
    lines = [f"{anim.set_name}: " + ", ".join(f"{m} ({anim.shafts.get(m, m)}) {fmt(n, 5)} 1/min"
                                              for m, n in anim.speeds.items() if m in ("sun", "ring", "carrier")),
             ", ".join(f"{m} {fmt(n, 5)} 1/min" for m, n in anim.speeds.items() if m.startswith("planet"))
             + f"; {anim.planets} planets; shown slowed down {fmt(anim.slowdown, 3)}×"]
    for k, text in enumerate(lines):
        out.append(f'<text x="{-R + size:.3f}" y="{y + 1.3 * k * size:.3f}" font-size="{size:.3f}" '
                   f'font-family="sans-serif">{html.escape(text)}</text>')
    if anim.willis:
        dur = 3 * anim.phase_frames / anim.fps
        for k, text in enumerate(WILLIS_PHASES):
            values = ";".join("1" if j == k else "0" for j in range(3))
            out.append(f'<text x="{-R + size:.3f}" y="{y + 2.8 * size:.3f}" font-size="{1.2 * size:.3f}" '
                       f'font-family="sans-serif" font-weight="bold" opacity="{1 if k == 0 else 0}">'
                       f'Willis {html.escape(text)}<animate attributeName="opacity" values="{values}" '
                       f'keyTimes="0;{1 / 3:.6f};{2 / 3:.6f}" calcMode="discrete" dur="{dur:.6g}s" '
                       f'repeatCount="indefinite"/></text>')
    out.append("</svg>")
    return "\n".join(out)


def write_gif(anim: PlanetaryAnimation, path: Path, dpi: int) -> Path:
    """Render the frames with matplotlib and write them with PillowWriter."""
    from matplotlib.animation import FuncAnimation, PillowWriter
    from matplotlib.patches import Polygon
    from matplotlib.transforms import Affine2D

    plt = pyplot()
    R = _extent(anim)
    fig, ax = plt.subplots(figsize=(5, 5.6))
    ax.set_xlim(-R, R)
    ax.set_ylim(-R, R)
    ax.set_aspect("equal")
    ax.set_axis_off()
    patches: list[tuple[GearShape, Any]] = []
    for shape in anim.shapes:
        colour = COLOURS[shape.member]
        outline = gear_outline(shape.teeth, shape.radius, internal=shape.member == "ring" and shape.internal)
        dashed = shape.step or (shape.member == "ring" and not shape.internal)
        fill = shape.member == "ring" and shape.internal
        patch = Polygon(outline, closed=True, facecolor="none" if dashed or fill else colour,
                        edgecolor=colour if dashed or fill else "black", lw=2.0 if fill or dashed else 0.8,
                        ls="--" if dashed else "-", alpha=0.8)
        ax.add_patch(patch)
        mark = ax.plot([0, 0.8 * shape.radius], [0, 0], color="black", lw=1)[0]
        patches.append((shape, (patch, mark)))
    arms = [ax.plot([], [], color=COLOURS["carrier"], lw=6, alpha=0.6, solid_capstyle="round")[0]
            for _ in {(s.axis, s.offset) for s in anim.shapes if s.member.startswith("planet")}]
    title = ax.set_title("", fontsize=9)
    speeds = ", ".join(f"{m} {fmt(n, 5)}" for m, n in anim.speeds.items())
    fig.text(0.5, 0.04, f"{speeds} 1/min\nslowed down {fmt(anim.slowdown, 3)}×, {anim.planets} planets",
             ha="center", fontsize=8)

    def update(frame: int) -> list[Any]:
        angles = anim.angles(frame)
        carrier = angles["carrier"]
        axes = sorted({(s.axis, s.offset) for s in anim.shapes if s.member.startswith("planet")})
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
            phase = min(int(frame // anim.phase_frames), 2)
            title.set_text(f"{anim.set_name} — Willis {WILLIS_PHASES[phase]}")
        else:
            title.set_text(f"{anim.set_name}: planetary set at the solved speeds")
        return []

    frames = 3 * anim.phase_frames + 1 if anim.willis else anim.frames
    movie = FuncAnimation(fig, update, frames=frames, blit=False)
    path.parent.mkdir(parents=True, exist_ok=True)
    movie.save(str(path), writer=PillowWriter(fps=anim.fps), dpi=dpi)
    plt.close(fig)
    return path
