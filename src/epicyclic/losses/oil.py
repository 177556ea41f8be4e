"""The oil: kinematic viscosity at any temperature (ASTM D341, Walther), density and thermal data.

Given by ν at 40 and 100 °C (:class:`Oil`) or by a table of measured viscosities
(:meth:`Oil.from_table`, the least-squares Walther line).

Walther's equation, standardised in ASTM D341, is a straight line through two
measured viscosities on the doubly logarithmic chart:

.. math::

    \\log_{10}\\log_{10}(\\nu + 0.7) = A - B \\log_{10} T

with ν in mm²/s (cSt) and T in kelvin; A and B follow from ν at 40 °C and
100 °C (the two values every data sheet gives, ISO 3104).  Valid for mineral
and most synthetic oils from the cloud point up to the onset of thermal
decomposition, for ν ≥ 2 mm²/s (ASTM D341; the 0.7 constant is the one for
that range).  The density falls linearly with temperature,
ρ(T) = ρ_15 (1 − α (T − 15 °C)), α ≈ 6.5·10⁻⁴ 1/K for mineral oils (DIN
51757 / ASTM D1250 give tabulated values of this order); the dynamic
viscosity is η = ρ ν.

References
----------
ASTM D341-20, *Standard Practice for Viscosity-Temperature Equations and Charts for Liquid
Petroleum or Hydrocarbon Products*, eq. (1) with Z = ν + 0.7;
Walther, C.: *Über die Auswertung von Viskositätsangaben*, Erdöl und Teer 7 (1931) 382–384;
DIN 51757:2011 (density of mineral oils and its temperature dependence).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..limits import OIL_TEMPERATURE_RANGE
from ._checks import positive
from .errors import LossModelError
from .friction import Lubricant

__all__ = ["Oil", "KELVIN", "EXTRAPOLATION_MARGIN", "OIL_WARNING_START", "walther_constants"]

#: 0 °C in kelvin.
KELVIN = 273.15
#: Walther's constant for ν ≥ 2 mm²/s (ASTM D341).
_WALTHER_SHIFT = 0.7
#: Temperatures (°C) the viscosity may be asked at: the equation's useful range for gear oils.
TEMPERATURE_RANGE = OIL_TEMPERATURE_RANGE
#: How far beyond its measured temperatures an oil's viscosity is used without a warning, K.
EXTRAPOLATION_MARGIN = 20.0
#: How :meth:`Oil.extrapolation_warning` begins (reports collect the oil's warnings by it).
OIL_WARNING_START = "the oil temperature"


def walther_constants(viscosity_40: float, viscosity_100: float) -> tuple[float, float]:
    """A and B of Walther's equation through ν(40 °C) and ν(100 °C), mm²/s.

    Parameters
    ----------
    viscosity_40, viscosity_100 : float
        Kinematic viscosities at 40 °C and 100 °C, mm²/s (ν_40 > ν_100 ≥ 2).

    Returns
    -------
    tuple of float
        (A, B) with log10 log10(ν + 0.7) = A − B log10(T / K).

    References
    ----------
    ASTM D341-20, eq. (1).
    """
    z1 = math.log10(math.log10(viscosity_40 + _WALTHER_SHIFT))
    z2 = math.log10(math.log10(viscosity_100 + _WALTHER_SHIFT))
    t1, t2 = math.log10(40.0 + KELVIN), math.log10(100.0 + KELVIN)
    b = (z1 - z2) / (t2 - t1)
    return z1 + b * t1, b


@dataclass(frozen=True)
class Oil:
    """A lubricant given by its data sheet: ν at 40 and 100 °C, density, thermal data.

    Parameters
    ----------
    viscosity_40, viscosity_100 : float
        Kinematic viscosity at 40 °C and at 100 °C, mm²/s (ν_40 > ν_100 ≥ 2).
    density : float, default 860
        Density at 15 °C, kg/m³ (ATF and mineral gear oils: 840–880).
    expansion : float, default 6.5e-4
        α of ρ(T) = ρ_15 (1 − α (T − 15)), 1/K.
    specific_heat : float, default 2000
        c_p, J/(kg K) (mineral oils 1900–2100 at 80 °C).
    lubricant_factor : float, default 1.0
        X_L of Schlenk's mesh friction (1 for mineral oil).
    data_range : (float, float), default (40, 100)
        The temperatures, °C, the viscosities were measured at (a table's coldest and hottest); beyond
        them by more than :data:`EXTRAPOLATION_MARGIN` the viscosity is an extrapolation, and
        :meth:`extrapolation_warning` says so.

    Examples
    --------
    >>> oil = Oil(46.0, 6.8)
    >>> round(float(oil.kinematic_viscosity(40.0)), 6), round(float(oil.kinematic_viscosity(100.0)), 6)
    (46.0, 6.8)
    >>> round(float(oil.dynamic_viscosity(80.0)), 2)  # mPa·s
    9.14
    """

    viscosity_40: float
    viscosity_100: float
    density: float = 860.0
    expansion: float = 6.5e-4
    specific_heat: float = 2000.0
    lubricant_factor: float = 1.0
    data_range: tuple[float, float] = (40.0, 100.0)

    def __post_init__(self) -> None:
        owner = "Oil"
        v40 = positive(self.viscosity_40, "viscosity_40 (mm^2/s at 40 degC)", owner)
        v100 = positive(self.viscosity_100, "viscosity_100 (mm^2/s at 100 degC)", owner)
        if v100 < 2.0:
            raise LossModelError(f"{owner}: viscosity_100 must be >= 2 mm^2/s (ASTM D341's range), got {v100!r}.")
        if not v40 > v100:
            raise LossModelError(f"{owner}: viscosity_40 must exceed viscosity_100 (oil thins when warm), "
                                 f"got {v40!r} and {v100!r}.")
        density = positive(self.density, "density (kg/m^3 at 15 degC)", owner)
        if not 500.0 <= density <= 2000.0:
            raise LossModelError(f"{owner}: density must lie in 500 ... 2000 kg/m^3, got {density!r}.")
        expansion = positive(self.expansion, "expansion (1/K)", owner, allow_zero=True)
        if expansion > 2e-3:
            raise LossModelError(f"{owner}: expansion must be at most 2e-3 1/K (oils: 6e-4 ... 8e-4), "
                                 f"got {expansion!r}.")
        for name, value in (("viscosity_40", v40), ("viscosity_100", v100), ("density", density),
                            ("expansion", expansion),
                            ("specific_heat", positive(self.specific_heat, "specific_heat (J/(kg K))", owner)),
                            ("lubricant_factor", positive(self.lubricant_factor, "lubricant_factor (X_L)", owner))):
            object.__setattr__(self, name, value)
        try:
            low, high = (float(t) for t in self.data_range)
        except (TypeError, ValueError):
            low = high = math.nan
        if not (TEMPERATURE_RANGE[0] <= low <= high <= TEMPERATURE_RANGE[1]):
            raise LossModelError(f"{owner}: data_range must be (coldest, hottest) measured temperatures in "
                                 f"{TEMPERATURE_RANGE[0]:g} ... {TEMPERATURE_RANGE[1]:g} degC, got {self.data_range!r}.")
        object.__setattr__(self, "data_range", (low, high))

    @classmethod
    def from_table(cls, table, **kwargs) -> Oil:
        """The oil whose Walther line fits a table of measured viscosities (least squares, ASTM D341).

        Parameters
        ----------
        table : sequence of (temperature °C, ν mm²/s)
            At least two points at different temperatures, ν ≥ 2 mm²/s.
        **kwargs
            ``density``, ``expansion``, ``specific_heat``, ``lubricant_factor`` as for :class:`Oil`.

        Returns
        -------
        Oil
            With ``viscosity_40`` and ``viscosity_100`` on the fitted line (through both points of a
            two-point table).

        Raises
        ------
        LossModelError
            Fewer than two temperatures, a viscosity below 2 mm²/s, or one that rises with temperature.

        References
        ----------
        ASTM D341-20 (the line log log(ν + 0.7) = A − B log T through measured points).

        Examples
        --------
        >>> oil = Oil.from_table([(0.0, 580.0), (40.0, 46.0), (100.0, 6.8)])
        >>> round(oil.viscosity_40, 2), round(oil.viscosity_100, 3)  # Tellus S2 M 46's three points
        (46.05, 6.798)
        """
        try:
            points = [(float(t), float(v)) for t, v in table]
        except (TypeError, ValueError):
            raise LossModelError(f"Oil: the viscosity table must be pairs [temperature degC, mm^2/s], got "
                                 f"{table!r}.") from None
        if len({t for t, _ in points}) < 2:
            raise LossModelError("Oil: the viscosity table needs at least two different temperatures.")
        for t, v in points:
            if not (math.isfinite(t) and TEMPERATURE_RANGE[0] <= t <= TEMPERATURE_RANGE[1]):
                raise LossModelError(f"Oil: a table temperature must lie in {TEMPERATURE_RANGE[0]:g} ... "
                                     f"{TEMPERATURE_RANGE[1]:g} degC, got {t!r}.")
            if not (math.isfinite(v) and v >= 2.0):
                raise LossModelError(f"Oil: a table viscosity must be >= 2 mm^2/s (ASTM D341's range), got {v!r}.")
        x = np.array([math.log10(t + KELVIN) for t, _ in points])
        z = np.array([math.log10(math.log10(v + _WALTHER_SHIFT)) for _, v in points])
        slope, intercept = np.polyfit(x, z, 1)
        if slope >= 0:
            raise LossModelError("Oil: the table's viscosity must fall with temperature.")

        def at(celsius: float) -> float:
            return 10.0 ** (10.0 ** (intercept + slope * math.log10(celsius + KELVIN))) - _WALTHER_SHIFT

        temperatures = [t for t, _ in points]
        return cls(at(40.0), at(100.0), **kwargs, data_range=(min(temperatures), max(temperatures)))

    def extrapolation_warning(self, temperature: float) -> str | None:
        """A warning where ``temperature`` (°C) lies more than :data:`EXTRAPOLATION_MARGIN` beyond the data.

        Walther's line (ASTM D341) is a fit of the measured points; far outside them (a cold start at
        −20 °C from ν at 40 and 100 °C) the viscosity, and every drag and churning loss that follows
        from it, is an extrapolation of unknown error.

        Parameters
        ----------
        temperature : float
            °C.

        Returns
        -------
        str or None
        """
        low, high = self.data_range
        if low - EXTRAPOLATION_MARGIN <= temperature <= high + EXTRAPOLATION_MARGIN:
            return None
        nu = float(self.kinematic_viscosity(temperature))
        return (f"{OIL_WARNING_START} {temperature:.4g} degC lies outside the lubricant's viscosity data "
                f"({low:g} ... {high:g} degC) by more than {EXTRAPOLATION_MARGIN:g} K: its viscosity "
                f"{nu:.4g} mm^2/s is extrapolated by ASTM D341 (Walther), and so are the losses that follow "
                "from it; give [lubricant] viscosity_table with a point near that temperature")

    def _temperature(self, temperature) -> np.ndarray:
        t = np.asarray(temperature, dtype=float)
        low, high = TEMPERATURE_RANGE
        if not np.all(np.isfinite(t)) or np.any(t < low) or np.any(t > high):
            bad = t[~(np.isfinite(t) & (t >= low) & (t <= high))].ravel()[0]
            raise LossModelError(f"Oil: the temperature must lie in {low:g} ... {high:g} degC, got {float(bad)!r}.")
        return t

    def kinematic_viscosity(self, temperature):
        """ν at ``temperature`` (°C; float or array), mm²/s, by Walther's equation (ASTM D341).

        Parameters
        ----------
        temperature : float or array_like
            Oil temperature, °C (−40 … 200).

        Returns
        -------
        ndarray or float
            ν, mm²/s.

        References
        ----------
        ASTM D341-20, eq. (1): log10 log10(ν + 0.7) = A − B log10 T.
        """
        a, b = walther_constants(self.viscosity_40, self.viscosity_100)
        t = self._temperature(temperature)
        return 10.0 ** (10.0 ** (a - b * np.log10(t + KELVIN))) - _WALTHER_SHIFT

    def density_at(self, temperature):
        """ρ at ``temperature`` (°C), kg/m³: ρ_15 (1 − α (T − 15)).

        Parameters
        ----------
        temperature : float or array_like
            °C.

        Returns
        -------
        ndarray or float
            kg/m³.
        """
        return self.density * (1.0 - self.expansion * (self._temperature(temperature) - 15.0))

    def dynamic_viscosity(self, temperature):
        """η = ρ ν at ``temperature`` (°C), mPa·s.

        Parameters
        ----------
        temperature : float or array_like
            °C.

        Returns
        -------
        ndarray or float
            mPa·s (ν in mm²/s times ρ in g/cm³).
        """
        return self.kinematic_viscosity(temperature) * self.density_at(temperature) * 1e-3

    def lubricant(self, temperature: float) -> Lubricant:
        """The :class:`~epicyclic.losses.friction.Lubricant` (η at ``temperature``) for Schlenk's friction.

        Parameters
        ----------
        temperature : float
            °C.

        Returns
        -------
        Lubricant
        """
        return Lubricant(float(self.dynamic_viscosity(float(temperature))), self.lubricant_factor)
