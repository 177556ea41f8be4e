"""Result objects of an analysis: immutable, self-describing, renderable.

Units: speeds in 1/min, torques in N·m, powers and losses in W.
Power is positive where it flows *into* the train (a drive) and negative at a
load (Brandenberger's convention).  Port torques are the torques a shaft
exerts on an element.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
import dataclasses
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from ..errors import UnknownShaftError
from .circulation import Circulation
from .render import solution_html, solution_table, solution_to_dict
from .zero import ZERO_TOLERANCE

if TYPE_CHECKING:  # pragma: no cover
    from ..units import Units

if TYPE_CHECKING:  # pragma: no cover
    from ..model.operating_point import OperatingPoint
    from ..model.train import GearTrain

__all__ = ["ShaftState", "ElementState", "SelfLocking", "Solution", "RPM_TO_RAD_S"]

#: 1/min → rad/s (explicit, never through Hz).
RPM_TO_RAD_S = math.pi / 30.0


@dataclass(frozen=True)
class ShaftState:
    """Speed (1/min), external torque (N·m) and power (W) of one shaft."""

    name: str
    speed: float
    torque: float
    power: float
    role: str  # "drive", "load", "housing", "internal"

    @property
    def angular_velocity(self) -> float:
        """ω in rad/s."""
        return self.speed * RPM_TO_RAD_S


@dataclass(frozen=True)
class ElementState:
    """The state of one element at the operating point.

    Attributes
    ----------
    ports : mapping port → shaft
    torques : mapping port → torque on the element from that shaft (N·m)
    speeds : mapping port → speed (1/min)
    rolling_power : float
        P_w = T_sun·(ω_sun − ω_carrier) in W for a set (first shaft for a stage);
        its sign is the direction of power flow relative to the carrier.
    coupling_power : float
        T_sun·ω_carrier in W: the part of the sun's power that passes without
        tooth sliding.  Zero for a fixed-axis stage.
    loss : float
        Power lost in the element, W (≥ 0).
    loss_direction : int
        w ∈ {−1, 0, +1}: +1 when the sun (first) shaft drives relative to the
        carrier, −1 when it is driven, 0 without rolling power.
    efficiency_factor : float
        η0^w applied to the torque ratio (1 where w = 0).
    engaged : bool or None
        For clutches and brakes.
    slip_speed : float or None
        Speed difference first − second (1/min) across a clutch or brake.
    planet_speeds, planet_speeds_relative : tuple of float
        Planet gear speeds, absolute and relative to the carrier (1/min), when
        tooth counts are known.
    loss_sources : mapping source → float
        The loss split by source, W (``mesh``, ``bearing``, ``drag``; see
        :mod:`epicyclic.solver.given_losses`); ``{"mesh": loss}`` with a typed-in η0.

    References
    ----------
    Brandenberger 1952, eq. 3' and Bild 8; Queitsch, Wälz- und Kupplungsleistung (P_w, P_k).
    """

    name: str
    kind: str
    ports: Mapping[str, str]
    torques: Mapping[str, float]
    speeds: Mapping[str, float]
    rolling_power: float = 0.0
    coupling_power: float = 0.0
    loss: float = 0.0
    loss_direction: int = 0
    efficiency_factor: float = 1.0
    engaged: bool | None = None
    slip_speed: float | None = None
    planet_speeds: tuple[float, ...] = ()
    planet_speeds_relative: tuple[float, ...] = ()
    loss_sources: Mapping[str, float] = field(default_factory=dict)

    @property
    def port_powers(self) -> dict[str, float]:
        """Power into the element at each port, W."""
        return {p: self.torques[p] * self.speeds[p] * RPM_TO_RAD_S for p in self.ports}

    @property
    def status(self) -> str:
        """One word for the element's state.

        Clutches and brakes: ``engaged`` or ``open``.  Sets and stages:
        ``rolling`` (rolling power flows), ``locked`` (no relative motion: the set
        turns as a block or stands still) or ``idle`` (relative motion, no torque).
        """
        if self.kind in ("clutch", "brake"):
            return "engaged" if self.engaged else "open"
        if self.loss_direction != 0:
            return "rolling"
        ports = list(self.ports)
        carrier = self.speeds[ports[2]]
        relative = max(abs(self.speeds[p] - carrier) for p in ports[:2])
        level = max(abs(v) for v in self.speeds.values())
        return "locked" if relative <= ZERO_TOLERANCE * level else "idle"


@dataclass(frozen=True)
class SelfLocking:
    """The train self-locks in the asked direction.

    Attributes
    ----------
    message : str
    formal_efficiency : float or None
        The (≤ 0) efficiency the loss rule gives formally; not an efficiency.
    thresholds : mapping element → η0
        For each lossy element, the value of its stationary efficiency below
        which the train self-locks (others unchanged); absent if none in (0, 1].
    cause : {"self-locking", "no-load losses"}
        ``"no-load losses"``: the torques given as no-load (spin) losses — drag, churning, pump,
        seals — take more power than the input gives, so no power reaches the load although the
        gearing itself does not lock (ISO/TR 14179-2: the loss as load-dependent plus no-load parts).

    References
    ----------
    Brandenberger 1952, text to Bild 9 (self-locking at η = bd/ac).
    """

    message: str
    formal_efficiency: float | None
    thresholds: Mapping[str, float] = field(default_factory=dict)
    cause: str = "self-locking"

    @property
    def label(self) -> str:
        """What a table shows in place of the efficiency: ``"self-locking"``, or ``"losses > input"``
        where the no-load (spin) losses alone exceed the input power (no self-locking of the gearing)."""
        return "losses > input" if self.cause == "no-load losses" else "self-locking"


class _Deferred:
    """A dataclass field that may be given a callable making its value; called once, on first access.

    A data descriptor, so the dataclass's ``__init__`` hands it the value (see "descriptor-typed
    fields" in the :mod:`dataclasses` documentation); the value lives in ``_<name>``.
    """

    def __init__(self, default: Any = None):
        self.default = default

    def __set_name__(self, owner: type, name: str) -> None:
        self.attribute = "_" + name

    def __get__(self, instance: Any, owner: type | None = None) -> Any:
        if instance is None:
            return self.default  # the field's default
        value = instance.__dict__[self.attribute]
        if callable(value):
            value = instance.__dict__[self.attribute] = value()
        return value

    def __set__(self, instance: Any, value: Any) -> None:
        instance.__dict__[self.attribute] = value.default if isinstance(value, _Deferred) else value


@dataclass(frozen=True)
class Solution:
    """Result of :func:`epicyclic.solve`: shafts, elements, efficiency, warnings.

    Attributes
    ----------
    shafts : mapping name → ShaftState
    elements : mapping name → ElementState
    input_power, output_power, loss : float
        W; input = Σ power of the drives, output = −Σ power of the loads.
    efficiency : float or None
        output/input; None when the train self-locks or has no drive/load.
    self_locking : SelfLocking or None
    circulation : Circulation
        Circulating power (Blindleistung) per closed loop and in total, and
        the largest element power, each in W and as a multiple of the input;
        not defined where the torque split is statically indeterminate.
    degrees_of_freedom : int
        Of the train (speeds to give), before the given speeds.
    warnings : tuple of str
    ideal : Solution or None
        The lossless solution at the same operating point.
    housing_loss_sources : mapping source → float
        Losses of auxiliaries that belong to no element (oil pump, shaft seals), W, by source;
        part of ``loss`` and of :attr:`loss_sources`.
    oil_temperature : float or None
        The oil temperature the spin losses were evaluated at, °C (None without spin losses).
    oil_viscosity : float or None
        The oil's dynamic viscosity there, mPa·s (what Schlenk's mesh friction used at this point).

    ``circulation``, ``warnings`` and ``ideal`` may be given as callables that make them: the solver
    does so, and each is made on first access (many callers never read them).  A pickled or copied
    solution carries them made; :meth:`replace` keeps them unmade.
    """

    train: GearTrain
    operating_point: OperatingPoint
    shafts: Mapping[str, ShaftState]
    elements: Mapping[str, ElementState]
    input_power: float
    output_power: float
    loss: float
    efficiency: float | None
    self_locking: SelfLocking | None
    degrees_of_freedom: int
    circulation: Circulation = field(default=_Deferred())
    warnings: tuple[str, ...] = field(default=_Deferred(()))
    ideal: Solution | None = field(default=_Deferred(), compare=False, repr=False)
    housing_loss_sources: Mapping[str, float] = field(default_factory=dict)
    oil_temperature: float | None = None
    oil_viscosity: float | None = None

    def __getstate__(self) -> dict[str, Any]:  # pickled and copied with the deferred fields built
        return {**self.__dict__, **{"_" + name: getattr(self, name) for name in _DEFERRED}}

    def replace(self, **changes: Any) -> Solution:
        """A copy with ``changes`` (as :func:`dataclasses.replace`), deferred fields not built."""
        kept = {name: self.__dict__["_" + name] for name in _DEFERRED if name not in changes}
        return dataclasses.replace(self, **kept, **changes)

    # ------------------------------------------------------------------ shortcuts
    def speed(self, shaft: str) -> float:
        """Speed of ``shaft`` in 1/min."""
        return self._shaft(shaft).speed

    def torque(self, shaft: str) -> float:
        """External torque on ``shaft`` in N·m."""
        return self._shaft(shaft).torque

    def power(self, shaft: str) -> float:
        """External power at ``shaft`` in W (positive into the train)."""
        return self._shaft(shaft).power

    def _shaft(self, shaft: str) -> ShaftState:
        try:
            return self.shafts[shaft]
        except KeyError:
            raise UnknownShaftError(shaft, list(self.shafts), "solution") from None

    @property
    def drives(self) -> tuple[str, ...]:
        return tuple(s.name for s in self.shafts.values() if s.role == "drive")

    @property
    def loss_sources(self) -> dict[str, float]:
        """The train's loss by source (``mesh``, ``bearing``, ``drag``), W: the elements' summed."""
        out: dict[str, float] = {}
        for parts in (*(e.loss_sources for e in self.elements.values()), self.housing_loss_sources):
            for source, value in parts.items():
                out[source] = out.get(source, 0.0) + value
        return out

    @property
    def loads(self) -> tuple[str, ...]:
        return tuple(s.name for s in self.shafts.values() if s.role == "load")

    @property
    def is_self_locking(self) -> bool:
        return self.self_locking is not None

    @property
    def ratio(self) -> float | None:
        """Speed ratio n_drive/n_load for one drive and one load (None otherwise)."""
        if len(self.drives) != 1 or len(self.loads) != 1:
            return None
        out = self.speed(self.loads[0])
        return None if out == 0 else self.speed(self.drives[0]) / out

    # ------------------------------------------------------------------ rendering
    def to_dict(self) -> dict[str, Any]:
        """Plain data (JSON-ready) with units stated; see :mod:`epicyclic.results.render`."""
        return solution_to_dict(self)

    def table(self, units: Units | Mapping[str, str] | None = None) -> str:
        """A plain-text table for terminals, in the core units or in ``units``.

        Parameters
        ----------
        units : Units or mapping quantity → unit, optional
            E.g. ``{"speed": "U/min", "torque": "kp*cm", "power": "PS"}`` (a file's ``[units]``);
            quantities not named stay in 1/min, N·m, W.

        Examples
        --------
        >>> from epicyclic.demo import brandenberger_1952
        >>> from epicyclic import solve
        >>> print(solve(*brandenberger_1952()).table({"power": "PS"}).splitlines()[-6])
        input power            3 PS
        """
        return solution_table(self, units)

    def _repr_html_(self) -> str:
        return solution_html(self)

    def __str__(self) -> str:
        return self.table()

    def __repr__(self) -> str:
        if self.self_locking is not None:
            state = "self-locking"
        elif self.efficiency is None:
            state = "efficiency n/a"
        else:
            state = f"efficiency {self.efficiency:.4f}"
        return (
            f"<Solution {self.train.name!r}: {state}, input {self.input_power:.6g} W, "
            f"loss {self.loss:.6g} W, {len(self.shafts)} shafts, {len(self.elements)} elements>"
        )


#: The fields of a Solution that may be made on first access.
_DEFERRED = ("circulation", "warnings", "ideal")
