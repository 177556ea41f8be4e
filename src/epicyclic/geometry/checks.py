"""Result objects of the fitting conditions (frozen, self-rendering).

See :mod:`epicyclic.geometry.fitting` for the conditions and their sources.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, fields
from typing import TYPE_CHECKING, Any

from ._render import html_table, text_table
from .errors import FittingError

if TYPE_CHECKING:  # pragma: no cover
    from .set_geometry import SetGeometry

__all__ = ["Check", "CoaxialityCheck", "AssemblyCheck", "NeighbourCheck", "UndercutCheck", "InterferenceCheck",
           "TipThicknessCheck", "ContactRatioCheck", "BacklashCheck", "FittingReport"]


#: Why a check's number is null in JSON (it is infinite: nothing to measure).
_WHY_NOT_FINITE = {("neighbours", "clearance"): "one planet: no neighbour, the clearance is unbounded"}


@dataclass(frozen=True)
class Check:
    """Result of one fitting condition.

    Attributes
    ----------
    condition : str
        ``coaxiality``, ``assembly``, ``neighbours``, ``undercut`` or ``interference``.
    passed : bool
    message : str
        Which condition, by how much, and what to change (or why it passes).
    severity : {"error", "warning"}
        Failing errors make the set unusable; warnings ask for a closer look.
    """

    condition: str
    passed: bool
    message: str
    severity: str

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data: every field of the check (mappings as dicts, tuples as lists).

        Lengths in mm, angles in degrees, as the check's fields.

        Returns
        -------
        dict
        """
        out: dict[str, Any] = {}
        reasons: dict[str, str] = {}
        for f in fields(self):
            value = getattr(self, f.name)
            if isinstance(value, float) and not math.isfinite(value):  # JSON has no inf/nan: null with a reason
                reasons[f.name] = _WHY_NOT_FINITE.get((self.condition, f.name), f"{value!r}: not a finite number")
                value = None
            out[f.name] = dict(value) if isinstance(value, Mapping) else (list(value) if isinstance(value, tuple) else value)
        if reasons:
            out["null_reasons"] = reasons
        return out

    def __str__(self) -> str:
        state = "ok" if self.passed else ("FAIL" if self.severity == "error" else "WARNING")
        return f"[{state}] {self.condition}: {self.message}"


@dataclass(frozen=True)
class CoaxialityCheck(Check):
    """Coaxiality: centre distances of the meshes (mm), their difference and a fix."""

    center_distances: Mapping[str, float]
    difference: float
    tolerance: float
    suggestion: Mapping[str, float]


@dataclass(frozen=True)
class AssemblyCheck(Check):
    """Assembly: possible planet positions, equal spacing, actual angles and phasing."""

    planets: int
    ticks: int
    min_angle: float
    equally_spaced: bool
    angles: tuple[float, ...]
    max_deviation: float
    phasing: Mapping[str, str]


@dataclass(frozen=True)
class NeighbourCheck(Check):
    """Neighbour condition: smallest clearance between planet tips (mm) and the most planets that fit."""

    planets: int
    clearance: float
    min_clearance: float
    max_planets: int


@dataclass(frozen=True)
class UndercutCheck(Check):
    """Undercut of one external gear: z, x, the limit z_g and the least profile shift x_min."""

    gear: str
    teeth: int
    profile_shift: float
    limit_teeth: float
    min_profile_shift: float
    limit: str


@dataclass(frozen=True)
class InterferenceCheck(Check):
    """Interference of an internal mesh: margins (≥ 0 passes) of the three KHK conditions."""

    mesh: str
    involute_margin: float
    trochoid_margin: float
    trimming_margin: float


@dataclass(frozen=True)
class TipThicknessCheck(Check):
    """Tip thickness of one gear: s_an in mm and as a multiple of the module, against the limits."""

    gear: str
    tip_thickness: float
    module: float
    error_limit: float
    warning_limit: float


@dataclass(frozen=True)
class ContactRatioCheck(Check):
    """Contact ratios of one mesh: ε_α, ε_β (None without face width) and ε_γ."""

    mesh: str
    transverse: float
    overlap: float | None
    total: float


@dataclass(frozen=True)
class BacklashCheck(Check):
    """Normal backlash j_bn of one mesh at its centre distance, mm (< 0: the teeth jam)."""

    mesh: str
    backlash: float
    center_distance: float
    given: bool


@dataclass(frozen=True)
class FittingReport:
    """All fitting conditions of one set.

    Attributes
    ----------
    geometry : SetGeometry, StageGeometry or None
        None for a report from tooth counts alone (:func:`~epicyclic.geometry.check_tooth_counts`);
        a StageGeometry for a fixed-axis stage (:func:`~epicyclic.geometry.working.check_stage`).
    checks : tuple of Check
    name : str
        The set's name where ``geometry`` is None.
    """

    geometry: SetGeometry | None
    checks: tuple[Check, ...] = field(default_factory=tuple)
    name: str = ""

    @property
    def set_name(self) -> str:
        """The set's (or stage's) name."""
        if self.geometry is None:
            return self.name
        owner = getattr(self.geometry, "planetary_set", None) or getattr(self.geometry, "stage", None)
        return owner.name

    @property
    def passed(self) -> bool:
        """True when no error-level condition fails (warnings allowed)."""
        return not self.failures

    @property
    def failures(self) -> tuple[Check, ...]:
        return tuple(c for c in self.checks if not c.passed and c.severity == "error")

    @property
    def warnings(self) -> tuple[Check, ...]:
        return tuple(c for c in self.checks if not c.passed and c.severity == "warning") + tuple(
            c for c in self.checks if c.passed and c.severity == "warning"
        )

    def raise_if_failed(self) -> None:
        """Raise :class:`~epicyclic.geometry.errors.FittingError` listing every failing condition."""
        if self.failures:
            lines = "; ".join(c.message for c in self.failures)
            raise FittingError(
                f"set {self.set_name!r} does not fit ({len(self.failures)} condition(s)): {lines}",
                self.failures,
            )

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready data: the set's name, whether it passes, every check.

        Returns
        -------
        dict
            ``set``, ``passed`` (no error-level condition fails) and ``checks``
            (:meth:`Check.to_dict` of each, in the order they were made).
        """
        return {"set": self.set_name, "passed": self.passed, "from_tooth_counts_only": self.geometry is None,
                "checks": [c.to_dict() for c in self.checks]}

    def _rows(self) -> list[list[object]]:
        return [[c.condition, "ok" if c.passed else ("FAIL" if c.severity == "error" else "warning"), c.message]
                for c in self.checks]

    def table(self) -> str:
        """The fitting conditions as a plain-text table: condition, result, numbers.

        The title says whether the set passes or FAILS; each row gives the numbers
        and, for a failing condition, what to change.

        Returns
        -------
        str
        """
        return text_table(["condition", "result", "numbers"], self._rows(),
                          title=f"fitting of {self.set_name!r}"
                                + (" from tooth counts only (no geometry table)" if self.geometry is None else "")
                                + ": " + ("passes" if self.passed else "FAILS"))

    def _repr_html_(self) -> str:
        return html_table(["condition", "result", "numbers"], self._rows(),
                          title=f"fitting of {self.set_name}")

    def __repr__(self) -> str:
        return f"FittingReport({self.set_name!r}, passed={self.passed}, " \
               f"failures={[c.condition for c in self.failures]})"


