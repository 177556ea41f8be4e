"""The pictures of the page: one entry per kind, drawn by :mod:`epicyclic.plotting` as ``epicyclic plot`` draws them.

A new kind of picture is one more :class:`FigureKind` in :data:`FIGURES`: a
title, a test whether it applies to what the page shows, and a function that
makes the picture.  Every picture is made from the file as ``plot`` and
``animate`` make it (:func:`epicyclic.plotting.figure_subject`): in the units
the page shows (the file's or SI), with the gear and the shift state in the
title, a transmission without operating point at the default operating point.  The page asks
for each picture separately (so a slow picture does not hold up the tables),
in a worker process; it shows inline SVG and saves SVG, PNG or PDF (the
animation as HTML, SVG or GIF) with the command line's options and limits
(``--dpi``, ``--size``, ``--frames``, ``--fps``; :mod:`epicyclic.limits`).

Examples
--------
>>> [kind.name for kind in FIGURES.values()]
['speed', 'animation', 'lever', 'chart', 'torque', 'power', 'flow']
>>> read_settings(FIGURES["animation"], {"fig_animation_size": "640", "fig_animation_format": "gif"})
Settings(option=None, format='gif', size=640, dpi=150, frames=48, fps=16)
"""

from __future__ import annotations

import math
import tempfile
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..limits import DPI_RANGE, FPS_RANGE, FRAMES_RANGE, SIZE_RANGE, LimitError, check_range

if TYPE_CHECKING:  # pragma: no cover
    from ..plotting import Subject

__all__ = ["FigureKind", "FIGURES", "Picture", "Settings", "applicable", "read_settings", "inline_svg", "save"]

#: What a picture can be saved as (the command line's suffixes).
FIGURE_FORMATS = ("svg", "png", "pdf")
ANIMATION_FORMATS = ("html", "svg", "gif")
#: Media types of the saved pictures.
MEDIA_TYPES = {"svg": "image/svg+xml", "png": "image/png", "pdf": "application/pdf", "html": "text/html; charset=utf-8",
               "gif": "image/gif"}


@dataclass(frozen=True)
class Settings:
    """The options of one picture, as ``plot``/``animate`` take them (defaults: theirs)."""

    option: str | None = None
    format: str = "svg"
    size: int = 480
    dpi: int = 150
    frames: int = 48
    fps: int = 16


@dataclass(frozen=True)
class Picture:
    """What a drawing function gets: the state to draw (:class:`epicyclic.plotting.Subject`) and the settings."""

    subject: Subject
    settings: Settings = Settings()


def _always(subject: Subject) -> bool:
    return True


def _no_options(subject: Subject) -> list[tuple[str, str]]:
    return []


@dataclass(frozen=True)
class FigureKind:
    """One kind of picture.

    Parameters
    ----------
    name : str
        Its key in URLs (``/figure/<name>``) and form fields (``fig_<name>_…``).
    title : str
    make : callable Picture → object
        A matplotlib figure, or (``animated``) a :class:`~epicyclic.plotting.PlanetaryAnimation`.
    applies : callable Subject → bool
        Whether the picture exists for what the page shows.
    options : callable Subject → list of (value, label)
        Choices (e.g. which planetary set); empty for none.  The chosen value
        reaches ``make`` as ``Picture.settings.option``.
    animated : bool
        An animation: saved as HTML, SVG or GIF, with a size, frames and frame rate.
    """

    name: str
    title: str
    make: Callable[[Picture], Any]
    applies: Callable[[Subject], bool] = _always
    options: Callable[[Subject], list[tuple[str, str]]] = _no_options
    animated: bool = False

    @property
    def formats(self) -> tuple[str, ...]:
        return ANIMATION_FORMATS if self.animated else FIGURE_FORMATS


def _has_sets(subject: Subject) -> bool:
    return bool(subject.solution.train.planetary_sets)


def _has_transmission(subject: Subject) -> bool:
    return subject.transmission is not None


#: Suffix of an animation option that shows the three superposed motions of the Willis derivation.
WILLIS = "|willis"


def _animation_options(subject: Subject) -> list[tuple[str, str]]:
    """Each planetary set at its solved speeds, then each in the three Willis phases; the first set that
    rolls (or else moves) comes first, so that the animation shown at first is not a set standing still."""
    solution = subject.solution

    def order(name: str) -> int:
        state = solution.elements[name]
        return 0 if state.status == "rolling" else 1 if any(state.speeds.values()) else 2

    names = sorted((s.name for s in solution.train.planetary_sets), key=order)
    return [(n, f"set {n}") for n in names] + [(n + WILLIS, f"set {n}, Willis phases") for n in names]


