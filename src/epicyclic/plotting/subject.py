"""What a figure of a train file shows: the solved state, its gear, the file's units and assumptions.

:func:`figure_subject` turns a train description (``epicyclic.io.TrainFile``)
into a :class:`Subject`: the solution to draw, the transmission (if the file
has a ``[transmission]`` table) and the :class:`FigureContext` with the
file's title and units.  Files plot as they are:

* with an ``[operating_point]`` the train is solved there (in ``gear`` if one
  is named, with ``--gear`` or in the file);
* a transmission without an operating point is drawn at **the default
  operating point** of :mod:`epicyclic.transmission.default_point` (the
  input driven at 1000 1/min with 100 N·m, the output as load, as
  ``epicyclic gears`` analyses it), in the gear asked for or else its first
  gear, with the file's loss models, and the figure says so;
* a train with neither cannot be solved: a clear error asks for an
  operating point.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..errors import ModelError
from .context import FigureContext

__all__ = ["Subject", "figure_subject"]


@dataclass(frozen=True)
class Subject:
    """A solved state to draw, with its gear, transmission and context."""

    solution: Any
    context: FigureContext
    transmission: Any = None
    gear: str | None = None


def _transmission(train_file: Any) -> Any:
    spec = getattr(train_file, "transmission", None)
    if spec is None:
        return None
    from ..transmission import Transmission

    return Transmission.from_train_file(train_file)


def figure_subject(train_file: Any, gear: str | None = None) -> Subject:
    """The solved state a figure of ``train_file`` shows (see the module text).

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
    from ..solver import solve
    from ..transmission import default_operating_point, default_point_note

    units = train_file.units
    sets = {name: g for name, g in (getattr(train_file, "geometry", None) or {}).items() if hasattr(g, "sun_mesh")}
    context = FigureContext(title=train_file.title or train_file.train.name, units=units, geometry=sets)
    transmission = _transmission(train_file)
    if gear is not None:
        if transmission is None:
            raise ModelError(f"--gear {gear!r:.40} needs a [transmission] table with a schedule in the file.")
        transmission.gear_train(gear)  # a clear error for an unknown gear
    if train_file.operating_point is not None:
        from dataclasses import replace

        gear = gear if gear is not None else train_file.gear
        solution = replace(train_file, gear=gear).solve()  # the file's own errors name its keys
        return Subject(solution, _with_gear(context, gear), transmission, gear)
    if transmission is None:
        raise ModelError(
            "the file has no [operating_point] table and no [transmission] table, so there is nothing to "
            "solve; add an [operating_point] with speeds, torques or powers, drives and loads."
        )
    gear = gear if gear is not None else transmission.gears[0]
    op = default_operating_point(transmission.input, transmission.output)
    if transmission.losses:  # the file's loss models, as `epicyclic gears` solves each gear
        from ..losses import solve_with_losses

        solution = solve_with_losses(transmission.gear_train(gear), op, transmission.losses)
    else:
        solution = solve(transmission.gear_train(gear), op)
    note = default_point_note(units)
    return Subject(solution, _with_gear(context, gear).with_note(note), transmission, gear)


def _with_gear(context: FigureContext, gear: str | None) -> FigureContext:
    from dataclasses import replace

    return replace(context, gear=gear)
