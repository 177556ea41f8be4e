"""The pictures of the page: one entry per kind, drawn by :mod:`epicyclic.plotting`.

A new kind of picture is one more :class:`FigureKind` in :data:`FIGURES`: a
title, a test whether it applies to a solved train, and a function that
returns inline SVG.  The page asks for each picture separately (so a slow
picture does not hold up the tables), in a worker process.

Examples
--------
>>> [kind.name for kind in FIGURES.values()]
['speed', 'animation', 'lever', 'torque', 'power', 'flow']
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from ..io import TrainFile
    from ..results import Solution

__all__ = ["FigureKind", "FIGURES", "applicable", "draw"]


@dataclass(frozen=True)
class Picture:
    """What a drawing function gets: the solution, the file it came from and an option (a set name)."""

    solution: Solution
    train_file: TrainFile
    option: str | None = None


@dataclass(frozen=True)
class FigureKind:
    """One kind of picture.

    Parameters
    ----------
    name : str
        Its key in URLs (``/figure/<name>``).
    title : str
    draw : callable Picture → str
        Inline SVG (starts with ``<svg``, no scripts, all text escaped).
    applies : callable Solution → bool
        Whether the picture exists for this solution.
    options : callable Solution → list of (value, label)
        Choices (e.g. which planetary set); empty for none.  The chosen value
        reaches ``draw`` as ``Picture.option``.
    """

    name: str
    title: str
    draw: Callable[[Picture], str]
    applies: Callable[[Solution], bool] = lambda solution: True
    options: Callable[[Solution], list[tuple[str, str]]] = lambda solution: []


def _has_sets(solution: Solution) -> bool:
    return bool(solution.train.planetary_sets)


#: Suffix of an animation option that shows the three superposed motions of the Willis derivation.
WILLIS = "|willis"


def _animation_options(solution: Solution) -> list[tuple[str, str]]:
    """Each planetary set at its solved speeds, then each in the three Willis phases."""
    names = [s.name for s in solution.train.planetary_sets]
    return [(n, f"set {n}") for n in names] + [(n + WILLIS, f"set {n}, Willis phases") for n in names]


def _matplotlib(kind: str) -> Callable[[Picture], str]:
    def draw(picture: Picture) -> str:
        from ..plotting import figure, figure_svg

        return figure_svg(figure(picture.solution, kind))

    return draw


def _animation(picture: Picture) -> str:
    from ..plotting import planetary_animation

    option = picture.option or ""
    willis = option.endswith(WILLIS)
    name = option.removesuffix(WILLIS) or None
    return planetary_animation(picture.solution, name, willis=willis).svg()


FIGURES: dict[str, FigureKind] = {k.name: k for k in (
    FigureKind("speed", "Speed plan (Kutzbach) and speed ranges", _matplotlib("speed"), _has_sets),
    FigureKind("animation", "Animation at the solved speeds", _animation, _has_sets, _animation_options),
    FigureKind("lever", "Lever diagram", _matplotlib("lever")),
    FigureKind("torque", "Torques with and without friction", _matplotlib("torque")),
    FigureKind("power", "Powers as areas, loss rectangle (Brandenberger Bild 8/9)", _matplotlib("power")),
    FigureKind("flow", "Power flow", _matplotlib("flow")),
)}


def applicable(solution: Solution) -> list[FigureKind]:
    """The kinds of picture that exist for ``solution``, in page order."""
    return [kind for kind in FIGURES.values() if kind.applies(solution)]


def draw(kind: str, picture: Picture) -> str:
    """Inline SVG of picture ``kind`` (a key of :data:`FIGURES`).

    Raises
    ------
    KeyError
        Unknown kind (the page only asks for listed kinds).
    """
    return FIGURES[kind].draw(picture)
