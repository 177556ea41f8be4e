"""``epicyclic plot FILE`` and ``epicyclic animate FILE``: pictures of a solved train.

``plot --kind speed|torque|power|lever|flow`` writes one figure (.svg, .png
or .pdf by the suffix of ``--out``); ``animate`` writes the animation of a
planetary set as a self-contained HTML/SVG page (plays offline) or a GIF.
Exit codes: 0 success, 2 bad input (one paragraph, no traceback), 1 bug.
"""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer

from ..io.output import atomic_path, refuse_input
from ..limits import DPI_RANGE, FPS_RANGE, FRAMES_RANGE, check_range
from ._common import guarded, load, say, solved

__all__ = ["PlotKind", "plot", "animate"]


class PlotKind(str, Enum):
    """Kinds of figure."""

    speed = "speed"
    torque = "torque"
    power = "power"
    lever = "lever"
    flow = "flow"


def _load(file: Path, gear: str | None):
    """(train file, operating train) with ``--gear`` applied."""
    return load(file, gear)


def _agg() -> None:
    import matplotlib

    matplotlib.use("Agg")  # files only: no display needed
    matplotlib.rcParams["text.parse_math"] = False  # a '$' in a title or name is text, not TeX math


@guarded
def plot(
    file: Annotated[Path, typer.Argument(help="Train description (.toml), see docs/file-format.md.")],
    kind: Annotated[PlotKind, typer.Option("--kind", "-k", help="Which picture.")] = PlotKind.speed,
    out: Annotated[Optional[Path], typer.Option(
        "--out", "-o", help="Output file: .svg, .png or .pdf (default: FILE-KIND.png here).")] = None,
    gear: Annotated[Optional[str], typer.Option("--gear", "-g", help="Gear of the \\[transmission] schedule.")] = None,
    dpi: Annotated[int, typer.Option(help="Resolution of .png output (20 … 600).")] = 150,
) -> None:
    """Draw FILE: speed plan, torque bars, power rectangles, lever diagram or power flow."""
    from ..plotting import FIGURE_SUFFIXES, lever_diagram, save_figure, save_plot
    from ..plotting._common import check_suffix

    check_range(dpi, "--dpi", DPI_RANGE)
    out = Path(out) if out is not None else Path(f"{file.stem}-{kind.value}.png")
    check_suffix(out, FIGURE_SUFFIXES, "plot --out")
    refuse_input(out, [file])
    _agg()
    train_file = _load(file, gear)
    with atomic_path(out) as temporary:
        if kind is PlotKind.lever and train_file.operating_point is None:
            save_figure(lever_diagram(train=train_file.operating_train).plot(), temporary, dpi=dpi)
        else:
            save_plot(solved(train_file, file), kind.value, temporary, dpi=dpi)
    say(f"wrote {out.resolve()}")


@guarded
def animate(
    file: Annotated[Path, typer.Argument(help="Train description (.toml), see docs/file-format.md.")],
    out: Annotated[Optional[Path], typer.Option(
        "--out", "-o", help="Output file: .html, .svg or .gif (default: FILE-animation.html here).")] = None,
    element: Annotated[Optional[str], typer.Option("--set", "-s", help="Planetary set (default: the first).")] = None,
    willis: Annotated[bool, typer.Option(
        "--willis", help="Show the three superposed motions of the Willis derivation in turn.")] = False,
    gear: Annotated[Optional[str], typer.Option("--gear", "-g", help="Gear of the \\[transmission] schedule.")] = None,
    frames: Annotated[int, typer.Option(help="Frames of one GIF loop (2 … 240).")] = 48,
    fps: Annotated[int, typer.Option(help="Frames per second (1 … 60).")] = 16,
) -> None:
    """Animate a planetary set of FILE at its solved speeds (HTML/SVG plays offline; or GIF)."""
    from ..plotting import planetary_animation
    from ..plotting._common import check_suffix
    from ..plotting.animation import ANIMATION_SUFFIXES

    check_range(frames, "--frames", FRAMES_RANGE)
    check_range(fps, "--fps", FPS_RANGE)
    out = Path(out) if out is not None else Path(f"{file.stem}-animation.html")
    check_suffix(out, ANIMATION_SUFFIXES, "animate --out")
    refuse_input(out, [file])
    _agg()
    solution = solved(_load(file, gear), file)
    anim = planetary_animation(solution, element, willis=willis, frames=frames, fps=fps)
    with atomic_path(out) as temporary:
        anim.save(temporary)
    say(f"wrote {out.resolve()}")
