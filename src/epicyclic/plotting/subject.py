"""What a figure of a train file shows: the train in a gear at a point, with the file's title and units.

The solved state itself — the operating point or the stated default point, the gear, the file's loss
models — is :func:`epicyclic.transmission.train_in_gear` (the concept lives beside the transmission, where
the reports and the page use it too); :func:`figure_subject` adds the :class:`FigureContext` a figure
needs: the file's title, units and set geometry, the gear and the notes of what was assumed.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from .context import FigureContext

__all__ = ["Subject", "figure_subject"]


@dataclass(frozen=True)
class Subject:
    """A solved state to draw, with its gear, transmission and context."""

    solution: Any
    context: FigureContext
    transmission: Any = None
    gear: str | None = None


def figure_subject(train_file: Any, gear: str | None = None) -> Subject:
    """The solved state a figure of ``train_file`` shows (see the module text), with the figure's context.

    The state is :func:`epicyclic.transmission.train_in_gear`'s (the train in a gear at a point); this
    adds the file's title, units and set geometry, and the notes of what was assumed.

    Parameters
    ----------
    train_file : epicyclic.io.TrainFile
    gear : str, optional
        A gear of the file's ``[transmission]`` schedule.

    Raises
    ------
    ModelError
        ``gear`` without a transmission table, an unknown gear, or a file with
        neither operating point nor transmission.

    Examples
    --------
    >>> from epicyclic.io import load_train_file
    >>> s = figure_subject(load_train_file("examples/simpson_c4_3speed.toml"), "2")
    >>> round(s.solution.ratio, 4), s.context.notes
    (1.4583, ('no operating point in the file: the default n_in = 1000 1/min, T_in = 100 N·m at the input',))
    """
    from ..transmission.train_in_gear import train_in_gear

    sets = {name: g for name, g in (getattr(train_file, "geometry", None) or {}).items() if hasattr(g, "sun_mesh")}
    context = FigureContext(title=train_file.title or train_file.train.name, units=train_file.units, geometry=sets)
    state = train_in_gear(train_file, gear)
    context = _with_gear(context, state.gear)
    for note in state.notes:
        context = context.with_note(note)
    rating = getattr(train_file, "rating", None)
    if rating is not None and train_file.geometry:  # meshes below their minimum safety are drawn red
        from dataclasses import replace

        from ..rating.train import rate_solution

        failing = rate_solution(state.solution, train_file.geometry, rating, gear=state.gear).below_minimum()
        context = replace(context, warnings=failing)
    return Subject(state.solution, context, state.transmission, state.gear)


def _with_gear(context: FigureContext, gear: str | None) -> FigureContext:
    from dataclasses import replace

    return replace(context, gear=gear)
