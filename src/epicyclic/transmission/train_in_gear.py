"""A train in a gear at a point: the solved state a file describes, whatever it draws or reports.

:func:`train_in_gear` turns a train description (``epicyclic.io.TrainFile``) into a
:class:`TrainInGear`: the solution, the transmission (if the file has a ``[transmission]`` table), the
gear and what was assumed. Files are solved as they are:

* with an ``[operating_point]`` the train is solved there (in ``gear`` if one is named, or the file's);
* a transmission without an operating point is solved at the stated default point
  (:func:`~epicyclic.transmission.default_operating_point`: the input at 1000 1/min with 100 N·m, the
  output loaded) in the gear asked for or else its first gear, with the file's loss models, and the
  assumption is stated (:attr:`TrainInGear.notes`);
* a train with neither cannot be solved: a clear error asks for an operating point.

The pictures (:func:`epicyclic.plotting.figure_subject`), ``epicyclic plot`` and the page start here.

References
----------
Brandenberger 1952, eq. 7 (the losses follow the rolling power, so the point is stated).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

from ..errors import ModelError
from .default_point import default_operating_point, default_point_note

__all__ = ["TrainInGear", "train_in_gear"]


@dataclass(frozen=True)
class TrainInGear:
    """The solved state of a file: its solution, transmission and gear, and what was assumed.

    Attributes
    ----------
    solution : Solution
    transmission : Transmission or None
        The file's ``[transmission]`` with its loss models.
    gear : str or None
    notes : tuple of str
        What was assumed (the default operating point), for the figure or report to say.
    """

    solution: Any
    transmission: Any = None
    gear: str | None = None
    notes: tuple[str, ...] = ()


def train_in_gear(train_file: Any, gear: str | None = None) -> TrainInGear:
    """The solved state of ``train_file`` in ``gear`` (see the module text).

    Parameters
    ----------
    train_file : epicyclic.io.TrainFile
    gear : str, optional
        A gear of the file's ``[transmission]`` schedule.

    Returns
    -------
    TrainInGear

    Raises
    ------
    ModelError
        ``gear`` without a transmission table, an unknown gear, or a file with neither operating point
        nor transmission.

    Examples
    --------
    >>> from epicyclic.io import load_train_file
    >>> state = train_in_gear(load_train_file("examples/simpson_c4_3speed.toml"), "2")
    >>> round(state.solution.ratio, 4), state.gear, state.notes
    (1.4583, '2', ('no operating point in the file: the default n_in = 1000 1/min, T_in = 100 N·m at the input',))
    """
    from .transmission import Transmission

    transmission = Transmission.from_train_file(train_file) if train_file.transmission is not None else None
    if gear is not None:
        if transmission is None:
            raise ModelError(f"--gear {gear!r:.40} needs a [transmission] table with a schedule in the file.")
        transmission.gear_train(gear)  # a clear error for an unknown gear
    if train_file.operating_point is not None:
        gear = gear if gear is not None else train_file.gear
        return TrainInGear(replace(train_file, gear=gear).solve(), transmission, gear)  # errors name its keys
    if transmission is None:
        raise ModelError(
            "the file has no [operating_point] table and no [transmission] table, so there is nothing to "
            "solve; add an [operating_point] with speeds, torques or powers, drives and loads."
        )
    gear = gear if gear is not None else transmission.gears[0]
    solution = transmission.solve(gear, default_operating_point(transmission.input, transmission.output))
    return TrainInGear(solution, transmission, gear, (default_point_note(train_file.units),))
