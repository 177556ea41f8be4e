"""Windage of fast gears and discs turning in air or oil mist (not dipped).

A gear of outside radius R and face width b turning at ω in a gas of density ρ
and kinematic viscosity ν drags like a free rotating disc (both faces), with
Dawson's allowance for the rim:

.. math::

    T_w = \\tfrac{1}{2} C_M \\rho \\omega^2 R^5 \\left(1 + 2.3 \\frac{b}{R}\\right), \\qquad
    C_M = \\begin{cases} 3.87\\, Re^{-1/2} & Re < 3\\cdot 10^5 \\ (laminar) \\\\
                         0.146\\, Re^{-1/5} & Re \\ge 3\\cdot 10^5 \\ (turbulent) \\end{cases}

with Re = ω R² / ν.  The laminar coefficient is Cochran's exact solution of the
free disc (von Kármán's flow); the turbulent one von Kármán's 1/7-power-law
result, which Theodorsen & Regier's measurements confirm from 5·10⁵ to 3·10⁶.
Validity: a disc far from walls (an enclosure lowers the drag, Daily & Nece
1960), smooth faces; teeth pumping the mist (Diab et al. 2004) add to it, so this
is the floor of a toothed gear's windage; above about 50 m/s tip speed windage
becomes a sizable loss, below about 20 m/s it is negligible.

References
----------
Schlichting, H., Gersten, K.: *Boundary-Layer Theory*, 8th ed., Springer 2000, §5.2.4 (Cochran:
C_M = 3.87/√Re) and §21.5 (turbulent free disc, C_M = 0.146 Re^−1/5);
Theodorsen, T., Regier, A.: NACA Report 793 (1944) (measured disc drag);
Dawson, P. H.: *Windage loss in larger high-speed gears*, Proc. IMechE A 198 (1984) 51–59 (rim factor);
Daily, J. W., Nece, R. E.: ASME J. Basic Eng. 82 (1960) 217–232 (enclosed discs).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..results.solution import RPM_TO_RAD_S
from ._checks import positive

__all__ = ["WindageGear", "TRANSITION_REYNOLDS", "AIR_DENSITY", "AIR_VISCOSITY"]

#: Re = ω R²/ν of the laminar-turbulent transition of a free disc.
TRANSITION_REYNOLDS = 3e5
#: Air at 20 °C: kg/m³ and mm²/s.
AIR_DENSITY, AIR_VISCOSITY = 1.204, 15.1

#: Angular speeds below this (rad/s) are evaluated at it: the coefficients diverge at standstill while
#: the torque, ∝ ω², vanishes (no 0·∞).
_SLOWEST = 1e-6


@dataclass(frozen=True)
class WindageGear:
    """A fast gear or disc on one shaft, turning in air or oil mist (reaction on the housing).

    Parameters
    ----------
    shaft : str
    radius : float
        Outside radius R, mm.
    face_width : float
        b, mm.
    density : float, default 1.204
        ρ of the air or mist, kg/m³.
    kinematic_viscosity : float, default 15.1
        ν of the air or mist, mm²/s.
    element : str or None
        The element the loss is reported under (None: reported under "housing").

    Examples
    --------
    >>> round(float(WindageGear("in", 100.0, 20.0).torque(6000.0)), 4)  # N·m
    0.0381
    """

    shaft: str
    radius: float
    face_width: float
    density: float = AIR_DENSITY
    kinematic_viscosity: float = AIR_VISCOSITY
    element: str | None = None

    def __post_init__(self) -> None:
        owner = f"windage of the gear on {self.shaft!r}"
        for name, unit in (("radius", "mm"), ("face_width", "mm"), ("density", "kg/m^3"),
                           ("kinematic_viscosity", "mm^2/s")):
            object.__setattr__(self, name, positive(getattr(self, name), f"{name} ({unit})", owner))

    def coefficient(self, speed):
        """C_M of the free disc at ``speed`` (1/min): Cochran laminar, von Kármán turbulent.

        Parameters
        ----------
        speed : float or array_like
            1/min.

        Returns
        -------
        ndarray

        References
        ----------
        Schlichting & Gersten 2000, §5.2.4 and §21.5.
        """
        omega = np.abs(np.asarray(speed, dtype=float)) * RPM_TO_RAD_S
        moving = omega > 0
        re = np.maximum(omega, _SLOWEST) * (self.radius * 1e-3) ** 2 / (self.kinematic_viscosity * 1e-6)
        return np.where(moving, np.where(re < TRANSITION_REYNOLDS, 3.87 * re ** -0.5, 0.146 * re ** -0.2), 0.0)

    def torque(self, speed):
        """Windage torque magnitude, N·m: ½ C_M ρ ω² R⁵ (1 + 2.3 b/R).

        Parameters
        ----------
        speed : float or array_like
            Speed against the housing, 1/min.

        Returns
        -------
        ndarray

        References
        ----------
        Schlichting & Gersten 2000, §21.5; Dawson 1984 (rim factor).
        """
        omega = np.abs(np.asarray(speed, dtype=float)) * RPM_TO_RAD_S
        r = self.radius * 1e-3
        return (0.5 * self.coefficient(speed) * self.density * omega ** 2 * r ** 5
                * (1.0 + 2.3 * self.face_width / self.radius)) + 0.0

    def loss(self, speed):
        """Power lost, W: T |ω|."""
        return self.torque(speed) * np.abs(np.asarray(speed, dtype=float)) * RPM_TO_RAD_S