def _matplotlib(kind: str) -> Callable[[Picture], Any]:
    def make(picture: Picture) -> Any:
        from ..plotting import figure

        s = picture.subject
        return figure(s.solution, kind, context=s.context, transmission=s.transmission)

    return make


def _animation(picture: Picture) -> Any:
    from ..plotting import planetary_animation

    settings = picture.settings
    option = settings.option or ""
    return planetary_animation(picture.subject.solution, option.removesuffix(WILLIS) or None,
                               willis=option.endswith(WILLIS), frames=settings.frames, fps=settings.fps,
                               size=settings.size, context=picture.subject.context)


FIGURES: dict[str, FigureKind] = {k.name: k for k in (
    FigureKind("speed", "Speed plan (Kutzbach) and speed ranges", _matplotlib("speed"), _has_sets),
    FigureKind("animation", "Animation at the solved speeds", _animation, _has_sets, _animation_options,
               animated=True),
    FigureKind("lever", "Lever diagram (compound lever of the shift state)", _matplotlib("lever")),
    FigureKind("chart", "Speed chart across gears (per unit input speed)", _matplotlib("chart"), _has_transmission),
    FigureKind("torque", "Torques with and without friction", _matplotlib("torque")),
    FigureKind("power", "Powers as areas, loss rectangle (Brandenberger Bild 8/9)", _matplotlib("power")),
    FigureKind("flow", "Power flow (circulating power in red)", _matplotlib("flow")),
)}


def applicable(subject: Subject) -> list[FigureKind]:
    """The kinds of picture that exist for ``subject``, in page order."""
    return [kind for kind in FIGURES.values() if kind.applies(subject)]


def _whole(text: str, field: str, bounds: tuple[int, int]) -> int:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not value.is_integer():  # also inf and NaN
        raise LimitError(f"{field}: expected a whole number from {bounds[0]} to {bounds[1]}, got {text[:40]!r}.",
                         field)
    return int(check_range(int(value), field, bounds))


def read_settings(kind: FigureKind, given: Mapping[str, str]) -> Settings:
    """The settings of picture ``kind`` from the page's fields ``fig_<kind>_<setting>``.

    Raises
    ------
    LimitError
        A format the picture cannot be saved as, or a number outside the
        command line's range (``--dpi`` 20 … 600, ``--size`` 120 … 2000,
        ``--frames`` 2 … 240, ``--fps`` 1 … 60).
    """
    def field(name: str) -> str:
        return (given.get(f"fig_{kind.name}_{name}") or "").strip()

    default = Settings()
    format = field("format") or kind.formats[0]
    if format not in kind.formats:
        raise LimitError(f"{kind.title}: save as {', '.join(kind.formats)}; got {format[:40]!r}.", "format")
    numbers = {}
    for name, label, bounds in (("size", "animation size (--size) in pixels", SIZE_RANGE),
                                ("dpi", "resolution (--dpi) of PNG", DPI_RANGE),
                                ("frames", "frames of one GIF loop (--frames)", FRAMES_RANGE),
                                ("fps", "frames per second (--fps)", FPS_RANGE)):
        text = field(name)
        numbers[name] = _whole(text, label, bounds) if text else getattr(default, name)
    return Settings(option=field("option") or None, format=format, **numbers)


def inline_svg(kind: FigureKind, picture: Picture) -> str:
    """The picture as inline SVG for the page (no scripts; every text escaped)."""
    from ..plotting import figure_svg

    made = kind.make(picture)
    return made.svg() if kind.animated else figure_svg(made)


def save(kind: FigureKind, picture: Picture) -> bytes:
    """The picture as a file in ``picture.settings.format``, written as ``plot``/``animate`` write it."""
    from ..plotting import save_figure

    made = kind.make(picture)
    with tempfile.TemporaryDirectory(prefix="epicyclic-picture-") as folder:
        path = Path(folder) / f"picture.{picture.settings.format}"
        if kind.animated:
            made.save(path)
        else:
            save_figure(made, path, dpi=picture.settings.dpi)
        return path.read_bytes()
