"""The operating point: what is given about a train's motion and load.

Core units: speeds in 1/min, torques in N·m, powers in W.
Torque and power are *external* values acting on a shaft from outside:
positive power flows into the train (a drive), negative power out (a load).
Units other than these are converted at the edges (:mod:`epicyclic.units`).
"""

from __future__ import annotations

import numbers
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from functools import cached_property
from types import MappingProxyType

from ..errors import OperatingPointError
from .planetary import finite_float

__all__ = ["OperatingPoint"]


#: The quantity of each group of values (for unit conversion).
_QUANTITIES = {"speeds": "speed", "torques": "torque", "powers": "power"}
#: A value of each group, for messages.
_EXAMPLES = {"speeds": "3000", "torques": "'100 N*m'", "powers": "'10 kW'"}


def _frozen_values(values: Mapping[str, object] | None, field_name: str) -> Mapping[str, float]:
    if values is None:
        values = {}
    if not isinstance(values, Mapping):
        raise OperatingPointError(
            f"operating point: {field_name} must be a mapping shaft → value, e.g. {field_name}={{'sun': "
            f"{_EXAMPLES[field_name]}}}, got {type(values).__name__} {values!r:.40}.", group=field_name)
    checked: dict[str, float] = {}
    for shaft, value in values.items():
        if not isinstance(shaft, str):
            raise OperatingPointError(f"operating point: {field_name} keys must be shaft names, got {shaft!r}.",
                                      group=field_name)
        if isinstance(value, bool):
            raise OperatingPointError(
                f"operating point: {field_name}[{shaft!r}] must be a number, got {value!r}.",
                group=field_name, shafts=[shaft],
            )
        if not isinstance(value, numbers.Real):
            # a unit string or a pint quantity: converted at this boundary, by the one converter
            from ..units import to_core

            value = to_core(value, _QUANTITIES[field_name], field=f"operating_point.{field_name}.{shaft}")
        elif not isinstance(value, (int, float)):
            value = float(value)  # numpy scalars and other real numbers
        if finite_float(value) is None:
            raise OperatingPointError(
                f"operating point: {field_name}[{shaft!r}] must be finite, got {value!r}.",
                group=field_name, shafts=[shaft],
            )
        checked[shaft] = float(value)
    return MappingProxyType(checked)


@dataclass(frozen=True)
class OperatingPoint:
    """Given speeds, torques and powers, and which shafts drive and which are loaded.

    Parameters
    ----------
    speeds : mapping shaft → float, str or pint.Quantity
        Given speeds in 1/min, or with a unit: ``"1500 rpm"``, ``"157 rad/s"``
        or a pint quantity (converted by :func:`epicyclic.units.to_core`).
    torques : mapping shaft → float, str or pint.Quantity
        Given external torques in N·m, or with a unit: ``"143.24 kp*cm"``,
        ``"100 lbf*ft"``.  At a drive or a load the magnitude is used and the
        role sets the sign (power enters at a drive, leaves at a load); at any
        other shaft the sign counts (positive with positive speed: power enters).
    powers : mapping shaft → float, str or pint.Quantity
        Given external powers in W, or with a unit: ``"3 PS"``, ``"30 kW"``.  A positive value at a load is read as its
        magnitude (power leaving the train); likewise a drive's power is taken
        as entering the train.
    drives, loads : iterable of str
        Shafts where power is put in / taken out.  Shafts with a given torque or
        power are external too.  Every other shaft (but the housing) carries no
        external torque.
    connected : iterable of str
        Further shafts connected to the outside whose role (drive or load)
        follows from the solution, e.g. both ends of a train run in either
        direction.

    Raises
    ------
    UnitError
        A value with a unit that cannot be read or has the wrong dimension; its
        ``field`` names the value (``"operating_point.speeds.in"``).
    OperatingPointError
        A value that is no number, not finite, a shaft named both drive and
        load, or both a torque and a power at one shaft.

    Examples
    --------
    >>> op = OperatingPoint(speeds={"in": 1500}, powers={"in": 3000}, drives=["in"], loads=["out"])
    >>> op.external_shafts
    ('in', 'out')
    >>> OperatingPoint(speeds={"in": "1500 U/min"}, powers={"in": "3 PS"}).powers["in"]
    2206.49625
    """

    speeds: Mapping[str, float] = field(default_factory=dict)
    torques: Mapping[str, float] = field(default_factory=dict)
    powers: Mapping[str, float] = field(default_factory=dict)
    drives: tuple[str, ...] = ()
    loads: tuple[str, ...] = ()
    connected: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        object.__setattr__(self, "speeds", _frozen_values(self.speeds, "speeds"))
        object.__setattr__(self, "torques", _frozen_values(self.torques, "torques"))
        object.__setattr__(self, "powers", _frozen_values(self.powers, "powers"))
        for name in ("drives", "loads", "connected"):
            value = getattr(self, name)
            if isinstance(value, str):
                value = (value,)
            try:
                value = tuple(value)
            except TypeError:
                value = (value,)
            for shaft in value:
                if not isinstance(shaft, str):
                    raise OperatingPointError(
                        f"operating point: {name} must be shaft names, e.g. {name}=['sun'], got {shaft!r:.40}.",
                        group=name)
            object.__setattr__(self, name, value)
        both = set(self.drives) & set(self.loads)
        if both:
            raise OperatingPointError(
                f"operating point: shaft(s) {', '.join(sorted(both))} are named both as drive and as load.",
                group="loads", shafts=sorted(both),
            )
        twice = set(self.torques) & set(self.powers)
        if twice:
            raise OperatingPointError(
                f"operating point: give a torque or a power at shaft(s) {', '.join(sorted(twice))}, not both.",
                group="powers", shafts=sorted(twice),
            )

    def __hash__(self) -> int:
        # the generated hash would hash the read-only mappings, which are unhashable
        return hash((*(frozenset(getattr(self, g).items()) for g in _QUANTITIES),
                     self.drives, self.loads, self.connected))

    @cached_property
    def external_shafts(self) -> tuple[str, ...]:
        """Shafts that carry an external torque (drives, loads, given torques/powers)."""
        ordered: list[str] = []
        for group in (self.drives, self.loads, self.connected, self.torques, self.powers):
            for shaft in group:
                if shaft not in ordered:
                    ordered.append(shaft)
        return tuple(ordered)

    def shaft_names(self) -> Iterable[str]:
        """Every shaft the operating point names."""
        yield from self.speeds
        yield from self.external_shafts
