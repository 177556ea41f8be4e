"""What fails over a duty cycle: every case and every sum below its minimum.

A :class:`Shortfall` is one value below its limit: a case's safety S_H or S_F below S_Hmin or
S_Fmin (ISO 6336-2, -3), a flank or root damage sum D ≥ 1 (ISO 6336-6, Palmgren–Miner), a bearing
life below the required life (ISO 281; the modified life L_nmh where the bearing has its inputs,
else L10h).  :func:`shortfalls` runs every check of :data:`CHECKS` over a
:class:`~epicyclic.rating.DutyCycleResult`; a failure mode added later (micropitting S_λ, scuffing
S_B) adds its check with :func:`register_check`.

The required life is the cycle's hours where the duty cycle gives them, else the rating's
``life``; without either no bearing life is checked (and the result says so).

References
----------
ISO 6336-1:2019, clause 4 (minimum safeties); ISO 6336-6:2019, clause 5 (D < 1); ISO 281:2007, 5.3 and 9.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["CHECKS", "Shortfall", "register_check", "shortfalls"]


@dataclass(frozen=True)
class Shortfall:
    """One value of a duty cycle below its minimum.

    Attributes
    ----------
    quantity : str
        ``"S_H"``, ``"S_F"``, ``"D_H"``, ``"D_F"``, ``"L10h"``, ``"Lnmh"`` (later ``"S_lambda"``, ``"S_B"``).
    where : str
        The gear (``"P sun-planet sun"``) or bearing (``"P planet 1"``).
    case : str or None
        The load case, None for a sum over the cycle.
    value, limit : float
        The value and the limit it misses (a damage sum: the value reaches the limit 1).
    unit : str
        ``"1"`` or ``"h"``.
    """

    quantity: str
    where: str
    case: str | None
    value: float
    limit: float
    unit: str = "1"

    def text(self) -> str:
        """One line for stderr: what, where, in which case, the value and its limit."""
        relation = ">=" if self.quantity.startswith("D_") else "<"
        unit = f" {self.unit}" if self.unit != "1" else ""
        at = f"case {self.case!r}" if self.case is not None else "over the cycle"
        return (f"below minimum: {self.where}, {at}: {self.quantity} = {self.value:.4g}{unit} {relation} "
                f"{self.limit:.6g}{unit}")

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready (an infinite value is null)."""
        return {"quantity": self.quantity, "where": self.where, "case": self.case,
                "value": self.value if math.isfinite(self.value) else None, "limit": self.limit, "unit": self.unit}


#: Checks run by :func:`shortfalls`: each takes the result and the required life (h or None).
CHECKS: list[Callable[[Any, float | None], Iterable[Shortfall]]] = []


def register_check(check: Callable[[Any, float | None], Iterable[Shortfall]]):
    """Add ``check`` (result, required life → shortfalls) to :data:`CHECKS`; returns it (a decorator).

    Parameters
    ----------
    check : callable
    """
    if check not in CHECKS:
        CHECKS.append(check)
    return check


@register_check
def _tooth_safeties(result, required: float | None) -> Iterable[Shortfall]:
    names = [c.name for c in result.duty.cases]
    for d in result.damage:
        where = f"{d.element} {d.mesh} {d.gear}"
        for quantity, values, limit in (("S_H", d.S_H, d.S_Hmin), ("S_F", d.S_F, d.S_Fmin)):
            if values is None:
                continue
            for k in np.flatnonzero(~(np.asarray(values) >= limit)):
                yield Shortfall(quantity, where, names[int(k)], float(values[k]), limit)


@register_check
def _damage_sums(result, required: float | None) -> Iterable[Shortfall]:
    for d in result.damage:
        for quantity, value in (("D_H", d.flank_damage), ("D_F", d.root_damage)):
            if not value < 1.0:
                yield Shortfall(quantity, f"{d.element} {d.mesh} {d.gear}", None, float(value), 1.0)


@register_check
def _bearing_lives(result, required: float | None) -> Iterable[Shortfall]:
    if required is None:
        return
    for b in result.bearings:
        modified = b.modified_life_hours
        quantity, value = ("Lnmh", modified) if modified is not None else ("L10h", b.life_hours)
        if not value >= required:
            yield Shortfall(quantity, f"{b.element} {b.position}", None, float(value), float(required), "h")


def shortfalls(result, required: float | None) -> tuple[Shortfall, ...]:
    """Every value of ``result`` below its minimum, by the checks of :data:`CHECKS`.

    Parameters
    ----------
    result : DutyCycleResult
    required : float or None
        The required life, h (bearings are not checked without one).

    Returns
    -------
    tuple of Shortfall

    References
    ----------
    ISO 6336-1:2019, clause 4; ISO 6336-6:2019, clause 5; ISO 281:2007, 5.3.
    """
    return tuple(s for check in CHECKS for s in check(result, required))
