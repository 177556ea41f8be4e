"""``epicyclic plot FILE`` and ``epicyclic animate FILE``: pictures of a solved train.

``plot --kind speed|torque|power|lever|flow|chart`` writes one figure (.svg,
.png or .pdf by the suffix of ``--out``); ``animate`` writes the animation of
a planetary set as a self-contained HTML/SVG page (plays offline) or a GIF.
Files plot as they are (:func:`epicyclic.plotting.figure_subject`): a
transmission without operating point at the default operating point (1000 1/min, 100 N·m) in the
gear of ``--gear`` (default: its first gear), said on the figure; figures use
the file's ``[units]``.  Exit codes: 0 success, 2 bad input (one paragraph,
no traceback), 1 bug.
"""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer

from ..errors import EpicyclicError
from ..io.located import located
from ..io.output import atomic_path, refuse_input
from ..limits import DPI_RANGE, FPS_RANGE, FRAMES_RANGE, SIZE_RANGE, check_range
from ._common import SetOption, check_finite, guarded, load, say

__all__ = ["PlotKind", "plot", "animate"]


class PlotKind(str, Enum):
    """Kinds of figure."""

    speed = "speed"
    torque = "torque"
    power = "power"
    lever = "lever"
    flow = "flow"
    chart = "chart"


def _subject(file: Path, gear: str | None, overrides: list[str] | None = None):
    """The solved state a figure of ``file`` shows (``--gear`` applied, the default point if no operating point).

    Errors name the file and the table; the numbers are checked to be finite.
    """
    from ..io.json_report import report_data
    from ..plotting import figure_subject

    train_file = load(file, gear, overrides)
    try:
        subject = figure_subject(train_file, gear)
    except EpicyclicError as exc:
        gearbox = train_file.operating_point is None and train_file.transmission is not None
        raise located(exc, str(file), "[transmission]" if gearbox else "[operating_point]") from None
    check_finite(report_data(subject.solution, train_file.units), file)
    return subject


def _agg() -> None:
    import matplotlib

    matplotlib.use("Agg")  # files only: no display needed
    matplotlib.rcParams["text.parse_math"] = False  # a '$' in a title or name is text, not TeX math


@guarded
def plot(
    file: Annotated[Path, typer.Argument(help="Train description (.toml), see docs/file-format.md.")],
    kind: Annotated[PlotKind, typer.Option("--kind", "-k", help="Which picture (chart: speeds across the "
                                                               "gears of a transmission).")] = PlotKind.speed,
    out: Annotated[Optional[Path], typer.Option(
        "--out", "-o", help="Output file: .svg, .png or .pdf (default: FILE-KIND.png here).")] = None,
    gear: Annotated[Optional[str], typer.Option("--gear", "-g", help="Gear of the [transmission] schedule "
                                                "(default: the operating point's, else the first gear).")] = None,
    dpi: Annotated[int, typer.Option(help="Resolution of .png output (20 … 600).")] = 150,
    set_: SetOption = None,
) -> None:
    """Draw FILE: speed plan, torque bars, power rectangles, lever diagram, power flow or speed chart."""
    from ..plotting import FIGURE_SUFFIXES, save_plot
    from ..plotting._common import check_suffix

    check_range(dpi, "--dpi", DPI_RANGE)
    out = Path(out) if out is not None else Path(f"{file.stem}-{kind.value}.png")
    check_suffix(out, FIGURE_SUFFIXES, "plot --out")
    refuse_input(out, [file])
    _agg()
    subject = _subject(file, gear, set_)
    try:
        with atomic_path(out) as temporary:
            save_plot(subject.solution, kind.value, temporary, dpi=dpi, context=subject.context,
                      transmission=subject.transmission)
    except EpicyclicError as exc:  # e.g. a speed chart of a train without transmission
        raise located(exc, str(file)) from None
    say(f"wrote {out.resolve()}")


@guarded
def animate(
    file: Annotated[Path, typer.Argument(help="Train description (.toml), see docs/file-format.md.")],
    out: Annotated[Optional[Path], typer.Option(
        "--out", "-o", help="Output file: .html, .svg or .gif (default: FILE-animation.html here).")] = None,
    element: Annotated[Optional[str], typer.Option(
        "--element", "-e", help="Name of the planetary set to animate (default: the first).")] = None,
    willis: Annotated[bool, typer.Option(
        "--willis", help="Show the three superposed motions of the Willis derivation in turn.")] = False,
    gear: Annotated[Optional[str], typer.Option("--gear", "-g", help="Gear of the [transmission] schedule.")] = None,
    frames: Annotated[int, typer.Option(help="Frames of one GIF loop (2 … 240).")] = 48,
    fps: Annotated[int, typer.Option(help="Frames per second (1 … 60).")] = 16,
    size: Annotated[int, typer.Option(help="Width of the SVG or GIF in pixels (120 … 2000).")] = 480,
    set_: SetOption = None,
) -> None:
    """Animate a planetary set of FILE at its solved speeds (HTML/SVG plays offline; or GIF)."""
    from ..plotting import planetary_animation
    from ..plotting._common import check_suffix
    from ..plotting.animation import ANIMATION_SUFFIXES

    check_range(frames, "--frames", FRAMES_RANGE)
    check_range(fps, "--fps", FPS_RANGE)
    check_range(size, "--size", SIZE_RANGE)
    out = Path(out) if out is not None else Path(f"{file.stem}-animation.html")
    check_suffix(out, ANIMATION_SUFFIXES, "animate --out")
    refuse_input(out, [file])
    _agg()
    subject = _subject(file, gear, set_)
    anim = planetary_animation(subject.solution, element, willis=willis, frames=frames, fps=fps, size=size,
                               context=subject.context)
    with atomic_path(out) as temporary:
        anim.save(temporary)
    say(f"wrote {out.resolve()}")
