"""The multi-speed transmission: a gear train, named shift elements and a shift schedule.

A :class:`Transmission` is a :class:`~epicyclic.GearTrain` whose clutches and
brakes are engaged in named combinations (gears).  Every gear is one shift
state, ``train.with_engaged(schedule[gear])``, solved by the engine's
general solver; nothing here is a special-case formula.

Per gear (:meth:`Transmission.analyze`): the ratio i = n_in/n_out, the
efficiency in drive (power in at the input) and in coast (power in at the
output, as in engine braking), the torque on every engaged shift element as a
multiple of the input torque, the slip speed of every open one as a multiple
of the input speed, rolling power per set, circulating power and which sets
roll, idle or are locked.  Across gears (:meth:`Transmission.analyze_all`):
step ratios, spread and the summary table.

References
----------
Brandenberger 1952, eqs. 1–10 (losses by the direction of rolling power);
Queitsch part 1, eqs. 12 and 26 (Willis and torque relations).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import Any

import numpy as np

from ..errors import ModelError
from ..model.operating_point import OperatingPoint
from ..model.planetary import PlanetarySet
from ..model.train import GearTrain
from ..results.solution import Solution
from ..solver import solve
from ..solver.assembly import matrices
from ..solver.kinematics import degrees_of_freedom, free_speed_shafts, solve_speeds
from ..units import to_core
from .default_point import DEFAULT_INPUT_SPEED, DEFAULT_INPUT_TORQUE, default_operating_point
from .errors import GearFreedomError, ShiftScheduleError, UnknownGearError
from .explore import Exploration, explore
from .input_point import InputPoint
from .results import GearResult, TransmissionAnalysis, gear_result

__all__ = ["Transmission", "ShiftScheduleError", "GearFreedomError"]


def _as_schedule(schedule: object) -> Mapping[str, tuple[str, ...]]:
    if not isinstance(schedule, Mapping) or not schedule:
        raise ShiftScheduleError(
            "transmission: schedule must be a non-empty mapping gear name -> engaged clutch/brake "
            f"names, e.g. {{'1': ('C1', 'B1')}}, got {schedule!r}."
        )
    out: dict[str, tuple[str, ...]] = {}
    for gear, engaged in schedule.items():
        if not isinstance(gear, str) or not gear.strip():
            raise ShiftScheduleError(f"transmission: gear names must be non-empty strings, got {gear!r}.")
        if isinstance(engaged, str) or not isinstance(engaged, Iterable):
            raise ShiftScheduleError(
                f"transmission: schedule[{gear!r}] must be a list of engaged element names, got {engaged!r}."
            )
        names = tuple(engaged)
        if len(set(names)) != len(names):
            raise ShiftScheduleError(f"transmission: schedule[{gear!r}] names an element twice: {names!r}.")
        out[gear] = names
    return MappingProxyType(out)


@dataclass(frozen=True)
class Transmission:
    """A gear train with a shift schedule, an input and an output shaft.

    Parameters
    ----------
    train : GearTrain
        Planetary sets, stages, clutches and brakes; the engaged flags of the
        shift elements are ignored (each gear sets them).
    schedule : mapping gear name → iterable of str
        The clutches and brakes engaged in each gear; all others are open.
    input, output : str
        The input (turbine) and output shafts.
    name : str, optional
        Defaults to the train's name.

    Raises
    ------
    ShiftScheduleError
        Empty schedule, unknown element, input/output not a moving shaft of the
        train or the same shaft.
    GearFreedomError
        A gear leaves more or less than one degree of freedom (the message
        names the gear and the shafts that stay free).

    References
    ----------
    Brandenberger 1952, eqs. 1–10; Benford & Leising 1981 (a shift state is a new lever).

    Examples
    --------
    >>> from epicyclic import GearTrain, PlanetarySet, Brake, Clutch
    >>> train = GearTrain([PlanetarySet("P", "in", "ring", "out", -2.0, 0.98),
    ...                    Brake("B", "ring"), Clutch("C", "in", "ring")])
    >>> t = Transmission(train, {"1": ["B"], "2": ["C"]}, "in", "out")
    >>> round(t.ratio("1"), 9), round(t.ratio("2"), 9)
    (3.0, 1.0)
    """

    train: GearTrain
    schedule: Mapping[str, tuple[str, ...]]
    input: str
    output: str
    name: str = ""
    _trains: Mapping[str, GearTrain] = field(default=None, repr=False, compare=False)  # type: ignore[assignment]
    #: Loss models of elements (element → :class:`~epicyclic.losses.ElementLosses`), e.g. a file's loss tables:
    #: every gear is then solved with them (:func:`~epicyclic.losses.solve_with_losses`).
    losses: Mapping[str, Any] = field(default_factory=dict, repr=False, compare=False)
    #: Spin losses (:class:`~epicyclic.losses.SpinLosses`: clutch drag, pump, churning, windage, seals at the
    #: oil temperature), e.g. a file's; every gear is solved with them.
    spin: Any = field(default=None, repr=False, compare=False)

    def __post_init__(self) -> None:
        if not isinstance(self.train, GearTrain):
            raise ShiftScheduleError(
                f"transmission: train must be a GearTrain, got {type(self.train).__name__}."
            )
        object.__setattr__(self, "schedule", _as_schedule(self.schedule))
        for role in ("input", "output"):
            shaft = getattr(self, role)
            if not isinstance(shaft, str) or shaft not in self.train.moving_shafts:
                raise ShiftScheduleError(
                    f"transmission: {role} must be a moving shaft of the train, got {shaft!r}; shafts are "
                    f"{', '.join(repr(s) for s in self.train.moving_shafts)}."
                )
        if self.input == self.output:
            raise ShiftScheduleError(
                f"transmission: input and output must be different shafts, got {self.input!r} twice."
            )
        if not self.name:
            object.__setattr__(self, "name", self.train.name)
        shift = {e.name for e in self.train.shift_elements}
        trains = {}
        for gear, engaged in self.schedule.items():
            unknown = [n for n in engaged if n not in shift]
            if unknown:
                raise ShiftScheduleError(
                    f"transmission: gear {gear!r} engages {', '.join(repr(n) for n in unknown)}, which "
                    f"is not a clutch or brake of the train; shift elements are "
                    f"{', '.join(repr(n) for n in sorted(shift)) or 'none'}."
                )
            trains[gear] = self.train.with_engaged(engaged)
            self._check_gear(gear, trains[gear])
        object.__setattr__(self, "_trains", MappingProxyType(trains))

    # ------------------------------------------------------------------ checks
    def _check_gear(self, gear: str, train: GearTrain) -> None:
        mats = matrices(train, [self.input, self.output])
        dof = degrees_of_freedom(mats)
        free = free_speed_shafts(mats, [self.input])
        engaged = ", ".join(self.schedule[gear]) or "nothing"
        if dof == 0:
            raise GearFreedomError(
                f"transmission: gear {gear!r} (engaged: {engaged}) locks the whole train (0 degrees of "
                "freedom): the input cannot turn. Release one of its shift elements.",
                gear, 0, (),
            )
        if dof == 1 and free:  # the one degree of freedom is not the input's: the gear holds the input
            raise GearFreedomError(
                f"transmission: gear {gear!r} (engaged: {engaged}) holds the input {self.input!r} still, so "
                f"the input cannot drive and the speed of shaft(s) {', '.join(repr(s) for s in free)} is left "
                "free. Release the element that holds the input.",
                gear, dof, free,
            )
        if dof != 1 or free:
            raise GearFreedomError(
                f"transmission: gear {gear!r} (engaged: {engaged}) leaves {dof} degrees of freedom, "
                f"expected 1: with the input speed given, the speed of shaft(s) "
                f"{', '.join(repr(s) for s in free)} is still free. Engage one more clutch or brake "
                "that fixes them.",
                gear, dof, free,
            )
        speeds = solve_speeds(mats, {self.input: 1.0})
        if abs(speeds[self.output]) < 1e-12:
            raise GearFreedomError(
                f"transmission: in gear {gear!r} (engaged: {engaged}) the output {self.output!r} stands "
                "still while the input turns (infinite ratio); this is no drive gear.",
                gear, dof, (),
            )

    # ------------------------------------------------------------------ look-ups
    @property
    def gears(self) -> tuple[str, ...]:
        """Gear names in schedule order."""
        return tuple(self.schedule)

    def gear_train(self, gear: str) -> GearTrain:
        """The train in ``gear`` (its shift elements engaged, all others open)."""
        try:
            return self._trains[gear]
        except (KeyError, TypeError):  # TypeError: an unhashable gear
            raise UnknownGearError(gear, self.schedule) from None

    def speeds(self, gear: str, input_speed: float | str = 1.0) -> dict[str, float]:
        """Every shaft speed (1/min) in ``gear`` at the given input speed (Willis, kinematics only).

        Parameters
        ----------
        gear : str
            A gear of the schedule (``"1"``, ``"R"``).
        input_speed : float, str or pint.Quantity, default 1
            1/min, or with a unit (``"2000 U/min"``).

        Returns
        -------
        dict shaft → float
            Speeds in 1/min.

        Raises
        ------
        UnknownGearError
            A gear the schedule does not have.
        UnitError
            An input speed that is no speed.
        """
        train = self.gear_train(gear)
        speed = to_core(input_speed, "speed", field="input_speed")
        return solve_speeds(matrices(train, [self.input, self.output]), {self.input: speed})

    def ratio(self, gear: str) -> float:
        """Speed ratio i = n_input / n_output of ``gear`` (negative: reverse).

        References
        ----------
        Queitsch part 1, eq. 12 (Willis) applied to every set of the gear.
        """
        return 1.0 / self.speeds(gear)[self.output]

    @property
    def ratios(self) -> dict[str, float]:
        """Ratio of every gear, schedule order."""
        return {g: self.ratio(g) for g in self.schedule}

    # ------------------------------------------------------------------ variants
    def with_efficiency(self, stationary_efficiency: float | Mapping[str, float]) -> Transmission:
        """A copy with η0 replaced: one value for every planetary set, or a mapping set name → η0."""
        if isinstance(stationary_efficiency, Mapping):
            values = dict(stationary_efficiency)
            sets = {s.name for s in self.train.planetary_sets}
            unknown = [k for k in values if k not in sets]
            if unknown:
                raise ModelError(
                    f"transmission: with_efficiency names {', '.join(repr(k) for k in unknown)}, which is "
                    f"not a planetary set; sets are {', '.join(repr(s) for s in sorted(sets))}."
                )
        else:
            values = {s.name: stationary_efficiency for s in self.train.planetary_sets}
        elements = tuple(
            replace(e, stationary_efficiency=values[e.name]) if isinstance(e, PlanetarySet) and e.name in values
            else e
            for e in self.train.elements
        )
        return Transmission(GearTrain(elements, self.train.shafts, self.train.name), self.schedule,
                            self.input, self.output, self.name)

    # ------------------------------------------------------------------ analysis
    def analyze(self, gear: str, *, input_speed: float | str = DEFAULT_INPUT_SPEED,
                input_torque: float | str = DEFAULT_INPUT_TORQUE) -> GearResult:
        """Analyse one gear in drive and coast.

        Parameters
        ----------
        gear : str
        input_speed : float, str or pint.Quantity, default 1000
            1/min, or with a unit (``"2000 U/min"``).  The results are ratios and
            multiples, independent of the level (losses depend on rolling power
            only, Brandenberger 1952, eq. 7), unless loss models are attached.
        input_torque : float, str or pint.Quantity, default 100
            N·m at the input in drive, or with a unit (``"15 kp*m"``); in coast
            the output is driven with the torque ``input_torque · |ratio|``.

        Returns
        -------
        GearResult

        References
        ----------
        Brandenberger 1952, eqs. 7, 7' and 10 (efficiency by direction of
        power flow).
        """
        input_speed = to_core(input_speed, "speed", field="input_speed")
        input_torque = to_core(input_torque, "torque", field="input_torque")
        if not (np.isfinite(input_speed) and input_speed != 0):
            raise ModelError(f"transmission: input_speed must be a finite, non-zero 1/min value, got {input_speed!r}.")
        if not (np.isfinite(input_torque) and input_torque > 0):
            raise ModelError(f"transmission: input_torque must be a positive N·m value, got {input_torque!r}.")
        drive = self.solve(gear, default_operating_point(self.input, self.output, speed=input_speed,
                                                         torque=input_torque))
        ratio = self.ratio(gear)
        coast_op = OperatingPoint(speeds={self.input: input_speed},
                                  torques={self.output: input_torque * abs(ratio)},
                                  drives=[self.output], loads=[self.input])
        return gear_result(self, gear, ratio, drive, self.solve(gear, coast_op))

    def solve(self, gear: str, operating_point: OperatingPoint) -> Solution:
        """The train in ``gear`` solved at ``operating_point``, with the transmission's loss models.

        The one place a gear is solved with the file's losses (mesh friction, bearings, drag, spin
        losses): :meth:`analyze`, the pictures and the page all come here.

        Parameters
        ----------
        gear : str
            A gear of the schedule.
        operating_point : OperatingPoint

        Returns
        -------
        Solution

        References
        ----------
        Brandenberger 1952, eq. 7 (the loss in the direction of the rolling power).
        """
        train = self.gear_train(gear)
        if self.losses or self.spin is not None:
            from ..losses import solve_with_losses

            return solve_with_losses(train, operating_point, self.losses, spin=self.spin, gear=gear, input=self.input)
        return solve(train, operating_point)

    def analyze_all(self, *, input_speed: float | str = DEFAULT_INPUT_SPEED,
                    input_torque: float | str = DEFAULT_INPUT_TORQUE,
                    point: InputPoint | None = None) -> TransmissionAnalysis:
        """:meth:`analyze` every gear of the schedule, in schedule order, at one stated input point.

        Parameters
        ----------
        input_speed : float, str or pint.Quantity, default 1000
            1/min, or with a unit (``"2000 U/min"``), as in :meth:`analyze`.
        input_torque : float, str or pint.Quantity, default 100
            N·m at the input in drive, or with a unit, as in :meth:`analyze`.
        point : InputPoint, optional
            The point with where it came from (:func:`~epicyclic.transmission.input_point.input_point`:
            ``--speed``/``--torque``, the file's ``[operating_point]`` or the defaults); replaces
            ``input_speed`` and ``input_torque``.  The analysis states it in every rendering.

        Returns
        -------
        TransmissionAnalysis
            Every gear's result, with steps, spread and mean step.

        Raises
        ------
        ModelError
            A zero or non-finite speed, or a torque that is not positive.
        UnitError
            A unit that does not fit the quantity.

        Examples
        --------
        >>> from epicyclic.transmission.library import build
        >>> analysis = build("simpson_c4").analyze_all()
        >>> [round(g.ratio, 2) for g in analysis.gears]
        [2.46, 1.46, 1.0, -2.18]
        """
        if point is None:
            speed = to_core(input_speed, "speed", field="input_speed")
            torque = to_core(input_torque, "torque", field="input_torque")
            default = speed == DEFAULT_INPUT_SPEED and torque == DEFAULT_INPUT_TORQUE
            point = InputPoint(speed, torque, *(("default",) * 2 if default else ("given",) * 2))
        results = tuple(self.analyze(g, input_speed=point.speed, input_torque=point.torque) for g in self.schedule)
        return TransmissionAnalysis(self.name, self.input, self.output, results, point)

    def explore(self, **kwargs) -> Exploration:
        """Every one-DOF combination of this train's shift elements (see :func:`explore`)."""
        return explore(self, **kwargs)

    # ------------------------------------------------------------------ files
    @classmethod
    def from_file(cls, path, *, overrides: Sequence[str] = ()) -> Transmission:
        """Read a train file (TOML) with a ``[transmission]`` table.

        Uses :func:`epicyclic.io.load_train_file`.

        Parameters
        ----------
        path : str or Path
            The TOML file (layout in ``docs/file-format.md``).
        overrides : sequence of str, default ()
            ``KEY=VALUE`` overrides applied before the file is read (the CLI's ``--set``).

        Returns
        -------
        Transmission
            Named by the file's title; its loss models come along.

        Raises
        ------
        InputFileError
            The file cannot be read or is invalid (the message names file and key).
        ShiftScheduleError
            The file has no ``[transmission]`` table.
        """
        from ..io import load_train_file  # the file format lives in epicyclic.io

        return cls.from_train_file(load_train_file(path, overrides=overrides))

    @classmethod
    def from_train_file(cls, data: Any) -> Transmission:
        """The transmission of a train file already read (:class:`epicyclic.io.TrainFile`), with its loss models.

        Every front end makes its transmission here (``epicyclic gears``, ``plot``, the page), so that they
        all solve the gears with the file's loss models (``[planetary.losses]``, ``[lubricant]``).

        Parameters
        ----------
        data : epicyclic.io.TrainFile
            A file with a ``[transmission]`` table.

        Returns
        -------
        Transmission
            Named by the file's title; its loss models come along.

        Raises
        ------
        ShiftScheduleError
            The file has no ``[transmission]`` table.

        References
        ----------
        Brandenberger 1952, eqs. 1–10; ISO/TR 14179-2:2001 (loss models).
        """
        spec = getattr(data, "transmission", None)
        if spec is None:
            raise ShiftScheduleError(
                f"{getattr(data, 'source', 'the file')}: the file describes a train but no [transmission] table "
                "(input, output, schedule); add one to analyse gears."
            )
        return cls(data.train, dict(spec.schedule), spec.input, spec.output,
                   name=getattr(data, "title", "") or data.train.name, losses=dict(getattr(data, "losses", {})),
                   spin=getattr(data, "spin", None))

    # ------------------------------------------------------------------ rendering
    def __repr__(self) -> str:
        return (f"<Transmission {self.name!r}: {len(self.schedule)} gears "
                f"({', '.join(self.schedule)}), input {self.input!r}, output {self.output!r}>")

    def shift_table(self) -> str:
        """The shift schedule as a text table (x = engaged)."""
        names = [e.name for e in self.train.shift_elements]
        width = max([len(g) for g in self.schedule] + [4])
        head = "gear".ljust(width) + " | " + " ".join(n.center(max(3, len(n))) for n in names)
        rows = [head, "-" * len(head)]
        for gear, engaged in self.schedule.items():
            rows.append(gear.ljust(width) + " | " + " ".join(
                ("x" if n in engaged else ".").center(max(3, len(n))) for n in names))
        return "\n".join(rows)


