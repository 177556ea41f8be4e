"""Inputs of the scuffing rating: :class:`ScuffingSpec` (the file's ``[rating.scuffing]``).

======================  ==========================  =============================================
key                     default                     meaning
======================  ==========================  =============================================
load_stage              required (or a temperature) FZG A/8.3/90 failure load stage of the oil (1 … 12; 13, 14)
oil_temperature         required                    θ_oil, °C (sump or injection temperature)
roughness_Ra            required                    R_a of the flanks, µm (one, or per gear)
oil_type                ``"mineral"``               X_L (ISO/TR 13989-2, Table 1)
oil_density             880                         kg/m³ at 15 °C (η = ρ ν at θ_oil)
lubrication             ``"dip"``                   X_S: dip 1.0, spray 1.2, immersed 0.2
structural_factor       1.0                         X_W (X_WrelT = X_W / X_WT, X_WT = 1 for the test gears)
contact_coefficient     13.78                       B_M of steel, N/(mm s^½ K)
run_in                  1.0                         φ_E of X_E = 1 + (1 − φ_E) 30 R_a/ρ_redC (1 run in, 0 new)
driving                 none                        ``"gear1"``/``"gear2"`` for X_Q; without, X_Q = 1 (safe side)
multiple_meshing        from the set                X_mp = (1 + n_p)/2, n_p the meshes of the busiest gear
S_Smin / S_Bmin         1.8 / 2.0                   minimum safeties (integral / flash); to be agreed
edition                 ``"2017"``                  ``"2017"``, ``"2022"`` (ISO/TS 6336-20/-21) or ``"2000"`` (ISO/TR 13989)
integral_scuffing_temperature  from the load stage  θ_intS, °C, from the oil's own test
scuffing_temperature    from the load stage         θ_S, °C, from the oil's own test
======================  ==========================  =============================================

The minimum safeties are agreed between customer and supplier; 1.8 and 2.0 are the values
commercial tools propose.  The editions differ in clause numbering here; differences of their
formulas are not modelled (their texts were not reachable), so results of the editions agree.

References
----------
ISO/TS 6336-20:2017, ISO/TS 6336-21:2017 (and their 2022 revisions); ISO/TR 13989-1, -2:2000;
ISO 14635-1:2000 (FZG A/8.3/90).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

from ..errors import RatingError
from .factors import LUBRICANT_FACTORS, MAX_LOAD_STAGE

__all__ = ["EDITIONS", "LUBRICATION_FACTORS", "ScuffingSpec"]

#: Editions: year → (flash temperature method, integral temperature method).
EDITIONS = {"2017": ("ISO/TS 6336-20:2017", "ISO/TS 6336-21:2017"),
            "2022": ("ISO/TS 6336-20:2022", "ISO/TS 6336-21:2022"),
            "2000": ("ISO/TR 13989-1:2000", "ISO/TR 13989-2:2000")}
#: X_S by lubrication (ISO/TR 13989-1:2000; ISO/TS 6336-21:2017).
LUBRICATION_FACTORS = {"dip": 1.0, "spray": 1.2, "immersed": 0.2}


def _number(value, key: str, low: float = 0.0, high: float = math.inf) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or not (
            low < value <= high):
        bound = f"> {low:g}" + (f" and <= {high:g}" if math.isfinite(high) else "")
        raise RatingError(f"rating.scuffing.{key} must be a number {bound}, got {value!r}.")
    return float(value)


@dataclass(frozen=True)
class ScuffingSpec:
    """What the scuffing rating needs beyond the ISO 6336 inputs.

    Parameters
    ----------
    oil_temperature : float
        θ_oil, °C.  Required.
    roughness_Ra : float or mapping gear → float
        R_a of the flanks, µm (the mean of both gears is used).  Required.
    load_stage : int, optional
        FZG A/8.3/90 failure load stage (ISO 14635-1), 1 … 12.  Required unless both
        temperatures are given.
    oil_type : str, default "mineral"
    oil_density : float, default 880
        kg/m³ at 15 °C.
    lubrication : str, default "dip"
    structural_factor : float, default 1.0
    contact_coefficient : float, default 13.78
    run_in : float, default 1.0
        φ_E, the running-in state of the flanks (1 well run in, 0 new) for X_E.
    driving : str, optional
        ``"gear1"`` or ``"gear2"``: which gear of each mesh drives (for X_Q).
    multiple_meshing : float, optional
        X_mp given for every mesh.
    S_Smin, S_Bmin : float, default 1.8, 2.0
    edition : str, default "2017"
    integral_scuffing_temperature, scuffing_temperature : float, optional
        θ_intS and θ_S in °C from the oil's own test (instead of the FZG load stage).

    Raises
    ------
    RatingError
        A value of the wrong kind or out of range; neither a load stage nor the temperatures.

    References
    ----------
    ISO/TS 6336-20:2017 and ISO/TS 6336-21:2017 (inputs); ISO 14635-1:2000.
    """

    oil_temperature: float | None = None
    roughness_Ra: float | Mapping[str, float] | None = None
    load_stage: int | None = None
    oil_type: str = "mineral"
    oil_density: float = 880.0
    lubrication: str = "dip"
    structural_factor: float = 1.0
    contact_coefficient: float = 13.78
    run_in: float = 1.0
    driving: str | None = None
    multiple_meshing: float | None = None
    S_Smin: float = 1.8
    S_Bmin: float = 2.0
    edition: str = "2017"
    integral_scuffing_temperature: float | None = None
    scuffing_temperature: float | None = None

    def __post_init__(self) -> None:
        if self.oil_temperature is None:
            raise RatingError("rating.scuffing.oil_temperature is missing (θ_oil, °C, for the bulk temperature and "
                              "the oil's viscosity); give it - e.g. oil_temperature = 80.0, the value commonly taken.")
        object.__setattr__(self, "oil_temperature", _number(self.oil_temperature, "oil_temperature", -40.0, 200.0))
        ra = self.roughness_Ra
        if ra is None:
            raise RatingError("rating.scuffing.roughness_Ra is missing (R_a of the flanks in µm, for μ_m); give it - "
                              "e.g. roughness_Ra = 0.5 (ground), or per gear { sun = 0.5, ring = 1.0 }.")
        if isinstance(ra, Mapping):
            object.__setattr__(self, "roughness_Ra", MappingProxyType(
                {k: _number(v, f"roughness_Ra.{k}") for k, v in ra.items()}))
        else:
            object.__setattr__(self, "roughness_Ra", _number(ra, "roughness_Ra"))
        if self.load_stage is not None:
            s = self.load_stage
            if isinstance(s, bool) or not isinstance(s, int) or not 1 <= s <= MAX_LOAD_STAGE:
                raise RatingError(f"rating.scuffing.load_stage must be a whole FZG A/8.3/90 load stage 1 ... 12 "
                                  f"(ISO 14635-1; 13 and 14 extrapolate), got {s!r}; an oil that passes stage 12 is "
                                  "rated with 12 (on the safe side), or give the scuffing temperatures of its own test.")
        elif self.integral_scuffing_temperature is None or self.scuffing_temperature is None:
            raise RatingError("rating.scuffing.load_stage is missing (the oil's FZG A/8.3/90 failure load stage, "
                              "ISO 14635-1, from its data sheet); give it - e.g. load_stage = 12 - or both "
                              "integral_scuffing_temperature and scuffing_temperature.")
        for key in ("integral_scuffing_temperature", "scuffing_temperature"):
            if getattr(self, key) is not None:
                object.__setattr__(self, key, _number(getattr(self, key), key, self.oil_temperature, 1000.0))
        if self.oil_type not in LUBRICANT_FACTORS:
            raise RatingError(f"rating.scuffing.oil_type must be one of {', '.join(map(repr, LUBRICANT_FACTORS))}, "
                              f"got {self.oil_type!r}; the default is 'mineral'.")
        if self.lubrication not in LUBRICATION_FACTORS:
            raise RatingError(f"rating.scuffing.lubrication must be one of "
                              f"{', '.join(map(repr, LUBRICATION_FACTORS))}, got {self.lubrication!r}; the default "
                              "is 'dip'.")
        if self.driving not in (None, "gear1", "gear2"):
            raise RatingError(f"rating.scuffing.driving must be 'gear1' or 'gear2', got {self.driving!r}; without "
                              "it X_Q = 1 (on the safe side).")
        if str(self.edition) not in EDITIONS:
            raise RatingError(f"rating.scuffing.edition must be one of {', '.join(EDITIONS)}, got {self.edition!r}.")
        object.__setattr__(self, "edition", str(self.edition))
        object.__setattr__(self, "oil_density", _number(self.oil_density, "oil_density", 500.0, 2000.0))
        run_in = self.run_in
        if isinstance(run_in, bool) or not isinstance(run_in, (int, float)) or not 0.0 <= run_in <= 1.0:
            raise RatingError(f"rating.scuffing.run_in must be a number 0 ... 1 (φ_E: 1 well run in, 0 new flanks), "
                              f"got {run_in!r}; the default is 1.")
        object.__setattr__(self, "run_in", float(run_in))
        for key, high in (("structural_factor", 3.0), ("contact_coefficient", 100.0), ("S_Smin", 100.0),
                          ("S_Bmin", 100.0)):
            object.__setattr__(self, key, _number(getattr(self, key), key, 0.0, high))
        if self.multiple_meshing is not None:
            object.__setattr__(self, "multiple_meshing", _number(self.multiple_meshing, "multiple_meshing", 0.0, 10.0))

    @property
    def clauses(self) -> tuple[str, str]:
        """(flash method, integral method) of the edition, e.g. ``("ISO/TS 6336-20:2017", "ISO/TS 6336-21:2017")``."""
        return EDITIONS[self.edition]

    def roughness_of(self, element: str, gear: str) -> float:
        """R_a of ``gear`` of ``element``, µm (``"P1:ring"``, ``"ring"``, ``"all"``).

        Parameters
        ----------
        element : str
        gear : str

        Returns
        -------
        float

        Raises
        ------
        RatingError
            No entry for the gear.
        """
        from ..spec import _per_gear

        given = self.roughness_Ra
        if not isinstance(given, Mapping):
            return float(given)
        return _per_gear(given, "scuffing.roughness_Ra", element, gear, "0.5 (R_a, µm)")

    def to_dict(self) -> dict[str, Any]:
        """Plain data of the inputs."""
        ra = self.roughness_Ra
        return {"oil_temperature": self.oil_temperature, "roughness_Ra": dict(ra) if isinstance(ra, Mapping) else ra,
                "load_stage": self.load_stage, "oil_type": self.oil_type, "oil_density": self.oil_density,
                "lubrication": self.lubrication, "structural_factor": self.structural_factor,
                "contact_coefficient": self.contact_coefficient, "run_in": self.run_in,
                "driving": self.driving, "multiple_meshing": self.multiple_meshing, "S_Smin": self.S_Smin,
                "S_Bmin": self.S_Bmin, "edition": self.edition,
                "integral_scuffing_temperature": self.integral_scuffing_temperature,
                "scuffing_temperature": self.scuffing_temperature}
