"""Gear materials and their allowable stress numbers σ_Hlim, σ_Flim (ISO 6336-5).

The data file ``epicyclic/data/rating/materials.toml`` holds

* per material treatment (ISO 6336-5 symbols ``St``, ``St(cast)``, ``V``, ``V(cast)``,
  ``Eh``, ``NT``, ``NV``) the figure lines of ISO 6336-5 Table 1 as
  σ_lim = A · hardness + B per quality grade ML, MQ, ME and the hardness range
  they are drawn for;
* common steels (``18CrNiMo7-6``, ``16MnCr5``, ``42CrMo4``, ``31CrMoV9``,
  ``42CrMo4N``, ``G42CrMo4``, ``C45``) with a treatment, a typical hardness, E,
  Poisson's ratio, density and yield strength.

:func:`material` looks one up (quality MQ by default); a user's own σ_Hlim and
σ_Flim replace the figure lines.  A hardness outside the line's range gives a
:class:`~epicyclic.rating.errors.RatingWarning` naming ISO 6336-5 Table 1 and is
clamped to the range (no extrapolation).

References
----------
ISO 6336-5:2016, Table 1 and Figures 1–13 (σ_Hlim, σ_Flim per ML/MQ/ME);
ISO 6336-3:2006, Table 4 (slip-layer thickness ρ' for Y_δrelT).
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources
from typing import Any

from .errors import RatingError, warn_validity
from .hardness import SCALES, convert_hardness
from .life_factors import TREATMENTS

__all__ = ["DEFAULT_QUALITY", "QUALITIES", "Material", "allowable_stress_numbers", "material", "material_names"]

#: Material quality grades of ISO 6336-5 (low, medium, high demands on production and testing).
QUALITIES = ("ML", "MQ", "ME")
DEFAULT_QUALITY = "MQ"


@lru_cache(maxsize=1)
def _data() -> dict[str, Any]:
    text = resources.files("epicyclic").joinpath("data/rating/materials.toml").read_text(encoding="utf-8")
    return tomllib.loads(text)


def material_names() -> tuple[str, ...]:
    """The names of the materials in the data file.

    Returns
    -------
    tuple of str

    References
    ----------
    ISO 6336-5:2016, Table 1.

    Examples
    --------
    >>> "18CrNiMo7-6" in material_names()
    True
    """
    return tuple(_data()["material"])


def allowable_stress_numbers(treatment: str, hardness: float, quality: str = DEFAULT_QUALITY) -> tuple[float, float]:
    """(σ_Hlim, σ_Flim) in N/mm² of a treatment at ``hardness`` from the ISO 6336-5 figure lines.

    Parameters
    ----------
    treatment : str
        ISO 6336-5 symbol with a line in the data file (``St``, ``St(cast)``, ``V``, ``V(cast)``,
        ``Eh``, ``NT``, ``NV``).
    hardness : float
        Surface hardness in the line's unit (HB or HV, see the data file).
    quality : {"ML", "MQ", "ME"}
        Material quality grade.

    Returns
    -------
    tuple of float

    Raises
    ------
    RatingError
        No line for the treatment or quality.

    References
    ----------
    ISO 6336-5:2016, Table 1 (σ_lim = A x + B).

    Examples
    --------
    >>> allowable_stress_numbers("Eh", 700, "MQ")
    (1500.0, 425.0)
    >>> allowable_stress_numbers("St", 190, "ME")  # 1.520·190 + 250, 0.386·190 + 147
    (538.8, 220.34)
    """
    lines = _data()["treatment"].get(treatment)
    if lines is None:
        raise RatingError(f"material: no ISO 6336-5 line for treatment {treatment!r} in the data file; lines exist "
                          f"for {', '.join(_data()['treatment'])}; give sigma_Hlim and sigma_Flim instead.")
    if quality not in QUALITIES:
        raise RatingError(f"material: quality must be one of {', '.join(QUALITIES)}, got {quality!r} "
                          f"(default {DEFAULT_QUALITY!r}).")
    if quality not in lines["sigma_Hlim"]:
        raise RatingError(f"material: the data file has no {quality} line for {treatment!r} (only "
                          f"{', '.join(lines['sigma_Hlim'])}); give sigma_Hlim and sigma_Flim, or another quality.")
    low, high = lines.get("ranges", {}).get(quality, lines["range"])
    if not low <= hardness <= high:
        warn_validity(f"hardness {hardness:g} {lines['hardness_unit']} of {treatment!r} lies outside the figure "
                      f"line's range {low}-{high}; the line's end value is used.", "ISO 6336-5:2016, Table 1")
        hardness = min(max(hardness, low), high)
    a_h, b_h = lines["sigma_Hlim"][quality]
    a_f, b_f = lines["sigma_Flim"][quality]
    return round(a_h * hardness + b_h, 6), round(a_f * hardness + b_f, 6)


@dataclass(frozen=True)
class Material:
    """A gear material with its treatment and allowable stress numbers.

    Parameters
    ----------
    name : str
    treatment : str
        ISO 6336-5 symbol (:data:`~epicyclic.rating.life_factors.TREATMENTS`).
    sigma_Hlim, sigma_Flim : float
        Allowable stress numbers (contact, bending), N/mm².
    hardness : float
        Surface hardness in ``hardness_scale``, for Z_W (0: not given).
    E : float, default 206000
        Modulus of elasticity, N/mm².
    poisson : float, default 0.3
    density : float, default 7.83e-6
        kg/mm³ (for K_v).
    yield_strength : float, default 800
        σ_0.2 or σ_S, N/mm² (for the slip-layer thickness of Y_δrelT).
    quality : str, default "MQ"
    hardness_scale : {"HB", "HV", "HRC"}, optional
        The scale of ``hardness`` (a material of the data file: its line's).  Without one a factor
        that needs the hardness (Z_W) refuses, naming the key.

    References
    ----------
    ISO 6336-5:2016; ISO 6336-2:2019, 6.3 (Z_E from E and ν); ASTM E140-12b, Table 1 (scales).
    """

    name: str
    treatment: str
    sigma_Hlim: float
    sigma_Flim: float
    hardness: float = 0.0
    E: float = 206000.0
    poisson: float = 0.3
    density: float = 7.83e-6
    yield_strength: float = 800.0
    quality: str = DEFAULT_QUALITY
    hardness_scale: str | None = None

    def __post_init__(self) -> None:
        if self.hardness_scale is not None and self.hardness_scale not in SCALES:
            raise RatingError(f"material {self.name!r}: hardness_scale must be one of {', '.join(SCALES)}, got "
                              f"{self.hardness_scale!r}.")
        if self.treatment not in TREATMENTS:
            raise RatingError(f"material {self.name!r}: unknown treatment {self.treatment!r}; expected one of "
                              f"{', '.join(TREATMENTS)} (ISO 6336-5 symbols).")
        for key in ("sigma_Hlim", "sigma_Flim", "E", "density", "yield_strength"):
            value = getattr(self, key)
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0:
                raise RatingError(f"material {self.name!r}: {key} must be a positive number, got {value!r}.")
            object.__setattr__(self, key, float(value))
        if not 0.0 <= self.poisson < 0.5:
            raise RatingError(f"material {self.name!r}: poisson must lie in [0, 0.5), got {self.poisson!r}.")

    @property
    def surface_hardened(self) -> bool:
        """Case-carburised, nitrided, induction or flame hardened (for Z_W and K_Hα running-in)."""
        return self.treatment in ("Eh", "IF", "NT", "NV", "NV(nitrocar)")

    def hardness_in(self, scale: str) -> float:
        """The surface hardness in ``scale`` (converted by ASTM E140, Table 1, where given in another).

        Parameters
        ----------
        scale : {"HB", "HV", "HRC"}

        Returns
        -------
        float

        Raises
        ------
        RatingError
            No hardness or no scale given (the message names the key), or no conversion.

        References
        ----------
        ASTM E140-12b, Table 1.
        """
        where = f"material {self.name!r}"
        if not self.hardness > 0:
            raise RatingError(f"{where}: no hardness is given; the factor needs it in {scale}: give hardness and "
                              f"hardness_scale = {scale!r} in [rating.materials.{self.name}].")
        if self.hardness_scale is None:
            raise RatingError(f"{where}: hardness {self.hardness:g} has no scale; give hardness_scale = 'HB', "
                              f"'HV' or 'HRC' in [rating.materials.{self.name}] (the factor takes {scale}).")
        return convert_hardness(self.hardness, self.hardness_scale, scale, key=f"{where}: hardness")

    def to_dict(self) -> dict[str, Any]:
        """Plain data (N/mm², kg/mm³)."""
        return {"name": self.name, "treatment": self.treatment, "quality": self.quality, "hardness": self.hardness,
                "hardness_scale": self.hardness_scale,
                "sigma_Hlim": self.sigma_Hlim, "sigma_Flim": self.sigma_Flim, "E": self.E, "poisson": self.poisson,
                "density": self.density, "yield_strength": self.yield_strength}


def material(name: str, *, quality: str = DEFAULT_QUALITY, hardness: float | None = None,
             sigma_Hlim: float | None = None, sigma_Flim: float | None = None) -> Material:
    """A material of the data file, its σ_Hlim/σ_Flim from the ISO 6336-5 line or given.

    Parameters
    ----------
    name : str
        A name of :func:`material_names`.
    quality : {"ML", "MQ", "ME"}, default "MQ"
    hardness : float, optional
        Surface hardness (default the file's typical value).
    sigma_Hlim, sigma_Flim : float, optional
        The user's values, N/mm² (replace the line's).

    Returns
    -------
    Material

    Raises
    ------
    RatingError
        Unknown name (the message lists the known ones), unknown quality.

    References
    ----------
    ISO 6336-5:2016, Table 1.

    Examples
    --------
    >>> m = material("18CrNiMo7-6")
    >>> m.treatment, m.sigma_Hlim, m.sigma_Flim
    ('Eh', 1500.0, 425.0)
    """
    entry = _data()["material"].get(name)
    if entry is None:
        raise RatingError(f"material: unknown material {name!r}; the data file has {', '.join(material_names())} "
                          "(or give treatment, sigma_Hlim and sigma_Flim).")
    hb = entry["hardness"] if hardness is None else hardness
    if sigma_Hlim is None or sigma_Flim is None:
        h, f = allowable_stress_numbers(entry["treatment"], hb, quality)
        sigma_Hlim = h if sigma_Hlim is None else sigma_Hlim
        sigma_Flim = f if sigma_Flim is None else sigma_Flim
    return Material(name, entry["treatment"], sigma_Hlim, sigma_Flim, hb, entry["E"], entry["poisson"],
                    entry["density"], entry["yield_strength"], quality,
                    _data()["treatment"].get(entry["treatment"], {}).get("hardness_unit"))
