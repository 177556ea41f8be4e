"""The lubricant in the tooth contact: viscosity, pressure-viscosity coefficient, EHL film thickness.

The properties ISO/TS 6336-22:2018 (and ISO/TR 15144-1:2014) Method B takes of the oil at the bulk
temperature θ_M and at the local contact temperature θ_B::

    ν_θ                     Walther / ASTM D341 through ν_40 and ν_100 (:class:`~epicyclic.losses.oil.Oil`)
    ρ_15 = 43.37 log10 ν_40 + 805.5          kg/m³, when not given        (ISO/TR 15144-1:2014, eq. (21))
    ρ_θ = ρ_15 (1 − 0.7 (θ + 273 − 289)/ρ_15)                                (eq. (20))
    η_θ = 10⁻⁶ ν_θ ρ_θ                        N·s/m²                       (eq. (16))
    α_38 = 2.657·10⁻⁸ η_38^0.1348  mineral,  1.466·10⁻⁸ η_38^0.0507  PAO,
           1.392·10⁻⁸ η_38^0.1572  PAG                      m²/N          (eqs. (9)–(11))
    α_θ = α_38 (1 + 516 (1/(θ + 273) − 1/311))                              (eq. (8))

and the film thickness of Dowson and Higginson in the form of the standard::

    h_Y = 1600 ρ_n,Y G_M^0.6 U_Y^0.7 W_Y^−0.13 S_GF,Y^0.22     µm, ρ in mm          (eq. (4))
    G_M = 10⁶ α_θM E_r,  U_Y = η_θM v_Σ,Y / (2000 E_r ρ_n,Y),  W_Y = 2π p_dyn,Y² / E_r²   (eqs. (5), (12), (22))
    S_GF,Y = α_θB,Y η_θB,Y / (α_θM η_θM)                                              (eq. (27))
    E_r = 2 / ((1 − ν1²)/E1 + (1 − ν2²)/E2)                                            (eq. (6))

(dimensionless groups of Dowson and Higginson: G = α E', U = η u/(E' R) with u = v_Σ/2 the mean
entraining velocity, W = w/(E' R) = 2π p²/E'²; h/R = 1.6 G^0.6 U^0.7 W^−0.13).

References
----------
Dowson, D.; Higginson, G. R.: *Elasto-hydrodynamic lubrication*, Pergamon (1966), the formula
h/R = 1.6 G^0.6 U^0.7 W^−0.13; ISO/TS 6336-22:2018, clause 7 (Method B film thickness); ISO/TR
15144-1:2014, eqs. (4)–(33) (equation numbers of that edition); ASTM D341-20.
"""

from __future__ import annotations

import math

import numpy as np

from ..losses.errors import LossModelError
from ..losses.oil import KELVIN, Oil, walther_constants
from .errors import RatingError
from .flank import elasticity_factor

__all__ = ["LUBRICANT_TYPES", "OilProperties", "film_thickness", "reduced_modulus"]

#: Base oils: (α_38 coefficient, exponent) of eqs. (9)–(11) and the lubricant factor X_L (ISO/TS 6336-22 Table 3,
#: the same as ISO/TR 13989-1 Table 1).
LUBRICANT_TYPES = {
    "mineral": (2.657e-8, 0.1348, 1.0),
    "pao": (1.466e-8, 0.0507, 0.8),
    "pag": (1.392e-8, 0.1572, 0.7),
    "pag_water_soluble": (1.392e-8, 0.1572, 0.6),
}


def reduced_modulus(E1: float, nu1: float, E2: float, nu2: float) -> float:
    """E_r = 2 / ((1 − ν1²)/E1 + (1 − ν2²)/E2) = 2π Z_E², N/mm² (Z_E of :func:`~.flank.elasticity_factor`).

    References
    ----------
    ISO/TS 6336-22:2018, eq. (6); ISO/TR 15144-1:2014, eq. (6).

    Examples
    --------
    >>> round(reduced_modulus(206000, 0.3, 206000, 0.3), 1)
    226373.6
    """
    return 2.0 * math.pi * elasticity_factor(E1, nu1, E2, nu2) ** 2


