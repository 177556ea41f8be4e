"""Result of the scuffing rating of one mesh: :class:`ScuffingRating`.

It carries the quantities of both methods as :class:`~epicyclic.rating.results.Factor` s (value —
a number or one per load case —, unit, clause, name), the flash and contact temperature along
the path of contact, and the safeties against their minimums; it renders itself (``table()``,
``to_dict()``, ``_repr_html_``).  JSON never holds NaN or infinity: an unbounded safety (no
load) is ``null``.

References
----------
ISO/TS 6336-20:2017 and ISO/TS 6336-21:2017 (symbols); ISO/TR 13989-1, -2:2000.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np

from ..results import Factor, json_value

__all__ = ["ScuffingRating"]


def _lowest(value) -> float:
    array = np.asarray(value, dtype=float)
    return float(np.min(array)) if array.size else float("nan")


@dataclass(frozen=True)
class ScuffingRating:
    """Scuffing of one mesh by the integral and the flash temperature method.

    Attributes
    ----------
    element, mesh : str
        The set or stage and the mesh's name.
    gears : (str, str)
        Gear 1 (in the role of the pinion) and gear 2.
    integral_method, flash_method : str
        The documents followed, e.g. ``"ISO/TS 6336-21:2017"``, ``"ISO/TS 6336-20:2017"``.
    integral : mapping symbol → Factor
        θ_oil, θ_M, θ_flaint, θ_int, θ_intS, S_intS, S_SL and their factors.
    flash : mapping symbol → Factor
        θ_M, θ_flm, θ_B,max, Γ there, θ_S, S_B and their factors.
    path : mapping name → ndarray
        ``gamma`` (points), ``X_Gamma``, ``theta_fl`` and ``theta_B`` (load cases + points), °C.
    S_Smin, S_Bmin : float
        Minimum safeties of the integral and the flash method.
    notes : tuple of str
        What the rating assumed.
    """

    element: str
    mesh: str
    gears: tuple[str, str]
    integral_method: str
    flash_method: str
    integral: Mapping[str, Factor]
    flash: Mapping[str, Factor]
    path: Mapping[str, Any] = field(default_factory=dict)
    S_Smin: float = 1.8
    S_Bmin: float = 2.0
    notes: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        for key in ("integral", "flash", "path"):
            object.__setattr__(self, key, MappingProxyType(dict(getattr(self, key))))

    @property
    def S_intS(self):
        """Safety against scuffing by the integral temperature, θ_intS / θ_int (number or one per case)."""
        return self.integral["S_intS"].value

    @property
    def S_SL(self):
        """Safety for the transmittable torque, (θ_intS − θ_oil) / (θ_int − θ_oil)."""
        return self.integral["S_SL"].value

    @property
    def S_B(self):
        """Safety against scuffing by the flash temperature, (θ_S − θ_oil) / (θ_B,max − θ_oil)."""
        return self.flash["S_B"].value

    @property
    def ok(self) -> bool:
        """Whether S_intS ≥ S_Smin and S_B ≥ S_Bmin in every case."""
        return bool(np.all(np.asarray(self.S_intS) >= self.S_Smin) and np.all(np.asarray(self.S_B) >= self.S_Bmin))

    def below_minimum(self) -> list[str]:
        """What falls short, e.g. ``["S_intS 1.52 < 1.8"]`` (the lowest case); empty where both hold."""
        out = []
        for name, value, minimum in (("S_intS", self.S_intS, self.S_Smin), ("S_B", self.S_B, self.S_Bmin)):
            if _lowest(value) < minimum:
                out.append(f"{name} {_lowest(value):.3g} < {minimum:g}")
        return out

    def to_dict(self) -> dict[str, Any]:
        """JSON data: element, mesh, gears, methods, both factor sets, the path, minimums, ok, notes."""
        return {"element": self.element, "mesh": self.mesh, "gears": list(self.gears),
                "integral_method": self.integral_method, "flash_method": self.flash_method,
                "integral": {s: f.to_dict() for s, f in self.integral.items()},
                "flash": {s: f.to_dict() for s, f in self.flash.items()},
                "path": {k: json_value(v) for k, v in self.path.items()},
                "S_intS": json_value(self.S_intS), "S_SL": json_value(self.S_SL), "S_B": json_value(self.S_B),
                "S_Smin": self.S_Smin, "S_Bmin": self.S_Bmin, "ok": self.ok, "notes": list(self.notes)}

    def modes(self) -> tuple:
        """(integral, flash) as :class:`~epicyclic.rating.mode_results.ModeRating` s, the failure modes of a mesh.

        ``scuffing_integral`` with the safety S_intS against S_Smin, ``scuffing_flash`` with S_B against
        S_Bmin and the temperatures along the path as its profile.
        """
        from ..mode_results import ModeRating

        integral = ModeRating("scuffing_integral", "Scuffing, integral temperature method", self.integral_method,
                              self.integral, "S_intS", self.S_Smin, gears=self.gears, notes=self.notes)
        flash = ModeRating("scuffing_flash", "Scuffing, flash temperature method", self.flash_method, self.flash,
                           "S_B", self.S_Bmin, gears=self.gears, profile=self.path, notes=self.notes)
        return integral, flash

    def table(self) -> str:
        """Both methods as plain-text tables (a safety below its minimum ends in ``!``)."""
        return "\n\n".join(m.table() for m in self.modes())

    def _repr_html_(self) -> str:
        return "".join(m.html() for m in self.modes())

    def __repr__(self) -> str:
        return (f"ScuffingRating({self.element}: {self.mesh}, S_intS {_lowest(self.S_intS):.3f}, "
                f"S_SL {_lowest(self.S_SL):.3f}, S_B {_lowest(self.S_B):.3f}, ok {self.ok})")
