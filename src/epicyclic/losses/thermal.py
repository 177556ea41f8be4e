"""Thermal balance of a transmission housing (ISO/TR 14179-1): the steady sump temperature.

In steady state the losses P_V heat the oil as fast as the housing and an
optional oil cooler carry the heat away (ISO/TR 14179-1, P_V = P_Q):

.. math::

    P_Q(\\vartheta) = A \\left[h_c (\\vartheta - \\vartheta_a)
                      + \\varepsilon \\sigma (T^4 - T_a^4)\\right] + k_{cool} (\\vartheta - \\vartheta_c)

with A the housing's outer surface, h_c the convection coefficient — given, or
for still air the laminar natural convection of a vertical wall of height L,
h_c = 1.32 (Δϑ / L)^{1/4} W/(m² K) (McAdams 1954) — ε the emissivity (0.9 for
a painted or cast surface), σ Stefan–Boltzmann's constant, and k_cool the
cooler's heat transfer W/K to coolant at ϑ_c.  P_Q rises monotonically with
the sump temperature ϑ, so P_Q(ϑ) = P_V has one root; since the spin losses
fall with temperature (the oil thins), the balance P_Q(ϑ) = P_V(ϑ) has one
root too, found by bracketed regula falsi (Illinois rule, :func:`steady_temperature`),
vectorised over operating points.

Validity: a housing in still or moving air with its whole surface at the sump
temperature (ISO/TR 14179-1's assumption; a real housing is cooler far from the
sump, so the method gives an upper bound of ϑ for a given area); no heat
flows through the mounting flanges or shafts.

References
----------
ISO/TR 14179-1:2001, *Gears — Thermal capacity — Part 1: Rating gear drives with thermal
equilibrium at 95 °C sump temperature* (heat balance P_V = P_Q; convection, radiation, cooler);
McAdams, W. H.: *Heat Transmission*, 3rd ed., McGraw-Hill 1954, table 7-2 (h = 1.32 (Δt/L)^0.25, air);
Incropera, F. P., DeWitt, D. P.: *Fundamentals of Heat and Mass Transfer*, 6th ed. (2007),
eq. (1.7) (radiation ε σ (T⁴ − T_sur⁴)).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..limits import OIL_TEMPERATURE_RANGE
from ._checks import fraction, positive
from .errors import LossModelError
from .oil import KELVIN

__all__ = ["Housing", "steady_temperature", "STEFAN_BOLTZMANN", "MAX_SUMP_TEMPERATURE", "ITERATIONS", "TOLERANCE"]

#: σ, W/(m² K⁴).
STEFAN_BOLTZMANN = 5.670374419e-8
#: Highest sump temperature searched, °C: hotter than any oil survives.
MAX_SUMP_TEMPERATURE = OIL_TEMPERATURE_RANGE[1]
#: Most steps of the temperature search (regula falsi, Illinois rule; each step at least halves the
#: bracket's stale side, so 100 steps are far more than the tolerance needs).
ITERATIONS = 100
#: Width of the temperature bracket at which the search stops, K.
TOLERANCE = 1e-10


@dataclass(frozen=True)
class Housing:
    """The heat paths of a transmission housing.

    Parameters
    ----------
    area : float
        Outer surface A, m².
    ambient : float, default 20
        Air temperature ϑ_a, °C.
    heat_transfer : float or None, default None
        Convection coefficient h_c, W/(m² K); None: natural convection 1.32 (Δϑ/L)^0.25.
    height : float, default 0.3
        L of the natural-convection formula, m.
    emissivity : float, default 0.9
        ε, [0, 1] (0: a housing that only convects).
    cooler : float, default 0
        k_cool, W/K (0: no cooler).
    coolant : float or None, default None
        ϑ_c, °C (None: the ambient temperature).

    Examples
    --------
    >>> round(float(Housing(0.5).dissipated(80.0)), 1)  # W at 80 °C sump, 20 °C air
    357.4
    """

    area: float
    ambient: float = 20.0
    heat_transfer: float | None = None
    height: float = 0.3
    emissivity: float = 0.9
    cooler: float = 0.0
    coolant: float | None = None

    def __post_init__(self) -> None:
        owner = "housing"
        object.__setattr__(self, "area", positive(self.area, "area (m^2)", owner))
        ambient = self.ambient
        if isinstance(ambient, bool) or not isinstance(ambient, (int, float)) or not -40.0 <= ambient <= 80.0:
            raise LossModelError(f"{owner}: ambient must be an air temperature in -40 ... 80 degC, got {ambient!r}.")
        object.__setattr__(self, "ambient", float(ambient))
        if self.heat_transfer is not None:
            object.__setattr__(self, "heat_transfer",
                               positive(self.heat_transfer, "heat_transfer (W/(m^2 K))", owner))
        object.__setattr__(self, "height", positive(self.height, "height (m)", owner))
        object.__setattr__(self, "emissivity", fraction(self.emissivity, "emissivity", owner, allow_zero=True))
        object.__setattr__(self, "cooler", positive(self.cooler, "cooler (W/K)", owner, allow_zero=True))
        if self.coolant is not None:
            coolant = self.coolant
            if isinstance(coolant, bool) or not isinstance(coolant, (int, float)) or not -40.0 <= coolant <= 150.0:
                raise LossModelError(f"{owner}: coolant must be a temperature in -40 ... 150 degC, got {coolant!r}.")
            object.__setattr__(self, "coolant", float(coolant))

    def convection(self, temperature):
        """h_c at sump temperature ``temperature`` (°C), W/(m² K).

        Parameters
        ----------
        temperature : float or array_like
            °C.

        Returns
        -------
        ndarray
            The given h_c, or 1.32 (|Δϑ|/L)^0.25 (McAdams 1954).
        """
        t = np.asarray(temperature, dtype=float)
        if self.heat_transfer is not None:
            return np.full(t.shape, self.heat_transfer)
        return 1.32 * (np.abs(t - self.ambient) / self.height) ** 0.25

    def dissipated(self, temperature):
        """P_Q, W: the heat the housing and cooler carry away at sump temperature ``temperature`` (°C).

        Parameters
        ----------
        temperature : float or array_like
            °C.

        Returns
        -------
        ndarray
            A [h_c Δϑ + ε σ (T⁴ − T_a⁴)] + k_cool (ϑ − ϑ_c).

        References
        ----------
        ISO/TR 14179-1:2001 (P_Q by convection, radiation and cooler).
        """
        t = np.asarray(temperature, dtype=float)
        delta = t - self.ambient
        radiation = self.emissivity * STEFAN_BOLTZMANN * ((t + KELVIN) ** 4 - (self.ambient + KELVIN) ** 4)
        coolant = self.ambient if self.coolant is None else self.coolant
        return self.area * (self.convection(t) * delta + radiation) + self.cooler * (t - coolant)


def _finite_balance(balance: np.ndarray, temperature: np.ndarray) -> np.ndarray:
    """``balance`` (P_V − P_Q, W) unchanged if finite everywhere, else the LossModelError naming the temperature."""
    bad = ~np.isfinite(balance)
    if np.any(bad):
        raise LossModelError(
            f"thermal balance: the losses at {float(np.broadcast_to(temperature, bad.shape)[bad][0]):.4g} degC are not "
            "finite numbers (NaN or infinity); check the loss model's inputs (speeds, torques, lubricant data)."
        )
    return balance


def steady_temperature(housing: Housing, loss: Callable[[np.ndarray], np.ndarray], shape: tuple[int, ...],
                       *, ceiling: float = MAX_SUMP_TEMPERATURE) -> np.ndarray:
    """The sump temperature ϑ at which P_Q(ϑ) = P_V(ϑ), at every operating point.

    Parameters
    ----------
    housing : Housing
        The heat paths.
    loss : callable
        ϑ array (°C, of ``shape``) → the losses P_V at those temperatures, W (non-increasing in ϑ).
    shape : tuple of int
        Shape of the operating points.
    ceiling : float, default 200
        Hottest sump searched, °C.

    Returns
    -------
    ndarray
        ϑ, °C, within :data:`TOLERANCE` (regula falsi with the Illinois rule, bracketed).

    Raises
    ------
    LossModelError
        The losses exceed what the housing sheds even at ``ceiling``: no steady state (a cooler
        or a larger housing is needed).

    References
    ----------
    ISO/TR 14179-1:2001 (thermal equilibrium P_V = P_Q).
    """
    coolest = housing.ambient if housing.coolant is None or housing.cooler == 0 else min(housing.ambient,
                                                                                         housing.coolant)
    low = np.full(shape, coolest)
    high = np.full(shape, float(ceiling))
    f_high = loss(high) - housing.dissipated(high)
    if not np.all(np.isfinite(f_high)):
        raise LossModelError(
            f"thermal balance: the losses at {ceiling:g} degC are not finite numbers (NaN or infinity) at some "
            "operating points; check the loss model's inputs (speeds, torques, lubricant data)."
        )
    if np.any(f_high > 0):
        worst = float(np.max(loss(high)))
        raise LossModelError(
            f"thermal balance: the losses ({worst:.4g} W at {ceiling:g} degC) exceed what the housing sheds "
            f"({float(np.min(housing.dissipated(high))):.4g} W) at some operating points: no steady sump "
            "temperature below that; enlarge [housing] area or add a cooler, or give a fixed temperature."
        )
    f_low = _finite_balance(loss(low) - housing.dissipated(low), low)  # > 0: the losses exceed what a cold housing sheds
    cold = f_low <= 0  # even the coldest sump sheds the losses: it stays at the coolest temperature
    # regula falsi with the Illinois rule (superlinear, always bracketed), vectorised over the points
    x = np.where(cold, low, 0.5 * (low + high))
    side = np.zeros(shape)
    for _ in range(ITERATIONS):
        with np.errstate(divide="ignore", invalid="ignore"):
            guess = np.where(f_low != f_high, high - f_high * (high - low) / (f_high - f_low), 0.5 * (low + high))
        guess = np.where(cold, low, np.clip(guess, low, high))
        step = np.abs(guess - x)
        x = guess
        if np.all(cold | (step <= TOLERANCE) | (high - low <= TOLERANCE)):
            break
        f_x = _finite_balance(loss(x) - housing.dissipated(x), x)
        hotter = f_x > 0  # the root lies above x
        low, high = np.where(hotter, x, low), np.where(hotter, high, x)
        f_low = np.where(hotter, f_x, np.where(side == -1, 0.5 * f_low, f_low))   # Illinois: halve the stale end
        f_high = np.where(hotter, np.where(side == 1, 0.5 * f_high, f_high), f_x)
        side = np.where(hotter, 1, -1)
    return x