class OilProperties:
    """The oil's viscosity, density and pressure-viscosity coefficient at any temperature.

    Parameters
    ----------
    viscosity_40, viscosity_100 : float
        ν at 40 °C and 100 °C, mm²/s.
    lubricant_type : str, default "mineral"
        ``"mineral"``, ``"pao"``, ``"pag"`` or ``"pag_water_soluble"`` (α_38 and X_L).
    density : float, optional
        ρ_15, kg/m³ (default eq. (21) of ISO/TR 15144-1:2014).

    Raises
    ------
    RatingError
        A value missing or out of range (the key is named).

    References
    ----------
    ISO/TR 15144-1:2014, eqs. (8)–(11), (16), (20), (21); ASTM D341-20.

    Examples
    --------
    ISO VG 220: ρ_15 = 43.37 lg 220 + 805.5 = 907.1 kg/m³, η_40 = 220 · (907.1 − 0.7 · 24) · 10⁻⁶ N·s/m²:

    >>> oil = OilProperties(220.0, 19.0)
    >>> round(oil.density_15, 1), round(float(oil.dynamic_viscosity(40.0)) * 1e3, 1)  # kg/m³, mPa·s
    (907.1, 195.9)
    """

    def __init__(self, viscosity_40: float, viscosity_100: float, lubricant_type: str = "mineral",
                 density: float | None = None) -> None:
        if lubricant_type not in LUBRICANT_TYPES:
            raise RatingError(f"rating.micropitting.lubricant_type must be one of {', '.join(LUBRICANT_TYPES)}, "
                              f"got {lubricant_type!r}; the default is 'mineral'.")
        try:
            self.oil = Oil(viscosity_40, viscosity_100)
        except LossModelError as exc:  # the oil's own message names its key
            raise RatingError(f"rating.lubricant: {exc}") from None
        self.lubricant_type = lubricant_type
        self.density_15 = float(density) if density is not None else 43.37 * math.log10(viscosity_40) + 805.5
        if not 500.0 <= self.density_15 <= 2000.0:
            raise RatingError(f"rating.micropitting.density (ρ_15) must lie in 500 ... 2000 kg/m^3, got {density!r}.")
        c, e, x_l = LUBRICANT_TYPES[lubricant_type]
        self.lubricant_factor = x_l
        self.alpha_38 = c * float(self.dynamic_viscosity(38.0)) ** e

    def kinematic_viscosity(self, theta):
        """ν at θ (°C), mm²/s (Walther's line through ν_40 and ν_100, ASTM D341; also above 200 °C, where
        the contact temperatures of a loaded mesh lie)."""
        a, b = walther_constants(self.oil.viscosity_40, self.oil.viscosity_100)
        return 10.0 ** (10.0 ** (a - b * np.log10(np.asarray(theta, dtype=float) + KELVIN))) - 0.7

    def density(self, theta):
        """ρ_θ = ρ_15 (1 − 0.7 (θ + 273 − 289)/ρ_15), kg/m³ (ISO/TR 15144-1:2014, eq. (20))."""
        return self.density_15 * (1.0 - 0.7 * (np.asarray(theta, dtype=float) + 273.0 - 289.0) / self.density_15)

    def dynamic_viscosity(self, theta):
        """η_θ = 10⁻⁶ ν_θ ρ_θ, N·s/m² (ISO/TR 15144-1:2014, eq. (16))."""
        return 1e-6 * self.kinematic_viscosity(theta) * self.density(theta)

    def pressure_viscosity(self, theta):
        """α_θ = α_38 (1 + 516 (1/(θ + 273) − 1/311)), m²/N (ISO/TR 15144-1:2014, eq. (8))."""
        return self.alpha_38 * (1.0 + 516.0 * (1.0 / (np.asarray(theta, dtype=float) + 273.0) - 1.0 / 311.0))

    def __repr__(self) -> str:
        return (f"OilProperties(ν40 {self.oil.viscosity_40:g}, ν100 {self.oil.viscosity_100:g} mm^2/s, "
                f"{self.lubricant_type}, ρ15 {self.density_15:.1f} kg/m^3, α38 {self.alpha_38:.4g} m^2/N)")


def film_thickness(rho_n, G_M, U, W, S_GF=1.0):
    """h_Y = 1600 ρ_n G_M^0.6 U^0.7 W^−0.13 S_GF^0.22, µm (ρ_n in mm).

    Parameters
    ----------
    rho_n : float or array_like
        Normal relative radius of curvature, mm.
    G_M, U, W : float or array_like
        Material, velocity and load parameters (dimensionless).
    S_GF : float or array_like, default 1
        Local sliding parameter (1: isothermal contact at θ_M).

    Returns
    -------
    ndarray or float

    References
    ----------
    ISO/TS 6336-22:2018, eq. (4) (ISO/TR 15144-1:2014, eq. (4)); Dowson and Higginson (1966),
    h/R = 1.6 G^0.6 U^0.7 W^−0.13.

    Examples
    --------
    1600 · 10 · 5000^0.6 · (10⁻¹¹)^0.7 · (10⁻⁴)^−0.13 = 16000 · 165.7 · 1.995·10⁻⁸ · 3.311:

    >>> round(float(film_thickness(10.0, 5000.0, 1e-11, 1e-4)), 4)
    0.1752
    """
    with np.errstate(divide="ignore"):  # W = 0 (no load): an unbounded film, h = ∞
        return 1600.0 * np.asarray(rho_n, dtype=float) * np.asarray(G_M, dtype=float) ** 0.6 * \
            np.asarray(U, dtype=float) ** 0.7 * np.asarray(W, dtype=float) ** -0.13 * \
            np.asarray(S_GF, dtype=float) ** 0.22
