"""The mean coefficient of friction μ_m of a gear mesh: given, or from Schlenk's correlation.

Schlenk's correlation (FZG, adopted in ISO/TR 14179-2) for the mean coefficient
of friction of a mesh:

.. math::

    \\mu_{mZ} = 0.048 \\left(\\frac{F_{bt}/b}{v_{\\Sigma C}\\,\\rho_C}\\right)^{0.2}
                \\eta_{oil}^{-0.05}\\, R_a^{0.25}\\, X_L

with F_bt/b the transverse base-circle load per face width (N/mm), v_ΣC the sum
of the rolling speeds at the pitch point (m/s, v_ΣC = 2 v_t sin α_wt), ρ_C the
normal radius of relative curvature at the pitch point (mm), η_oil the dynamic
viscosity at the operating temperature (mPa·s), R_a the arithmetic mean
roughness of both flanks (µm) and X_L the lubricant factor (1 for mineral oil).

μ rises with the load and falls with speed.  At standstill the correlation
diverges (v_ΣC^−0.2); it is evaluated at no less than
:data:`MINIMUM_SUM_VELOCITY` (0.1 m/s), where μ is about twice its value at
5 m/s — there the sliding speed, and so the loss, vanish anyway.

References
----------
Schlenk, L.: *Untersuchungen zur Fresstragfähigkeit von Großzahnrädern*, Diss. TU München (1994);
ISO/TR 14179-2:2001, *Gears — Thermal capacity — Part 2: Thermal load-carrying capacity*
(mean coefficient of friction μ_mZ); Fernandes, Martins, Seabra 2014,
*Torque loss of type C40 FZG gears lubricated with wind turbine gear oils*, Tribol. Int. 70, eq. (7).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import LossModelError

__all__ = ["Lubricant", "ConstantFriction", "SchlenkFriction", "schlenk_friction", "MINIMUM_SUM_VELOCITY"]

#: Sum velocities (m/s) below this are evaluated at this value (the correlation diverges at standstill).
MINIMUM_SUM_VELOCITY = 0.1


def _positive(value: object, name: str, owner: str, allow_zero: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or value < 0 or (value == 0 and not allow_zero):
        raise LossModelError(
            f"{owner}: {name} must be a {'non-negative' if allow_zero else 'positive'} number, got {value!r}."
        )
    return float(value)


def _positive_array(value: object, name: str, allow_negative: bool = False) -> np.ndarray:
    """``value`` (a number or an array) as floats, each finite and > 0 (any number with ``allow_negative``)."""
    if isinstance(value, (bool, str, bytes)):
        raise LossModelError(f"schlenk_friction: {name} must be a number, got {value!r}.")
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise LossModelError(f"schlenk_friction: {name} must be a number or an array of numbers, "
                             f"got {value!r:.80}.") from None
    if allow_negative:
        return array
    ok = np.isfinite(array) & (array > 0)
    if not np.all(ok):
        raise LossModelError(f"schlenk_friction: {name} must be a positive finite number, "
                             f"got {float(array[~ok].ravel()[0])!r}.")
    return array


@dataclass(frozen=True)
class Lubricant:
    """The oil at its operating temperature.

    Parameters
    ----------
    viscosity : float
        Dynamic viscosity η_oil at the operating temperature, mPa·s.
    lubricant_factor : float, default 1.0
        X_L of Schlenk's correlation (1.0 for mineral oil; lower for
        friction-reducing synthetic oils).

    Examples
    --------
    >>> Lubricant(49.85, 0.65)
    Lubricant(viscosity=49.85, lubricant_factor=0.65)
    """

    viscosity: float
    lubricant_factor: float = 1.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "viscosity", _positive(self.viscosity, "viscosity (mPa*s)", "Lubricant"))
        object.__setattr__(self, "lubricant_factor",
                           _positive(self.lubricant_factor, "lubricant_factor (X_L)", "Lubricant"))


def schlenk_friction(load_per_width, sum_velocity, radius, viscosity: float, roughness: float,
                     lubricant_factor: float = 1.0):
    """Schlenk's mean coefficient of friction μ_mZ (floats or arrays).

    Parameters
    ----------
    load_per_width : float or ndarray
        F_bt/b, N/mm (≥ 0).
    sum_velocity : float or ndarray
        v_ΣC, m/s (values below 0.1 m/s are taken as 0.1 m/s).
    radius : float
        ρ_C, normal radius of relative curvature at the pitch point, mm.
    viscosity : float
        η_oil, mPa·s.
    roughness : float
        R_a, µm (mean of both flanks).
    lubricant_factor : float, default 1.0
        X_L.

    Examples
    --------
    FZG type C40 gear, P320 oil at 80 °C (η = 49.85 mPa·s, X_L = 0.65), R_a = (0.4 + 0.31)/2 µm,
    215.5 N·m at 1800 1/min: F_bt/b = 6370.3/40 N/mm, v_ΣC = 5.2666 m/s, ρ_C = 8.382 mm;
    GEARpie prints μ_mZ = 0.0256 (report C40):

    >>> round(schlenk_friction(6370.3 / 40, 5.2666, 8.382, 49.85, 0.355, 0.65), 4)
    0.0256

    Raises
    ------
    LossModelError
        ``radius``, ``viscosity``, ``roughness`` or ``lubricant_factor`` not a positive finite number
        (the correlation divides by ρ_C and raises η_oil to −0.05), or a load or speed that is not a number.

    References
    ----------
    Schlenk 1994; ISO/TR 14179-2:2001 (μ_mZ).
    """
    for name, value in (("radius", radius), ("viscosity", viscosity), ("roughness", roughness),
                        ("lubricant_factor", lubricant_factor)):
        _positive_array(value, name)
    for name, value in (("load_per_width", load_per_width), ("sum_velocity", sum_velocity)):
        _positive_array(value, name, allow_negative=True)  # numbers (a NaN gives a NaN μ, refused by the mesh)
    v = np.maximum(np.asarray(sum_velocity, dtype=float), MINIMUM_SUM_VELOCITY)
    w = np.maximum(np.asarray(load_per_width, dtype=float), 0.0)
    mu = 0.048 * (w / (v * radius)) ** 0.2 * viscosity ** -0.05 * roughness ** 0.25 * lubricant_factor
    return float(mu) if mu.ndim == 0 else mu


@dataclass(frozen=True)
class ConstantFriction:
    """A given mean coefficient of friction μ_m (same at every load and speed).

    >>> ConstantFriction(0.05).coefficient(np.array([1.0, 2.0]), 3.0, 4.0).tolist()
    [0.05, 0.05]
    """

    value: float

    def __post_init__(self) -> None:
        value = _positive(self.value, "friction coefficient mu", "ConstantFriction", allow_zero=True)
        if value >= 1.0:
            raise LossModelError(f"ConstantFriction: a gear mesh friction coefficient is below 1 "
                                 f"(typically 0.03-0.08), got {value!r}.")
        object.__setattr__(self, "value", value)

    def coefficient(self, load_per_width, sum_velocity, radius):
        """μ_m, broadcast to the shape of ``load_per_width``.

        Parameters
        ----------
        load_per_width : float or numpy.ndarray
            F_bt/b, N/mm (only its shape is used).
        sum_velocity : float or numpy.ndarray
            v_ΣC, m/s (not used).
        radius : float
            ρ_C, mm (not used).

        Returns
        -------
        numpy.ndarray
            The constant μ_m at every point.
        """
        return np.full(np.shape(load_per_width), self.value)

    @property
    def label(self) -> str:
        return f"mu = {self.value:g}"


@dataclass(frozen=True)
class SchlenkFriction:
    """μ_m from Schlenk's correlation (ISO/TR 14179-2) for a lubricant and a flank roughness.

    Parameters
    ----------
    lubricant : Lubricant
    roughness : float
        R_a, arithmetic mean roughness of both flanks, µm.
    """

    lubricant: Lubricant
    roughness: float

    def __post_init__(self) -> None:
        if not isinstance(self.lubricant, Lubricant):
            raise LossModelError(f"SchlenkFriction: lubricant must be a Lubricant, got {self.lubricant!r}.")
        object.__setattr__(self, "roughness", _positive(self.roughness, "roughness Ra (um)", "SchlenkFriction"))

    def coefficient(self, load_per_width, sum_velocity, radius):
        """μ_mZ from the load per face width (N/mm), sum velocity (m/s) and radius of curvature (mm).

        Schlenk's correlation with this model's lubricant (viscosity, lubricant factor)
        and roughness: :func:`schlenk_friction`.

        Parameters
        ----------
        load_per_width : float or numpy.ndarray
            F_bt/b, transverse tangential load at the base circle per face width, N/mm.
        sum_velocity : float or numpy.ndarray
            v_ΣC, the sum of the tangential velocities at the pitch point, m/s.
        radius : float or numpy.ndarray
            ρ_C, the relative radius of curvature at the pitch point, mm.

        Returns
        -------
        numpy.ndarray or float
            μ_mZ, of the broadcast shape.

        References
        ----------
        Schlenk 1994; ISO/TR 14179-2:2001 (mean coefficient of friction μ_mZ).
        """
        lub = self.lubricant
        viscosity = self.__dict__.get("_viscosity", lub.viscosity)  # one per point: at_viscosity
        return schlenk_friction(load_per_width, sum_velocity, radius, viscosity, self.roughness,
                                lub.lubricant_factor)

    def at_viscosity(self, viscosity) -> SchlenkFriction:
        """This model with the oil's dynamic viscosity replaced (mPa·s; a float or one per point).

        Parameters
        ----------
        viscosity : float or ndarray
            η_oil at the oil temperature, mPa·s (> 0).

        Returns
        -------
        SchlenkFriction
            A model whose :meth:`coefficient` uses ``viscosity`` (arrays broadcast with the loads).
        """
        eta = np.asarray(viscosity, dtype=float)
        if not np.all(np.isfinite(eta) & (eta > 0)):
            raise LossModelError(f"SchlenkFriction: viscosity must be positive mPa*s values, got {viscosity!r}.")
        model = SchlenkFriction(Lubricant(float(np.mean(eta)), self.lubricant.lubricant_factor), self.roughness)
        object.__setattr__(model, "_viscosity", eta)
        return model

    @property
    def label(self) -> str:
        return (f"Schlenk (eta_oil = {self.lubricant.viscosity:g} mPa*s, X_L = {self.lubricant.lubricant_factor:g}, "
                f"Ra = {self.roughness:g} um)")
