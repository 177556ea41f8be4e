"""The load-independent (spin) losses of a transmission, by source, at the oil temperature.

:class:`SpinLosses` holds the models of the losses that do not depend on the
transmitted torque — open clutch and brake drag (:mod:`.clutch_drag`), the oil
pump (:mod:`.pump`), churning (:mod:`.churning`), windage (:mod:`.windage`) and
shaft seals (:mod:`.seals`) — with the oil (:mod:`.oil`) and its temperature:
given, or ``"thermal"``, from the housing's heat balance (:mod:`.thermal`).

Evaluated at the shafts' speeds (which the losses do not change) and the oil
temperature, they give torques on shafts, by source and by the element they are
reported under (``"housing"`` for the pump and the seals, which belong to no
element), in the form the general solver takes (``loss_torques`` of
:func:`~epicyclic.solver.solve`), and the power each loses (T·ω ≥ 0).  Every
function is vectorised over operating points.

References
----------
ISO/TR 14179-2:2001 (the gearbox loss as the sum of load-dependent and no-load losses:
P_V = P_VZP + P_VZ0 + P_VLP + P_VL0 + P_VD + P_VX); Höhn, Michaelis, Hinterstoißer 2009.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

import numpy as np

from ..limits import OIL_TEMPERATURE_RANGE
from ..model.elements import HOUSING, Brake, Clutch
from ..model.train import GearTrain
from ..results.solution import RPM_TO_RAD_S
from .churning import ChurningGear
from .clutch_drag import ClutchDrag
from .errors import LossModelError
from .oil import Oil
from .pump import OilPump
from .seals import ShaftSeal
from .thermal import Housing
from .windage import WindageGear

__all__ = ["SpinLosses", "SpinState", "SPIN_SOURCES", "ALL_SOURCES"]

#: Names of the spin-loss sources, in report order.
SPIN_SOURCES = ("clutch_drag", "pump", "churning", "windage", "seals")
#: Every loss source, load-dependent first, in report order.
ALL_SOURCES = ("mesh", "bearing", "drag", *SPIN_SOURCES)


@dataclass(frozen=True, eq=False)
class SpinState:
    """The spin losses at arrays of operating points.

    Attributes
    ----------
    torques : mapping host → mapping source → mapping shaft → ndarray
        Torques on shafts (N·m, opposing the motion, reactions included), as the solver's
        ``loss_torques`` take them; host is an element name or ``"housing"``.
    losses : mapping (host, source) → ndarray
        Power lost, W (≥ 0).
    temperature : ndarray
        Oil temperature at each point, °C.
    viscosity : ndarray or None
        The oil's dynamic viscosity there, mPa·s (None without an oil): every viscosity-dependent
        loss, Schlenk's mesh friction included, is evaluated with it.
    """

    torques: Mapping[str, Mapping[str, Mapping[str, np.ndarray]]]
    losses: Mapping[tuple[str, str], np.ndarray]
    temperature: np.ndarray
    viscosity: np.ndarray | None = None

    @property
    def total(self) -> np.ndarray:
        """Sum of the spin losses, W, at each point."""
        out = np.zeros(np.shape(self.temperature))
        for value in self.losses.values():
            out = out + value
        return out

    def by_source(self) -> dict[str, np.ndarray]:
        """Loss by source (summed over hosts), W."""
        out: dict[str, np.ndarray] = {}
        for (_, source), value in self.losses.items():
            out[source] = out.get(source, 0.0) + value
        return out


@dataclass(frozen=True)
class SpinLosses:
    """The spin-loss models of a transmission and its oil.

    Parameters
    ----------
    oil : Oil or None
        Needed by clutch drag and churning (viscosity, density).
    temperature : float or None
        Oil (sump) temperature, °C; None with a ``housing``: found by the thermal balance.
    housing : Housing or None
        Heat paths for the thermal balance (ISO/TR 14179-1).
    clutch_drag : tuple of ClutchDrag
        Drag of open clutches and brakes (an engaged one has none).
    pump : OilPump or None
    churning : tuple of ChurningGear
    windage : tuple of WindageGear
    seals : tuple of ShaftSeal
    defaults : tuple of str
        The defaults the models' inputs took (stated by the file reader, shown by ``explain``).

    Examples
    --------
    >>> spin = SpinLosses(seals=(ShaftSeal("in", 40.0),))
    >>> state = spin.evaluate({"in": np.array([3000.0])})
    >>> round(float(state.total[0]), 2)  # W: 7.69e-6 · 40² · 3000
    36.91
    """

    oil: Oil | None = None
    temperature: float | None = None
    housing: Housing | None = None
    clutch_drag: tuple[ClutchDrag, ...] = ()
    pump: OilPump | None = None
    churning: tuple[ChurningGear, ...] = ()
    windage: tuple[WindageGear, ...] = ()
    seals: tuple[ShaftSeal, ...] = ()
    defaults: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        owner = "spin losses"
        for name, kind in (("clutch_drag", ClutchDrag), ("churning", ChurningGear), ("windage", WindageGear),
                           ("seals", ShaftSeal)):
            items = tuple(getattr(self, name))
            for item in items:
                if not isinstance(item, kind):
                    raise LossModelError(f"{owner}: {name} must hold {kind.__name__} models, got {item!r}.")
            object.__setattr__(self, name, items)
        if self.oil is not None and not isinstance(self.oil, Oil):
            raise LossModelError(f"{owner}: oil must be an Oil, got {self.oil!r}.")
        if self.housing is not None and not isinstance(self.housing, Housing):
            raise LossModelError(f"{owner}: housing must be a Housing, got {self.housing!r}.")
        if self.pump is not None and not isinstance(self.pump, OilPump):
            raise LossModelError(f"{owner}: pump must be an OilPump, got {self.pump!r}.")
        if self.temperature is not None:
            t = self.temperature
            low, high = OIL_TEMPERATURE_RANGE
            if isinstance(t, bool) or not isinstance(t, (int, float)) or not low <= t <= high:
                raise LossModelError(f"{owner}: temperature must be an oil temperature in {low:g} ... {high:g} degC "
                                     f"(see docs/limits.md), got {t!r}.")
            object.__setattr__(self, "temperature", float(t))
        if (self.clutch_drag or self.churning) and self.oil is None:
            raise LossModelError(f"{owner}: clutch drag and churning need the oil: give viscosity_40 and "
                                 "viscosity_100 in [lubricant].")
        if self.oil is not None and self.temperature is None and self.housing is None:
            raise LossModelError(f"{owner}: the oil needs a temperature: give [lubricant] temperature (degC) or "
                                 "temperature = \"thermal\" with a [housing] table.")
        names = [d.element for d in self.clutch_drag]
        twice = sorted({n for n in names if names.count(n) > 1})
        if twice:
            raise LossModelError(f"{owner}: clutch drag is given twice for {', '.join(map(repr, twice))}.")

    # ---------------------------------------------------------------- facts
    @property
    def is_empty(self) -> bool:
        """No model and no oil (the train's losses are those of its elements, bit for bit)."""
        return self.oil is None and not (self.clutch_drag or self.pump or self.churning or self.windage
                                         or self.seals)

    @property
    def thermal(self) -> bool:
        """Whether the oil temperature comes from the thermal balance."""
        return self.temperature is None and self.housing is not None

    def check(self, train: GearTrain, input: str | None = None) -> None:
        """Raise a LossModelError if a model names an element or shaft ``train`` does not have.

        Parameters
        ----------
        train : GearTrain
        input : str or None
            The transmission's input (drives the pump unless it names its shaft).
        """
        elements = {e.name: e for e in train.elements}
        for drag in self.clutch_drag:
            element = elements.get(drag.element)
            if not isinstance(element, (Clutch, Brake)):
                raise LossModelError(
                    f"clutch drag: {drag.element!r} is not a clutch or brake of the train; shift elements are "
                    f"{', '.join(repr(e.name) for e in train.shift_elements) or 'none'}."
                )
        shafts = set(train.shafts)
        named = [(f"seal on {s.shaft!r}", s.shaft) for s in self.seals]
        named += [(f"churning gear on {g.shaft!r}", g.shaft) for g in self.churning]
        named += [(f"windage gear on {g.shaft!r}", g.shaft) for g in self.windage]
        if self.pump is not None:
            if self.pump.shaft is None and input is None:
                raise LossModelError("oil pump: name the shaft that drives it (shaft = ...); this train has no "
                                     "transmission input.")
            named.append(("oil pump", self.pump.shaft or input))
        for what, shaft in named:
            if shaft not in shafts or shaft == HOUSING:
                raise LossModelError(f"{what}: the train has no moving shaft {shaft!r}; its shafts are "
                                     f"{', '.join(repr(s) for s in train.shafts if s != HOUSING)}.")
        for gear in (*self.churning, *self.windage):
            if gear.element is not None and gear.element not in elements:
                raise LossModelError(f"{type(gear).__name__} on {gear.shaft!r}: the train has no element "
                                     f"{gear.element!r} to report it under.")

    # ---------------------------------------------------------------- evaluation
    def oil_state(self, temperature) -> tuple[Any, Any, Any]:
        """(η mPa·s, ν mm²/s, ρ kg/m³) of the oil at ``temperature`` (°C); None without an oil."""
        if self.oil is None:
            return None, None, None
        return (self.oil.dynamic_viscosity(temperature), self.oil.kinematic_viscosity(temperature),
                self.oil.density_at(temperature))

    def evaluate(self, speeds: Mapping[str, Any], temperature=None, *, train: GearTrain | None = None,
                 gear: str | None = None, input: str | None = None) -> SpinState:
        """Torques and losses of every model at the shafts' speeds and the oil temperature.

        Parameters
        ----------
        speeds : mapping shaft → array_like
            Speed of each shaft, 1/min (one shape for all).
        temperature : float or array_like, optional
            Oil temperature, °C (default: the model's fixed ``temperature``).
        train : GearTrain, optional
            The train in the gear (which clutches are open); needed with clutch drag.
        gear : str, optional
            The gear (a pump pressure by gear).
        input : str, optional
            The shaft that drives the pump when it names none.

        Returns
        -------
        SpinState

        Raises
        ------
        LossModelError
            Clutch drag without the train, a temperature outside the oil's range.
        """
        arrays = {s: np.asarray(v, dtype=float) for s, v in speeds.items()}
        shape = np.broadcast_shapes(*(v.shape for v in arrays.values())) if arrays else ()
        if temperature is None:
            temperature = self.temperature if self.temperature is not None else 80.0
        temp = np.broadcast_to(np.asarray(temperature, dtype=float), shape)
        eta, nu, rho = self.oil_state(temp)
        torques: dict[str, dict[str, dict[str, np.ndarray]]] = {}
        losses: dict[tuple[str, str], np.ndarray] = {}

        def speed(shaft: str) -> np.ndarray:
            return np.zeros(shape) if shaft == HOUSING else np.broadcast_to(arrays[shaft], shape)

        def put(host: str, source: str, first: str, second: str, magnitude, relative) -> None:
            on_first = -np.broadcast_to(magnitude, shape) * np.sign(relative)
            if not np.any(on_first):
                return
            shafts = torques.setdefault(host, {}).setdefault(source, {})
            shafts[first] = shafts.get(first, 0.0) + on_first
            shafts[second] = shafts.get(second, 0.0) - on_first
            key = (host, source)
            losses[key] = losses.get(key, 0.0) + np.abs(on_first * relative) * RPM_TO_RAD_S

        if self.clutch_drag:
            if train is None:
                raise LossModelError("spin losses: clutch drag needs the train in its gear (which elements are open).")
            elements = {e.name: e for e in train.elements}
            for drag in self.clutch_drag:
                element = elements[drag.element]
                if element.engaged:
                    continue
                first, second = ((element.first, element.second) if isinstance(element, Clutch)
                                 else (element.shaft, HOUSING))
                slip = speed(first) - speed(second)
                put(drag.element, "clutch_drag", first, second, drag.torque(slip, eta, rho), slip)
        if self.pump is not None:
            shaft = self.pump.shaft or input
            if shaft is None:
                raise LossModelError("oil pump: name the shaft that drives it (shaft = ...) or give the input.")
            n = speed(shaft)
            put(HOUSING, "pump", shaft, HOUSING, np.full(shape, self.pump.torque(gear)), n)
        for dipped in self.churning:
            n = speed(dipped.shaft)
            put(dipped.element or HOUSING, "churning", dipped.shaft, HOUSING, dipped.torque(n, nu, rho), n)
        for fast in self.windage:
            n = speed(fast.shaft)
            put(fast.element or HOUSING, "windage", fast.shaft, HOUSING, fast.torque(n), n)
        for seal in self.seals:
            n = speed(seal.shaft)
            put(HOUSING, "seals", seal.shaft, HOUSING, np.full(shape, seal.torque()), n)
        frozen = MappingProxyType({h: MappingProxyType({s: MappingProxyType(t) for s, t in by.items()})
                                   for h, by in torques.items()})
        return SpinState(frozen, MappingProxyType(losses), np.array(temp), None if eta is None else np.array(eta))

    def describe(self) -> dict[str, Any]:
        """Plain data for reports: the oil, its temperature and every model's parameters."""
        def plain(obj):
            return {k: (dict(v) if isinstance(v, Mapping) else v) for k, v in vars(obj).items()
                    if not k.startswith("_")}

        return {
            "oil": None if self.oil is None else plain(self.oil),
            "temperature": "thermal" if self.thermal else self.temperature,
            "housing": None if self.housing is None else plain(self.housing),
            "clutch_drag": [plain(d) for d in self.clutch_drag],
            "pump": None if self.pump is None else plain(self.pump),
            "churning": [plain(g) for g in self.churning],
            "windage": [plain(g) for g in self.windage],
            "seals": [plain(s) for s in self.seals],
            "defaults": list(self.defaults),
        }
