"""The inputs of the tooth flank fracture rating: case depth, hardness and the method's constants.

A :class:`FlankFractureSpec` (``[rating.flank_fracture]`` in a train file) gives, per gear or
for all, the case hardness depth CHD, the surface and core hardness (HV) or a measured hardness
profile, and the constants of the material strength::

    τ_per(y) = K_τ,per HV(y)                   local permissible shear stress, N/mm²
    A_FF(y)  = τ_eff(y) / τ_per(y) + c_1        local material exposure

K_τ,per defaults to 0.45 × 3.2 / √3 = 0.831 N/mm² per HV, an engineering assumption of this
package: the torsional fatigue strength 1/√3 of the push–pull one (von Mises), that 0.45 of the
tensile strength, and the tensile strength 3.2 × HV — the orders of magnitude that the FKM guideline
(fatigue strength factors f_W,σ, f_W,τ of steels) and the conversion tables of ISO 18265 give for
steels; the texts were not checked here, and a fatigue ratio that falls at high hardness would
lower the strength of the case.  ISO/TS 6336-4:2019 gives its own conversion and the calibration
constant c_1; neither was reachable to this package, so the default c_1 is 0 and both are reported
as assumed (give ``shear_strength_factor`` and ``calibration_factor`` to use the standard's values).

References
----------
ISO/TS 6336-4:2019, clauses 5.2 and 5.3 (material exposure) and its local material strength; FKM guideline
"Analytical strength assessment of components", 6th ed. 2012 (f_W,σ, f_W,τ; not checked here);
ISO 18265:2013 (hardness conversion); ISO 2639:2002 (CHD).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

from ..errors import RatingError
from .hardness import LIMIT_HARDNESS, HardnessProfile

__all__ = ["DEFAULT_SHEAR_STRENGTH_FACTOR", "FlankFractureSpec"]

TENSILE_PER_HV = 3.2
"""R_m / HV of steels, N/mm² per HV (the order of ISO 18265's conversion tables; assumed)."""
FATIGUE_RATIO = 0.45
"""Push–pull fatigue strength / R_m of steel (the order of the FKM guideline's f_W,σ; assumed)."""
DEFAULT_SHEAR_STRENGTH_FACTOR = FATIGUE_RATIO * TENSILE_PER_HV / math.sqrt(3.0)
"""K_τ,per assumed when none is given: τ_per = K_τ,per HV, N/mm² per HV (≈ 0.831)."""

_PER_GEAR = ("case_depth", "surface_hardness", "core_hardness")


def _number(value, key: str, *, minimum: float = 0.0, strict: bool = True) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or \
            (value <= minimum if strict else value < minimum):
        raise RatingError(f"rating.flank_fracture.{key} must be a number {'>' if strict else '>='} {minimum:g}, "
                          f"got {value!r}.")
    return float(value)


def _lookup(given, element: str, gear: str):
    if isinstance(given, Mapping):
        for key in (f"{element}:{gear}", gear, "all"):
            if key in given:
                return given[key]
        return None
    return given


@dataclass(frozen=True)
class FlankFractureSpec:
    """Inputs of the flank fracture rating of a mesh's gears.

    Parameters
    ----------
    case_depth : float or mapping gear → float, optional
        CHD at 550 HV, mm (ISO 2639).
    surface_hardness, core_hardness : float or mapping gear → float, optional
        HV_s and HV_c, Vickers.
    hardness_profile : sequence of (depth, HV) or mapping gear → sequence, optional
        A measured profile (it replaces the three values above for its gears).
    shear_strength_factor : float, optional
        K_τ,per, N/mm² per HV (default :data:`DEFAULT_SHEAR_STRENGTH_FACTOR`, an assumption).
    calibration_factor : float, default 0
        c_1 of the material exposure.
    S_FFmin : float, default 1
        Minimum of S_FF = 1 / A_FF,max (agreed; the exposure 1 is the limit).
    points : int, default 25
        Contact points along the path.
    depths_per_decade : int, default 115
        Depths evaluated per decade of depth (every 2 %) below each point, from 1 µm.

    References
    ----------
    ISO/TS 6336-4:2019, clause 5; ISO 2639:2002.
    """

    case_depth: Any = None
    surface_hardness: Any = None
    core_hardness: Any = None
    hardness_profile: Any = None
    shear_strength_factor: float | None = None
    calibration_factor: float = 0.0
    S_FFmin: float = 1.0
    points: int = 25
    depths_per_decade: int = 115

    def __post_init__(self) -> None:
        for key in _PER_GEAR:
            value = getattr(self, key)
            if isinstance(value, Mapping):
                object.__setattr__(self, key, MappingProxyType({k: _number(v, f"{key}.{k}")
                                                                for k, v in value.items()}))
            elif value is not None:
                object.__setattr__(self, key, _number(value, key))
        for key, above in (("surface_hardness", True), ("core_hardness", False)):
            value = getattr(self, key)
            for v in (value.values() if isinstance(value, Mapping) else () if value is None else (value,)):
                if (v <= LIMIT_HARDNESS) if above else (v >= LIMIT_HARDNESS):
                    raise RatingError(f"rating.flank_fracture.{key} = {v:g} HV: the case hardness depth is defined "
                                      f"at 550 HV, so the {'surface' if above else 'core'} hardness must be "
                                      f"{'above' if above else 'below'} it (case-carburised gears: typically "
                                      "650-750 HV at the surface, 300-450 HV in the core).")
        prof = self.hardness_profile
        if prof is not None:
            if isinstance(prof, Mapping):
                object.__setattr__(self, "hardness_profile", MappingProxyType(
                    {k: HardnessProfile.measured(v) for k, v in prof.items()}))
            else:
                object.__setattr__(self, "hardness_profile", HardnessProfile.measured(prof))
        elif self.case_depth is None and self.surface_hardness is None:
            raise RatingError("rating.flank_fracture needs case_depth (CHD at 550 HV, mm), surface_hardness and "
                              "core_hardness (HV), or a measured hardness_profile; e.g. case_depth = 1.0, "
                              "surface_hardness = 700, core_hardness = 400.")
        if self.shear_strength_factor is not None:
            object.__setattr__(self, "shear_strength_factor", _number(self.shear_strength_factor,
                                                                      "shear_strength_factor"))
        object.__setattr__(self, "calibration_factor", _number(self.calibration_factor, "calibration_factor",
                                                               strict=False))
        object.__setattr__(self, "S_FFmin", _number(self.S_FFmin, "S_FFmin"))
        for key, low in (("points", 3), ("depths_per_decade", 20)):
            value = getattr(self, key)
            if isinstance(value, bool) or not isinstance(value, int) or not low <= value <= 2000:
                raise RatingError(f"rating.flank_fracture.{key} must be a whole number {low} ... 2000, got {value!r}.")

    @property
    def K_tau_per(self) -> float:
        """K_τ,per: given, else :data:`DEFAULT_SHEAR_STRENGTH_FACTOR`."""
        return self.shear_strength_factor if self.shear_strength_factor is not None else \
            DEFAULT_SHEAR_STRENGTH_FACTOR

    def profile_of(self, element: str, gear: str) -> HardnessProfile | None:
        """The :class:`HardnessProfile` of ``gear`` of ``element`` (``"P:ring"``, ``"ring"``, ``"all"``).

        None where neither a case depth nor a measured profile is given for the gear (it is not
        rated, e.g. a through-hardened or nitrided ring).

        Raises
        ------
        RatingError
            A case depth without a surface or core hardness (the message names the key and a
            typical value).
        """
        measured = _lookup(self.hardness_profile, element, gear)
        if measured is not None:
            return measured
        values = {key: _lookup(getattr(self, key), element, gear) for key in _PER_GEAR}
        if values["case_depth"] is None:
            return None
        typical = {"surface_hardness": "700 (HV, 60 HRC)", "core_hardness": "400 (HV)"}
        for key, value in values.items():
            if value is None:
                raise RatingError(f"rating.flank_fracture.{key} is missing for {element} {gear}: give it for all "
                                  f"gears or as {{ {gear} = ... }}, e.g. {typical[key]}; or a hardness_profile.")
        return HardnessProfile(values["surface_hardness"], values["core_hardness"], values["case_depth"])

    def to_dict(self) -> dict[str, Any]:
        """Plain data."""
        def plain(v):
            if isinstance(v, HardnessProfile):
                return [list(p) for p in v.points]
            return {k: plain(x) for k, x in v.items()} if isinstance(v, Mapping) else v
        out = {k: plain(getattr(self, k)) for k in (*_PER_GEAR, "hardness_profile")}
        out.update({"shear_strength_factor": self.shear_strength_factor, "K_tau_per": self.K_tau_per,
                    "calibration_factor": self.calibration_factor,
                    "S_FFmin": self.S_FFmin, "points": self.points, "depths_per_decade": self.depths_per_decade})
        return out
