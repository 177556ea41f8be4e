"""How a number appears on a figure: one zero rule and one formatter for every label.

A value whose magnitude is at most :data:`ZERO_RELATIVE` times the scale of
its quantity in the drawn train (the largest speed, torque or power) is
round-off, not a result: it is drawn and labelled as exactly 0, and a
branch carrying it is left out.  Every label of the plotting package is
written by :func:`label` (or :func:`fmt` after :func:`clean`), so that no
figure shows ``1e-13`` noise or ``-0``.

The rule is the solver's own, :mod:`epicyclic.results.zero` (tolerance
``ZERO_TOLERANCE`` relative to the scale of the terms); this module only
chooses the scale a figure compares against (its quantity's largest value
in the train) and formats the result.

Examples
--------
>>> clean(-1.14e-10, 10472.0), label(-1.14e-10, 10472.0), label(212.963, 10472.0)
(0.0, '0', '213')
>>> fmt(-0.0), fmt(0.00012345), fmt(123456.0)
('0', '0.0001234', '123456')
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ..results import zero

if TYPE_CHECKING:  # pragma: no cover
    from ..results.solution import Solution

__all__ = ["ZERO_RELATIVE", "Scales", "clean", "fmt", "is_zero", "label", "scale_of"]

#: Magnitudes up to this fraction of their quantity's scale are numerically zero (the solver's rule).
ZERO_RELATIVE = zero.ZERO_TOLERANCE


def scale_of(values: Iterable[float]) -> float:
    """The scale of a set of values: the largest finite magnitude (0.0 if none)."""
    return zero.scale_of(*(v for v in values if math.isfinite(v)))


def is_zero(value: float, scale: float) -> bool:
    """Whether ``value`` is round-off relative to ``scale`` (:func:`epicyclic.results.zero.is_zero`)."""
    return zero.is_zero(value, scale)


def clean(value: float, scale: float) -> float:
    """``value``, or exactly 0.0 where it is numerically zero against ``scale`` (never −0.0)."""
    return zero.clean(value, scale)


def fmt(value: float, digits: int = 4) -> str:
    """A compact number for labels: ``digits`` significant digits, whole numbers when large, ``-0`` as ``0``."""
    if not math.isfinite(value):
        return "—"
    if 10 ** (digits - 1) <= abs(value) < 1e12:
        text = f"{value:.0f}"
    else:
        text = f"{value:.{digits}g}"
    return "0" if re.fullmatch(r"-0(\.0*)?", text) else text


def label(value: float, scale: float, digits: int = 4) -> str:
    """:func:`fmt` of :func:`clean`: the text every figure shows for a value."""
    return fmt(clean(value, scale), digits)


@dataclass(frozen=True)
class Scales:
    """The speed (1/min), torque (N·m) and power (W) scales of a solved train."""

    speed: float
    torque: float
    power: float

    @classmethod
    def of(cls, solution: Solution) -> Scales:
        """Largest shaft speed, largest torque (shafts and ports) and largest power (shafts and ports).

        Examples
        --------
        >>> from epicyclic.demo import brandenberger_1952
        >>> from epicyclic import solve
        >>> s = Scales.of(solve(*brandenberger_1952()))
        >>> round(s.speed), round(s.power)
        (5280, 2206)
        """
        torques = [s.torque for s in solution.shafts.values()]
        powers = [s.power for s in solution.shafts.values()]
        for state in solution.elements.values():
            torques += list(state.torques.values())
            powers += list(state.port_powers.values())
        return cls(scale_of(s.speed for s in solution.shafts.values()), scale_of(torques), scale_of(powers))
